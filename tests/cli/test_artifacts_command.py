"""``symdecomp artifacts``: the table per valence, --json, bad input in one line with exit 2."""

import json
import subprocess
import sys

import pytest

from symdecomp.cli import main
from symdecomp.output.artifact_table import COLUMNS, Column, table


def test_the_table_has_a_row_per_valence_with_the_regime(capsys):
    assert main(["artifacts", "--n", "3:6", "--jobs", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith("catmull-clark:") and lines[1].split()[:4] == ["n", "lambda_1", "lambda_1^2", "mu"]
    rows = {int(line.split()[0]): line.split() for line in lines[2:6]}
    assert rows[3][6:8] == ["zero", "elliptic"] and rows[5][6:8] == ["unbounded", "hyperbolic"]
    assert rows[4][4] == "0,2" and rows[4][5] == "3" and rows[4][6] == "bounded"  # x^2 + y^2 at 0; x^2 - y^2, xy at 2


def test_json_for_loop(capsys):
    assert main(["artifacts", "--n", "5:7", "--scheme", "loop", "--json", "--jobs", "1"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [r["curvature"]["regime"] for r in rows] == ["bounded", "bounded", "unbounded"]
    assert rows[0]["curvature"]["mu"][0]["exact"] is True and rows[1]["density"] == "regular"
    assert float(rows[2]["curvature"]["mu"][0]["value"]) > float(rows[2]["curvature"]["lambda1_squared"])


def test_a_column_is_one_entry():
    rows = [{"n": 3, "x": "a"}, {"n": 10, "x": "bcd"}]
    assert table(rows, [COLUMNS[0], Column("x", lambda r: r["x"])]) == "n   x\n3   a\n10  bcd"


@pytest.mark.slow
def test_bad_valences_are_one_line_and_exit_2():
    for bad in ("2:5", "5:3", "3.0", "x"):
        done = subprocess.run([sys.executable, "-m", "symdecomp", "artifacts", "--n", bad], capture_output=True, text=True)
        assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1 and "--n" in done.stderr
