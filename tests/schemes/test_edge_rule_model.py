"""Issue 32 item 2: an edge rule in n is read, by every command, from the edge's extraordinary end at its valence.

The edges at the centre O use the rule at O's valence n (what the 1-ring stencils say), every other edge the rule at
the regular valence. The K-ring matrices built by refinement, the ring blocks and spectra, the limit masks and Reif's
test read the same rules, so their results agree with each other and with the 1-ring stencils.
"""

from __future__ import annotations

from pathlib import Path

import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.frequency import ring_blocks
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.files import load_scheme, scheme_from_text
from symdecomp.schemes.refinement import edge_centre, mesh_rules
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import n as N

CORPUS = Path(__file__).parents[1] / "corpus"
#: Catmull-Clark's rules except the edge rule's weights on its two ends: 3/8 +- (n - 4)/64 (O gets more).
LOPSIDED_ENDS = load_scheme(str(CORPUS / "n-dependent-edge.toml"))
#: Edge weights (2n - 5)/8 on the ends and (9 - 2n)/16 on the sides: Catmull-Clark's at n = 4.
SYMMETRIC_IN_N = scheme_from_text('name = "frequency two"\n[edge]\nO = "(2*n - 5)/8"\n'
                                  'a = { "-1" = "(9 - 2*n)/16", "0" = "(2*n - 5)/8", "1" = "(9 - 2*n)/16" }\n'
                                  'b = { "-1" = "(9 - 2*n)/16", "0" = "(9 - 2*n)/16" }\n'
                                  '[face]\nO = "1/4"\na = { "0" = "1/4", "1" = "1/4" }\nb = { "0" = "1/4" }\n'
                                  '[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n')


def test_which_end_is_O():
    assert [edge_centre(*v, 4) for v in ((5, 4), (4, 5), (4, 4), (3, 4), (4, 3), (3, 7), (7, 3), (5, 5))] == [0, 1, 0, 0, 1, 1, 0, 0]


@pytest.mark.parametrize("scheme", [LOPSIDED_ENDS, SYMMETRIC_IN_N], ids=["lopsided ends", "symmetric in n"])
@pytest.mark.parametrize("n", [3, 5, 7])
def test_the_two_ring_matrix_reads_the_stencils_at_n_and_the_regular_rule_elsewhere(scheme, n):
    one, two = ring_subdivision_matrix(scheme, n, 1), ring_subdivision_matrix(scheme, n, 2)
    order = list(one.block_order())  # (O, a_0..a_(n-1), b_0..b_(n-1))
    assert one.exact_matrix().extract(order, order) == subdivision_matrix(scheme, n)  # the 1-ring: the stencils at n
    inner = [two.labels.index(label) for label in one.labels]
    S = two.exact_matrix()
    assert S.extract(inner, inner) == one.exact_matrix()
    # the new points of the second ring (on edges and faces away from O) are Catmull-Clark's
    reference = ring_subdivision_matrix(catmull_clark(), n, 2)
    assert reference.labels == two.labels
    outer = [r for r in range(two.size) if r not in inner]
    R = reference.exact_matrix()
    assert all(S[r, :] == R[r, :] for r in outer)
    assert any(S[r, :] != R[r, :] for r in inner)  # ... and the 1-ring's are not (n = 4 aside)


@pytest.mark.slow
@pytest.mark.parametrize("n", [5, 6])
def test_ring_blocks_spectrum_and_reifs_test_agree(n):
    from symdecomp.verify.c1 import c1_test

    blocks = ring_blocks(SYMMETRIC_IN_N, 2)
    assert blocks.frequency_matrix().has(N)  # the blocks are functions of n and omega
    assert blocks.full_matrix(n).subs(N, n) == ring_subdivision_matrix(SYMMETRIC_IN_N, n, 2).exact_matrix().extract(
        *(list(ring_subdivision_matrix(SYMMETRIC_IN_N, n, 2).block_order()),) * 2)
    spectrum = ring_spectrum(SYMMETRIC_IN_N, n, 2)
    r = c1_test(SYMMETRIC_IN_N, n)
    top = r.spectral.subdominant.value
    second = [e for e in spectrum.eigenvalues if not (e.value - 1).contains(0)][0]
    assert (second.value - top).contains(0), (second.text, top)  # the same subdominant eigenvalue
    # and both equal an eigenvalue of the exact 2-ring matrix (numerically, 30 digits)
    S = ring_subdivision_matrix(SYMMETRIC_IN_N, n, 2).exact_matrix()
    with mpmath.workdps(40):
        eigs, _ = mpmath.eig(mpmath.matrix([[mpmath.mpf(x.p) / x.q for x in S.row(r)] for r in range(S.rows)]))
        assert min(abs(complex(e) - complex(second.value.mid())) for e in eigs) < 1e-12


