"""``oracle --mesh``: the limit positions and normals of every analysed vertex of a mesh against OpenSubdiv's.

The toolkit's side is :func:`~symdecomp.analysis.mesh_limits.mesh_limits` (exact masks per neighbourhood kind,
applied in float64); OpenSubdiv's side refines the same mesh with the same tags (creases, corners, boundary
interpolation; uniform creasing) ``L`` levels, ``L`` the largest finite sharpness rounded up (so every semi-sharp
crease has decayed), and takes ``Far::PrimvarRefiner::Limit`` at each base vertex's descendant: its limit
position and first derivatives ``d/du``, ``d/dv``; the normal is ``d/du x d/dv`` normalised.

:func:`compare_mesh` reports, over the analysed vertices, the largest distance between the limit positions
(relative to the mesh's bounding-box diagonal, at least 1) and between the unit normals; they agree when both are
at most ``tolerance`` (default ``1e-12``). At a crease the surface has one tangent plane per side: the normals are
not compared there, nor where the toolkit's masks are not certified the tangent plane's (an interior corner); those
vertices are counted apart (:attr:`MeshOracleResult.normals_skipped`).

At a dart OpenSubdiv's limit mask is the smooth vertex's (``Sdc::Scheme::ComputeVertexLimitMask`` treats
``RULE_DART`` as ``RULE_SMOOTH``), not a left eigenvector of the dart's subdivision matrix, whose exact mask the
toolkit applies: the two differ by design, so dart vertices are compared apart
(:attr:`MeshOracleResult.dart_position_disagreement`), outside the verdict.

At a boundary vertex of more faces than a regular one (``k >= 3`` for Catmull-Clark, ``k >= 4`` for Loop; a
semi-sharp crease into it decays first) OpenSubdiv's cross-boundary tangent is Biermann et al.'s
(``Sdc::Scheme<...>::assignCreaseLimitTangentMasks``, "the irregular case"): the tangent of their modified
boundary rules (``theta = pi/k``), not of the surface OpenSubdiv refines with the plain crease rule. The
positions there agree, the normals differ by design: they are compared apart
(:attr:`MeshOracleResult.biermann_normal_disagreement`), outside the verdict.

OpenSubdiv holds a sharpness in single precision: reading ``t crease 2/1/0 3 5 0.1`` it refines with the float
nearest ``1/10``. Both sides are then given that float, exactly (:func:`single_precision_tags`; the toolkit's
masks are exact in it), and the tags so rounded are counted (:attr:`MeshOracleResult.rounded_tags`).
"""

from __future__ import annotations

import ctypes
import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from symdecomp.analysis.mesh_limits import KindMasks, float_points, mesh_limits
from symdecomp.errors import InternalError
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import Scheme, check_scheme

__all__ = ["MeshOracleResult", "compare_mesh", "osd_mesh_frames", "single_precision_tags", "TOLERANCE"]

#: The default agreement: positions relative to the mesh's size, normals as unit vectors.
TOLERANCE = 1e-12


#: The tolerance at vertices blended with a weight OpenSubdiv rounds to single precision (relative error ``2**-24``,
#: times the difference of the two rules' points, a fraction of the mesh's size).
SINGLE_PRECISION_TOLERANCE = 1e-6


def _single_precision(ours) -> np.ndarray:
    """The transient vertices whose fractional weights are not exact in single precision."""
    def exact(w) -> bool:
        return Fraction(float(np.float32(float(w)))) == w

    return np.array([v for v, o in ours.kinds.outcomes.items() if o.eventual is not None and not all(map(exact, o.weights))],
                    dtype=np.int64)


