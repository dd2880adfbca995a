"""schemes/polygon_step.py and mesh_refine.py: Catmull-Clark's first step on any polygons, whole meshes refined exactly."""

import math
from fractions import Fraction

import pytest

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.lattice import QUAD
from symdecomp.schemes.mesh_refine import refine_mesh
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.polygon_step import catmull_clark_polygon_step
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.tagged_refinement import TaggedMesh, refine_tagged
from tests.analysis.test_mesh_limits import grid


def test_on_quads_it_is_the_tagged_refinement_s_step():
    """On an all-quad mesh with a boundary the polygon step is refine_tagged's (OpenSubdiv's edge-and-corner rules):
    the same points, exactly."""
    mesh = grid()
    step = catmull_clark_polygon_step(mesh)
    tagged, _, ids = refine_tagged(TaggedMesh(mesh.local_mesh(QUAD)), catmull_clark())
    values = tagged.mesh.values
    for v in range(len(mesh.points)):
        assert step.mesh.points[step.vertex_point[v]] == tuple(values[ids[("vertex", v)]])
    for edge, new in step.edge_point.items():
        assert step.mesh.points[new] == tuple(values[ids[("edge", edge)]])


def test_an_n_gon_becomes_a_valence_n_vertex_at_its_centroid():
    pentagon = PolygonMesh.from_arrays([(0, 0, 0), (2, 0, 0), (3, 2, 0), (1, 3, 0), (-1, 2, 1)], [(0, 1, 2, 3, 4)])
    step = catmull_clark_polygon_step(pentagon)
    centre = step.face_point[0]
    assert step.mesh.points[centre] == (Fraction(1), Fraction(7, 5), Fraction(1, 5))
    assert step.mesh.valence(centre) == 5 and len(step.mesh.faces) == 5
    assert step.mesh.points[0] == pentagon.points[0]  # a boundary vertex of one face: a corner, kept


@pytest.mark.parametrize("boundary", ["edge-and-corner", "edge-only"])
def test_with_tags_it_is_the_tagged_refinement_s_step(boundary):
    """With creases (semi-sharp, 1 and sharper), a semi-sharp corner and a dart, the tagged polygon step (OpenSubdiv's
    rules written for any face) is refine_tagged's step exactly, and carries the decayed tags."""
    from symdecomp.schemes.sharp import SharpOptions

    creases = {(13, 14): Fraction(5, 2), (14, 15): Fraction(1, 2), (8, 14): Fraction(1), (20, 21): Fraction(3, 4),
               (2, 8): Fraction(10)}
    corners = {27: Fraction(3, 2)}
    mesh = grid(MeshTags(creases=creases, corners=corners, interpolate_boundary=boundary))
    step = catmull_clark_polygon_step(mesh)
    edges = {frozenset(e): (math.inf if s >= 10 else s) for e, s in creases.items()}
    tagged = TaggedMesh(mesh.local_mesh(QUAD), edges, dict(corners))
    refined, _, ids = refine_tagged(tagged, catmull_clark(), SharpOptions(boundary))
    values = refined.mesh.values
    for v in range(len(mesh.points)):
        assert step.mesh.points[step.vertex_point[v]] == tuple(values[ids[("vertex", v)]])
    for edge, new in step.edge_point.items():
        assert step.mesh.points[new] == tuple(values[ids[("edge", edge)]])
    halves = {(min(step.vertex_point[v], step.edge_point[frozenset(e)]), max(step.vertex_point[v], step.edge_point[frozenset(e)])): s
              for e, s in [((13, 14), Fraction(3, 2)), ((2, 8), Fraction(10))] for v in e}
    assert dict(step.mesh.tags.creases) == halves
    assert dict(step.mesh.tags.corners) == {27: Fraction(1, 2)}


