"""Limit positions, tangents and normals of every vertex of a mesh: exact masks once per kind, applied with numpy.

The masks of a vertex depend only on its neighbourhood kind (:mod:`symdecomp.analysis.mesh_kinds`), and a
mesh of a million faces has a few dozen kinds. :func:`kind_masks` computes a kind's masks exactly, once:

* ``smooth`` valence ``n``: the position mask, the exact left eigenvector of the frequency-0 block for 1 (as
  :func:`~symdecomp.analysis.inspection.position_weights` solves it, evaluated to 30 digits; its closed form on
  request, :func:`exact_position`) and the two tangent masks of frequency 1
  (:func:`~symdecomp.analysis.masks.ring_masks`);
* boundary, crease, corner and dart vertices: the left eigenvectors of the vertex's exact 1-ring matrix
  (:func:`~symdecomp.analysis.masks.sharp_masks`). At a semi-sharp vertex (sharpness ``s``, finite)
  the rules change for ``L = ceil(s)`` levels before they settle, so the limit masks are the settled masks at
  level ``L`` times the exact one-step matrices ``S_{L-1} .. S_0`` (:func:`~symdecomp.schemes.sector.exact_sharp_matrix`).

then converts them to float64 once. :func:`mesh_limits` gathers each kind's 1-rings (one integer array) and
applies its masks with one matrix product: no per-vertex symbolic work. The unit normal is
``t_1 x t_2 / |t_1 x t_2|`` of the first two tangent masks (at a crease: the curve tangent and the first
sector's cross tangent, so the normal of that side), turned to the side the faces are counter-clockwise
from (one sign per kind, by the total of its rings' vector areas: a control net folded over at a vertex does not
turn its normal). With ``exact=True`` the limit positions are also computed exactly, vertex by vertex (slow; on request).

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> cube = PolygonMesh.from_arrays([(x, y, z) for z in (0, 2) for y in (0, 2) for x in (0, 2)],
...     [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])
>>> r = mesh_limits(cube, catmull_clark(), exact=True)
>>> r.exact[0], r.normals[0].round(12).tolist()
((1/2, 1/2, 1/2), [-0.57735026919, -0.57735026919, -0.57735026919])
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from symdecomp.analysis.mesh_kinds import NeighbourhoodKind, VertexKinds, classify_vertices
from symdecomp.errors import InvalidMeshError, NotApplicableError
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached, check_memory, check_type

__all__ = ["KindMasks", "MeshLimits", "kind_masks", "mesh_limits", "float_points", "exact_as_floats", "exact_position", "apply_masks"]


@dataclass(frozen=True)
class KindMasks:
    """The limit masks of one neighbourhood kind, as float64 rows over the kind's 1-ring (``O, a_0.., b_0..``)."""

    kind: NeighbourhoodKind
    #: The position mask (weights summing to 1).
    position: np.ndarray
    #: The tangent masks, one row each (2, or 3 at a crease: the curve tangent and one cross tangent per side).
    tangents: np.ndarray
    #: Their names (``"tangent 1"``, ``"boundary curve tangent"``, ``"cross tangent, sector 1"``, ...).
    tangent_names: tuple[str, ...]
    #: The position mask exactly (sympy numbers) for sharp kinds, ``None`` for smooth ones (:func:`exact_position`
    #: brings it to closed form on request) and where it is not a closed form here.
    exact_position: tuple | None
    #: Whether the tangents' eigenvalues are certified the subdominant ones (``None``: the caller decides, smooth kinds).
    tangent_plane: bool | None
    #: Why, or why not (empty for smooth kinds).
    reason: str
    #: Levels of semi-sharp rules folded into the masks (0: the masks of the one-step matrix).
    levels: int = 0


def float_points(mesh: PolygonMesh) -> np.ndarray:
    """The mesh's vertices as a ``(V, 3)`` float64 array (the one place a mesh's points become doubles)."""
    points = getattr(mesh, "points_array", None)
    if points is not None:
        return np.asarray(points, dtype=np.float64)
    check_memory(24 * len(mesh.points) + 1, f"{mesh.name}: the float coordinates of {len(mesh.points)} vertices")
    return np.array(mesh.points, dtype=np.float64).reshape(-1, 3)


