"""Exact refinement of quad and triangle meshes by a scheme's rules (whole-mesh view of Eq. 14-16).

The 1-ring rules of a :class:`~symdecomp.schemes.scheme.Scheme` say how the 1-ring of *one* vertex moves. On a whole
quad mesh every vertex is the centre of its own 1-ring, so the three rules must be readable as rules *of the mesh*:
one point per face, per edge and per vertex. This module derives those mesh rules from the scheme (:func:`mesh_rules`)
and refuses schemes whose 1-ring rules cannot be read that way (a face point that depends on which corner is called
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

**Edge rules that depend on n** (the model, :class:`~symdecomp.schemes.scheme.Scheme`): an edge's point is
made by the edge rule read at the valence of its extraordinary end (the end whose valence is not the regular
one; the larger valence if both are extraordinary), and at the regular valence when both ends are regular
(:func:`edge_valence`). So in the neighbourhood of one extraordinary vertex of valence ``n`` the ``n`` edges
at the centre use the rule at ``n`` (the 1-ring stencils say so) and every other edge the regular rule; a
vertex on the mesh's border (its valence unknown) counts as regular. The face rule of a rule of the mesh is
the centroid (``1/4`` on each corner, forced), so it never depends on ``n``.

A mesh may have a boundary. Refinement only computes points whose rules see all their
inputs (interior vertices, edges with two faces, all faces) and keeps the new faces whose four
corners were computed, so everything in the refined mesh is exact: it is what refining an
arbitrarily large mesh containing this one would give there. Refining the ``R``-ring mesh
around a vertex gives the ``2R - 1``-ring mesh around it; in particular (``R = 1``) the new
1-ring of a vertex depends only on its old 1-ring.

Values at vertices (:mod:`symdecomp.schemes.mesh`) may be Fractions, sympy expressions or floats; rational weights are
applied as ``Fraction``, and their terms on rational zeros left out, so exact refinement of rational data stays fast.

**Triangles.** A triangle scheme (on :data:`~symdecomp.schemes.lattice.TRIANGLE`, e.g.
:func:`~symdecomp.schemes.loop.loop`) moves the 1-ring ``(O, a_0..a_{n-1})`` of a vertex by an edge
rule and a vertex rule; read as rules *of the mesh* (:func:`triangle_mesh_rules`) they give

* the edge point of an edge ``(u, v)`` with its two triangles ``(u, v, x)`` and ``(v, u, y)``:
  ``edge_end`` on ``u`` and ``v``, ``edge_side`` on ``x`` and ``y`` (Loop: 3/8 and 1/8);
* the vertex point of a vertex of valence ``m``: the scheme's vertex rule at ``n = m``
  (Loop: ``1 - m beta(m)`` on the vertex, ``beta(m)`` on each neighbour).

As for quads, refinement computes only the points whose rules see all their inputs and keeps
the new triangles whose three corners were computed (:func:`refine_triangles`).


>>> from symdecomp.schemes.mesh import ring_mesh, triangle_ring_mesh
>>> from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
>>> mesh = ring_mesh(5, rings=1, values=lambda s, u, v: (u + v,))
>>> _, ring = central_rings(mesh, catmull_clark(), center=0, levels=1)
>>> [x[0] for x in ring][:3]   # O: 5 (3/50) 1 + 5 (1/100) 2;  a_0: (3/8)(0 + 1) + (1 + 1 + 2 + 2)/16
[Fraction(2, 5), Fraction(3, 4), Fraction(3, 4)]
>>> from symdecomp.schemes.loop import loop
>>> step = refine_triangles(triangle_ring_mesh(6, rings=1, values=lambda s, u, v: (u + v,)), loop())
>>> step.mesh.values[step.vertex_point[0]], step.mesh.values[step.edge_point[frozenset((0, 1))]]
((Fraction(3, 8),), (Fraction(5, 8),))
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType
from typing import TYPE_CHECKING

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic
from symdecomp.algebra.numbers import to_fraction
from symdecomp.errors import InvalidSchemeError
from symdecomp.expressions import identically_zero
from symdecomp.schemes.mesh import InvalidMeshError, QuadMesh, TriangleMesh
from symdecomp.symbols import n as N
from symdecomp.validate import check_levels, check_memory

if TYPE_CHECKING:  # the lattice objects (imported by the scheme) call this module's refinement
    from symdecomp.schemes.scheme import Scheme

__all__ = [
    "MeshRules", "Refinement", "mesh_rules", "edge_centre", "refine", "point_stencils", "refinement_matrix", "central_rings",
    "TriangleMeshRules", "TriangleRefinement", "triangle_mesh_rules", "refine_triangles",
]

#: Most refinement levels :func:`central_rings` follows (exact values grow with every level).
MAX_LEVELS = 64


def _as_weight(w: sp.Expr):
    if isinstance(w, (Fraction, Cyclotomic, flint.fmpq)):  # already exact numbers (a caller's own arithmetic)
        return w
    w = sp.sympify(w, strict=True)
    if w.is_Rational:
        return to_fraction(w)
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
    #: The edge rule read from its end ``O`` (expressions in ``n``): the weight on ``O``, on the other end, on each of
    #: the two side corners next to ``O`` (``a_{i-1}``, ``a_{i+1}``) and on each next to the other end (``b_{i-1}``, ``b_i``).
    #: The four agree with ``edge_end, edge_end, edge_side, edge_side`` at the regular valence (a rule of the mesh there).
    oriented: tuple[sp.Expr, ...] = ()

    def vertex_weights(self, valence: int) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """``(center, each edge neighbour, each face neighbour)`` of the vertex point at this valence."""
        v = self.scheme.vertex_rule
        values = (w.subs(N, valence) for w in (v.center, v.each_a, v.each_b))
        return tuple(x if x.is_Rational else sp.simplify(x) for x in values)

    def edge_weights(self, valence: int) -> tuple[sp.Expr, ...]:
        """:attr:`oriented` at this valence: the edge rule of an edge whose end ``O`` has this valence (the model)."""
        return _oriented_at(self.oriented, valence)

    @property
    def depends_on_valence(self) -> bool:
        """Whether the edge rule's weights depend on ``n`` (then each edge reads them at its end ``O``'s valence)."""
        return any(sp.sympify(w, strict=True).has(N) for w in self.oriented)


def edge_centre(valence_u: int, valence_v: int, regular: int) -> int:
    """Which end of an edge is its ``O`` (``0``: the first, ``1``: the second) under the model (module docstring): the
    extraordinary end, the one of larger valence if both are; ``0`` if both are regular (the rule is symmetric there)."""
    if valence_u == valence_v or valence_v == regular:
        return 0
    return 1 if valence_u == regular or valence_v > valence_u else 0


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
    from symdecomp.schemes.scheme import check_scheme  # the scheme module imports this one (lattices)

    check_scheme(scheme)
    face, edge = scheme.face_rule, scheme.edge_rule
    fa, fb = dict(face.a), dict(face.b)
    if set(fa) - {0, 1} or set(fb) - {0}:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the face rule reaches beyond the face (O, a_i, b_i, a_{{i+1}})")
    corners = [face.center, fa.get(0, 0), fb.get(0, 0), fa.get(1, 0)]
    if any(not identically_zero(c - corners[0]) for c in corners[1:]):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: face rule weights {corners} on (O, a_i, b_i, a_{{i+1}}) differ, so the face "
            "point would depend on which corner is the centre; it is not a rule of the mesh"
        )
    ea, eb = dict(edge.a), dict(edge.b)
    if set(ea) - {-1, 0, 1} or set(eb) - {-1, 0}:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the edge rule reaches beyond the two faces of the edge (O, a_i)")
    z = sp.Integer(0)
    # Seen from a_i (as the centre of its own 1-ring) the roles swap: O <-> a_i,
    # a_{i+1} <-> b_i, a_{i-1} <-> b_{i-1}; the point is the same only if these weights agree. The model asks it of the
    # rule at the regular valence (edges between regular vertices); an edge at an extraordinary vertex reads it from there.
    regular = {N: scheme.lattice.regular_valence}
    pairs = [(edge.center, ea.get(0, z)), (ea.get(-1, z), eb.get(0, z)), (ea.get(1, z), eb.get(-1, z))]
    if any(not identically_zero((p - q).subs(regular)) for p, q in pairs):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the edge rule gives a different point when computed from the 1-ring of "
            "the other end of the edge; it is not a rule of the mesh"
        )
    if not identically_zero(ea.get(-1, z) - ea.get(1, z)) or not identically_zero(eb.get(-1, z) - eb.get(0, z)):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the edge rule is not mirror symmetric (a_{{i-1}} and a_{{i+1}} weigh differently)"
        )
    # With the mirror symmetry the four side corners (a_{i-1}, b_{i-1}, b_i, a_{i+1}) weigh the same at the regular valence.
    oriented = tuple(sp.sympify(w, strict=True) for w in (edge.center, ea.get(0, z), ea.get(1, z), eb.get(0, z)))
    return MeshRules(scheme, sp.sympify(face.center, strict=True), *oriented[::2], oriented)


@dataclass(frozen=True)
class TriangleMeshRules:
    """Edge and vertex point rules of a triangle scheme on a whole mesh (weights are sympy)."""

    scheme: Scheme
    #: Weight of each end of an edge in its edge point.
    edge_end: sp.Expr
    #: Weight of each of the two vertices opposite the edge.
    edge_side: sp.Expr
    #: The edge rule read from its end ``O`` (expressions in ``n``): on ``O``, on the other end, on each opposite vertex.
    oriented: tuple[sp.Expr, ...] = ()

    def vertex_weights(self, valence: int) -> tuple[sp.Expr, sp.Expr]:
        """``(center, each neighbour)`` of the vertex point at this valence (exact sympy values)."""
        v = self.scheme.vertex_rule
        return tuple(w.subs(N, valence) for w in (v.center, v.each_a))

    def edge_weights(self, valence: int) -> tuple[sp.Expr, ...]:
        """:attr:`oriented` at this valence, as :meth:`MeshRules.edge_weights`."""
        return _oriented_at(self.oriented, valence)

    depends_on_valence = MeshRules.depends_on_valence


def _oriented_at(oriented: tuple, valence: int) -> tuple[sp.Expr, ...]:
    """An edge rule read from its end ``O`` (expressions in ``n``) at ``O``'s valence."""
    return tuple(sp.sympify(w, strict=True).subs(N, valence) for w in oriented)


