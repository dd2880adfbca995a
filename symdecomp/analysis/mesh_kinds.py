"""Every vertex of a modeller's mesh classified by its neighbourhood kind, as OpenSubdiv tags it.

A vertex's *kind* decides its limit masks: an interior vertex without sharp edges is ``smooth`` with its
valence ``n``; a vertex on the boundary or on sharp edges is a
:class:`~symdecomp.schemes.sector.SharpVertex`: its fan of faces (open on a boundary, closed inside) split
by the sharp edges into sectors of ``k_1, k_2, ..`` faces, tagged as a corner or not, with the sharpness of
its sharp edges that are not boundary edges. OpenSubdiv's rule (``Sdc::Crease``) counts the sharp edges at
the vertex, boundary edges counted as infinitely sharp under ``edge-only`` and ``edge-and-corner``
interpolation: none is smooth, one a dart, two a crease (a boundary vertex with no inner sharp edge is
one), more or a sharp vertex a corner; under ``edge-and-corner`` a boundary vertex of one face is a corner.

:func:`classify_vertices` returns one :class:`VertexKinds`: the distinct kinds, and per kind the vertices
of that kind with their ordered 1-rings in the masks' order (``O, a_0.., b_0..``; ``a_0`` on the first sharp
edge, faces ``(O, a_i, b_i, a_{i+1})`` counter-clockwise), gathered into one integer array per kind, so that a
kind's masks apply to all its vertices with one matrix product. A vertex of no kind gets its computed
:class:`~symdecomp.analysis.mesh_outcomes.Outcome` (:attr:`VertexKinds.outcomes`): off the limit surface (every face
of it a hole, tagged or under ``none`` interpolation; in no face), transient (a semi-sharp vertex tag, sharp edges of
different sharpness: the kind it becomes once they have decayed), or a fan judged by its spectrum (valence 2; one face
under ``edge-only``). A corner of a hole keeps its kind (holes change no rule). What is left (more faces around a
vertex than the bounds) is listed with the reason.

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> grid = PolygonMesh.from_arrays([(x, y, 0) for y in range(3) for x in range(3)],
...     [(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)])
>>> from symdecomp.schemes.lattice import QUAD
>>> kinds = classify_vertices(grid, QUAD)
>>> sorted(str(k) for k in kinds.rings)
['boundary k = 1, corner', 'boundary k = 2', 'smooth n = 4']
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np

from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.sector import MAX_SECTOR_FACES, SharpVertex
from symdecomp.schemes.sharp import SHARPNESS_INFINITE
from symdecomp.validate import MAX_MESH_VALENCE

__all__ = ["NeighbourhoodKind", "VertexKinds", "classify_vertices", "decayed_outcome", "MAX_SMOOTH_VALENCE"]

#: Most faces around a smooth interior vertex analysed (the exact masks are solved per valence).
MAX_SMOOTH_VALENCE = MAX_MESH_VALENCE  # the one bound of every command that reads meshes (validate)


@dataclass(frozen=True, order=True)
class NeighbourhoodKind:
    """One kind of vertex neighbourhood: ``smooth`` valence ``n``, or a sharp vertex (:attr:`sharp`)."""

    #: ``"smooth"``, ``"boundary"``, ``"dart"``, ``"crease"`` or ``"corner"`` (OpenSubdiv's words; a sharp
    #: interior vertex with three or more sharp edges is a ``"corner"``).
    name: str
    #: Faces around the vertex (its valence when interior).
    faces: int
    #: Faces of each sector between sharp edges (``(n,)`` when smooth).
    sectors: tuple[int, ...]
    #: Whether the fan of faces is closed (an interior vertex).
    closed: bool
    #: Tagged or made a corner (interpolated).
    corner: bool = False
    #: Sharpness of the inner sharp edges (``inf`` when infinitely sharp or none).
    sharpness: float | Fraction = math.inf

    def __str__(self) -> str:
        if self.name == "smooth":
            return f"smooth n = {self.faces}"
        where = "boundary" if not self.closed else self.name
        sectors = ",".join(map(str, self.sectors))
        extra = (", corner" if self.corner and where != "corner" else "") + (
            "" if math.isinf(self.sharpness) or (not self.closed and len(self.sectors) == 1) else f", sharpness {self.sharpness}")
        return f"{where} k = {sectors}{extra}"

    def sharp_vertex(self, lattice) -> SharpVertex:
        """The :class:`~symdecomp.schemes.sector.SharpVertex` of this kind (not for ``smooth``)."""
        return SharpVertex(lattice, self.sectors, self.closed, self.corner, self.sharpness)

    def is_regular(self, lattice) -> bool:
        """A regular vertex of the lattice: smooth at the regular valence (the analysis covers it too)."""
        return self.name == "smooth" and self.faces == lattice.regular_valence


@dataclass(frozen=True)
class VertexKinds:
    """The kinds of a mesh's vertices (see the module docstring)."""

    #: Kind -> ``(vertices, rings)``: the vertex indices (int array) and their 1-rings (one row each, masks' order).
    rings: dict
    #: Vertex -> why its kind is not analysed.
    not_analysed: dict
    #: Per vertex, the index of its kind in :attr:`kinds` (-1: not of a kind).
    kind_of: np.ndarray
    #: Vertex -> its computed :class:`~symdecomp.analysis.mesh_outcomes.Outcome` where it is of no kind here (off the
    #: surface; transient tags: the kind it becomes; a fan judged by its spectrum).
    outcomes: dict = field(default_factory=dict)

    @property
    def kinds(self) -> tuple[NeighbourhoodKind, ...]:
        """The distinct kinds, sorted."""
        return tuple(sorted(self.rings))