def _position_values(scheme: Scheme, n: int) -> list[complex]:
    """The class weights of the position mask ``(w_O, w_a[, w_b])`` to 30 digits: the exact left eigenvector of the
    frequency-0 block for 1 (as :func:`~symdecomp.analysis.inspection.position_weights` solves it), evaluated without
    bringing it to a closed form first (sympy's simplification is what costs there)."""
    from symdecomp.analysis.frequency import ring_blocks
    from symdecomp.analysis.inspection import position_weights

    blocks = ring_blocks(scheme, 1)
    E0 = sp.Matrix(blocks.frequency_zero_matrix(n)) - sp.eye(1 + len(blocks.classes))
    K = E0.shape[0]
    system = sp.Matrix([[E0[r, c] for r in range(1, K)] for c in range(1, K)])
    if abs(complex(sp.N(system.det(), 30))) < 1e-20:  # singular or nearly: the exact route decides, and says why
        return [complex(sp.N(w, 30)) for w in position_weights(scheme, n)]
    y = [sp.Integer(1)] + list(system.LUsolve(sp.Matrix([-E0[0, c] for c in range(1, K)])))
    values = [complex(sp.N(x, 30)) for x in y]
    total = sum(values)
    if not abs(total) > 1e-20:  # the eigenvector sums to 0: no affine mask; the exact route says so
        return [complex(sp.N(w, 30)) for w in position_weights(scheme, n)]
    return [values[0] / total] + [x / (n * total) for x in values[1:]]


def _smooth(scheme: Scheme, kind: NeighbourhoodKind) -> KindMasks:
    from symdecomp.analysis.inspection import _tangent_weights

    n = kind.faces
    scheme.fitting_valence(n)
    classes = _position_values(scheme, n)
    values = [classes[0]] + [w for w in classes[1:] for _ in range(n)]
    if any(abs(v.imag) > 1e-25 or not np.isfinite(v.real) for v in values):
        raise NotApplicableError(f"{scheme.name} at valence {n}: the position mask is not a real vector ({classes[0]}, ...)")
    position = np.array([v.real for v in values])
    tangents = np.array(_tangent_weights(scheme, n))
    return KindMasks(kind, position, tangents, ("tangent 1", "tangent 2"), None, None, "")


def exact_position(scheme: Scheme, masks: KindMasks) -> tuple | None:
    """The position mask of ``masks``' kind exactly (sympy numbers, one per 1-ring point), or ``None`` where it is not
    a closed form here (a semi-sharp kind; a sharp mask past degree 2)."""
    from symdecomp.analysis.inspection import position_weights

    if masks.exact_position is not None or masks.kind.name != "smooth":
        return masks.exact_position
    n = masks.kind.faces
    classes = position_weights(scheme, n)
    return (classes[0],) + tuple(w for w in classes[1:] for _ in range(n))


def _floats(mask) -> np.ndarray:
    return np.array([float(t) for t in mask.texts(20)])


def _settle_levels(sharpness) -> int:
    """Levels until a semi-sharp sharpness has decayed to 0 (uniform rule: one per level)."""
    return 0 if math.isinf(sharpness) or sharpness == 0 else math.ceil(sharpness)


def _sharp(scheme: Scheme, kind: NeighbourhoodKind) -> KindMasks:
    from symdecomp.analysis.masks import sharp_masks
    from symdecomp.schemes.sector import exact_sharp_matrix

    vertex = kind.sharp_vertex(scheme.lattice)
    levels = _settle_levels(kind.sharpness)
    masks = sharp_masks(scheme, vertex, level=levels)
    if len(masks.tangents) < 2:
        raise NotApplicableError(f"{kind}: only {len(masks.tangents)} tangent mask(s): {masks.reason}")
    position = _floats(masks.position)
    tangents = np.array([_floats(t) for t in masks.tangents])
    exact = masks.position.exact() if levels == 0 else None
    for level in reversed(range(levels)):  # m_L S_{L-1} .. S_0, applied from the left
        step = exact_sharp_matrix(scheme, vertex, level=level)
        S = np.array([[float(step[i, j]) for j in range(step.ncols())] for i in range(step.nrows())])
        position, tangents = position @ S, tangents @ S
    return KindMasks(kind, position, tangents, tuple(t.name for t in masks.tangents),
                     None if exact is None else tuple(exact), masks.tangent_plane, masks.reason, levels)


def _check_kind(kind) -> NeighbourhoodKind:
    return check_type(kind, NeighbourhoodKind, "kind", hint="a kind of symdecomp.analysis.mesh_kinds.classify_vertices")


@cached(maxsize=512, scheme=check_scheme, kind=_check_kind)
def kind_masks(scheme: Scheme, kind: NeighbourhoodKind) -> KindMasks:
    """The masks of ``kind`` under ``scheme`` (module docstring), computed exactly once and kept.

    :class:`~symdecomp.errors.NotApplicableError` when the kind has no masks here (1 not a simple eigenvalue,
    weights out of reach of exact arithmetic), with the reason.
    """
    return _smooth(scheme, kind) if kind.name == "smooth" else _sharp(scheme, kind)


