"""Products of split balls rounded in double-double: certified entries are the correctly rounded float64.

The reference is exact: each factor is a rational held in a ball, and CPython's ``float(Fraction)`` is
the correctly rounded value (ties to even) of the exact product.
"""

from __future__ import annotations

import random
from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.rounding import round_products, split_balls


def _ball(q: Fraction) -> flint.arb:
    return flint.arb(flint.fmpq(q.numerator, q.denominator))


def test_certified_products_are_the_correctly_rounded_doubles():
    rnd = random.Random(33)
    pairs = [(Fraction(rnd.randint(-10**40, 10**40), rnd.randint(1, 10**40)), Fraction(rnd.randint(-10**30, 10**30), rnd.randint(1, 10**30)))
             for _ in range(2000)]
    with flint.ctx.workprec(256):
        s, c = split_balls([_ball(a) for a, _ in pairs]), split_balls([_ball(b) for _, b in pairs])
    values, certified = round_products(s, c)
    assert certified.mean() > 0.99  # at 256 bits nearly every product is decided
    exact = np.array([float(a * b) for a, b in pairs])
    assert (values[certified].view("u8") == exact[certified].view("u8")).all()


def test_a_product_on_a_rounding_boundary_is_not_certified_and_zero_is_plus_zero():
    tie = Fraction(1) + Fraction(1, 2**53)  # exactly halfway between 1 and the next double
    with flint.ctx.workprec(256):
        s = split_balls([_ball(tie), _ball(Fraction(-3, 7)), _ball(Fraction(5))])
        c = split_balls([_ball(Fraction(1)), flint.arb(0), _ball(Fraction(1, 3))])
    values, certified = round_products(s, c)
    assert not certified[0]  # the exact value sits on the boundary: left to round_ball, which refuses it
    assert certified[1] and values[1] == 0.0 and not np.signbit(values[1])  # -3/7 * 0 is +0.0, as in the file
    assert certified[2] and values[2] == float(Fraction(5, 3))