def triangle_mesh_rules(scheme: Scheme) -> TriangleMeshRules:
    """Read a triangle scheme's 1-ring rules as edge/vertex point rules of a whole mesh.

    Raises :class:`~symdecomp.errors.InvalidSchemeError` when the edge rule reaches beyond the two triangles of its
    edge, or weighs the two ends (or the two opposite vertices) differently, so that the edge point would depend on
    which end is called ``O``. An edge rule in ``n`` is read at each edge's :func:`edge_valence`.
    """

    if "face" in scheme.lattice.stencil_sections:
        raise InvalidSchemeError(f"scheme {scheme.name!r} lives on {scheme.lattice} meshes, not triangle meshes (its 1-ring has face neighbours)")
    edge = scheme.edge_rule
    ea = dict(edge.a)
    if set(ea) - {-1, 0, 1}:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the edge rule reaches beyond the two triangles of the edge (O, a_i)")
    z = sp.Integer(0)
    if not identically_zero((edge.center - ea.get(0, z)).subs(N, 6)) or not identically_zero(ea.get(-1, z) - ea.get(1, z)):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the edge rule weighs the two ends (or the two opposite vertices) differently, "
            "so it is not a rule of the mesh"
        )
    oriented = tuple(sp.sympify(w, strict=True) for w in (edge.center, ea.get(0, z), ea.get(1, z)))
    return TriangleMeshRules(scheme, oriented[0], oriented[2], oriented)


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
    # a rational zero times a rational weight adds nothing (after the first term, which fixes the sum's type)
    rest = [(w, val) for w, val in terms[1:] if not (isinstance(w, Fraction) and all(type(x) in (Fraction, int) and x == 0 for x in val))]
    return tuple(sum((w * val[k] for w, val in rest), terms[0][0] * terms[0][1][k]) for k in range(len(terms[0][1])))


