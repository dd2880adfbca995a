"""``symdecomp c1`` on a scheme of the zoo: the route its model allows, with --json, and one-line refusals."""

import json

import pytest
import sympy as sp

from symdecomp.cli import common, main
from symdecomp.schemes.stencils import J, KindRules, M, Rule, StencilScheme, Term


def _corner_scheme(name, **kw):
    corner = sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M)
    fields = dict(lattice="quad", topology="dual", kinds=(KindRules("corner", (Rule((Term(corner, over="face"),)),)),))
    return StencilScheme(name, **{**fields, **kw})


ZOO = {"interp": _corner_scheme("interp", lattice="triangle", topology="primal", interpolatory=True), "ds": _corner_scheme("ds")}


@pytest.fixture
def zoo(monkeypatch):
    """``--scheme interp`` and ``--scheme ds`` name the two stencil schemes above (the zoo's files are not read here)."""
    known = common.any_scheme_by_name
    monkeypatch.setattr(common, "any_scheme_by_name", lambda text: ZOO[text] if text in ZOO else known(text))


def test_a_primal_scheme_goes_to_zorins_test_which_names_what_stops_it(zoo, capsys):
    assert main(["c1", "--scheme", "interp", "--n", "3:4", "--json"]) == 1
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [(r["n"], r["verdict"]) for r in rows] == [(3, "undecided"), (4, "undecided")]
    assert rows[0]["reason"] == "the regular rules give no difference bound: a primal scheme needs [vertex] rules"
    assert rows[0]["method"].startswith("Zorin's test")
    assert main(["c1", "--scheme", "interp", "--n", "5"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "interp: C1 by the test its model allows, valences 5..5" and out[1].startswith("method: Zorin's test")
    assert out[2] == "n =   5: undecided: the regular rules give no difference bound: a primal scheme needs [vertex] rules"


def test_refusals_are_one_line(zoo, capsys):
    for argv, text in (
        (["--every-n"], "--every-n: the spectral conditions for every n are not derived for 'interp'"),
        (["--boundary", "--k", "2"], "--boundary: sharp vertices are not tested for 'interp' (a scheme of the zoo)"),
    ):
        assert main(["c1", "--scheme", "interp", *argv]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and text in err[0]


def test_the_dual_route_runs_on_the_engines_neighbourhood(zoo, capsys):
    assert main(["c1", "--scheme", "ds", "--n", "5", "--json"]) == 0
    (row,) = json.loads(capsys.readouterr().out)["rows"]
    assert row["verdict"] == "c1" and row["frequency"] == 1 and row["winding_number"] == 1




def test_the_depth_help_names_zorins_refinement_cap(capsys):
    """``c1 --help`` states the cap Zorin's test puts on ``--depth`` as the test defines it (MAX_REFINEMENT)."""
    from types import SimpleNamespace

    from symdecomp.verify.c1_zorin import MAX_REFINEMENT, depths

    assert main(["c1", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    triadic = depths(SimpleNamespace(dilation=3), None, MAX_REFINEMENT).stop - 1  # sqrt(3)'s two steps: a = 3
    assert f"in Zorin's test, capped at {MAX_REFINEMENT} (at {triadic} for sqrt3," in text
