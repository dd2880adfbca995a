"""Reading real meshes (schemes/mesh_obj.py, mesh_ply.py, mesh_topology.py, meshformats.py): OpenSubdiv's tags,
mixed meshes and valence 2, lenient reading, linear-time checks, and the discipline of files (each finding of
issues 31 and 35 that concerns reading meshes)."""

import io
import os
import struct
import sys
from fractions import Fraction

import numpy as np
import pytest

from symdecomp import validate
from symdecomp.errors import InvalidMeshError, ResourceLimitError
from symdecomp.schemes import mesh_obj
from symdecomp.schemes.lattice import QUAD, TRIANGLE
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.meshformats import decode_mesh, encode_mesh, read_mesh

CUBE_V = "".join(f"v {x} {y} {z}\n" for z in (0, 1) for y in (0, 1) for x in (0, 1))
CUBE_F = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def obj(faces, vertices=CUBE_V, tail="") -> bytes:
    """OBJ text in OpenSubdiv's shape style: ``f v/t/n`` corners, ``s off``, then tags."""
    return (vertices + "s off\n" + "".join("f " + " ".join(f"{i + 1}/{i + 1}/{i + 1}" for i in f) + "\n" for f in faces) + tail).encode()


def one_line(exc: pytest.ExceptionInfo) -> str:
    text = str(exc.value)
    assert "\n" not in text
    return text


# -- 1. OBJ with OpenSubdiv's tags ---------------------------------------------------------------


def test_opensubdiv_tags_fill_the_mesh_tags_exactly():
    tags = ("t crease 4/1/0 0 1 1 3 2.5\nt crease 2/1/0 4 5 10.0\nt corner 2/2/0 6 7 0.1 3\nt hole 1/0/0 5\n"
            "t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 smooth\n"
            "t facevaryinginterpolateboundary 1/0/0 3\n")
    mesh = decode_mesh(obj(CUBE_F, tail=tags), "obj", name="cube.obj", strict=True)
    t = mesh.tags
    assert dict(t.creases) == {(0, 1): Fraction(5, 2), (1, 3): Fraction(5, 2), (4, 5): Fraction(10)}
    assert dict(t.corners) == {6: Fraction(1, 10), 7: Fraction(3)}
    assert t.holes == frozenset({5}) and t.interpolate_boundary == "edge-and-corner"
    assert (t.crease_method, t.triangle_subdivision) == ("chaikin", "smooth")
    assert t.sharpness_of_edge(3, 1) == Fraction(5, 2) and t.sharpness_of_edge(0, 7) == 0


def test_interpolateboundary_follows_renderman_and_opensubdiv_and_defaults_to_edge_and_corner():
    assert decode_mesh(obj(CUBE_F), "obj").tags.interpolate_boundary == "edge-and-corner"
    modes = [decode_mesh(obj(CUBE_F, tail=f"t interpolateboundary 1/0/0 {m}\n"), "obj").tags.interpolate_boundary for m in (0, 1, 2)]
    assert modes == ["none", "edge-and-corner", "edge-only"]


@pytest.mark.parametrize(("tail", "words"), [
    ("t vertexedit 4/1/3 5 4 1 0 1 add P value\n", "line 16: tag 'vertexedit': the path at integer 1 does not fit its length 5"),
    ("t faceedit 1/0/1 0 hole\n", "line 16: tag 'faceedit': the path at integer 1 does not fit its length 0"),
    ("t bogus 0/0/0\n", "line 16: unknown tag 'bogus'"),
    ("t crease 2/1/0 0 7 1\n", "line 16: tag 'crease': (0, 7) is not an edge of a face of the file"),
    ("t crease 3/1/0 0 1 2 1\n", "line 16: tag 'crease' takes pairs of vertices"),
    ("t crease 2/1/0 0 1 -1\n", "line 16: tag 'crease': sharpness -1 is negative"),
    ("t crease 2/1/0 0 1\n", "line 16: tag 'crease' announces 3 arguments and has 2"),
    ("t corner 1/1/0 8 1\n", "line 16: tag 'corner': vertex 8 is out of range"),
    ("t hole 1/0/0 6\n", "line 16: tag 'hole': face 6 is out of range"),
    ("t interpolateboundary 1/0/0 3\n", "line 16: tag 'interpolateboundary' with arguments 1/0/0 '3' is malformed"),
    ("t creasemethod 0/0/1 sideways\n", "line 16: tag 'creasemethod' with arguments"),
    ("t corner 1/1/0 1.5 1\n", "line 16: tag argument '1.5' is not an integer"),
    ("curv 0 1 1 2\n", "line 16: unknown OBJ keyword 'curv'"),
])
def test_a_tag_or_keyword_that_would_change_the_surface_is_refused_with_its_line(tail, words):
    with pytest.raises(InvalidMeshError) as exc:
        decode_mesh(obj(CUBE_F, tail=tail), "obj", name="cube.obj")
    assert one_line(exc).startswith("cube.obj: ") and words in str(exc.value)


