"""``oracle --mesh``: every analysed vertex of whole tagged meshes against OpenSubdiv's limit masks, to 1e-12
(skipped where OpenSubdiv is not installed)."""

import json
import math
from fractions import Fraction

import pytest

from symdecomp.cli import main
from symdecomp.schemes.loop import loop
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.opensubdiv import build as osd_build
from tests.analysis.test_mesh_limits import CREASE, grid, idx

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

from symdecomp.verify.oracle_mesh import compare_mesh  # noqa: E402

THROUGH = {(idx(x, 2), idx(x + 1, 2)): Fraction(10) for x in range(5)}  # a crease across the grid: no dart

CASES = {
    "smooth and boundary": MeshTags(),
    "edge-only boundary": MeshTags(interpolate_boundary="edge-only"),
    "infinite crease": MeshTags(creases=THROUGH),
    "semi-sharp crease 2": MeshTags(creases={e: Fraction(2) for e in THROUGH}),
    "semi-sharp crease 3/2": MeshTags(creases={e: Fraction(3, 2) for e in THROUGH}),
    "corner tag": MeshTags(corners={idx(2, 2): Fraction(10)}),
    "crease into a corner": MeshTags(creases=THROUGH, corners={idx(2, 2): Fraction(10)}),
}


@pytest.mark.parametrize("tags", CASES.values(), ids=CASES.keys())
@pytest.mark.parametrize("triangles", [False, True], ids=["catmull-clark", "loop"])
def test_every_analysed_vertex_agrees_with_opensubdiv(tags, triangles):
    mesh = grid(tags, triangles=triangles)
    r = compare_mesh(mesh, loop() if triangles else catmull_clark())
    assert r.compared > 25 and r.darts == 0
    assert r.position_disagreement <= 1e-12 and r.normal_disagreement <= 1e-12, r
    assert r.agrees


def test_a_dart_is_compared_apart_with_the_reason():
    """OpenSubdiv gives a dart the smooth limit mask: it differs from the dart's eigenvector, so darts stay out of the
    verdict (and are reported with their difference)."""
    r = compare_mesh(grid(MeshTags(creases=CREASE)), catmull_clark())
    assert r.darts == 1 and r.dart_position_disagreement > 1e-6 and r.agrees