def point_stencils(mesh: QuadMesh, rules: MeshRules, vertex_weights: Callable | None = None,
                   edge_weights: Callable | None = None) -> tuple[dict, dict, dict]:
    """``(face, edge, vertex)`` stencils ``{key: ((weight, old vertex id), ...)}`` of the refined points
    (keys: face index, ``frozenset({u, v})`` of an edge with two faces, interior vertex id);
    ``vertex_weights(valence)`` and ``edge_weights(valence)`` override the rules' vertex and edge weights (the ring
    matrices' symbolic centre)."""
    fc = _as_weight(rules.face_corner)
    edge_at = _edge_weights_at(mesh, rules, edge_weights, 4)
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
        # x, q next to v and y, p next to u: left face (u, v, x, y), right face (v, u, p, q)
        wu, wv, su, sv = edge_at(u, v)
        near_v, near_u = (fl[(kl + 2) % 4], fr[(kr + 3) % 4]), (fl[(kl + 3) % 4], fr[(kr + 2) % 4])
        edge[key] = ((wu, u), (wv, v)) + tuple((sv, x) for x in near_v) + tuple((su, x) for x in near_u)
    vertex, cache = {}, {}
    for v in (v for v in mesh.vertices() if mesh.is_interior(v)):
        _, a, b = mesh.one_ring(v)
        if len(a) not in cache:
            cache[len(a)] = tuple(_as_weight(w) for w in (vertex_weights or rules.vertex_weights)(len(a)))
        wc, wa, wb = cache[len(a)]
        vertex[v] = ((wc, v),) + tuple((wa, x) for x in a) + tuple((wb, x) for x in b)
    return face, edge, vertex


