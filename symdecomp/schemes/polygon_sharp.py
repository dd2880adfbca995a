"""Catmull-Clark's first exact step on a polygon mesh with OpenSubdiv's tags (creases, corners, holes, boundary).

:func:`tagged_polygon_step` is :func:`~symdecomp.schemes.polygon_step.catmull_clark_polygon_step` for a mesh with
sharpness tags or another boundary interpolation; it follows OpenSubdiv's ``Sdc`` masks for one level with uniform
creasing (real boundary edges are infinitely sharp; under ``edge-and-corner`` a boundary vertex of one face is a
corner):

* face point: the centroid;
* edge point of sharpness ``s``: the midpoint when ``s >= 1``, the smooth point ``(v + w + f_1 + f_2)/4`` when
  ``s = 0``, ``s * midpoint + (1 - s) * smooth`` between (``ComputeEdgeVertexMask``);
* vertex point: the rule of :func:`~symdecomp.schemes.sharp.vertex_rule_kind` (smooth and dart
  ``(F + 2 R + (n - 3) V)/n``, crease ``(u + 6 v + w)/8`` on its two sharp neighbours, corner ``V``), blended
  with the next level's rule by :func:`~symdecomp.schemes.sharp.fractional_weight` when the two differ
  (``ComputeVertexVertexMask``).

The refined mesh carries the decayed tags: both halves of an edge of sharpness ``s`` get ``s - 1``
(:func:`~symdecomp.schemes.sharp.decrement`), a corner ``s - 1``, the quads of a hole are holes. Chaikin's creasing
and OpenSubdiv's ``smooth`` triangles are refused (one line), as is a mesh whose first step they would change.

>>> from fractions import Fraction
>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> from symdecomp.schemes.mesh_tags import MeshTags
>>> tri = PolygonMesh.from_arrays([(0, 0, 0), (4, 0, 0), (0, 4, 0)], [(0, 1, 2)], tags=MeshTags(creases={(0, 1): Fraction(3)}))
>>> step = tagged_polygon_step(tri)
>>> step.mesh.points[step.edge_point[frozenset((0, 1))]], sorted(step.mesh.tags.creases.values())
((Fraction(2, 1), Fraction(0, 1), Fraction(0, 1)), [Fraction(2, 1), Fraction(2, 1)])
"""

from __future__ import annotations

import math
from fractions import Fraction

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.sharp import (
    SHARPNESS_INFINITE,
    SharpOptions,
    VertexRuleKind,
    child_edge_sharpnesses,
    decrement,
    fractional_weight,
    vertex_rule_kind,
)

__all__ = ["tagged_polygon_step"]


def _mean(points) -> tuple:
    points = list(points)
    return tuple(sum((p[c] for p in points), Fraction(0)) / len(points) for c in range(3))


def _blend(w, first: tuple, second: tuple) -> tuple:
    return tuple(w * a + (1 - w) * b for a, b in zip(first, second))


def _exact(s):
    """A tag's sharpness for the rules: ``math.inf`` at 10 and above (OpenSubdiv's infinitely sharp)."""
    return math.inf if s >= SHARPNESS_INFINITE else Fraction(s)


class _Topology:
    """Faces at each vertex, faces at each edge, each vertex's edges (with their sharpness) and corner sharpness."""

    def __init__(self, mesh: PolygonMesh):
        self.faces_at: dict[int, list[int]] = {}
        self.edge_faces: dict[frozenset, list[int]] = {}
        self.nbrs: dict[int, list[int]] = {}
        for i, f in enumerate(mesh.faces):
            for k, v in enumerate(f):
                w = f[(k + 1) % len(f)]
                self.faces_at.setdefault(v, []).append(i)
                self.edge_faces.setdefault(frozenset((v, w)), []).append(i)
                for x in (w, f[k - 1]):
                    if x not in self.nbrs.setdefault(v, []):
                        self.nbrs[v].append(x)
        tags = mesh.tags
        self.corner_rule = tags.interpolate_boundary == "edge-and-corner"
        self.edge = {e: (math.inf if len(fs) == 1 else _exact(tags.sharpness_of_edge(*e))) for e, fs in self.edge_faces.items()}
        self.vertex = {v: _exact(s) for v, s in tags.corners.items()}

    def vertex_sharpness(self, v: int):
        if self.corner_rule and len(self.faces_at.get(v, ())) == 1:
            return math.inf
        return self.vertex.get(v, Fraction(0))


def _rule_point(kind, mesh, v, topo, face_pts, sharp_nbrs) -> tuple:
    p = mesh.points[v]
    if kind == VertexRuleKind.CORNER:
        return p
    if kind == VertexRuleKind.CREASE:
        u, w = (mesh.points[x] for x in sharp_nbrs)
        return tuple((u[c] + 6 * p[c] + w[c]) / 8 for c in range(3))
    n = len(topo.nbrs[v])
    F = _mean(face_pts[i] for i in topo.faces_at[v])
    R = _mean(tuple((p[c] + mesh.points[w][c]) / 2 for c in range(3)) for w in topo.nbrs[v])
    return tuple((F[c] + 2 * R[c] + (n - 3) * p[c]) / n for c in range(3))


