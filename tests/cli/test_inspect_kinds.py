"""``symdecomp inspect MESH``: the table by neighbourhood kind, exit codes 0/1/2, --strict, mixed meshes, and the coloured
PLY/OBJ and picture parsed back."""

import json
import struct
from fractions import Fraction

import numpy as np
import pytest

from symdecomp.cli import main
from symdecomp.output.colored_mesh import CATEGORY_COLORS
from symdecomp.schemes import meshformats
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.meshformats import encode_mesh
from tests.analysis.test_mesh_limits import N, grid, idx
from tests.cli.test_inspect_cmd import MODEL


def read_ply(data: bytes):
    """A binary PLY of ``inspect --out``: points, colours, quality and faces."""
    head, body = data.split(b"end_header\n", 1)
    lines = head.decode().splitlines()
    V = int(next(line for line in lines if line.startswith("element vertex")).split()[-1])
    F = int(next(line for line in lines if line.startswith("element face")).split()[-1])
    colored = "property uchar red" in lines
    dtype = [("p", "<f8", 3), ("c", "u1", 3), ("q", "<f4")] if colored else [("p", "<f8", 3)]
    vertex = np.frombuffer(body, dtype=dtype, count=V)
    rest, faces = body[vertex.nbytes :], []
    for _ in range(F):
        k = rest[0]
        faces.append(struct.unpack(f"<{k}i", rest[1 : 1 + 4 * k]))
        rest = rest[1 + 4 * k :]
    assert rest == b""
    return vertex, faces


