"""symdecomp evaldata --crease, and BLZ's rules at boundaries and corners: the file evaluates like the API's data."""

import json
from fractions import Fraction

import pytest

from symdecomp.analysis.sector_evaldata import sector_evaldata
from symdecomp.analysis.sector_evaluation import evaluate
from symdecomp.cli import main
from symdecomp.output.sector_evaldata import read_sector_json
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from tests.cli.evaldata_refusals import assert_refused

PARAMS = [(Fraction(3, 8), Fraction(5, 16)), (Fraction(0), Fraction(0)), (Fraction(1, 64), Fraction(1, 80))]


def test_crease_file_evaluates_like_the_api_and_is_deterministic(tmp_path, capsys):
    out, again = tmp_path / "c.json", tmp_path / "d.json"
    assert main(["evaldata", "--crease", "--k", "2:3", "--out", str(out)]) == 0
    line = capsys.readouterr().out.strip()
    assert line.startswith(f"wrote {out}: sector-evaldata (catmull-clark), crease vertices with K = 2..3 faces on each side")
    assert main(["evaldata", "--crease", "--k", "2:3", "--out", str(again), "--quiet"]) == 0
    assert out.read_bytes() == again.read_bytes()
    data = read_sector_json(out)
    assert sorted(data) == [("crease", (2, 2)), ("crease", (3, 3))]
    api = sector_evaldata(catmull_clark(), SharpVertex.crease(3, 3, "quad"))
    read = data[("crease", (3, 3))]
    net = [[Fraction(i % 5), Fraction(1, i + 1)] for i in range(api.size)]
    for u, v in PARAMS:
        assert evaluate(read, 4, u, v, net) == evaluate(api, 4, u, v, net)


def test_blz_boundary_balls_contain_the_api_values(tmp_path, capsys):
    out = tmp_path / "b.json"
    assert main(["evaldata", "--boundary", "--k", "3:4", "--scheme", "catmull-clark-blz", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert {k: summary[k] for k in ("format", "scheme", "kind", "k", "exact")} == {
        "format": "sector-evaldata", "scheme": "catmull-clark-blz", "kind": "boundary", "k": [3, 4], "exact": [True, False]}
    assert summary["bytes"] == out.stat().st_size
    read = read_sector_json(out)[("boundary", (4,))]
    api = sector_evaldata(load_scheme("catmull-clark-blz"), SharpVertex.boundary(4, "quad"))
    assert read.modified == api.modified == ((1, 1, 0), (2, 1, 0), (3, 1, 0))
    net = [[Fraction(i % 7)] for i in range(api.size)]
    for u, v in PARAMS:
        (a,), (b,) = evaluate(read, 2, u, v, net)["point"], evaluate(api, 2, u, v, net)["point"]
        assert a.overlaps(b) and a.rad() < 2.0**-150


@pytest.mark.parametrize("argv, message", [
    (["--crease", "--corner", "--k", "2"], "--corner and --crease cannot be used together"),
    (["--crease"], "--crease needs --k"),
    (["--crease", "--k", "1:3"], "--k 1: a crease vertex with K faces on each side needs K >= 2"),
    (["--crease", "--k", "2", "--scheme", "loop"], "the triangle lattice has no \"sector evaluation data"),
    (["--crease", "--k", "2", "--digits", "30"], "--digits does not apply to --crease"),
    (["--crease", "--k", "30:33"], "--k 33: --crease takes at most 32 faces on each side"),
])
def test_bad_input_one_line_exit_2(tmp_path, capsys, argv, message):
    assert_refused(argv, message, tmp_path, capsys)


def test_a_failed_run_keeps_the_old_file(tmp_path, capsys):
    out = tmp_path / "keep.json"
    out.write_text("old")
    assert main(["evaldata", "--crease", "--k", "2", "--scheme", "loop", "--out", str(out)]) == 2
    assert out.read_text() == "old"
