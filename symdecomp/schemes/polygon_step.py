"""One exact Catmull-Clark step on a polygon mesh of any faces: every face becomes quads, an n-gon a valence-n vertex.

Catmull-Clark is defined on any polygon mesh; one step makes it all quads, and the limit surface is the same.
:func:`catmull_clark_polygon_step` takes that step exactly (``Fraction`` coordinates) with Catmull-Clark's rules
for every face size: the face point is the centroid; an interior edge point ``(v + w + f_1 + f_2)/4``; an interior
vertex of valence ``n`` goes to ``(F + 2 R + (n - 3) V)/n`` (``F`` the mean of its face points, ``R`` of its edge
midpoints); OpenSubdiv's boundary rules under ``edge-and-corner`` interpolation: a boundary edge point is the
midpoint, a boundary vertex ``(u + 6 v + w)/8`` with its two boundary neighbours, a boundary vertex of one face
stays (a corner). The topology is :meth:`~symdecomp.schemes.meshfile.PolygonMesh.split_into_quads`'s.

With OpenSubdiv's tags (uniform creasing, ``catmark`` triangles) the step takes OpenSubdiv's sharp rules
(:mod:`symdecomp.schemes.polygon_sharp`): a crease edge's point is the midpoint (blended with the smooth one below
sharpness 1), a vertex's rule is its kind's (smooth, dart, crease, corner) blended with the next level's, and the
refined mesh carries the decayed tags (each half of a crease ``s - 1``, a corner ``s - 1``, a hole's quads holes).

The result records which new vertex came from which old vertex, edge or face: the centre of an ``n``-gon
(``n != 4``) is an extraordinary vertex of valence ``n`` that came from a face.

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> tri = PolygonMesh.from_arrays([(0, 0, 0), (3, 0, 0), (0, 3, 0)], [(0, 1, 2)])
>>> step = catmull_clark_polygon_step(tri)
>>> len(step.mesh.faces), step.face_point[0], step.mesh.points[step.face_point[0]]
(3, 3, (Fraction(1, 1), Fraction(1, 1), Fraction(0, 1)))
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.meshfile import PolygonMesh

__all__ = ["PolygonStep", "catmull_clark_polygon_step"]


@dataclass(frozen=True)
class PolygonStep:
    """The refined all-quad mesh and where its vertices came from."""

    mesh: PolygonMesh
    #: Old vertex -> its new vertex point.
    vertex_point: dict
    #: Old face index -> its new face point.
    face_point: dict
    #: ``frozenset({u, v})`` -> the new edge point.
    edge_point: dict


def _mean(points) -> tuple:
    points = list(points)
    return tuple(sum((p[c] for p in points), Fraction(0)) / len(points) for c in range(3))


def _vertex(mesh: PolygonMesh, v: int, face_pts: list, faces_at: dict, nbrs: dict, boundary: set) -> tuple:
    p = mesh.points[v]
    if v not in nbrs:  # in no face (an isolated vertex left out of the analysis): it stays
        return p
    if v in boundary:
        ends = [w for w in nbrs[v] if frozenset((v, w)) in boundary_edges(mesh)]
        if len(faces_at[v]) == 1:
            return p
        u, w = (mesh.points[x] for x in ends)
        return tuple((u[c] + 6 * p[c] + w[c]) / 8 for c in range(3))
    n = len(nbrs[v])
    F = _mean(face_pts[i] for i in faces_at[v])
    R = _mean(tuple((p[c] + mesh.points[w][c]) / 2 for c in range(3)) for w in nbrs[v])
    return tuple((F[c] + 2 * R[c] + (n - 3) * p[c]) / n for c in range(3))


def boundary_edges(mesh: PolygonMesh) -> frozenset:
    """The edges of one face, as ``frozenset({u, v})``."""
    cached = mesh._topology.get("polygon-boundary-edges")
    if cached is None:
        d = mesh._topology["directed"]
        cached = frozenset(frozenset(e) for e in d if (e[1], e[0]) not in d)
        mesh._topology["polygon-boundary-edges"] = cached
    return cached


def catmull_clark_polygon_step(mesh: PolygonMesh) -> PolygonStep:
    """One exact Catmull-Clark step of ``mesh`` (any faces; no sharpness tags), see the module docstring."""
    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    if not mesh.tags.is_empty() or mesh.tags.interpolate_boundary != "edge-and-corner":
        from symdecomp.schemes.polygon_sharp import tagged_polygon_step

        return tagged_polygon_step(mesh)
    faces = mesh.faces
    face_pts = [_mean(mesh.points[v] for v in f) for f in faces]
    faces_at: dict[int, list[int]] = {}
    edge_faces: dict[frozenset, list[int]] = {}
    nbrs: dict[int, set] = {}
    for i, f in enumerate(faces):
        for k, v in enumerate(f):
            w = f[(k + 1) % len(f)]
            faces_at.setdefault(v, []).append(i)
            edge_faces.setdefault(frozenset((v, w)), []).append(i)
            nbrs.setdefault(v, set()).update((w, f[k - 1]))
    boundary = {v for e in boundary_edges(mesh) for v in e}
    points = [_vertex(mesh, v, face_pts, faces_at, nbrs, boundary) for v in range(len(mesh.points))]
    vertex_point = {v: v for v in range(len(mesh.points))}
    face_point = {}
    for i, p in enumerate(face_pts):
        face_point[i] = len(points)
        points.append(p)
    edge_point = {}
    for edge, fs in edge_faces.items():
        ends = [mesh.points[v] for v in edge]
        around = ends + ([face_pts[i] for i in fs] if len(fs) == 2 else [])
        edge_point[edge] = len(points)
        points.append(_mean(around))
    quads = []
    for i, f in enumerate(faces):
        c = len(f)
        for k in range(c):
            before, after = frozenset((f[k - 1], f[k])), frozenset((f[k], f[(k + 1) % c]))
            quads.append((f[k], edge_point[after], face_point[i], edge_point[before]))
    refined = PolygonMesh(tuple(points), tuple(quads), mesh.name, strict=False)  # isolated vertices stay
    return PolygonStep(refined, vertex_point, face_point, edge_point)