@pytest.mark.slow
def test_masks_and_one_ring_suffices_read_the_file():
    from symdecomp.analysis.masks import limit_masks_at
    from symdecomp.claims import Status, check_claim

    masks = limit_masks_at(LOPSIDED_ENDS, 5)
    assert masks is not None
    r = check_claim("1-ring suffices (after Eq. 51)", LOPSIDED_ENDS)
    assert r.status is Status.VERIFIED and r.valences == (4, 4)


def test_an_edge_between_two_vertices_of_one_valence_needs_a_symmetric_rule():
    """Two adjacent valence-5 vertices and a rule that weighs its ends differently at n = 5: neither end is O."""
    from symdecomp.schemes.mesh import ring_mesh
    from symdecomp.schemes.refinement import refine

    rules = mesh_rules(LOPSIDED_ENDS)
    assert rules.depends_on_valence and rules.edge_weights(4) == (sp.Rational(3, 8), sp.Rational(3, 8), sp.Rational(1, 16), sp.Rational(1, 16))
    mesh = ring_mesh(5, 3)
    # the centre has valence 5; glue nothing else: every other vertex is regular, so refinement goes through
    refine(mesh, rules)
    symmetric = mesh_rules(SYMMETRIC_IN_N)
    assert symmetric.edge_weights(5)[0] == symmetric.edge_weights(5)[1]


def test_tagged_refinement_refuses_an_edge_rule_in_n():
    from symdecomp.schemes.sharp import SharpOptions
    from symdecomp.schemes.tagged_refinement import _Rules

    with pytest.raises(InvalidSchemeError, match="depends on the valence n"):
        _Rules(SYMMETRIC_IN_N, SharpOptions())


def test_masks_of_a_lopsided_rule_in_n_are_left_eigenvectors_at_that_valence():
    """A lopsided edge rule in n (weights 1/16 -+ (n - 4)/128 on a_(i-1), a_(i+1)): the masks are computed at n = 5
    (it was 'cannot evaluate n'), and the position mask is the left eigenvector of 1 of the 1-ring matrix there."""
    from symdecomp.analysis.masks import ring_masks

    s = scheme_from_text('name = "lopsided in n"\n[edge]\nO = "3/8"\na = { "-1" = "1/16 - (n - 4)/128", "0" = "3/8", '
                         '"1" = "1/16 + (n - 4)/128" }\nb = { "-1" = "1/16", "0" = "1/16" }\n[face]\nO = "1/4"\n'
                         'a = { "0" = "1/4", "1" = "1/4" }\nb = { "0" = "1/4" }\n[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n')
    masks = ring_masks(s, 5)
    y = [float(masks["position"]["O"])] + [float(x) for x in masks["position"]["a"] + masks["position"]["b"]]
    S = subdivision_matrix(s, 5)
    assert max(abs(sum(y[r] * float(S[r, c]) for r in range(11)) - y[c]) for c in range(11)) < 1e-15
    assert abs(sum(y) - 1) < 1e-15


def test_the_ring_certificate_and_the_product_form_read_the_blocks_at_n():
    """The structural certificate compares the refined matrix with the blocks at n (it said 'refuted', the block entry
    n/64 + 5/16 against 25/64), and the product form equals chi_S at 31 points (it raised on n in E(omega))."""
    from symdecomp.analysis.charpoly import ring_charpoly
    from symdecomp.verify.certify import certify_ring

    assert ring_charpoly(LOPSIDED_ENDS, 5, 2)["matches_matrix"] is True
    certificate = certify_ring(LOPSIDED_ENDS, 5, 2)
    assert certificate.status.value == "agree", certificate
