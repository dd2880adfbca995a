"""``symdecomp refine MESH --steps K --out OUT``: exact steps written whole, read back to the same doubles."""

import json
import math

from symdecomp import __version__
from symdecomp.cli import main
from symdecomp.schemes.mesh_refine import refine_mesh
from symdecomp.schemes.meshformats import read_mesh
from symdecomp.schemes.scheme import catmull_clark
from tests.cli.test_inspect_cmd import MODEL
from tests.cli.test_inspect_kinds import read_ply


def test_obj_out_reads_back_as_the_exact_points_rounded_once(tmp_path, capsys):
    out = tmp_path / "r.obj"
    assert main(["refine", str(MODEL), "--steps", "2", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert (summary.pop("command"), summary.pop("version")) == ("refine", __version__)
    assert summary.pop("inputs")["steps"] == 2
    exact = refine_mesh(read_mesh(MODEL), catmull_clark(), 2)
    assert summary == {"mesh": "valences-3-5-6.obj", "scheme": "catmull-clark", "steps": 2, "vertices": len(exact.points),
                       "faces": 16 * 34, "creases": 0, "out": str(out), "bytes": out.stat().st_size}
    back = read_mesh(out)
    assert [tuple(float(c) for c in p) for p in back.points] == [tuple(float(c) for c in p) for p in exact.points]
    assert max(len(line) for line in out.read_text().splitlines()) < 80  # repr doubles, not 55-digit decimals


def test_ply_out_and_the_refined_surface_has_the_same_limits(tmp_path):
    out = tmp_path / "r.ply"
    assert main(["refine", str(MODEL), "--out", str(out)]) == 0
    vertex, faces = read_ply(out.read_bytes())
    assert len(faces) == 4 * 34 and math.isfinite(float(vertex["p"].sum()))


def test_bad_steps_and_out_are_one_line(tmp_path, capsys):
    assert main(["refine", str(MODEL), "--steps", "9", "--out", str(tmp_path / "r.obj")]) == 2
    assert "argument --steps: expected a number of steps <= 8, got 9" in capsys.readouterr().err
    assert main(["refine", str(MODEL), "--out", str(tmp_path / "r.stl")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "give a .obj or .ply file name" in err
    assert not (tmp_path / "r.stl").exists() and not (tmp_path / "r.obj").exists()


CORNERED = """v 0 0 0\nv 2 0 0\nv 4 0 0\nv 0 2 0\nv 2 2 1\nv 4 2 0\nv 1 4 0\nv 3 4 0\nv 2 5 1
f 1 2 5 4\nf 2 3 6 5\nf 4 5 7\nf 5 6 8 9 7
t crease 2/1/0 3 4 3.5
t corner 1/1/0 4 2.5
t interpolateboundary 1/0/0 2
"""


def test_a_tagged_mixed_mesh_keeps_its_corners_and_boundary_rule_in_obj_and_says_what_ply_loses(tmp_path, capsys):
    """Refined once (Catmull-Clark's first step with OpenSubdiv's rules), the corner tag 5/2 is 3/2 and edge-only
    interpolation stays (both were dropped from the OBJ, changing the surface); a PLY says in one line what it lacks."""
    src = tmp_path / "cornered.obj"
    src.write_text(CORNERED)
    out = tmp_path / "r.obj"
    assert main(["refine", str(src), "--steps", "1", "--out", str(out)]) == 0
    back = read_mesh(out)
    exact = refine_mesh(read_mesh(src), catmull_clark(), 1)
    assert dict(back.tags.corners) == {4: 1.5} == exact.corners and back.tags.interpolate_boundary == "edge-only"
    assert sorted(back.tags.creases.values()) == [2.5, 2.5]
    assert main(["inspect", str(out), "--json"]) in (0, 1)
    capsys.readouterr()
    assert main(["refine", str(src), "--steps", "1", "--out", str(tmp_path / "r.ply")]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"symdecomp refine: {tmp_path / 'r.ply'}: PLY holds no sharpness tags: the 2 crease edges, 1 corners "
                   "and the boundary interpolation (edge-only) are not in it (write .obj to keep them)"]
