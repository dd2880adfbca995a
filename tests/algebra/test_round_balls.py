"""Balls rounded in one pass (:func:`round_balls`): the correctly rounded float64 or None, as :func:`round_ball` says.

The reference is exact: each ball holds a rational, and CPython's ``float(Fraction)`` is its correctly
rounded value (ties to even).
"""

from __future__ import annotations

import random
from fractions import Fraction

import flint

from symdecomp.algebra.rounding import round_ball, round_balls, round_shared_balls


def _ball(q: Fraction) -> flint.arb:
    return flint.arb(flint.fmpq(q.numerator, q.denominator))


def test_round_balls_gives_the_correctly_rounded_doubles():
    rnd = random.Random(40)
    values = [Fraction(rnd.randint(-10**40, 10**40), rnd.randint(1, 10**40)) * Fraction(2) ** rnd.randint(-200, 200)
              for _ in range(3000)]
    with flint.ctx.workprec(256):
        rounded = round_balls([_ball(q) for q in values])
    assert rounded == [float(q) for q in values]


def test_a_ball_on_a_rounding_boundary_or_around_zero_is_not_rounded_as_a_guess():
    # exactly half-way between two doubles (the tie, decided only by ties-to-even, which a ball cannot show),
    # a ball straddling that point, an exact zero, a ball around 0 wider than 2^-1075, and a subnormal
    tie = Fraction(1) + Fraction(1, 2**53)
    with flint.ctx.workprec(256):
        balls = [_ball(tie), _ball(tie) + flint.arb(0, 2.0**-80), flint.arb(0), flint.arb(0, 2.0**-1000),
                 _ball(Fraction(3, 2**1070))]
        assert round_balls(balls) == [round_ball(x) for x in balls] == [None, None, 0.0, None, float(Fraction(3, 2**1070))]


def test_shared_balls_round_as_each_would_alone():
    """A list repeating its ball objects (a rational eigenvector's period) rounds, object by object, to the exact
    values' float64s, with None where a ball does not round, wherever the object repeats."""
    rnd = random.Random(41)
    values = [Fraction(rnd.randint(-10**30, 10**30), rnd.randint(1, 10**30)) for _ in range(40)]
    tie = Fraction(1) + Fraction(1, 2**53)
    with flint.ctx.workprec(256):
        period = [_ball(q) for q in values] + [_ball(tie)]
        balls = [flint.arb(0)] + period * 7
        rounded = round_shared_balls(balls)
    assert rounded == [0.0] + ([float(q) for q in values] + [None]) * 7