@dataclass(frozen=True)
class MeshOracleResult:
    """The comparison of one mesh with OpenSubdiv."""

    mesh: str
    scheme: str
    #: Vertices compared (the analysed ones but darts).
    compared: int
    #: Largest distance between limit positions, over the bounding-box diagonal (at least 1).
    position_disagreement: float
    #: Largest distance between unit normals.
    normal_disagreement: float
    #: The vertex where each is largest (``None`` with nothing compared).
    worst_position_vertex: int | None
    worst_normal_vertex: int | None
    #: Vertices whose normal is not compared: creases (one tangent plane per side) and vertices whose masks are not
    #: certified the tangent plane's (an interior corner).
    normals_skipped: int
    #: Dart vertices (compared apart: OpenSubdiv's limit mask there is the smooth one) and their largest disagreement.
    darts: int
    dart_position_disagreement: float
    #: OpenSubdiv's refinement levels before the limit.
    levels: int
    tolerance: float
    #: Sharpness tags not exact in OpenSubdiv's single precision, given to both sides rounded to it.
    rounded_tags: int = 0
    #: Boundary vertices of more faces than a regular one (OpenSubdiv's normal is Biermann et al.'s) and their largest normal
    #: disagreement, outside the verdict.
    biermann: int = 0
    biermann_normal_disagreement: float = 0.0
    #: Transient vertices whose rule changes with a fractional weight not exact in single precision (OpenSubdiv blends
    #: with the float nearest it): compared apart, to :data:`SINGLE_PRECISION_TOLERANCE`, and their largest disagreement.
    single_precision: int = 0
    single_precision_disagreement: float = 0.0

    @property
    def agrees(self) -> bool:
        return (self.position_disagreement <= self.tolerance and self.normal_disagreement <= self.tolerance
                and self.single_precision_disagreement <= SINGLE_PRECISION_TOLERANCE)

    def as_json(self) -> dict:
        out = {name: getattr(self, name) for name in self.__dataclass_fields__}
        out["agrees"] = self.agrees
        return out


def single_precision_tags(mesh: PolygonMesh) -> tuple[PolygonMesh, int]:
    """``mesh`` with each finite sharpness replaced by the single-precision float OpenSubdiv stores for it (exactly,
    as a ``Fraction``), and how many tags changed; ``mesh`` itself when none does."""
    from fractions import Fraction

    from symdecomp.schemes.mesh_tags import MeshTags

    def single(s):
        return s if s >= 10 else Fraction(float(np.float32(float(s))))

    tags = mesh.tags
    creases = {e: single(s) for e, s in tags.creases.items()}
    corners = {v: single(s) for v, s in tags.corners.items()}
    changed = sum(creases[e] != s for e, s in tags.creases.items()) + sum(corners[v] != s for v, s in tags.corners.items())
    if not changed:
        return mesh, 0
    rounded = MeshTags(creases, corners, tags.holes, tags.interpolate_boundary, tags.crease_method, tags.triangle_subdivision)
    out = PolygonMesh(mesh.points, mesh.faces, mesh.name, tags=rounded)
    out.defects, out.face_index = mesh.defects, mesh.face_index
    return out, changed


def _levels(mesh: PolygonMesh) -> int:
    finite = [s for s in list(mesh.tags.creases.values()) + list(mesh.tags.corners.values()) if 0 < s < 10]
    return min(10, max((math.ceil(s) for s in finite), default=0))


