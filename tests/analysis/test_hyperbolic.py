"""Section 5.3: j = 2 eigenvalues against lambda_1^2; the hyperbolic-only 1-ring under the exact matrix."""

import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.elliptic import tangent_lambda
from symdecomp.analysis.hyperbolic import hyperbolic_defect, hyperbolic_equality, hyperbolic_lambda, hyperbolic_ring, iterate_hyperbolic_ring
from symdecomp.errors import InvalidValenceError
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import n as N

CC = catmull_clark()


def test_equality_only_at_n4():
    eq = hyperbolic_equality(CC)
    assert eq.valences == (4,)
    assert sp.simplify(hyperbolic_defect(CC).subs(N, 4)) == 0


@pytest.mark.parametrize("n", [3, 5, 6, 12, 50])
def test_defect_positive_elsewhere(n):
    assert sp.N(hyperbolic_defect(CC).subs(N, n), 30) > 0


def test_n3_hyperbolic_equals_tangent():
    assert sp.simplify(hyperbolic_lambda(CC).subs(N, 3) - tangent_lambda(CC, 1).subs(N, 3)) == 0


@pytest.mark.parametrize("n", [4, 5, 8])
def test_lambda2_is_an_eigenvalue_of_the_exact_matrix(n):
    with mpmath.workdps(30):
        S = subdivision_matrix(CC, n)
        M = mpmath.matrix([[mpmath.mpf(e.p) / e.q for e in row] for row in S.tolist()])
        ev = [mpmath.re(v) for v in mpmath.eig(M, left=False, right=False)]
        lam2 = mpmath.mpf(str(sp.N(hyperbolic_lambda(CC).subs(N, n), 40)))
        assert min(abs(v - lam2) for v in ev) < mpmath.mpf(10) ** -25


def test_hyperbolic_ring_has_no_elliptic_input():
    ring = hyperbolic_ring(5, height=2)
    assert ring.shape == (11, 3) and ring.row(0) == sp.zeros(1, 3)
    assert sp.simplify(sum(ring[1:6, 2])) == 0 and sp.simplify(sum(ring[6:, 2])) == 0
    assert sp.simplify(ring[1, 2] - 2) == 0  # a_0 at height 2 cos 0


@pytest.mark.parametrize("n", range(3, 11))
def test_iteration_matches_prediction_exactly(n):
    it = iterate_hyperbolic_ring(CC, n, steps=4, digits=20)
    assert it.matches_prediction and it.elliptic_component_zero


def test_normal_over_tangent_squared_grows_like_predicted():
    it = iterate_hyperbolic_ring(CC, 5, steps=14, digits=20)
    with mpmath.workdps(20):
        r = it.normal_over_tangent_squared
        assert abs(r[-1] / r[-2] - it.predicted_factor) < mpmath.mpf("1e-3")
        assert it.predicted_factor > 1  # n = 5: the hyperbolic part shrinks slower than quadratically
    it4 = iterate_hyperbolic_ring(CC, 4, steps=14, digits=20)
    with mpmath.workdps(20):
        assert abs(it4.predicted_factor - 1) < mpmath.mpf("1e-18")
        assert abs(it4.normal_over_tangent_squared[-1] / it4.normal_over_tangent_squared[-2] - 1) < mpmath.mpf("1e-3")


def test_bad_input():
    with pytest.raises(InvalidValenceError):
        hyperbolic_ring(2)
    with pytest.raises(ValueError, match="steps"):
        iterate_hyperbolic_ring(CC, 5, steps=-1)


def test_the_comparison_can_fail(monkeypatch):
    import symdecomp.analysis.hyperbolic as module

    original = module._laurent_in
    # predict the heights with M_1 instead of M_2: the exact iteration must disagree
    monkeypatch.setattr(module, "_laurent_in", lambda K, e, unit: original(K, e, 4 if unit == 8 else unit))
    assert not iterate_hyperbolic_ring(CC, 5, steps=2).matches_prediction


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_basis_function_claim_with_a_cos_vertex_weight_keeps_the_range_and_says_why():
    # cos(2 pi/n) in the vertex rule: the resultants are not rational in n, so no every-n argument, but no error either
    import sympy as sp

    from symdecomp.claims import Status
    from symdecomp.claims.registry import check_claim
    from symdecomp.schemes.scheme import catmull_clark
    from symdecomp.symbols import n

    scheme = catmull_clark(sp.Rational(3, 2) / n**2 + sp.cos(2 * sp.pi / n) / (100 * n**2), sp.Rational(1, 4) / n**2)
    result = check_claim("Section 5.3: basis function", scheme)
    assert result.status is Status.VERIFIED
    assert "not a rational function of n" in str(result.evidence)
