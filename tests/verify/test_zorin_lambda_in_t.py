"""sqrt(3)'s spectral conditions for every valence (issue 30): ``lambda_1 = lambda(t)`` derived from the structural blocks.

The polynomials ``p_k`` are compared with the explicit matrix of the zoo's engine at ``n = 16, 17`` (their product at
``t = cos(2 pi k/n)`` is its characteristic polynomial, in Arb), ``lambda_1(n)`` with that matrix's eigenvalues at two
valences; the bad vertex weight ``alpha_n = (n - 3)/9`` of ``tests/verify/test_c1_zorin_sqrt3.py`` flips the
frequency-0 step with a valence computed and checked on the explicit matrix; the other-frequencies argument and the
scaled Schur-Cohn polynomials are checked on polynomials whose roots are known.
"""

from __future__ import annotations

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp.algebra.schur_cohn import schur_cohn_conditions
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text, stencil_scheme_to_text
from symdecomp.symbols import n as N
from symdecomp.verify.c1_every_n import T
from symdecomp.verify.c1_uniform import t_lower_bound
from symdecomp.verify.c1_zorin_every_n import X, c1_zorin_every_n, frequency_polynomials, zorin_lambda_one, zorin_spectral_every_n
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zorin_lambda_in_t import linear_roots, other_frequencies_in_t, scaled_deltas
from tests.verify.test_c1_zorin_every_n import stub

SQRT3 = load_zoo("sqrt3")
DIGITS = 40
STEPS = {"lambda-one", "frequency-zero", "frequency-one", "other-frequencies"}


def _bad_alpha():
    """``alpha_n = (n - 3)/9``: Kobbelt's ``1/3`` at ``n = 6``, the frequency-0 eigenvalue ``((n - 9)/9)^2`` besides 1."""
    text = stencil_scheme_to_text(SQRT3)
    centre, ring = "2*cos(2*pi/n)/9 + 5/9", "(4 - 2*cos(2*pi/n))/(9*n)"
    assert centre in text and ring in text
    text = text.replace(centre, "(12 - n)/9").replace(ring, "(n - 3)/(9*n)").replace('name = "sqrt3"', 'name = "bad-alpha"')
    return stencil_scheme_from_text(text, source="bad-alpha.toml")


def _moduli(scheme, n: int) -> list[mpmath.mpf]:
    """The moduli of the explicit matrix's eigenvalues at ``n`` (mpmath, :data:`DIGITS` digits), largest first."""
    with mpmath.workdps(DIGITS):
        A = mpmath.matrix([[mpmath.mpf(str(sp.N(e, DIGITS + 10))) for e in row] for row in zoo_matrix(scheme, n).matrix.tolist()])
        return sorted((abs(z) for z in mpmath.eig(A, left=False, right=False)), reverse=True)


def _arb(e: sp.Expr) -> flint.arb:
    return flint.arb(str(sp.N(e, DIGITS + 20)), flint.arb(10) ** -(DIGITS + 15))


@pytest.mark.parametrize("n", [16, 17])
def test_the_derived_polynomials_multiply_to_the_explicit_characteristic_polynomial(n):
    polys = frequency_polynomials(SQRT3)
    with flint.ctx.workprec(4 * DIGITS):
        derived = flint.acb_poly([1])
        for k in range(n):
            signed = k if k <= n // 2 else k - n
            p, angle = (polys.at[signed], 1) if signed in polys.at else (polys.other, k)
            p = sp.expand(p.subs(sp.cos(2 * sp.pi / N), T).subs(T, sp.cos(2 * sp.pi * angle / n)).subs(N, n))
            derived *= flint.acb_poly([_arb(c) for c in reversed(sp.Poly(p, X).all_coeffs())])
        A = flint.acb_mat([[_arb(e) for e in row] for row in zoo_matrix(SQRT3, n).matrix.tolist()])
        for a, b in zip(A.charpoly().coeffs(), derived.coeffs(), strict=True):
            assert abs(a - b) < flint.arb(10) ** -DIGITS


