"""Injectivity of a sector's characteristic map, and what the map's part of a sector test found (one finding type).

A sector's ring is either *open*, between two sharp rays (a boundary or corner vertex, a side of an infinitely sharp crease:
:func:`injective_condition`), or *closed*, its first ray a copy of its last (a dart's fan cut by its one sharp ray:
:func:`closed_fan_condition`). Both decide from the Jacobian's certified sign ``s`` and the arguments ``(Delta_in,
Delta_out)`` swept by the images of the ring's inner and outer arcs (rigorous: Bezier pieces in half-planes,
:func:`~symdecomp.verify.bezier.curve_angle`); the test that reaches them reports a :class:`SectorFinding`, whose
``opening`` (open) or ``winding`` (closed) says how injectivity was read.

**Injectivity of an open sector** (the argument used here, in place of the interior winding number).
Let ``K`` be the closed sector minus ``O`` and ``R`` one ring of it (a topological disk bounded by the
inner arc ``g_in`` from ray 0 to ray ``k``, the outer arc ``g_out``, and the two ray segments).
``chi(x / 2) = A chi(x)`` with ``A = diag(lambda_1, lambda_2)``. On each sharp ray the boundary values of an
eigenvector are exactly linear along the ray and 0 at ``O`` (they lie in the kernel of ``C - 1/2`` for the
curve block ``C``, or vanish; checked exactly), so ``chi`` maps each ray onto a segment of a ray from the
origin, in a direction ``d_0`` or ``d_k`` (certified non-zero). Suppose ``chi`` is regular on ``R`` with
Jacobian sign ``s``, and let ``Delta`` be the argument swept by ``chi(g_in)``. The closed curve ``chi(dR)`` sweeps
``Delta_out - Delta_in`` (the ray segments sweep nothing); when that is certified ``0``, ``chi`` has no zero
in ``R`` (each zero of a regular map counts ``s``). Then ``F = log chi`` has a continuous branch on ``K``
(simply connected), a local homeomorphism mapping ray 0 onto the line ``arg = a_0`` and ray ``k`` onto
``arg = a_0 + Delta`` (``|chi|`` runs from 0 to infinity along each ray, monotone by regularity). ``F`` is
proper, and ``arg chi`` is bounded on ``K`` (``A`` keeps every quadrant), so over each of the two outer
half-planes ``F`` is a covering with a constant number of sheets which is 0 far away: nothing of ``K`` maps
outside the strip between the lines. Over the open strip ``F`` is a covering of a simply connected set,
crossing a line adds one sheet for the boundary points, so ``F`` is a homeomorphism of ``K`` onto the strip
when ``sign(Delta) = s`` (near ray 0 the inside of ``K`` lies on the strip's side). Hence ``chi`` is
injective iff ``0 < s Delta < 2 pi``; ``s Delta < 0`` means the sector folds over its boundary (an inner
point and a boundary point share an image) and ``s Delta > 2 pi`` means it overlaps itself: not injective.
With a ring past modified edges (:mod:`.sector_ring`) the argument holds with that ring as ``R``.

**A closed fan** (U. Reif, *A unified approach to subdivision algorithms near extraordinary vertices*, CAGD 12, 1995,
as at an interior vertex): a regular ``chi`` is injective iff the image of the ring's inner boundary winds once around
the origin, and the outer one as often (no zero in the ring), in the Jacobian's orientation.

>>> import flint
>>> pi = flint.arb.pi()
>>> closed_fan_condition(1, (2 * pi, 2 * pi))[0], closed_fan_condition(1, (4 * pi, 4 * pi))[0]
(<C1Verdict.C1: 'c1'>, <C1Verdict.NOT_C1: 'not-c1'>)
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.c1_spectrum import SpectralResult, ball_text
from symdecomp.verify.result import C1Verdict

#: The arguments ``(Delta_in, Delta_out)`` swept by the images of a ring's inner and outer arcs (``None``: not certified).
Sweeps = tuple["flint.arb | None", "flint.arb | None"]

__all__ = ["SectorFinding", "injective_condition", "closed_fan_condition", "winding_number"]


@dataclass(frozen=True)
class SectorFinding:
    """What a sector test found in one sector (before it becomes a result): the verdict, and the map's certified facts."""

    #: ``c1``, ``not-c1`` or ``undecided``.
    verdict: C1Verdict
    #: Why, in words.
    reason: str
    #: The sector's spectral conditions, where the finding holds them (``None``: reported apart, as at a dart).
    spectral: SpectralResult | None = None
    #: ``lambda_1, lambda_2`` (midpoints), when determined.
    lambdas: tuple[float, ...] | None = None
    #: The Jacobian's certified sign (``None``: not certified).
    sign: int | None = None
    #: A lower bound of ``|J|`` on the ring, when certified.
    bound: float | None = None
    #: The subdivision depth the sign needed.
    depth: int | None = None
    #: Injectivity of an open sector: the argument ``Delta / pi`` swept by its image, when certified.
    opening: float | None = None
    #: Injectivity of a closed fan: the winding number of the ring's inner boundary around the origin, when certified.
    winding: int | None = None
    #: How the map was certified, where a route other than the dense test's did it (``None``: the caller's method).
    method: str | None = None
    #: The blocks' verdict is final (an exact multiple subdominant eigenvalue): the dense test would find the same.
    final: bool = False


