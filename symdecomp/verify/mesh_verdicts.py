"""The verdicts of a mesh's neighbourhood kinds: C1 and the curvature regime, computed once per kind.

For each :class:`~symdecomp.analysis.mesh_kinds.NeighbourhoodKind` of a mesh (a few dozen in a mesh of a
million faces) :func:`kind_verdict` gives the certified C1 verdict (Reif's test at a smooth vertex of valence
``n``, :func:`~symdecomp.verify.c1.c1_test`; Zorin's conditions per sector at a boundary, crease or corner
vertex, :func:`~symdecomp.verify.c1_sector_matrix.c1_sharp_test`) and, at smooth vertices, the curvature regime of
the artifact indicators (:func:`~symdecomp.verify.artifacts.artifact_indicators`: bounded, zero, unbounded).
Where a test does not apply (a scheme with free parameters) the verdict is ``n/a`` and the reason is kept.

**Darts** (one sharp edge ends at an interior vertex; OpenSubdiv keeps the smooth vertex rule there) get a verdict of
their own (:func:`dart_verdict`). A semi-sharp dart is smooth from level ``ceil(s)`` on, so Reif's test at its valence
decides, as for a semi-sharp crease (and so does the curvature regime at that valence). An infinitely sharp dart is
judged by Reif's test on its closed fan cut by one sharp ray (:func:`~symdecomp.verify.c1_closed_fan.c1_dart_test`): the
exact spectrum of its 1-ring matrix (``check --k N --dart --certify`` proves that spectrum; ``not-c1`` when the
eigenvalue 1 is not simple and strictly dominant), then the characteristic map's regularity and winding number.

A vertex of no kind has a computed :class:`~symdecomp.analysis.mesh_outcomes.Outcome` (:func:`outcome_verdict`): a
transient vertex has its eventual kind's verdicts, the reason saying after how many levels; a vertex off the limit
surface has none (``n/a``, with why); a fan the sector model does not take is judged by its exact spectrum.

>>> from symdecomp.analysis.mesh_kinds import NeighbourhoodKind
>>> from symdecomp.schemes.scheme import catmull_clark
>>> v = kind_verdict(catmull_clark(), NeighbourhoodKind("smooth", 3, (3,), True))
>>> v.c1, v.regime
('c1', 'zero')
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from symdecomp.analysis.mesh_kinds import NeighbourhoodKind
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached, check_type

__all__ = ["KindVerdict", "kind_verdict", "dart_verdict", "outcome_verdict"]


@dataclass(frozen=True)
class KindVerdict:
    """The verdicts of one kind."""

    #: ``"c1"``, ``"not-c1"``, ``"undecided"`` or ``"n/a"``.
    c1: str
    #: Why (the test's reason, or why it does not apply).
    c1_reason: str
    #: ``"bounded"``, ``"zero"``, ``"unbounded"`` (smooth kinds), or ``"n/a"``.
    regime: str
    #: Why the regime is ``n/a``, else ``""``.
    regime_reason: str


def _check_kind(kind) -> NeighbourhoodKind:
    return check_type(kind, NeighbourhoodKind, "kind", hint="a kind of symdecomp.analysis.mesh_kinds.classify_vertices")


def _c1(scheme: Scheme, kind: NeighbourhoodKind) -> tuple[str, str]:
    from symdecomp.verify.c1 import c1_test
    from symdecomp.verify.c1_sector_matrix import c1_sharp_test

    try:
        if kind.name == "smooth":
            result = c1_test(scheme, kind.faces)
        elif kind.name == "dart":
            return dart_verdict(scheme, kind)
        else:
            result = c1_sharp_test(scheme, kind.sharp_vertex(scheme.lattice))
    except NotApplicableError as exc:
        return "n/a", str(exc)
    return result.verdict.value, result.reason


def dart_verdict(scheme: Scheme, kind: NeighbourhoodKind) -> tuple[str, str]:
    """The C1 verdict of a dart kind and why (module docstring): Reif's test when semi-sharp, else the exact spectrum."""
    from symdecomp.verify.c1 import c1_test

    if not math.isinf(kind.sharpness):
        r = c1_test(scheme, kind.faces)
        return r.verdict.value, (f"semi-sharp dart (sharpness {kind.sharpness}): smooth from level "
                                 f"{math.ceil(kind.sharpness)} on, so the interior test at valence n = {kind.faces} decides: "
                                 f"{r.reason}")
    return _dart_spectral(scheme, kind)


def _dart_spectral(scheme: Scheme, kind: NeighbourhoodKind) -> tuple[str, str]:
    """An infinitely sharp dart: Reif's test on its closed fan (:func:`~symdecomp.verify.c1_closed_fan.c1_dart_test`)."""
    from symdecomp.verify.c1_closed_fan import c1_dart_test

    try:
        r = c1_dart_test(scheme, kind.faces)
    except NotApplicableError as exc:
        return "undecided", f"Reif's test at a dart does not apply: {exc}"
    return r.verdict.value, r.reason


def _regime(scheme: Scheme, kind: NeighbourhoodKind) -> tuple[str, str]:
    from symdecomp.verify.artifacts import artifact_indicators

    semi_sharp_dart = kind.name == "dart" and not math.isinf(kind.sharpness)  # smooth from level ceil(s) on
    if kind.name != "smooth" and not semi_sharp_dart:
        return "n/a", "the curvature regime is defined at smooth vertices"
    try:
        return artifact_indicators(scheme, kind.faces).curvature.regime.value, ""
    except NotApplicableError as exc:
        return "n/a", str(exc)


@cached(maxsize=512, scheme=check_scheme, kind=_check_kind)
def kind_verdict(scheme: Scheme, kind: NeighbourhoodKind) -> KindVerdict:
    """The C1 verdict and curvature regime of ``kind`` under ``scheme`` (module docstring), once per kind."""
    c1, why = _c1(scheme, kind)
    regime, regime_why = _regime(scheme, kind)
    return KindVerdict(c1, why, regime, regime_why)


def outcome_verdict(scheme: Scheme, outcome) -> KindVerdict:
    """The verdicts of a vertex's computed :class:`~symdecomp.analysis.mesh_outcomes.Outcome` (module docstring)."""
    from symdecomp.analysis.mesh_outcomes import Outcome, spectrum_verdict

    outcome = check_type(outcome, Outcome, "outcome", hint="an outcome of symdecomp.analysis.mesh_kinds.classify_vertices")
    check_scheme(scheme)
    if outcome.eventual is not None:
        eventual = kind_verdict(scheme, outcome.eventual)
        return KindVerdict(eventual.c1, f"{outcome.reason}: {eventual.c1_reason}", eventual.regime, eventual.regime_reason)
    if outcome.fan is not None:
        c1, why = spectrum_verdict(scheme, outcome)
        return KindVerdict(c1, why, "n/a", "the curvature regime is defined at smooth vertices")
    return KindVerdict(outcome.c1, outcome.reason, "n/a", outcome.reason)