def _fan(mesh: PolygonMesh, v: int) -> tuple[list[int], bool]:
    """The edge neighbours of ``v`` counter-clockwise (``a_0`` first: where an open fan starts) and whether it closes."""
    step = mesh._topology["next"][v]
    boundary = bool(mesh._topo.boundary[v])
    if boundary:
        targets = set(step.values())
        a = next(x for x in step if x not in targets)
    else:
        a = min(step)
    out = [a]
    while True:
        a = step[a]
        if a is None or a == out[0]:
            return out, not boundary
        out.append(a)


def _edge_sharpness(mesh: PolygonMesh, v: int, fan: list[int], closed: bool) -> list:
    """Per edge ``(v, a_i)``: its sharpness, a boundary edge infinite (OpenSubdiv's boundary interpolation)."""
    tags = mesh.tags
    out = []
    for i, a in enumerate(fan):
        s = tags.sharpness_of_edge(v, a)
        if not closed and i in (0, len(fan) - 1):
            s = math.inf
        elif s >= SHARPNESS_INFINITE:
            s = math.inf
        out.append(s)
    return out


#: ``_kind_of``'s answer for a vertex whose tags decay (a semi-sharp vertex tag, sharp edges of different sharpness).
_TRANSIENT = "transient"
#: ``_kind_of``'s answer for a fan the sector model does not take (judged by its spectrum).
_SPECTRUM = "spectrum"


def _kind(mesh: PolygonMesh, v: int, fan: list[int], closed: bool):
    """The kind of ``v`` and the rotation that puts ``a_0`` on its first sharp edge; or why it is not analysed (a
    string); or its computed :class:`~symdecomp.analysis.mesh_outcomes.Outcome` (transient tags, a fan judged by its
    spectrum)."""
    from symdecomp.analysis.mesh_outcomes import decay, fan_outcome

    faces = len(fan) if closed else len(fan) - 1
    sharp = _edge_sharpness(mesh, v, fan, closed)
    vertex_sharpness = mesh.tags.corners.get(v, Fraction(0))
    kind = _kind_of(mesh.tags.interpolate_boundary, faces, sharp, vertex_sharpness, closed)
    if kind == _TRANSIENT:
        outcome = decayed_outcome(mesh, v)
        if not isinstance(outcome, str):
            return outcome
        levels, sharp, vertex_sharpness = decay(sharp, vertex_sharpness, mesh.tags.crease_method)
        kind = _kind_of(mesh.tags.interpolate_boundary, faces, sharp, vertex_sharpness, closed)
    if kind == _SPECTRUM:  # the fan it keeps once its semi-sharp tags have decayed (the asymptotic one)
        _, sharp, vertex_sharpness = decay(sharp, vertex_sharpness, mesh.tags.crease_method)
        return fan_outcome(faces, closed, sharp, vertex_sharpness, mesh.tags.interpolate_boundary)
    if isinstance(kind, tuple) and _chaikin_far_ends(mesh, fan, sharp):
        outcome = decayed_outcome(mesh, v)
        return outcome if not isinstance(outcome, str) else kind
    return kind