def _vertex(mesh: PolygonMesh, v: int, topo: _Topology, face_pts: list, options: SharpOptions) -> tuple:
    if v not in topo.nbrs:
        return mesh.points[v]
    nbrs = topo.nbrs[v]
    edges = [topo.edge[frozenset((v, w))] for w in nbrs]
    corner = topo.vertex_sharpness(v)
    parent = vertex_rule_kind(corner, edges)
    sharp = [w for w, s in zip(nbrs, edges) if s > 0]
    point = _rule_point(parent, mesh, v, topo, face_pts, sharp)
    children = child_edge_sharpnesses(edges, options)
    child = vertex_rule_kind(decrement(corner), children)
    if child == parent:
        return point
    weight = fractional_weight(corner, decrement(corner), edges, children, options)
    still = [w for w, s in zip(nbrs, children) if s > 0]
    return _blend(weight, point, _rule_point(child, mesh, v, topo, face_pts, still))


def _edge(mesh: PolygonMesh, edge: frozenset, topo: _Topology, face_pts: list) -> tuple:
    ends = [mesh.points[v] for v in edge]
    middle, s = _mean(ends), topo.edge[edge]
    if s >= 1:
        return middle
    smooth = _mean(ends + [face_pts[i] for i in topo.edge_faces[edge]])
    return smooth if s == 0 else _blend(s, middle, smooth)


def _check(mesh: PolygonMesh) -> None:
    tags = mesh.tags
    if tags.crease_method != "uniform":
        raise InvalidMeshError(f"{mesh.name}: Chaikin's creasing on a mesh with faces other than quads: its first step "
                               "is taken with uniform creasing only (refine it with OpenSubdiv first)")
    if tags.triangle_subdivision != "catmark" and 3 in mesh.face_sizes():
        raise InvalidMeshError(f"{mesh.name}: OpenSubdiv's smooth triangles (t smoothtriangles) on a mesh with faces "
                               "other than quads: its first step takes Catmull-Clark's rules only")


def _child_tags(mesh: PolygonMesh, topo: _Topology, edge_point: dict, vertex_point: dict, holes: list) -> MeshTags:
    creases = {}
    for edge, s in mesh.tags.creases.items():
        child = decrement(_exact(s))
        if child > 0:
            mid = edge_point[frozenset(edge)]
            for v in edge:
                a, b = sorted((vertex_point[v], mid))
                creases[(a, b)] = Fraction(SHARPNESS_INFINITE) if child == math.inf else child
    corners = {}
    for v, s in mesh.tags.corners.items():
        child = decrement(_exact(s))
        if child > 0:
            corners[vertex_point[v]] = Fraction(SHARPNESS_INFINITE) if child == math.inf else child
    t = mesh.tags
    return MeshTags(creases, corners, frozenset(holes), t.interpolate_boundary, t.crease_method, t.triangle_subdivision)


def tagged_polygon_step(mesh: PolygonMesh):
    """One exact Catmull-Clark step of ``mesh`` with its tags (module docstring): a
    :class:`~symdecomp.schemes.polygon_step.PolygonStep` whose mesh carries the decayed tags."""
    from symdecomp.schemes.polygon_step import PolygonStep

    _check(mesh)
    options = SharpOptions(mesh.tags.interpolate_boundary if mesh.tags.interpolate_boundary != "none" else "edge-only")
    topo = _Topology(mesh)
    face_pts = [_mean(mesh.points[v] for v in f) for f in mesh.faces]
    points = [_vertex(mesh, v, topo, face_pts, options) for v in range(len(mesh.points))]
    vertex_point = {v: v for v in range(len(mesh.points))}
    face_point = {}
    for i, p in enumerate(face_pts):
        face_point[i] = len(points)
        points.append(p)
    edge_point = {}
    for edge in topo.edge_faces:
        edge_point[edge] = len(points)
        points.append(_edge(mesh, edge, topo, face_pts))
    quads: list[tuple[int, int, int, int]] = []
    holes: list[int] = []
    for i, f in enumerate(mesh.faces):
        for k in range(len(f)):
            if i in mesh.tags.holes:
                holes.append(len(quads))
            before, after = frozenset((f[k - 1], f[k])), frozenset((f[k], f[(k + 1) % len(f)]))
            quads.append((f[k], edge_point[after], face_point[i], edge_point[before]))
    tags = _child_tags(mesh, topo, edge_point, vertex_point, holes)
    return PolygonStep(PolygonMesh(tuple(points), tuple(quads), mesh.name, tags=tags, strict=False), vertex_point, face_point, edge_point)