@pytest.mark.parametrize("n", [16, 23])
def test_lambda_one_in_n_is_the_explicit_matrix_double_subdominant_eigenvalue(n):
    lam = zorin_lambda_one(SQRT3)
    assert lam.has(N)
    moduli = _moduli(SQRT3, n)
    with mpmath.workdps(DIGITS):
        value = mpmath.mpf(str(sp.N(lam.subs(N, n), DIGITS + 10)))
        assert abs(moduli[0] - 1) < mpmath.mpf(10) ** -30
        assert abs(moduli[1] - value) < mpmath.mpf(10) ** -30 and abs(moduli[2] - value) < mpmath.mpf(10) ** -30
        assert moduli[3] < value - mpmath.mpf(10) ** -3  # double, and strictly above the rest
    # the closed form Kobbelt gives (SIGGRAPH 2000, Section 5), two steps: (2 + 2 cos(2 pi/n))/9
    assert sp.simplify(lam - (2 + 2 * sp.cos(2 * sp.pi / N)) / 9) == 0


def test_every_spectral_step_of_sqrt3_is_proved_for_every_n_from_the_structural_form():
    steps = zorin_spectral_every_n(SQRT3, per_valence=False)
    assert {s.name for s in steps} == STEPS
    assert all(s.status == "proved" and s.valences == (16, None) for s in steps)
    lam = dict(steps[0].formulas)[r"\lambda_1(t)"]
    assert sp.expand(lam - linear_roots(frequency_polynomials(SQRT3).at[1])[0]) == 0 and lam.has(T)


def test_the_bad_vertex_weight_fails_frequency_zero_at_a_computed_valence_the_explicit_matrix_confirms():
    bad = _bad_alpha()
    steps = {s.name: s for s in zorin_spectral_every_n(bad, per_valence=False)}
    zero = steps["frequency-zero"]
    assert zero.status == "failed" and zero.valences == (16, 16) and "n = 16" in zero.text
    assert steps["lambda-one"].status == "proved" and steps["other-frequencies"].status == "proved"
    # at n = 16 the explicit matrix has an eigenvalue besides 1 of modulus above lambda_1(16): ((16 - 9)/9)^2 = 49/81
    moduli = _moduli(bad, 16)
    lam = float(zorin_lambda_one(bad).subs(N, 16))
    assert abs(float(moduli[1]) - 49 / 81) < 1e-12 and float(moduli[1]) > lam + 0.1
    certified = stub(C1Verdict.C1, "certified by the stub of this test")
    result = c1_zorin_every_n(bad, 4, certify=certified, per_valence=False)
    assert result.status == "refuted" and result.failure == 16
    good = c1_zorin_every_n(SQRT3, 4, certify=certified, per_valence=False)
    assert good.status == "undecided" and good.summary.startswith("the spectral conditions hold for every n")


@pytest.mark.parametrize("t", [sp.Rational(-1, 2), sp.Rational(1, 3), sp.Rational(9, 10), sp.Integer(1)])
@pytest.mark.parametrize("root", [sp.Rational(1, 5), T / 3, sp.Rational(-5, 11)])
def test_the_scaled_schur_cohn_polynomials_decide_the_disc_of_radius_lambda_t(t, root):
    lam = (2 + 2 * T) / 9
    poly = sp.expand((X - root) * (X + sp.Rational(1, 20)))
    inside = all(abs(r) < lam.subs(T, t) for r in (root.subs(T, t), sp.Rational(-1, 20)))
    deltas = [d.subs(T, t) for d in scaled_deltas(poly, lam)]
    assert all(d > 0 for d in deltas) == inside
    # the same signs as the test with the number lambda(t) for the radius
    plain = schur_cohn_conditions(sp.Poly(poly.subs(T, t), X), lam.subs(T, t))
    assert [sp.sign(d) for d in deltas] == [sp.sign(d) for d in plain]


def test_the_other_frequencies_take_lambda_increasing_and_bound_the_rest_by_lambda_t0():
    lam, t0 = (2 + 2 * T) / 9, t_lower_bound(16)
    low = lam.subs(T, t0)  # 2/9 + 2 t0/9, just below lambda_1(16)
    below, above = low - sp.Rational(1, 100), low + sp.Rational(1, 10**6)
    ok = other_frequencies_in_t(sp.expand((X - lam) * (X - below)), lam, t0, 16, 1)
    assert ok.status == "proved" and dict(ok.formulas)["m"] == 1
    # a rest root above lambda(t0): lambda(t0) is only a sufficient bound, so open, not failed
    assert other_frequencies_in_t(sp.expand((X - lam) * (X - above)), lam, t0, 16, 1).status == "open"
    # lambda decreasing: at s < t the block's lambda(s) is above lambda(t); not shown
    down = (2 - T) / 9
    assert other_frequencies_in_t(sp.expand(X - down), down, t0, 16, 1).status == "open"
