"""The neighbourhood of a boundary, crease, corner or dart vertex, and its exact subdivision matrix.

A :class:`SharpVertex` is the vertex ``O`` of a fan of faces split by sharp edges into sectors: ``sectors``
gives the faces of each sector in rotational order, the fan is ``closed`` (an interior vertex: a crease
with two sectors, a dart with one, a corner-like vertex with more) or open (a boundary: one sector between the
two boundary edges, or more with creases inside), ``corner`` tags ``O`` as a corner (interpolated), and
``sharpness`` is the sharpness of the sharp edges that are not boundary edges (semi-sharp: a ``Fraction``).
Every other vertex of the neighbourhood is regular: valence 4 (quads) or 6 (triangles) inside, 2 faces
(quads) or 3 (triangles) on a boundary, and the vertices along a crease are regular crease vertices.

The 1-ring in matrix order is ``O, a_0..a_m, b_0..b_{f-1}``: the edge neighbours in rotational order
(``a_0`` on the first sharp edge; ``m + 1 = f + 1`` of them on an open fan of ``f`` faces, ``f`` on a closed
one) and on quads the face neighbours, ``b_i`` in the face ``(O, a_i, b_i, a_{i+1})``. The ``K``-ring
(:meth:`SharpVertex.ring_labels`) is the 1-ring in that order, then ring by ring, sector by sector (face by
face of ``O``), the points ``(s, u, v)`` labelled as in :mod:`symdecomp.schemes.mesh` (``u`` steps along the
edge ray ``s``, ``v`` along ray ``s + 1``), and on an open fan the last ray's points ``(f, u, 0)``.

:func:`sharp_subdivision_matrix` refines the tagged ``K``-ring mesh once with the scheme's rules for the whole
mesh, sharp ones included (:mod:`symdecomp.schemes.tagged_refinement`: every vertex with the rule its own tags
and valence give, OpenSubdiv's semantics), and reads the new ``K``-ring: row ``i`` is the stencil of the new
point at label ``i``. ``level`` is the refinement level at which the matrix is taken: semi-sharp edges have
lost ``level`` of their sharpness (every sharp edge of the neighbourhood has the same sharpness, so uniform
and Chaikin decay agree here).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.lattice import QUAD
>>> v = SharpVertex.boundary(2, QUAD)
>>> v.vertex_order()
('O', 'a_0', 'a_1', 'a_2', 'b_0', 'b_1')
>>> sharp_subdivision_matrix(catmull_clark(), v)[0, :]
Matrix([[3/4, 1/8, 0, 1/8, 0, 0]])
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from itertools import accumulate
from types import SimpleNamespace

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_sympy
from symdecomp.errors import InternalError, InvalidInputError, InvalidMeshError, NotApplicableError
from symdecomp.expressions import exact_value
from symdecomp.schemes.lattice import Lattice, lattice
from symdecomp.schemes.rings import MAX_RINGS, check_rings
from symdecomp.schemes.scheme import check_scheme
from symdecomp.schemes.sharp import SharpOptions, check_sharpness, decrement
from symdecomp.schemes.tagged_refinement import TaggedMesh, sharp_stencils
from symdecomp.validate import INPUT_LIMITS, cached, check_int, check_levels, check_memory, check_type

__all__ = ["SharpVertex", "sharp_subdivision_matrix", "sharp_matrix_rows", "exact_sharp_matrix", "MAX_SECTOR_FACES", "MAX_DENSE_FACES", "MAX_LEVEL"]

#: Most faces around a sharp vertex (the structural route, :mod:`symdecomp.analysis.block_values`, is O(k)).
MAX_SECTOR_FACES = INPUT_LIMITS["--boundary, --corner, --crease: faces by the blocks"][0]
#: Most faces around a vertex whose matrix is built here (dense, exact): checked before any work.
MAX_DENSE_FACES = INPUT_LIMITS["--boundary, --corner, --crease, --dart: faces"][0]
#: Highest refinement level of :func:`sharp_subdivision_matrix` (past 10 every finite sharpness is 0).
MAX_LEVEL = 16


def _faces(value, argument: str) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not 1 <= value <= MAX_SECTOR_FACES:
        raise InvalidInputError(f"{argument} must be an integer from 1 to {MAX_SECTOR_FACES}, got {value!r:.40}")
    return int(value)


@dataclass(frozen=True)
class SharpVertex:
    """A boundary, crease, corner or dart vertex and its fan of faces (see the module docstring)."""

    #: The lattice: :data:`~symdecomp.schemes.lattice.QUAD` or ``TRIANGLE`` (or its name).
    lattice: Lattice
    #: Faces of each sector between consecutive sharp edges, in rotational order.
    sectors: tuple[int, ...]
    #: ``False`` on a boundary: the fan of faces is open.
    closed: bool
    #: ``O`` is tagged as a corner (an infinitely sharp vertex: interpolated).
    corner: bool = False
    #: Sharpness of the sharp edges that are not boundary edges: a ``Fraction`` or ``math.inf``.
    sharpness: object = math.inf
    #: Corner angle for BLZ's ``theta_k = angle/k`` (an exact expression such as ``pi/2``); ``None``: ``pi/k``.
    angle: sp.Expr | None = None

    def __post_init__(self):
        object.__setattr__(self, "lattice", lattice(self.lattice))
        if isinstance(self.sectors, (str, bytes)) or not hasattr(self.sectors, "__iter__"):
            raise InvalidInputError(f"sectors must be a tuple of face counts, got {self.sectors!r:.40}")
        sectors = tuple(_faces(k, "faces of a sector") for k in self.sectors)
        for name in ("closed", "corner"):
            check_type(getattr(self, name), bool, name)
        if not sectors or sum(sectors) > MAX_SECTOR_FACES or (self.closed and sum(sectors) < 3):
            raise InvalidInputError(f"sectors {sectors}: need 1 to {MAX_SECTOR_FACES} faces (3 or more around a closed fan: "
                                    "an interior vertex has valence 3 or more)")
        object.__setattr__(self, "sectors", sectors)
        object.__setattr__(self, "sharpness", check_sharpness(self.sharpness, "sharpness"))
        if self.angle is not None:
            angle = exact_value(self.angle, {}, argument="corner angle")
            if not (angle.is_positive and (angle - 2 * sp.pi).is_negative):
                raise InvalidInputError(f"corner angle must be in (0, 2*pi), got {angle}")
            object.__setattr__(self, "angle", angle)

    def __repr__(self) -> str:
        extra = "".join(f", {name}={getattr(self, name)!r}" for name, default in (("corner", False), ("sharpness", math.inf),
                                                                                   ("angle", None))
                        if getattr(self, name) != default)
        return f"SharpVertex({self.lattice.name!r}, {self.sectors}, closed={self.closed}{extra})"

    @classmethod
    def boundary(cls, k: int, lattice: Lattice | str) -> SharpVertex:
        """A boundary vertex with ``k`` faces."""
        return cls(lattice, (k,), False)

    @classmethod
    def crease(cls, k1: int, k2: int, lattice: Lattice | str, sharpness=math.inf) -> SharpVertex:
        """An interior vertex on a crease: two sharp edges with ``k1`` faces on one side and ``k2`` on the other."""
        return cls(lattice, (k1, k2), True, False, sharpness)

    @classmethod
    def dart(cls, n: int, lattice: Lattice | str, sharpness=math.inf) -> SharpVertex:
        """An interior vertex of valence ``n`` where a crease ends (one sharp edge)."""
        return cls(lattice, (n,), True, False, sharpness)

    @property
    def faces(self) -> int:
        """Faces around ``O``."""
        return sum(self.sectors)

    def edge_count(self) -> int:
        """Edge neighbours ``a_i`` of ``O``: one more than the faces on an open fan."""
        return self.faces + (0 if self.closed else 1)

    def sharp_rays(self) -> tuple[int, ...]:
        """Indices ``i`` of the sharp edges ``(O, a_i)``: ``a_0`` and every sector's end."""
        ends = (0, *accumulate(self.sectors))
        return tuple(sorted({e % self.faces for e in ends} if self.closed else set(ends)))

    def crease_points(self) -> tuple[int, ...]:
        """The rows of ``O`` and of its neighbours ``a_m`` on sharp edges in the 1-ring order ``O, a_0, ..``: the seeds of
        the crease block (:func:`~symdecomp.analysis.triangular_eigen.matrix_parts`)."""
        return (0,) + tuple(1 + m for m in self.sharp_rays())

    def one_ring_size(self) -> int:
        """Points of the 1-ring: ``O``, the edge neighbours and (quads) the face neighbours."""
        return 1 + sum(count for _, _, count in self._one_ring_classes())

    def vertex_order(self) -> tuple[str, ...]:
        """Names of the 1-ring points in matrix order: ``O, a_0..a_m, b_0..b_{f-1}``."""
        return ("O",) + tuple(f"{name}_{i}" for name, _, count in self._one_ring_classes() for i in range(count))

    def _one_ring_classes(self) -> tuple[tuple[str, tuple[int, int], int], ...]:
        """The lattice's kinds of 1-ring neighbours as ``(name, (u, v), count)``: one ``a_i`` per edge, the others per face."""
        return tuple((name, uv, self.edge_count() if uv == (1, 0) else self.faces) for name, uv in self.lattice.one_ring_classes)

    def at_level(self, level: int) -> SharpVertex:
        """The same vertex ``level`` refinements later: a semi-sharp sharpness decreased by ``level``."""
        s = self.sharpness
        for _ in range(check_levels(level, "level", maximum=MAX_LEVEL)):
            s = decrement(s)
        return SharpVertex(self.lattice, self.sectors, self.closed, self.corner, s, self.angle)

    def ring_labels(self, rings: int = 1) -> tuple[tuple[int, int, int], ...]:
        """Labels ``(s, u, v)`` of the closed ``rings``-ring in matrix order (see the module docstring)."""
        return self._labels(check_rings(rings))

    def _labels(self, rings: int) -> tuple[tuple[int, int, int], ...]:
        f = self.faces
        out = [(0, 0, 0)] + [(i, u, v) for _, (u, v), count in self._one_ring_classes() for i in range(count)]
        for r in range(2, rings + 1):
            ring = self.lattice.sector_ring(r)
            for s in range(f):
                out += [(s, u, v) for u, v in ring]
            out += [] if self.closed else [(f, r, 0)]
        return tuple(out)

    def _canonical(self, s: int, u: int, v: int) -> tuple[int, int, int]:
        """The label of the point ``(s, u, v)`` of a sector, with ``u >= 1`` (``(0, 0, 0)``: ``O``)."""
        if u == 0 and v == 0:
            return (0, 0, 0)
        if u == 0:
            s, u, v = s + 1, v, 0
        return (s % self.faces if self.closed else s, u, v)

    def tagged_mesh(self, rings: int = 1) -> tuple[TaggedMesh, dict]:
        """The tagged ``rings``-ring mesh around ``O`` (vertex ids in matrix order) and the ids of its labels."""
        labels = self._labels(check_int(rings, "rings", minimum=1, maximum=MAX_RINGS + 1))
        check_memory(len(labels) * 2048, f"the tagged {rings}-ring mesh of a vertex with {self.faces} faces")
        ids = {lab: i for i, lab in enumerate(labels)}

        def vid(s, u, v):
            return ids[self._canonical(s, u, v)]

        lat = self.lattice
        faces = []
        for s in range(self.faces):
            for u in range(rings):
                for v in range(rings):  # the lattice's faces of the cell at (u, v) that lie within the rings
                    cell = lat.cell_faces((u, v), (u + 1, v), (u + 1, v + 1), (u, v + 1))
                    faces += [tuple(vid(s, *p) for p in face) for face in cell if all(lat.ring_of(*p) <= rings for p in face)]
        mesh = self.lattice.mesh(tuple(faces), {i: (0,) for i in range(len(labels))})
        rays = {r: [frozenset((vid(r, u, 0), vid(r, u + 1, 0))) for u in range(rings)] for r in self.sharp_rays()}
        boundary = {e for r in rays for e in rays[r] if not self.closed and r in (0, self.faces)}
        sharp = {e: self.sharpness for r in rays for e in rays[r] if e not in boundary}
        tagged = TaggedMesh(mesh, {}, {}, frozenset(), {})
        cut = tagged.boundary_edges(all_edges=True) - boundary
        return TaggedMesh(mesh, sharp, {0: math.inf} if self.corner else {}, cut,
                          {} if self.angle is None else {0: self.angle}), ids