def test_the_model_s_kinds_and_its_coloured_ply(tmp_path, capsys):
    out = tmp_path / "colored.ply"
    assert main(["inspect", str(MODEL), "--out", str(out), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [(k["kind"], k["count"], k["c1"], k["regime"]) for k in data["kinds"]] == [
        ("smooth n = 3", 11, "c1", "zero"), ("smooth n = 4", 23, "c1", "bounded"), ("smooth n = 5", 1, "c1", "unbounded"),
        ("smooth n = 6", 1, "c1", "unbounded")]
    assert data["exit_status"] == 0 and data["not_analysed"] == {} and len(data["extraordinary"]) == 13
    vertex, faces = read_ply(out.read_bytes())
    assert len(vertex) == 36 and len(faces) == 34
    assert {tuple(c) for c in vertex["c"]} == {CATEGORY_COLORS["c1"]} and set(vertex["q"]) == {1.0}
    six = next(v for v in data["extraordinary"] if v["kind"] == "smooth n = 6")
    assert six["limit"] == pytest.approx([-12 / 275, 6 / 275, -64 / 55], abs=1e-15)  # the exact limit, as a double


def test_colour_by_regime_in_obj_and_displacement_as_quality(tmp_path):
    out = tmp_path / "colored.obj"
    assert main(["inspect", str(MODEL), "--out", str(out), "--color-by", "regime"]) == 0
    rows = [line.split() for line in out.read_text().splitlines() if line.startswith("v ")]
    colours = {tuple(round(float(c) * 255) for c in r[4:7]) for r in rows}
    assert colours == {CATEGORY_COLORS["zero"], CATEGORY_COLORS["bounded"], CATEGORY_COLORS["unbounded"]}
    ply = tmp_path / "d.ply"
    assert main(["inspect", str(MODEL), "--out", str(ply), "--color-by", "displacement"]) == 0
    vertex, _ = read_ply(ply.read_bytes())
    assert vertex["q"].min() >= 0 and vertex["q"].max() > 0


def test_a_transient_vertex_gets_its_eventual_kind_s_row_and_its_limit_point(tmp_path, capsys, monkeypatch):
    """Two creases of different sharpness meet at vertex 14: its row is the kind it becomes once they have decayed, with
    that kind's verdicts and the levels; its limit point is computed, so nothing is left out (exit 0). The tagged mesh is
    handed to the command as the reader would."""
    tags = MeshTags(creases={(idx(1, 2), idx(2, 2)): Fraction(1), (idx(2, 2), idx(3, 2)): Fraction(2)})
    monkeypatch.setattr(meshformats, "read_mesh", lambda *args, **kwargs: grid(tags))
    (tmp_path / "tagged.obj").write_text("")
    assert main(["inspect", str(tmp_path / "tagged.obj"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["not_analysed"] == {} and data["no_limit"] == {}
    row = next(r for r in data["kinds"] if r["eventual"] is not None)
    smooth = next(r for r in data["kinds"] if r["kind"] == "smooth n = 4")
    assert (row["kind"], row["eventual"], row["levels"], row["count"]) == ("smooth n = 4 after 2 levels", "smooth n = 4", 2, 1)
    assert (row["c1"], row["regime"], row["on_surface"]) == (smooth["c1"], smooth["regime"], True)
    assert row["c1_reason"].startswith("sharp edges of different sharpness (1, 2) meet there: after 2 levels")
    entry = next(e for e in data["extraordinary"] if e["vertex"] == idx(2, 2))
    assert entry["kind"] == row["kind"] and None not in entry["limit"] and None not in entry["normal"]


def test_a_vertex_without_a_limit_point_is_exit_1_and_strict_refuses_it(tmp_path, capsys, monkeypatch):
    """Under edge-only a boundary vertex of one face (OpenSubdiv's crease rule) is judged by its spectrum: a verdict, no
    limit point here (exit 1, listed with why); ``--strict`` refuses it in one line (exit 2)."""
    monkeypatch.setattr(meshformats, "read_mesh", lambda *args, **kwargs: grid(MeshTags(interpolate_boundary="edge-only")))
    (tmp_path / "edge-only.obj").write_text("")
    assert main(["inspect", str(tmp_path / "edge-only.obj"), "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    corners = [idx(0, 0), idx(N, 0), idx(0, N), idx(N, N)]
    assert sorted(map(int, data["no_limit"])) == corners and data["not_analysed"] == {}
    row = next(r for r in data["kinds"] if r["name"] == "spectrum")
    assert (row["count"], row["c1"], row["faces"], row["closed"]) == (4, "undecided", 1, False)
    assert main(["inspect", str(tmp_path / "edge-only.obj")]) == 1
    assert f"no limit point: 4 vertices ({', '.join(map(str, corners))}): a fan judged by its spectrum" in capsys.readouterr().out
    assert main(["inspect", str(tmp_path / "edge-only.obj"), "--strict"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"--strict: vertex {corners[0]} is not analysed: no limit point: " in err


def test_a_mixed_mesh_takes_catmull_clark_s_first_step(tmp_path, capsys):
    """A quad strip closed by a triangle and a pentagon: after the exact first step their centres are valence-3 and
    valence-5 vertices, named as coming from faces."""
    points = [(0, 0, 0), (2, 0, 0), (4, 0, 1), (0, 2, 0), (2, 2, 1), (4, 2, 0), (1, 4, 0), (3, 4, 1), (5, 3, 0)]
    faces = [(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 6), (4, 5, 8, 7, 6)]
    from symdecomp.schemes.meshfile import PolygonMesh

    (tmp_path / "mixed.obj").write_bytes(encode_mesh(PolygonMesh.from_arrays(points, faces), "obj"))
    assert main(["inspect", str(tmp_path / "mixed.obj"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["refined_first"] and data["faces"] == 4 + 4 + 3 + 5
    assert sorted(data["from_faces"].values()) == [2, 3]
    by_vertex = {e["vertex"]: e["kind"] for e in data["extraordinary"]}
    assert sorted(by_vertex[int(v)] for v in data["from_faces"]) == ["smooth n = 3", "smooth n = 5"]
    assert main(["inspect", str(tmp_path / "mixed.obj")]) == 0
    assert "2 extraordinary points came from faces: vertex" in capsys.readouterr().out


def test_the_picture_and_a_bad_out_name(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    assert main(["inspect", str(MODEL), "--plot", str(tmp_path / "m.png")]) == 0
    assert (tmp_path / "m.png").read_bytes().startswith(b"\x89PNG")
    capsys.readouterr()
    assert main(["inspect", str(MODEL), "--out", str(tmp_path / "m.stl")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "give a .ply or .obj file name" in err


def test_a_fifo_as_out_is_written_not_replaced(tmp_path):
    import os
    import threading

    fifo = tmp_path / "pipe.obj"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(open(fifo, "rb").read()))
    reader.start()
    assert main(["inspect", str(MODEL), "--out", str(fifo)]) == 0
    reader.join(10)
    assert got and got[0].startswith(b"v ") and fifo.is_fifo()


def test_the_memory_estimate_comes_before_reading(tmp_path, capsys, monkeypatch):
    """A mesh whose estimated memory is past the limit is refused before it is read, in one line; a FIFO given as
    the mesh is never opened by the estimate (the reader is the one to refuse it)."""
    import os

    import symdecomp.validate as validate
    from symdecomp.cli.inspect_outputs import MEMORY_PER_FILE_BYTE, memory_note

    monkeypatch.setattr(validate, "MEMORY_LIMIT", 10 * MEMORY_PER_FILE_BYTE["text"])
    monkeypatch.setattr(meshformats, "read_mesh", lambda *a, **k: pytest.fail("read before the estimate"))
    assert main(["inspect", str(MODEL)]) != 0
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "reading" in err and "valences-3-5-6.obj" in err and "memory" in err
    fifo = tmp_path / "mesh.obj"
    os.mkfifo(fifo)
    assert memory_note(fifo) is None  # returns at once: a FIFO is not opened
