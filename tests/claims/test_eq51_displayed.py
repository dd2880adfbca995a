"""Eq. 51's displayed closed form expanded exactly at each valence: one square root reduced over Q (issue 33)."""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial
from symdecomp.analysis.tuning import with_free_vertex_rule
from symdecomp.claims.s6_cb_subdivision import _displayed_expression_agrees, _one_root_polynomial, _reduced_in_flint, _Unread
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import lam
from symdecomp.symbols import n as N

x = sp.Symbol("x")


def test_one_square_root_is_reduced_exactly():
    """((1 + r)^3 + (1 - r)^3)/2 = 1 + 3 r^2 with r^2 = x^2 + 1; divided by x^2 + 4/3 it is 3."""
    r = sp.sqrt(x**2 + 1)
    assert _one_root_polynomial(((1 + r) ** 3 + (1 - r) ** 3) / 2, x) == sp.Poly(3 * x**2 + 4, x, domain=sp.QQ)
    assert _one_root_polynomial(((1 + r) ** 3 + (1 - r) ** 3) / (6 * x**2 + 8), x) == sp.Poly(1, x, domain=sp.QQ)
    assert _one_root_polynomial(r + x, x) is None  # the root remains: not a polynomial in x
    assert _one_root_polynomial((1 + r) ** 2 / (x - 1), x) is None  # r remains after the reduction
    assert _one_root_polynomial(x**2 + 1, x) is None  # no root: left to sympy
    assert _one_root_polynomial(r + sp.sqrt(x), x) is None  # two roots


def test_the_displayed_expression_is_checked_against_the_matrix():
    """Catmull-Clark's displayed closed form agrees with the matrix at n = 3..6; one with lambda^n changed by a factor
    1 + 1/1000 does not, at the first valence."""
    free = with_free_vertex_rule(catmull_clark())
    expression = closed_form_characteristic_polynomial(free).expression
    assert _displayed_expression_agrees(free, expression, range(3, 7)) is None
    wrong = expression.xreplace({(lam / 16) ** N: sp.Rational(1001, 1000) * (lam / 16) ** N})
    assert wrong != expression
    assert _displayed_expression_agrees(free, wrong, range(3, 7)) == "n = 3, alpha = 0, beta = 0"


def test_the_flint_reduction_is_the_sympy_reduction():
    """FLINT's walk of ``(a + b r)/d`` gives the polynomial sympy's reduction gives (Catmull-Clark's displayed form at
    n = 3..8 with the vertex weights 0 and 1, and the small cases above), ``None`` where sympy's is ``None`` because ``r``
    or a denominator remains, and leaves to sympy what has no square root or two."""
    from symdecomp.analysis.charpoly import to_fmpq_poly
    from symdecomp.symbols import alpha, beta

    free = with_free_vertex_rule(catmull_clark())
    expression = closed_form_characteristic_polynomial(free).expression
    for k in range(3, 9):
        for values in ({alpha: 0, beta: 0}, {alpha: 1, beta: 0}, {alpha: 0, beta: 1}):
            value = expression.subs({N: k, **values})
            assert _reduced_in_flint(value, lam) == to_fmpq_poly(_one_root_polynomial(value, lam).as_expr(), lam)
    r = sp.sqrt(x**2 + 1)
    assert _reduced_in_flint(((1 + r) ** 3 + (1 - r) ** 3) / (6 * x**2 + 8), x) == flint.fmpq_poly([1])
    assert _reduced_in_flint(((1 + r) ** 3 + (1 - r) ** 3) / 2, x) == flint.fmpq_poly([4, 0, 3])
    assert _reduced_in_flint(r + x, x) is None and _reduced_in_flint((1 + r) ** 2 / (x - 1), x) is None
    assert _reduced_in_flint(1 / (1 + r) + 1 / (1 - r), x) is None  # -2/x^2: not a polynomial
    assert _reduced_in_flint(x**2 + 1, x) is _Unread and _reduced_in_flint(r + sp.sqrt(x), x) is _Unread
