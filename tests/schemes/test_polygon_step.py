"""schemes/polygon_step.py and mesh_refine.py: Catmull-Clark's first step on any polygons, whole meshes refined exactly."""

from fractions import Fraction

import pytest

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.lattice import QUAD
from symdecomp.schemes.mesh_refine import refine_mesh
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.polygon_step import catmull_clark_polygon_step
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sharp_refinement import TaggedMesh, refine_tagged
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


def test_tagged_mixed_meshes_are_refused_in_one_line():
    tri = PolygonMesh.from_arrays([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])
    tagged = PolygonMesh(tri.points, tri.faces, "t.obj", tags=MeshTags(creases={(0, 1): Fraction(2)}))
    with pytest.raises(InvalidMeshError, match="t.obj: a mesh with faces other than quads and sharpness tags"):
        catmull_clark_polygon_step(tagged)


def test_refine_mesh_keeps_the_creases_decayed():
    """Sharpness 2 on an edge: after one step its two halves have sharpness 1, after two none is left."""
    mesh = grid(MeshTags(creases={(13, 14): Fraction(2)}))
    one, two = refine_mesh(mesh, catmull_clark(), 1), refine_mesh(mesh, catmull_clark(), 2)
    assert sorted(one.creases.values()) == [1, 1] and two.creases == {}
    assert len(two.faces) == 16 * len(mesh.faces)
