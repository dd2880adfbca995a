"""Errors raised for bad input.

Every error names the problem in the caller's terms (a valence, a frequency, a polygon,
a rule of a scheme) so that no user meets a traceback from deep inside sympy.
"""

from __future__ import annotations

import numbers

import sympy as sp

__all__ = [
    "SymdecompError",
    "InvalidValenceError",
    "FrequencyOutOfRangeError",
    "InvalidPolygonError",
    "NotAffineError",
    "InvalidSchemeError",
    "InvalidExpressionError",
    "check_valence",
    "check_frequency",
]


class SymdecompError(ValueError):
    """Base class of every input error of symdecomp."""


class InvalidValenceError(SymdecompError):
    """The valence is not an integer of at least 3."""


class FrequencyOutOfRangeError(SymdecompError):
    """A frequency index is not an integer in the allowed range."""


class InvalidPolygonError(SymdecompError):
    """A polygon has the wrong shape or non-finite coordinates."""


class NotAffineError(SymdecompError):
    """The weights of a subdivision rule do not sum to 1."""


class InvalidSchemeError(SymdecompError):
    """A scheme is malformed in a way other than affinity (e.g. a stencil wider than the ring)."""


class InvalidExpressionError(SymdecompError):
    """Text or a value given as an exact number is outside the accepted grammar (see :mod:`symdecomp.expressions`)."""


def check_valence(n, *, minimum: int = 3) -> int:
    """Return ``n`` as an ``int`` if it is an integer valence ``>= minimum``.

    >>> check_valence(5)
    5
    >>> check_valence(2)
    Traceback (most recent call last):
    ...
    symdecomp.errors.InvalidValenceError: valence n must be an integer >= 3, got 2
    """
    if isinstance(n, bool) or not isinstance(n, (numbers.Integral, sp.Integer)):
        raise InvalidValenceError(
            f"valence n must be an integer >= {minimum}, got {n!r} of type {type(n).__name__}"
        )
    n = int(n)
    if n < minimum:
        raise InvalidValenceError(f"valence n must be an integer >= {minimum}, got {n}")
    return n


def check_frequency(j, n: int, *, period: int | None = None) -> int:
    """Return ``j`` as an ``int`` if ``0 <= j < period`` (``period`` defaults to ``2n``).

    The paper indexes the components of the 1-ring 2n-gon by ``j = 0..2n-1`` (Eq. 11), so
    that is the default range.

    >>> check_frequency(7, 4)
    7
    >>> check_frequency(8, 4)
    Traceback (most recent call last):
    ...
    symdecomp.errors.FrequencyOutOfRangeError: frequency j must be an integer with 0 <= j < 8 (valence n = 4), got 8
    """
    n = check_valence(n)
    period = 2 * n if period is None else period
    if isinstance(j, bool) or not isinstance(j, (numbers.Integral, sp.Integer)):
        raise FrequencyOutOfRangeError(
            f"frequency j must be an integer with 0 <= j < {period}, got {j!r} of type {type(j).__name__}"
        )
    j = int(j)
    if not 0 <= j < period:
        raise FrequencyOutOfRangeError(
            f"frequency j must be an integer with 0 <= j < {period} (valence n = {n}), got {j}"
        )
    return j
