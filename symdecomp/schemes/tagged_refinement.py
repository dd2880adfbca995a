"""Exact refinement of quad and triangle meshes with tagged sharp edges and vertices (OpenSubdiv's semantics).

A :class:`TaggedMesh` is a quad or triangle mesh (:mod:`symdecomp.schemes.mesh`) with a sharpness on
some edges and vertices (:func:`~symdecomp.schemes.sharp.check_sharpness`: a ``Fraction`` or ``math.inf``)
and, for a mesh cut out of a larger one, the ``cut`` edges: boundary edges of the piece that are not
boundary edges of the surface. Every other boundary edge is a real boundary, infinitely sharp, and a
boundary vertex with one face is a corner under ``"edge-and-corner"`` interpolation
(:class:`~symdecomp.schemes.sharp.SharpOptions`), as in OpenSubdiv's ``TopologyRefinerFactory``.

One refinement (:func:`sharp_stencils`, :func:`refine_tagged`) computes every point whose rule sees all
its inputs (a vertex whose fan of faces is not cut, an edge with its faces, every face), each from the
rule its own tags and valence give (the whole-mesh model):

* face point (quads): the centroid, the scheme's face rule;
* edge point: the scheme's smooth edge rule (or BLZ's near-edge rule, :class:`~symdecomp.schemes.sharp.SharpRules`,
  when exactly one end is a crease, boundary or corner vertex and the edge is smooth), the crease rule
  ``crease_edge`` on each end when the edge's sharpness is at least 1 (Chaikin: when both child halves stay
  sharp), and for ``0 < s < 1`` the blend ``s * crease + (1 - s) * smooth`` (OpenSubdiv's
  ``ComputeEdgeVertexMask``);
* vertex point: the rule of :func:`~symdecomp.schemes.sharp.vertex_rule_kind` (smooth and dart: the scheme's
  vertex rule at the vertex's valence; crease: ``crease_centre`` and ``crease_end`` on the two sharp
  neighbours; corner: the vertex itself), blended with the child level's rule by
  :func:`~symdecomp.schemes.sharp.fractional_weight` when the two differ (``ComputeVertexVertexMask``).

BLZ's sector angle at a sharp vertex: the smooth edge lies in a sector of ``k`` faces between two sharp
edges (or the whole fan of a dart); ``theta_k = pi/k``, or ``angle/k`` at a vertex given a corner angle.

>>> from symdecomp.schemes.mesh import QuadMesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> square = TaggedMesh(QuadMesh(((0, 1, 2, 3),), {i: (i,) for i in range(4)}))
>>> stencils = sharp_stencils(square, catmull_clark())
>>> stencils.vertex[0], stencils.edge[frozenset((0, 1))]
({0: Fraction(1, 1)}, {0: Fraction(1, 2), 1: Fraction(1, 2)})
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from types import MappingProxyType

import sympy as sp

from symdecomp.errors import InvalidMeshError, InvalidSchemeError, LatticeFactMissing
from symdecomp.schemes.lattice import lattice_of
from symdecomp.schemes.mesh import QuadMesh, TriangleMesh
from symdecomp.schemes.refinement import _as_weight
from symdecomp.schemes.sharp import (
    SharpOptions,
    VertexRuleKind,
    check_sharpness,
    child_edge_sharpnesses,
    decrement,
    fractional_weight,
    is_sharp,
    vertex_rule_kind,
)

__all__ = ["TaggedMesh", "VertexFan", "PointStencils", "sharp_stencils", "refine_tagged"]

_SMOOTH = (VertexRuleKind.SMOOTH, VertexRuleKind.DART)


@dataclass(frozen=True)
class TaggedMesh:
    """A quad or triangle mesh with sharp edges and vertices (see the module docstring)."""

    #: The faces and the values at the vertices.
    mesh: QuadMesh | TriangleMesh
    #: ``frozenset({u, v})`` -> sharpness of the edge (missing: 0, smooth; a real boundary edge is infinite anyway).
    edge_sharpness: Mapping[frozenset, object] = field(default_factory=dict)
    #: Vertex id -> sharpness of the vertex (``math.inf``: a corner, interpolated).
    vertex_sharpness: Mapping[int, object] = field(default_factory=dict)
    #: Boundary edges of ``mesh`` where it was cut out of a larger mesh (not a boundary of the surface).
    cut: frozenset = frozenset()
    #: Vertex id -> corner angle (a sympy expression such as ``pi/2``) for BLZ's ``theta_k = angle/k``.
    angles: Mapping[int, object] = field(default_factory=dict)

    def __post_init__(self):
        try:
            lattice_of(self.mesh)  # a local mesh of some lattice's kind
        except LatticeFactMissing:
            raise InvalidMeshError(f"a tagged mesh needs a QuadMesh or TriangleMesh, got {type(self.mesh).__name__}") from None
        edges = {frozenset(e) for e in self.mesh._directed}
        sharp = {}
        for e, s in dict(self.edge_sharpness).items():
            key = frozenset(e)
            if key not in edges:
                raise InvalidMeshError(f"edge {sorted(key)} has a sharpness but is not an edge of the mesh")
            sharp[key] = check_sharpness(s, f"sharpness of edge {sorted(key)}")
        corners = {}
        for v, s in dict(self.vertex_sharpness).items():
            self.mesh._check_vertex(v)
            corners[v] = check_sharpness(s, f"sharpness of vertex {v}")
        cut = frozenset(frozenset(e) for e in self.cut)
        stray = cut - self.boundary_edges(all_edges=True)
        if stray:
            raise InvalidMeshError(f"cut edge {sorted(next(iter(stray)))} is not a boundary edge of the mesh")
        object.__setattr__(self, "edge_sharpness", MappingProxyType(sharp))
        object.__setattr__(self, "vertex_sharpness", MappingProxyType(corners))
        object.__setattr__(self, "cut", cut)
        object.__setattr__(self, "angles", MappingProxyType(dict(self.angles)))

    def boundary_edges(self, *, all_edges: bool = False) -> frozenset:
        """The real boundary edges (with ``all_edges``: every edge with one face, the cut ones included)."""
        d = self.mesh._directed
        out = frozenset(frozenset(e) for e in d if (e[1], e[0]) not in d)
        return out if all_edges else out - self.cut

    def sharpness(self, u: int, v: int):
        """The sharpness of the edge ``(u, v)``: infinite on a real boundary."""
        key = frozenset((u, v))
        d = self.mesh._directed
        if (u, v) not in d or (v, u) not in d:
            return math.inf
        return self.edge_sharpness.get(key, Fraction(0))


@dataclass(frozen=True)
class VertexFan:
    """The faces around a vertex in rotational order (counter-clockwise), open on a boundary."""

    #: Edge neighbours ``a_0..a_m`` (``m + 1`` of them on an open fan, one per face on a closed one).
    edges: tuple[int, ...]
    #: The corners of face ``i`` after ``a_i`` and before ``a_{i+1}`` (quads: ``(b_i,)``; triangles: ``()``).
    between: tuple[tuple[int, ...], ...]
    #: Whether the fan closes (an interior vertex).
    closed: bool


def vertex_fan(tagged: TaggedMesh, v: int) -> VertexFan | None:
    """The fan of ``v``, or ``None`` when it is cut (part of it is outside the mesh)."""
    mesh = tagged.mesh
    nxt = {}
    for fi in mesh.faces_of(v):
        f = mesh.faces[fi]
        k, c = f.index(v), len(f)
        nxt[f[(k + 1) % c]] = tuple(f[(k + i) % c] for i in range(2, c))
    last = {rest[-1] for rest in nxt.values()}
    starts = sorted(set(nxt) - last)
    if len(starts) > 1:
        raise InvalidMeshError(f"the faces around vertex {v} form more than one fan (non-manifold vertex)")
    if any(frozenset((v, a)) in tagged.cut for a in set(nxt) | last):
        return None
    start = starts[0] if starts else min(nxt)
    fan, between = [start], []
    while fan[-1] in nxt and len(between) < len(nxt):
        rest = nxt[fan[-1]]
        between.append(rest[:-1])
        fan.append(rest[-1])
    closed = not starts
    if closed:
        fan.pop()
    return VertexFan(tuple(fan), tuple(between), closed)


@dataclass(frozen=True)
class PointStencils:
    """The refined points' stencils ``{old vertex id: weight}`` (exact: ``Fraction`` or sympy)."""

    #: Face index -> stencil of its face point (quads).
    face: Mapping[int, dict]
    #: ``frozenset({u, v})`` -> stencil of the edge point.
    edge: Mapping[frozenset, dict]
    #: Vertex id -> stencil of its vertex point.
    vertex: Mapping[int, dict]
    #: Vertex id -> ``(parent sharpness per fan edge, child sharpness per fan edge, parent, child vertex sharpness)``.
    sharpness: Mapping[int, tuple]


