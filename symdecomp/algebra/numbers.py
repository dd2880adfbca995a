"""Conversions between the exact number types the package computes with: one home for each of them.

The same rational number travels as a sympy ``Rational`` (symbolic work), a ``fractions.Fraction``
(exact arithmetic in pure Python: meshes, small matrices), a FLINT ``fmpq`` (fast exact linear
algebra and polynomials), an Arb ball (certified interval arithmetic) or an mpmath number (the
numeric cross-checks). Each function here takes any exact rational (``int``, ``Fraction``, sympy
``Rational``/``Integer``, FLINT ``fmpq``/``fmpz``) and returns one type:

======================  =========================================================================
:func:`to_fraction`     ``fractions.Fraction``
:func:`to_fmpq`         ``flint.fmpq``
:func:`to_sympy`        sympy ``Rational`` (any other sympy object is returned as it is)
:func:`to_arb`          ``flint.arb`` (exact when the denominator is a power of 2; an ``arb`` is returned as it is)
:func:`to_mpf`          ``mpmath.mpf`` at the current mpmath precision
:func:`rational_poly`   ``flint.fmpq_poly`` from a sympy polynomial with rational coefficients (else ``None``)
======================  =========================================================================

Floats are refused (exact means exact): :class:`~symdecomp.errors.InvalidInputError` names the value.

>>> to_fmpq(sp.Rational(3, 8)), to_fraction(flint.fmpq(3, 8)), to_sympy(Fraction(3, 8))
(3/8, Fraction(3, 8), 3/8)
"""

from __future__ import annotations

from fractions import Fraction

import flint
import mpmath
import sympy as sp

from symdecomp.errors import InvalidInputError

__all__ = ["to_fraction", "to_fmpq", "to_sympy", "to_arb", "to_mpf", "numerator_denominator", "rational_poly"]


def numerator_denominator(x) -> tuple[int, int]:
    """``(p, q)`` as Python integers, ``q > 0``, for an exact rational ``x`` (see the module docstring)."""
    kind = type(x)  # the common exact types first, by identity: the eigen-data convert about 10^5 rationals a file
    if kind is int:
        return x, 1
    if kind is Fraction:
        return x.numerator, x.denominator
    if kind is flint.fmpq:
        return int(x.p), int(x.q)
    if isinstance(x, bool):
        return int(x), 1
    if isinstance(x, int):
        return x, 1
    if isinstance(x, Fraction):
        return x.numerator, x.denominator
    if isinstance(x, sp.Rational):  # sympy Integer too
        return int(x.p), int(x.q)
    if isinstance(x, flint.fmpq):
        return int(x.p), int(x.q)
    if isinstance(x, flint.fmpz):
        return int(x), 1
    raise InvalidInputError(f"expected an exact rational number, got {x!r} ({type(x).__name__})")


def to_fraction(x) -> Fraction:
    """``x`` as a ``fractions.Fraction``."""
    if isinstance(x, Fraction):
        return x
    return Fraction(*numerator_denominator(x))


def to_fmpq(x) -> flint.fmpq:
    """``x`` as a FLINT ``fmpq``."""
    if isinstance(x, flint.fmpq):
        return x
    return flint.fmpq(*numerator_denominator(x))


def to_sympy(x) -> sp.Expr:
    """``x`` as a sympy ``Rational``; a sympy object is returned as it is (an expression in ``n``, say)."""
    if isinstance(x, sp.Basic):
        return x
    return sp.Rational(*numerator_denominator(x))


def to_arb(x) -> flint.arb:
    """``x`` as an Arb ball at the current FLINT precision; an ``arb`` is returned as it is."""
    if isinstance(x, flint.arb):
        return x
    p, q = numerator_denominator(x)
    return flint.arb(p) / q


def to_mpf(x) -> mpmath.mpf:
    """``x`` as an mpmath number, correctly rounded at the current mpmath precision."""
    p, q = numerator_denominator(x)
    return mpmath.mpf(p) / q


def rational_poly(expr, symbol: sp.Symbol) -> flint.fmpq_poly | None:
    """``expr`` (a sympy expression) as an ``fmpq_poly`` in ``symbol``; ``None`` where it is not a polynomial in ``symbol``
    with rational coefficients (another symbol, a root, a negative power): the caller names the problem.

    >>> x = sp.Symbol("x")
    >>> rational_poly(sp.Rational(1, 2) * x**2 - 3, x), rational_poly(sp.sqrt(2) * x, x)
    (1/2*x^2 + (-3), None)
    """
    try:
        poly = sp.Poly(expr, symbol, domain=sp.QQ)
    except sp.polys.polyerrors.BasePolynomialError:
        return None
    return flint.fmpq_poly([flint.fmpq(int(c.numerator), int(c.denominator)) for c in reversed(poly.all_coeffs())])