def _chaikin_far_ends(mesh: PolygonMesh, fan: list[int], sharp: list) -> bool:
    """Under Chaikin's creasing, whether a semi-sharp edge at the vertex has semi-sharp edges of another sharpness at its
    far end: its far half then decays otherwise than the kind's one-step matrices assume (they decay both halves alike),
    so the vertex takes the transient route (its 2-ring refined exactly)."""
    if mesh.tags.crease_method != "chaikin":
        return False
    for a, s in zip(fan, sharp):
        if 0 < s < SHARPNESS_INFINITE:
            far, _ = _fan(mesh, a)
            if {t for b in far if 0 < (t := mesh.tags.sharpness_of_edge(a, b)) < SHARPNESS_INFINITE} != {s}:
                return True
    return False


def decayed_outcome(mesh: PolygonMesh, v: int):
    """``v`` as a transient vertex (:func:`~symdecomp.analysis.mesh_outcomes.transient`) whatever its tags: the kind it
    is once its semi-sharp tags have decayed, and after how many levels; or why there is none."""
    from symdecomp.analysis.mesh_outcomes import decay, transient, transition_weights

    fan, closed = _fan(mesh, v)
    faces = len(fan) if closed else len(fan) - 1
    sharp = _edge_sharpness(mesh, v, fan, closed)
    vertex_sharpness = mesh.tags.corners.get(v, Fraction(0))
    weights = transition_weights(sharp, vertex_sharpness, mesh.tags.crease_method)
    levels, sharp, vertex_sharpness = decay(sharp, vertex_sharpness, mesh.tags.crease_method)
    eventual = _kind_of(mesh.tags.interpolate_boundary, faces, sharp, vertex_sharpness, closed)
    if not isinstance(eventual, tuple):
        return f"once its tags have decayed: {eventual}"
    return transient(eventual[0], levels, _cause(mesh, v, fan, closed), weights)


def _cause(mesh: PolygonMesh, v: int, fan: list[int], closed: bool) -> str:
    """What makes ``v`` transient, in words."""
    sharp = _edge_sharpness(mesh, v, fan, closed)
    inner = sorted({s for i, s in enumerate(sharp) if s > 0 and (closed or 0 < i < len(fan) - 1)})
    vertex = mesh.tags.corners.get(v, Fraction(0))
    parts = ([f"a semi-sharp vertex tag ({vertex})"] if 0 < vertex < SHARPNESS_INFINITE else []) + (
        [f"sharp edges of different sharpness ({', '.join(str(s) for s in inner)}) meet there"] if len(inner) > 1 else [])
    return " and ".join(parts) or f"semi-sharp tags ({', '.join(str(s) for s in inner)})"


def _kind_of(boundary: str, faces: int, sharp: list, vertex_sharpness, closed: bool):
    """The kind from the sharpness of the fan's edges (boundary edges infinite) and of the vertex (:func:`_kind`)."""
    marks = [i for i, s in enumerate(sharp) if s > 0]
    inner = {s for i, s in enumerate(sharp) if s > 0 and (closed or 0 < i < len(sharp) - 1)}
    if len(inner) > 1 or 0 < vertex_sharpness < SHARPNESS_INFINITE:
        return _TRANSIENT
    corner = vertex_sharpness >= SHARPNESS_INFINITE
    if not marks and not corner:
        return _smooth(faces)
    if closed and faces < 3:
        return _SPECTRUM
    if faces > MAX_SECTOR_FACES:
        return f"{faces} faces around a sharp vertex, more than {MAX_SECTOR_FACES}"
    if not closed and faces == 1 and boundary != "edge-and-corner" and not corner:
        return _SPECTRUM  # OpenSubdiv's crease rule on one face (the sector model makes a one-face sector a corner)
    sharpness = next(iter(inner)) if inner else math.inf
    if closed and not marks:  # a corner tag alone: the vertex is interpolated, its edges stay smooth
        return NeighbourhoodKind("corner", faces, (faces,), True, True, Fraction(0)), 0
    if closed:
        count = len(marks)
        sector = [((marks[(j + 1) % count] - marks[j]) % faces) or faces for j in range(count)]
        rotations = [(tuple(sector[(i + t) % count] for t in range(count)), marks[i]) for i in range(count)]
        sectors, start = min(rotations)
    else:
        sectors, start = tuple(b - a for a, b in zip(marks, marks[1:])), 0
    count = len(marks)
    name = "corner" if corner or count > 2 else ("dart", "crease")[count - 1] if closed else "boundary"
    return NeighbourhoodKind(name, faces, sectors, closed, corner or (not closed and faces == 1 and
                             boundary == "edge-and-corner"), sharpness), start