def test_a_tagged_triangle_beside_a_quad_blends_its_semi_sharp_edge():
    """A quad and a triangle sharing an edge of sharpness 1/2: its point is half the midpoint, half the smooth point;
    the triangle's centre is a valence-3 vertex; the hole's quads stay holes."""
    points = [(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0), (2, 8, 4)]
    tags = MeshTags(creases={(2, 3): Fraction(1, 2)}, holes=frozenset({0}))
    mesh = PolygonMesh.from_arrays(points, [(0, 1, 2, 3), (3, 2, 4)], tags=tags)
    step = catmull_clark_polygon_step(mesh)
    quad_centre, tri_centre = (Fraction(2), Fraction(2), Fraction(0)), (Fraction(2), Fraction(16, 3), Fraction(4, 3))
    middle = (Fraction(2), Fraction(4), Fraction(0))
    smooth = tuple((2 * m + a + b) / 4 for m, a, b in zip(middle, quad_centre, tri_centre))
    assert step.mesh.points[step.edge_point[frozenset((2, 3))]] == tuple((m + s) / 2 for m, s in zip(middle, smooth))
    assert step.mesh.valence(step.face_point[1]) == 3 and step.mesh.tags.holes == frozenset({0, 1, 2, 3})
    assert step.mesh.tags.creases == {}


def test_chaikin_on_a_mixed_mesh_is_refused_in_one_line():
    tri = PolygonMesh.from_arrays([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])
    tagged = PolygonMesh(tri.points, tri.faces, "t.obj", tags=MeshTags(creases={(0, 1): Fraction(2)}, crease_method="chaikin"))
    with pytest.raises(InvalidMeshError, match="^t.obj: Chaikin's creasing on a mesh with faces other than quads"):
        catmull_clark_polygon_step(tagged)


def test_refine_mesh_keeps_the_creases_decayed():
    """Sharpness 2 on an edge: after one step its two halves have sharpness 1, after two none is left."""
    mesh = grid(MeshTags(creases={(13, 14): Fraction(2)}))
    one, two = refine_mesh(mesh, catmull_clark(), 1), refine_mesh(mesh, catmull_clark(), 2)
    assert sorted(one.creases.values()) == [1, 1] and two.creases == {}
    assert len(two.faces) == 16 * len(mesh.faces)


def test_an_isolated_vertex_left_out_stays_where_it_is():
    """A vertex in no face (lenient reading) does not stop the first step (it raised KeyError): it stays, unanalysed."""
    points = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (1, 3, 0), (9, 9, 9)]
    mesh = PolygonMesh.from_arrays(points, [(0, 1, 2, 3), (3, 2, 4)], strict=False)
    assert mesh.defects.isolated_vertices == (5,)
    step = catmull_clark_polygon_step(mesh)
    assert step.mesh.points[5] == (9, 9, 9) and len(step.mesh.faces) == 7


def test_a_valence_2_vertex_on_a_crease_is_judged_by_its_spectrum_and_has_no_limit_masks():
    """OpenSubdiv's val2_interior: a cube with a vertex in the middle of an edge (two pentagons), the edge's halves
    infinitely sharp: after the first step the vertex has two faces and two sharp edges, a fan the sector model does
    not take: its outcome is its exact 1-ring spectrum's verdict, it has no limit point here, and every other vertex does."""
    from symdecomp.analysis.mesh_limits import mesh_limits

    points = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2), (1, 0, 0)]
    faces = [(0, 3, 2, 1, 8), (4, 5, 6, 7), (0, 8, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    tags = MeshTags(creases={(0, 8): Fraction(10), (1, 8): Fraction(10)})
    step = catmull_clark_polygon_step(PolygonMesh.from_arrays(points, faces, tags=tags))
    assert step.mesh.valence(8) == 2
    result = mesh_limits(step.mesh, catmull_clark())
    assert not result.not_analysed() and list(result.no_limit()) == [8]
    outcome = result.kinds.outcomes[8]
    assert outcome.label == "interior vertex of valence 2, sharpness inf, inf (spectrum)" and outcome.fan[:2] == (2, True)
    assert outcome.fan[2] == (math.inf, math.inf)
