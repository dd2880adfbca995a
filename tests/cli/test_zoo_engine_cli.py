"""The commands reach the zoo's engine when the scheme is a StencilScheme (``is_stencil_scheme``).

Until the scheme files of the zoo are loaded by name, the tests hand the command a StencilScheme built in
Python through the one loader the ``--scheme`` option calls.
"""

import json

import pytest

from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.cli import common, main
from tests.analysis.zoo_engine_schemes import doo_sabin_stencils, sqrt3_stencils

ZOO = {"doo-sabin": doo_sabin_stencils, "sqrt3": sqrt3_stencils}


@pytest.fixture(autouse=True)
def _zoo_names(monkeypatch):
    known = common.load_scheme
    monkeypatch.setattr(common, "load_scheme", lambda name: ZOO[name]() if name in ZOO else known(name))


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_spectrum_json_is_the_engines(capsys):
    out = _json(capsys, ["spectrum", "5", "--scheme", "doo-sabin", "--json"])
    expected = zoo_spectrum(doo_sabin_stencils(), 5).as_json()
    assert out["command"] == "spectrum" and out["eigenvalues"] == expected["eigenvalues"] and out["size"] == 20


@pytest.mark.slow
def test_spectrum_text_says_two_steps(capsys):
    assert main(["spectrum", "5", "--scheme", "sqrt3"]) == 0
    assert "over 2 steps" in capsys.readouterr().out


def test_masks_json(capsys):
    out = _json(capsys, ["masks", "4", "--scheme", "doo-sabin", "--json", "--digits", "8"])
    assert out["subdominant"] == "0.5" and out["position"]["classes"]["0"] == ["0.25"] * 4 and "O" not in out["position"]


def test_check_certify_json(capsys):
    out = _json(capsys, ["check", "--n", "3:5", "--certify", "--scheme", "doo-sabin", "--json", "--quiet"])
    assert [r["n"] for r in out["rows"]] == [3, 4, 5] and {r["status"] for r in out["rows"]} == {"agree"}
    assert out["summary"]["ok"] is True


def test_check_without_certify_is_one_line(capsys):
    assert main(["check", "--n", "3:4", "--scheme", "doo-sabin"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--certify" in err[0]


def test_sharp_options_are_refused_in_one_line(capsys):
    assert main(["spectrum", "3", "--scheme", "doo-sabin", "--boundary"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "boundary" in err[0]


def test_spectrum_text_shows_jordan_blocks(capsys):
    assert main(["spectrum", "6", "--scheme", "doo-sabin"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("0.25 "))
    assert "2+2+1+1+1+1+1" in line and line.rstrip().endswith("1/4")