def _add(stencil: dict, weight, vertex: int) -> None:
    stencil[vertex] = stencil.get(vertex, 0) + weight


def _mix(p, first: dict, second: dict) -> dict:
    """``p * first + (1 - p) * second``."""
    if p == 1:
        return first
    if p == 0:
        return second
    out: dict = {}
    for w, st in ((p, first), (1 - p, second)):
        for x, c in st.items():
            _add(out, w * c, x)
    return {x: c for x, c in out.items() if c != 0}


class _Rules:
    """The scheme's rules as exact weights, with the options (one object per refinement)."""

    def __init__(self, scheme, options: SharpOptions):
        self.scheme, self.options, self.sharp = scheme, options, scheme.sharp
        self.mesh_rules = scheme.lattice.mesh_rules(scheme)
        if self.mesh_rules.depends_on_valence:  # a sharp vertex's sectors have no valence to read the rule at
            raise InvalidSchemeError(f"scheme {scheme.name!r}: its edge rule depends on the valence n, and a mesh with "
                                     "sharp features reads it at no valence; give an edge rule without n")
        self.edge_end = _as_weight(self.mesh_rules.edge_end)
        self.edge_side = _as_weight(self.mesh_rules.edge_side)
        self.crease = tuple(_as_weight(w) for w in (self.sharp.crease_centre, self.sharp.crease_end, self.sharp.crease_edge))
        self._vertex_cache: dict[int, tuple] = {}
        #: Per sharp vertex, its fan's ``{neighbour: edge index}`` and each edge's sector size (:func:`_near_edge`).
        self.sectors: dict[int, tuple[dict, list]] = {}

    def vertex_weights(self, valence: int) -> tuple:
        if valence not in self._vertex_cache:
            self.scheme.check_values_at(valence, note=f" (a vertex of valence {valence} in the mesh)")
            self._vertex_cache[valence] = tuple(_as_weight(w) for w in self.mesh_rules.vertex_weights(valence))
        return self._vertex_cache[valence]


