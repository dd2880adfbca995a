"""Section 5.2: the Eq. 43 recursion, its eigenpairs, the two conditions, Prop. 5.2, Remark 5.2, Eq. 40-41."""

import random

import mpmath
import pytest
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.analysis.ellipses import ellipse_axes, ring_components
from symdecomp.analysis.elliptic import (
    MU,
    elliptic_component,
    elliptic_defect_table,
    eq44_ratio,
    nice_elliptic_conditions,
    recursion_eigenvector,
    recursion_left_eigenvector,
    rotation_free_form,
)
from symdecomp.analysis.frequency import recursion_matrix
from symdecomp.analysis.hyperbolic import apply_rational_matrix
from symdecomp.errors import InvalidPolygonError
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import alpha, beta
from symdecomp.symbols import n as N

CC = catmull_clark()
FREE = catmull_clark(alpha, beta)


def test_eq43_first_row_uses_total_weights():
    T = recursion_matrix(FREE)
    assert sp.expand(T[0, 0] - (1 - N * alpha - N * beta)) == 0
    assert sp.expand(T[0, 1] - N * alpha) == 0 and sp.expand(T[0, 2] - N * beta) == 0


def test_eigenvector_is_an_eigenvector_for_symbolic_n_and_weights():
    T = sp.Matrix(recursion_matrix(FREE))
    u = recursion_eigenvector(FREE, MU)
    quad = sp.Poly(sp.cancel((T - MU * sp.eye(3)).det() / (1 - MU)), MU)
    residual = (T * u - MU * u).applyfunc(lambda e: sp.rem(sp.Poly(sp.expand(e), MU), quad).as_expr())
    assert all(sp.simplify(e) == 0 for e in residual)
    left = recursion_left_eigenvector(FREE, MU)
    lres = (left.T * T - MU * left.T).applyfunc(lambda e: sp.rem(sp.Poly(sp.expand(e), MU), quad).as_expr())
    assert all(sp.simplify(e) == 0 for e in lres)


def test_eq44_ratio_does_not_involve_the_vertex_rule():
    ratio = eq44_ratio(FREE, MU)
    assert ratio.free_symbols == {MU}
    assert sp.simplify(ratio - 8 * MU / (8 * MU - 1)) == 0


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 8])
def test_subdominant_is_an_exact_eigenvalue_of_the_subdivision_matrix(n):
    # The quadratic whose larger root is mu(n) divides the exact characteristic polynomial of S.
    x = sp.Symbol("x")
    mu = nice_elliptic_conditions(CC).subdominant.subs(N, n)
    minimal = sp.minimal_polynomial(mu, x)
    charpoly = subdivision_matrix(CC, n).charpoly(x).as_expr()
    assert sp.rem(sp.Poly(charpoly, x), sp.Poly(minimal, x)).is_zero
    # and its eigenvector, lifted to the 1-ring, is an eigenvector of S (exactly, modulo the minimal polynomial)
    u = recursion_eigenvector(CC, x, n)
    V = sp.Matrix([u[0]] + [u[1]] * n + [u[2]] * n)
    residual = subdivision_matrix(CC, n) * V - x * V
    assert all(sp.rem(sp.Poly(sp.expand(e), x), sp.Poly(minimal, x)).is_zero for e in residual)


@pytest.mark.parametrize("n", [3, 5, 7])
def test_lambda1_matches_numeric_spectrum(n):
    cond = nice_elliptic_conditions(CC)
    with mpmath.workdps(30):
        S = mpmath.matrix([[mpmath.mpf(sp.Rational(e).p) / sp.Rational(e).q for e in row] for row in subdivision_matrix(CC, n).tolist()])
        ev = sorted((mpmath.re(v) for v in mpmath.eig(S, left=False, right=False)), reverse=True)
        lam1 = mpmath.mpf(str(sp.N(cond.lambda1.subs(N, n), 40)))
        assert abs(ev[1] - lam1) < mpmath.mpf(10) ** -25 and abs(ev[2] - lam1) < mpmath.mpf(10) ** -25


def test_defect_table_regular_case_and_signs():
    rows = {r.n: r for r in elliptic_defect_table(CC, range(3, 13), digits=25)}
    assert rows[4].eigenvalue_defect == 0 and rows[4].ratio_defect == 0
    assert rows[4].texts[0] == "0.25" and rows[4].texts[3] == "2.0"
    assert rows[3].eigenvalue_defect < 0 < rows[5].eigenvalue_defect
    assert all(rows[n].ratio_defect < 0 for n in range(5, 13))
    # closed forms: mu(3) = 1/6, Eq. 44 ratio at n = 3 is 4
    with mpmath.workdps(30):
        assert abs(rows[3].subdominant - mpmath.mpf(1) / 6) < mpmath.mpf(10) ** -24
        assert abs(rows[3].eq44_ratio - 4) < mpmath.mpf(10) ** -24


