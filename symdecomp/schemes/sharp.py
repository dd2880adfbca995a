"""A scheme's rules at sharp features: boundaries, creases, corners and darts (OpenSubdiv's semantics).

The one home of the sharp rules and of the sharpness arithmetic that decides which rule applies:

* :class:`SharpRules`, the weights a scheme uses at sharp features (part of every
  :class:`~symdecomp.schemes.scheme.Scheme`, field ``sharp``): the crease/boundary vertex rule
  (``crease_centre`` on the vertex, ``crease_end`` on each of its two crease neighbours; the cubic
  B-spline's ``3/4, 1/8`` by default, for Catmull-Clark and Loop alike), the crease/boundary edge
  rule (``crease_edge`` on each end: ``1/2``), corners interpolate (the identity rule), and
  optionally Biermann-Levin-Zorin's modified rule for a *smooth* edge incident to a crease, boundary
  or corner vertex (``near_edge_centre`` on the sharp vertex, ``near_edge_end`` on the edge's other end,
  expressions in the sector angle :data:`~symdecomp.symbols.theta_k` and the sector's face count
  :data:`~symdecomp.symbols.sector_faces` ``k``; ``None``: the scheme's smooth edge rule);
* :class:`SharpOptions`, OpenSubdiv's ``Sdc::Options`` that matter here: the boundary interpolation
  (``"edge-only"``: a boundary vertex uses the crease rule; ``"edge-and-corner"``: a boundary vertex
  with a single face is a corner) and the creasing method (``"uniform"``: sharpness ``s -> s - 1`` per
  level; ``"chaikin"``: Chaikin's averaging of the semi-sharp edges at a vertex);
* the sharpness arithmetic of OpenSubdiv's ``Sdc::Crease`` (``opensubdiv/sdc/crease.cpp``), exact:
  a sharpness is a :class:`~fractions.Fraction` ``>= 0`` or ``math.inf`` (every value ``>= 10`` is
  infinite, OpenSubdiv's ``SHARPNESS_INFINITE``): the vertex rule from the vertex sharpness and the number of
  sharp incident edges (:func:`vertex_rule_kind`: smooth 0, dart 1, crease 2, corner more or a sharp
  vertex), the child sharpness after one level (:func:`decrement`, :func:`child_edge_sharpnesses`) and the
  fractional weight that blends the parent and child vertex rules when they differ
  (:func:`fractional_weight`). The edge rule blends its smooth and crease masks with the edge's sharpness
  ``s`` when ``0 < s < 1``.

>>> r = standard_sharp_rules()
>>> r.crease_centre, r.crease_end, r.crease_edge, r.near_edge_centre
(3/4, 1/8, 1/2, None)
>>> vertex_rule_kind(0, [math.inf, 0, math.inf, 0]).name
'CREASE'
>>> fractional_weight(0, 0, [Fraction(1, 2), 0, Fraction(1, 2), 0], [0, 0, 0, 0], SharpOptions())
Fraction(1, 2)
"""

from __future__ import annotations

import enum
import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import sympy as sp

from symdecomp.errors import InvalidExpressionError, InvalidInputError, InvalidSchemeError, NotAffineError
from symdecomp.expressions import exact_value
from symdecomp.symbols import sector_faces, theta_k

__all__ = [
    "SharpRules", "standard_sharp_rules", "SharpOptions", "BOUNDARY_INTERPOLATIONS", "CREASE_METHODS",
    "VertexRuleKind", "SHARPNESS_INFINITE", "check_sharpness", "is_sharp", "is_infinite", "decrement",
    "vertex_rule_kind", "child_edge_sharpnesses", "fractional_weight", "SHARP_SYMBOLS",
]

#: OpenSubdiv's ``Sdc::Crease::SHARPNESS_INFINITE``: every sharpness at least this is infinite.
SHARPNESS_INFINITE = 10
#: Names the weights of the sharp rules may use (besides a scheme's parameters).
SHARP_SYMBOLS = {"theta_k": theta_k, "k": sector_faces}
#: OpenSubdiv's ``VtxBoundaryInterpolation`` values this package models.
BOUNDARY_INTERPOLATIONS = ("edge-only", "edge-and-corner")
#: OpenSubdiv's ``CreasingMethod`` values.
CREASE_METHODS = ("uniform", "chaikin")


def _weight(value, where: str) -> sp.Expr:
    try:
        return exact_value(value, SHARP_SYMBOLS, argument=f"{where}: weight", other_symbols=True)
    except InvalidExpressionError as exc:
        raise InvalidSchemeError(str(exc)) from None


