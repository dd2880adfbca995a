"""Local triangle meshes and their exact refinement by a triangle scheme's rules (Loop-type).

The triangle counterpart of :mod:`symdecomp.schemes.mesh`. A triangle scheme
(``Scheme.lattice`` :data:`~symdecomp.schemes.lattice.TRIANGLE`, e.g. :func:`~symdecomp.schemes.loop.loop`) moves the 1-ring
``(O, a_0..a_{n-1})`` of a vertex by an edge rule and a vertex rule; read as rules *of the
mesh* (:func:`triangle_mesh_rules`) they give

* the edge point of an edge ``(u, v)`` with its two triangles ``(u, v, x)`` and ``(v, u, y)``:
  ``edge_end`` on ``u`` and ``v``, ``edge_side`` on ``x`` and ``y`` (Loop: 3/8 and 1/8);
* the vertex point of a vertex of valence ``m``: the scheme's vertex rule at ``n = m``
  (Loop: ``1 - m beta(m)`` on the vertex, ``beta(m)`` on each neighbour).

As for quads, refinement computes only the points whose rules see all their inputs and keeps
the new triangles whose three corners were computed, so everything it returns is exact.

>>> from symdecomp.schemes.loop import loop
>>> mesh = triangle_ring_mesh(6, rings=1, values=lambda s, u, v: (u + v,))
>>> step = refine_triangles(mesh, loop())
>>> step.mesh.values[step.vertex_point[0]], step.mesh.values[step.edge_point[frozenset((0, 1))]]
((Fraction(3, 8),), (Fraction(5, 8),))
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType

import sympy as sp

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.lattice import TRIANGLE
from symdecomp.schemes.mesh import InvalidMeshError, _as_weight, _combine, _set_topology
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = [
    "TriangleMesh",
    "TriangleMeshRules",
    "TriangleRefinement",
    "triangle_mesh_rules",
    "triangle_ring_mesh",
    "triangle_ring_labels",
    "refine_triangles",
]


@dataclass(frozen=True)
class TriangleMeshRules:
    """Edge and vertex point rules of a triangle scheme on a whole mesh (weights are sympy)."""

    scheme: Scheme
    #: Weight of each end of an edge in its edge point.
    edge_end: sp.Expr
    #: Weight of each of the two vertices opposite the edge.
    edge_side: sp.Expr

    def vertex_weights(self, valence: int) -> tuple[sp.Expr, sp.Expr]:
        """``(center, each neighbour)`` of the vertex point at this valence (exact sympy values)."""
        v = self.scheme.vertex_rule
        return tuple(w.subs(N, valence) for w in (v.center, v.each_a))


def triangle_mesh_rules(scheme: Scheme) -> TriangleMeshRules:
    """Read a triangle scheme's 1-ring rules as edge/vertex point rules of a whole mesh.

    Raises :class:`~symdecomp.errors.InvalidSchemeError` when the edge rule depends on ``n``,
    reaches beyond the two triangles of its edge, or weighs the two ends (or the two opposite
    vertices) differently, so that the edge point would depend on which end is called ``O``.
    """
    if scheme.lattice is not TRIANGLE:
        raise InvalidSchemeError(f"scheme {scheme.name!r} lives on {scheme.lattice} meshes, not triangle meshes")
    edge = scheme.edge_rule
    ea = dict(edge.a)
    weights = [edge.center, *ea.values()]
    if any(sp.sympify(w, strict=True).has(N) for w in weights):
        raise InvalidSchemeError(f"scheme {scheme.name!r}: its edge rule depends on the valence n, so it is not a rule of the mesh")
    if set(ea) - {-1, 0, 1}:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the edge rule reaches beyond the two triangles of the edge (O, a_i)")
    z = sp.Integer(0)
    if sp.simplify(edge.center - ea.get(0, z)) != 0 or sp.simplify(ea.get(-1, z) - ea.get(1, z)) != 0:
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the edge rule weighs the two ends (or the two opposite vertices) differently, "
            "so it is not a rule of the mesh"
        )
    return TriangleMeshRules(scheme, sp.sympify(edge.center, strict=True), sp.sympify(ea.get(1, z), strict=True))


@dataclass(frozen=True)
class TriangleMesh:
    """A consistently oriented triangle mesh (possibly with boundary) with values at its vertices."""

    #: The faces, each a 3-tuple of vertex ids in counter-clockwise order.
    faces: tuple[tuple[int, int, int], ...]
    #: Vertex id -> value (a tuple of coordinates).
    values: Mapping[int, tuple]

    def __post_init__(self):
        _set_topology(self, 3, "a triangle with three distinct vertices")

    def vertices(self) -> tuple[int, ...]:
        return tuple(sorted(self._incident))

    def is_interior(self, v: int) -> bool:
        """Whether every edge at ``v`` has two triangles."""
        if v not in self._incident:
            raise InvalidMeshError(f"vertex {v!r} is not a corner of any face of the mesh")
        for fi in self._incident[v]:
            f = self.faces[fi]
            k = f.index(v)
            if (f[(k + 1) % 3], v) not in self._directed:
                return False
        return True

    def one_ring(self, v: int, start: int | None = None) -> tuple[int, tuple[int, ...]]:
        """``(v, (a_0..a_{m-1}))``: the neighbours of an interior vertex, counter-clockwise from ``start``."""
        if not self.is_interior(v):
            raise InvalidMeshError(f"vertex {v} is on the boundary of the mesh: its 1-ring is not closed")
        nxt = {}
        for fi in self._incident[v]:
            f = self.faces[fi]
            k = f.index(v)
            nxt[f[(k + 1) % 3]] = f[(k + 2) % 3]
        start = min(nxt) if start is None else start
        if start not in nxt:
            raise InvalidMeshError(f"vertex {start} is not a neighbour of {v}")
        ring = [start]
        while nxt[ring[-1]] != start:
            ring.append(nxt[ring[-1]])
            if len(ring) > len(nxt):  # pragma: no cover - guarded by the orientation check
                raise InvalidMeshError(f"the faces around {v} do not form one fan")
        if len(ring) != len(nxt):
            raise InvalidMeshError(f"the faces around {v} form more than one fan (non-manifold vertex)")
        return v, tuple(ring)


@dataclass(frozen=True)
class TriangleRefinement:
    """One refinement step: the refined mesh and where its vertices come from."""

    mesh: TriangleMesh
    #: Old vertex id -> id of its vertex point (interior vertices only).
    vertex_point: Mapping[int, int]
    #: ``frozenset({u, v})`` -> id of the edge point (edges with two faces only).
    edge_point: Mapping[frozenset, int]


def refine_triangles(mesh: TriangleMesh, scheme_or_rules, *, vertex_weights: Callable | None = None) -> TriangleRefinement:
    """One exact refinement step of ``mesh`` by the scheme's mesh rules (1-to-4 split).

    ``vertex_weights(valence)`` overrides the rules' vertex weights (``(center, each
    neighbour)``); :mod:`symdecomp.schemes.rings` uses it to keep the centre's weights symbolic.
    """
    rules = scheme_or_rules if isinstance(scheme_or_rules, TriangleMeshRules) else triangle_mesh_rules(scheme_or_rules)
    weights_at = vertex_weights or rules.vertex_weights
    ee, es = _as_weight(rules.edge_end), _as_weight(rules.edge_side)
    vals = mesh.values
    new_values: dict[int, tuple] = {}
    edge_point, vertex_point = {}, {}
    for (u, v), left in mesh._directed.items():
        key = frozenset((u, v))
        right = mesh._directed.get((v, u))
        if key in edge_point or right is None:
            continue
        x = next(c for c in mesh.faces[left] if c not in key)
        y = next(c for c in mesh.faces[right] if c not in key)
        edge_point[key] = len(new_values)
        new_values[len(new_values)] = _combine([(ee, vals[u]), (ee, vals[v]), (es, vals[x]), (es, vals[y])])
    cache: dict[int, tuple] = {}
    for v in mesh.vertices():
        if not mesh.is_interior(v):
            continue
        _, ring = mesh.one_ring(v)
        m = len(ring)
        if m not in cache:
            cache[m] = tuple(_as_weight(w) for w in weights_at(m))
        wc, wa = cache[m]
        vertex_point[v] = len(new_values)
        new_values[len(new_values)] = _combine([(wc, vals[v])] + [(wa, vals[x]) for x in ring])
    new_faces = []
    for f in mesh.faces:
        e = [edge_point.get(frozenset((f[k], f[(k + 1) % 3]))) for k in range(3)]
        for k in range(3):
            corner = (vertex_point.get(f[k]), e[k], e[(k + 2) % 3])
            if None not in corner:
                new_faces.append(corner)
        if None not in e:
            new_faces.append(tuple(e))
    used = {x for f in new_faces for x in f}
    refined = TriangleMesh(tuple(new_faces), {i: val for i, val in new_values.items() if i in used})
    return TriangleRefinement(
        refined,
        MappingProxyType({k: i for k, i in vertex_point.items() if i in used}),
        MappingProxyType({k: i for k, i in edge_point.items() if i in used}),
    )


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
    n = check_valence(n)
    if isinstance(rings, bool) or not isinstance(rings, numbers.Integral) or rings < 1:
        raise InvalidMeshError(f"rings must be a positive integer, got {rings!r}")
    labels = triangle_ring_labels(n, rings)
    ident = {lab: i for i, lab in enumerate(labels)}

    def vid(s, u, v):
        if u == 0 and v == 0:
            return 0
        return ident[((s + 1) % n, v, 0)] if u == 0 else ident[(s % n, u, v)]

    faces = []
    for s in range(n):
        for u in range(rings):
            for v in range(rings - u):
                faces.append((vid(s, u, v), vid(s, u + 1, v), vid(s, u, v + 1)))
                if u + v <= rings - 2:
                    faces.append((vid(s, u + 1, v), vid(s, u + 1, v + 1), vid(s, u, v + 1)))
    vals = {}
    for i, (s, u, v) in enumerate(labels):
        raw = values(s, u, v) if values is not None else (s, u, v)
        vals[i] = tuple(raw) if isinstance(raw, (tuple, list)) else (raw,)
    return TriangleMesh(tuple(faces), vals)
