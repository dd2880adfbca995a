"""A polygon mesh from outside (a modeller's file): validated, with its vertex stars and extraordinary vertices.

:class:`PolygonMesh` holds its vertices as a float64 array (:attr:`PolygonMesh.points_array`, ``(V, 3)``)
and their exact coordinates on request (:attr:`PolygonMesh.points`, :meth:`PolygonMesh.exact_point`:
``fractions.Fraction``; a decimal in a text file is the rational it spells, a double of a binary file
its exact value), and faces as tuples of vertex indices (0-based, counter-clockwise seen from
outside): quads, triangles, n-gons and any mixture. Coordinates are finite, of magnitude at most
:data:`~symdecomp.validate.MAX_COORDINATE`. Building one checks the whole mesh
(:mod:`symdecomp.schemes.mesh_topology`, linear or ``n log n`` time) in this order:

* a coordinate that is not a finite real number of that magnitude, a vertex without 3 coordinates,
  a vertex index that is not an integer or out of range (always refused);
* no faces; a face with fewer than 3 corners, a corner repeated, zero area (its corners collinear or
  coincident: decided in floats with an error bound, exactly when the bound cannot decide);
* a vertex in no face; two faces on the same corners;
* an edge of 3 or more faces (non-manifold edge); two faces running along an edge in the same
  direction (inconsistent orientation);
* a vertex where two or more fans of faces meet (non-manifold vertex).

``strict=True`` (the default of :meth:`PolygonMesh.from_arrays`: arrays from code are expected to be
right) refuses the first such element in one line (:class:`~symdecomp.errors.InvalidMeshError`), e.g.
``model.obj: edge (3, 7) is shared by 3 faces [0, 4, 9] (non-manifold edge)``. ``strict=False`` (the
default of :func:`~symdecomp.schemes.meshformats.read_mesh`) keeps the valid rest by the rules of
:mod:`symdecomp.schemes.mesh_topology` and lists what it left out in :attr:`PolygonMesh.defects`; vertex
``i`` of the input stays vertex ``i`` (a vertex left in no face is listed and not analysed), and
:attr:`PolygonMesh.face_index` gives each kept face's index in the input.

Interior vertices of valence 2 are taken (Catmull-Clark is defined there); :meth:`PolygonMesh.one_ring`,
where an extraordinary vertex is analysed, refuses them and vertices of valence above
:data:`~symdecomp.validate.MAX_MESH_VALENCE`, naming the vertex. A scheme asks for its lattice
(:meth:`PolygonMesh.require_lattice`: every face a quad for Catmull-Clark, a triangle for Loop; a face
of another size is named), the ordered 1-ring of an interior vertex (:meth:`PolygonMesh.one_ring`:
``O``, ``a_i``, ``b_i`` as in Eq. 10) and the extraordinary vertices (interior, valence other than the
regular one). Reading and writing OBJ, OFF and PLY files is :mod:`symdecomp.schemes.meshformats`.

>>> cube = PolygonMesh.from_arrays([(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)],
...     [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)], name="cube")
>>> from symdecomp.schemes.lattice import QUAD
>>> cube.extraordinary_vertices(QUAD), cube.one_ring(0, QUAD)
((0, 1, 2, 3, 4, 5, 6, 7), (0, (1, 4, 2), (5, 6, 3)))
>>> PolygonMesh.from_arrays(cube.points, cube.faces[:5] + ((1, 5, 7, 3),), name="cube.obj")
Traceback (most recent call last):
...
symdecomp.errors.InvalidMeshError: cube.obj: faces 2 and 5 both run along edge 1 -> 5 (inconsistent orientation)
>>> m = PolygonMesh.from_arrays(cube.points, cube.faces + ((0, 2, 3, 1),), strict=False)
>>> len(m.faces), m.defects.repeated_faces
(6, (6,))
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import replace
from fractions import Fraction

import numpy as np

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.mesh_topology import LegacyTopology, check_faces
from symdecomp.validate import MAX_COORDINATE, MAX_MESH_VALENCE, MESH_ADVICE, check_memory, check_mesh_valence, finite_double, mesh_memory

__all__ = ["PolygonMesh", "exact_coordinate", "scheme_for_mesh"]

_SIDE_NAMES = {3: "a triangle", 4: "a quad"}


def exact_coordinate(x, where: str) -> Fraction:
    """``x`` as an exact rational: ints, Fractions and finite floats (their exact binary value) of magnitude at most
    :data:`~symdecomp.validate.MAX_COORDINATE`; else one line naming ``where``."""
    if isinstance(x, bool):
        raise InvalidMeshError(f"{where}: coordinate {x!r} is not a number")
    if isinstance(x, Fraction):
        value = x
    elif isinstance(x, numbers.Integral):
        value = Fraction(int(x))
    elif isinstance(x, numbers.Rational):
        value = Fraction(int(x.numerator), int(x.denominator))
    elif isinstance(x, numbers.Real):
        f = float(x)
        if not math.isfinite(f):
            raise InvalidMeshError(f"{where}: coordinate {f!r} is not finite")
        value = Fraction(f)
    else:
        raise InvalidMeshError(f"{where}: coordinate {x!r:.40} is not a real number")
    if finite_double(value) is None:
        digits = math.floor(math.log10(abs(value.numerator)) - math.log10(value.denominator)) + 1
        raise InvalidMeshError(f"{where}: coordinate of about {digits} digits is beyond the range of doubles (a mesh coordinate is at "
                               f"most {MAX_COORDINATE:.4g} in magnitude)")
    return value


def _sides(k: int) -> str:
    return _SIDE_NAMES.get(k, f"a {k}-gon")


class PolygonMesh:
    """A validated, consistently oriented, manifold polygon mesh (closed or with boundary); see the module docstring.

    Build it with :meth:`from_arrays` (or read a file, :func:`symdecomp.schemes.meshformats.read_mesh`); the
    constructor takes the same arguments.
    """

    def __init__(self, points: Sequence, faces: Sequence, name: str = "mesh", *, tags: MeshTags | None = None, strict: bool = True):
        if not isinstance(name, str):
            raise InvalidMeshError(f"name must be a string, got {type(name).__name__}")
        floats, exact = _points(points, name)
        offsets, corners = _faces(faces, len(floats), name)
        self._build(floats, exact, offsets, corners, name, tags, strict)

    @classmethod
    def from_arrays(cls, points: Sequence, faces: Sequence, *, name: str = "mesh", tags: MeshTags | None = None,
                    strict: bool = True) -> PolygonMesh:
        """Validate ``points`` (``V`` triples of numbers, or a ``(V, 3)`` numpy array) and ``faces`` (sequences of 0-based
        indices, or an ``(F, k)`` integer array); ``strict=False`` keeps the valid rest (module docstring)."""
        return cls(points, faces, name, tags=tags, strict=strict)

    @classmethod
    def from_parsed(cls, floats: np.ndarray, exact_point, offsets: np.ndarray, corners: np.ndarray, *, name: str,
                    tags: MeshTags | None = None, strict: bool = False, edits: tuple = ()) -> PolygonMesh:
        """A mesh from a reader's checked arrays: ``floats`` ``(V, 3)`` finite float64 within the bound, ``exact_point(i)``
        the exact coordinates of vertex ``i``, ``offsets``/``corners`` integer indices in range (not checked again);
        ``edits``, the ``(line, level)`` of the file's hierarchical edits, are left out and listed in the defects
        (``strict``: refused)."""
        if edits and strict:
            line, level = edits[0]
            raise InvalidMeshError(f"{name}: line {line}: a hierarchical edit (acting at level {level}) is left out of the mesh, "
                                   "and strict reading refuses to leave anything out")
        mesh = cls.__new__(cls)
        mesh._build(floats, exact_point, offsets, corners, name, tags, strict)
        if edits:
            mesh.defects = replace(mesh.defects, hierarchical_edits=tuple(edits))
        return mesh

    def _build(self, floats, exact, offsets, corners, name, tags, strict) -> None:
        check_memory(mesh_memory(corners=len(corners), faces=len(offsets) - 1, vertices=len(floats)), f"{name}: a mesh of {len(floats)} vertices and "
                     f"{len(offsets) - 1} faces", MESH_ADVICE)
        self.name, self._cache = name, {}
        self.points_array = np.ascontiguousarray(floats, dtype=np.float64)
        self.points_array.flags.writeable = False
        self._exact = exact
        kept, self.defects, self._topo = check_faces(self.points_array, offsets, corners, name=name, strict=bool(strict),
                                                     exact_point=self.exact_point)
        #: Each kept face's index among the input's faces.
        self.face_index = kept
        self.tags = _kept_tags(tags or MeshTags(), kept, self._topo, name, bool(strict))

    # -- coordinates and faces --------------------------------------------------------------------

    def exact_point(self, v: int) -> tuple[Fraction, Fraction, Fraction]:
        """The exact coordinates of vertex ``v``."""
        v = self._check_vertex(v)
        if isinstance(self._exact, tuple):
            return self._exact[v]
        if callable(self._exact):
            return self._exact(v)
        return tuple(Fraction(float(x)) for x in self.points_array[v])

    @property
    def points(self) -> Sequence[tuple[Fraction, Fraction, Fraction]]:
        """Every vertex's exact coordinates, ``points[i]`` as :meth:`exact_point` (a sequence that makes each on first use)."""
        if "points" not in self._cache:
            self._cache["points"] = self._exact if isinstance(self._exact, tuple) else ExactPoints(self)
        return self._cache["points"]

    @property
    def faces(self) -> tuple[tuple[int, ...], ...]:
        """The kept faces, each a tuple of vertex indices in counter-clockwise order (seen from outside)."""
        if "faces" not in self._cache:
            flat, off = self._topo.corners.tolist(), self._topo.offsets.tolist()
            self._cache["faces"] = tuple(tuple(flat[a:b]) for a, b in zip(off, off[1:]))
        return self._cache["faces"]

    @property
    def face_count(self) -> int:
        """How many faces were kept (``len(faces)`` without building the tuples)."""
        return len(self._topo.offsets) - 1

    def __eq__(self, other):
        if not isinstance(other, PolygonMesh):
            return NotImplemented
        return (self.name == other.name and np.array_equal(self._topo.offsets, other._topo.offsets)
                and np.array_equal(self._topo.corners, other._topo.corners) and self.points == other.points)

    def __hash__(self):
        return hash((self.name, len(self.points_array), len(self._topo.corners)))

    def __repr__(self):
        return f"PolygonMesh({self.name!r}: {len(self.points_array)} vertices, {len(self._topo.offsets) - 1} faces)"

    def with_points(self, points: Sequence) -> PolygonMesh:
        """The same faces, tags and name with other points (checked again); what was left out stays listed."""
        mesh = PolygonMesh(points, self.faces, self.name, tags=self.tags)
        mesh.defects, mesh.face_index = self.defects, self.face_index
        return mesh

    @property
    def _topology(self) -> dict:
        """Dict-shaped incidences for callers written against the first mesh model (``"next"``: vertex -> ``{a: a'}``,
        ``"boundary"``: frozenset, ``"directed"``: ``(u, w)`` -> face), each made on first use; other keys are a cache."""
        if "legacy" not in self._cache:
            self._cache["legacy"] = LegacyTopology(self._topo)
        return self._cache["legacy"]

    # -- topology ---------------------------------------------------------------------------------

    def _check_vertex(self, v) -> int:
        if isinstance(v, bool) or not isinstance(v, numbers.Integral) or not 0 <= v < len(self.points_array):
            raise InvalidMeshError(f"{self.name}: vertex {v!r} is not an index 0..{len(self.points_array) - 1}")
        return int(v)

    def _in_faces(self, v) -> int:
        v = self._check_vertex(v)
        if not self._topo.faces_at[v]:
            raise InvalidMeshError(f"{self.name}: vertex {v} is in no face of the mesh (isolated vertex): it is not analysed")
        return v

    def is_boundary(self, v: int) -> bool:
        """Whether ``v`` is on the boundary (one of its edges has a single face)."""
        return bool(self._topo.boundary[self._check_vertex(v)])

    def boundary_vertices(self) -> tuple[int, ...]:
        """The vertices on boundary edges, sorted."""
        return tuple(np.flatnonzero(self._topo.boundary).tolist())

    def valence(self, v: int) -> int:
        """The number of edges at ``v`` (for an interior vertex, also its number of faces)."""
        v = self._in_faces(v)
        return int(self._topo.faces_at[v]) + int(self._topo.boundary[v])

    def valences(self) -> np.ndarray:
        """Every vertex's valence as an array (0 for a vertex in no face)."""
        return self._topo.faces_at + (self._topo.boundary & (self._topo.faces_at > 0))

    def face_sizes(self) -> tuple[int, ...]:
        """The distinct numbers of sides of the faces, sorted."""
        return tuple(np.unique(np.diff(self._topo.offsets)).tolist())

    def require_lattice(self, lattice, scheme_name: str = "the scheme") -> None:
        """Refuse, naming the first such face, a face that is not of the lattice's kind (a triangle in a quad mesh)."""
        wrong = np.flatnonzero(np.diff(self._topo.offsets) != lattice.face_sides)
        if len(wrong):
            i = int(wrong[0])
            raise InvalidMeshError(
                f"{self.name}: face {i} is {_sides(len(self.faces[i]))}; {scheme_name} takes {lattice.name} meshes only (every "
                f"face {_sides(lattice.face_sides)}); choose --scheme catmull-clark, which takes any polygons (symdecomp "
                f"refine writes its first step, every face a quad)"
            )

    def local_mesh(self, lattice):
        """The mesh as the lattice's local mesh type (vertex id = index, value = exact point); faces checked first."""
        key = ("local", lattice.name)
        if key not in self._cache:
            self.require_lattice(lattice)
            used = np.flatnonzero(self._topo.faces_at).tolist()
            self._cache[key] = lattice.mesh(self.faces, {v: self.exact_point(v) for v in used})
        return self._cache[key]

    def one_ring(self, v: int, lattice, start: int | None = None) -> tuple:
        """The ordered 1-ring of an interior vertex: ``(O, (a_0..), (b_0..))`` on quads, ``(O, (a_0..))`` on triangles.

        Counter-clockwise from ``start`` (default the smallest neighbour); faces ``(O, a_i, b_i, a_{i+1})`` (Eq. 10).
        Refused, naming the vertex: a boundary vertex, a face at ``v`` not of the lattice's kind, valence 2, and a
        valence above :data:`~symdecomp.validate.MAX_MESH_VALENCE`.
        """
        v = self._in_faces(v)
        if self._topo.boundary[v]:
            raise InvalidMeshError(f"{self.name}: vertex {v} is on the boundary: its 1-ring is not closed")
        fan = self._fan(v)
        n = len(fan)
        if n < 3:
            raise InvalidMeshError(f"{self.name}: vertex {v} is interior with {n} faces (valence 2); the analysis of an "
                                   "extraordinary vertex needs valence 3 or more")
        check_mesh_valence(n, v, self.name)
        for i, f in fan:
            if len(f) != lattice.face_sides:
                raise InvalidMeshError(f"{self.name}: face {i} at vertex {v} is {_sides(len(f))}; {lattice.name} meshes have "
                                       f"every face {_sides(lattice.face_sides)}")
        a = [f[1] for _, f in fan]
        first = min(a) if start is None else start
        if first not in a:
            raise InvalidMeshError(f"{self.name}: vertex {start!r} is not an edge neighbour of {v}")
        k = a.index(first)
        fan = fan[k:] + fan[:k]
        if lattice.face_sides == 4:
            return v, tuple(f[1] for _, f in fan), tuple(f[2] for _, f in fan)
        return v, tuple(f[1] for _, f in fan)

    def _fan(self, v: int) -> list[tuple[int, tuple[int, ...]]]:
        """The faces at an interior vertex counter-clockwise, each ``(index, corners rotated to start at v)``."""
        t = self._topo
        c = int(t.by_vertex[t.vertex_start[v]])
        out = []
        for _ in range(min(int(t.faces_at[v]), MAX_MESH_VALENCE + 1)):
            i = int(np.searchsorted(t.offsets, c, side="right") - 1)
            a, b = int(t.offsets[i]), int(t.offsets[i + 1])
            k = c - a
            f = t.corners[a:b].tolist()
            out.append((i, tuple(f[k:] + f[:k])))
            c = int(t.succ[c])
        if t.faces_at[v] > MAX_MESH_VALENCE:
            check_mesh_valence(int(t.faces_at[v]), v, self.name)
        return out

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
        """The interior vertices (in a face) whose valence is not the lattice's regular valence, in index order."""
        self.require_lattice(lattice)
        t = self._topo
        return tuple(np.flatnonzero((t.faces_at > 0) & ~t.boundary & (t.faces_at != lattice.regular_valence)).tolist())