def _corner(cls, k: int, lattice: Lattice | str, angle=None) -> SharpVertex:
    """A boundary vertex with ``k`` faces tagged as a corner (angle for BLZ's rules, default ``None``: ``pi``)."""
    return cls(lattice, (k,), False, True, math.inf, angle)


# The constructor ``SharpVertex.corner(k, lattice)`` shares its name with the field ``corner``: set on the class
# after the dataclass has taken the field's default, it is what the class gives, while an instance's own value (in
# its __dict__, ahead of a classmethod) is what the instance gives.
SharpVertex.corner = classmethod(_corner)


def _refined_point(vertex: SharpVertex, stencils, ids: dict, face_of: dict, label) -> dict:
    """The stencil of the refined point at ``label``: the point at lattice position ``(u/2, v/2)`` of the old mesh."""
    s, u, v = label
    if not vertex.closed and s == vertex.faces:  # the last ray of an open fan, seen from the last sector
        s, u, v = s - 1, 0, u

    def old(a, b):
        return ids[vertex._canonical(s, a, b)]

    # the lattice names the new point (a vertex, edge or face point) at the fine lattice point (u, v)
    step = SimpleNamespace(vertex_point=stencils.vertex, edge_point=stencils.edge, face_point=stencils.face)
    return vertex.lattice.refined_point(step, old, u, v, face_of)


