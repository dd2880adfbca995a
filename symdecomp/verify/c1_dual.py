"""Reif's test on a quad neighbourhood whose regular part is the biquadratic B-spline (Doo-Sabin and its variants).

**Input.** An explicit local mesh (:class:`DualNeighbourhood`: faces as counter-clockwise vertex tuples, the
extraordinary element's vertices (for Doo-Sabin the centre ``n``-gon) and the orbit labels
``vertex -> (sector s, class c)``), and the characteristic map's control points: the real planar map
``vertex -> (x, y)`` of the two real subdominant eigenvectors (exact rationals or Arb balls, or one
complex ball per vertex). Nothing here knows the scheme: the mesh and the points say everything.

**The patches.** A vertex of valence 4 whose four faces are quads, with the 3 x 3 control points of
its four faces, is the centre of a uniform biquadratic B-spline patch (:func:`vertex_grid` orders the
grid so that the patch's ``(u, v)`` frame has the faces' orientation). One ring of the characteristic
map is the union of the patches of the vertices that share a face with the extraordinary element's
vertices (:func:`ring_patches`): a dual step halves the parameters, so the next ring in, the same
patches one step later, starts where this one ends. Each patch is converted to Bezier form
(``b_0 = (p_0 + p_1)/2, b_1 = p_1, b_2 = (p_1 + p_2)/2`` per direction) and raised to bicubic, so that
today's bicubic Jacobian (:func:`~symdecomp.verify.bezier.jacobian_net`, bidegree (5, 5)) and its
sign certificate (:func:`~symdecomp.verify.bezier.certify_sign`, de Casteljau where a ball straddles
0) apply unchanged; degree raising only averages the coefficients, so it never loses a sign.

**Regularity** is the Jacobian of one strict sign on every patch of the ring (all of them, so no
symmetry of the points is assumed). **Injectivity** is Reif's winding argument as
:mod:`symdecomp.verify.c1` applies it: a patch's side that faces a vertex of the extraordinary
element (that vertex has no patch) is part of the ring's inner boundary; traversed with the hole on
its left, these sides form a closed curve, and the argument its image sweeps
(:func:`~symdecomp.verify.bezier.curve_angle`, summed piece by piece, which needs no order) is
``2 pi`` times its winding number around the origin. A regular ring whose inner boundary winds once,
with the Jacobian's sign, covers the annulus once: injective. Winding ``|w| > 1``: not injective.

>>> ring_patches(DualNeighbourhood(faces=((0, 1, 2, 3),), centre=(0,)))
Traceback (most recent call last):
  ...
symdecomp.errors.InvalidMeshError: mesh: vertex 1 shares a face with the centre but has no biquadratic patch (valence 1, not 4 quads)
>>> from fractions import Fraction
>>> [str(b) for b in biquadratic_to_bicubic([[Fraction(k) for k in range(3)]] * 3)[0]]  # linear in v: points on a line
['1/2', '5/6', '7/6', '3/2']
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import flint

from symdecomp.algebra.numbers import to_arb
from symdecomp.errors import InvalidInputError, InvalidMeshError
from symdecomp.verify.bezier import certify_sign, curve_angle, jacobian_net

__all__ = ["DualNeighbourhood", "RingPatch", "RingCertificate", "vertex_grid", "ring_patches", "biquadratic_to_bicubic",
           "control_ball", "winding_of", "certify_ring"]

#: A quadratic B-spline span to its cubic Bezier points: B-spline to quadratic Bezier, then raised by one degree.
_RAISE = ((3, 3, 0), (1, 5, 0), (0, 5, 1), (0, 3, 3))
_RAISE_DENOMINATOR = 6


@dataclass(frozen=True)
class DualNeighbourhood:
    """An explicit local mesh around the extraordinary element, with its orbit labels."""

    #: The faces, each a tuple of vertex ids in counter-clockwise order.
    faces: tuple[tuple[Any, ...], ...]
    #: The extraordinary element's vertices (for a dual scheme the centre ``n``-gon).
    centre: tuple[Any, ...]
    #: ``vertex -> (sector, class)``: the orbit labelling under the rotation by one sector.
    labels: Mapping[Any, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        seen: dict[tuple[Any, Any], int] = {}
        for f, face in enumerate(self.faces):
            if len(face) < 3 or len(set(face)) != len(face):
                raise InvalidMeshError(f"mesh: face {f} must have at least 3 distinct vertices, got {tuple(face)!r:.60}")
            for k, v in enumerate(face):
                edge = (v, face[(k + 1) % len(face)])
                if edge in seen:
                    raise InvalidMeshError(f"mesh: edge {edge!r:.40} is in faces {seen[edge]} and {f} in the same direction "
                                           "(faces must be consistently counter-clockwise)")
                seen[edge] = f
        vertices = {v for face in self.faces for v in face}
        missing = [v for v in self.centre if v not in vertices]
        if not self.centre or missing:
            raise InvalidMeshError(f"mesh: centre vertex {missing[0] if missing else None!r:.20} is in no face")


@dataclass(frozen=True)
class RingPatch:
    """One biquadratic patch of the ring: its vertex, the 3 x 3 grid, and the sides that face the hole."""

    vertex: Any
    #: ``grid[i][k]``: the control vertex at ``u``-index ``i``, ``v``-index ``k`` (the vertex itself at ``[1][1]``).
    grid: tuple[tuple[Any, ...], ...]
    #: The sides ``"u0"``, ``"u1"``, ``"v0"``, ``"v1"`` whose neighbour across is a vertex of the extraordinary element.
    hole_sides: tuple[str, ...]


_Halfedges = dict[tuple[Any, Any], tuple[int, int]]


def _halfedges(mesh: DualNeighbourhood) -> _Halfedges:
    """``(tail, tip) -> (face, index of the tail in the face)``."""
    return {(face[k], face[(k + 1) % len(face)]): (f, k) for f, face in enumerate(mesh.faces) for k in range(len(face))}


def vertex_grid(mesh: DualNeighbourhood, vertex: Any, halfedges: _Halfedges | None = None) -> tuple[tuple[Any, ...], ...] | None:
    """The 3 x 3 control grid of ``vertex``'s biquadratic patch, or ``None`` unless it has valence 4 with four quads.

    Around the vertex counter-clockwise the faces are ``(v, a, d, b)``, then the face holding the halfedge
    ``v -> b``, and so on; ``a`` is at ``u + 1``, ``b`` at ``v + 1``, so the frame ``(u, v)`` is the faces' orientation.
    """
    halfedges = _halfedges(mesh) if halfedges is None else halfedges
    start = next((h for h in halfedges if h[0] == vertex), None)
    if start is None or sum(1 for h in halfedges if h[0] == vertex) != 4:
        return None
    grid: list[list[Any]] = [[None] * 3 for _ in range(3)]
    grid[1][1] = vertex
    steps = ((1, 0), (0, 1), (-1, 0), (0, -1))
    tip = start[1]
    for q in range(4):
        if (vertex, tip) not in halfedges:
            return None
        f, k = halfedges[(vertex, tip)]
        face = mesh.faces[f]
        if len(face) != 4:
            return None
        (du, dv), (eu, ev) = steps[q], steps[(q + 1) % 4]
        grid[1 + du][1 + dv] = face[(k + 1) % 4]
        grid[1 + du + eu][1 + dv + ev] = face[(k + 2) % 4]
        tip = face[(k + 3) % 4]
    if tip != start[1]:
        return None
    return tuple(tuple(row) for row in grid)


def ring_patches(mesh: DualNeighbourhood) -> list[RingPatch]:
    """The patches of one ring: every vertex that shares a face with a centre vertex, not itself a centre vertex."""
    centre = set(mesh.centre)
    halfedges = _halfedges(mesh)
    ring = sorted({v for face in mesh.faces if centre & set(face) for v in face} - centre, key=repr)
    out = []
    for v in ring:
        grid = vertex_grid(mesh, v, halfedges)
        if grid is None:
            valence = sum(1 for h in halfedges if h[0] == v)
            raise InvalidMeshError(f"mesh: vertex {v!r:.20} shares a face with the centre but has no biquadratic patch "
                                   f"(valence {valence}, not 4 quads)")
        sides = tuple(name for name, (i, k) in (("u0", (0, 1)), ("u1", (2, 1)), ("v0", (1, 0)), ("v1", (1, 2)))
                      if grid[i][k] in centre)
        out.append(RingPatch(v, grid, sides))
    if not out:
        raise InvalidMeshError("mesh: no vertex shares a face with the centre (the ring is empty)")
    return out


def biquadratic_to_bicubic(values: Sequence[Sequence[Any]]) -> list[list[Any]]:
    """The 4 x 4 bicubic Bezier net of the uniform biquadratic B-spline patch with 3 x 3 control ``values`` (balls or exact)."""
    rows = [[sum((_RAISE[i][a] * values[a][k] for a in range(3)), 0 * values[0][0]) for k in range(3)] for i in range(4)]
    d = _RAISE_DENOMINATOR * _RAISE_DENOMINATOR
    return [[sum((_RAISE[k][b] * rows[i][b] for b in range(3)), 0 * values[0][0]) / d for k in range(4)] for i in range(4)]


def control_ball(value: Any, vertex: Any) -> flint.acb:
    """A control point as a complex ball: an ``acb``, or a pair ``(x, y)`` of exact rationals or ``arb`` balls."""
    if isinstance(value, flint.acb):
        return value
    try:
        x, y = value
    except (TypeError, ValueError):
        raise InvalidMeshError(f"points: the control point of vertex {vertex!r:.20} must be a complex ball or a pair (x, y), "
                               f"got {value!r:.40}") from None
    try:
        return flint.acb(to_arb(x), to_arb(y))
    except InvalidInputError as exc:
        raise InvalidMeshError(f"points: the control point of vertex {vertex!r:.20}: {exc}") from None


#: The control points along each side of a bicubic net, traversed with the outside (the hole) on the left.
_SIDES = {
    "u0": lambda net: [net[0][k] for k in range(4)],
    "v1": lambda net: [net[i][3] for i in range(4)],
    "u1": lambda net: [net[3][k] for k in range(3, -1, -1)],
    "v0": lambda net: [net[i][0] for i in range(3, -1, -1)],
}


@dataclass(frozen=True)
class RingCertificate:
    """What the ring's patches show: regularity (the Jacobian's sign) and the inner boundary's winding number."""

    #: ``"regular"`` (one strict sign), ``"changes"`` (shown to change sign) or ``"undecided"``.
    status: str
    #: ``+1``/``-1`` when regular.
    jacobian_sign: int | None
    #: A rigorous lower bound of ``sign * J`` (in the patches' own parameters) when regular.
    jacobian_lower_bound: float | None
    #: The deepest de Casteljau subdivision used.
    depth: int
    #: The winding number of the inner boundary's image around the origin (``None``: not certified).
    winding_number: int | None
    #: The patches examined (all of the ring).
    patches: int
    #: Where the sign failed: the patch's vertex, its orbit label and the parameter box (else ``None``).
    where: str | None = None