def osd_mesh_frames(mesh: PolygonMesh, scheme: Scheme, levels: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """OpenSubdiv's limit positions and first derivatives of every vertex of ``mesh`` (tags included), ``(V, 3)`` each."""
    return _osd_frames(float_points(mesh), mesh.faces, mesh.tags.creases, mesh.tags.corners, mesh.tags.interpolate_boundary,
                       scheme, levels, mesh.tags.crease_method)


def _osd_frames(points, faces, creases, corners, interpolate_boundary: str, scheme: Scheme, levels: int,
                creasing: str = "uniform") -> tuple:
    from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
    from symdecomp.verify.opensubdiv.sharp import OsdOptions, _entry, _tags

    options = OsdOptions(scheme.lattice.select({BICUBIC: "catmull-clark", BOX_SPLINE: "loop"}, "OpenSubdiv's scheme"),
                         interpolate_boundary, creasing)
    fn = _entry("symdecomp_osd_tagged_limit_frames")
    ip, dp, fp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_float)
    fn.argtypes = [ip, ctypes.c_int, ctypes.c_int, ctypes.c_int, ip, dp, ctypes.c_int, ip, fp, ctypes.c_int, ip, fp,
                   ctypes.c_int, dp, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    points = np.ascontiguousarray(points, dtype=np.float64)
    faces = np.ascontiguousarray(faces, dtype=np.intc)
    def osd(s):  # OpenSubdiv's infinitely sharp is 10 and above
        return math.inf if s >= 10 else s

    tags = _tags({tuple(e): osd(s) for e, s in creases.items() if s > 0}, {v: osd(s) for v, s in corners.items() if s > 0},
                 len(points))
    limits, du, dv = (np.zeros_like(points) for _ in range(3))
    err = ctypes.create_string_buffer(512)
    rc = fn(options.codes(), options.sides, len(points), len(faces), faces.ctypes.data_as(ip), points.ctypes.data_as(dp),
            *tags, levels, limits.ctypes.data_as(dp), du.ctypes.data_as(dp), dv.ctypes.data_as(dp), err, len(err))
    if rc != 0:
        raise InternalError(f"OpenSubdiv bridge failed (code {rc}): {err.value.decode(errors='replace')}")
    return limits, du, dv


#: Faces OpenSubdiv holds at most after the levels of one call (about 400 bytes each): the stars are taken in batches.
REFINED_FACES = 1 << 20


def _star_frames(mesh: PolygonMesh, scheme: Scheme, vertices, levels: int) -> tuple:
    """OpenSubdiv's frames at ``vertices`` after ``levels`` levels, each from its star alone (the faces at it, their tags).

    A vertex's 1-ring one level down is made from its faces only (its vertex point from its 1-ring, the points of its
    edges from the two faces at each, the face points from its faces), so the limit of its descendant depends on its
    star alone; the stars go to OpenSubdiv as disjoint pieces of one mesh, a batch at a time, instead of the whole
    mesh refined ``levels`` times (OpenSubdiv's rook, 3,000 quads at 7 levels, took 19 GB). Under Chaikin's rule a half
    edge's sharpness at its far end depends on the other edges there, so a vertex's piece is its 2-ring (the faces at
    its 1-ring's vertices): one level down, the child's 2-ring is made from the children of the 1-ring's faces, whose
    every rule sees complete fans in the 2-ring (:mod:`symdecomp.analysis.mesh_transient` refines the same pieces).
    """
    points, faces, tags = float_points(mesh), mesh.faces, mesh.tags
    at: dict[int, list[int]] = {}
    for i, f in enumerate(faces):
        for x in f:
            at.setdefault(x, []).append(i)
    if tags.crease_method == "chaikin":
        at = {v: sorted({i for x in {x for j in at[v] for x in faces[j]} for i in at[x]}) for v in vertices} | {
            x: fs for x, fs in at.items() if x not in vertices}
    out = tuple(np.zeros((len(vertices), 3)) for _ in range(3))
    per_batch = max(1, REFINED_FACES // (4**levels))
    done = 0
    while done < len(vertices):
        piece_points: list = []
        piece_faces: list = []
        creases: dict = {}
        corners: dict = {}
        where: list[int] = []
        count = 0
        for v in vertices[done:]:
            if count and count + len(at[v]) > per_batch:
                break
            star = sorted({x for i in at[v] for x in faces[i]})
            local = {x: len(piece_points) + k for k, x in enumerate(star)}
            piece_points += [points[x] for x in star]
            piece_faces += [[local[x] for x in faces[i]] for i in at[v]]
            creases.update({(min(local[a], local[b]), max(local[a], local[b])): tags.sharpness_of_edge(a, b)
                            for i in at[v] for a, b in zip(faces[i], faces[i][1:] + faces[i][:1])})
            corners.update({local[x]: tags.corners[x] for x in star if x in tags.corners})
            where.append(local[v])
            count += len(at[v])
        got = _osd_frames(np.array(piece_points), piece_faces, creases, corners, tags.interpolate_boundary, scheme, levels,
                          tags.crease_method)
        for frame, values in zip(out, got):
            frame[done:done + len(where)] = values[where]
        done += len(where)
    return out


def _frames(mesh: PolygonMesh, scheme: Scheme, ours, levels: int) -> tuple:
    """OpenSubdiv's frames after ``levels`` levels at the kinds with a semi-sharp feature (it must decay first), at level
    0 elsewhere: a smooth or infinitely sharp neighbourhood refines by the same rules at every level, and OpenSubdiv's
    own rounding grows with the levels (``1e-11`` in the normals after 6)."""
    frames = osd_mesh_frames(mesh, scheme, 0)
    if levels == 0:
        return frames
    late = [int(v) for kind in ours.kinds.kinds if not (kind.name == "smooth" or kind.sharpness == math.inf)
            for v in ours.kinds.rings[kind][0]]
    late += [v for v, outcome in ours.kinds.outcomes.items() if outcome.eventual is not None]  # transient tags
    if late:
        for frame, values in zip(frames, _star_frames(mesh, scheme, late, levels)):
            frame[late] = values
    return frames


def _groups(ours, scheme: Scheme):
    """``(kind, masks, vertices)`` per kind, and per transient vertex its eventual kind (whose rules act at its limit)."""
    from symdecomp.analysis.mesh_limits import kind_masks
    from symdecomp.errors import NotApplicableError

    for kind in ours.kinds.kinds:
        yield kind, ours.masks[kind], ours.kinds.rings[kind][0]
    for v, outcome in ours.kinds.outcomes.items():
        if outcome.eventual is not None:
            masks: KindMasks | str
            try:
                masks = kind_masks(scheme, outcome.eventual)
            except NotApplicableError as exc:
                masks = str(exc)
            yield outcome.eventual, masks, np.array([v], dtype=np.int64)


def compare_mesh(mesh: PolygonMesh, scheme: Scheme, *, tolerance: float = TOLERANCE) -> MeshOracleResult:
    """Compare every analysed vertex's limit position and normal with OpenSubdiv's (module docstring)."""
    scheme = check_scheme(scheme)
    mesh, rounded = single_precision_tags(mesh)
    ours = mesh_limits(mesh, scheme)
    levels = _levels(mesh)
    limits, du, dv = _frames(mesh, scheme, ours, levels)
    analysed = np.flatnonzero(ours.analysed())
    points = float_points(mesh)
    size = max(1.0, float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))))
    regular = 2 if scheme.lattice.face_sides == 4 else 3  # faces at a regular boundary vertex
    two_sided, dart, biermann = (np.zeros(len(points), dtype=bool) for _ in range(3))
    for kind, masks, where in _groups(ours, scheme):
        if (kind.closed and kind.name != "smooth" and len(kind.sectors) >= 2) or getattr(masks, "tangent_plane", None) is False:
            two_sided[where] = True
        elif not kind.closed and (len(kind.sectors) == 1 or kind.sharpness < 10) and sum(kind.sectors) > regular:
            biermann[where] = True
        if kind.name == "dart":
            dart[where] = True
    rounded_weights = np.intersect1d(_single_precision(ours), analysed)
    analysed = np.setdiff1d(analysed, rounded_weights)
    single = (np.linalg.norm(ours.limits[rounded_weights] - limits[rounded_weights], axis=1) / size).max(initial=0.0)
    darts, analysed = analysed[dart[analysed]], analysed[~dart[analysed]]
    dart_position = np.linalg.norm(ours.limits[darts] - limits[darts], axis=1) / size
    cross = np.cross(du, dv)
    with np.errstate(invalid="ignore", divide="ignore"):
        theirs = cross / np.linalg.norm(cross, axis=1)[:, None]
    position = np.linalg.norm(ours.limits[analysed] - limits[analysed], axis=1) / size
    def normals(ids):
        out = np.linalg.norm(ours.normals[ids] - theirs[ids], axis=1)
        return np.where(np.isnan(out), np.inf, out)

    apart = analysed[biermann[analysed] & ~two_sided[analysed]]
    one_sided = analysed[~two_sided[analysed] & ~biermann[analysed]]
    normal = normals(one_sided)

    def worst(values, ids):
        return (float(values.max()), int(ids[int(values.argmax())])) if len(values) else (0.0, None)

    (p, pv), (nrm, nv) = worst(position, analysed), worst(normal, one_sided)
    return MeshOracleResult(mesh.name, scheme.name, len(analysed), p, nrm, pv, nv, int(two_sided[analysed].sum()),
                            len(darts), float(dart_position.max()) if len(darts) else 0.0, levels, float(tolerance), rounded,
                            len(apart), float(normals(apart).max()) if len(apart) else 0.0, len(rounded_weights), float(single))
