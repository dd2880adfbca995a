"""The neighbourhood of an extraordinary element: its explicit local mesh and its orbit labelling.

The centre is a vertex of valence ``n`` (primal schemes) or an ``n``-sided face (dual schemes:
the neighbourhood is the dual of a primal ring mesh, whose centre vertex becomes the centre face).
Around it, the neighbourhood of *depth* ``d`` is the faces within ``d`` rings of the centre
(a ring: the faces that share a vertex with the ones before; the faces at a centre vertex are its
first ring, a centre face is ring 0), every other vertex and face regular. The local meshes are
the lattice's own (:meth:`~symdecomp.schemes.lattice.Lattice.ring_mesh`); what is regular comes
from the lattice (:attr:`~symdecomp.schemes.lattice.Lattice.regular_valence`,
:attr:`~symdecomp.schemes.lattice.Lattice.regular_face_size`).

The neighbourhood knows its symmetry, the rotation by one sector, as an *orbit labelling* of its
points: a fixed centre point (vertex-centred) and classes of ``n`` points each, point ``(s, c)``
being the rotation ``s`` of class ``c``'s representative. The labels are computed from the mesh
alone, by a canonical traversal (breadth first over halfedges, moves ``next`` then ``twin``) from
a start halfedge (an outgoing halfedge of the centre vertex, or a halfedge of the centre face), so
the same function labels a refined mesh from the tracked start halfedge
(:func:`label_points`), and the subdivision matrix is read in one order on both sides.

>>> from symdecomp.schemes.lattice import QUAD
>>> nb = neighbourhood(QUAD, 5, 1)
>>> nb.centre is not None, len(nb.classes), len(nb.order)
(True, 2, 11)
>>> dual = neighbourhood(QUAD, 5, 1, centred="face")
>>> dual.centre is None, len(dual.classes), len(dual.order)
(True, 4, 20)
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from dataclasses import dataclass

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.halfedge import HalfedgeMesh, halfedge_mesh
from symdecomp.schemes.lattice import Lattice
from symdecomp.validate import check_int, check_valence

__all__ = ["CENTRES", "Neighbourhood", "neighbourhood", "label_points", "local_faces", "dual_faces"]

#: The kinds of centre element.
CENTRES = ("vertex", "face")


@dataclass(frozen=True)
class Neighbourhood:
    """The local mesh around an extraordinary element, with the orbit labelling of its points."""

    #: The lattice (:class:`~symdecomp.schemes.lattice.Lattice`) of the scheme.
    lattice: Lattice
    #: The valence of the centre vertex, or the number of sides of the centre face.
    n: int
    #: The ring depth.
    depth: int
    #: ``"vertex"`` or ``"face"``.
    centred: str
    #: The explicit local mesh.
    mesh: HalfedgeMesh
    #: The start halfedge of the canonical traversal.
    start: int
    #: The centre vertex (fixed by the rotation), or ``None`` for a centre face.
    centre: int | None
    #: Each class's representative as the walk (moves) from the start halfedge that reaches it first.
    classes: tuple[tuple[str, ...], ...]
    #: Vertex id -> ``(s, c)``: rotation ``s`` of class ``c``'s representative.
    labels: dict[int, tuple[int, int]]
    #: The vertex ids in matrix order: the centre (if any), then class by class, ``s = 0..n-1``.
    order: tuple[int, ...]

    @property
    def regular_valence(self) -> int:
        """The valence of a regular vertex of this mesh (of the lattice; its dual's: the lattice's face size)."""
        return int(self.lattice.regular_valence if self.centred == "vertex" else self.lattice.regular_face_size)

    def index(self) -> dict[int, int]:
        """Vertex id -> row of the subdivision matrix."""
        return {v: i for i, v in enumerate(self.order)}

    def rotate(self, h: int) -> int:
        """The rotation by one sector, on a halfedge at the centre."""
        return _rotation(self.mesh, self.centred)(h)


def _rotation(mesh: HalfedgeMesh, centred: str) -> Callable[[int], int]:
    if centred == "vertex":
        return lambda h: mesh.twin[mesh.prev[h]]
    return lambda h: mesh.next[h]


def _first_words(mesh: HalfedgeMesh, start: int) -> dict[int, tuple[str, ...]]:
    """Vertex -> the first walk from ``start`` (breadth first, moves ``next`` before ``twin``) that reaches it."""
    words: dict[int, tuple[str, ...]] = {mesh.origin[start]: ()}
    seen = {start}
    queue: deque[tuple[int, tuple[str, ...]]] = deque([(start, ())])
    while queue:
        h, word = queue.popleft()
        for move in ("next", "twin"):
            g = mesh.move(h, move)
            if g is None or g in seen:
                continue
            seen.add(g)
            w = word + (move,)
            words.setdefault(mesh.origin[g], w)
            queue.append((g, w))
    return words


def label_points(mesh: HalfedgeMesh, start: int, n: int, centred: str) -> tuple[
        int | None, tuple[tuple[str, ...], ...], dict[int, tuple[int, int]], tuple[int, ...]]:
    """``(centre, classes, labels, order)``: the orbit labelling of ``mesh`` from ``start`` under the rotation by one sector.

    :class:`InvalidMeshError` if the mesh does not have that symmetry.
    """
    rotate = _rotation(mesh, centred)
    starts = [start]
    for _ in range(n - 1):
        starts.append(rotate(starts[-1]))
    if rotate(starts[-1]) != start:
        raise InvalidMeshError(f"the centre is not of order {n}: the rotation does not return after {n} steps")
    centre = mesh.origin[start] if centred == "vertex" else None
    words = _first_words(mesh, start)
    labels: dict[int, tuple[int, int]] = {}
    classes: list[tuple[str, ...]] = []
    for v, word in words.items():
        if v == centre or v in labels:
            continue
        c = len(classes)
        classes.append(word)
        for s, h in enumerate(starts):
            g = mesh.walk(h, word)
            if g is None or mesh.origin[g] in labels or mesh.origin[g] == centre:
                raise InvalidMeshError(f"the mesh is not symmetric under the rotation (class {c}, sector {s})")
            labels[mesh.origin[g]] = (s, c)
    if len(labels) + (centre is not None) != len(mesh.vertices()):
        raise InvalidMeshError("the canonical traversal does not reach every vertex of the mesh")
    order = ((centre,) if centre is not None else ()) + tuple(sorted(labels, key=lambda v: labels[v][::-1]))
    return centre, tuple(classes), labels, order


def local_faces(mesh: HalfedgeMesh, start: int, depth: int, centred: str) -> tuple[int, ...]:
    """The faces within ``depth`` rings of the centre of ``start`` (sorted face indices)."""
    if centred == "vertex":
        ring = mesh.ring(start)
        if ring is None:
            raise InvalidMeshError("the centre vertex is on the boundary of the mesh")
        chosen = {_face(mesh, h) for h in ring}
        expansions = depth - 1
    else:
        chosen = {_face(mesh, start)}
        expansions = depth
    incident: dict[int, set[int]] = {}
    for fi, f in enumerate(mesh.faces):
        for v in f:
            incident.setdefault(v, set()).add(fi)
    for _ in range(expansions):
        chosen |= {g for fi in list(chosen) for v in mesh.faces[fi] for g in incident[v]}
    return tuple(sorted(chosen))


def _face(mesh: HalfedgeMesh, h: int) -> int:
    """The face of a halfedge that has one."""
    f = mesh.face[h]
    if f is None:
        raise InvalidMeshError("a boundary halfedge has no face")
    return f


def dual_faces(mesh: HalfedgeMesh) -> tuple[tuple[int, ...], ...]:
    """The faces of the dual mesh (one per interior vertex, its faces counter-clockwise); vertex ids are face indices."""
    out = []
    for v in mesh.vertices():
        ring = mesh.outgoing(v)
        if ring is not None:
            out.append(tuple(_face(mesh, h) for h in ring))
    return tuple(out)


def _centre_mesh(lattice: Lattice, n: int, depth: int, centred: str) -> tuple[HalfedgeMesh, int]:
    """The local mesh and the start halfedge (at the centre vertex 0 of the lattice's ring mesh, or its dual face)."""
    if centred == "vertex":
        primal = halfedge_mesh(lattice.ring_mesh(n, depth).faces)
        return primal, primal.first_out[0]
    primal = halfedge_mesh(lattice.ring_mesh(n, depth + 1).faces)
    ring = primal.ring(primal.first_out[0])
    assert ring is not None  # the centre of a ring mesh is interior
    dual = halfedge_mesh(dual_faces(primal))
    return dual, dual.halfedge(_face(primal, ring[0]), _face(primal, ring[1]))


def neighbourhood(lattice: Lattice, n: int, depth: int, *, centred: str = "vertex") -> Neighbourhood:
    """The neighbourhood of depth ``depth`` of a valence-``n`` vertex (or, ``centred="face"``, an ``n``-sided face) on ``lattice``."""
    n = check_valence(n)
    depth = check_int(depth, "depth", minimum=1, error=InvalidMeshError)
    if centred not in CENTRES:
        raise InvalidMeshError(f"centred must be one of {', '.join(CENTRES)}, got {centred!r:.20}")
    mesh, start = _centre_mesh(lattice, n, depth, centred)
    centre, classes, labels, order = label_points(mesh, start, n, centred)
    return Neighbourhood(lattice, n, depth, centred, mesh, start, centre, classes, labels, order)