def test_hierarchical_edits_are_left_out_with_their_line_and_level_and_refused_when_strict():
    tail = "t vertexedit 4/4/3 3 4 1 0 0 0 1 0 add P value\nt faceedit 8/0/1 2 4 1 4 3 0 2 2 hole\n"
    mesh = decode_mesh(obj(CUBE_F, tail=tail), "obj", name="cube.obj")
    assert mesh.defects.hierarchical_edits == ((16, 1), (17, 1)) and mesh.faces == tuple(CUBE_F)
    assert mesh.defects.as_dict()["hierarchical_edits"] == [[16, 1], [17, 1]] and not mesh.defects.is_empty()
    with pytest.raises(InvalidMeshError) as exc:
        decode_mesh(obj(CUBE_F, tail=tail), "obj", name="cube.obj", strict=True)
    assert one_line(exc) == ("cube.obj: line 16: a hierarchical edit (acting at level 1) is left out of the mesh, and strict "
                             "reading refuses to leave anything out")


def test_lines_that_do_not_change_the_surface_are_ignored():
    extra = "mtllib a.mtl\no cube\ng side\nusemtl red\nvt 0 0\nvn 0 0 1\nl 1 2\np 3\ns 1\n# note\n"
    assert decode_mesh(obj(CUBE_F, vertices=CUBE_V + extra), "obj").faces == tuple(CUBE_F)


# -- 2. mixed meshes and valence 2 ---------------------------------------------------------------

#: The cube with its top face split at the diagonal's midpoint 8 into two quads: 8 is interior of valence 2.
VALENCE_2 = CUBE_F[:1] + [(4, 5, 7, 8), (7, 6, 4, 8)] + CUBE_F[2:]
VALENCE_2_V = CUBE_V + "v 0.5 0.5 1\n"


def test_valence_2_is_read_and_refused_where_it_is_analysed():
    mesh = decode_mesh(obj(VALENCE_2, VALENCE_2_V), "obj", name="v2.obj", strict=True)
    assert mesh.valence(8) == 2 and not mesh.is_boundary(8) and 8 in mesh.extraordinary_vertices(QUAD)
    with pytest.raises(InvalidMeshError) as exc:
        mesh.one_ring(8, QUAD)
    assert one_line(exc) == ("v2.obj: vertex 8 is interior with 2 faces (valence 2); the analysis of an extraordinary vertex "
                             "needs valence 3 or more")
    assert mesh.one_ring(0, QUAD) == (0, (1, 4, 2), (5, 6, 3))  # its neighbours are unaffected


def test_a_mixed_mesh_is_read_and_the_ring_needs_only_its_own_faces_of_the_lattice_kind():
    # the cube with one face split into two triangles: the quad vertex 0's ring is a quad ring
    faces = [(0, 2, 3), (0, 3, 1)] + CUBE_F[1:]
    mesh = PolygonMesh.from_arrays([(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)], faces)
    assert mesh.face_sizes() == (3, 4) and mesh.valence(0) == 4 and mesh.valence(3) == 4
    assert mesh.one_ring(6, QUAD) == (6, (2, 4, 7), (0, 5, 3))
    with pytest.raises(InvalidMeshError, match=r"^mesh: face 0 at vertex 0 is a triangle; quad meshes have every face a quad"):
        mesh.one_ring(0, QUAD)
    with pytest.raises(InvalidMeshError, match=r"^mesh: face 2 is a quad; the scheme takes triangle meshes only"):
        mesh.require_lattice(TRIANGLE)


