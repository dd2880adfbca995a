"""A rational expression in one symbol and one square root reduced exactly to the polynomial it equals."""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from symdecomp.algebra.quadratic_extension import NotInExtension, polynomial_in

x = sp.Symbol("x")
r = sp.sqrt(x**2 + 1)


def test_one_square_root_is_reduced_exactly():
    """((1 + r)^3 + (1 - r)^3)/2 = 1 + 3 r^2 with r^2 = x^2 + 1; divided by x^2 + 4/3 it is 1."""
    assert polynomial_in(((1 + r) ** 3 + (1 - r) ** 3) / 2, x) == flint.fmpq_poly([4, 0, 3])
    assert polynomial_in(((1 + r) ** 3 + (1 - r) ** 3) / (6 * x**2 + 8), x) == flint.fmpq_poly([1])
    # (1 + r)(1 - r) = 1 - r^2 = -x^2, through a quotient whose denominator needs its conjugate
    assert polynomial_in(-x**4 / ((1 + r) * (1 - r)), x) == flint.fmpq_poly([0, 0, 1])


def test_no_square_root_is_the_rational_case():
    """With no root the walk is rational arithmetic in Q(x): (x^2 - 1)/(x - 1) = x + 1, 1/x is no polynomial."""
    assert polynomial_in((x**2 - 1) / (x - 1), x) == flint.fmpq_poly([1, 1])
    assert polynomial_in(1 / x + x, x) is None


def test_what_is_no_polynomial_is_none():
    assert polynomial_in(r + x, x) is None  # the root remains
    assert polynomial_in((1 + r) ** 2 / (x - 1), x) is None  # r remains after the reduction
    assert polynomial_in(1 / (1 + r) + 1 / (1 - r), x) is None  # -2/x^2: not a polynomial


@pytest.mark.parametrize("value", [r + sp.sqrt(x), r + sp.Symbol("y"), sp.exp(x) + r, r * sp.sqrt(2) + 1])
def test_another_form_is_refused(value):
    """Two square roots, another symbol, a function, an irrational coefficient: not an element of Q(x)(r)."""
    with pytest.raises(NotInExtension):
        polynomial_in(value, x)
