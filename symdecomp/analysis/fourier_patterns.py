"""The trig table of a valence and the Fourier patterns of the 1-ring's eigenvectors, kept as their factors.

A pattern of frequency ``j`` on the 1-ring is a scalar times ``cos(pi m/(2n))`` for an index ``m`` per
point (:class:`PatternForm`); the table holds those cosines once per valence (:func:`trig_table`, or
:class:`LazyTable` where a few entries are read). :mod:`symdecomp.analysis.eigendata_columns` builds the
eigenvectors from them, and the data file rounds them from their factors or sums them as waves.
"""

from __future__ import annotations

from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.numbers import to_arb, to_fmpq
from symdecomp.algebra.rounding import split_balls

__all__ = ["PatternForm", "LazyTable", "TrigTable", "trig_table"]

arb = flint.arb


#: ``q`` (in units of pi, mod 2) -> the exact value of ``cos(pi q)`` where it is rational.
_EXACT_COS = {
    Fraction(0): 1, Fraction(1): -1, Fraction(1, 2): 0, Fraction(3, 2): 0,
    Fraction(1, 3): Fraction(1, 2), Fraction(5, 3): Fraction(1, 2), Fraction(2, 3): Fraction(-1, 2), Fraction(4, 3): Fraction(-1, 2),
}  # fmt: skip


def _trig_pi(m: int, den: int, fn: str) -> arb:
    """``cos`` or ``sin`` of ``pi m/den``, exact when the value is rational."""
    if fn == "sin":
        m, den = 2 * m - den, 2 * den  # sin(pi m/den) = cos(pi (m/den - 1/2))
    q = Fraction(m % (2 * den), den)
    if q in _EXACT_COS:
        return to_arb(_EXACT_COS[q])
    return arb.cos_pi_fmpq(to_fmpq(q))



class PatternForm:
    """A Fourier pattern kept as its factors: entry ``p`` is ``scalars[coef[p]] * table[index[p]]``
    (``index[p] = -1``: an exact 0), the products formed only where they are read.

    The data file rounds a whole row from the factors
    (:func:`symdecomp.algebra.rounding.round_products`) instead of forming ``K`` products in Arb.

    ``wave``: ``(j, shift, steps)`` when the pattern is a wave of frequency ``j``: ``index[p] = (2 j steps[p] +
    shift) mod 4n`` where ``steps[p] >= 0`` (the point's position around ``O`` in half steps), so entry ``p``
    is ``scalars[coef[p]] cos(pi j steps[p]/n + pi shift/(2n))`` (``shift = 0``: cosine, ``-n``: sine); sums of
    waves over the columns are then discrete Fourier transforms.
    """

    __slots__ = ("scalars", "coef", "index", "table", "wave", "_lists")

    def __init__(self, scalars: tuple, coef: np.ndarray, index: np.ndarray, table, wave: tuple | None = None):
        self.scalars, self.coef, self.index, self.table, self._lists = scalars, coef, index, table, None
        self.wave = wave

    def _pairs(self) -> tuple[list, list]:
        if self._lists is None:
            self._lists = (self.coef.tolist(), self.index.tolist())
        return self._lists

    def at(self, p: int):
        coef, index = self._pairs()
        return arb(0) if index[p] < 0 else self.scalars[coef[p]] * self.table[index[p]]

    def entries(self) -> list:
        scalars, table = self.scalars, self.table
        return [arb(0) if i < 0 else scalars[c] * table[i] for c, i in zip(*self._pairs())]


#: The patterns of one valence, ``{n: {shift: (coef, index)}}``: keyed by the valence and holding only the last one
#: asked; one row of ``index`` per frequency, made in one numpy step (a few small arrays made per frequency and
#: shift cost more than the rows).
_PATTERNS: dict[int, dict[int, tuple[np.ndarray, np.ndarray]]] = {}


def _pattern_index(n: int, j: int, shift: int) -> tuple[np.ndarray, np.ndarray]:
    """``(coef, index)`` of the pattern of frequency ``j`` on ``(O, e_0, f_0, ...)``, remembered for the last valence
    (read-only arrays: ``coef`` is one array for every ``j``, ``index`` a row of the valence's table)."""
    if not 0 <= j < n:  # not a row of the table (the index is not periodic in j with period n)
        coef, index = _pattern_rows(n, np.array([[j]]), shift)
        return coef, index[0]
    if n not in _PATTERNS:
        _PATTERNS.clear()
        _PATTERNS[n] = {}
    patterns = _PATTERNS[n]
    if shift not in patterns:
        coef, index = _pattern_rows(n, np.arange(n)[:, None], shift)
        index.setflags(write=False)
        coef.setflags(write=False)
        patterns[shift] = coef, index
    coef, index = patterns[shift]
    return coef, index[j]


