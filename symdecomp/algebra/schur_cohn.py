"""All roots of a polynomial in the open unit disc, as finitely many polynomial inequalities: the Schur-Cohn test.

For ``q(y) = a_d y^d + ... + a_0`` with real coefficients and ``a_d != 0``, Schur and Cohn's transform

    ``(T q)(y) = (a_d q(y) - a_0 q*(y))/y``,  ``q*(y) = y^d q(1/y)`` (the reversed polynomial),

has degree ``d - 1`` and leading coefficient ``delta = a_d^2 - a_0^2``. If ``delta > 0`` then ``q`` and ``T q`` have
the same number of roots outside the open disc (Rouche's theorem on the unit circle, where ``|a_0 q*| < |a_d q|``), and
if ``delta <= 0`` the product of the roots, ``|a_0/a_d| >= 1``, puts one on or outside the circle. So every root of
``q`` lies in ``|y| < 1`` exactly when the ``d`` numbers ``delta_d, delta_(d-1), ..., delta_1`` of the repeated
transform are all positive (the Jury table's conditions in Schur's form).

When the coefficients are polynomials in a parameter ``t`` the ``delta_j`` are polynomials in ``t`` (no division is
ever made), so "every root in the disc for every ``t`` of an interval" is a sign condition on each of them, which
Sturm sequences decide exactly (:func:`symdecomp.algebra.valence_signs.sign_on_interval`). A disc of radius ``r``
is the unit disc of ``q(r y)``.

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> schur_cohn_conditions(sp.Poly(x**2 - x / 4, x))  # roots 0 and 1/4
(1, 15/16)
>>> schur_cohn_conditions(sp.Poly((x - sp.Rational(1, 2)) * x, x), radius=sp.Rational(1, 2))  # 1/2: on the circle
(1/16, 0)
"""

from __future__ import annotations

import sympy as sp

from symdecomp.errors import InvalidInputError

__all__ = ["schur_cohn_conditions"]


def schur_cohn_conditions(poly: sp.Poly, radius: sp.Expr | int = 1) -> tuple[sp.Expr, ...]:
    """``(delta_d, ..., delta_1)``: every root of ``poly`` has modulus ``< radius`` exactly when all are positive.

    ``poly`` is a :class:`sympy.Poly` in one generator whose coefficients may hold other symbols (a parameter ``t``),
    real for the real values of those symbols; ``radius`` is positive. The ``delta`` are expanded polynomials in the
    coefficients (module docstring); a leading coefficient that vanishes is refused (the degree would drop).
    """
    if not isinstance(poly, sp.Poly) or len(poly.gens) != 1:
        raise InvalidInputError(f"poly: expected a sympy Poly in one generator, got {type(poly).__name__}")
    radius = sp.sympify(radius, strict=True)
    if not (radius.is_positive and radius.is_real):
        raise InvalidInputError(f"radius: expected a positive real number, got {radius}")
    if poly.degree() < 1:
        return ()
    if sp.expand(poly.LC()) == 0:
        raise InvalidInputError("poly: its leading coefficient is 0")
    # q(y) = poly(radius y): the coefficients a_0..a_d, lowest first
    a = [sp.expand(c * radius**k) for k, c in enumerate(reversed(poly.all_coeffs()))]
    deltas = []
    while len(a) > 1:
        d = len(a) - 1
        deltas.append(sp.expand(a[d] ** 2 - a[0] ** 2))
        a = [sp.expand(a[d] * a[i + 1] - a[0] * a[d - 1 - i]) for i in range(d)]
    return tuple(deltas)