def injective_condition(sm: object, vertex: SharpVertex, sign: int, dirs: object, sweeps: Sweeps) -> tuple[C1Verdict, str, float | None]:
    """Conditions 4 and 5 of the sector test (:mod:`.c1_sector_matrix`) at an open sector, from the certified sweeps
    ``(Delta_in, Delta_out)`` and the Jacobian's ``sign`` (module docstring)."""
    din, dout = sweeps
    if din is None or dout is None:
        return C1Verdict.UNDECIDED, "the argument swept by the ring's arcs is not certified (a curve may pass near 0)", None
    two_pi = 2 * flint.arb.pi()
    if not abs(dout - din) < two_pi:
        return C1Verdict.UNDECIDED, "the ring's boundary is not shown to wind 0 times around O (a zero of chi in the ring?)", None
    turn = din * sign
    opening = float((turn / flint.arb.pi()).mid())
    text = f"the sector's image opens by {ball_text(turn / flint.arb.pi(), 5)} pi (in the Jacobian's orientation)"
    if turn < 0:
        return C1Verdict.NOT_C1, f"{text} against the Jacobian's sign {sign}: the sector folds over its boundary", opening
    if turn > two_pi:
        return C1Verdict.NOT_C1, f"{text}, more than a full turn: the characteristic map overlaps itself", opening
    if not (turn > 0 and turn < two_pi):
        return C1Verdict.UNDECIDED, f"{text}: not separated from 0 or 2 pi", opening
    if vertex.corner and vertex.angle is not None and vertex.angle != sp.pi:
        concave = bool(vertex.angle > sp.pi)
        if turn.contains(flint.arb.pi()):
            return C1Verdict.UNDECIDED, f"{text}: convex or concave not decided", opening
        if concave != bool(turn > flint.arb.pi()):
            want, got = ("concave", "convex") if concave else ("convex", "concave")
            return C1Verdict.NOT_C1, (f"{text}: a {got} sector, but the corner is {want} (angle {vertex.angle}); the surface "
                                      "folds there (Biermann-Levin-Zorin's corner types)"), opening
    return C1Verdict.C1, f"{text} and winds once between the sharp rays: injective", opening


def winding_number(total: flint.arb | None) -> int | None:
    """The integer ``w`` with ``total = 2 pi w`` (a closed curve's swept argument), or ``None`` if not isolated."""
    if total is None:
        return None
    ratio = total / (2 * flint.arb.pi())
    w = round(float(ratio.mid()))
    return w if abs(ratio - w) < 0.5 else None


def closed_fan_condition(sign: int, sweeps: Sweeps) -> tuple[C1Verdict, str, int | None]:
    """Injectivity of a closed fan's regular map (module docstring): ``(verdict, why, winding number)`` from the Jacobian's
    ``sign`` and the sweeps ``(Delta_in, Delta_out)``; ``why`` follows "the characteristic map is regular"."""
    inner, outer = (winding_number(t) for t in sweeps)
    if inner is None or outer is None or inner != outer:
        return C1Verdict.UNDECIDED, "the winding numbers of the ring's boundary curves are not certified equal", None
    if abs(inner) != 1:
        return C1Verdict.NOT_C1, f"but its ring winds {abs(inner)} times around O: not injective", inner
    if inner != sign:  # a regular map keeps the orientation: its boundary winds with the Jacobian's sign
        return C1Verdict.UNDECIDED, "but its ring winds against the Jacobian's sign", inner
    return C1Verdict.C1, "and its ring winds once around O: injective", inner