def _pattern_rows(n: int, js: np.ndarray, shift: int) -> tuple[np.ndarray, np.ndarray]:
    """``(coef, index)``: one ``index`` row per frequency in the column ``js``."""
    k = np.arange(n)
    index, coef = np.full((len(js), 2 * n + 1), -1, dtype=np.int64), np.zeros(2 * n + 1, dtype=np.int64)
    index[:, 1::2] = (4 * js * k + shift) % (4 * n)
    index[:, 2::2] = (2 * js * (2 * k + 1) + shift) % (4 * n)
    coef[2::2] = 1
    return coef, index


class LazyTable:
    """``_trig_table(n)`` computed entry by entry on first use (a few columns need few entries)."""

    def __init__(self, n: int):
        self.n, self.cache = n, {}

    def __getitem__(self, m: int):
        if m not in self.cache:
            self.cache[m] = _trig_pi(m, 2 * self.n, "cos")
        return self.cache[m]


def trig_table(n: int) -> TrigTable:
    """``cos(pi m/(2n))`` for ``m = 0..4n-1``: cos(pi m/n) is entry ``2m``, sin(pi m/n) entry ``2m - n``.

    Only the quarter ``m = 0..n`` is evaluated; the rest are its balls by ``cos(pi - x) = -cos(x)`` and
    ``cos(2 pi - x) = cos(x)`` (exact: a negated ball holds the negated values).

    >>> t = trig_table(5)
    >>> all(t[m].overlaps(arb.cos_pi_fmpq(flint.fmpq(m, 10))) for m in range(20))
    True
    """
    quarter = [_trig_pi(m, 2 * n, "cos") for m in range(n + 1)]
    half = quarter + [-quarter[2 * n - m] for m in range(n + 1, 2 * n + 1)]
    return TrigTable(n, half + [half[4 * n - m] for m in range(2 * n + 1, 4 * n)])


class TrigTable(list):
    """:func:`trig_table`'s balls (a list), which knows that they were made from the quarter ``m = 0..n``."""

    def __init__(self, n: int, balls: list):
        super().__init__(balls)
        self.n = n

    def split(self) -> np.ndarray:
        """``split_balls(self)``, the quarter's balls split and the rest placed by the two symmetries the table was
        made by: a ball's negation splits into the negated ``hi`` and ``lo`` and the same ``err`` (rounding to nearest
        and Arb's midpoint rounding are symmetric about 0), so the bits are those of splitting every ball, in a
        quarter of the Arb operations (the table is ``4n`` balls a valence, split for the 1-ring rows of ``V^-1``).

        >>> t = trig_table(7)
        >>> (t.split().view("u8") == split_balls(list(t)).view("u8")).all()
        np.True_
        """
        n = self.n
        quarter = split_balls(self[: n + 1])
        m = np.arange(4 * n)
        folded = np.where(m <= 2 * n, m, 4 * n - m)  # cos(2 pi - x) = cos(x)
        negated = folded > n  # cos(pi - x) = -cos(x)
        out = quarter[:, np.where(negated, 2 * n - folded, folded)]
        out[:2, negated] = 0.0 - out[:2, negated]  # 0.0 - x: a zero lo stays +0.0, as float() of an exact 0 gives
        return out


def _pattern(table: list, n: int, j: int, fn: str, ce, cf) -> PatternForm:
    """``[0, ce T(2jk), cf T(j(2k+1)), ...]``: a Fourier pattern on ``(O, e_0, f_0, ...)``."""
    shift = 0 if fn == "cos" else -n
    coef, index = _pattern_index(n, j, shift)
    return PatternForm((ce, cf), coef, index, table, (j, shift, _steps(2 * n + 1, 1)))


_STEPS: dict = {}


def _steps(size: int, stride: int) -> np.ndarray:
    """Positions in half steps around ``O`` of the points ``1..size-1`` (-1 at ``O``): ``stride`` 1 for
    ``(e_0, f_0, e_1, ...)``, 2 for ``(a_0, a_1, ...)``; one array per layout, shared."""
    if (size, stride) not in _STEPS:
        if len(_STEPS) > 8:
            _STEPS.clear()
        _STEPS[(size, stride)] = np.concatenate([[-1], stride * np.arange(size - 1)])
    return _STEPS[(size, stride)]
