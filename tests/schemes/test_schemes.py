"""Schemes as data: the exact matrix, its circulant blocks, user-defined schemes."""

import pytest
import sympy as sp

from symdecomp import Scheme, Stencil, VertexRule, catmull_clark, circulant_blocks, subdivision_matrix
from symdecomp.algebra.circulant import circ_from_offsets
from symdecomp.symbols import alpha, beta, n

R = sp.Rational


@pytest.mark.parametrize("valence", range(3, 11))
def test_matrix_blocks_are_the_derived_circulants(valence):
    cc = catmull_clark(alpha, beta)
    S = subdivision_matrix(cc, valence)
    blocks = circulant_blocks(cc)
    m = valence
    assert S[1 : 1 + m, 1 : 1 + m] == circ_from_offsets(blocks.aa, m)
    assert S[1 : 1 + m, 1 + m :] == circ_from_offsets(blocks.ab, m)
    assert S[1 + m :, 1 : 1 + m] == circ_from_offsets(blocks.ba, m)
    assert S[1 + m :, 1 + m :] == circ_from_offsets(blocks.bb, m)
    assert [sp.simplify(sum(S.row(r))) for r in range(2 * m + 1)] == [1] * (2 * m + 1)


def test_user_defined_scheme_without_touching_the_package():
    edge = Stencil.from_weights(R(1, 2), {0: R(1, 4)}, {0: R(1, 8), -1: R(1, 8)}, name="my edge rule")
    face = Stencil.from_weights(R(1, 4), {0: R(1, 4), 1: R(1, 4)}, {0: R(1, 4)}, name="my face rule")
    mine = Scheme("mine", edge, face, VertexRule.affine(R(1, 4) / n, 0))
    S = subdivision_matrix(mine, 6)
    assert S[0, 0] == R(3, 4) and S[1, 0] == R(1, 2) and S[1, 1] == R(1, 4) and S[1, 7] == R(1, 8) and S[1, 12] == R(1, 8)
    from symdecomp import per_frequency_matrix
    from symdecomp.symbols import omega

    assert sp.expand(per_frequency_matrix(mine)[0, 1] - (R(1, 8) + R(1, 8) / omega)) == 0


def test_substitute_tunes_parameters():
    tuned = catmull_clark(alpha, beta)
    assert set(tuned.parameters) == {alpha, beta}
    fixed = tuned.substitute({alpha: 3 / (2 * n**2), beta: 1 / (4 * n**2)})
    assert fixed.parameters == ()
    assert subdivision_matrix(fixed, 7) == subdivision_matrix(catmull_clark(), 7)


def test_stencil_wider_than_the_ring_is_rejected():
    from symdecomp import InvalidSchemeError

    edge = Stencil.from_weights(R(1, 2), {-2: R(1, 8), 2: R(1, 8), 0: R(1, 4)}, {}, name="wide")
    face = catmull_clark().face_rule
    wide = Scheme("wide", edge, face, VertexRule.affine(0, 0))
    assert wide.minimum_valence() == 5
    with pytest.raises(InvalidSchemeError, match="wider than the valence n = 4"):
        subdivision_matrix(wide, 4)
