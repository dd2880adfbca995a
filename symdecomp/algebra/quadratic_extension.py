"""Exact arithmetic in a quadratic extension ``Q(x)(r)``, ``r^2 = D(x)``: a rational expression in one symbol and one
square root reduced to the rational polynomial it equals.

An element is ``(a + b r)/d`` with ``a``, ``b``, ``d`` rational polynomials in ``x`` (FLINT ``fmpq_poly``); sums and
products follow ``r^2 = D``, and a quotient's denominator is made free of ``r`` by its conjugate,
``1/(a + b r) = (a - b r)/(a^2 - b^2 D)``. An expression with no square root is the case ``D = 0``. What sympy's
``together``/``rem``/``div`` would do with ``r`` as a second generator, in a few FLINT operations: about ten times
faster on Eq. 51's closed form of the characteristic polynomial.

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> r = sp.sqrt(x**2 + 1)
>>> polynomial_in(((1 + r) ** 3 + (1 - r) ** 3) / 2, x)        # 1 + 3 r^2
3*x^2 + 4
>>> polynomial_in(r + x, x) is None                              # r remains: not a polynomial in x
True
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.numbers import rational_poly, to_fmpq

__all__ = ["NotInExtension", "polynomial_in"]

#: ``(a, b, d)``: the element ``(a + b r)/d``.
_Element = tuple[flint.fmpq_poly, flint.fmpq_poly, flint.fmpq_poly]


class NotInExtension(ValueError):
    """The expression is not rational in the symbol and at most one square root (another symbol, a second root, a
    power that is not an integer, a coefficient that is not rational), or one of its denominators is zero."""


def polynomial_in(value: sp.Expr, symbol: sp.Symbol) -> flint.fmpq_poly | None:
    """The rational polynomial in ``symbol`` that ``value`` equals exactly, ``value`` a rational expression in
    ``symbol`` and at most one square root ``sqrt(D(symbol))``; ``None`` when ``value`` is no polynomial in ``symbol``
    (``r`` remains, or the denominator does not divide). Raises :class:`NotInExtension` for an expression of another
    form."""
    roots = {p for p in value.atoms(sp.Pow) if p.exp == sp.S.Half}
    if len(roots) > 1:
        raise NotInExtension(f"{len(roots)} square roots")
    root = next(iter(roots), None)
    D = _rational_poly(root.base, symbol) if root is not None else flint.fmpq_poly([])
    a, b, d = _walk(value, root, symbol, D)
    if not b.is_zero():
        return None
    quotient, rest = divmod(a, d)
    return quotient if rest.is_zero() else None


def _rational_poly(e: sp.Expr, symbol: sp.Symbol) -> flint.fmpq_poly:
    poly = rational_poly(e, symbol)
    if poly is None:
        raise NotInExtension(f"{e} is not a rational polynomial in {symbol}")
    return poly


def _walk(e: sp.Expr, root: sp.Expr | None, symbol: sp.Symbol, D: flint.fmpq_poly) -> _Element:
    one, zero = flint.fmpq_poly([1]), flint.fmpq_poly([])
    if root is not None and e == root:
        return zero, one, one
    if e == symbol:
        return flint.fmpq_poly([0, 1]), zero, one
    if e.is_Rational:
        return flint.fmpq_poly([to_fmpq(e)]), zero, one
    if isinstance(e, (sp.Add, sp.Mul)):
        parts = [_walk(x, root, symbol, D) for x in e.args]
        out = parts[0]
        for a2, b2, d2 in parts[1:]:
            a1, b1, d1 = out
            out = ((a1 * d2 + a2 * d1, b1 * d2 + b2 * d1, d1 * d2) if isinstance(e, sp.Add)
                   else (a1 * a2 + b1 * b2 * D, a1 * b2 + a2 * b1, d1 * d2))
        return out
    if isinstance(e, sp.Pow) and e.exp.is_Integer:
        return _power(_walk(e.base, root, symbol, D), int(e.exp), D)
    raise NotInExtension(f"{type(e).__name__} {e}")


def _power(base: _Element, k: int, D: flint.fmpq_poly) -> _Element:
    a, b, d = base
    if k < 0:  # 1/((a + b r)/d) = d (a - b r)/(a^2 - b^2 D)
        norm = a * a - b * b * D
        if norm.is_zero():
            raise NotInExtension("a denominator is zero")
        a, b, d, k = d * a, -(d * b), norm, -k
    out = (flint.fmpq_poly([1]), flint.fmpq_poly([]), flint.fmpq_poly([1]))
    for _ in range(k):
        out = (out[0] * a + out[1] * b * D, out[0] * b + out[1] * a, out[2] * d)
    return out
