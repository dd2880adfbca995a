"""Fuzzed mesh texts (OBJ with tags, OFF, ASCII PLY) and face lists: a mesh or one line of InvalidMeshError, never
another exception, in bounded time; the lenient rules leave a mesh that they keep whole. Fast by default; the
wide runs are in the slow set."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes import mesh_obj
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.meshformats import decode_mesh

NUMBERS = st.one_of(st.integers(-3, 3).map(str), st.sampled_from(["0.5", "-1.25e-1", "1e309", "1e9999", "nan", "inf", "0x1p3", "1.7",
                                                                  "+.5", "5.", "1e", "-", "1_0", "9" * 40, "0." + "0" * 1200 + "1"]))
INDICES = st.one_of(st.integers(-6, 8).map(str), st.sampled_from(["1/1/1", "2//3", "1.5", "nan", "99999999999999", "+2", "x"]))
TAGS = st.sampled_from(["t crease 2/1/0 0 1 2", "t crease 2/1/0 0 1 -1", "t corner 1/1/0 0 10", "t hole 1/0/0 0",
                        "t interpolateboundary 1/0/0 1", "t creasemethod 0/0/1 chaikin", "t vertexedit 0/0/0", "t crease 1/1/0",
                        "t", "t crease x/y/z", "t hole 1/0/0 -1"])
OBJ_LINES = st.one_of(
    st.tuples(st.just("v"), NUMBERS, NUMBERS, NUMBERS).map(" ".join),
    st.lists(INDICES, min_size=0, max_size=6).map(lambda xs: " ".join(["f", *xs])),
    TAGS, st.sampled_from(["", "# c", "vt 0 0", "g x", "s off", "curv 1 2", "v 1 2", "v 1 2 3 1", "v 1 2 3 2", "f"]),
)
SETTINGS = {"deadline": 5000, "suppress_health_check": [HealthCheck.too_slow]}


def outcome(data: bytes, fmt: str, strict: bool = False):
    """The mesh, or the message of the one-line refusal (any other exception fails the test)."""
    try:
        return decode_mesh(data, fmt, name=f"fuzz.{fmt}", strict=strict)
    except InvalidMeshError as exc:
        text = str(exc)
        assert "\n" not in text and text.startswith(("fuzz.", "format")), text
        return text


def off_text(draw) -> bytes:
    nv, nf = draw(st.integers(0, 5)), draw(st.integers(0, 4))
    head = draw(st.sampled_from([f"OFF\n{nv} {nf} 0\n", f"OFF {nv} {nf} 0\n", f"OFF\n{nv} {nf}\n", "OFF\n-1 2 0\n"]))
    rows = [" ".join(draw(st.lists(NUMBERS, min_size=2, max_size=4))) for _ in range(nv)]
    rows += [" ".join(draw(st.lists(INDICES, min_size=1, max_size=5))) for _ in range(nf)]
    return (head + "\n".join(rows) + "\n").encode()


def ply_text(draw) -> bytes:
    nv, nf = draw(st.integers(0, 5)), draw(st.sampled_from([0, 1, 2, 3, 10**9]))
    kind = draw(st.sampled_from(["int", "uchar", "float", "double"]))
    head = (f"ply\nformat ascii 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {nf}\nproperty list uchar {kind} vertex_indices\nend_header\n")
    rows = [" ".join(draw(st.lists(NUMBERS, min_size=2, max_size=4))) for _ in range(nv)]
    rows += [" ".join(draw(st.lists(INDICES, min_size=1, max_size=5))) for _ in range(min(nf, 3))]
    return (head + "\n".join(rows) + "\n").encode()


def binary_ply(draw) -> bytes:
    nv, nf = draw(st.sampled_from([0, 1, 3, 4, 2**31])), draw(st.sampled_from([0, 1, 2, 10**9]))
    order = draw(st.sampled_from(["binary_little_endian", "binary_big_endian"]))
    count, kind = draw(st.sampled_from(["uchar", "int", "float"])), draw(st.sampled_from(["int", "uint", "short", "double"]))
    head = (f"ply\nformat {order} 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {nf}\nproperty list {count} {kind} vertex_indices\nend_header\n")
    return head.encode() + draw(st.binary(max_size=120))


@st.composite
def mesh_texts(draw):
    fmt = draw(st.sampled_from(["obj", "obj", "off", "ply", "binary"]))
    if fmt == "binary":
        return "ply", binary_ply(draw)
    if fmt == "obj":
        return fmt, ("\n".join(draw(st.lists(OBJ_LINES, max_size=14))) + "\n").encode()
    return fmt, off_text(draw) if fmt == "off" else ply_text(draw)


def check_texts(case) -> None:
    fmt, data = case
    result = outcome(data, fmt)
    if isinstance(result, PolygonMesh):
        assert isinstance(outcome(data, fmt, strict=True), (PolygonMesh, str))
    if fmt == "obj":  # the fast reader never takes what the line reader refuses, and reads the same
        lines = data.split(b"\n")
        try:
            fast = mesh_obj._fast(lines, "fuzz.obj")
        except (mesh_obj._Irregular, InvalidMeshError):
            return
        slow = mesh_obj._slow(lines, "fuzz.obj")
        assert np.array_equal(fast.floats, slow.floats) and np.array_equal(fast.corners, slow.corners)
        assert np.array_equal(fast.offsets, slow.offsets)


@settings(max_examples=150, **SETTINGS)
@given(mesh_texts())
def test_fuzzed_mesh_texts_read_or_refuse_in_one_line(case):
    check_texts(case)


@pytest.mark.slow
@settings(max_examples=4000, **SETTINGS)
@given(mesh_texts())
def test_fuzzed_mesh_texts_wide(case):
    check_texts(case)


@st.composite
def face_lists(draw):
    count = draw(st.integers(3, 9))
    points = draw(st.lists(st.tuples(*[st.integers(-2, 2)] * 3), min_size=count, max_size=count))
    faces = draw(st.lists(st.lists(st.integers(0, count - 1), min_size=2, max_size=5), min_size=1, max_size=12))
    return points, faces


def check_lenient(case) -> None:
    points, faces = case
    try:
        mesh = PolygonMesh.from_arrays(points, faces, strict=False)
    except InvalidMeshError as exc:
        assert "\n" not in str(exc) and "no face can be kept" in str(exc)
        return
    again = PolygonMesh.from_arrays(points, mesh.faces, strict=False)  # what the rules keep, they keep whole
    assert again.faces == mesh.faces and again.defects.dropped_faces == ()
    kept = set(mesh.face_index.tolist())
    assert kept.isdisjoint(mesh.defects.dropped_faces) and len(kept) + len(mesh.defects.dropped_faces) == len(faces)
    for v in range(len(points)):  # every vertex: in no kept face (listed), or with one fan of faces
        if v in mesh.defects.isolated_vertices:
            assert all(v not in f for f in mesh.faces)
        else:
            assert mesh.valence(v) >= 2


@pytest.mark.slow
@settings(max_examples=200, **SETTINGS)
@given(face_lists())
def test_lenient_reading_leaves_a_mesh_it_keeps_whole(case):
    check_lenient(case)


@pytest.mark.slow
@settings(max_examples=5000, **SETTINGS)
@given(face_lists())
def test_lenient_reading_wide(case):
    check_lenient(case)
