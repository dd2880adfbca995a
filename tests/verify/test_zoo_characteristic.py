"""C1 of the zoo's dual schemes on the engine's neighbourhood: the eigenvector read from a frequency block is one of the
whole matrix, and the verdicts follow from the scheme's weights (Doo-Sabin C1; a centre rule pushing frequency 2 above
frequency 1 not C1)."""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.schemes.stencils import J, M
from symdecomp.verify.c1_zoo import c1_zoo
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import C1_DEPTH, engine_neighbourhood
from tests.verify.test_c1_dual import doo_sabin_scheme

DOO_SABIN = doo_sabin_scheme()
#: Doo-Sabin's rule plus (7/10) cos(4 pi j/m)/m in faces other than quads: frequency 2 of an n-gon goes from 1/4 to 3/5.
LIFTED = doo_sabin_scheme("lifted", corner=sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M)
                          + (1 - sp.KroneckerDelta(M, 4)) * sp.Rational(7, 10) * sp.cos(4 * sp.pi * J / M) / M)


@pytest.mark.parametrize("n", [3, 5, 6])
def test_the_block_eigenvector_is_an_eigenvector_of_the_whole_matrix(n):
    nb = engine_neighbourhood(DOO_SABIN, n)
    zm = zoo_matrix(DOO_SABIN, n, C1_DEPTH)
    lam = nb.spectral.subdominant.value
    order = zm.neighbourhood.order
    with flint.ctx.workprec(128):
        S = flint.acb_mat([[flint.acb(str(sp.N(x, 50))) for x in row] for row in zm.matrix.tolist()])
        X = flint.acb_mat([[nb.points[v]] for v in order])
        residual = S * X - X * lam
        assert max(abs(residual[i, 0]).upper() for i in range(len(order))) < 1e-30
    assert abs(X[0, 0]).lower() > 0.01  # not the zero vector


@pytest.mark.parametrize("n", [3, 4, 5, 7])
def test_doo_sabin_is_c1_on_the_engines_neighbourhood(n):
    r = c1_zoo(DOO_SABIN, n, neighbourhood=engine_neighbourhood)
    assert r.verdict is C1Verdict.C1 and r.frequency == 1 and r.winding_number == 1
    assert abs(r.spectral.subdominant.value - flint.fmpq(1, 2)).upper() < 1e-15


def test_a_centre_rule_with_frequency_two_above_one_is_not_c1():
    r = c1_zoo(LIFTED, 6, neighbourhood=engine_neighbourhood)
    assert r.verdict is C1Verdict.NOT_C1 and r.frequency == 2 and r.winding_number == 2
    assert abs(r.spectral.subdominant.value - flint.fmpq(3, 5)).upper() < 1e-15