def test_defect_table_up_to_fifty_is_real_and_finite():
    rows = elliptic_defect_table(CC, range(3, 51), digits=15)
    assert [r.n for r in rows] == list(range(3, 51))
    # lambda_1 stays the subdominant eigenvalue of S: mu < lambda_1 for all these n
    for r in rows:
        assert r.subdominant < mpmath.sqrt(r.lambda1_squared)


def test_proposition_5_2_symbolically_and_on_the_exact_matrix():
    assert rotation_free_form(FREE)[1] == sp.zeros(2, 2)
    # A ring made of the 2n-gon component j = 1 only: a_i = omega^i, b_i = omega_2n omega^i (complex coordinate)
    for n in (3, 5, 6):
        K = CyclotomicField(2 * n)
        S = subdivision_matrix(CC, n)
        vec = [K(0)] + [K.zeta(2 * i) for i in range(n)] + [K.zeta(2 * i + 1) for i in range(n)]
        for _ in range(3):
            vec = apply_rational_matrix(S, vec)
            r_a = vec[1]  # a_0 / 1
            r_b = vec[n + 1] * K.zeta(-1)  # b_0 / omega_2n
            assert r_a == r_a.conjugate() and r_b == r_b.conjugate()  # real
            for i in range(n):  # still the same rotation pattern
                assert vec[1 + i] == r_a * K.zeta(2 * i)
                assert vec[1 + n + i] == r_b * K.zeta(2 * i + 1)


@pytest.mark.parametrize("n", [3, 4, 5, 9])
def test_remark_5_2_cases(n):
    assert elliptic_component(CC, n, (1, 1, 1)) == 0
    assert elliptic_component(CC, n, (0, 1, 1)) != 0


@pytest.mark.parametrize("scheme", [CC, catmull_clark(sp.Rational(1, 8) / N, sp.Rational(1, 32) / N)], ids=["cc", "tuned"])
def test_component_in_the_quadratic_field_is_the_simplified_quotient(scheme):
    """The component computed in ``Q(sqrt d)`` equals ``(l . x)/(l . u)`` simplified by sympy, exactly."""
    from symdecomp.analysis.spectrum import recursion_eigenvalues

    for n in (3, 5, 8):
        mu = recursion_eigenvalues(scheme)[1].subs(N, n)
        left, right = recursion_left_eigenvector(scheme, mu, n), recursion_eigenvector(scheme, mu, n)
        for x in ((1, 1, 1), (0, 1, 1), (1, 0, 0), (0, 1, -1)):
            value = elliptic_component(scheme, n, x)
            assert value is not None and sp.simplify(value - left.dot(sp.Matrix(x)) / left.dot(right)) == 0

def test_remark_5_2_third_case_at_n4():
    assert elliptic_component(CC, 4, (0, 1, -1)) == 0
    assert elliptic_component(CC, 5, (0, 1, -1)) != 0


def test_ellipse_axes_match_the_singular_values_and_e_a_equals_e_b():
    rng = random.Random(11)
    for n in (3, 4, 7):
        ring = sp.Matrix(2 * n + 1, 3, lambda r, c: sp.Rational(rng.randint(-9, 9), rng.randint(1, 5)))
        ea, eb = ellipse_axes(ring, 1, digits=40), ellipse_axes(ring, 1, "b", digits=40)
        for x, y, z in zip(ea.semi_axes, ea.singular_values, eb.semi_axes):
            assert abs(sp.N(x - y, 40)) < 1e-35 and abs(sp.N(x - z, 40)) < 1e-35


def test_ring_components_reconstruct_the_ring():
    ring = sp.Matrix([[0, 0, 0], [1, 2, 0], [0, 1, 3], [-1, 0, 0], [2, 2, 1], [0, 0, 1], [1, 1, 1]])
    z = ring_components(ring)
    n = 3
    for k in range(2 * n):
        P = ring.row(1 + k // 2) if k % 2 == 0 else ring.row(1 + n + k // 2)
        rebuilt = sum((z[j].T * sp.exp(2 * sp.pi * sp.I * sp.Rational(j * k, 2 * n)) for j in range(2 * n)), sp.zeros(1, 3))
        assert all(abs(sp.N(a - b, 30)) < 1e-25 for a, b in zip(rebuilt, P))


def test_bad_ring_is_rejected():
    with pytest.raises(InvalidPolygonError, match="1-ring"):
        ellipse_axes(sp.zeros(4, 3))


def test_proposition_5_2_check_can_fail_for_an_asymmetric_scheme():
    from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule

    R = sp.Rational
    edge = Stencil.from_weights(R(1, 4), {0: R(1, 2)}, {0: R(1, 4)})  # leans on b_i only, not b_{i-1}
    face = Stencil.from_weights(R(1, 4), {0: R(1, 4), 1: R(1, 4)}, {0: R(1, 4)})
    lopsided = Scheme("lopsided", edge, face, VertexRule.affine(R(1, 4) / N, 0))
    assert rotation_free_form(lopsided)[1] != sp.zeros(2, 2)