def winding_of(angle: flint.arb | None) -> int | None:
    """The winding number whose ``2 pi`` multiple is the swept ``angle``, if the ball holds one integer (else ``None``)."""
    if angle is None:
        return None
    w = angle / (2 * flint.arb.pi())
    lo, hi = math.ceil(float(w.lower())), math.floor(float(w.upper()))
    return lo if lo == hi else None


def certify_ring(mesh: DualNeighbourhood, points: Mapping[Any, Any], *, max_depth: int = 6) -> RingCertificate:
    """Certify the characteristic map's ring on ``mesh`` (see the module docstring) at the current FLINT precision."""
    patches = ring_patches(mesh)
    nets = []
    angle: flint.arb | None = flint.arb(0)
    for patch in patches:
        try:
            values = [[control_ball(points[v], v) for v in row] for row in patch.grid]
        except KeyError as e:
            raise InvalidMeshError(f"points: no control point for vertex {e.args[0]!r:.20}") from None
        net = biquadratic_to_bicubic(values)
        x, y = [[z.real for z in row] for row in net], [[z.imag for z in row] for row in net]
        nets.append(jacobian_net(x, y))  # type: ignore[no-untyped-call]  # bezier's nets are untyped lists of balls
        for side in patch.hole_sides:
            piece = curve_angle(_SIDES[side](net))
            angle = None if angle is None or piece is None else angle + piece
    sign = certify_sign(nets, max_depth)
    winding = winding_of(angle)
    if sign.status in ("changes", "undecided"):
        where = None
        if sign.where is not None:
            p, ur, vr = sign.where
            v = patches[p].vertex
            where = (f"the patch of vertex {v!r} (orbit {mesh.labels.get(v, '?')}), u in [{ur[0]:g}, {ur[1]:g}], "
                     f"v in [{vr[0]:g}, {vr[1]:g}]")
        return RingCertificate(sign.status, None, None, sign.depth, winding, len(patches), where)
    s = 1 if sign.status == "positive" else -1
    return RingCertificate("regular", s, sign.lower_bound, sign.depth, winding, len(patches))
