"""Signs and zeros of rational functions of the valence ``n`` for every integer ``n >= n_0`` (exact).

Statements "for every valence" often reduce to a rational function ``f(n)`` (a weight, a resultant)
that must not vanish, or must be positive, at every integer ``n >= n_0``. Both are decided exactly:

* :func:`integer_zeros`: the integers ``n >= n_0`` where the numerator or the denominator of ``f``
  vanishes, from the linear factors of their factorisations over ``Q`` (a factor of degree ``>= 2``
  that is irreducible over ``Q`` has no rational, hence no integer, root);
* :func:`sign_on_interval`: a polynomial positive (or nonnegative) on a closed interval, from its roots there (in FLINT,
  :mod:`symdecomp.algebra.interval_signs`, where the coefficients and the ends are rational);
* :func:`positive_from`: ``f(x) > 0`` for every real ``x >= n_0``, when numerator and denominator have
  no real root in ``[n_0, oo)`` (Sturm sequences, :meth:`sympy.Poly.count_roots`) and ``f(n_0) > 0``.

>>> import sympy as sp
>>> n = sp.Symbol("n")
>>> integer_zeros((n - 5) * (n**2 + 1) / (2 * n - 7), n, 3)
(5,)
>>> positive_from(1 - sp.Rational(7, 4) / n, n, 3), positive_from(1 - 4 / n, n, 3)
(True, False)
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.interval_signs import count_roots, positive_on
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.errors import InvalidInputError

__all__ = ["integer_zeros", "positive_from", "sign_on_interval"]


def _parts(expr, variable: sp.Symbol) -> tuple[sp.Poly, sp.Poly]:
    expr = sp.together(sp.sympify(expr, strict=True))
    numerator, denominator = sp.fraction(sp.cancel(expr))
    free = (numerator.free_symbols | denominator.free_symbols) - {variable}
    if free:
        raise InvalidInputError(f"{expr} has free symbols {sorted(map(str, free))} besides {variable}")
    try:
        return sp.Poly(numerator, variable), sp.Poly(denominator, variable)
    except sp.PolynomialError as exc:  # e.g. cos(2*pi/n): not a rational function of the variable
        raise InvalidInputError(f"{expr} is not a rational function of {variable}") from exc


def integer_zeros(expr, variable: sp.Symbol, start: int) -> tuple[int, ...] | None:
    """The integers ``>= start`` where the numerator or denominator of ``expr`` vanishes; ``None`` when ``expr`` is 0."""
    numerator, denominator = _parts(expr, variable)
    if numerator.is_zero:
        return None
    out = set()
    for poly in (numerator, denominator):
        for factor, _ in poly.factor_list()[1]:
            if factor.degree() == 1:
                a, b = factor.all_coeffs()
                root = -b / a
                if root.is_Integer and root >= start:
                    out.add(int(root))
    return tuple(sorted(out))


def positive_from(expr, variable: sp.Symbol, start: int) -> bool:
    """Whether ``expr`` (a rational function of ``variable``) is positive for every real ``variable >= start``."""
    numerator, denominator = _parts(expr, variable)
    if numerator.is_zero:
        return False
    for poly in (numerator, denominator):
        if poly.degree() > 0 and _roots_from(poly, start) > 0:
            return False
    return bool(numerator.eval(start) / denominator.eval(start) > 0)


def sign_on_interval(expr, variable: sp.Symbol, low, high, *, strict: bool = True) -> bool | None:
    """Whether the polynomial ``expr`` in ``variable`` is positive (``strict``) or nonnegative on ``[low, high]``,
    exactly (Sturm sequences); ``None`` when ``expr`` is not a polynomial in ``variable`` alone.

    Nonnegative: no root of odd multiplicity strictly inside (the sign cannot change) and positive at a point
    that is no root; the zero polynomial is nonnegative, not positive.
    """
    try:
        poly = sp.Poly(sp.expand(sp.sympify(expr, strict=True)), variable)
    except sp.PolynomialError:
        return None
    if poly.free_symbols - {variable}:
        return None
    if poly.is_zero:
        return not strict
    if poly.domain in (sp.ZZ, sp.QQ) and all(isinstance(x, (int, sp.Rational)) for x in (low, high)):
        return _flint_sign(poly, low, high, strict)
    if strict:
        return poly.count_roots(low, high) == 0 and poly.eval(low) > 0
    odd = [f for f, mult in poly.sqf_list()[1] if mult % 2 == 1 and f.degree() > 0]
    if sum(f.count_roots(low, high) - (f.eval(low) == 0) - (f.eval(high) == 0) for f in odd):
        return False
    points = (low + (high - low) * sp.Rational(k, poly.degree() + 2) for k in range(1, poly.degree() + 2))
    return bool(poly.eval(next(x for x in points if poly.eval(x) != 0)) > 0)


def _flint_sign(poly: sp.Poly, low, high, strict: bool) -> bool:
    """:func:`sign_on_interval` for rational coefficients and ends, in FLINT (the same decision, much faster)."""
    return positive_on(flint.fmpq_poly([to_fmpq(c) for c in reversed(poly.all_coeffs())]), low, high, strict=strict)


def _roots_from(poly: sp.Poly, start) -> int:
    """The distinct real roots of ``poly`` in ``[start, oo)``; in FLINT up to Cauchy's bound ``1 + max |a_k/a_d|`` (beyond
    which there is no root) where the coefficients and ``start`` are rational."""
    if poly.domain not in (sp.ZZ, sp.QQ) or not isinstance(start, (int, sp.Rational)):
        return poly.count_roots(start, None)
    p = flint.fmpq_poly([to_fmpq(c) for c in reversed(poly.all_coeffs())])
    bound = 1 + max(abs(c / p.leading_coefficient()) for c in p.coeffs()[:-1])
    return count_roots(p, start, max(to_fmpq(start), bound))
