"""What a comparison with OpenSubdiv reports (:mod:`symdecomp.verify.oracle`), at an interior vertex and at a sector.

At an interior vertex a :class:`Prediction` is one quantity of the toolkit's against OpenSubdiv's, ``"exact"`` (agrees
to double precision, :data:`EXACT_TOLERANCE`) or ``"limit"`` (converges with the levels at a predicted rate), and a
:class:`ValenceComparison` holds one valence's. At a boundary, corner, crease or dart vertex a :class:`SharpCheck` is
one measure of the two one-step matrices of a level (at most :data:`TOLERANCE`), and a :class:`SharpResult` one
level's checks.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from symdecomp.verify.oracle import SharpCase

__all__ = ["EXACT_TOLERANCE", "TOLERANCE", "Prediction", "ValenceComparison", "error_levels", "exact_row", "limit_row", "rate_from",
           "SharpCheck", "SharpResult"]


#: Agreement required of the quantities that are exact in exact arithmetic (data of size ~1).
EXACT_TOLERANCE = 1e-13


#: Largest disagreement accepted (weights are at most 1 in size: absolute = relative).
TOLERANCE = 1e-12


@dataclass(frozen=True)
class Prediction:
    """One predicted quantity compared with OpenSubdiv at one valence."""

    #: Short name, e.g. ``"one-step matrix"`` or ``"shrink rate j=1"``.
    name: str
    #: ``"exact"`` (agrees to double precision) or ``"limit"`` (converges with the levels).
    kind: str
    #: The toolkit's value (a float, or a complex for the Eq. 39 ratio; None for matrix checks).
    predicted: complex | float | None
    #: OpenSubdiv's value at the last level (same type as ``predicted``).
    observed: complex | float | None
    #: The largest disagreement (absolute).
    disagreement: float
    #: For ``"limit"`` rows: the factor by which the disagreement should shrink per level.
    rate: float | None
    #: For ``"limit"`` rows: the disagreement's observed shrink factor over the last levels
    #: still above rounding (None if it could not be measured).
    observed_rate: float | None
    #: Whether the disagreement is within what the kind allows (see :func:`~symdecomp.verify.oracle.compare_with_opensubdiv`).
    agrees: bool
    #: For ``"limit"`` rows: the disagreement at each level compared, in order (the last is ``disagreement``); what
    #: ``oracle --plot`` draws against the predicted rate. Empty for ``"exact"`` rows.
    errors: tuple[float, ...] = ()

    def as_json(self, levels: int | None = None) -> dict:
        """The row as JSON; given the ``levels`` run, also ``"per_level"``: ``[{"level", "disagreement"}]`` of
        :attr:`errors` (:func:`error_levels`), the numbers ``oracle --plot`` draws (empty for ``"exact"`` rows)."""

        def enc(x):
            if x is None:
                return None
            if isinstance(x, complex):
                return [x.real, x.imag]
            return float(x)

        return {
            "name": self.name,
            "kind": self.kind,
            "predicted": enc(self.predicted),
            "observed": enc(self.observed),
            "disagreement": self.disagreement,
            "rate": self.rate,
            "observed_rate": self.observed_rate,
            "agrees": self.agrees,
            **({} if levels is None else {"per_level": [{"level": k, "disagreement": e} for k, e in
                                                        zip(error_levels(self.errors, levels), self.errors)]}),
        }


def error_levels(errors: Sequence[float], levels: int) -> list[int]:
    """The level of each of a limit row's ``errors``: its last one is the last level run (the limit position starts at
    level 0, a ratio or a shrink rate at level 1).

    >>> error_levels([0.5, 0.25, 0.125], 2), error_levels([0.25, 0.125], 2)
    ([0, 1, 2], [1, 2])
    """
    return list(range(levels - len(errors) + 1, levels + 1))


@dataclass(frozen=True)
class ValenceComparison:
    """All predictions at one valence."""

    #: The valence.
    n: int
    #: Number of refinement levels run in OpenSubdiv.
    levels: int
    #: Seed of the random 1-ring.
    seed: int
    #: The compared predictions.
    predictions: tuple[Prediction, ...]

    @property
    def agrees(self) -> bool:
        return all(p.agrees for p in self.predictions)

    def as_json(self) -> dict:
        return {
            "n": self.n,
            "levels": self.levels,
            "seed": self.seed,
            "agrees": self.agrees,
            "predictions": [p.as_json(self.levels) for p in self.predictions],
        }


def rate_from(errors: list[float], floor: float) -> float | None:
    """Shrink factor of a disagreement sequence over its last two levels above ``floor``."""
    usable = [k for k in range(1, len(errors)) if errors[k] > floor and errors[k - 1] > floor]
    if not usable:
        return None
    k = usable[-1]
    return errors[k] / errors[k - 1]


def exact_row(name, disagreement, predicted=None, observed=None) -> Prediction:
    """An ``"exact"`` row: it agrees when ``disagreement`` is at most :data:`EXACT_TOLERANCE`."""
    return Prediction(name, "exact", predicted, observed, disagreement, None, None, disagreement <= EXACT_TOLERANCE)


def limit_row(name, predicted, observed, errors, rate, floor, levels) -> Prediction:
    """A ``"limit"`` row: it agrees when the last error is at most ``100 rate^levels + 1e-12``."""
    last = errors[-1]
    bound = 100.0 * rate**levels + 1e-12
    return Prediction(name, "limit", predicted, observed, last, rate, rate_from(errors, floor), last <= bound,
                      tuple(float(e) for e in errors))


@dataclass(frozen=True)
class SharpCheck:
    """One comparison: its name, the largest disagreement, whether it counts towards the verdict."""

    name: str
    disagreement: float
    comparable: bool = True
    note: str = ""

    @property
    def agrees(self) -> bool:
        return not self.comparable or self.disagreement <= TOLERANCE


@dataclass(frozen=True)
class SharpResult:
    """The checks of one case at one refinement level."""

    case: SharpCase
    level: int
    checks: tuple

    @property
    def agrees(self) -> bool:
        return all(c.agrees for c in self.checks)

    def as_json(self) -> dict:
        s = self.case.sharpness
        return {"scheme": self.case.scheme, "kind": self.case.kind, "k": self.case.k,
                "sharpness": "inf" if s == math.inf else str(s), "boundary": self.case.boundary,
                "creasing": self.case.creasing, "level": self.level, "agrees": self.agrees,
                "checks": [{"name": c.name, "disagreement": c.disagreement, "comparable": c.comparable,
                            "agrees": c.agrees, "note": c.note} for c in self.checks]}