class ExactPoints(Sequence):
    """A mesh's exact points as a read-only sequence: ``points[i]`` is made on first use and kept; equal to a tuple of
    the same points."""

    def __init__(self, mesh: PolygonMesh):
        self._mesh = mesh
        self._made: dict = {}

    def __len__(self) -> int:
        return len(self._mesh.points_array)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return tuple(self[k] for k in range(*i.indices(len(self))))
        if isinstance(i, numbers.Integral) and not isinstance(i, bool) and -len(self) <= i < len(self):
            i = int(i) % len(self)
            if i not in self._made:
                self._made[i] = self._mesh.exact_point(i)
            return self._made[i]
        raise IndexError(f"{self._mesh.name}: vertex {i!r} is not an index 0..{len(self) - 1}")

    def __eq__(self, other):
        if not isinstance(other, Sequence) or isinstance(other, (str, bytes)):
            return NotImplemented
        return len(self) == len(other) and all(a == b for a, b in zip(self, other))

    __hash__ = None

    def __repr__(self):
        return f"ExactPoints({self._mesh.name!r}: {len(self)} points)"


def _points(points, name: str) -> tuple[np.ndarray, tuple | None]:
    """``(floats, exact)``: the ``(V, 3)`` float64 array and the exact points (``None``: the floats are exact)."""
    if isinstance(points, np.ndarray) and points.dtype.kind in "iuf" and points.ndim == 2 and points.shape[1] == 3:
        floats = points.astype(np.float64)
        bad = np.flatnonzero(~np.isfinite(floats).all(axis=1))
        if len(bad):
            for x in points[bad[0]].tolist():
                exact_coordinate(x, f"{name}: vertex {bad[0]}")
        if points.dtype.kind != "f" and (np.abs(points) > 2**53).any():  # pragma: no cover - refused above
            raise InvalidMeshError(f"{name}: integer coordinates beyond 2^53")
        return floats, None
    if isinstance(points, (str, bytes)) or not hasattr(points, "__len__"):
        raise InvalidMeshError(f"{name}: points must be a sequence of (x, y, z), got {type(points).__name__}")
    check_memory(mesh_memory(vertices=8 * len(points)), f"{name}: a mesh of {len(points)} vertices", MESH_ADVICE)
    exact = tuple(_point(p, i, name) for i, p in enumerate(points))
    floats = np.array([[finite_double(c) for c in p] for p in exact], dtype=np.float64).reshape(-1, 3)
    return floats, exact


