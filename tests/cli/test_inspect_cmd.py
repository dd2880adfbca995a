"""``symdecomp inspect MESH``: a malformed mesh is exit status 2 and one line naming the element; ``--vertices``: one row
per extraordinary vertex (the kinds' table, coloured outputs and exit codes: ``test_inspect_kinds.py``)."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from symdecomp.cli import main

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "notebooks" / "data" / "valences-3-5-6.obj"

CUBE_V = "".join(f"v {x} {y} {z}\n" for z in (0, 1) for y in (0, 1) for x in (0, 1))
CUBE_F = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def obj(faces, vertices=CUBE_V) -> str:
    return vertices + "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)


def off(faces, vertices) -> str:
    return f"OFF\n{len(vertices)} {len(faces)} 0\n" + "".join(" ".join(map(str, p)) + "\n" for p in vertices) + \
        "".join(" ".join(map(str, (len(f),) + tuple(f))) + "\n" for f in faces)


SQUARE_V = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
PLY_HEADER = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"

#: (file name, content, words the one line must contain): every kind of mesh the command refuses.
MALFORMED = [
    ("model.stl", "solid x\n", "unknown mesh format 'stl'"),
    ("words.obj", SQUARE_V + "v 1 two 3\nf 1 2 3\n", "line 5: 'two' is not a finite decimal number"),
    ("nan.obj", SQUARE_V + "v 1 nan 3\n", "line 5: 'nan' is not a finite decimal number"),
    ("flat.obj", "v 0 0\n", "line 1: a vertex needs 3 coordinates, got 2"),
    ("range.obj", SQUARE_V + "f 1 2 9\n", "line 5: vertex index 9 is out of range"),
    ("zero.obj", SQUARE_V + "f 0 1 2\n", "line 5: vertex index 0 (OBJ indices start at 1)"),
    ("keyword.obj", SQUARE_V + "curv 1 2\n", "line 5: unknown OBJ keyword 'curv'"),
    ("noheader.off", "4 1 0\n0 0 0\n", "line 1: the file must start with the keyword OFF"),
    ("short.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n", "the header announces 4 vertices and 1 faces, the file has 2 and 0 (truncated file)"),
    ("count.off", off([(0, 1, 2, 3)], [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]).replace("4 0 1 2 3", "4 0 1 2"),
     "the face says it has 4 corners but lists 3"),
    ("broken.ply", PLY_HEADER + "end_header\n0 0 0\n", "not a readable PLY file"),
    ("noface.ply", PLY_HEADER + "end_header\n0 0 0\n1 0 0\n0 1 0\n", "a PLY mesh needs 'vertex' and 'face' elements"),
    ("empty.obj", SQUARE_V, "the mesh has no faces"),
    ("two.obj", SQUARE_V + "f 1 2\n", "face 0 has 2 corners; a face needs at least 3 (degenerate face)"),
    ("repeat.obj", SQUARE_V + "f 1 2 2 3\n", "face 0 repeats vertex 1 (degenerate face)"),
    ("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "face 0 (0, 1, 2) has zero area (degenerate face)"),
    ("isolated.obj", SQUARE_V + "v 5 5 5\nf 1 2 3 4\n", "vertex 4 is in no face (isolated vertex)"),
    ("duplicate.obj", obj(CUBE_F + [(3, 1, 0, 2)]), "faces 0 and 6 have the same corners [0, 1, 2, 3] (duplicate face)"),
    ("fin.obj", obj(CUBE_F + [(1, 0, 8, 9)], CUBE_V + "v 0 -1 0\nv 1 -1 0\n"), "edge (0, 1) is shared by 3 faces [0, 2, 6] (non-manifold edge)"),
    ("flipped.obj", obj(CUBE_F[:5] + [(1, 5, 7, 3)]), "faces 2 and 5 both run along edge 1 -> 5 (inconsistent orientation)"),
    ("bowtie.obj", obj([(0, 1, 2), (0, 3, 4)], "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"),
     "vertex 0 joins 2 separate fans of faces (non-manifold vertex)"),
    ("pillow.obj", obj([(0, 1, 2, 3), (0, 3, 4, 1)], SQUARE_V + "v 0.5 0.5 1\n"), "vertex 0 is not analysed: no limit point: a fan judged"),
    ("loop-on-mixed.obj", obj(CUBE_F[:5] + [(1, 3, 7), (1, 7, 5)]), "face 0 is a quad; loop takes triangle meshes only"),
    ("loop-on-quads.obj", obj(CUBE_F), "face 0 is a quad; loop takes triangle meshes only"),
    ("binary.obj", "v 0 0 0\n\udcff", "not a text file"),
]


#: The elements that lenient reading leaves out and lists (exit 1); --strict refuses them in one line (exit 2).
LEFT_OUT = {"isolated.obj", "duplicate.obj", "fin.obj", "flipped.obj", "bowtie.obj", "pillow.obj"}


@pytest.mark.parametrize(("name", "content", "words"), MALFORMED, ids=[m[0] for m in MALFORMED])
def test_a_malformed_mesh_is_one_line_and_exit_2(tmp_path, capsys, name, content, words):
    path = tmp_path / name
    path.write_bytes(content.encode("utf-8", "surrogateescape"))
    extra = ["--scheme", "loop"] if name.startswith("loop") else []
    if name in LEFT_OUT:  # read leniently by default (the rest analysed, exit 1); --strict refuses them
        extra.append("--strict")
    assert main(["inspect", str(path), *extra]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("symdecomp: error: ") and words in err
    if name != "model.stl":
        assert name in err  # the line names the file


def test_the_table_covers_at_least_fifteen_kinds():
    assert len({words for _, _, words in MALFORMED}) >= 15


def test_a_missing_file_and_a_bad_figures_directory_are_named(tmp_path, capsys):
    assert main(["inspect", str(tmp_path / "absent.obj")]) == 2
    assert "absent.obj: cannot read the file" in capsys.readouterr().err
    (tmp_path / "file").write_text("x")
    assert main(["inspect", str(MODEL), "--figures", str(tmp_path / "file")]) == 2
    assert "--figures" in capsys.readouterr().err


def vertex_rows(out: str) -> list[str]:
    """The rows of the ``--vertices`` table (after its header line)."""
    lines = out.splitlines()
    start = next(i for i, line in enumerate(lines) if line.split()[:2] == ["vertex", "n"])
    return lines[start + 1 :]


def test_one_row_per_extraordinary_vertex_of_the_model(capsys):
    assert main(["inspect", str(MODEL), "--vertices"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("valences-3-5-6.obj: 36 vertices, 34 faces; scheme catmull-clark; 36 of 36 vertices analysed in 4 kinds")
    rows = [line.split() for line in vertex_rows(out) if not line.startswith("artifact indicators")]
    assert sorted({int(r[1]) for r in rows}) == [3, 5, 6] and len(rows) == 13
    by_vertex = {int(r[0]): r for r in rows}
    # vertex 11 (valence 5): its limit position from the exact mask, (1/40, -3/200, 47/40)
    assert [float(x) for x in by_vertex[11][2:5]] == [0.025, -0.015, 1.175]


def test_json_has_the_exact_limits_and_the_components(capsys):
    assert main(["inspect", str(MODEL), "--json", "--vertices"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["scheme"] == "catmull-clark" and data["not_analysed"] == {}
    six = next(v for v in data["extraordinary_details"] if v["valence"] == 6)
    assert six["limit_exact"] == ["-12/275", "6/275", "-64/55"] and six["hyperbolic_size"] > 0
    # the 12-gon of a valence-6 1-ring: frequencies 0 and 6 alone, five coplanar pairs (Eq. 6)
    assert [c["frequencies"] for c in six["components"]] == [[0], [1, 11], [2, 10], [3, 9], [4, 8], [5, 7], [6]]


def test_boundary_vertices_are_analysed(tmp_path, capsys):
    """Issue 31: the boundary is no longer skipped ("boundary rules are a later issue" is gone): the corners of a
    2 x 2 grid are corner vertices of one face, the edge midpoints boundary vertices of two faces."""
    grid = "".join(f"v {x} {y} {(x * y) % 3}\n" for y in range(3) for x in range(3))
    (tmp_path / "grid.obj").write_text(obj([(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)], grid))
    assert main(["inspect", str(tmp_path / "grid.obj")]) == 0
    out, err = capsys.readouterr()
    assert "9 of 9 vertices analysed in 3 kinds" in out and err == ""
    assert [line.split()[1:6] for line in out.splitlines()[2:]] == [
        ["boundary", "k", "=", "1,", "corner"], ["boundary", "k", "=", "2", "4"], ["smooth", "n", "=", "4", "1"]]


def fan(n: int) -> str:
    """A 1-ring alone: ``n`` quads around vertex 0 (the only interior vertex), rounded coordinates."""
    import math

    points = [(0, 0, 0.25)] + [(round(math.cos(2 * math.pi * i / n), 3), round(math.sin(2 * math.pi * i / n), 3), 0) for i in range(n)]
    points += [(round(1.4 * math.cos(2 * math.pi * (i + 0.5) / n), 3), round(1.4 * math.sin(2 * math.pi * (i + 0.5) / n), 3),
                round(0.3 * math.cos(4 * math.pi * i / n), 3)) for i in range(n)]
    return obj([(0, 1 + i, 1 + n + i, 1 + (i + 1) % n) for i in range(n)], "".join(f"v {x} {y} {z}\n" for x, y, z in points))


def test_figures_are_written_once_per_vertex_and_deterministic(tmp_path, capsys):
    mesh = tmp_path / "fan.obj"
    mesh.write_text(fan(5))
    (tmp_path / "figs").mkdir()
    (tmp_path / "figs" / "keep.txt").write_text("mine")
    (tmp_path / "figs" / "vertex-99.png").write_bytes(b"old")
    assert main(["inspect", str(mesh), "--figures", str(tmp_path / "figs")]) == 0
    first = {p.name: p.read_bytes() for p in (tmp_path / "figs").iterdir()}
    assert sorted(first) == ["keep.txt", "vertex-0.png"] and first["vertex-0.png"].startswith(b"\x89PNG")
    assert main(["inspect", str(mesh), "--figures", str(tmp_path / "figs")]) == 0
    assert {p.name: p.read_bytes() for p in (tmp_path / "figs").iterdir()} == first


def test_a_user_sees_no_traceback(tmp_path):
    bad = tmp_path / "fin.obj"
    bad.write_text(obj(CUBE_F + [(1, 0, 8, 9)], CUBE_V + "v 0 -1 0\nv 1 -1 0\n"))
    run = subprocess.run([sys.executable, "-m", "symdecomp", "inspect", str(bad), "--strict"], capture_output=True, text=True,
                         cwd=ROOT)
    assert run.returncode == 2 and run.stdout == ""
    assert run.stderr == "symdecomp: error: fin.obj: edge (0, 1) is shared by 3 faces [0, 2, 6] (non-manifold edge)\n"


def test_a_scheme_without_a_tangent_plane_or_a_limit_is_said_so(capsys):
    corpus = ROOT / "tests" / "corpus"
    assert main(["inspect", str(MODEL), "--scheme", str(corpus / "double-one.toml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "double-one at valence 3: the eigenvalue 1 is not simple" in err
    # a subdominant eigenvalue at frequency 2 (valence 5): rows printed (artifact indicators n/a, the reason once), exit 1,
    # one line per valence on stderr
    assert main(["inspect", str(MODEL), "--scheme", str(corpus / "negative-other-root.toml"), "--vertices"]) == 1
    out, err = capsys.readouterr()
    rows = vertex_rows(out)
    assert len(rows) == 13 + 1 and rows[-1].startswith("artifact indicators n/a at valence 3, 5, 6: ")
    assert [line.split(" (")[0] for line in err.splitlines()] == [
        "symdecomp inspect: smooth n = 5: the tangents are not certified the tangent plane's",
        "symdecomp inspect: smooth n = 6: the tangents are not certified the tangent plane's"]


def test_a_triangle_mesh_in_ply_goes_to_loop(tmp_path, capsys):
    """The octahedron: every vertex has valence 4, extraordinary for Loop; by Loop's mask (beta(4) = 31/256,
    chi = 31/220) the limit of (1, 0, 0) is (1 - 4 chi) (1, 0, 0) = (24/55, 0, 0), and the normal is (1, 0, 0)."""
    from symdecomp.schemes.meshfile import PolygonMesh
    from symdecomp.schemes.meshformats import encode_mesh

    points = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    (tmp_path / "octahedron.ply").write_bytes(encode_mesh(PolygonMesh.from_arrays(points, faces), "ply"))
    assert main(["inspect", str(tmp_path / "octahedron.ply"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["scheme"] == "loop" and [v["kind"] for v in data["extraordinary"]] == ["smooth n = 4"] * 6
    assert main(["inspect", str(tmp_path / "octahedron.ply"), "--json", "--exact"]) == 0
    first = json.loads(capsys.readouterr().out)["extraordinary"][0]
    assert first["limit_exact"] == ["24/55", "0", "0"]
    assert first["normal"] == pytest.approx([1, 0, 0], abs=1e-15)


def test_each_vertex_has_its_valences_artifact_indicators(capsys, monkeypatch):
    """The regime, cause, shape and density of each vertex are ``artifact_indicators(catmull_clark(), n)``'s for its
    valence, computed once per valence, and the regime is what |mu| against lambda_1^2 says."""
    import symdecomp.verify.artifacts as artifacts
    from symdecomp.schemes.scheme import catmull_clark

    calls = []
    real = artifacts.artifact_indicators
    monkeypatch.setattr(artifacts, "artifact_indicators", lambda s, n: calls.append(n) or real(s, n))
    assert main(["inspect", str(MODEL), "--json", "--vertices"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert {3, 5, 6} <= set(calls) <= {3, 4, 5, 6} and data["artifacts_not_applicable"] == {}
    for v in data["extraordinary_details"]:
        expected = real(catmull_clark(), v["valence"])
        assert v["artifacts"] == {"regime": expected.curvature.regime.value, "cause": expected.curvature.as_json()["cause"],
                                  "shape": expected.shape_text, "density": expected.density_text}
        curvature = expected.curvature.as_json()
        mu, square = abs(float(curvature["mu"][0]["value"])), float(curvature["lambda1_squared"])
        assert v["artifacts"]["regime"] == ("zero" if mu < square else "unbounded")  # no regular valence 4 in the model
    assert main(["inspect", str(MODEL), "--vertices"]) == 0
    rows = {int(line.split()[0]): line for line in vertex_rows(capsys.readouterr().out)}
    for v in data["extraordinary_details"]:
        a = v["artifacts"]
        assert rows[v["vertex"]].endswith(f"{a['regime']} ({a['cause']})".ljust(24) + f"  {a['density']:<12}  {a['shape']}")


def test_artifact_indicators_not_applicable_say_why_once(capsys):
    """A scheme file whose regular rules are not Catmull-Clark's: n/a per vertex, the reason once (the library's)."""
    from symdecomp.errors import NotApplicableError
    from symdecomp.schemes.files import load_scheme
    from symdecomp.verify.artifacts import artifact_indicators

    path = ROOT / "tests" / "corpus" / "moved.toml"
    with pytest.raises(NotApplicableError) as exc:
        artifact_indicators(load_scheme(str(path)), 3)
    assert main(["inspect", str(MODEL), "--scheme", str(path), "--json", "--vertices"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert all(v["artifacts"] is None for v in data["extraordinary_details"])
    assert data["artifacts_not_applicable"] == {"3": str(exc.value), "5": str(exc.value), "6": str(exc.value)}
    assert main(["inspect", str(MODEL), "--scheme", str(path), "--vertices"]) == 0
    lines = vertex_rows(capsys.readouterr().out)
    assert len(lines) == 13 + 1 and all(line.endswith("n/a") for line in lines[:-1])
    assert lines[-1] == f"artifact indicators n/a at valence 3, 5, 6: {exc.value}"


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(LEFT_OUT))
def test_without_strict_the_rest_is_analysed_and_what_was_left_out_is_listed(tmp_path, name):
    """Issue 31: a mesh with bad elements is analysed around them, the elements listed in --json, exit status 1."""
    content = next(c for n, c, _ in MALFORMED if n == name)
    path = tmp_path / name
    path.write_text(content)
    run = subprocess.run([sys.executable, "-m", "symdecomp", "inspect", str(path), "--json"], capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 1, run.stderr
    data = json.loads(run.stdout)
    assert any(data["defects"].values()) or data["not_analysed"] or data["no_limit"]
