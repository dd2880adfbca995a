"""Correct rounding of Arb balls to float64.

A ball rounds correctly when every point in it has the same nearest float64 (ties to even):
it must lie strictly between the two rounding boundaries around a candidate. A ball around 0
rounds to 0.0 only inside ``(-2^-1075, 2^-1075)``.
"""

from __future__ import annotations

import math

import flint

__all__ = ["round_ball"]

arb = flint.arb
_TINY = None  # 2^-1075 as an Arb number, made on first use
_INF = math.inf


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
