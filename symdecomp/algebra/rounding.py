"""Correct rounding of Arb balls to float64 and to decimal digits.

A ball rounds correctly when every point in it has the same nearest float64 (ties to even):
it must lie strictly between the two rounding boundaries around a candidate. A ball around 0
rounds to 0.0 only inside ``(-2^-1075, 2^-1075)``. :func:`round_ball_decimal` does the same for
``D`` significant decimal digits, in one step from the ball.
"""

from __future__ import annotations

import math

import flint
import numpy as np

__all__ = ["round_ball", "round_balls", "round_shared_balls", "round_ball_decimal", "split_balls", "round_products", "TINY_EXPONENT"]

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


def round_balls(balls) -> list[float | None]:
    """:func:`round_ball` of each ball, the cheap case for all at once: the candidate is the midpoint's float64 ``m``,
    accepted when ``|x - m|`` is below half the smaller gap to ``m``'s neighbours (shrunk by ``2^-20``: strictly
    inside the rounding cell, in certified Arb comparisons); the others (a ball around 0, near a rounding boundary,
    subnormal or huge) go to :func:`round_ball`. The same floats, in fewer Arb operations per ball.

    >>> with flint.ctx.workprec(200):
    ...     round_balls([arb(1) / 3, arb(0), arb("0.5 +/- 0.1")]) == [1 / 3, 0.0, None]
    True
    >>> round_balls([arb(0), arb("0 +/- 1e-400"), arb("0 +/- 1e-300")])  # exact; inside (-2^-1075, 2^-1075); not
    [0.0, 0.0, None]
    """
    balls = list(balls)
    hi = [float(x) for x in balls]
    ahi = np.abs(np.array(hi, dtype=float))
    with np.errstate(invalid="ignore"):
        gap = np.minimum(np.nextafter(ahi, _INF) - ahi, ahi - np.nextafter(ahi, 0.0)) * (0.5 - 2.0**-21)
    gap[~((ahi > 2.0**-1020) & (ahi < 2.0**1020))] = -1.0  # 0, subnormal, huge or not finite: round_ball decides
    # an exact 0 (a symmetry's, set exactly) is 0.0 at once, without round_ball's test of a ball around 0
    return [m if g > 0 and abs(x - m) < g else 0.0 if m == 0.0 and x.is_zero() else round_ball(x)
            for x, m, g in zip(balls, hi, gap.tolist())]


def round_shared_balls(balls) -> list[float | None]:
    """:func:`round_balls` of a list whose balls repeat the same objects (a period of balls shared by its
    repetitions, as a rational eigenvector's are): each object rounded once.

    >>> with flint.ctx.workprec(200):
    ...     third = arb(1) / 3
    ...     round_shared_balls([third, arb(1), third]) == [1 / 3, 1.0, 1 / 3]
    True
    """
    balls = list(balls)
    first: dict[int, arb] = {}
    for x in balls:
        first.setdefault(id(x), x)  # the objects stay alive in balls: their ids are theirs
    rounded = dict(zip(first, round_balls(first.values())))
    return [rounded[id(x)] for x in balls]


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


def split_balls(balls) -> np.ndarray:
    """``(3, M)`` float64: ``hi``, ``lo`` and ``err`` of each ball, every point of which is within ``err`` of ``hi + lo``.

    ``hi`` is the midpoint's nearest float64, ``lo`` the remainder's; ``err`` bounds the rest and
    the radius (an Arb upper bound, widened by ``2^-50`` for its own conversion).
    """
    out = np.empty((3, len(balls)))
    for q, x in enumerate(balls):
        hi = float(x)
        rest = x - hi
        lo = float(rest)
        out[0, q], out[1, q], out[2, q] = hi, lo, float(abs(rest - lo).upper())
    out[2] *= 1 + 2.0**-50
    return out


_SPLIT = 134217729.0  # 2^27 + 1: Dekker's splitter for float64


def _two_product(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(p, e)`` with ``p + e = a b`` exactly (Dekker; no overflow or underflow for the magnitudes checked by the caller)."""
    p = a * b
    t = _SPLIT * a
    ah = t - (t - a)
    al = a - ah
    t = _SPLIT * b
    bh = t - (t - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def round_products(s: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(values, certified)``: the float64 nearest to ``s_q c_q`` for split balls ``s``, ``c`` (:func:`split_balls`'
    rows, gathered to one shape each), and where that nearest float64 is proved.

    The product of ``hi + lo`` pairs is formed in double-double (error-free ``hi hi``, the cross terms
    rounded) with a bound on everything left out, rounding errors included; the candidate is the sum
    rounded once, and it is the correctly rounded value where the exact remainder plus the bound is
    below half the gap to either neighbour. An exact 0 factor gives +0.0. Entries not certified
    (products near a rounding boundary, or outside ``[2^-900, 2^900]``) are for :func:`round_ball`.
    """
    s_hi, s_lo, s_err = s
    c_hi, c_lo, c_err = c
    with np.errstate(over="ignore", invalid="ignore"):
        p, e = _two_product(s_hi, c_hi)
        t1, t2 = s_hi * c_lo, s_lo * c_hi
        t = t1 + t2
        q = e + t
        y = p + q
        bb = y - p
        r = (p - (y - bb)) + (q - bb)  # p + q = y + r exactly
        bound = (abs(s_hi) * c_err + abs(c_hi) * s_err + abs(s_lo * c_lo) + abs(s_lo) * c_err + abs(c_lo) * s_err
                 + s_err * c_err + (abs(t1) + abs(t2) + abs(t) + abs(q)) * 2.0**-52)
        ay = abs(y)
        gap = np.minimum(np.nextafter(ay, np.inf) - ay, ay - np.nextafter(ay, 0.0)) / 2
        certified = ((abs(r) + bound) * (1 + 2.0**-40) < gap) & (ay > 2.0**-900) & (ay < 2.0**900)
        certified &= (abs(s_hi) < 2.0**500) & (abs(c_hi) < 2.0**500)
    zero = ((c_hi == 0) & (c_lo == 0) & (c_err == 0)) | ((s_hi == 0) & (s_lo == 0) & (s_err == 0))
    return np.where(zero, 0.0, y), certified | zero