def _smooth(faces: int):
    """An untagged interior vertex: smooth (the common case, decided without looking at sharpness)."""
    if faces > MAX_SMOOTH_VALENCE:
        return f"valence {faces} is more than {MAX_SMOOTH_VALENCE}"
    if faces < 3:
        return _SPECTRUM
    return NeighbourhoodKind("smooth", faces, (faces,), True), 0


def _opposite_at(mesh: PolygonMesh, v: int) -> dict:
    """``a -> b`` for every quad ``(v, a, b, a')`` at ``v``: the face neighbour after each edge neighbour."""
    t = mesh._topo
    at = t.by_vertex[t.vertex_start[v]:t.vertex_start[v + 1]]
    return dict(zip(t.corners[t.next[at]].tolist(), t.corners[t.next[t.next[at]]].tolist()))


def _ring(v: int, fan: list[int], closed: bool, opposite: dict | None) -> list[int]:
    """``O, a_0.., b_0..`` with ``b_i`` the corner opposite ``O`` in the face ``(O, a_i, b_i, a_{i+1})``."""
    if opposite is None:
        return [v] + fan
    return [v] + fan + [opposite[a] for a in (fan if closed else fan[:-1])]


def _smooth_at_once(mesh: PolygonMesh, candidates: np.ndarray, quads: bool) -> tuple[dict, np.ndarray]:
    """The untagged interior vertices (``candidates``) of 3 to :data:`MAX_SMOOTH_VALENCE` faces, valence by valence
    with numpy (:func:`~symdecomp.schemes.mesh_topology.closed_fans`): ``({kind: (ids, rings)}, the rest)``, the
    rest (not one closed fan) for the vertex-by-vertex route."""
    from symdecomp.schemes.mesh_topology import closed_fans

    t = mesh._topo
    gathered, rest = {}, []
    valence = t.faces_at[candidates]
    for n in np.unique(valence[(valence >= 3) & (valence <= MAX_SMOOTH_VALENCE)]).tolist():
        ids = candidates[valence == n]
        fans, closes = closed_fans(t, ids, n)
        rest.append(ids[~closes])
        ids, fans = ids[closes], fans[closes]
        columns = [ids[:, None], t.corners[t.next[fans]]] + ([t.corners[t.next[t.next[fans]]]] if quads else [])
        gathered[_smooth(n)[0]] = (ids, np.hstack(columns))
    rest.append(candidates[(valence < 3) | (valence > MAX_SMOOTH_VALENCE)])
    return gathered, np.sort(np.concatenate(rest))