def test_the_valence_bound_is_shared_and_names_the_vertex():
    n = validate.MAX_MESH_VALENCE + 6  # a bipyramid: both apexes interior of valence n
    ring = [(np.cos(2 * np.pi * k / n), np.sin(2 * np.pi * k / n), 0.0) for k in range(n)]
    faces = [(n, k, (k + 1) % n) for k in range(n)] + [(n + 1, (k + 1) % n, k) for k in range(n)]
    mesh = PolygonMesh.from_arrays(ring + [(0, 0, 1), (0, 0, -1)], faces, name="fan")
    assert mesh.valence(n) == n
    with pytest.raises(InvalidMeshError) as exc:
        mesh.one_ring(n, TRIANGLE)
    assert one_line(exc) == f"fan: vertex {n} has valence {n}; a mesh's vertices are analysed up to valence {validate.MAX_MESH_VALENCE}"
    assert validate.check_mesh_valence(validate.MAX_MESH_VALENCE, 0) == validate.MAX_MESH_VALENCE


# -- 3. lenient reading --------------------------------------------------------------------------

FIN = obj(CUBE_F + [(1, 0, 8, 9)], CUBE_V + "v 0 -1 0\nv 1 -1 0\n")


def test_a_non_manifold_edge_keeps_the_first_face_and_the_first_opposite_one():
    with pytest.raises(InvalidMeshError, match=r"^fin.obj: edge \(0, 1\) is shared by 3 faces \[0, 2, 6\] \(non-manifold edge\)$"):
        decode_mesh(FIN, "obj", name="fin.obj", strict=True)
    mesh = decode_mesh(FIN, "obj", name="fin.obj")
    # faces 0 (0 -> 1 reversed: 1 -> 0) and 2 (0 -> 1) are kept, the fin 6 is dropped; its two own vertices are left alone
    assert mesh.faces == tuple(CUBE_F) and mesh.face_index.tolist() == [0, 1, 2, 3, 4, 5]
    d = mesh.defects
    assert (d.non_manifold_edges, d.dropped_faces, d.isolated_vertices) == (((0, 1),), (6,), (8, 9))
    assert mesh.points_array.shape == (10, 3) and mesh.exact_point(9) == (1, -1, 0)  # numbering of the file kept
    with pytest.raises(InvalidMeshError, match="vertex 8 is in no face of the mesh"):
        mesh.valence(8)


def test_a_non_manifold_vertex_keeps_the_fan_of_its_first_face():
    text = obj([(0, 1, 2), (0, 3, 4), (0, 2, 5)], "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nv -1 1 0\n")
    with pytest.raises(InvalidMeshError, match=r"^bow.obj: vertex 0 joins 2 separate fans of faces \(non-manifold vertex\)$"):
        decode_mesh(text, "obj", name="bow.obj", strict=True)
    mesh = decode_mesh(text, "obj", name="bow.obj")
    assert mesh.faces == ((0, 1, 2), (0, 2, 5)) and mesh.defects.non_manifold_vertices == (0,)
    assert mesh.defects.dropped_faces == (1,) and mesh.defects.isolated_vertices == (3, 4)


def test_degenerate_repeated_and_misoriented_faces_are_listed_and_the_rest_kept():
    text = obj(CUBE_F + [(0, 2, 3, 1), (0, 1, 1), (0, 1, 8), (2, 3, 9)], CUBE_V + "v 2 0 0\nv 0 0 -1\n")
    mesh = decode_mesh(text, "obj")
    d = mesh.defects
    # face 6 repeats face 0; 7 repeats a corner; 8 = (0, 1, 8) is flat (exactly: 8 is on the line of 0 and 1);
    # 9 = (2, 3, 9) is a third face at edge (2, 3), running 2 -> 3 as face 0 does
    assert (d.repeated_faces, d.degenerate_faces, d.non_manifold_edges) == ((6,), (7, 8), ((2, 3),))
    assert d.dropped_faces == (6, 7, 8, 9) and mesh.faces == tuple(CUBE_F) and d.isolated_vertices == (8, 9)
    assert d.as_dict()["non_manifold_edges"] == [[2, 3]] and not d.is_empty()
    flipped = decode_mesh(obj(CUBE_F[:5] + [(1, 5, 7, 3)]), "obj")  # the last face turned over: every edge of it runs twice
    assert flipped.defects.misoriented_edges == ((1, 3), (1, 5), (3, 7), (5, 7)) and flipped.defects.dropped_faces == (5,)


