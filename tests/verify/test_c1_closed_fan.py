"""verify/c1_closed_fan.py: Reif's test at an infinitely sharp dart (one sharp edge ending at a smooth vertex).

The spectral facts are checked against sympy on the exact matrix built by refinement; the characteristic map's verdict
against mutations (an eigenvector of the wrong eigenvalue, another weight of the dart's vertex rule)."""

import flint
import pytest
import sympy as sp

from symdecomp.algebra.null_vector import null_vector
from symdecomp.errors import InvalidValenceError
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.c1_closed_fan import _shift, c1_dart_test, dart_map, dart_spectrum, dart_vectors
from symdecomp.verify.mirror_parts import ball_matrix, sector_eigenvalues, sector_matrices
from symdecomp.verify.result import C1Verdict


def dart(scheme, n):
    sm = sector_matrices(scheme, SharpVertex.dart(n, scheme.lattice), 0)
    return sm, dart_spectrum(scheme, n, sm)


@pytest.mark.parametrize("n", range(3, 9))
def test_catmull_clark_darts_of_valence_3_to_8_are_c1(n):
    r = c1_dart_test(catmull_clark(), n)
    assert r.verdict is C1Verdict.C1, r.reason
    assert r.winding_number == r.jacobian_sign and r.jacobian_lower_bound > 0
    assert r.reason.endswith("its ring winds once around O: injective")


@pytest.mark.parametrize("n", [3, 5, 6])
def test_the_subdominant_pair_is_the_exact_matrix_s(n):
    """lambda_1, lambda_2 are roots of the exact matrix's characteristic polynomial, and 1 is a simple root."""
    sm, spectrum = dart(catmull_clark(), n)
    S = sp.Matrix(sm.matrix)
    x = sp.Symbol("x")
    p = sp.Poly(S.charpoly(x).as_expr(), x)
    assert p.eval(1) == 0 and sp.Poly(sp.diff(p.as_expr(), x), x).eval(1) != 0
    for value in spectrum.pair:
        assert p.rem(sp.Poly(value.factor.coeffs()[::-1], x)).is_zero
    assert spectrum.pair[0].key != spectrum.pair[1].key


def test_at_valence_4_the_pair_is_one_half_twice_with_two_exact_eigenvectors():
    sm, spectrum = dart(catmull_clark(), 4)
    assert [v.exact for v in spectrum.pair] == [sp.Rational(1, 2)] * 2
    vectors = dart_vectors(sm, spectrum)
    S = ball_matrix(sm.matrix.tolist())
    for v in vectors:
        col = flint.acb_mat([[flint.acb(x)] for x in v])
        assert all((S * col - col / 2)[i, 0].contains(0) for i in range(S.nrows()))
    assert len((sp.Matrix(sm.matrix) - sp.eye(sm.matrix.rows) / 2).nullspace()) == 2


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_an_eigenvector_of_the_wrong_eigenvalue_breaks_the_map(n):
    """Mutation: lambda_2's eigenvector replaced by the next eigenvalue's: the Jacobian changes sign."""
    sm, spectrum = dart(catmull_clark(), n)
    v1, _ = dart_vectors(sm, spectrum)
    with flint.ctx.workprec(64):
        values = sorted((x for x, _, _ in sector_eigenvalues(sm)), key=lambda x: -abs(x).mid())
        third = null_vector(_shift(ball_matrix(sm.matrix.tolist()), values[3]))
        found = dart_map(sm, [v1, [x.real for x in third]])
    assert found.verdict is C1Verdict.NOT_C1 and "changes sign" in found.reason


def test_swapping_the_eigenvectors_flips_sign_and_winding_together():
    sm, spectrum = dart(catmull_clark(), 5)
    v1, v2 = dart_vectors(sm, spectrum)
    a, b = dart_map(sm, [v1, v2]), dart_map(sm, [v2, v1])
    assert a.verdict is b.verdict is C1Verdict.C1
    assert (a.sign, a.winding) == (-b.sign, -b.winding) and a.sign == a.winding


def test_another_weight_of_the_dart_s_vertex_rule_is_not_c1():
    """Mutation of the scheme: vertex weights alpha = 1/2, beta = 1/4 at n = 3 (O's weight -5/4): an eigenvalue of modulus
    above 1 (sympy on the exact matrix), so the rings do not shrink to a point; the verdict flips to not-c1."""
    mutated = catmull_clark(sp.Rational(1, 2), sp.Rational(1, 4))
    r = c1_dart_test(mutated, 3)
    assert r.verdict is C1Verdict.NOT_C1 and "the eigenvalue 1 is not simple and strictly dominant" in r.reason
    sm, _ = dart(mutated, 3)
    x = sp.Symbol("x")
    factors = [f for f, _ in sp.factor_list(sp.Matrix(sm.matrix).charpoly(x).as_expr(), x)[1]]  # simple roots each
    assert max(abs(complex(z)) for f in factors for z in sp.Poly(f, x).nroots(n=20)) > 1.5


@pytest.mark.parametrize("n", [3, 4, 6])
def test_loop_darts_where_the_weights_are_rational_are_c1(n):
    r = c1_dart_test(loop(), n)
    assert r.verdict is C1Verdict.C1, r.reason


def test_loop_darts_with_irrational_weights_are_undecided_with_the_reason():
    r = c1_dart_test(loop(), 5)
    assert r.verdict is C1Verdict.UNDECIDED and "is not rational" in r.reason


def test_a_bad_valence_is_one_clear_error():
    with pytest.raises(InvalidValenceError, match="valence n"):
        c1_dart_test(catmull_clark(), 2)