@dataclass(frozen=True)
class SharpRules:
    """The weights of a scheme's rules at sharp features (sympy expressions; see the module docstring).

    Checked affine when built: ``crease_centre + 2 crease_end = 1``, ``2 crease_edge = 1``; the two
    near-edge weights are given together or not at all (their sum is checked against the scheme's
    edge rule by the scheme: the weights on the other corners stay the smooth rule's).
    """

    #: Weight of a crease or boundary vertex on itself in its new point (the B-spline's 3/4).
    crease_centre: sp.Expr
    #: Weight of a crease or boundary vertex on each of its two crease neighbours (1/8).
    crease_end: sp.Expr
    #: Weight of each end of a crease or boundary edge in its edge point (1/2).
    crease_edge: sp.Expr
    #: BLZ: weight on the crease/corner vertex in the point of a smooth edge at it (``None``: smooth rule).
    near_edge_centre: sp.Expr | None = None
    #: BLZ: weight on the other end of that edge (``None`` with ``near_edge_centre``).
    near_edge_end: sp.Expr | None = None

    def __post_init__(self):
        for name in ("crease_centre", "crease_end", "crease_edge", "near_edge_centre", "near_edge_end"):
            value = getattr(self, name)
            if value is not None or name in ("crease_centre", "crease_end", "crease_edge"):
                object.__setattr__(self, name, _weight(value, f"sharp rules: {name}"))
        if (self.near_edge_centre is None) != (self.near_edge_end is None):
            raise InvalidSchemeError("sharp rules: give near_edge_centre and near_edge_end together (or neither)")
        for name in _NAMES:
            _check_angle_use(getattr(self, name), name)
        for label, total in (("crease vertex rule: crease_centre + 2*crease_end", self.crease_centre + 2 * self.crease_end),
                             ("crease edge rule: 2*crease_edge", 2 * self.crease_edge)):
            if sp.simplify(total - 1) != 0:
                raise NotAffineError(f"sharp rules: {label} = {sp.simplify(total)}, not 1")

    def weights(self) -> tuple[sp.Expr, ...]:
        """Every weight given (the near-edge ones only when they are)."""
        near = () if self.near_edge_centre is None else (self.near_edge_centre, self.near_edge_end)
        return (self.crease_centre, self.crease_end, self.crease_edge, *near)

    def check_edge_rule(self, edge_end: sp.Expr, owner: str) -> None:
        """BLZ's near-edge rule keeps the smooth edge rule's weights on the other corners, so its two weights must
        sum to the smooth rule's weights ``edge_end`` on the two ends (the edge point stays affine)."""
        if self.near_edge_centre is not None and sp.simplify(self.near_edge_centre + self.near_edge_end - 2 * edge_end) != 0:
            raise NotAffineError(
                f"{owner}: sharp rules: near_edge_centre + near_edge_end must equal the edge rule's weights on the two "
                f"ends, {2 * edge_end} (the other weights are the smooth rule's)")

    def near_edge(self, theta, k) -> tuple[sp.Expr, sp.Expr] | None:
        """BLZ's ``(centre, end)`` weights for a sector of ``k`` faces and angle ``theta`` (``None``: no such rule)."""
        if self.near_edge_centre is None:
            return None
        values = {theta_k: theta, sector_faces: k}
        out = tuple(w.xreplace(values) for w in (self.near_edge_centre, self.near_edge_end))
        for name, weight, value in zip(_NAMES[3:], (self.near_edge_centre, self.near_edge_end), out):
            _check_defined_at(name, weight, value, k)
        return out

    def check_at(self, sectors: Sequence[int], angle=None) -> None:
        """Refuse rules that cannot be evaluated at a vertex whose sectors have ``sectors`` faces (``angle``: a corner's
        angle, else ``pi``): a free parameter left in a weight, or a near-edge weight undefined at a sector's ``k``
        (``1/(k - 2)`` at ``k = 2``). One :class:`~symdecomp.errors.InvalidSchemeError` naming the weight."""
        for name in _NAMES:
            weight = getattr(self, name)
            free = sorted(str(s) for s in getattr(weight, "free_symbols", ()) if s not in (theta_k, sector_faces))
            if free:
                raise InvalidSchemeError(f"[sharp] {name} = {weight} has free parameters {', '.join(free)}: a boundary, "
                                         "crease, corner or dart vertex needs their values (give them in the file)")
        for k in sorted(set(sectors)):
            self.near_edge((sp.pi if angle is None else angle) / k, k)

    def substitute(self, subs) -> SharpRules:
        """The rules with some parameters replaced (``subs``: symbol -> value)."""
        near = (None, None) if self.near_edge_centre is None else (self.near_edge_centre.subs(subs),
                                                                   self.near_edge_end.subs(subs))
        return SharpRules(self.crease_centre.subs(subs), self.crease_end.subs(subs), self.crease_edge.subs(subs), *near)

    def xreplace(self, move) -> SharpRules:
        """The rules with symbols exchanged (no evaluation; the scheme's move of user symbols to parameters)."""
        near = (None, None) if self.near_edge_centre is None else (self.near_edge_centre.xreplace(move),
                                                                   self.near_edge_end.xreplace(move))
        return SharpRules(self.crease_centre.xreplace(move), self.crease_end.xreplace(move),
                          self.crease_edge.xreplace(move), *near)


