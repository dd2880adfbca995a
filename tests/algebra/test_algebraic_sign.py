"""Exact signs of real algebraic numbers: balls decide, a minimal polynomial proves zero."""

import sympy as sp

from symdecomp.algebra.algebraic_sign import exact_sign


def test_signs_near_zero_and_exact_zero():
    c = sp.cos(sp.pi / 7)
    # cos(pi/7) is a root of 8x^3 - 4x^2 - 4x + 1: exactly zero, though no ball shows it
    assert exact_sign(8 * c**3 - 4 * c**2 - 4 * c + 1) == 0
    assert exact_sign(8 * c**3 - 4 * c**2 - 4 * c + 1 + sp.Rational(1, 10**40)) == 1
    assert exact_sign(sp.sqrt(2) - sp.Rational(665857, 470832)) == -1  # a convergent of sqrt(2), 1e-12 away
    assert exact_sign(sp.Rational(-3, 7)) == -1