@dataclass(frozen=True)
class MeshLimits:
    """The limit data of every vertex of a mesh (rows of ``NaN`` where a vertex was not analysed)."""

    scheme: str
    #: The classification: kinds, 1-rings, and the vertices not analysed with why.
    kinds: VertexKinds
    #: Kind -> its :class:`KindMasks`, or the reason it has none.
    masks: dict
    #: ``(V, 3)`` limit positions.
    limits: np.ndarray
    #: ``(V, 3)`` unit normals (``NaN`` where the tangents are parallel).
    normals: np.ndarray
    #: ``(V, 2, 3)`` the first two tangents (the masks' scaling).
    tangents: np.ndarray
    #: Vertex -> exact limit position (sympy numbers), with ``exact=True`` only.
    exact: dict
    #: Vertex -> why its float limit is missing although its kind has masks (coordinates too large for doubles).
    numeric: dict
    #: Transient vertex -> why its limit frame was not computed (:mod:`symdecomp.analysis.mesh_transient`).
    unresolved: dict = field(default_factory=dict)

    def analysed(self) -> np.ndarray:
        """Boolean per vertex: whether it has a limit position."""
        return ~np.isnan(self.limits[:, 0])

    def not_analysed(self) -> dict[int, str]:
        """Vertex -> why it has no verdict (no kind, no outcome) or its float limit overflowed."""
        out = dict(self.kinds.not_analysed)
        out.update(self.numeric)
        return dict(sorted(out.items()))

    def no_limit(self) -> dict[int, str]:
        """Vertex -> why it has a verdict but no limit point: off the surface, not computed for a computed outcome
        (:attr:`VertexKinds.outcomes`), or its kind has no limit masks here."""
        out = {v: self.unresolved.get(v, o.no_limit) for v, o in self.kinds.outcomes.items()}
        for kind, masks in self.masks.items():
            if isinstance(masks, str):
                out.update({int(v): self.unresolved.get(int(v), f"{kind}: no limit masks: {masks}")
                            for v in self.kinds.rings[kind][0]})
        return {v: why for v, why in sorted(out.items()) if np.isnan(self.limits[v, 0])}


#: Vertices per block when a kind's masks are applied: bounds the temporary ``(block, ring, 3)`` arrays.
BLOCK_VERTICES = 1 << 16


def _cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``u x v`` over the last axis (``numpy.cross`` copies both operands first)."""
    return np.stack([u[..., 1] * v[..., 2] - u[..., 2] * v[..., 1], u[..., 2] * v[..., 0] - u[..., 0] * v[..., 2],
                     u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]], axis=-1)


def _orientation(points: np.ndarray, rings: np.ndarray, edge_count: int, closed: bool) -> np.ndarray:
    """Per vertex: the 1-ring's vector area ``sum (a_i - O) x (a_{i+1} - O)`` (counter-clockwise faces: outward)."""
    centre = points[rings[:, 0]][:, None, :]
    a = points[rings[:, 1 : 1 + edge_count]] - centre
    nxt = np.roll(a, -1, axis=1) if closed else a[:, 1:]
    return _cross(a[:, : nxt.shape[1]], nxt).sum(axis=1)