def classify_vertices(mesh: PolygonMesh, lattice, *, progress=None) -> VertexKinds:
    """Classify every vertex of ``mesh`` (every face of the lattice's kind) and gather the 1-rings per kind.

    The untagged interior vertices (most of a mesh) are classified and gathered with numpy, valence by valence; the
    others (boundary, tagged, next to a hole) one by one; ``progress(iterable, total)``, when given, wraps that loop.
    """
    from symdecomp.analysis.mesh_outcomes import Outcome, off_surface

    mesh.require_lattice(lattice)
    quads = "b" in dict(lattice.one_ring_classes)  # face neighbours b_i in the 1-ring
    t = mesh._topo
    off = _off_surface(mesh)
    tagged = {v for e in mesh.tags.creases for v in e} | set(mesh.tags.corners)  # the rest of the interior is smooth
    simple = (t.faces_at > 0) & ~t.boundary
    simple[np.fromiter(set(off) | tagged, dtype=np.int64)] = False
    fast, rest = _smooth_at_once(mesh, np.flatnonzero(simple), quads)
    gathered: dict[NeighbourhoodKind, tuple[list, list]] = {}
    not_analysed: dict[int, str] = {}
    outcomes: dict[int, Outcome] = {}
    vertices = np.sort(np.concatenate([np.flatnonzero(~simple), rest])).tolist()
    for v in progress(vertices, len(vertices)) if progress is not None else vertices:
        if v in off:
            outcomes[v] = off_surface(off[v])
            continue
        fan, closed = _fan(mesh, v)
        kind = _kind(mesh, v, fan, closed) if v in tagged or not closed else _smooth(len(fan))
        if kind == _SPECTRUM:  # an untagged interior vertex of valence 2
            kind = _kind(mesh, v, fan, closed)
        if isinstance(kind, (str, Outcome)):
            (not_analysed if isinstance(kind, str) else outcomes)[v] = kind
            continue
        kind, start = kind
        if closed and start:
            fan = fan[start:] + fan[:start]
        ids, rings = gathered.setdefault(kind, ([], []))
        ids.append(v)
        rings.append(_ring(v, fan, closed, _opposite_at(mesh, v) if quads else None))
    return _gather(len(mesh.points), fast, gathered, dict(sorted(not_analysed.items())), dict(sorted(outcomes.items())))


def _off_surface(mesh: PolygonMesh) -> dict[int, str]:
    """The vertices with no point on the limit surface, with why: in no face, or every face of theirs a hole (tagged, or
    under ``interpolateboundary none`` a face at a boundary vertex with a boundary edge not infinitely sharp, which
    OpenSubdiv's ``TopologyRefinerFactory`` makes a hole: :mod:`~symdecomp.analysis.mesh_outcomes`)."""
    t = mesh._topo
    faces, count = len(t.offsets) - 1, len(mesh.points)
    face_of = np.repeat(np.arange(faces), np.diff(t.offsets))
    tagged = np.zeros(faces, dtype=bool)
    tagged[np.fromiter(mesh.tags.holes, dtype=np.int64)] = True
    excluded = tagged.copy()
    if mesh.tags.interpolate_boundary == "none":
        rim = np.flatnonzero(t.opposite < 0)  # corners starting a boundary edge
        u, w = t.corners[rim], t.corners[t.next[rim]]
        soft = np.array([mesh.tags.sharpness_of_edge(a, b) < SHARPNESS_INFINITE for a, b in zip(u.tolist(), w.tolist())], dtype=bool)
        bad = np.zeros(count, dtype=bool)
        bad[u[soft]], bad[w[soft]] = True, True
        excluded |= np.bincount(face_of, weights=bad[t.corners], minlength=faces) > 0
    holes_at = np.bincount(t.corners, weights=excluded[face_of], minlength=count)
    tagged_at = np.bincount(t.corners, weights=tagged[face_of], minlength=count)
    out = {int(v): "in no face of the mesh (isolated, or its faces were left out)" for v in np.flatnonzero(t.faces_at == 0)}
    for v in np.flatnonzero((t.faces_at > 0) & (holes_at == t.faces_at)).tolist():
        out[v] = ("every face of it is tagged as a hole" if tagged_at[v] == t.faces_at[v] else "under interpolateboundary "
                  "none its faces are holes (OpenSubdiv makes every face at a boundary vertex whose boundary edges are not "
                  "tagged infinitely sharp a hole)")
    return out


def _gather(count: int, fast: dict, gathered: dict, not_analysed: dict, outcomes: dict) -> VertexKinds:
    """One ``(ids, rings)`` per kind from both routes, in vertex order, and each vertex's kind index."""
    rings = {}
    for kind in set(fast) | set(gathered):
        parts = [fast[kind]] if kind in fast else []
        if kind in gathered:
            ids, rs = gathered[kind]
            parts.append((np.array(ids, dtype=np.int64), np.array(rs, dtype=np.int64)))
        ids = np.concatenate([p[0] for p in parts])
        order = np.argsort(ids, kind="stable")
        rings[kind] = (ids[order], np.concatenate([p[1] for p in parts])[order])
    kind_of = np.full(count, -1, dtype=np.int64)
    for i, k in enumerate(sorted(rings)):
        kind_of[rings[k][0]] = i
    return VertexKinds(rings, not_analysed, kind_of, outcomes)