def _check_vertex(vertex) -> SharpVertex:
    return check_type(vertex, SharpVertex, "vertex", hint="SharpVertex.boundary(k, lattice), .crease(k1, k2, lattice), ...")


def _check_level(level) -> int:
    return check_levels(level, "level", maximum=MAX_LEVEL)


def _check_options(options) -> SharpOptions:
    return check_type(SharpOptions() if options is None else options, SharpOptions, "options")


def _sparse_rows(scheme, vertex, rings, level, options, limit: int = MAX_DENSE_FACES) -> tuple[dict, ...]:
    scheme, vertex, rings = check_scheme(scheme), _check_vertex(vertex), check_rings(rings)
    level, options = _check_level(level), _check_options(options)
    if vertex.lattice is not scheme.lattice:
        raise InvalidMeshError(f"scheme {scheme.name!r} lives on {scheme.lattice} meshes, the vertex on {vertex.lattice}")
    if vertex.faces > limit:
        dense = "(dense and exact)" if limit == MAX_DENSE_FACES else "(sparse rows)"
        raise InvalidInputError(f"vertex: {vertex.faces} faces; its exact matrix is built for at most {limit} faces {dense}")
    vertex = vertex.at_level(level)
    # one ring more than is read: whether a vertex of the K-ring is a sharp vertex (BLZ's rules ask) and its
    # rule's inputs are decided by its whole fan, which the (K + 1)-ring mesh holds
    tagged, ids = vertex.tagged_mesh(rings + 1)
    stencils = sharp_stencils(tagged, scheme, options)
    face_of = {frozenset(f): i for i, f in enumerate(tagged.mesh.faces)}
    labels = vertex.ring_labels(rings)
    rows = []
    for label in labels:
        row = _refined_point(vertex, stencils, ids, face_of, label)
        if any(c >= len(labels) for c in row):  # pragma: no cover - the K-ring depends on the K-ring only
            raise InternalError(f"the refined point {label} depends on a point outside the {rings}-ring")
        rows.append(row)
    return tuple(rows)