def test_from_arrays_is_strict_by_default_and_lenient_on_request():
    points = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)] + [(5, 5, 5)]
    with pytest.raises(InvalidMeshError, match=r"^mesh: vertex 8 is in no face \(isolated vertex\)$"):
        PolygonMesh.from_arrays(points, CUBE_F)
    assert PolygonMesh.from_arrays(points, CUBE_F, strict=False).defects.isolated_vertices == (8,)


def test_coordinates_near_the_double_range_are_checked_exactly_without_warnings():
    import warnings

    big = Fraction(3, 2) * 10**308  # the float products overflow: the exact check decides
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cube = PolygonMesh.from_arrays([(x * big, y * big, z * big) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], CUBE_F)
        flat = PolygonMesh.from_arrays([(0, 0, 0), (big, 0, 0), (-big, 0, 0), (0, big, 0)], [(0, 1, 2), (0, 1, 3)], strict=False)
    assert cube.points_array.max() == float(big) and flat.defects.degenerate_faces == (0,)


def test_a_nearly_flat_face_is_decided_exactly():
    eps = Fraction(1, 10**30)  # far below float64's resolution at 1: the floats cannot tell, the exact check can
    flat = PolygonMesh.from_arrays([(0, 0, 0), (1, 0, 0), (2, 0, 0), (1, -1, 0)], [(0, 1, 2), (0, 3, 1)], strict=False)
    bent = PolygonMesh.from_arrays([(0, 0, 0), (1, eps, 0), (2, 0, 0)], [(0, 1, 2)])
    assert flat.defects.degenerate_faces == (0,) and bent.faces == ((0, 1, 2),)
    assert bent.points_array[1, 1] == 1e-30 and bent.exact_point(1)[1] == eps


# -- 4. scale --------------------------------------------------------------------------------------


def test_one_face_of_100000_corners_is_read_in_linear_time():
    k = 100_000  # main's repeated-corner check was quadratic: about a minute
    angles = 2 * np.pi * np.arange(k) / k
    text = "".join(f"v {np.cos(a):.17g} {np.sin(a):.17g} 0\n" for a in angles) + "f " + " ".join(map(str, range(1, k + 1))) + "\n"
    mesh = decode_mesh(text.encode(), "obj")
    assert mesh.face_sizes() == (k,) and len(mesh.boundary_vertices()) == k


def test_points_are_float64_and_exact_coordinates_come_on_request():
    mesh = decode_mesh(b"v 0.1 -2.5e-3 1E2\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj")
    assert mesh.points_array.dtype == np.float64 and mesh.points_array[0].tolist() == [0.1, -0.0025, 100.0]
    assert mesh.exact_point(0) == (Fraction(1, 10), Fraction(-1, 400), Fraction(100)) == mesh.points[0]


def test_the_memory_estimate_refuses_before_reading(tmp_path, monkeypatch):
    path = tmp_path / "big.obj"
    path.write_bytes(obj(CUBE_F))
    monkeypatch.setattr(validate, "MEMORY_LIMIT", validate.mesh_memory(file_bytes=100))
    words = r"big.obj: reading a mesh file of \d+ bytes would need about 2 KiB of memory, more than the limit of 1 KiB; split the mesh"
    with pytest.raises(ResourceLimitError, match=words):
        read_mesh(path)


# -- 5. the discipline of files ------------------------------------------------------------------


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="POSIX FIFOs")
def test_a_fifo_is_refused_at_once_without_being_opened(tmp_path):
    fifo = tmp_path / "mesh.obj"
    os.mkfifo(fifo)  # opening it for reading would block: no writer
    with pytest.raises(InvalidMeshError) as exc:
        read_mesh(fifo)
    assert one_line(exc) == f"{fifo}: not a regular file (a FIFO); a mesh is read from a regular file or '-'"


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="a character device")
def test_a_device_is_refused_whatever_its_size_says(tmp_path):
    link = tmp_path / "zero.ply"
    link.symlink_to("/dev/zero")
    with pytest.raises(InvalidMeshError, match=r"zero.ply: not a regular file \(a character device\)"):
        read_mesh(link)


