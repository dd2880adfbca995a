"""The Fourier patterns on the quad 1-ring (:mod:`symdecomp.analysis.fourier_patterns`): each entry is the wave's
cosine at the point's angle, for the frequencies of the valence's table and outside it."""

from __future__ import annotations

import flint
import pytest

from symdecomp.algebra.rounding import split_balls
from symdecomp.analysis.fourier_patterns import _pattern, trig_table


@pytest.mark.parametrize("n", [3, 4, 5, 8, 13])
@pytest.mark.parametrize("fn", ["cos", "sin"])
def test_a_pattern_is_the_wave_at_each_point(n, fn):
    """Entry ``e_k`` is ``ce cos(2 pi j k/n)`` (or the sine), ``f_k`` is ``cf cos(pi j (2k + 1)/n)``, ``O`` is 0:
    agreeing with Arb's cosine to 60 digits, for ``j`` in ``0..n-1`` and for ``j`` past it and below 0 (not read
    from the valence's rows)."""
    with flint.ctx.workprec(256):
        table, ce, cf = trig_table(n), flint.arb(3) / 7, flint.arb(-5) / 11
        for j in [*range(n), n, n + 1, 2 * n + 3, -1]:
            form = _pattern(table, n, j, fn, ce, cf)
            wave = flint.arb.cos_pi if fn == "cos" else flint.arb.sin_pi
            assert form.at(0) == 0
            for k in range(n):
                for point, scalar, angle in ((1 + 2 * k, ce, flint.fmpq(2 * j * k, n)), (2 + 2 * k, cf, flint.fmpq(j * (2 * k + 1), n))):
                    error = form.at(point) - scalar * wave(flint.arb(angle))
                    assert abs(error) < flint.arb(10) ** -60, (j, k, point)


@pytest.mark.parametrize("n", [3, 4, 7, 12, 61, 128])
@pytest.mark.parametrize("prec", [256, 1200])
def test_the_table_split_from_its_quarter_is_every_ball_split(n, prec):
    """``TrigTable.split`` (the quarter's balls split, the rest placed by ``cos(pi - x) = -cos(x)`` and ``cos(2 pi - x)
    = cos(x)``) has the bits of splitting every ball, and ``hi + lo`` is within ``err`` of ``cos(pi m/(2n))``."""
    with flint.ctx.workprec(prec):
        table = trig_table(n)
        fast, each = table.split(), split_balls(list(table))
        assert fast.shape == each.shape == (3, 4 * n)
        assert (fast.view("u8") == each.view("u8")).all()
        for m in range(4 * n):
            exact = flint.arb.cos_pi_fmpq(flint.fmpq(m, 2 * n))
            assert abs(exact - fast[0, m] - fast[1, m]) < fast[2, m] + flint.arb(2) ** -(prec - 8), m