def apply_masks(points: np.ndarray, rings: np.ndarray, masks: KindMasks, edge_count: int) -> tuple:
    """``(limits, unit normals, tangents)`` of the vertices whose 1-rings (rows of indices into ``points``, the masks'
    order) are ``rings``; ``edge_count``: the edge neighbours ``a_i`` in a ring."""
    m = len(rings)
    limit, cross, tangents = np.empty((m, 3)), np.empty((m, 3)), np.empty((m, 2, 3))
    turn = 0.0
    for lo in range(0, m, BLOCK_VERTICES):
        block = slice(lo, lo + BLOCK_VERTICES)
        ring_points = points[rings[block]]  # (block, ring, 3)
        limit[block] = np.einsum("k,mkc->mc", masks.position, ring_points)
        tangents[block] = np.einsum("tk,mkc->mtc", masks.tangents[:2], ring_points)
        cross[block] = _cross(tangents[block, 0], tangents[block, 1])
        # t_1 x t_2 turns the same way against the faces at every vertex of a kind (a linear map of the ring), so one
        # sign serves the kind: the vector areas' total decides it (one control net folded over cannot flip its normal)
        turn += float(np.einsum("mc,mc->", cross[block], _orientation(points, rings[block], edge_count, masks.kind.closed)))
    side = np.sign(turn) or 1.0
    norm = np.linalg.norm(cross, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        cross *= (side / np.where(norm > 0, norm, np.nan))[:, None]
    return limit, cross, tangents


def _exact_limit(mesh: PolygonMesh, ring, weights) -> tuple:
    from symdecomp.analysis.inspection import exact_combination

    return exact_combination(weights, [[sp.Rational(x.numerator, x.denominator) for x in mesh.points[v]] for v in ring])


def mesh_limits(mesh: PolygonMesh, scheme: Scheme, *, exact: bool = False, progress=None) -> MeshLimits:
    """Classify every vertex of ``mesh``, compute each kind's masks once, apply them (module docstring).

    ``progress(iterable, total, what)``, when given, wraps the loops (the command line's progress lines).
    """
    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    scheme = check_scheme(scheme)
    wrap = (lambda xs, total, what: progress(xs, total, what)) if progress is not None else (lambda xs, total, what: xs)
    kinds = classify_vertices(mesh, scheme.lattice, progress=lambda xs, total: wrap(xs, total, "classify"))
    points = float_points(mesh)
    V = len(points)
    check_memory(120 * V + 1, f"{mesh.name}: the limit data of {V} vertices")
    limits, normals, tangents = np.full((V, 3), np.nan), np.full((V, 3), np.nan), np.full((V, 2, 3), np.nan)
    masks: dict[NeighbourhoodKind, KindMasks | str] = {}
    exact_limits, overflow = {}, {}
    largest = float(np.max(np.abs(points))) if V else 1.0
    scale = largest if largest > 1e100 or 0 < largest < 1e-100 else 1.0  # keep the products in the double range
    scaled = points / scale if scale != 1.0 else points
    for kind in wrap(kinds.kinds, len(kinds.kinds), "kinds"):
        try:
            masks[kind] = m = kind_masks(scheme, kind)
        except NotApplicableError as exc:
            masks[kind] = str(exc)
            continue
        ids, rings = kinds.rings[kind]
        edge_count = kind.faces + (0 if kind.closed else 1)
        with np.errstate(all="ignore"):  # coordinates near the double range: scaled, and what overflows is named below
            limit, normals[ids], tangent = apply_masks(scaled, rings, m, edge_count)
            limits[ids], tangents[ids] = limit * scale, tangent * scale
        bad = ids[~np.isfinite(limits[ids]).all(axis=1)]
        limits[bad], normals[bad], tangents[bad] = np.nan, np.nan, np.nan
        overflow.update({int(v): "its 1-ring's coordinates overflow double precision in the masks" for v in bad})
        weights = exact_position(scheme, m) if exact else None
        if weights is not None:
            exact_limits.update({int(v): _exact_limit(mesh, ring, weights) for v, ring in zip(ids, rings.tolist())})
    unresolved = _transient(mesh, scheme, kinds, masks, (limits, normals, tangents), wrap)
    return MeshLimits(scheme.name, kinds, masks, limits, normals, tangents, dict(sorted(exact_limits.items())), overflow,
                      unresolved)


def _transient(mesh: PolygonMesh, scheme: Scheme, kinds: VertexKinds, masks: dict, frames: tuple, wrap) -> dict[int, str]:
    """The limit frames of the transient vertices (:mod:`symdecomp.analysis.mesh_transient`), and of the semi-sharp
    vertices whose kind has no masks here, vertex by vertex, into ``frames``; returns why, where one is not computed."""
    from symdecomp.analysis.mesh_kinds import decayed_outcome
    from symdecomp.analysis.mesh_transient import transient_frame

    todo = {v: o for v, o in kinds.outcomes.items() if o.eventual is not None}
    for kind in kinds.kinds:  # semi-sharp kinds whose one-step matrices are not rational (Loop's): the same route
        if not math.isinf(kind.sharpness) and kind.name != "smooth" and isinstance(masks.get(kind), str):
            todo.update({int(v): decayed_outcome(mesh, int(v)) for v in kinds.rings[kind][0]})
    unresolved = {}
    for v in wrap(list(todo), len(todo), "transient vertices"):
        frame = transient_frame(mesh, scheme, v, todo[v]) if not isinstance(todo[v], str) else todo[v]
        if isinstance(frame, str):
            unresolved[v] = frame
            continue
        for array, value in zip(frames, frame):
            array[v] = value
    return unresolved


def exact_as_floats(values) -> tuple[float, ...]:
    """Exact sympy numbers as doubles (for comparing the exact route with the float one)."""
    return tuple(float(sp.N(x, 30)) for x in values)

