"""A polygon mesh from outside (a modeller's file): validated, with its vertex stars and extraordinary vertices.

:class:`PolygonMesh` holds exact vertex coordinates (``fractions.Fraction``: a decimal in a text file
is read as the rational it spells, a double of a binary file as its exact value) and faces as
tuples of vertex indices (0-based, counter-clockwise seen from outside). Building one checks the
whole mesh and names the first element that a subdivision scheme cannot take, in one line
(:class:`~symdecomp.errors.InvalidMeshError`), e.g. ``model.obj: edge (3, 7) is shared by 3 faces
(non-manifold edge)``. The kinds refused, in the order they are checked:

* a coordinate that is not a finite real number, a vertex without 3 coordinates;
* no faces; a face with fewer than 3 corners, an index out of range, a corner repeated;
* a face of zero area (its corners collinear or coincident; decided exactly);
* a vertex in no face; two faces on the same corners;
* an edge of 3 or more faces (non-manifold edge); two faces running along an edge in the same
  direction (inconsistent orientation);
* a vertex where two or more fans of faces meet (non-manifold vertex);
* an interior vertex of fewer than 3 faces.

A scheme then asks for its lattice (:meth:`PolygonMesh.require_lattice`: every face a quad for
Catmull-Clark, a triangle for Loop; a face of another size is named) and gets the local mesh of
that kind (:meth:`PolygonMesh.local_mesh`, a :class:`~symdecomp.schemes.mesh.QuadMesh` or
``TriangleMesh`` whose vertex ids are the indices), the ordered 1-ring of an interior vertex
(:meth:`PolygonMesh.one_ring`: ``O``, ``a_i``, ``b_i`` as in Eq. 10) and the extraordinary vertices
(interior, valence other than the regular one). Boundary vertices are found, not analysed.
Reading and writing OBJ, OFF and PLY files is :mod:`symdecomp.schemes.meshformats`.

>>> cube = PolygonMesh.from_arrays([(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)],
...     [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)], name="cube")
>>> from symdecomp.schemes.lattice import QUAD
>>> cube.extraordinary_vertices(QUAD), cube.one_ring(0, QUAD)
((0, 1, 2, 3, 4, 5, 6, 7), (0, (1, 4, 2), (5, 6, 3)))
>>> PolygonMesh.from_arrays(cube.points, cube.faces[:5] + ((1, 5, 7, 3),), name="cube.obj")
Traceback (most recent call last):
...
symdecomp.errors.InvalidMeshError: cube.obj: faces 2 and 5 both run along edge 1 -> 5 (inconsistent orientation)
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass, field
from fractions import Fraction

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_tags import MeshDefects, MeshTags
from symdecomp.validate import check_memory

__all__ = ["PolygonMesh", "exact_coordinate", "scheme_for_mesh"]

_SIDE_NAMES = {3: "a triangle", 4: "a quad"}


def exact_coordinate(x, where: str) -> Fraction:
    """``x`` as an exact rational: ints, Fractions and finite floats (their exact binary value); else one line naming ``where``."""
    if isinstance(x, bool):
        raise InvalidMeshError(f"{where}: coordinate {x!r} is not a number")
    if isinstance(x, Fraction):
        return x
    if isinstance(x, numbers.Integral):
        return Fraction(int(x))
    if isinstance(x, numbers.Rational):
        return Fraction(int(x.numerator), int(x.denominator))
    if isinstance(x, numbers.Real):
        value = float(x)
        if not math.isfinite(value):
            raise InvalidMeshError(f"{where}: coordinate {value!r} is not finite")
        return Fraction(value)
    raise InvalidMeshError(f"{where}: coordinate {x!r:.40} is not a real number")


def _sides(k: int) -> str:
    return _SIDE_NAMES.get(k, f"a {k}-gon")


@dataclass(frozen=True)
class PolygonMesh:
    """A validated, consistently oriented, manifold polygon mesh (closed or with boundary); see the module docstring.

    Build it with :meth:`from_arrays` (or read a file, :func:`symdecomp.schemes.meshformats.read_mesh`).
    """

    #: The vertices, each ``(x, y, z)`` as exact ``Fraction``s; vertex ``i`` is ``points[i]``.
    points: tuple[tuple[Fraction, Fraction, Fraction], ...]
    #: The faces, each a tuple of vertex indices in counter-clockwise order (seen from outside).
    faces: tuple[tuple[int, ...], ...]
    #: The name errors start with (a file name, or ``"mesh"``).
    name: str = "mesh"
    #: OpenSubdiv's sharpness tags read with the mesh (creases, corners, holes, boundary interpolation); none by default.
    tags: MeshTags = field(default_factory=MeshTags, compare=False)
    #: The elements of the file left out of this mesh (non-manifold, degenerate, repeated, isolated), in the file's numbering.
    defects: MeshDefects = field(default_factory=MeshDefects, compare=False)
    _topology: dict = field(default_factory=dict, repr=False, compare=False)

    @classmethod
    def from_arrays(cls, points: Sequence, faces: Sequence, *, name: str = "mesh") -> PolygonMesh:
        """Validate ``points`` (``V`` triples of numbers) and ``faces`` (sequences of 0-based indices)."""
        if not isinstance(name, str):
            raise InvalidMeshError(f"name must be a string, got {type(name).__name__}")
        if isinstance(points, (str, bytes)) or not hasattr(points, "__len__"):
            raise InvalidMeshError(f"{name}: points must be a sequence of (x, y, z), got {type(points).__name__}")
        if isinstance(faces, (str, bytes)) or not hasattr(faces, "__len__"):
            raise InvalidMeshError(f"{name}: faces must be a sequence of index sequences, got {type(faces).__name__}")
        check_memory(256 * (len(points) + len(faces)), f"{name}: a mesh of {len(points)} vertices and {len(faces)} faces")
        return cls(tuple(_point(p, i, name) for i, p in enumerate(points)), tuple(_face(f, i, len(points), name) for i, f in enumerate(faces)),
                   name)

    def __post_init__(self):
        if not self.faces:
            raise InvalidMeshError(f"{self.name}: the mesh has no faces")
        for i, f in enumerate(self.faces):
            _check_area(self, i, f)
        used = {v for f in self.faces for v in f}
        for v in range(len(self.points)):
            if v not in used:
                raise InvalidMeshError(f"{self.name}: vertex {v} is in no face (isolated vertex)")
        seen: dict[frozenset, int] = {}
        for i, f in enumerate(self.faces):
            if frozenset(f) in seen:
                raise InvalidMeshError(f"{self.name}: faces {seen[frozenset(f)]} and {i} have the same corners {sorted(f)} (duplicate face)")
            seen[frozenset(f)] = i
        directed = _directed_edges(self)
        nxt = _fans(self, directed)
        self._topology.update(directed=directed, next=nxt)

    # -- topology ---------------------------------------------------------------------------------

    def _check_vertex(self, v) -> int:
        if isinstance(v, bool) or not isinstance(v, numbers.Integral) or not 0 <= v < len(self.points):
            raise InvalidMeshError(f"{self.name}: vertex {v!r} is not an index 0..{len(self.points) - 1}")
        return int(v)

    def is_boundary(self, v: int) -> bool:
        """Whether ``v`` is on the boundary (one of its edges has a single face)."""
        return self._check_vertex(v) in self._topology["boundary"]

    def boundary_vertices(self) -> tuple[int, ...]:
        """The vertices on boundary edges, sorted."""
        return tuple(sorted(self._topology["boundary"]))

    def valence(self, v: int) -> int:
        """The number of edges at ``v`` (for an interior vertex, also its number of faces)."""
        return len(self._topology["next"][self._check_vertex(v)])

    def face_sizes(self) -> tuple[int, ...]:
        """The distinct numbers of sides of the faces, sorted."""
        return tuple(sorted({len(f) for f in self.faces}))

    def require_lattice(self, lattice, scheme_name: str = "the scheme") -> None:
        """Refuse, naming the first such face, a face that is not of the lattice's kind (a triangle in a quad mesh)."""
        for i, f in enumerate(self.faces):
            if len(f) != lattice.face_sides:
                raise InvalidMeshError(
                    f"{self.name}: face {i} is {_sides(len(f))}; {scheme_name} takes {lattice.name} meshes only (every face "
                    f"{_sides(lattice.face_sides)}); refine the mesh first or choose another --scheme"
                )

    def local_mesh(self, lattice):
        """The mesh as the lattice's local mesh type (vertex id = index, value = exact point); faces checked first."""
        key = ("local", lattice.name)
        if key not in self._topology:
            self.require_lattice(lattice)
            self._topology[key] = lattice.mesh(self.faces, dict(enumerate(self.points)))
        return self._topology[key]

    def one_ring(self, v: int, lattice, start: int | None = None) -> tuple:
        """The ordered 1-ring of an interior vertex: ``(O, (a_0..), (b_0..))`` on quads, ``(O, (a_0..))`` on triangles.

        Counter-clockwise from ``start`` (default the smallest neighbour); faces ``(O, a_i, b_i, a_{i+1})`` (Eq. 10).
        """
        v = self._check_vertex(v)
        if v in self._topology["boundary"]:
            raise InvalidMeshError(f"{self.name}: vertex {v} is on the boundary: its 1-ring is not closed")
        return self.local_mesh(lattice).one_ring(v, start)

    def split_into_quads(self) -> PolygonMesh:
        """Every ``k``-gon split into ``k`` quads at its centroid and edge midpoints (exact): an all-quad mesh.

        The topology of one Catmull-Clark step with linear positions: the old vertices keep their
        valence, a ``k``-gon's centroid gets valence ``k``, edge midpoints valence 4 (3 on the boundary).
        New vertices follow the old ones: the centroids in face order, then the midpoints in order of first use.
        """
        points = list(self.points)
        centre = []
        for f in self.faces:
            centre.append(len(points))
            points.append(tuple(sum((self.points[v][c] for v in f), Fraction(0)) / len(f) for c in range(3)))
        middle: dict[frozenset, int] = {}
        for f in self.faces:
            for k in range(len(f)):
                edge = frozenset((f[k], f[(k + 1) % len(f)]))
                if edge not in middle:
                    middle[edge] = len(points)
                    points.append(tuple((self.points[f[k]][c] + self.points[f[(k + 1) % len(f)]][c]) / 2 for c in range(3)))
        faces = []
        for i, f in enumerate(self.faces):
            c = len(f)
            for k in range(c):
                before, after = frozenset((f[k - 1], f[k])), frozenset((f[k], f[(k + 1) % c]))
                faces.append((f[k], middle[after], centre[i], middle[before]))
        return PolygonMesh(tuple(points), tuple(faces), self.name)

    def extraordinary_vertices(self, lattice) -> tuple[int, ...]:
        """The interior vertices whose valence is not the lattice's regular valence, in index order."""
        self.require_lattice(lattice)
        nxt, boundary = self._topology["next"], self._topology["boundary"]
        return tuple(v for v in range(len(self.points)) if v not in boundary and len(nxt[v]) != lattice.regular_valence)