def test_the_command_line(tmp_path, capsys):
    from symdecomp.schemes.meshformats import encode_mesh

    path = tmp_path / "grid.obj"
    path.write_bytes(encode_mesh(grid(), "obj"))
    assert main(["oracle", "--mesh", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["agrees"] and data["compared"] == 36 and data["position_disagreement"] <= 1e-12
    assert main(["oracle", "--mesh", str(path), "--kind", "dart"]) == 2
    assert "--mesh: not with --kind" in capsys.readouterr().err


def test_a_sharpness_not_exact_in_single_precision_is_given_to_both_sides_as_opensubdiv_s_float():
    """OpenSubdiv stores t crease ... 0.1 as the float nearest 1/10: both sides get that float (they agree), and the
    count says so; OpenSubdiv's float is exactly what the toolkit analysed."""
    from symdecomp.verify.oracle_mesh import single_precision_tags

    tags = MeshTags(creases={e: Fraction(1, 10) for e in THROUGH}, corners={idx(1, 1): Fraction(7, 10)})
    rounded, count = single_precision_tags(grid(tags))
    assert count == len(THROUGH) + 1
    assert set(rounded.tags.creases.values()) == {Fraction(13421773, 134217728)}
    r = compare_mesh(grid(tags), catmull_clark())
    assert r.rounded_tags == count and r.agrees, r
    exact = MeshTags(creases={e: Fraction(1, 2) for e in THROUGH})
    assert single_precision_tags(grid(exact))[1] == 0


GREGORY = """v 1 1 0\nv 1 0 0\nv 1 -1 0\nv 0 1 0\nv 0 0 1.5\nv 0 -1 0\nv -1 2 0\nv -1 1 0\nv -1 0 1.5\nv -1 -1 0
v -2 2 0\nv -2 1 0\nv -2 0 0\nv -2 -1 0\nvt 0 0\nvn 0 0 1\ns off
f 2/1/1 1/1/1 4/1/1 5/1/1\nf 3/1/1 2/1/1 5/1/1 6/1/1\nf 5/1/1 4/1/1 8/1/1 9/1/1\nf 6/1/1 5/1/1 9/1/1 10/1/1
f 8/1/1 7/1/1 11/1/1 12/1/1\nf 9/1/1 8/1/1 12/1/1 13/1/1\nf 10/1/1 9/1/1 13/1/1 14/1/1
t crease 2/1/0 4 8 0.900000
"""


def test_a_boundary_vertex_of_three_faces_has_its_normal_compared_apart(tmp_path, capsys):
    """OpenSubdiv's gregory_test3 (its syntax: vt, vn, s, t crease with a float sharpness): vertex 7, on the boundary
    with three faces, gets OpenSubdiv's Biermann cross tangent, not its surface's: compared apart, the rest agrees."""
    path = tmp_path / "gregory.obj"
    path.write_text(GREGORY)
    assert main(["oracle", "--mesh", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["agrees"] and data["biermann"] == 1 and data["biermann_normal_disagreement"] > 1e-3
    assert data["rounded_tags"] == 1 and data["darts"] == 2 and data["compared"] == 12


def test_a_control_net_folded_over_keeps_the_surface_s_normal(tmp_path, capsys):
    """OpenSubdiv's val2_foldover, one piece: a flat pentagon with a quad and a triangle folded behind it. The vertex
    area of one ring points against the faces' turn; the normal (one sign per kind) still agrees with OpenSubdiv's
    (it was turned over: 2.0 apart)."""
    path = tmp_path / "fold.obj"
    path.write_text("v 0.8 0 0.6\nv 1.2 0 0.6\nv 1.4 0 1.0\nv 1.0 0 1.4\nv 0.6 0 1.0\nf 1 2 3 4 5\nf 4 3 2 1\nf 4 1 5\n")
    assert main(["oracle", "--mesh", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["agrees"] and data["compared"] == 11 and data["normal_disagreement"] <= 1e-12


def test_a_loop_boundary_vertex_of_four_faces_has_its_normal_compared_apart():
    """Loop's regular boundary vertex has 3 faces; at 4 OpenSubdiv's cross tangent is the general formula's."""
    from symdecomp.schemes.meshfile import PolygonMesh

    points = [(0, 0, 0), (2, 0, Fraction(1, 2)), (2, 2, 1), (0, 2, 0), (-2, 2, Fraction(-3, 10)), (-3, 0, Fraction(7, 10)),
              (1, 4, 0), (-1, 4, 1)]
    faces = [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5), (3, 2, 6), (3, 7, 4), (3, 6, 7)]
    r = compare_mesh(PolygonMesh.from_arrays(points, faces), loop())
    assert r.biermann == 1 and r.biermann_normal_disagreement > 1e-3 and r.agrees, r


def test_smooth_and_infinitely_sharp_kinds_are_taken_at_level_0_semi_sharp_ones_after_the_decay():
    """OpenSubdiv's rounding grows with levels (the car shape: 1.9e-11 in a smooth normal after 6 levels): only the
    kinds with a semi-sharp feature are taken after ceil(s) levels; every vertex still agrees."""
    import numpy as np

    from symdecomp.analysis.mesh_limits import mesh_limits
    from symdecomp.verify.oracle_mesh import _frames, osd_mesh_frames

    mesh = grid(MeshTags(creases={e: Fraction(6) for e in THROUGH}))
    ours = mesh_limits(mesh, catmull_clark())
    frames, base, late = _frames(mesh, catmull_clark(), ours, 6), osd_mesh_frames(mesh, catmull_clark(), 0), \
        osd_mesh_frames(mesh, catmull_clark(), 6)
    for kind in ours.kinds.kinds:
        where = ours.kinds.rings[kind][0]
        expected = base if kind.name == "smooth" or kind.sharpness == math.inf else late
        assert all(np.array_equal(f[where], e[where]) for f, e in zip(frames, expected)), kind
    assert any(k.name == "crease" and k.sharpness == 6 for k in ours.kinds.kinds)
    assert compare_mesh(mesh, catmull_clark()).agrees