def test_standard_input_is_read_with_its_format(monkeypatch):
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(obj(CUBE_F))))
    assert read_mesh("-", "obj").faces == tuple(CUBE_F)
    with pytest.raises(InvalidMeshError, match=r"^-: give the format"):
        read_mesh("-")


def ply_header(fmt: str, vertices: int, faces: int, index: str = "int") -> bytes:
    return (f"ply\nformat {fmt} 1.0\nelement vertex {vertices}\nproperty double x\nproperty double y\nproperty double z\n"
            f"element face {faces}\nproperty list uchar {index} vertex_indices\nend_header\n").encode()


TRIANGLE_ASCII = b"0 0 0\n1 0 0\n0 1 0\n"


@pytest.mark.parametrize(("data", "words"), [
    (ply_header("ascii", 3, 300_000_000) + TRIANGLE_ASCII + b"3 0 1 2\n",
     "announces 300000000 'face' elements, more than the 26 bytes"),
    (ply_header("binary_little_endian", 10**9, 1), "announces 1000000000 'vertex' elements, more than the 0 bytes"),
    (ply_header("binary_little_endian", 3, 1) + struct.pack("<9d", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\x03\x00\x00",
     "the binary data ends inside the face 0 (truncated file)"),
    (ply_header("ascii", 3, 1, "float") + TRIANGLE_ASCII + b"3 0 1 2\n", "the face list 'vertex_indices' has a float type"),
    (ply_header("ascii", 3, 1) + TRIANGLE_ASCII + b"3 0 1.7 2\n", "face 0: vertex index '1.7' is not an integer"),
    (ply_header("ascii", 3, 1) + TRIANGLE_ASCII + b"3 0 nan 2\n", "face 0: vertex index 'nan' is not an integer"),
    (ply_header("ascii", 3, 1) + TRIANGLE_ASCII + b"3 0 inf 2\n", "face 0: vertex index 'inf' is not an integer"),
    (ply_header("ascii", 3, 1) + TRIANGLE_ASCII + b"3 0 -1 2\n", "face 0: vertex index -1 is out of range"),
    (ply_header("ascii", 3, 1) + b"0 0 0\n1 0 0\n0 1e309 0\n3 0 1 2\n", "vertex 2: coordinates [0.0, inf, 0.0] are not finite numbers"),
    (ply_header("binary_little_endian", 3, 1) + struct.pack("<9d", 0, 0, 0, 1, 0, 0, 0, float("nan"), 0) + b"\x03" +
     struct.pack("<3i", 0, 1, 2), "vertex 2: coordinates [0.0, nan, 0.0] are not finite"),
])
def test_a_malformed_ply_is_one_line_before_any_allocation(data, words):
    with pytest.raises(InvalidMeshError) as exc:
        decode_mesh(data, "ply", name="m.ply")
    assert one_line(exc).startswith("m.ply: ") and words in str(exc.value)


def test_binary_ply_of_both_byte_orders_and_mixed_faces_is_read():
    body = struct.pack(">15d", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0)
    faces = b"\x04" + struct.pack(">4i", 0, 1, 2, 3) + b"\x03" + struct.pack(">3i", 1, 4, 2)
    mesh = decode_mesh(ply_header("binary_big_endian", 5, 2) + body + faces, "ply")
    assert mesh.faces == ((0, 1, 2, 3), (1, 4, 2)) and mesh.exact_point(4) == (2, 0, 0)


@pytest.mark.parametrize(("coordinate", "words"), [
    ("1e309", "1e309 is beyond the range of doubles (a mesh coordinate is at most 1.798e+308 in magnitude)"),
    ("1e9999", "1e9999 is beyond the range of doubles"),
    ("-1.8e308", "-1.8e308 is beyond the range of doubles"),
    ("1" * 5000, "a number of 5000 characters (at most 1100)"),
    ("0." + "0" * 4997 + "1", "a number of 5000 characters (at most 1100)"),
    ("0x10", "'0x10' is not a finite decimal number"),
    ("inf", "'inf' is not a finite decimal number"),
])
@pytest.mark.parametrize("fmt", ["obj", "off"])
def test_coordinates_are_finite_and_bounded(coordinate, words, fmt):
    text = (f"OFF\n3 1 0\n0 0 0\n1 0 0\n0 {coordinate} 0\n3 0 1 2\n" if fmt == "off" else
            f"v 0 0 0\nv 1 0 0\nv 0 {coordinate} 0\nf 1 2 3\n")
    with pytest.raises(InvalidMeshError) as exc:
        decode_mesh(text.encode(), fmt, name=f"m.{fmt}")
    assert one_line(exc).startswith(f"m.{fmt}: line {5 if fmt == 'off' else 3}: {words}")


def test_api_coordinates_are_bounded_too():
    with pytest.raises(InvalidMeshError, match=r"^mesh: vertex 2: coordinate of about 309 digits is beyond the range of doubles"):
        PolygonMesh.from_arrays([(0, 0, 0), (1, 0, 0), (0, Fraction(2 * 10**308), 0)], [(0, 1, 2)])
    with pytest.raises(InvalidMeshError, match=r"vertex 2: coordinate of about 5001 digits is beyond the range of doubles"):
        PolygonMesh.from_arrays([(0, 0, 0), (1, 0, 0), (0, Fraction(10**5000), 0)], [(0, 1, 2)])
    with pytest.raises(InvalidMeshError, match=r"^mesh: vertex 1: coordinate nan is not finite"):
        PolygonMesh.from_arrays(np.array([(0, 0, 0), (1, np.nan, 0), (0, 1, 0)]), np.array([(0, 1, 2)]))


def test_obj_negative_indices_are_relative_and_out_of_range_ones_named():
    text = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf 1 3 -1\n"
    assert decode_mesh(text, "obj").faces == ((0, 1, 2), (0, 2, 3))
    with pytest.raises(InvalidMeshError, match=r"^m.obj: line 4: vertex index -4 is out of range \(3 vertices defined before this face\)$"):
        decode_mesh(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nf -4 -2 -1\n", "obj", name="m.obj")
    with pytest.raises(InvalidMeshError, match=r"^m.off: line 6: vertex index -1 is out of range"):
        decode_mesh(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "off", name="m.off")


def test_a_huge_line_is_refused_with_its_number(monkeypatch):
    monkeypatch.setattr(mesh_obj, "MAX_LINE_BYTES", 1000)
    with pytest.raises(InvalidMeshError, match=r"^m.obj: line 2 has more than 1000 bytes$"):
        decode_mesh(b"v 0 0 0\n#" + b"x" * 2000 + b"\nf 1 1 1\n", "obj", name="m.obj")


def test_encode_mesh_writes_what_decode_mesh_reads_back():
    tiny = Fraction(1, 2**5000)  # its exact decimal has 5000 digits: written as the nearest double
    mesh = PolygonMesh.from_arrays([(0, 0, 0), (1 + tiny, 0, 0), (0, 1, 0), (Fraction(1, 3), 2, Fraction(1, 1024))],
                                   [(0, 1, 2), (2, 1, 3)])
    for fmt in ("obj", "off", "ply"):
        back = decode_mesh(encode_mesh(mesh, fmt), fmt, strict=True)
        assert back.faces == mesh.faces
        assert back.exact_point(1)[0] == 1 and back.exact_point(3)[2] == Fraction(1, 1024)
        assert float(back.exact_point(3)[0]) == 1 / 3  # a non-terminating rational: the nearest double (its shortest decimal)


def test_the_fast_reader_and_the_line_reader_agree():
    text = obj(CUBE_F, vertices=CUBE_V.replace("v 1 1 1", "v 1.000 1e0 +1")).replace(b"s off\n", b"")
    lines = text.split(b"\n")
    fast, slow = mesh_obj._fast(lines, "m"), mesh_obj._slow(lines, "m")
    assert np.array_equal(fast.floats, slow.floats) and np.array_equal(fast.corners, slow.corners)
    assert [fast.exact_point(i) for i in range(8)] == [slow.exact_point(i) for i in range(8)]


def test_tags_follow_the_kept_faces_and_are_dropped_with_the_left_out_elements():
    faces = [CUBE_F[0], CUBE_F[0]] + CUBE_F[1:] + [(1, 0, 8, 9)]  # face 1 repeats face 0; face 7 is a fin at edge (0, 1)
    text = obj(faces, CUBE_V + "v 0 -1 0\nv 1 -1 0\n", "t hole 2/0/0 3 7\nt crease 4/1/0 8 9 0 2 3\nt corner 1/1/0 9 1\n")
    mesh = decode_mesh(text, "obj")
    assert mesh.face_index.tolist() == [0, 2, 3, 4, 5, 6] and mesh.tags.holes == frozenset({2})  # file face 3 is kept face 2
    assert dict(mesh.tags.creases) == {(0, 2): 3} and dict(mesh.tags.corners) == {}
    with pytest.raises(InvalidMeshError, match=r"^mesh: faces 0 and 1 have the same corners \[0, 1, 2, 3\] \(duplicate face\)$"):
        decode_mesh(text, "obj", strict=True)


def test_exact_points_are_made_one_by_one_and_equal_a_tuple():
    mesh = decode_mesh(b"v 0.1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj")
    points = mesh.points
    assert len(points) == 3 and not points._made  # nothing made yet
    assert points[-3] == (Fraction(1, 10), 0, 0) and list(points._made) == [0]
    assert points == ((Fraction(1, 10), 0, 0), (1, 0, 0), (0, 1, 0)) == tuple(points) and points[1:] == ((1, 0, 0), (0, 1, 0))
    with pytest.raises(IndexError, match="vertex 3 is not an index 0..2"):
        points[3]


@pytest.mark.parametrize("fmt", ["obj", "off", "ply"])
def test_a_mesh_and_its_tags_travel_to_worker_processes(fmt):
    import pickle

    cube = decode_mesh(obj(CUBE_F, tail="t crease 2/1/0 0 1 2\n"), "obj")
    mesh = decode_mesh(encode_mesh(cube, fmt), fmt)
    back = pickle.loads(pickle.dumps(mesh))
    assert back == mesh and back.one_ring(0, QUAD) == mesh.one_ring(0, QUAD)
    tags = pickle.loads(pickle.dumps(cube.tags))
    assert tags == cube.tags and tags.creases[(0, 1)] == 2


def test_binary_ply_faces_of_several_sizes_and_every_truncation():
    points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0.125), (2.5, 1, 0), (1.5, 2, 0), (-0.5, 2, -0.75), (-1 / 1024, 1.5, 0),
              (1, 3, 1)]
    mesh = PolygonMesh.from_arrays(points, [(0, 1, 2, 3), (1, 4, 5, 6, 2), (3, 2, 6, 9, 7, 8), (3, 8, 0)])
    data = encode_mesh(mesh, "ply")
    assert decode_mesh(data, "ply", strict=True).faces == mesh.faces
    for cut in range(1, 120):  # the data cut anywhere: one line, never another exception
        with pytest.raises(InvalidMeshError, match=r"^m.ply: not a readable PLY file: .*(truncated file|can hold)"):
            decode_mesh(data[:-cut], "ply", name="m.ply")


def test_the_first_models_incidences_and_a_mesh_with_other_points():
    grid = PolygonMesh.from_arrays([(x, y, 0) for y in range(3) for x in range(3)], [(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)])
    topology = grid._topology
    assert topology["next"][4] == {1: 5, 3: 1, 5: 7, 7: 3} and topology["next"][0] == {1: 3, 3: None}  # face (v, a, .., next[a])
    assert topology["boundary"] == frozenset({0, 1, 2, 3, 5, 6, 7, 8}) and topology["directed"][(4, 5)] == 3
    assert topology.get("cache") is None
    moved = grid.with_points([(x, y, x * y) for y in range(3) for x in range(3)])
    assert moved.faces == grid.faces and moved.exact_point(8) == (2, 2, 4)


def test_a_binary_face_announcing_a_huge_list_is_one_line():
    head = (b"ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
            b"element face 1\nproperty list int int vertex_indices\nend_header\n")
    for body in (b" \x00\x00\x00", b"\x00\x00", b"\x7f\xff\xff\xff" + b"\x00" * 8):  # found by the wide fuzz run
        with pytest.raises(InvalidMeshError, match=r"^m.ply: not a readable PLY file: .*(truncated file|can hold)"):
            decode_mesh(head + body, "ply", name="m.ply")
