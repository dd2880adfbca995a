"""symdecomp evaldata --boundary/--corner, as a user runs it: the file evaluates exactly like the API's data."""

import json
from fractions import Fraction

import pytest

from symdecomp.analysis.evaluation import evaluate
from symdecomp.analysis.subpatch_data import sharp_patch_data
from symdecomp.cli import main
from symdecomp.output.evaldata import read_sharp_json
from symdecomp.schemes.loop import loop
from symdecomp.schemes.sector import SharpVertex
from tests.cli.evaldata_refusals import assert_refused


def test_boundary_file_and_summary(tmp_path, capsys):
    out = tmp_path / "b.json"
    assert main(["evaldata", "--boundary", "--k", "1:3", "--out", str(out)]) == 0
    line = capsys.readouterr().out.strip()
    assert line.startswith(f"wrote {out}: sharp-patches (catmull-clark), boundary vertices with K = 1..3 faces")
    data = read_sharp_json(out)
    assert sorted(data) == [("boundary", 1), ("boundary", 2), ("boundary", 3)]
    assert [data[("boundary", k)].size for k in (1, 2, 3)] == [9, 15, 21]


def test_loop_corner_json_summary_matches_the_api(tmp_path, capsys):
    out = tmp_path / "c.json"
    assert main(["evaldata", "--corner", "--k", "4", "--scheme", "loop", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert {k: summary[k] for k in ("format", "scheme", "kind", "k")} == {
        "format": "sharp-patches", "scheme": "loop", "kind": "corner", "k": [4]}
    assert summary["bytes"] == out.stat().st_size
    (read,) = read_sharp_json(out).values()
    api = sharp_patch_data(loop(), SharpVertex.corner(4, "triangle"))
    net = [[Fraction(i % 5), Fraction(1, i + 1)] for i in range(api.size)]
    assert evaluate(read, 3, Fraction(1, 8), Fraction(5, 8), net) == evaluate(api, 3, Fraction(1, 8), Fraction(5, 8), net)


@pytest.mark.parametrize("argv, message", [
    (["--boundary", "--corner", "--k", "2"], "cannot be used together"),
    (["--boundary"], "--boundary needs --k"),
    (["--k", "2"], "--k needs --boundary, --corner or --crease"),
    (["--n", "3:4", "--boundary", "--k", "2"], "--n (interior vertices) and --boundary"),
    (["--corner", "--k", "2", "--digits", "30"], "--digits does not apply"),
    (["--corner", "--k", "2", "--format", "binary"], "--corner writes json"),
    (["--boundary", "--k", "0:2"], "expected an integer >= 1"),
    (["--boundary", "--k", "65"], "<= 64"),
    ([], "give --n 3:N"),
])
def test_bad_input_one_line_exit_2(tmp_path, capsys, argv, message):
    assert_refused(argv, message, tmp_path, capsys)