_NAMES = ("crease_centre", "crease_end", "crease_edge", "near_edge_centre", "near_edge_end")


def _check_angle_use(weight, name: str) -> None:
    """``theta_k`` only as ``cos``/``sin`` of a rational multiple (their values at ``theta_k = pi/k`` are exact in
    ``Q(cos(pi/k))``); a bare ``theta_k``, or ``cos(sqrt(2)*theta_k)``, is not algebraic at the vertex."""
    if weight is None or not (theta_k in weight.free_symbols or weight.has(sp.pi)):
        return
    for call in weight.atoms(sp.cos, sp.sin):
        ratio = sp.simplify(call.args[0] / theta_k)
        if theta_k in call.args[0].free_symbols and not ratio.is_Rational:
            raise InvalidSchemeError(f"sharp rules: {name} = {weight}: {call} is not the cosine or sine of a rational "
                                     "multiple of theta_k (such as cos(theta_k) or sin(2*theta_k)), so it is not exact at "
                                     "the vertex")
    rest = weight.xreplace({call: sp.Dummy() for call in weight.atoms(sp.cos, sp.sin)})
    if rest.has(sp.pi):
        raise InvalidSchemeError(f"sharp rules: {name} = {weight}: pi outside cos and sin is transcendental; the weights "
                                 "must be exact algebraic numbers at the vertex (cos(pi/3), cos(theta_k))")
    if theta_k in rest.free_symbols:
        raise InvalidSchemeError(f"sharp rules: {name} = {weight}: theta_k outside cos and sin (theta_k = pi/k, so the "
                                 "weight would be transcendental); use cos(theta_k) or sin(theta_k)")


def _check_defined_at(name: str, weight, value, k) -> None:
    free = sorted(str(s) for s in value.free_symbols)
    if free:
        raise InvalidSchemeError(f"[sharp] {name} = {weight} has free parameters {', '.join(free)}: a boundary, crease, "
                                 "corner or dart vertex needs their values")
    if value.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or value.is_finite is False:
        raise InvalidSchemeError(f"[sharp] {name} = {weight} is undefined at k = {k} (a sector of {k} faces)")


def standard_sharp_rules() -> SharpRules:
    """The standard rules (OpenSubdiv's, for Catmull-Clark and Loop): 3/4 and 1/8 at a crease vertex, 1/2 on a crease edge."""
    return SharpRules(sp.Rational(3, 4), sp.Rational(1, 8), sp.Rational(1, 2))


@dataclass(frozen=True)
class SharpOptions:
    """OpenSubdiv's options for sharp features (``Sdc::Options``): boundary interpolation and creasing method."""

    #: ``"edge-and-corner"`` (a boundary vertex with one face is a corner) or ``"edge-only"``.
    boundary_interpolation: str = "edge-and-corner"
    #: ``"uniform"`` (sharpness decreases by 1 per level) or ``"chaikin"``.
    crease_method: str = "uniform"

    def __post_init__(self):
        for name, allowed in (("boundary_interpolation", BOUNDARY_INTERPOLATIONS), ("crease_method", CREASE_METHODS)):
            value = getattr(self, name)
            if not isinstance(value, str) or value not in allowed:
                raise InvalidInputError(f"{name} must be one of {', '.join(allowed)}, got {value!r:.40}")

    @property
    def chaikin(self) -> bool:
        return self.crease_method == "chaikin"

    @property
    def corners(self) -> bool:
        """Whether a boundary vertex with a single face is a corner."""
        return self.boundary_interpolation == "edge-and-corner"


class VertexRuleKind(enum.Enum):
    """OpenSubdiv's vertex rules (``Sdc::Crease::Rule``)."""

    SMOOTH = 0
    DART = 1
    CREASE = 2
    CORNER = 3