def _point(p, i: int, name: str) -> tuple[Fraction, Fraction, Fraction]:
    where = f"{name}: vertex {i}"
    if isinstance(p, (str, bytes)) or not hasattr(p, "__len__"):
        raise InvalidMeshError(f"{where}: expected 3 coordinates, got {p!r:.40}")
    if len(p) != 3:
        raise InvalidMeshError(f"{where}: expected 3 coordinates (x, y, z), got {len(p)}")
    return tuple(exact_coordinate(x, where) for x in p)


def _face(f, i: int, count: int, name: str) -> tuple[int, ...]:
    where = f"{name}: face {i}"
    if isinstance(f, (str, bytes)) or not hasattr(f, "__len__"):
        raise InvalidMeshError(f"{where}: expected a sequence of vertex indices, got {f!r:.40}")
    if len(f) < 3:
        raise InvalidMeshError(f"{where} has {len(f)} corner{'s' * (len(f) != 1)}; a face needs at least 3 (degenerate face)")
    out = []
    for v in f:
        if isinstance(v, bool) or not isinstance(v, numbers.Integral):
            raise InvalidMeshError(f"{where}: vertex index {v!r:.40} is not an integer")
        if not 0 <= v < count:
            raise InvalidMeshError(f"{where}: vertex index {int(v)} is out of range (the mesh has {count} vertices, 0..{count - 1})")
        out.append(int(v))
    repeated = [v for k, v in enumerate(out) if v in out[:k]]
    if repeated:
        raise InvalidMeshError(f"{where} repeats vertex {repeated[0]} (degenerate face)")
    return tuple(out)