def _fan_sharpness(tagged: TaggedMesh, v: int, fan: VertexFan, options: SharpOptions) -> tuple:
    parent = [tagged.sharpness(v, a) for a in fan.edges]
    pv = tagged.vertex_sharpness.get(v, Fraction(0))
    if options.corners and not fan.closed and len(fan.between) == 1:
        pv = math.inf  # OpenSubdiv sharpens a boundary vertex with one face (TopologyRefinerFactory)
    return parent, child_edge_sharpnesses(parent, options), pv, decrement(pv)


def _vertex_mask(kind: VertexRuleKind, v: int, fan: VertexFan, sharp: list, rules: _Rules) -> dict:
    if kind in _SMOOTH:
        if not fan.closed:
            raise InvalidMeshError(f"vertex {v} is on a boundary but its rule is smooth")  # pragma: no cover
        wc, wa, *wb = rules.vertex_weights(len(fan.edges))
        out = {v: wc}
        for a, rest in zip(fan.edges, fan.between):
            _add(out, wa, a)
            for x in rest:
                _add(out, wb[0], x)
        return out
    if kind is VertexRuleKind.CORNER:
        return {v: Fraction(1)}
    ends = [a for a, s in zip(fan.edges, sharp) if is_sharp(s)]
    centre, end, _ = rules.crease
    out = {v: centre}
    for a in (ends[0], ends[-1]):
        _add(out, end, a)
    return out


def _vertex_stencil(v: int, fan: VertexFan, sharpness: tuple, rules: _Rules) -> dict:
    parent, child, pv, cv = sharpness
    p_kind, c_kind = vertex_rule_kind(pv, parent), vertex_rule_kind(cv, child)
    mask = _vertex_mask(p_kind, v, fan, parent, rules)
    if p_kind in _SMOOTH or p_kind is c_kind:
        return mask
    weight = fractional_weight(pv, cv, parent, child, rules.options)
    return _mix(weight, mask, _vertex_mask(c_kind, v, fan, child, rules))


