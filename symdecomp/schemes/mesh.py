"""Local meshes around a vertex, quad and triangle: topology, ring meshes and their labels.

A :class:`QuadMesh` or :class:`TriangleMesh` is a consistently oriented mesh (possibly with
boundary) with values at its vertices; both share incidence, interior and boundary questions
and sub-meshes. :func:`ring_mesh` and :func:`triangle_ring_mesh` build ``rings`` rings around a
vertex of valence ``n`` (every other vertex regular), labelled ``(s, u, v)`` as the lattice
(:mod:`symdecomp.schemes.lattice`) names its points. Refining a mesh by a scheme's rules is
:mod:`symdecomp.schemes.refinement`.

Values at vertices are tuples of coordinates (any length; scalar fields are 1-tuples) of
``fractions.Fraction``, sympy expressions or floats.

>>> m = ring_mesh(3, 2)
>>> len(m.faces), m.one_ring(0), m.neighbourhood(0, 1).is_disk()
(12, (0, (1, 3, 5), (2, 4, 6)), True)
>>> triangle_ring_mesh(5, 2).one_ring(0)
(0, (1, 2, 3, 4, 5))
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType

from symdecomp.errors import InvalidMeshError
from symdecomp.validate import check_int, check_memory, check_valence

__all__ = [
    "InvalidMeshError", "QuadMesh", "TriangleMesh", "ring_mesh", "ring_mesh_labels", "cube_mesh",
    "triangle_ring_mesh", "triangle_ring_labels",
]




def _sequence(value, what: str) -> tuple:
    if isinstance(value, (str, bytes, Mapping)) or not isinstance(value, Iterable):
        raise InvalidMeshError(f"{what} must be a sequence of vertex ids or faces, got {value!r:.60} ({type(value).__name__})")
    return tuple(value)


def _face(face, corners: int, shape: str) -> tuple[int, ...]:
    """A face as a tuple of ``int`` vertex ids; a label that is not an integer (``3.5``, ``"a"``) is refused, never truncated."""
    f = _sequence(face, "a face")
    try:
        f = tuple(check_int(v, "a vertex id", error=InvalidMeshError) for v in f)
    except InvalidMeshError as exc:
        raise InvalidMeshError(f"face {face!r:.60}: {exc}") from None
    if len(f) != corners or len(set(f)) != corners:
        raise InvalidMeshError(f"face {f} is not {shape}")
    return f


def _set_topology(mesh, corners: int, shape: str) -> None:
    """Validate ``mesh.faces`` (``corners``-gons, consistently oriented, every corner valued) and set
    ``faces``, ``values``, ``_directed`` (directed edge -> face) and ``_incident`` (vertex -> faces)."""
    faces = tuple(_face(f, corners, shape) for f in _sequence(mesh.faces, "faces"))
    if not isinstance(mesh.values, Mapping):
        raise InvalidMeshError(f"values must be a mapping {{vertex id: coordinates}}, got {type(mesh.values).__name__}")
    object.__setattr__(mesh, "faces", faces)
    object.__setattr__(mesh, "values", MappingProxyType(dict(mesh.values)))
    missing = {v for f in faces for v in f} - set(mesh.values)
    if missing:
        raise InvalidMeshError(f"vertices {sorted(missing)[:5]} have no value")
    directed: dict[tuple[int, int], int] = {}
    incident: dict[int, list[int]] = {}
    for fi, f in enumerate(faces):
        for k in range(corners):
            e = (f[k], f[(k + 1) % corners])
            if e in directed:
                raise InvalidMeshError(f"edge {e} is used twice in the same direction: the faces are not consistently oriented")
            directed[e] = fi
            incident.setdefault(f[k], []).append(fi)
    object.__setattr__(mesh, "_directed", directed)
    object.__setattr__(mesh, "_incident", {v: tuple(fs) for v, fs in incident.items()})
    # a vertex is interior when every edge at it has its twin: the ends of the twinless edges are the others (asked
    # tens of thousands of times by refinement and support classification, so found once per mesh)
    object.__setattr__(mesh, "_border", frozenset(x for (u, w) in directed if (w, u) not in directed for x in (u, w)))


class _Mesh:
    """What quad and triangle meshes share: incidence, interior and boundary, sub-meshes (any face size)."""

    def vertices(self) -> tuple[int, ...]:
        """The vertex ids that are corners of faces, sorted."""
        return tuple(sorted(self._incident))

    def faces_of(self, v: int) -> tuple[int, ...]:
        """Indices of the faces incident to ``v``."""
        self._check_vertex(v)
        return self._incident[v]

    def _check_vertex(self, v):
        if v not in self._incident:
            raise InvalidMeshError(f"vertex {v!r} is not a corner of any face of the mesh")

    def is_interior(self, v: int) -> bool:
        """Whether ``v`` is surrounded by a closed fan of faces (each of its edges has two faces)."""
        self._check_vertex(v)
        return v not in self._border

    def _fan(self, v: int, start: int | None) -> tuple[tuple[int, tuple[int, ...]], ...]:
        """``((a_i, rest_i), ...)``: the edge neighbours of an interior vertex counter-clockwise from ``start``
        (default: the smallest id), each with the corners of the face ``(v, a_i, .., a_{i+1})`` between them."""
        if not self.is_interior(v):
            raise InvalidMeshError(f"vertex {v} is on the boundary of the mesh: its 1-ring is not closed")
        nxt = {}
        for fi in self._incident[v]:
            f = self.faces[fi]
            k, c = f.index(v), len(f)
            nxt[f[(k + 1) % c]] = tuple(f[(k + i) % c] for i in range(2, c))  # ..., a_{i+1}
        start = min(nxt) if start is None else start
        if start not in nxt:
            raise InvalidMeshError(f"vertex {start} is not an edge neighbour of {v}")
        fan = [start]
        while nxt[fan[-1]][-1] != start:
            fan.append(nxt[fan[-1]][-1])
            if len(fan) > len(nxt):  # pragma: no cover - guarded by the orientation check
                raise InvalidMeshError(f"the faces around {v} do not form one fan")
        if len(fan) != len(nxt):
            raise InvalidMeshError(f"the faces around {v} form more than one fan (non-manifold vertex)")
        return tuple((a, nxt[a][:-1]) for a in fan)

    def valence(self, v: int) -> int:
        """Number of faces at ``v`` (its valence when it is interior)."""
        return len(self.faces_of(v))

    def neighbourhood(self, v: int, rings: int):
        """The sub-mesh of faces within ``rings`` face-rings of ``v`` (1: the faces at ``v``)."""
        if isinstance(rings, bool) or not isinstance(rings, numbers.Integral) or rings < 1:
            raise InvalidMeshError(f"rings must be a positive integer, got {rings!r}")
        self._check_vertex(v)
        chosen = set(self._incident[v])
        for _ in range(rings - 1):
            corners = {x for fi in chosen for x in self.faces[fi]}
            chosen |= {fi for x in corners for fi in self._incident[x]}
        faces = tuple(self.faces[fi] for fi in sorted(chosen))
        used = {x for f in faces for x in f}
        return type(self)(faces, {x: self.values[x] for x in used})

    def boundary_vertices(self) -> frozenset:
        """The vertices on boundary edges (edges with one face)."""
        d = self._directed
        return frozenset(x for (u, v) in d if (v, u) not in d for x in (u, v))

    def is_disk(self) -> bool:
        """Whether the mesh is a topological disk: Euler characteristic 1 and a boundary.

        (``V - E + F = 1`` with a nonempty boundary; enough for the neighbourhoods this package
        builds, which are connected and manifold by construction.)
        """
        edges = len({frozenset(e) for e in self._directed})
        return len(self._incident) - edges + len(self.faces) == 1 and bool(self.boundary_vertices())

    def with_values(self, values: Mapping[int, tuple]):
        """The same faces with other values."""
        return type(self)(self.faces, values)


@dataclass(frozen=True)
class QuadMesh(_Mesh):
    """A consistently oriented quad mesh (possibly with boundary) with values at its vertices."""

    #: The faces, each a 4-tuple of vertex ids in counter-clockwise order.
    faces: tuple[tuple[int, int, int, int], ...]
    #: Vertex id -> value (a tuple of coordinates).
    values: Mapping[int, tuple]

    def __post_init__(self):
        _set_topology(self, 4, "a quad with four distinct vertices")

    def one_ring(self, v: int, start: int | None = None) -> tuple[int, tuple[int, ...], tuple[int, ...]]:
        """``(v, (a_0..a_{m-1}), (b_0..b_{m-1}))``: the ordered 1-ring of an interior vertex.

        ``a_i`` are the edge neighbours counter-clockwise starting at ``start`` (default: the
        smallest id), ``b_i`` the vertex of the face ``(v, a_i, b_i, a_{i+1})`` opposite ``v``.
        """
        fan = self._fan(v, start)
        return v, tuple(a for a, _ in fan), tuple(rest[0] for _, rest in fan)

    def one_ring_values(self, v: int, start: int | None = None) -> tuple:
        """Values at ``(v, a_0..a_{m-1}, b_0..b_{m-1})``: the order of the subdivision matrix."""
        o, a, b = self.one_ring(v, start)
        return tuple(self.values[x] for x in (o,) + a + b)


@dataclass(frozen=True)
class TriangleMesh(_Mesh):
    """A consistently oriented triangle mesh (possibly with boundary) with values at its vertices."""

    #: The faces, each a 3-tuple of vertex ids in counter-clockwise order.
    faces: tuple[tuple[int, int, int], ...]
    #: Vertex id -> value (a tuple of coordinates).
    values: Mapping[int, tuple]

    def __post_init__(self):
        _set_topology(self, 3, "a triangle with three distinct vertices")

    def one_ring(self, v: int, start: int | None = None) -> tuple[int, tuple[int, ...]]:
        """``(v, (a_0..a_{m-1}))``: the neighbours of an interior vertex, counter-clockwise from ``start``."""
        return v, tuple(a for a, _ in self._fan(v, start))


def _as_value(raw) -> tuple:
    """A vertex value as a tuple (a scalar is a 1-tuple)."""
    return tuple(raw) if isinstance(raw, (tuple, list)) else (raw,)


def _ring_chart(n: int, rings: int, ring_labels: Callable):
    """``(n, labels, vid)`` of a ring mesh: the checked valence, the labels in id order, and the id of
    the vertex ``(s, u, v)`` named from any sector (``s`` mod ``n``; ``(s, 0, v) = (s + 1, v, 0)``)."""
    n = check_valence(n)
    if isinstance(rings, bool) or not isinstance(rings, numbers.Integral) or rings < 1:
        raise InvalidMeshError(f"rings must be a positive integer, got {rings!r}")
    check_memory(n * int(rings) ** 2 * 512, f"a mesh of {rings} rings around a vertex of valence {n}")
    labels = ring_labels(n, rings)
    ident = {lab: i for i, lab in enumerate(labels)}

    def vid(s, u, v):
        if u == 0 and v == 0:
            return 0
        return ident[((s + 1) % n, v, 0)] if u == 0 else ident[(s % n, u, v)]

    return n, labels, vid


def _ring_values(labels, values) -> dict:
    """Vertex id -> value of a ring mesh: ``values(s, u, v)``, or the label itself."""
    return {i: _as_value(values(s, u, v) if values is not None else (s, u, v)) for i, (s, u, v) in enumerate(labels)}


def ring_mesh(n: int, rings: int, values: Callable[[int, int, int], Sequence] | None = None) -> QuadMesh:
    """The quad mesh of ``rings`` rings around a vertex of valence ``n`` (all others regular).

    It is made of ``n`` sectors, each a ``rings x rings`` grid. A vertex is labelled by
    ``(s, u, v)``: sector ``s``, ``u`` steps along the edge ray ``s``, ``v`` steps along ray
    ``s + 1``; ``(s, u, 0)`` is on ray ``s``, ``(s, 0, v) = (s + 1, v, 0)``. The central vertex has
    id 0, ``a_i = (i, 1, 0)`` and ``b_i = (i, 1, 1)``; :func:`ring_mesh_labels` gives the ids.
    ``values(s, u, v)`` gives each vertex's value (default: ``(s, u, v)`` itself as exact integers,
    which is enough for topology questions).

    >>> m = ring_mesh(3, 2)
    >>> len(m.faces), len(m.vertices()), m.one_ring(0)
    (12, 19, (0, (1, 3, 5), (2, 4, 6)))
    """
    n, labels, vid = _ring_chart(n, rings, ring_mesh_labels)
    faces = []
    for s in range(n):
        for u in range(rings):
            for v in range(rings):
                faces.append((vid(s, u, v), vid(s, u + 1, v), vid(s, u + 1, v + 1), vid(s, u, v + 1)))
    vals = _ring_values(labels, values)
    return QuadMesh(tuple(faces), vals)


def cube_mesh(values: Callable[[int], Sequence] | None = None) -> QuadMesh:
    """The cube as a closed quad mesh: 8 vertices of valence 3 (ids ``x + 2y + 4z``), 6 faces.

    ``values(i)`` gives vertex ``i``'s value (default: its corner ``(x, y, z)``).

    >>> m = cube_mesh()
    >>> len(m.faces), m.one_ring(0), m.boundary_vertices()
    (6, (0, (1, 4, 2), (5, 6, 3)), frozenset())
    """
    faces = ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5))
    vals = {}
    for i in range(8):
        raw = values(i) if values is not None else (i & 1, (i >> 1) & 1, (i >> 2) & 1)
        vals[i] = _as_value(raw)
    return QuadMesh(faces, vals)


def ring_mesh_labels(n: int, rings: int) -> tuple[tuple[int, int, int], ...]:
    """``(s, u, v)`` of every vertex of :func:`ring_mesh` in id order (id 0 is ``(0, 0, 0)``).

    Ids run ring by ring (ring ``r``: the ``2rn`` vertices with ``max(u, v) = r``, sector by
    sector), so the closed ``r``-ring of the centre is the first ``1 + n r (r + 1)`` ids.
    """
    n = check_valence(n)
    out = [(0, 0, 0)]
    for r in range(1, rings + 1):
        for s in range(n):
            for u in range(1, r + 1):
                for v in range(0, r + 1):
                    if max(u, v) == r:
                        out.append((s, u, v))
    return tuple(out)


def triangle_ring_labels(n: int, rings: int) -> tuple[tuple[int, int, int], ...]:
    """``(s, u, v)`` of every vertex of :func:`triangle_ring_mesh` in id order (id 0 is the centre).

    Sector ``s`` is the wedge between the edge rays ``s`` and ``s + 1``; ``(s, u, v)`` is ``u``
    steps along ray ``s`` and ``v`` along ray ``s + 1`` (``u >= 1``; ``(s, 0, v) = (s + 1, v, 0)``),
    at ring distance ``u + v``. Ids run ring by ring (``r n`` vertices in ring ``r``), sector by
    sector, so the closed ``r``-ring is the first ``1 + n r (r + 1)/2`` ids.
    """
    n = check_valence(n)
    out = [(0, 0, 0)]
    for r in range(1, rings + 1):
        out += [(s, r - v, v) for s in range(n) for v in range(r)]
    return tuple(out)


def triangle_ring_mesh(n: int, rings: int, values: Callable[[int, int, int], Sequence] | None = None) -> TriangleMesh:
    """The triangle mesh of ``rings`` rings around a vertex of valence ``n`` (all others valence 6).

    ``n`` sectors, each a triangular grid of ``rings^2`` triangles; labels as in
    :func:`triangle_ring_labels`, ``a_i = (i, 1, 0)``. ``values(s, u, v)`` gives each vertex's
    value (default: the label itself).

    >>> m = triangle_ring_mesh(5, 2)
    >>> len(m.faces), len(m.vertices()), m.one_ring(0)
    (20, 16, (0, (1, 2, 3, 4, 5)))
    """
    n, labels, vid = _ring_chart(n, rings, triangle_ring_labels)
    faces = []
    for s in range(n):
        for u in range(rings):
            for v in range(rings - u):
                faces.append((vid(s, u, v), vid(s, u + 1, v), vid(s, u, v + 1)))
                if u + v <= rings - 2:
                    faces.append((vid(s, u + 1, v), vid(s, u + 1, v + 1), vid(s, u, v + 1)))
    vals = _ring_values(labels, values)
    return TriangleMesh(tuple(faces), vals)
