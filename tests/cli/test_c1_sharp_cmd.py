"""symdecomp c1 at boundary, corner and crease vertices, as a user runs it."""

import json

import pytest

from symdecomp.cli import main


def test_boundary_range_prints_one_line_per_k(capsys):
    assert main(["c1", "--boundary", "--k", "2:5"]) == 1  # not every k is C1
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "catmull-clark: Zorin's conditions at boundary vertices"
    rows = [line for line in out if line.startswith("boundary k =")]
    assert [r.split(": ")[1] for r in rows] == ["C1 certified", "C1 certified", "undecided", "not C1"]
    assert "tangent of the boundary curve" in rows[3]


def test_blz_scheme_file_json(capsys):
    assert main(["c1", "--scheme", "loop-blz", "--boundary", "--k", "3:4", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)["rows"]
    assert [d["vertex"] for d in data] == ["boundary k = 3", "boundary k = 4"]
    assert all(d["lambdas"] == pytest.approx([0.5, 0.5]) for d in data)
    # k = 3 is Loop's regular boundary, where BLZ's rule is Loop's: certified on the usual ring; at k = 4 the modified
    # edges make that ring's patches other than splines, so the map is certified on the ring past them
    assert all(d["verdict"] == "c1" and d["jacobian_lower_bound"] > 0 and d["opening_over_pi"] == pytest.approx(1.0) for d in data)
    assert "past the modified edges" in data[1]["reason"] and "past the modified edges" not in data[0]["reason"]


def test_catmull_clark_blz_is_c1_at_every_boundary_k_tried(capsys):
    assert main(["c1", "--scheme", "catmull-clark-blz", "--boundary", "--k", "3:5"]) == 0
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("boundary k =")]
    assert [r.split(": ")[1] for r in rows] == ["C1 certified"] * 3 and all("past the modified edges" in r for r in rows)


def test_a_user_scheme_file_with_sharp_rules(tmp_path, capsys):
    # a user's file: Loop with a [sharp] near-edge rule that keeps the first sine mode at 1/2 (BLZ's, written out)
    path = tmp_path / "mine.toml"
    path.write_text('name = "mine"\nmesh = "triangle"\n[edge]\nO = "3/8"\na = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }\n'
                    '[vertex]\nbeta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"\n'
                    '[sharp]\nnear_edge_centre = "1/4 + cos(theta_k)/4"\nnear_edge_end = "1/2 - cos(theta_k)/4"\n')
    assert main(["c1", "--scheme", str(path), "--boundary", "--k", "8"]) == 0
    out = capsys.readouterr().out
    assert "boundary k = 8: C1 certified: lambda_1 = 0.500000, lambda_2 = 0.500000" in out and "past the modified edges" in out


def test_crease_and_corner(capsys):
    assert main(["c1", "--crease", "2,3"]) == 0
    assert "crease 2,3: C1 certified: side 1 (2 faces)" in capsys.readouterr().out
    assert main(["c1", "--corner", "--k", "1", "--angle", "3*pi/2"]) == 1
    assert "corner k = 1, angle 3*pi/2: not C1" in capsys.readouterr().out


@pytest.mark.parametrize("argv, words", [
    (["c1", "--boundary"], "--boundary needs --k"),
    (["c1", "--k", "3"], "--k needs --boundary, --corner or --crease"),
    (["c1", "--n", "5", "--corner", "--k", "2"], "cannot be used together"),
    (["c1", "--boundary", "--corner", "--k", "2"], "cannot be used together"),
    (["c1", "--boundary", "--k", "2", "--angle", "pi/2"], "--angle is the angle of a corner"),
    (["c1", "--crease", "2,3", "--k", "2"], "--k and --crease cannot be used together"),
    (["c1", "--crease", "2"], "expected K1,K2"),
    (["c1", "--corner", "--k", "2", "--angle", "7"], "expected an angle in (0, 2*pi)"),
    (["c1", "--corner", "--k", "0"], "expected an integer >= 1"),
    (["c1", "--boundary", "--k", "10001"], "<= 10000"),
    (["c1", "--corner", "--k", "33", "--angle", "pi/2"], "--k: a corner given an --angle is tested on its dense matrices, faces <= 32"),
    (["c1", "--boundary", "--k", "30:40", "--plot", "map.png"], "--plot: the characteristic map is drawn from the dense matrices, faces <= 32"),
    (["c1", "--crease", "3,100", "--plot", "map.png"], "--plot: the characteristic map is drawn from the dense matrices, faces <= 32"),
    (["c1"], "give --n A:B"),
])
def test_bad_sharp_invocations_are_one_line_and_exit_2(argv, words, capsys):
    try:
        code = main(argv)
    except SystemExit as exc:  # argparse's own errors
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1


def test_darts(capsys):
    """``c1 --dart --k A:B``: Reif's test on the dart's closed fan, the verdict of :func:`c1_dart_test`; bad valences and
    --plot are one-line errors (exit 2)."""
    from symdecomp.schemes.scheme import catmull_clark
    from symdecomp.verify.c1_closed_fan import c1_dart_test

    assert main(["c1", "--dart", "--k", "3:4", "--json", "--quiet"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [(r["n"], r["verdict"], r["reason"]) for r in rows] == [
        (n, "c1", c1_dart_test(catmull_clark(), n).reason) for n in (3, 4)]
    assert main(["c1", "--dart", "--k", "5"]) == 0
    assert "dart n = 5: C1 certified" in capsys.readouterr().out
    for argv, line in ((["c1", "--dart", "--k", "2:4"], "--k: a dart's valence is 3 to 32, got 2:4"),
                       (["c1", "--dart", "--k", "3", "--plot", "x.png"], "--plot: a dart's characteristic map is not drawn"),
                       (["c1", "--dart", "--boundary", "--k", "3"], "--boundary and --dart cannot be used together: give one kind of vertex")):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse's own errors
            code = exc.code
        err = capsys.readouterr().err.strip()
        assert code == 2 and err.count("\n") == 0 and err.endswith(line)
