"""The Schur-Cohn steps with an algebraic radius ``lambda_1`` (issue 30): exact in ``Q(lambda_1)``, checked against roots.

Each verdict of :func:`field_positive` on the reduced Schur-Cohn polynomials is compared with the polynomial's roots
computed by mpmath at 40 digits (every root below ``lambda_1`` in modulus, or not); a root exactly on the circle
``|x| = lambda_1`` makes a polynomial reduce to exactly 0; a factor with coefficients in ``Q(t)`` holding the largest
root of ``p_1`` leaves the ``lambda-one`` step open, naming it.
"""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from symdecomp.algebra.algebraic_sign import exact_sign
from symdecomp.verify.c1_every_n import T
from symdecomp.verify.c1_zorin_every_n import FrequencyPolynomials, _lambda_one
from symdecomp.verify.zorin_lambda_algebraic import (
    LAMBDA,
    algebraic_radius,
    constant_roots,
    field_deltas,
    field_positive,
)

X = sp.Symbol("x")
QUADRATIC = 16 * X**2 - 8 * X - 1  # roots (1 +- sqrt 2)/4
CUBIC = X**3 - X**2 / 2 - sp.Rational(1, 10)  # one real root near 0.69, two complex ones of modulus near 0.38


def _largest(f: sp.Expr) -> sp.Expr:
    return max(constant_roots(sp.expand(f * (8 * X - 1))), key=lambda r: abs(complex(r)))


def _below(poly: sp.Expr, lam: sp.Expr) -> bool:
    """Every root of ``poly`` below ``lam`` in modulus, by mpmath at 40 digits (a margin of 10^-20 either way)."""
    with mpmath.workdps(40):
        coefficients = [mpmath.mpf(str(sp.N(c, 50))) for c in sp.Poly(poly, X).all_coeffs()]
        radius = mpmath.mpf(str(sp.N(lam, 50)))
        moduli = [abs(r) for r in mpmath.polyroots(coefficients, maxsteps=200, extraprec=200)]
        assert all(abs(m - radius) > mpmath.mpf(10) ** -20 for m in moduli)
        return all(m < radius for m in moduli)


@pytest.mark.parametrize("factor", [QUADRATIC, CUBIC])
@pytest.mark.parametrize("poly", [
    (4 * X - 1) * (4 * X + 1), X**2 + X / 2 + sp.Rational(1, 4), X**3 - sp.Rational(3, 10),
    (5 * X - 3) * (16 * X**2 - 4 * X - 1), X**2 - sp.Rational(2, 5) * X + sp.Rational(9, 25), X - sp.Rational(7, 10),
])
def test_the_verdict_in_the_field_agrees_with_the_roots(factor, poly):
    lam = _largest(factor)
    radius = algebraic_radius(lam)
    assert sp.Poly(radius.minimal.as_expr().subs(LAMBDA, X), X).monic() == sp.Poly(factor, X).monic()
    verdicts = [field_positive(d, radius, sp.Integer(-1), start=16, frequency=None, reach=2)[0]
                for d in field_deltas(sp.expand(poly), radius)]
    assert "open" not in verdicts
    assert all(v == "proved" for v in verdicts) == _below(poly, lam)


@pytest.mark.parametrize("factor", [QUADRATIC, CUBIC])
def test_dividing_out_lambda_one_leaves_its_conjugates_which_are_below_it(factor):
    lam = _largest(factor)
    radius = algebraic_radius(lam)
    poly = sp.expand((8 * X - 1) * factor)
    deltas = field_deltas(poly, radius, divide=True)
    assert len(deltas) == sp.degree(poly, X) - 1
    assert all(field_positive(d, radius, sp.Integer(-1), start=16, frequency=1, reach=2)[0] == "proved" for d in deltas)
    # not divided out, lambda_1 itself lies on the circle: one Schur-Cohn polynomial is exactly 0 in Q(lambda_1)
    undivided = field_deltas(poly, radius)
    assert 0 in undivided
    assert field_positive(0 * T, radius, sp.Integer(-1), start=16, frequency=1, reach=2)[0] == "failed"


def test_a_polynomial_in_t_is_proved_by_its_norm_and_refuted_with_a_valence_where_it_is_negative():
    radius = algebraic_radius(_largest(QUADRATIC))  # (1 + sqrt 2)/4 = 0.6036
    # roots t/2 and -1/8: below lambda_1 for t in [-1, 1) since 1/2 < 0.6036
    good = field_deltas(sp.expand((2 * X - T) * (8 * X + 1)), radius)
    assert all(field_positive(d, radius, sp.Integer(-1), start=16, frequency=None, reach=2)[0] == "proved" for d in good)
    # root 3 t/4 reaches modulus 3/4 > lambda_1 near t = +-1: the first frequency k where it exceeds lambda_1 is found
    bad = field_deltas(sp.expand(4 * X - 3 * T), radius)
    status, note, n = field_positive(bad[0], radius, sp.Integer(-1), start=16, frequency=None, reach=2)
    assert status == "failed" and n == 16
    k = int(note.split("k = ")[1].split(" ")[0])
    excess = [exact_sign(sp.Abs(3 * sp.cos(2 * sp.pi * j / 16) / 4) - _largest(QUADRATIC)) for j in range(3, k + 1)]
    assert excess[-1] == 1 and all(e == -1 for e in excess[:-1])


def _polys(p1: sp.Expr) -> FrequencyPolynomials:
    rest = sp.expand((X - 1) * (8 * X - 1))
    return FrequencyPolynomials({0: rest, 1: sp.expand(p1), -1: sp.expand(p1)}, sp.expand(8 * X - 1), 16)


def test_a_quadratic_factor_in_t_holding_the_largest_root_leaves_lambda_one_open_naming_it():
    in_t = X**2 - (1 + T) * X / 2 - sp.Rational(1, 16)  # its root near t = 1 is about 1.06 > (1 + sqrt 2)/4
    lam, step = _lambda_one(_polys((8 * X - 1) * QUADRATIC * in_t))
    assert lam is None and step.status == "open" and "of degree 2 in x with coefficients depending on t" in step.text
    assert str(sp.factor(in_t)) in step.text
    # scaled down so that its roots stay below (1 + sqrt 2)/4 at t_0 and at 1: lambda_1 is the quadratic's root
    small = X**2 - (1 + T) * X / 8 - sp.Rational(1, 64)
    lam, step = _lambda_one(_polys((8 * X - 1) * QUADRATIC * small))
    assert step.status == "proved" and sp.minimal_polynomial(lam, X) == QUADRATIC
