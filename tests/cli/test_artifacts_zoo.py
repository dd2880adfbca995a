"""``symdecomp artifacts --scheme <zoo scheme>``: the engine's regimes as text and --json, exit codes, one-line refusals."""

import json

import pytest

from symdecomp.cli import main
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.zoo_artifacts import NOT_COMPUTED, zoo_artifacts


def test_json_rows_are_the_engines(capsys):
    assert main(["artifacts", "--n", "3:4", "--scheme", "sqrt3", "--json", "--quiet", "--jobs", "1"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["command"] == "artifacts" and [r["n"] for r in out["rows"]] == [3, 4]
    scheme = load_zoo("sqrt3")
    assert out["rows"] == [zoo_artifacts(scheme, n).as_json() for n in (3, 4)]
    assert out["rows"][0]["steps"] == 2 and out["rows"][0]["not_computed"] == NOT_COMPUTED


def test_text_says_the_steps_and_what_is_not_computed(capsys):
    assert main(["artifacts", "--n", "3", "--scheme", "sqrt3", "--quiet", "--jobs", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == ("sqrt3: curvature regime and density at the extraordinary element, valences 3..3, over 2 steps "
                        "(the lattice returns after 2)")
    a = zoo_artifacts(load_zoo("sqrt3"), 3)
    assert lines[1].startswith(f"n =   3: {a.regime.value}; lambda_1 = {a.lambda1.exact}, lambda_1^2 = {a.lambda1_squared}, ")
    assert lines[-1] == NOT_COMPUTED


def test_a_midedge_triangle_is_not_applicable_and_exits_0(capsys):
    assert main(["artifacts", "--n", "3", "--scheme", "midedge", "--quiet", "--jobs", "1"]) == 0
    assert "n =   3: not applicable; lambda_1 = -" in capsys.readouterr().out


@pytest.mark.parametrize("argv, text", [
    (["--every-n"], "--every-n: the curvature regime for every n is not derived for 'doo-sabin' (a scheme of the zoo); give --n A:B"),
    ([], "give --n A:B (the valences)"),
])
def test_refusals_are_one_line(capsys, argv, text, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["artifacts", "--scheme", "doo-sabin", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and text in err[0]
    assert not (tmp_path / "regime.png").exists()