def _edge_weights_at(mesh, rules, override: Callable | None, regular: int) -> Callable:
    """``(u, v) -> (on u, on v, each side next to u, each side next to v)`` (triangles: ``(on u, on v, each side)``):
    the edge rule read from the edge's end ``O`` at its valence (:func:`edge_centre`), one reading per valence."""
    cache: dict[int, tuple] = {}

    def at(valence: int) -> tuple:
        if valence not in cache:
            cache[valence] = tuple(_as_weight(w) for w in (override or rules.edge_weights)(valence))
        return cache[valence]

    if override is None and not rules.depends_on_valence:
        fixed = at(regular)
        return lambda u, v: fixed
    valence: dict[int, int] = {}

    def of(x: int) -> int:
        if x not in valence:
            valence[x] = len(mesh.one_ring(x)[1]) if mesh.is_interior(x) else regular
        return valence[x]

    def oriented(u: int, v: int) -> tuple:
        mu, mv = of(u), of(v)
        w = at(mu)
        if mu == mv != regular and (w[0] != w[1] or w[2] != w[-1]):
            raise InvalidSchemeError(f"scheme {rules.scheme.name!r}: an edge joins two vertices of valence {mu}, and the "
                                     f"edge rule at n = {mu} weighs its two ends differently: the model reads it from neither")
        w = at(mv if edge_centre(mu, mv, regular) else mu)
        return w if not edge_centre(mu, mv, regular) else (w[1], w[0], *w[2:][::-1])

    return oriented


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


def refine(mesh: QuadMesh, scheme_or_rules: Scheme | MeshRules, *, vertex_weights: Callable | None = None,
           edge_weights: Callable | None = None) -> Refinement:
    """One exact refinement step of ``mesh`` by the scheme's mesh rules (:func:`mesh_rules`).

    Points whose rule needs something outside the mesh (boundary vertices and edges) are not
    computed, and new faces with such a corner are dropped. ``vertex_weights``: :func:`point_stencils`.
    """
    rules = scheme_or_rules if isinstance(scheme_or_rules, MeshRules) else mesh_rules(scheme_or_rules)
    face, edge, vertex = point_stencils(mesh, rules, vertex_weights, edge_weights)
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

    >>> from symdecomp.schemes.mesh import ring_mesh
    >>> from symdecomp.schemes.scheme import catmull_clark
    >>> rings = central_rings(ring_mesh(4, 1, lambda s, u, v: (u*u + v*v,)), catmull_clark(), 0, 2)
    >>> [r[0] for r in rings]
    [(0,), (Fraction(1, 2),), (Fraction(5, 8),)]
    """
    levels = check_levels(levels, maximum=MAX_LEVELS, reason="the exact values grow with every level")
    if keep_rings is None:
        check_memory(len(mesh.faces) * 4**levels * 256, f"{levels} levels of refinement of the whole mesh")
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


# --------------------------------------------------------------------------------------------
# triangles


@dataclass(frozen=True)
class TriangleRefinement:
    """One refinement step: the refined mesh and where its vertices come from."""

    mesh: TriangleMesh
    #: Old vertex id -> id of its vertex point (interior vertices only).
    vertex_point: Mapping[int, int]
    #: ``frozenset({u, v})`` -> id of the edge point (edges with two faces only).
    edge_point: Mapping[frozenset, int]


def refine_triangles(mesh: TriangleMesh, scheme_or_rules, *, vertex_weights: Callable | None = None,
                     edge_weights: Callable | None = None) -> TriangleRefinement:
    """One exact refinement step of ``mesh`` by the scheme's mesh rules (1-to-4 split).

    ``vertex_weights(valence)`` overrides the rules' vertex weights (``(center, each
    neighbour)``); :mod:`symdecomp.schemes.rings` uses it to keep the centre's weights symbolic.
    """
    rules = scheme_or_rules if isinstance(scheme_or_rules, TriangleMeshRules) else triangle_mesh_rules(scheme_or_rules)
    weights_at = vertex_weights or rules.vertex_weights
    edge_at = _edge_weights_at(mesh, rules, edge_weights, 6)
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
        wu, wv, es = edge_at(u, v)
        new_values[len(new_values)] = _combine([(wu, vals[u]), (wv, vals[v]), (es, vals[x]), (es, vals[y])])
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
