"""The exact sign of a real algebraic number written as a sympy expression.

An expression built from rationals, ``+ * /``, integer and half-integer powers, ``sqrt`` and
``cos``/``sin`` of rational multiples of ``pi`` is an algebraic number. Its sign is decided in
two ways that never guess:

* an Arb ball (:func:`symdecomp.algebra.compile.compile_expression`, engine ``"arb"``) that
  excludes 0 gives the sign, rigorously;
* a ball that holds 0 at the first precision is tested for being exactly 0 with sympy's
  ``minimal_polynomial`` (an algebraic number is 0 iff its minimal polynomial is ``x``); a
  nonzero number is then separated from 0 by raising the precision, which ends for every
  nonzero number (the loop stops at :data:`MAX_BITS` and says so).

>>> exact_sign(sp.cos(sp.pi / 5) - (1 + sp.sqrt(5)) / 4)
0
>>> exact_sign(sp.sqrt(2) - sp.Rational(99, 70))
-1
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.errors import PrecisionError

__all__ = ["exact_sign", "real_ball", "rational_between", "MAX_BITS"]

#: The highest precision (bits) tried before a sign is reported as not separated.
MAX_BITS = 1 << 14

_X = sp.Symbol("x")


def real_ball(expr, prec: int = 128) -> flint.arb:
    """A rigorous Arb enclosure of the real number ``expr`` at ``prec`` bits."""
    f = compile_expression(sp.sympify(expr, strict=True), (), "arb")
    with flint.ctx.workprec(prec):
        value = flint.acb(f())
        if not value.imag.contains(0):
            raise PrecisionError(f"{expr} is not a real number")
        return +value.real


def _is_zero(expr) -> bool | None:
    try:
        return sp.minimal_polynomial(expr, _X) == _X
    except (NotImplementedError, sp.PolificationFailed, ValueError):  # pragma: no cover - not an algebraic expression sympy reads
        return None


def exact_sign(expr) -> int:
    """``-1``, ``0`` or ``1``: the sign of the real algebraic number ``expr``, decided exactly (module docstring)."""
    expr = sp.sympify(expr, strict=True)
    if expr.is_Rational:
        return int(sp.sign(expr))
    prec, zero_tested = 64, False
    while prec <= MAX_BITS:
        ball = real_ball(expr, prec)
        if ball > 0:
            return 1
        if ball < 0:
            return -1
        if not zero_tested:
            zero_tested = True
            verdict = _is_zero(sp.expand(expr))
            if verdict:
                return 0
        prec *= 4
    raise PrecisionError(f"the sign of {sp.sstr(expr)[:80]} is not separated from 0 at {MAX_BITS} bits"
                         + ("" if zero_tested else " (and not shown to be 0)"))


def rational_between(lo, hi) -> sp.Rational:
    """A rational strictly between the real algebraic numbers ``lo < hi`` (either may be ``None``: unbounded), small
    denominator first; chosen from certified balls, so it is strictly inside."""
    if lo is None and hi is None:
        return sp.Integer(0)
    if lo is None or hi is None:
        b = real_ball(hi if lo is None else lo, 64)
        return sp.floor(_to_rational(b.lower())) - 1 if lo is None else sp.ceiling(_to_rational(b.upper())) + 1
    prec = 64
    while True:
        a, b = real_ball(lo, prec), real_ball(hi, prec)
        if a.upper() < b.lower():
            break
        if prec > MAX_BITS:
            raise PrecisionError(f"{sp.sstr(lo)[:40]} and {sp.sstr(hi)[:40]} are not separated at {MAX_BITS} bits")
        prec *= 4
    left, right = _to_rational(a.upper()), _to_rational(b.lower())
    for q in range(1, 10_001):
        p = sp.floor(left * q) + 1
        if sp.Rational(p, q) < right:
            return sp.Rational(p, q)
    return (left + right) / 2


def _to_rational(x) -> sp.Rational:
    """The exact (dyadic) midpoint of an Arb ball whose radius is 0 (an end of a ball)."""
    man, exp = x.mid().man_exp()
    return sp.Rational(int(man)) * sp.Integer(2) ** int(exp)