def _check_area(mesh: PolygonMesh, i: int, f: tuple[int, ...]) -> None:
    """A face's vector area ``sum p_k x p_{k+1}`` is zero exactly when its corners are collinear (or it folds flat)."""
    pts = [mesh.points[v] for v in f]
    area = [Fraction(0)] * 3
    for p, q in zip(pts, pts[1:] + pts[:1]):
        area[0] += p[1] * q[2] - p[2] * q[1]
        area[1] += p[2] * q[0] - p[0] * q[2]
        area[2] += p[0] * q[1] - p[1] * q[0]
    if not any(area):
        raise InvalidMeshError(f"{mesh.name}: face {i} {f} has zero area (degenerate face)")


def _directed_edges(mesh: PolygonMesh) -> dict[tuple[int, int], int]:
    """Directed edge -> its face; refuses a non-manifold edge and two faces running the same way along an edge."""
    directed: dict[tuple[int, int], int] = {}
    around: dict[frozenset, list[int]] = {}
    for i, f in enumerate(mesh.faces):
        for k in range(len(f)):
            around.setdefault(frozenset((f[k], f[(k + 1) % len(f)])), []).append(i)
    for edge, fs in around.items():
        if len(fs) > 2:
            u, v = sorted(edge)
            raise InvalidMeshError(f"{mesh.name}: edge ({u}, {v}) is shared by {len(fs)} faces {fs} (non-manifold edge)")
    for i, f in enumerate(mesh.faces):
        for k in range(len(f)):
            e = (f[k], f[(k + 1) % len(f)])
            if e in directed:
                raise InvalidMeshError(f"{mesh.name}: faces {directed[e]} and {i} both run along edge {e[0]} -> {e[1]} (inconsistent orientation)")
            directed[e] = i
    return directed


