"""``symdecomp tune N --region [--plot]``: output, deterministic figures, bad input."""

import json

import pytest

from symdecomp.cli import main
from symdecomp.schemes.files import scheme_to_text
from symdecomp.schemes.scheme import catmull_clark


@pytest.fixture
def free_file(tmp_path):
    text = scheme_to_text(catmull_clark()).replace('a = "3/(2*n**2)"', 'a = "alpha"').replace('b = "1/(4*n**2)"', 'b = "beta"')
    path = tmp_path / "cc-free.toml"
    path.write_text('parameters = ["alpha", "beta"]\n' + text)
    return path


def test_region_json_places_catmull_clark_on_the_bounded_set(free_file, capsys):
    assert main(["tune", "4", "--region", "--scheme", str(free_file), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["c1_test"]["verdict"] == "c1"
    assert data["fixed_vs_lambda1_squared"] == "="
    assert data["regions"]["zero"] == []
    cc = next(p for p in data["points"] if p["name"] == "Catmull-Clark")
    assert cc["values"] == ["3/32", "1/64"] and cc["regime"] == "bounded" and cc["on"] == ["Q(lambda_1^2)"]


def test_region_intervals_one_parameter(tmp_path, capsys):
    path = tmp_path / "loop-free.toml"
    path.write_text('name = "loop-free"\nmesh = "triangle"\nparameters = ["beta"]\n[edge]\nO = "3/8"\n'
                    'a = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }\n[vertex]\nbeta = "beta"\n')
    assert main(["tune", "5", "--region", "--scheme", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    bounded = [i for i in data["intervals"] if i["regime"] == "bounded"]
    assert [i["interval"] for i in bounded] == ["{13/128 - sqrt(5)/128}", "{sqrt(5)/128 + 19/128}"]
    assert {p["name"]: p["regime"] for p in data["points"]} == {"Loop": "bounded", "Warren": "unbounded"}


@pytest.mark.slow
def test_region_text_and_plot_deterministic(free_file, tmp_path, capsys):
    first, second = tmp_path / "a.png", tmp_path / "b.png"
    assert main(["tune", "3", "--region", "--scheme", str(free_file), "--plot", str(first)]) == 0
    out = capsys.readouterr().out
    assert "C1 and curvature tends to zero, a flat spot (|mu| < lambda_1^2):" in out and "Catmull-Clark: (1/6, 1/36)" in out and ": zero" in out
    assert main(["tune", "3", "--region", "--scheme", str(free_file), "--plot", str(second)]) == 0
    assert first.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert first.read_bytes() == second.read_bytes()


@pytest.mark.parametrize("argv, word", [
    (["tune", "5", "--region"], "no free parameters"),
    (["tune", "5", "--plot", "x.png"], "--region"),
    (["tune", "5", "--region", "--plot", "x.svg"], "--plot"),
    (["tune", "5", "--region", "--table"], "--table"),
])
def test_bad_region_input(argv, word, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert word in err and "\n" not in err and "Traceback" not in err


def test_three_parameters_refused(tmp_path, capsys):
    text = scheme_to_text(catmull_clark()).replace('a = "3/(2*n**2)"', 'a = "alpha + gamma"').replace('b = "1/(4*n**2)"', 'b = "beta"')
    path = tmp_path / "three.toml"
    path.write_text('parameters = ["alpha", "beta", "gamma"]\n' + text)
    assert main(["tune", "5", "--region", "--scheme", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert "3 parameters" in err and "\n" not in err
