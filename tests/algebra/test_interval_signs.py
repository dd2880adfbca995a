"""Real roots and signs of rational polynomials on an interval in FLINT (Sturm sequences), against roots known in closed
form and against sympy's own root counting."""

from __future__ import annotations

import random

import flint
import pytest
import sympy as sp

from symdecomp.algebra.interval_signs import count_roots, odd_multiplicity_part, positive_on
from symdecomp.algebra.valence_signs import sign_on_interval

t = sp.Symbol("t")


def _fmpq_poly(expr) -> flint.fmpq_poly:
    return flint.fmpq_poly([flint.fmpq(int(c.p), int(c.q)) for c in reversed(sp.Poly(expr, t).all_coeffs())])


@pytest.mark.parametrize("k", [1, 2, 5, 8, 13])
@pytest.mark.parametrize(("low", "high"), [(-1, 1), (0, 1), (sp.Rational(-1, 3), sp.Rational(1, 2)), (1, 3)])
def test_chebyshev_roots_are_counted(k, low, high):
    """T_k has the k simple roots cos((2j - 1) pi/(2k)), j = 1..k; those in [low, high] are counted."""
    expected = sum(1 for j in range(1, k + 1) if low <= sp.cos((2 * j - 1) * sp.pi / (2 * k)) <= high)
    assert count_roots(flint.fmpq_poly(flint.fmpz_poly.chebyshev_t(k)), low, high) == expected


def test_roots_at_the_ends_and_multiple_roots_count_once():
    p = _fmpq_poly((t - sp.Rational(1, 2)) ** 3 * (t + 1) ** 2 * (t**2 - 2))
    assert count_roots(p, -1, sp.Rational(1, 2)) == 2 and count_roots(p, sp.Rational(-1, 2), 1) == 1
    assert count_roots(p, -2, 2) == 4 and count_roots(p, 2, 3) == 0
    assert odd_multiplicity_part(p) == _fmpq_poly((t - sp.Rational(1, 2)) * (t**2 - 2))  # monic


def test_signs():
    """(t - 1)^2 (t + 2) is nonnegative on [-2, 2] but not positive; (t - 1/2)^3 changes sign on [0, 1]; 0 is nonnegative."""
    square = _fmpq_poly((t - 1) ** 2 * (t + 2))
    assert positive_on(square, -2, 2, strict=False) and not positive_on(square, -2, 2)
    assert positive_on(square, sp.Rational(11, 10), 3)
    cube = _fmpq_poly((t - sp.Rational(1, 2)) ** 3)
    assert not positive_on(cube, 0, 1, strict=False) and positive_on(cube, sp.Rational(1, 2), 1, strict=False)
    assert positive_on(flint.fmpq_poly([]), 0, 1, strict=False) and not positive_on(flint.fmpq_poly([]), 0, 1)


def test_the_same_decisions_as_sympys_sturm_sequences():
    """Random products of rational and quadratic factors with repeated roots, some at the interval's ends: FLINT's
    decisions equal sympy's (count_roots and square-free factorisation) on each."""
    rng = random.Random(33)
    for _ in range(300):
        factors = [(t - sp.Rational(rng.randint(-4, 4), rng.choice([1, 2, 4]))) ** rng.randint(1, 3)
                   if rng.random() < 0.7 else t**2 - sp.Rational(rng.randint(-2, 3), rng.randint(1, 3))
                   for _ in range(rng.randint(0, 4))]
        expr = sp.expand(rng.choice([1, -1, sp.Rational(3, 7)]) * sp.Mul(*factors))
        low = sp.Rational(rng.randint(-4, 2), rng.choice([1, 2]))
        high = low + sp.Rational(rng.randint(1, 4), rng.choice([1, 2]))
        poly = sp.Poly(expr, t)
        assert count_roots(_fmpq_poly(expr), low, high) == poly.count_roots(low, high)
        odd = [f for f, m in poly.sqf_list()[1] if m % 2 and f.degree() > 0]
        inside = sum(f.count_roots(low, high) - (f.eval(low) == 0) - (f.eval(high) == 0) for f in odd)
        assert positive_on(_fmpq_poly(expr), low, high) is bool(poly.count_roots(low, high) == 0 and poly.eval(low) > 0)
        if inside:
            assert positive_on(_fmpq_poly(expr), low, high, strict=False) is False
        assert sign_on_interval(expr, t, low, high, strict=False) is positive_on(_fmpq_poly(expr), low, high, strict=False)


def test_roots_from_a_valence_on_as_sympy_counts_them():
    """The real roots in [start, oo) (positive_from's question), counted in FLINT up to Cauchy's bound, as sympy counts
    them; the roots 9/2 and 40 of (2n - 9)(n - 40)(n^2 + 1) lie beyond 3, 9/2 and 40, not beyond 41."""
    from symdecomp.algebra.valence_signs import _roots_from

    n = sp.Symbol("n")
    poly = sp.Poly((2 * n - 9) * (n - 40) * (n**2 + 1), n)
    assert [_roots_from(poly, s) for s in (3, sp.Rational(9, 2), 40, 41)] == [2, 2, 1, 0]
    rng = random.Random(34)
    for _ in range(200):
        expr = sp.expand(sp.Mul(*[n - sp.Rational(rng.randint(-50, 50), rng.randint(1, 3)) for _ in range(rng.randint(1, 4))])
                         * rng.choice([1, n**2 + rng.randint(1, 5), n**2 - rng.randint(1, 30)]))
        start = rng.randint(-5, 20)
        assert _roots_from(sp.Poly(expr, n), start) == sp.Poly(expr, n).count_roots(start, None)