def _sectors(fan: VertexFan, sharp: list) -> list[int | None]:
    """For each edge ``i`` of the fan, the number of faces of the sector (between two sharp edges of the fan) that holds
    it, in one pass each way (O(edges); ``None`` where no sector holds it: the first edge of an open fan)."""
    m = len(fan.edges)
    if not fan.closed:
        marks = [j == 0 or j == m - 1 or is_sharp(sharp[j]) for j in range(m)]
    else:
        marks = [is_sharp(sharp[j]) for j in range(m)]
        if sum(marks) < 2:
            return [m] * m
    first, last = marks.index(True), m - 1 - marks[::-1].index(True)
    before: list[int | None] = [None] * m
    after: list[int | None] = [None] * m
    mark = last - m if fan.closed else None
    for j in range(m):
        before[j] = mark
        mark = j if marks[j] else mark
    mark = first + m if fan.closed else None
    for j in reversed(range(m)):
        after[j] = mark
        mark = j if marks[j] else mark
    return [None if b is None or a is None else a - b for b, a in zip(before, after)]


def _near_edge(tagged: TaggedMesh, x: int, y: int, fans: dict, kinds: dict, rules: _Rules):
    """BLZ's ``(weight on x, weight on y)`` for the smooth edge ``(x, y)`` at the sharp vertex ``x`` (else ``None``)."""
    if kinds.get(x) not in (VertexRuleKind.CREASE, VertexRuleKind.CORNER):
        return None
    if x not in rules.sectors:  # once per vertex: a fan of k faces has k smooth edges
        fan = fans[x]
        rules.sectors[x] = ({a: i for i, a in enumerate(fan.edges)},
                            _sectors(fan, [tagged.sharpness(x, a) for a in fan.edges]))
    index, sizes = rules.sectors[x]
    k = sizes[index[y]]
    theta = tagged.angles.get(x, sp.pi) / k
    return tuple(_as_weight(w) for w in rules.sharp.near_edge(theta, k))


def _smooth_edge(tagged: TaggedMesh, u: int, v: int, fans: dict, kinds: dict, rules: _Rules) -> dict | None:
    mesh = tagged.mesh
    left, right = mesh._directed[(u, v)], mesh._directed[(v, u)]
    sides = [x for fi in (left, right) for x in mesh.faces[fi] if x not in (u, v)]
    out = {u: rules.edge_end, v: rules.edge_end}
    if rules.sharp.near_edge_centre is not None:
        if fans.get(u) is None or fans.get(v) is None:
            return None  # whether an end is a sharp vertex is decided outside the mesh
        at_u, at_v = _near_edge(tagged, u, v, fans, kinds, rules), _near_edge(tagged, v, u, fans, kinds, rules)
        if (at_u is None) != (at_v is None):  # at two sharp ends the smooth rule stays (as implementations of BLZ do)
            out = {u: at_u[0], v: at_u[1]} if at_u else {u: at_v[1], v: at_v[0]}
    for x in sides:
        _add(out, rules.edge_side, x)
    return out


def _edge_stencil(tagged: TaggedMesh, u: int, v: int, fans: dict, kinds: dict, sharpness: dict, rules: _Rules):
    """The edge point's stencil (``None``: not computable in this mesh)."""
    key = frozenset((u, v))
    if key in tagged.cut:
        return None
    s = tagged.sharpness(u, v)
    crease = {u: rules.crease[2], v: rules.crease[2]}
    if s == 0:
        return _smooth_edge(tagged, u, v, fans, kinds, rules)
    if math.isinf(s):
        return crease
    halves = []
    for x, y in ((u, v), (v, u)):
        if not rules.options.chaikin:
            halves.append(decrement(s))
        elif x not in sharpness:
            return None
        else:
            halves.append(sharpness[x][1][fans[x].edges.index(y)])
    if all(is_sharp(h) for h in halves):
        return crease
    smooth = _smooth_edge(tagged, u, v, fans, kinds, rules)
    return None if smooth is None else _mix(s, crease, smooth)


