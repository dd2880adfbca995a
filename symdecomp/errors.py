"""The package's error types.

Every error names the problem in the caller's terms (a valence, a frequency, a polygon,
a rule of a scheme) so that no user meets a traceback from deep inside sympy. The hierarchy:

* :class:`SymdecompError`: the base of every error the package raises on purpose;
* :class:`InvalidInputError` (also a ``ValueError``): an input of the right kind with a bad
  value (a valence of 2, a weight that is a float, text outside the grammar), with one
  subclass per kind of input below;
* :class:`InvalidTypeError` (also a ``TypeError``): an input of the wrong kind altogether
  (a polygon that is a dict, a scheme that is not a :class:`~symdecomp.schemes.scheme.Scheme`);
* :class:`ResourceLimitError` (a ``ValueError``): a request refused because its estimated
  time or memory is beyond the stated limit (the estimate is in the message);
* :class:`UnavailableError`: an optional component (the OpenSubdiv bridge) is missing;
* :class:`InternalError`: the package caught itself in an inconsistency (a bug, not bad input).

The checks themselves live in :mod:`symdecomp.validate`.
"""

from __future__ import annotations

__all__ = [
    "SymdecompError",
    "InvalidValenceError",
    "FrequencyOutOfRangeError",
    "InvalidPolygonError",
    "NotAffineError",
    "InvalidSchemeError",
    "InvalidExpressionError",
    "InvalidInputError",
    "InvalidTypeError",
    "ResourceLimitError",
    "UnavailableError",
    "InternalError",
]


class SymdecompError(Exception):
    """Base class of every error symdecomp raises on purpose."""


class InvalidInputError(SymdecompError, ValueError):
    """An input has a bad value (the message names the argument and the value)."""


class InvalidTypeError(SymdecompError, TypeError):
    """An input is of the wrong kind altogether."""


class ResourceLimitError(InvalidInputError):
    """A request is refused before it starts: its estimated memory or time is beyond the limit."""


class UnavailableError(SymdecompError):
    """An optional component (e.g. the OpenSubdiv bridge) is missing; the message says how to get it."""


class InternalError(SymdecompError):
    """An internal inconsistency: a bug in symdecomp, not a problem with the input."""


class InvalidValenceError(InvalidInputError):
    """The valence is not an integer of at least 3."""


class FrequencyOutOfRangeError(InvalidInputError):
    """A frequency index is not an integer in the allowed range."""


class InvalidPolygonError(InvalidInputError):
    """A polygon has the wrong shape or non-finite coordinates."""


class NotAffineError(InvalidInputError):
    """The weights of a subdivision rule do not sum to 1."""


class InvalidSchemeError(InvalidInputError):
    """A scheme is malformed in a way other than affinity (e.g. a stencil wider than the ring).

    ``parts``, when given, is the message as words (``str``) and computed objects (sympy), in
    order, so that a report can typeset the formulas (``symdecomp.claims.Text``); the message
    itself stays plain text.
    """

    def __init__(self, message: str, *, parts: tuple | None = None):
        super().__init__(message)
        #: The message as words and objects, or ``None``.
        self.parts = parts


class InvalidExpressionError(InvalidInputError):
    """Text or a value given as an exact number is outside the accepted grammar (see :mod:`symdecomp.expressions`)."""
