"""Polygon mesh files (schemes/meshfile.py, schemes/meshformats.py): exact reading, round trips that keep
quads and n-gons, the topology of a validated mesh, and one line naming the element for a bad mesh."""

from fractions import Fraction
from pathlib import Path

import pytest

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.lattice import QUAD, TRIANGLE
from symdecomp.schemes.meshfile import PolygonMesh, scheme_for_mesh
from symdecomp.schemes.meshformats import FORMATS, decode_mesh, encode_mesh, read_mesh

MODEL = Path(__file__).resolve().parents[2] / "notebooks" / "data" / "valences-3-5-6.obj"

CUBE_POINTS = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_FACES = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def mixed_mesh() -> PolygonMesh:
    """A quad, a triangle, a pentagon and a hexagon, with dyadic coordinates (exact as doubles too)."""
    points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, Fraction(1, 8)), (Fraction(5, 2), 1, 0), (Fraction(3, 2), 2, 0),
              (Fraction(-1, 2), 2, Fraction(-3, 4)), (Fraction(-1, 1024), Fraction(3, 2), 0), (1, 3, 1)]
    faces = [(0, 1, 2, 3), (1, 4, 5, 6, 2), (3, 2, 6, 9, 7, 8), (3, 8, 0)]
    return PolygonMesh.from_arrays(points, faces, name="mixed")


@pytest.mark.parametrize("fmt", FORMATS)
def test_round_trip_keeps_quads_and_ngons_and_exact_dyadic_coordinates(fmt):
    mesh = mixed_mesh()
    back = decode_mesh(encode_mesh(mesh, fmt), fmt, name=f"mixed.{fmt}")
    assert back.faces == mesh.faces  # sides 4, 5, 6, 3 in the same order and orientation
    assert back.points == mesh.points  # exact: every coordinate is a double
    assert encode_mesh(back, fmt) == encode_mesh(mesh, fmt)  # deterministic bytes


def test_text_coordinates_are_the_rationals_they_spell():
    mesh = decode_mesh(b"v 0.1 -2.5e-3 1E2\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj")
    assert mesh.points[0] == (Fraction(1, 10), Fraction(-1, 400), Fraction(100))
    # written back exactly, and read again to the same rationals
    assert decode_mesh(encode_mesh(mesh, "off"), "off").points == mesh.points


def test_obj_slash_groups_negative_indices_and_ignored_keywords():
    text = b"# a comment\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ns off\nf 1/1/1 2//1 -2/1 -1\n"
    assert decode_mesh(text, "obj").faces == ((0, 1, 2, 3),)


def test_ply_ascii_from_another_writer_is_read():
    text = (b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            b"element face 1\nproperty list uchar int vertex_index\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0.5\n4 0 1 2 3\n")
    mesh = decode_mesh(text, "ply")
    assert mesh.faces == ((0, 1, 2, 3),) and mesh.points[3] == (0, 1, Fraction(1, 2))


def test_shipped_model_has_extraordinary_vertices_of_valence_3_5_and_6():
    mesh = read_mesh(MODEL)
    assert mesh.boundary_vertices() == ()
    assert sorted({mesh.valence(v) for v in mesh.extraordinary_vertices(QUAD)}) == [3, 5, 6]
    # a closed orientable mesh: V - E + F = 2 (a sphere)
    edges = {frozenset((f[k], f[(k + 1) % 4])) for f in mesh.faces for k in range(4)}
    assert len(mesh.points) - len(edges) + len(mesh.faces) == 2
    assert scheme_for_mesh(mesh).name == "catmull-clark"


def test_one_ring_is_counter_clockwise_and_matches_the_faces():
    cube = PolygonMesh.from_arrays(CUBE_POINTS, CUBE_FACES)
    for v in range(8):
        o, a, b = cube.one_ring(v, QUAD)
        n = len(a)
        assert n == cube.valence(v) == 3
        face_sets = {frozenset(f) for f in cube.faces}
        assert all(frozenset((o, a[i], b[i], a[(i + 1) % n])) in face_sets for i in range(n))


def test_split_into_quads_gives_valences_of_the_faces():
    mesh = mixed_mesh().split_into_quads()
    assert mesh.face_sizes() == (4,)
    centres = range(10, 14)  # one per face, in face order
    assert [mesh.valence(c) for c in centres] == [4, 5, 6, 3]
    assert mesh.points[11] == tuple(sum(mixed_mesh().points[v][c] for v in (1, 4, 5, 6, 2)) / 5 for c in range(3))


def test_boundary_vertices_are_not_extraordinary():
    grid = PolygonMesh.from_arrays([(x, y, 0) for y in range(3) for x in range(3)],
                                   [(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)])
    assert grid.boundary_vertices() == (0, 1, 2, 3, 5, 6, 7, 8)
    assert grid.extraordinary_vertices(QUAD) == ()
    with pytest.raises(InvalidMeshError, match="vertex 0 is on the boundary"):
        grid.one_ring(0, QUAD)


def test_the_scheme_must_fit_the_faces():
    cube = PolygonMesh.from_arrays(CUBE_POINTS, CUBE_FACES, name="cube.obj")
    with pytest.raises(InvalidMeshError, match=r"^cube.obj: face 0 is a quad; .* triangle meshes only"):
        cube.extraordinary_vertices(TRIANGLE)
    with pytest.raises(InvalidMeshError, match=r"^mixed: face 0 is a quad and face 1 is a 5-gon, and no scheme takes it"):
        scheme_for_mesh(mixed_mesh())
    pentagons = PolygonMesh.from_arrays([(0, 0, 0), (2, 0, 0), (3, 2, 0), (1, 3, 0), (-1, 2, 0)], [(0, 1, 2, 3, 4)], name="p")
    with pytest.raises(InvalidMeshError, match=r"^p: every face is a 5-gon, .*catmull-clark needs every face a quad"):
        scheme_for_mesh(pentagons)


@pytest.mark.parametrize(("points", "faces", "message"), [
    ([(0, 0, 0), (1, 0, 0), (0, 1)], [(0, 1, 2)], "vertex 2: expected 3 coordinates"),
    ([(0, 0, 0), (1, 0, 0), (0, float("nan"), 0)], [(0, 1, 2)], "vertex 2: coordinate nan is not finite"),
    ([(0, 0, 0), (1, 0, 0), (0, "1", 0)], [(0, 1, 2)], "vertex 2: coordinate '1' is not a real number"),
    ([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2.0)], "face 0: vertex index 2.0 is not an integer"),
    ([(0, 0, 0), (1, 0, 0), (0, 1, 0)], "abc", "faces must be a sequence"),
])
def test_api_input_of_the_wrong_kind_is_named(points, faces, message):
    with pytest.raises(InvalidMeshError, match=message):
        PolygonMesh.from_arrays(points, faces)
