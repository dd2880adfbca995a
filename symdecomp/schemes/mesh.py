"""Local quad meshes and their exact refinement by a scheme's rules (whole-mesh view of Eq. 14-16).

The 1-ring rules of a :class:`~symdecomp.schemes.scheme.Scheme` say how the 1-ring of *one* vertex
moves. On a whole quad mesh every vertex is the centre of its own 1-ring, so the three rules
must be readable as rules *of the mesh*: one point per face, per edge and per vertex. This
module derives those mesh rules from the scheme (:func:`mesh_rules`) and refuses schemes whose
1-ring rules cannot be read that way (a face point that depends on which corner is called
``O``, an edge point that depends on which end is called ``O``):

* face rule (Eq. 15) -> face point: the four corners of the face, which consistency forces to
  carry equal weights ``1/4`` (the centroid);
* edge rule (Eq. 14) -> edge point of an edge ``(u, v)`` with its two faces: a weight on each
  end and a weight on each of the four other corners of the two faces. For Catmull-Clark this
  is ``3/8, 3/8`` and ``1/16`` each, which is the familiar ``(v_1 + v_2 + f_1 + f_2)/4`` with
  ``f_1, f_2`` the face points;
* vertex rule (Eq. 16) -> vertex point of a vertex of valence ``m``: the scheme's vertex rule
  at ``n = m`` (so tuned weights ``alpha(n), beta(n)`` apply at every vertex with its own
  valence). For standard Catmull-Clark this is ``(Q + 2R + (m - 3)S)/m``.

A mesh may have a boundary. Refinement only computes points whose rules see all their
inputs (interior vertices, edges with two faces, all faces) and keeps the new faces whose four
corners were computed, so everything in the refined mesh is exact: it is what refining an
arbitrarily large mesh containing this one would give there. Refining the ``R``-ring mesh
around a vertex gives the ``2R - 1``-ring mesh around it; in particular (``R = 1``) the new
1-ring of a vertex depends only on its old 1-ring.

Values at vertices are tuples of coordinates (any length; scalar fields are 1-tuples) of
``fractions.Fraction``, sympy expressions or floats; rational weights are applied as
``Fraction`` so exact refinement of rational data stays fast.

>>> from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
>>> mesh = ring_mesh(5, rings=1, values=lambda s, u, v: (u + v,))
>>> _, ring = central_rings(mesh, catmull_clark(), center=0, levels=1)
>>> [x[0] for x in ring][:3]   # O: 5 (3/50) 1 + 5 (1/100) 2;  a_0: (3/8)(0 + 1) + (1 + 1 + 2 + 2)/16
[Fraction(2, 5), Fraction(3, 4), Fraction(3, 4)]
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType

import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic
from symdecomp.errors import InvalidInputError, InvalidSchemeError
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = [
    "InvalidMeshError", "QuadMesh", "MeshRules", "Refinement", "mesh_rules", "ring_mesh", "ring_mesh_labels",
    "cube_mesh", "refine", "point_stencils", "refinement_matrix", "central_rings",
]


class InvalidMeshError(InvalidInputError):
    """A mesh is not a consistently oriented quad mesh, or a vertex asked about is not in it."""


def _as_weight(w: sp.Expr):
    if isinstance(w, (Fraction, Cyclotomic)):  # already exact numbers (a caller's own arithmetic)
        return w
    w = sp.sympify(w, strict=True)
    if w.is_Rational:
        return Fraction(int(w.p), int(w.q))
    return w


# --------------------------------------------------------------------------------------------
# mesh rules derived from the 1-ring rules


@dataclass(frozen=True)
class MeshRules:
    """The face, edge and vertex point rules of a scheme on a whole quad mesh.

    Derived from the 1-ring rules by :func:`mesh_rules`; weights are sympy expressions.
    """

    #: The scheme the rules come from.
    scheme: Scheme
    #: Weight of each of the four corners in a face point (1/4 for every affine face rule).
    face_corner: sp.Expr
    #: Weight of each end of an edge in its edge point.
    edge_end: sp.Expr
    #: Weight of each of the other four corners of the two faces of the edge in its edge point.
    edge_side: sp.Expr

    def vertex_weights(self, valence: int) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """``(center, each edge neighbour, each face neighbour)`` of the vertex point at this valence."""
        v = self.scheme.vertex_rule
        values = (w.subs(N, valence) for w in (v.center, v.each_a, v.each_b))
        return tuple(x if x.is_Rational else sp.simplify(x) for x in values)


def mesh_rules(scheme: Scheme) -> MeshRules:
    """Read the scheme's 1-ring rules as face/edge/vertex point rules of a whole quad mesh.

    Raises :class:`~symdecomp.errors.InvalidSchemeError` when that is impossible: a face or
    edge rule that reaches beyond its face or its two faces, that depends on the valence, or
    that would give a different point when computed from the 1-ring of another corner.

    >>> from symdecomp.schemes.scheme import catmull_clark
    >>> r = mesh_rules(catmull_clark())
    >>> r.face_corner, r.edge_end, r.edge_side
    (1/4, 3/8, 1/16)
    >>> r.vertex_weights(3)
    (5/12, 1/6, 1/36)
    """
    face, edge = scheme.face_rule, scheme.edge_rule
    for label, rule in (("face rule", face), ("edge rule", edge)):
        weights = [rule.center] + [w for _, w in rule.a + rule.b]
        if any(sp.sympify(w, strict=True).has(N) for w in weights):
            raise InvalidSchemeError(
                f"scheme {scheme.name!r}: its {label} depends on the valence n, so it is not a rule of the mesh "
                "(an edge or face is in the 1-rings of vertices of different valences)"
            )
    fa, fb = dict(face.a), dict(face.b)
    if set(fa) - {0, 1} or set(fb) - {0}:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the face rule reaches beyond the face (O, a_i, b_i, a_{{i+1}})")
    corners = [face.center, fa.get(0, 0), fb.get(0, 0), fa.get(1, 0)]
    if any(sp.simplify(c - corners[0]) != 0 for c in corners[1:]):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: face rule weights {corners} on (O, a_i, b_i, a_{{i+1}}) differ, so the face "
            "point would depend on which corner is the centre; it is not a rule of the mesh"
        )
    ea, eb = dict(edge.a), dict(edge.b)
    if set(ea) - {-1, 0, 1} or set(eb) - {-1, 0}:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the edge rule reaches beyond the two faces of the edge (O, a_i)")
    z = sp.Integer(0)
    # Seen from a_i (as the centre of its own 1-ring) the roles swap: O <-> a_i,
    # a_{i+1} <-> b_i, a_{i-1} <-> b_{i-1}; the point is the same only if these weights agree.
    pairs = [(edge.center, ea.get(0, z)), (ea.get(-1, z), eb.get(0, z)), (ea.get(1, z), eb.get(-1, z))]
    if any(sp.simplify(p - q) != 0 for p, q in pairs):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the edge rule gives a different point when computed from the 1-ring of "
            "the other end of the edge; it is not a rule of the mesh"
        )
    if sp.simplify(ea.get(-1, z) - ea.get(1, z)) != 0:
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the edge rule is not mirror symmetric (a_{{i-1}} and a_{{i+1}} weigh differently)"
        )
    # With the mirror symmetry the four side corners (a_{i-1}, b_{i-1}, b_i, a_{i+1}) weigh the same.
    return MeshRules(scheme, sp.sympify(face.center, strict=True), sp.sympify(edge.center, strict=True), sp.sympify(ea.get(1, z), strict=True))


# --------------------------------------------------------------------------------------------
# the mesh


def _set_topology(mesh, corners: int, shape: str) -> None:
    """Validate ``mesh.faces`` (``corners``-gons, consistently oriented, every corner valued) and set
    ``faces``, ``values``, ``_directed`` (directed edge -> face) and ``_incident`` (vertex -> faces)."""
    faces = tuple(tuple(int(v) for v in f) for f in mesh.faces)
    for f in faces:
        if len(f) != corners or len(set(f)) != corners:
            raise InvalidMeshError(f"face {f} is not {shape}")
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


@dataclass(frozen=True)
class QuadMesh:
    """A consistently oriented quad mesh (possibly with boundary) with values at its vertices."""

    #: The faces, each a 4-tuple of vertex ids in counter-clockwise order.
    faces: tuple[tuple[int, int, int, int], ...]
    #: Vertex id -> value (a tuple of coordinates).
    values: Mapping[int, tuple]

    def __post_init__(self):
        _set_topology(self, 4, "a quad with four distinct vertices")

    # -- topology ------------------------------------------------------------------------------

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
        for fi in self._incident[v]:
            f = self.faces[fi]
            k = f.index(v)
            if (f[(k + 1) % 4], v) not in self._directed or (v, f[(k + 3) % 4]) not in self._directed:
                return False
        return True

    def one_ring(self, v: int, start: int | None = None) -> tuple[int, tuple[int, ...], tuple[int, ...]]:
        """``(v, (a_0..a_{m-1}), (b_0..b_{m-1}))``: the ordered 1-ring of an interior vertex.

        ``a_i`` are the edge neighbours counter-clockwise starting at ``start`` (default: the
        smallest id), ``b_i`` the vertex of the face ``(v, a_i, b_i, a_{i+1})`` opposite ``v``.
        """
        if not self.is_interior(v):
            raise InvalidMeshError(f"vertex {v} is on the boundary of the mesh: its 1-ring is not closed")
        nxt = {}
        for fi in self._incident[v]:
            f = self.faces[fi]
            k = f.index(v)
            nxt[f[(k + 1) % 4]] = (f[(k + 2) % 4], f[(k + 3) % 4])
        if start is None:
            start = min(nxt)
        if start not in nxt:
            raise InvalidMeshError(f"vertex {start} is not an edge neighbour of {v}")
        a, b = [start], []
        while True:
            bi, an = nxt[a[-1]]
            b.append(bi)
            if an == start:
                break
            a.append(an)
            if len(a) > len(nxt):  # pragma: no cover - guarded by the orientation check
                raise InvalidMeshError(f"the faces around {v} do not form one fan")
        if len(a) != len(nxt):
            raise InvalidMeshError(f"the faces around {v} form more than one fan (non-manifold vertex)")
        return v, tuple(a), tuple(b)

    def valence(self, v: int) -> int:
        """Number of faces at ``v`` (its valence when it is interior)."""
        return len(self.faces_of(v))

    def one_ring_values(self, v: int, start: int | None = None) -> tuple:
        """Values at ``(v, a_0..a_{m-1}, b_0..b_{m-1})``: the order of the subdivision matrix."""
        o, a, b = self.one_ring(v, start)
        return tuple(self.values[x] for x in (o,) + a + b)

    def neighbourhood(self, v: int, rings: int) -> QuadMesh:
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
        return QuadMesh(faces, {x: self.values[x] for x in used})

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

    def with_values(self, values: Mapping[int, tuple]) -> QuadMesh:
        """The same faces with other values."""
        return QuadMesh(self.faces, values)


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
    n = check_valence(n)
    if isinstance(rings, bool) or not isinstance(rings, numbers.Integral) or rings < 1:
        raise InvalidMeshError(f"rings must be a positive integer, got {rings!r}")
    labels = ring_mesh_labels(n, rings)
    ident = {lab: i for i, lab in enumerate(labels)}

    def vid(s, u, v):
        s %= n
        if u == 0 and v == 0:
            return 0
        if u == 0:
            return ident[((s + 1) % n, v, 0)]
        return ident[(s, u, v)]

    faces = []
    for s in range(n):
        for u in range(rings):
            for v in range(rings):
                faces.append((vid(s, u, v), vid(s, u + 1, v), vid(s, u + 1, v + 1), vid(s, u, v + 1)))
    vals = {}
    for i, (s, u, v) in enumerate(labels):
        raw = values(s, u, v) if values is not None else (s, u, v)
        vals[i] = tuple(raw) if isinstance(raw, (tuple, list)) else (raw,)
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
        vals[i] = tuple(raw) if isinstance(raw, (tuple, list)) else (raw,)
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


# --------------------------------------------------------------------------------------------
# refinement


@dataclass(frozen=True)
class Refinement:
    """One refinement step: the refined mesh and where its vertices come from."""

    #: The refined mesh (only exact points: see the module docstring).
    mesh: QuadMesh
    #: Old vertex id -> id of its vertex point (interior vertices only).
    vertex_point: Mapping[int, int]
    #: ``frozenset({u, v})`` -> id of the edge point (edges with two faces only).
    edge_point: Mapping[frozenset, int]
    #: Old face index -> id of its face point.
    face_point: Mapping[int, int]


def _combine(terms: Iterable[tuple[object, tuple]]) -> tuple:
    terms = list(terms)
    if len({len(val) for _, val in terms}) != 1:
        raise InvalidMeshError("vertex values have different lengths")
    return tuple(sum((w * val[k] for w, val in terms[1:]), terms[0][0] * terms[0][1][k]) for k in range(len(terms[0][1])))


def point_stencils(mesh: QuadMesh, rules: MeshRules, vertex_weights: Callable | None = None) -> tuple[dict, dict, dict]:
    """``(face, edge, vertex)`` stencils ``{key: ((weight, old vertex id), ...)}`` of the refined points
    (keys: face index, ``frozenset({u, v})`` of an edge with two faces, interior vertex id);
    ``vertex_weights(valence)`` overrides the rules' vertex weights (the ring matrices' symbolic centre)."""
    fc, ee, es = (_as_weight(w) for w in (rules.face_corner, rules.edge_end, rules.edge_side))
    face = {fi: tuple((fc, x) for x in f) for fi, f in enumerate(mesh.faces)}
    edge = {}
    for (u, v), left in mesh._directed.items():
        key = frozenset((u, v))
        right = mesh._directed.get((v, u))
        if key in edge or right is None:
            continue
        fl, fr = mesh.faces[left], mesh.faces[right]
        kl, kr = fl.index(u), fr.index(v)
        # left face (u, v, x, y), right face (v, u, p, q): the ends and the four side corners.
        sides = (fl[(kl + 2) % 4], fl[(kl + 3) % 4], fr[(kr + 2) % 4], fr[(kr + 3) % 4])
        edge[key] = ((ee, u), (ee, v)) + tuple((es, x) for x in sides)
    vertex, cache = {}, {}
    for v in (v for v in mesh.vertices() if mesh.is_interior(v)):
        _, a, b = mesh.one_ring(v)
        if len(a) not in cache:
            cache[len(a)] = tuple(_as_weight(w) for w in (vertex_weights or rules.vertex_weights)(len(a)))
        wc, wa, wb = cache[len(a)]
        vertex[v] = ((wc, v),) + tuple((wa, x) for x in a) + tuple((wb, x) for x in b)
    return face, edge, vertex


def refinement_matrix(mesh: QuadMesh, scheme_or_rules: Scheme | MeshRules, columns: Sequence[int], rows: Sequence) -> list[dict]:
    """The exact matrix, sparse rows ``{column index: weight}``, from the values at ``columns`` (old ids)
    to the refined points ``rows``, each named by a vertex id, a 2-set of ids (edge) or a face's 4
    corners. Raises :class:`InvalidMeshError` for a point outside ``mesh`` or depending on a vertex
    outside ``columns``."""
    rules = scheme_or_rules if isinstance(scheme_or_rules, MeshRules) else mesh_rules(scheme_or_rules)
    face, edge, vertex = point_stencils(mesh, rules)
    face_by_corners = {frozenset(f): fi for fi, f in enumerate(mesh.faces)}
    col = {v: k for k, v in enumerate(columns)}
    out = []
    for r in rows:
        key = frozenset(r) if isinstance(r, (set, frozenset, tuple, list)) else frozenset((r,))
        table = {1: vertex, 2: edge, 4: face}.get(len(key))
        index = next(iter(key)) if len(key) == 1 else face_by_corners.get(key) if len(key) == 4 else key
        if table is None or index not in table:
            raise InvalidMeshError(f"refined point of {sorted(key)} is not computable in this mesh")
        row: dict = {}
        for w, x in table[index]:
            if x not in col:
                raise InvalidMeshError(f"refined point of {sorted(key)} depends on vertex {x}, outside the given columns")
            row[col[x]] = row.get(col[x], 0) + w
        out.append(row)
    return out


def _child_faces(mesh: QuadMesh, vertex_point: dict, edge_point: dict, face_point: dict) -> list[tuple[int, ...]]:
    """The four children of each face (vertex, edge, face and edge point), where all four exist."""
    new_faces = []
    for fi, f in enumerate(mesh.faces):
        for k in range(4):
            corner, nxt, prv = f[k], f[(k + 1) % 4], f[(k + 3) % 4]
            quad = (vertex_point.get(corner), edge_point.get(frozenset((corner, nxt))), face_point[fi], edge_point.get(frozenset((prv, corner))))
            if None not in quad:
                new_faces.append(quad)
    return new_faces


def refine(mesh: QuadMesh, scheme_or_rules: Scheme | MeshRules, *, vertex_weights: Callable | None = None) -> Refinement:
    """One exact refinement step of ``mesh`` by the scheme's mesh rules (:func:`mesh_rules`).

    Points whose rule needs something outside the mesh (boundary vertices and edges) are not
    computed, and new faces with such a corner are dropped. ``vertex_weights``: :func:`point_stencils`.
    """
    rules = scheme_or_rules if isinstance(scheme_or_rules, MeshRules) else mesh_rules(scheme_or_rules)
    face, edge, vertex = point_stencils(mesh, rules, vertex_weights)
    vals = mesh.values
    new_values: dict[int, tuple] = {}
    counter = iter(range(10**12))
    face_point, edge_point, vertex_point = {}, {}, {}
    for table, ids in ((face, face_point), (edge, edge_point), (vertex, vertex_point)):
        for key, stencil in table.items():
            i = next(counter)
            ids[key] = i
            new_values[i] = _combine((w, vals[x]) for w, x in stencil)
    new_faces = _child_faces(mesh, vertex_point, edge_point, face_point)
    used = {x for f in new_faces for x in f}
    refined = QuadMesh(tuple(new_faces), {i: val for i, val in new_values.items() if i in used})
    kept = (MappingProxyType({k: i for k, i in m.items() if i in used}) for m in (vertex_point, edge_point, face_point))
    return Refinement(refined, *kept)


def central_rings(
    mesh: QuadMesh, scheme: Scheme, center: int, levels: int, *, start: int | None = None, keep_rings: int | None = 1
) -> tuple[tuple, ...]:
    """The 1-ring values ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` of ``center`` at levels ``0..levels``.

    ``a_0`` at level ``k + 1`` is the edge point of ``(O, a_0)`` at level ``k``, so the order is
    the one :func:`~symdecomp.schemes.scheme.subdivision_matrix` uses at every level. After each step
    the mesh is cut down to ``keep_rings`` face-rings around the centre (``None``: keep all).

    >>> from symdecomp.schemes.scheme import catmull_clark
    >>> rings = central_rings(ring_mesh(4, 1, lambda s, u, v: (u*u + v*v,)), catmull_clark(), 0, 2)
    >>> [r[0] for r in rings]
    [(0,), (Fraction(1, 2),), (Fraction(5, 8),)]
    """
    if isinstance(levels, bool) or not isinstance(levels, numbers.Integral) or levels < 0:
        raise InvalidMeshError(f"levels must be a non-negative integer, got {levels!r}")
    rules = mesh_rules(scheme)
    o, a, _ = mesh.one_ring(center, start)
    first = a[0]
    out = [mesh.one_ring_values(o, first)]
    for _ in range(levels):
        step = refine(mesh if keep_rings is None else mesh.neighbourhood(o, keep_rings), rules)
        mesh = step.mesh
        o, first = step.vertex_point[o], step.edge_point[frozenset((o, first))]
        out.append(mesh.one_ring_values(o, first))
    return tuple(out)