def check_sharpness(value, argument: str = "sharpness"):
    """``value`` as an exact sharpness: a ``Fraction >= 0`` (a float is read exactly, e.g. ``0.5``), or ``math.inf``
    for an infinitely sharp feature (so is every value ``>= 10``, OpenSubdiv's ``SHARPNESS_INFINITE``)."""
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, str, sp.Basic)):
        raise InvalidInputError(f"{argument} must be a number >= 0 or inf, got {value!r:.40} ({type(value).__name__})")
    if isinstance(value, float):
        if math.isnan(value) or value < 0:
            raise InvalidInputError(f"{argument} must be a number >= 0 or inf, got {value!r}")
        return math.inf if value >= SHARPNESS_INFINITE else Fraction(value)
    if isinstance(value, str) and value.strip().lower() in ("inf", "infinite", "oo"):
        return math.inf
    if isinstance(value, sp.Basic) and value == sp.oo:
        return math.inf
    try:
        expr = exact_value(value, {}, argument=argument)
    except InvalidExpressionError as exc:
        raise InvalidInputError(str(exc)) from None
    if not isinstance(expr, sp.Rational) or expr < 0:
        raise InvalidInputError(f"{argument} must be an exact rational >= 0 or inf, got {expr}")
    return math.inf if expr >= SHARPNESS_INFINITE else Fraction(int(expr.p), int(expr.q))


def is_sharp(s) -> bool:
    return s > 0


def is_infinite(s) -> bool:
    return s >= SHARPNESS_INFINITE


def _semi_sharp(s) -> bool:
    return 0 < s < SHARPNESS_INFINITE


def decrement(s):
    """The sharpness one level finer, uniform rule: ``s - 1``, never below 0; infinite stays infinite."""
    if is_infinite(s):
        return math.inf
    return s - 1 if s > 1 else Fraction(0)


def vertex_rule_kind(vertex_sharpness, edge_sharpnesses: Sequence) -> VertexRuleKind:
    """OpenSubdiv's ``DetermineVertexVertexRule``: a sharp vertex or more than two sharp edges: corner; else by
    the count of sharp incident edges (0 smooth, 1 dart, 2 crease)."""
    if is_sharp(vertex_sharpness):
        return VertexRuleKind.CORNER
    count = sum(1 for s in edge_sharpnesses if is_sharp(s))
    return VertexRuleKind.CORNER if count > 2 else (VertexRuleKind.SMOOTH, VertexRuleKind.DART, VertexRuleKind.CREASE)[count]


def child_edge_sharpnesses(edge_sharpnesses: Sequence, options: SharpOptions) -> list:
    """The sharpness of the child edges at a vertex (one per parent edge, in order) after one level.

    OpenSubdiv's ``SubdivideEdgeSharpnessesAroundVertex``: uniform (or fewer than two edges): :func:`decrement`;
    Chaikin: a semi-sharp edge ``s`` among ``m > 1`` semi-sharp edges becomes ``3/4 s + 1/4 avg(others) - 1``.
    """
    if not options.chaikin or len(edge_sharpnesses) < 2:
        return [decrement(s) for s in edge_sharpnesses]
    semi = [s for s in edge_sharpnesses if _semi_sharp(s)]
    out = []
    for s in edge_sharpnesses:
        if not _semi_sharp(s) or not semi:
            out.append(s if not semi else (math.inf if is_infinite(s) else Fraction(0)))
        elif len(semi) == 1:
            out.append(decrement(s))
        else:
            child = Fraction(3, 4) * s + Fraction(1, 4) * (sum(semi) - s) / (len(semi) - 1) - 1
            out.append(child if child > 0 else Fraction(0))
    return out


def fractional_weight(parent_vertex, child_vertex, parent_edges: Sequence, child_edges: Sequence,
                      options: SharpOptions) -> Fraction:
    """The weight of the parent vertex rule when the parent and child rules differ (OpenSubdiv's
    ``ComputeFractionalWeightAtVertex``): the mean sharpness of the features that turn smooth, at most 1."""
    count, total = 0, Fraction(0)
    if is_sharp(parent_vertex) and not is_sharp(child_vertex):
        count, total = 1, Fraction(parent_vertex)
    for p, c in zip(parent_edges, child_edges):
        turning = (is_sharp(p) and p <= 1) if not options.chaikin else (is_sharp(p) and not is_sharp(c))
        if turning:
            count, total = count + 1, total + p
    if count == 0:
        return Fraction(0)
    return min(Fraction(1), total / count)