def _point(p, i: int, name: str) -> tuple[Fraction, Fraction, Fraction]:
    where = f"{name}: vertex {i}"
    if isinstance(p, (str, bytes)) or not hasattr(p, "__len__"):
        raise InvalidMeshError(f"{where}: expected 3 coordinates, got {p!r:.40}")
    if len(p) != 3:
        raise InvalidMeshError(f"{where}: expected 3 coordinates (x, y, z), got {len(p)}")
    return tuple(exact_coordinate(x, where) for x in p)


def _faces(faces, count: int, name: str) -> tuple[np.ndarray, np.ndarray]:
    """``(offsets, corners)`` of ``faces``; every index an integer in ``0..count-1``, else one line naming the face."""
    if isinstance(faces, np.ndarray) and faces.dtype.kind in "iu" and faces.ndim == 2:
        corners = faces.astype(np.int64).reshape(-1)
        offsets = np.arange(0, len(corners) + 1, max(faces.shape[1], 1), dtype=np.int64)[: len(faces) + 1]
    else:
        if isinstance(faces, (str, bytes)) or not hasattr(faces, "__len__"):
            raise InvalidMeshError(f"{name}: faces must be a sequence of index sequences, got {type(faces).__name__}")
        check_memory(mesh_memory(corners=3 * len(faces), faces=len(faces)), f"{name}: a mesh of {len(faces)} faces", MESH_ADVICE)
        flat, sizes = [], []
        for i, f in enumerate(faces):
            if isinstance(f, (str, bytes)) or not hasattr(f, "__len__"):
                raise InvalidMeshError(f"{name}: face {i}: expected a sequence of vertex indices, got {f!r:.40}")
            for v in f:
                if type(v) is not int and (isinstance(v, bool) or not isinstance(v, numbers.Integral)):
                    raise InvalidMeshError(f"{name}: face {i}: vertex index {v!r:.40} is not an integer")
            flat.extend(f)
            sizes.append(len(f))
        corners = np.array([int(v) for v in flat], dtype=object if any(abs(int(v)) >= 2**62 for v in flat) else np.int64)
        offsets = np.zeros(len(sizes) + 1, dtype=np.int64)
        np.cumsum(sizes, out=offsets[1:])
    bad = np.flatnonzero((corners < 0) | (corners >= count))
    if len(bad):
        i = int(np.searchsorted(offsets, bad[0], side="right") - 1)
        raise InvalidMeshError(f"{name}: face {i}: vertex index {int(corners[bad[0]])} is out of range (the mesh has {count} "
                               f"vertices, 0..{count - 1})")
    return offsets, corners.astype(np.int64)


