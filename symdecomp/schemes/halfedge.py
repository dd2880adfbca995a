"""A small halfedge structure for the local meshes of the zoo's engine.

Faces are tuples of vertex ids in counter-clockwise order, of any size. Every directed edge of a
face is a halfedge with that face; an edge with one face also gets a *boundary* halfedge in the
other direction, which has no face (``face`` is ``None``, ``next``/``prev`` are ``-1``). A walk
(:mod:`symdecomp.schemes.stencils`) that needs the face of a boundary halfedge leaves the mesh:
:meth:`HalfedgeMesh.move` returns ``None`` then, and the point it names is not in the mesh.

>>> m = halfedge_mesh(((0, 1, 2, 3), (0, 3, 4, 5)))
>>> h = m.halfedge(0, 1)
>>> m.origin[m.next[h]], m.face_size(m.face[h]), m.valence(0), m.is_interior(0)
(1, 4, None, False)
>>> m.origin[m.twin[m.halfedge(0, 3)]]
3
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from symdecomp.errors import InvalidMeshError

__all__ = ["HalfedgeMesh", "halfedge_mesh"]


@dataclass(frozen=True)
class HalfedgeMesh:
    """Halfedges of a consistently oriented polygon mesh (possibly with boundary)."""

    #: The faces, each a tuple of vertex ids, counter-clockwise.
    faces: tuple[tuple[int, ...], ...]
    #: The vertex each halfedge leaves.
    origin: tuple[int, ...]
    #: The face of each halfedge (``None`` on the boundary).
    face: tuple[int | None, ...]
    #: The next halfedge of the same face (``-1`` on the boundary).
    next: tuple[int, ...]
    #: The previous halfedge of the same face (``-1`` on the boundary).
    prev: tuple[int, ...]
    #: The opposite halfedge.
    twin: tuple[int, ...]
    #: The halfedge of each directed edge ``(origin, tip)``.
    by_edge: dict[tuple[int, int], int]
    #: The halfedges of each face, from its first corner.
    face_halfedges: tuple[tuple[int, ...], ...]
    #: The smallest outgoing halfedge of each vertex.
    first_out: dict[int, int]

    def halfedge(self, a: int, b: int) -> int:
        """The halfedge from ``a`` to ``b``."""
        try:
            return int(self.by_edge[(a, b)])
        except KeyError:
            raise InvalidMeshError(f"the mesh has no edge from {a} to {b}") from None

    def tip(self, h: int) -> int:
        """The vertex ``h`` points to."""
        return self.origin[self.twin[h]]

    def move(self, h: int | None, move: str) -> int | None:
        """One move of a walk (``next``, ``prev``, ``twin``); ``None`` when it leaves the mesh."""
        if h is None:
            return None
        if move == "twin":
            return self.twin[h]
        if self.face[h] is None:
            return None
        return self.next[h] if move == "next" else self.prev[h]

    def walk(self, h: int | None, moves: Iterable[str]) -> int | None:
        """The halfedge a walk from ``h`` ends on (``None`` if it leaves the mesh)."""
        for m in moves:
            h = self.move(h, m)
        return h

    def vertices(self) -> tuple[int, ...]:
        """The vertex ids, sorted."""
        return tuple(sorted(set(self.origin)))

    def outgoing(self, v: int) -> tuple[int, ...] | None:
        """The outgoing halfedges of an interior vertex ``v``, counter-clockwise from its smallest one; ``None`` on the boundary."""
        if v not in self.first_out:
            raise InvalidMeshError(f"vertex {v!r} is not in the mesh")
        return self.ring(self.first_out[v])

    def ring(self, h: int) -> tuple[int, ...] | None:
        """The outgoing halfedges of ``h``'s origin counter-clockwise from ``h`` (``h_(j+1) = twin(prev(h_j))``); ``None`` on the boundary."""
        out = [h]
        while True:
            p = self.move(out[-1], "prev")
            if p is None:
                return None
            nxt = self.twin[p]
            if nxt == h:
                return tuple(out)
            out.append(nxt)

    def is_interior(self, v: int) -> bool:
        """Whether ``v`` is surrounded by a closed fan of faces."""
        return self.outgoing(v) is not None

    def valence(self, v: int) -> int | None:
        """The number of edges at an interior vertex (``None`` on the boundary: the mesh does not show it)."""
        ring = self.outgoing(v)
        return None if ring is None else len(ring)

    def face_size(self, f: int) -> int:
        """The number of sides of face ``f``."""
        return len(self.faces[f])

    def around_face(self, h: int) -> tuple[int, ...]:
        """The halfedges of ``h``'s face from ``h`` on (``h_j = next^j(h)``)."""
        f = self.face[h]
        if f is None:
            raise InvalidMeshError("a boundary halfedge has no face")
        hs = self.face_halfedges[f]
        i = hs.index(h)
        return hs[i:] + hs[:i]


def halfedge_mesh(faces: Iterable[Iterable[int]]) -> HalfedgeMesh:
    """The halfedges of ``faces`` (vertex-id tuples, counter-clockwise, consistently oriented)."""
    polygons: tuple[tuple[int, ...], ...] = tuple(tuple(int(v) for v in f) for f in faces)
    origin: list[int] = []
    face: list[int | None] = []
    nxt: list[int] = []
    prv: list[int] = []
    by_edge: dict[tuple[int, int], int] = {}
    per_face = []
    for fi, f in enumerate(polygons):
        if len(f) < 3 or len(set(f)) != len(f):
            raise InvalidMeshError(f"face {f} needs at least three distinct vertices")
        base = len(origin)
        m = len(f)
        for k in range(m):
            e = (f[k], f[(k + 1) % m])
            if e in by_edge:
                raise InvalidMeshError(f"edge {e} is used twice in the same direction: the faces are not consistently oriented")
            by_edge[e] = base + k
            origin.append(f[k])
            face.append(fi)
            nxt.append(base + (k + 1) % m)
            prv.append(base + (k - 1) % m)
        per_face.append(tuple(range(base, base + m)))
    for (a, b) in list(by_edge):
        if (b, a) not in by_edge:
            by_edge[(b, a)] = len(origin)
            origin.append(b)
            face.append(None)
            nxt.append(-1)
            prv.append(-1)
    twin = [0] * len(origin)
    for (a, b), h in by_edge.items():
        twin[h] = by_edge[(b, a)]
    first: dict[int, int] = {}
    for h, v in enumerate(origin):
        first.setdefault(v, h)
    return HalfedgeMesh(polygons, tuple(origin), tuple(face), tuple(nxt), tuple(prv), tuple(twin), by_edge, tuple(per_face), first)
