"""Signs and zeros of rational functions of the valence ``n`` for every integer ``n >= n_0`` (exact).

Statements "for every valence" often reduce to a rational function ``f(n)`` (a weight, a resultant)
that must not vanish, or must be positive, at every integer ``n >= n_0``. Both are decided exactly:

* :func:`integer_zeros`: the integers ``n >= n_0`` where the numerator or the denominator of ``f``
  vanishes, from the linear factors of their factorisations over ``Q`` (a factor of degree ``>= 2``
  that is irreducible over ``Q`` has no rational, hence no integer, root);
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

import sympy as sp

from symdecomp.errors import InvalidInputError

__all__ = ["integer_zeros", "positive_from"]


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
        if poly.degree() > 0 and poly.count_roots(start, None) > 0:
            return False
    return bool(numerator.eval(start) / denominator.eval(start) > 0)
