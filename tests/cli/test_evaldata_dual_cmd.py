"""symdecomp evaldata --scheme doo-sabin --n A:B: the file evaluates like the API's data; the families without a
biquadratic B-spline part get one line; the file's layout is its format docstring's."""

import json
import re
from fractions import Fraction
from pathlib import Path

import pytest

from symdecomp.analysis.dual_evaldata import dual_evaldata
from symdecomp.analysis.dual_evaluation import evaluate
from symdecomp.cli import main
from symdecomp.errors import EvalDataFileError
from symdecomp.output import dual_evaldata as dual_file
from symdecomp.output.dual_evaldata import read_dual_json
from symdecomp.schemes.stencil_files import load_zoo
from tests.cli.evaldata_refusals import assert_refused

PARAMS = [(Fraction(3, 8), Fraction(5, 16)), (Fraction(0), Fraction(0)), (Fraction(1, 64), Fraction(1, 80)), (Fraction(1), Fraction(1, 2))]
VARIANT = Path(__file__).parents[1] / "corpus" / "zoo" / "doo-sabin-rational-gon.toml"


def test_the_file_evaluates_like_the_api_and_is_deterministic(tmp_path, capsys):
    out, again = tmp_path / "d.json", tmp_path / "e.json"
    assert main(["evaldata", "--scheme", "doo-sabin", "--n", "3:6", "--out", str(out)]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert lines[0].startswith(f"wrote {out}: dual-evaldata (doo-sabin), faces with n = 3..6 sides, {out.stat().st_size} bytes "
                               "(exact rationals and Arb balls; control points: the face and two rings of faces, 27..54 points)")
    assert lines[1] == "not diagonalizable at n = 6: the decomposition over Q holds their Jordan blocks"
    assert main(["evaldata", "--scheme", "doo-sabin", "--n", "3:6", "--out", str(again), "--quiet"]) == 0
    assert out.read_bytes() == again.read_bytes()
    read = read_dual_json(out)
    assert sorted(read) == [3, 4, 5, 6]
    scheme = load_zoo("doo-sabin")
    for n in (3, 6):
        api = dual_evaldata(scheme, n)
        net = [[Fraction(i % 5), Fraction(1, i + 1)] for i in range(api.size)]
        assert [b.factor for b in read[n].decomposition] == [b.factor for b in api.decomposition]
        for u, v in PARAMS:
            assert evaluate(read[n], n - 1, u, v, net) == evaluate(api, n - 1, u, v, net)
    api, net = dual_evaldata(scheme, 5), [[Fraction(i % 7)] for i in range(45)]
    for u, v in PARAMS:
        (a,), (b,) = evaluate(read[5], 2, u, v, net)["point"], evaluate(api, 2, u, v, net)["point"]
        assert a.overlaps(b) and a.rad() < 2.0**-150


def test_json_summary_of_a_user_variant(tmp_path, capsys):
    out = tmp_path / "v.json"
    assert main(["evaldata", "--scheme", str(VARIANT), "--n", "5", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert {k: summary[k] for k in ("format", "scheme", "n", "sizes", "exact", "jordan")} == {
        "format": "dual-evaldata", "scheme": "doo-sabin-rational-gon", "n": [5], "sizes": [45], "exact": [True], "jordan": []}
    assert summary["bytes"] == out.stat().st_size and summary["command"] == "evaldata"


def test_the_layout_is_the_format_docstring_s():
    doc = " ".join(dual_file.__doc__.split())
    top = re.findall(r'"(\w+)"', doc.split("``{", 1)[1].split("}``", 1)[0])
    face = re.findall(r'"(\w+)"', doc.split("Each face: ``{", 1)[1].split("}``", 1)[0])
    entry = dual_file.dual_entry(dual_evaldata(load_zoo("doo-sabin"), 3))
    document = json.loads("".join(dual_file.dual_json_chunks([entry], "doo-sabin", "quad")))
    assert list(document) == [k for k in top if k != "dual"] and document["format"] == "dual-evaldata"
    assert list(entry) == face


@pytest.mark.parametrize("argv, message", [
    (["--scheme", "midedge", "--n", "4"], "evaldata: scheme 'midedge': the new point at (-1/4, 3/4) of a quad face is not "
                                          "the biquadratic B-spline's corner rule"),
    (["--scheme", "sqrt3", "--n", "4"], "evaldata: scheme 'sqrt3' takes sqrt3 steps on the triangle lattice"),
    (["--scheme", "modified-butterfly", "--n", "4"], "evaldata: scheme 'modified-butterfly' is interpolatory"),
    (["--scheme", "doo-sabin", "--n", "3", "--format", "binary"], "--format binary: the binary layout is Stam's Catmull-Clark file"),
    (["--scheme", "doo-sabin", "--n", "3:33"], "--n 33: --scheme doo-sabin takes faces of at most 32 sides"),
    (["--scheme", "doo-sabin", "--crease", "--k", "2"], "--crease: the evaluation data of --scheme doo-sabin"),
    (["--scheme", "doo-sabin"], "--scheme doo-sabin: give --n A:B"),
    (["--scheme", "doo-sabin", "--n", "3", "--jobs", "2"], "--jobs does not apply to --scheme doo-sabin"),
])
def test_bad_input_one_line_exit_2(tmp_path, capsys, argv, message):
    assert_refused(argv, message, tmp_path, capsys)


def test_a_malformed_file_is_one_line(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"format": "dual-evaldata", "cells": [[1, 0], [1, 1], [0, 1]], "scheme": "x",
                               "faces": [{"n": 3, "size": 26, "exact": True}]}))
    with pytest.raises(EvalDataFileError, match=r"malformed dual evaluation data document \(n = 3 with size 26"):
        read_dual_json(bad)
    bad.write_text(json.dumps({"format": "dual-evaldata", "cells": [[1, 0], [1, 1], [0, 1]], "scheme": "x",
                               "faces": [{"n": 3, "size": 27}]}))
    with pytest.raises(EvalDataFileError, match=r"malformed dual evaluation data document \(no key 'exact'\)"):
        read_dual_json(bad)
    other = tmp_path / "other.json"
    other.write_text(json.dumps({"format": "sector-evaldata"}))
    with pytest.raises(EvalDataFileError, match="not a dual evaluation data document"):
        read_dual_json(other)