@cached(maxsize=256, scheme=check_scheme, vertex=_check_vertex, rings=check_rings, level=_check_level,
        options=_check_options)
def sharp_subdivision_matrix(scheme, vertex: SharpVertex, *, rings: int = 1, level: int = 0,
                             options: SharpOptions | None = None) -> sp.ImmutableMatrix:
    """The exact one-step subdivision matrix of the ``rings``-ring of ``vertex`` under ``scheme`` (sympy).

    Built by one exact refinement of the tagged ring mesh with the rules of the whole mesh (the scheme's
    smooth rules at every vertex's own valence, its :class:`~symdecomp.schemes.sharp.SharpRules` at sharp
    features, OpenSubdiv's semantics: :mod:`symdecomp.schemes.tagged_refinement`), at refinement ``level``
    (semi-sharp sharpness decayed ``level`` times). Rows and columns in :meth:`SharpVertex.ring_labels` order;
    ``options``: boundary interpolation and creasing method (:class:`~symdecomp.schemes.sharp.SharpOptions`).
    """
    rows = _sparse_rows(scheme, vertex, rings, level, options)
    size = len(rows)
    return sp.ImmutableMatrix(size, size, lambda r, c: to_sympy(rows[r].get(c, 0)))


def sharp_matrix_rows(scheme, vertex: SharpVertex, *, rings: int = 1, level: int = 0,
                      options: SharpOptions | None = None) -> tuple[dict, ...]:
    """:func:`sharp_subdivision_matrix`'s rows, sparse: ``{column: exact weight}`` per row (only the entries that are read).

    Sparse, so built for up to :data:`MAX_SECTOR_FACES` faces (the refinement is O(faces)), where the dense matrix stops at
    :data:`MAX_DENSE_FACES`."""
    return _sparse_rows(scheme, vertex, rings, level, options, MAX_SECTOR_FACES)


def exact_sharp_matrix(scheme, vertex: SharpVertex, *, rings: int = 1, level: int = 0,
                       options: SharpOptions | None = None) -> flint.fmpq_mat:
    """:func:`sharp_subdivision_matrix` as a FLINT rational matrix (for schemes whose weights are rational there)."""
    rows = _sparse_rows(scheme, vertex, rings, level, options)
    size = len(rows)
    out = flint.fmpq_mat(size, size)
    for r, row in enumerate(rows):
        for c, w in row.items():
            w = to_sympy(w)
            if not w.is_Rational:
                raise NotApplicableError(f"scheme {scheme.name!r}: weight {w} of the sharp matrix is not rational; "
                                         "use sharp_subdivision_matrix")
            out[r, c] = flint.fmpq(int(w.p), int(w.q))
    return out
