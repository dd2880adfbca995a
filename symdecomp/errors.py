"""The package's error types.

Every error names the problem in the caller's terms (a valence, a frequency, a polygon,
a rule of a scheme) so that no user meets a traceback from deep inside sympy. The hierarchy:

* :class:`SymdecompError`: the base of every error the package raises on purpose (all of them
  are defined here; the modules that raise them import them from here);
* :class:`InvalidInputError` (also a ``ValueError``): an input of the right kind with a bad
  value (a valence of 2, a weight that is a float, text outside the grammar), with one
  subclass per kind of input below;
* :class:`NotApplicableError` (an :class:`InvalidSchemeError`): a well-formed scheme that
  does not meet the hypotheses of the question asked (a test for mirror-symmetric schemes, a
  scheme with free parameters where numbers are needed); a claim's check reports it as
  "not applicable";
* :class:`LatticeFactMissing` (an :class:`InvalidSchemeError`): a lattice asked for a fact its
  file does not state (the message names the lattice and the fact);
* :class:`InvalidTypeError` (also a ``TypeError``): an input of the wrong kind altogether
  (a polygon that is a dict, a scheme that is not a :class:`~symdecomp.schemes.scheme.Scheme`);
* :class:`ResourceLimitError` (a ``ValueError``): a request refused because its estimated
  time or memory is beyond the stated limit (the estimate is in the message);
* :class:`UnavailableError`: an optional component (the OpenSubdiv bridge) is missing;
* :class:`OutputWriteError` (also an ``OSError``): an output file checked beforehand could not be
  written after all (a full disk, an I/O error); not bad input (the command line's exit code 1);
* :class:`InternalError`: the package caught itself in an inconsistency (a bug, not bad input).

Private control-flow exceptions that never leave the module raising them (a signal to retry at
a higher precision, to stop a search) stay in that module; each says why in a comment.

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
    "NotApplicableError",
    "LatticeFactMissing",
    "InvalidExpressionError",
    "InvalidMeshError",
    "NotCirculantBlockError",
    "NotDiagonalizableError",
    "UnsupportedExpressionError",
    "EvaluationError",
    "EvalDataFileError",
    "InvalidInputError",
    "InvalidTypeError",
    "ResourceLimitError",
    "UnavailableError",
    "OutputWriteError",
    "InternalError",
    "PrecisionError",
    "BridgeUnavailableError",
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


class OutputWriteError(SymdecompError, OSError):
    """Writing an output failed (disk full, I/O error) after the path was checked; the message names the path."""


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


class LatticeFactMissing(InvalidSchemeError):
    """A lattice was asked for a fact it does not have (its own file does not state it).

    The message names the lattice and the fact (``the triangle lattice has no 'xyz'``): code outside
    the lattice's file asks the lattice, and a lattice without the answer fails here instead of being
    treated as another lattice.
    """

    def __init__(self, lattice, fact: str, why: str = ""):
        #: The lattice's name.
        self.lattice = getattr(lattice, "name", lattice)
        #: The name of the fact asked for.
        self.fact = fact
        self._why = why
        super().__init__(f"the {self.lattice} lattice has no {fact!r}{why}")

    def __reduce__(self):  # the arguments, not the message: the error crosses process pools intact
        return type(self), (self.lattice, self.fact, self._why)


class InvalidExpressionError(InvalidInputError):
    """Text or a value given as an exact number is outside the accepted grammar (see :mod:`symdecomp.expressions`)."""


class NotApplicableError(InvalidSchemeError):
    """The question does not apply to this scheme: a test whose hypotheses the scheme does not meet.

    The scheme itself is well formed (unlike a plain :class:`InvalidSchemeError`); e.g. a
    check written for mirror-symmetric rules asked about a scheme without that symmetry, or a
    numeric question asked about a scheme with free parameters.
    """


class InvalidMeshError(InvalidInputError):
    """A mesh is not a consistently oriented quad mesh, or a vertex asked about is not in it."""


class NotCirculantBlockError(InvalidInputError):
    """A block of a matrix meant to be a CB-matrix is not circulant (or has the wrong size)."""


class NotDiagonalizableError(InvalidInputError):
    """A matrix has no basis of (real) eigenvectors."""


class UnsupportedExpressionError(InvalidInputError):
    """A closed form uses a function the fast evaluators do not know."""


class EvaluationError(InvalidInputError):
    """Parameters outside ``[0, 1]^2`` or control points of the wrong shape."""


class EvalDataFileError(InvalidInputError):
    """An eigen-data file cannot be written or read (path, truncated or malformed content)."""


class PrecisionError(InternalError):
    """A ball stayed too wide to decide a sign or round correctly, up to the precision cap."""


class BridgeUnavailableError(UnavailableError):
    """The OpenSubdiv bridge is not built and cannot be built here (no g++ or no OpenSubdiv)."""