def _kept_tags(tags: MeshTags, kept: np.ndarray, topo, name: str, strict: bool) -> MeshTags:
    """``tags`` on the kept mesh: holes renumbered to kept faces; creases on edges, corners on vertices of kept faces
    (strict: a tag on anything else is refused; lenient: dropped with the elements listed in the defects)."""
    if not isinstance(tags, MeshTags):
        raise InvalidMeshError(f"{name}: tags must be a MeshTags, got {type(tags).__name__}")
    if tags.is_empty():
        return tags
    count = len(topo.faces_at)

    def is_edge(u, v):
        if not (0 <= u < count and 0 <= v < count):
            return False
        at = topo.by_vertex[topo.vertex_start[u]:topo.vertex_start[u + 1]]
        return bool(np.any(topo.corners[topo.next[at]] == v) or np.any(topo.corners[topo.prev[at]] == v))

    creases = {e: s for e, s in tags.creases.items() if is_edge(*e)}
    corners = {v: s for v, s in tags.corners.items() if 0 <= v < count and topo.faces_at[v]}
    position = np.searchsorted(kept, sorted(tags.holes))
    holes = {int(p) for p, h in zip(position, sorted(tags.holes)) if p < len(kept) and kept[p] == h}
    lost = [f"crease on {e}, not an edge" for e in tags.creases if e not in creases]
    lost += [f"corner at vertex {v}, in no face" for v in tags.corners if v not in corners]
    lost += [f"hole at face {h}, not a face" for h in sorted(tags.holes) if h not in {int(kept[p]) for p in holes}]
    if strict and lost:
        raise InvalidMeshError(f"{name}: tag {lost[0]} of the mesh")
    return MeshTags(creases=creases, corners=corners, holes=frozenset(holes), interpolate_boundary=tags.interpolate_boundary,
                    crease_method=tags.crease_method, triangle_subdivision=tags.triangle_subdivision)


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