def sharp_stencils(tagged: TaggedMesh, scheme, options: SharpOptions | None = None) -> PointStencils:
    """The stencils of every computable refined point of ``tagged`` (see the module docstring)."""
    from symdecomp.schemes.scheme import check_scheme

    check_scheme(scheme)
    options = SharpOptions() if options is None else options
    if not isinstance(options, SharpOptions):
        raise InvalidMeshError(f"options must be SharpOptions, got {type(options).__name__}")
    if (tagged.mesh.faces and len(tagged.mesh.faces[0])) != scheme.lattice.face_sides:
        raise InvalidMeshError(f"scheme {scheme.name!r} lives on {scheme.lattice} meshes; the mesh has other faces")
    rules = _Rules(scheme, options)
    mesh = tagged.mesh
    fans = {v: vertex_fan(tagged, v) for v in mesh.vertices()}
    sharpness = {v: _fan_sharpness(tagged, v, fan, options) for v, fan in fans.items() if fan is not None}
    kinds = {v: vertex_rule_kind(s[2], s[0]) for v, s in sharpness.items()}
    vertex = {v: _vertex_stencil(v, fans[v], sharpness[v], rules) for v in sharpness}
    edge = {}
    for u, v in mesh._directed:
        key = frozenset((u, v))
        if key not in edge:
            stencil = _edge_stencil(tagged, u, v, fans, kinds, sharpness, rules)
            if stencil is not None:
                edge[key] = stencil
    face = {}
    if "face" in scheme.lattice.stencil_sections:
        corner = _as_weight(rules.mesh_rules.face_corner)
        face = {fi: {x: corner for x in f} for fi, f in enumerate(mesh.faces)}
    return PointStencils(MappingProxyType(face), MappingProxyType(edge), MappingProxyType(vertex),
                         MappingProxyType(sharpness))


def _combine(stencil: dict, values: Mapping) -> tuple:
    items = list(stencil.items())
    size = len(values[items[0][0]])
    return tuple(sum((w * values[x][c] for x, w in items[1:]), items[0][1] * values[items[0][0]][c]) for c in range(size))


def _child_faces(mesh, vertex_point: dict, edge_point: dict, face_point: dict) -> list:
    """The children of each face (quads: four, triangles: four) whose corners were all computed."""
    out = []
    for fi, f in enumerate(mesh.faces):
        c = len(f)
        e = [edge_point.get(frozenset((f[k], f[(k + 1) % c]))) for k in range(c)]
        for k in range(c):
            corners = (vertex_point.get(f[k]), e[k]) + ((face_point[fi],) if c == 4 else ()) + (e[k - 1],)
            if None not in corners:
                out.append(corners)
        if c == 3 and None not in e:
            out.append(tuple(e))
    return out


def refine_tagged(tagged: TaggedMesh, scheme, options: SharpOptions | None = None):
    """One exact refinement of ``tagged``: ``(refined TaggedMesh, stencils, ids)`` where ``ids`` maps
    ``("vertex", v)``, ``("edge", frozenset)``, ``("face", index)`` to the refined point's id.

    The refined mesh carries the child sharpness of every half of a sharp edge (at its end's vertex, Chaikin
    or uniform), the decremented vertex sharpness, and cut edges where the parent was cut.
    """
    options = SharpOptions() if options is None else options
    st = sharp_stencils(tagged, scheme, options)
    values = tagged.mesh.values
    ids, new_values = {}, {}
    for kind, table in (("face", st.face), ("edge", st.edge), ("vertex", st.vertex)):
        for key, stencil in table.items():
            ids[(kind, key)] = len(new_values)
            new_values[len(new_values)] = _combine(stencil, values)
    vp = {k: i for (kind, k), i in ids.items() if kind == "vertex"}
    ep = {k: i for (kind, k), i in ids.items() if kind == "edge"}
    fp = {k: i for (kind, k), i in ids.items() if kind == "face"}
    faces = _child_faces(tagged.mesh, vp, ep, fp)
    used = {x for f in faces for x in f}
    mesh = type(tagged.mesh)(tuple(faces), {i: x for i, x in new_values.items() if i in used})
    boundary = tagged.boundary_edges()
    edge_sharpness, real = {}, set()
    for v, (_, child, _, _) in st.sharpness.items():
        fan = vertex_fan(tagged, v)
        for a, c in zip(fan.edges, child):
            half = frozenset((vp[v], ep.get(frozenset((v, a)))))
            if frozenset((v, a)) in boundary:
                real.add(half)
            elif c > 0 and half <= used:
                edge_sharpness[half] = c
    for edge in boundary:  # halves at a vertex whose fan is cut (its vertex point is not computed: no half)
        real.update(frozenset((vp[v], ep[edge])) for v in edge if v in vp and edge in ep)
    vertex_sharpness = {vp[v]: s[3] for v, s in st.sharpness.items() if s[3] > 0 and vp[v] in used}
    child = TaggedMesh(mesh, {}, {}, frozenset(), {})
    cut = child.boundary_edges(all_edges=True) - real
    angles = {vp[v]: a for v, a in tagged.angles.items() if v in vp and vp[v] in used}
    return TaggedMesh(mesh, edge_sharpness, vertex_sharpness, cut, angles), st, MappingProxyType(ids)