def _fans(mesh: PolygonMesh, directed: dict) -> dict[int, dict[int, int]]:
    """Per vertex ``v``: ``{a: a'}``, the next edge neighbour counter-clockwise (face ``(v, a, .., a')``); checks one fan per vertex."""
    nxt: dict[int, dict[int, int]] = {v: {} for v in range(len(mesh.points))}
    for f in mesh.faces:
        c = len(f)
        for k in range(c):
            nxt[f[k]][f[(k + 1) % c]] = f[(k - 1) % c]
    boundary = {x for (u, v) in directed if (v, u) not in directed for x in (u, v)}
    for v, step in nxt.items():
        targets = set(step.values())
        starts = [a for a in step if a not in targets] if v in boundary else [min(step)]
        if len(starts) > 1:
            raise InvalidMeshError(f"{mesh.name}: vertex {v} joins {len(starts)} separate fans of faces (non-manifold vertex)")
        seen, a = {starts[0]}, starts[0]
        while a in step and step[a] not in seen:
            a = step[a]
            seen.add(a)
        if len(seen) < len(set(step) | targets):
            raise InvalidMeshError(f"{mesh.name}: vertex {v} joins separate fans of faces (non-manifold vertex)")
        if v not in boundary and len(step) < 3:
            raise InvalidMeshError(f"{mesh.name}: vertex {v} is interior with {len(step)} faces; a subdivision scheme needs at "
                                   "least 3 (valence 2)")
    for v in boundary:  # a boundary vertex also has the edge that ends its fan
        nxt[v] = dict(nxt[v])
        nxt[v].update({b: None for b in set(nxt[v].values()) - set(nxt[v])})
    mesh._topology["boundary"] = frozenset(boundary)
    return nxt


def scheme_for_mesh(mesh: PolygonMesh):
    """The scheme for ``mesh`` when none is given: the reference scheme of the lattice whose faces the mesh has
    (Catmull-Clark for quads, Loop for triangles); a mesh with faces of several sizes is refused, naming two.
    A given scheme is checked with :meth:`PolygonMesh.require_lattice` instead."""
    from symdecomp.schemes.lattice import LATTICES

    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    sizes = mesh.face_sizes()
    fits = [lat for lat in LATTICES.values() if (lat.face_sides,) == sizes]
    if not fits:
        first = next((i for i, f in enumerate(mesh.faces) if len(f) != len(mesh.faces[0])), None)
        which = (f"every face is {_sides(len(mesh.faces[0]))}" if first is None else
                 f"face 0 is {_sides(len(mesh.faces[0]))} and face {first} is {_sides(len(mesh.faces[first]))}")
        kinds = ", ".join(f"{lat.reference().name} needs every face {_sides(lat.face_sides)}" for lat in LATTICES.values())
        raise InvalidMeshError(f"{mesh.name}: {which}, and no scheme takes it ({kinds}); refine the mesh first")
    return fits[0].reference()
