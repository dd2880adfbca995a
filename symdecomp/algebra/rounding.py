"""Correct rounding of Arb balls to float64 and to decimal digits.

A ball rounds correctly when every point in it has the same nearest float64 (ties to even):
it must lie strictly between the two rounding boundaries around a candidate. A ball around 0
rounds to 0.0 only inside ``(-2^-1075, 2^-1075)``. :func:`round_ball_decimal` does the same for
``D`` significant decimal digits, in one step from the ball.
"""

from __future__ import annotations

import math

import flint

__all__ = ["round_ball", "round_ball_decimal", "TINY_EXPONENT"]

arb = flint.arb
_TINY = None  # 2^-1075 as an Arb number, made on first use
_INF = math.inf
#: A ball inside ``(-2^-TINY_EXPONENT, 2^-TINY_EXPONENT)`` rounds to 0.0: half the smallest subnormal.
TINY_EXPONENT = 1075


def _round_slow(x: arb) -> float | None:
    global _TINY
    if x.contains(0):
        if _TINY is None:
            _TINY = arb(2) ** -1075
        return 0.0 if abs(x) < _TINY else None
    m = float(x.mid())
    for c in (m, math.nextafter(m, _INF), math.nextafter(m, -_INF)):
        below, above = math.nextafter(c, -_INF), math.nextafter(c, _INF)
        if math.isfinite(below) and math.isfinite(above):
            d = x - arb(c)
            if d > (arb(below) - arb(c)) / 2 and d < (arb(above) - arb(c)) / 2:
                return c
    return None


def round_ball(x: arb) -> float | None:
    """The float64 nearest to every point of the ball ``x`` (ties to even), or None if that differs.

    A candidate ``m`` (the midpoint converted to float) is accepted when the whole ball lies
    strictly between the midpoints to its two neighbours (certified Arb comparisons); otherwise
    its neighbours are tried, and a ball around 0 rounds to 0.0 inside ``(-2^-1075, 2^-1075)``.

    >>> round_ball(arb(1) / 3) is None      # 53 bits cannot tell 1/3 from its rounding boundary
    True
    >>> with flint.ctx.workprec(200):
    ...     round_ball(arb(1) / 3) == 1 / 3, round_ball(arb("0.5 +/- 0.1"))
    (True, None)
    """
    m = float(x)
    if m != 0.0 and 2.0**-1020 < abs(m) < 2.0**1020:
        d = x - m
        if d > (math.nextafter(m, -_INF) - m) / 2 and d < (math.nextafter(m, _INF) - m) / 2:
            return m
    return _round_slow(x)


def round_ball_decimal(x: arb, digits: int) -> str | None:
    """The exact value in ``x`` correctly rounded (ties to even) to ``digits`` significant digits, or None.

    One rounding, from the ball to the decimal: None when the ball does not lie inside a single
    rounding cell (a higher precision may decide it). An exact ball is rounded exactly. A ball
    around 0 gives ``"0"`` only inside ``(-2^-1075, 2^-1075)`` (where it also rounds to 0.0: the
    caller's exact zeros, e.g. of a symmetry), else None. The text is ``d.ddd...e+XX``.

    >>> with flint.ctx.workprec(200):
    ...     round_ball_decimal(arb(2) / 3, 20), round_ball_decimal(arb("0.5 +/- 0.1"), 5)
    ('6.6666666666666666667e-01', None)
    >>> round_ball_decimal(arb(1) / 16, 2)  # exactly 0.0625: the tie goes to the even 6.2
    '6.2e-02'
    """
    if x.contains(0):
        return "0" if round_ball(x) == 0.0 else None
    exponent = math.floor(math.log10(abs(float(x.mid()))))
    for e in (exponent, exponent + 1, exponent - 1):
        scaled = _scaled_round(x, digits - 1 - e)
        if scaled is None:
            return None
        if 10 ** (digits - 1) <= abs(scaled) < 10**digits:
            text = str(abs(scaled))
            return f"{'-' if scaled < 0 else ''}{text[0]}.{text[1:]}e{e:+03d}" if digits > 1 else f"{'-' if scaled < 0 else ''}{text}e{e:+03d}"
    return None


def _scaled_round(x: arb, k: int) -> int | None:
    """The integer nearest to ``x 10^k`` (ties to even) if every point of ``x`` has the same one, else None."""
    if x.rad() == 0:
        from fractions import Fraction

        m, e = (int(t) for t in x.mid().man_exp())
        return round(Fraction(m) * Fraction(2) ** e * Fraction(10) ** k)
    with flint.ctx.workprec(flint.ctx.prec + 4 * abs(k) + 64):  # 10^k exact, the product as sharp as x
        y = x * arb(10) ** k + arb(1) / 2
        below = y.floor()
    if not below.is_exact() or (y - below).contains(0):  # straddles a cell boundary, or might sit on it
        return None
    return int(below.unique_fmpz())
