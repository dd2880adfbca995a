"""Issue 24: ``check --certify`` by the structural route by default, the dense one on request; Arb beside mpmath."""

import dataclasses
import json
from pathlib import Path

import pytest
import sympy as sp

from symdecomp.analysis.closed_forms import derived_closed_forms
from symdecomp.analysis.defective import jordan_vertex_weights
from symdecomp.cli import build_parser, check_cmd, main
from symdecomp.cli.check_cmd import check_valences
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import alpha, beta
from symdecomp.verify.arb_numeric import arb_numeric_check
from symdecomp.verify.certify import certify
from symdecomp.verify.numeric import numeric_check
from symdecomp.verify.result import CrossCheckStatus
from symdecomp.verify.structural import certify_structural, structural_obstacle

CC = catmull_clark()
JORDAN = catmull_clark(alpha, beta).substitute(jordan_vertex_weights(catmull_clark(alpha, beta), 5, sp.Rational(3, 8)))
CORPUS = Path(__file__).parents[1] / "corpus"

N_DEPENDENT_EDGE = """
name = "edge-in-n"
[edge]
O = "3/8"
a = { "-1" = "1/16", "0" = "3/8 - 1/(8*n)", "1" = "1/16" }
b = { "-1" = "1/16", "0" = "1/16 + 1/(8*n)" }
[face]
O = "1/4"
a = { "0" = "1/4", "1" = "1/4" }
b = { "0" = "1/4" }
[vertex]
a = "3/(2*n**2)"
b = "1/(4*n**2)"
"""

ALGEBRAIC_VERTEX = N_DEPENDENT_EDGE.replace('name = "edge-in-n"', 'name = "cos-vertex"').replace(
    '"3/8 - 1/(8*n)"', '"3/8"').replace('"1/16 + 1/(8*n)"', '"1/16"').replace(
    'a = "3/(2*n**2)"', 'a = "3/(2*n**2) + (cos(2*pi/n) - cos(2*pi/4))/(64*n)"')


def _wrong(cf, kind):
    k0, k1 = cf.frequency_k
    if kind == "dominant + 1e-40":  # the symmetric functions no longer reduce
        return dataclasses.replace(cf, frequency_k=(k0 + sp.Rational(1, 10**40), k1))
    if kind == "both + 1e-60":  # they reduce, the identity fails
        eps = sp.Rational(1, 10**60)
        return dataclasses.replace(cf, frequency_k=(k0 + eps, k1 + eps))
    if kind == "dominant twice":  # right values, wrong multiplicities
        return dataclasses.replace(cf, frequency_k=(k0, k0))
    zero = list(cf.frequency_zero)
    zero[1] = zero[1] * (1 + sp.Rational(1, 10**30))
    return dataclasses.replace(cf, frequency_zero=tuple(zero))


KINDS = ["dominant + 1e-40", "both + 1e-60", "dominant twice", "Eq. 43 root 2"]


@pytest.mark.parametrize("scheme", [CC, JORDAN, load_scheme(str(CORPUS / "lopsided.toml"))], ids=lambda s: s.name)
def test_dense_and_structural_routes_agree(scheme):
    """Both routes prove the derived closed forms (with the same multiplicities) and refuse every wrong one."""
    cf = derived_closed_forms(scheme)
    for n in (n for n in (3, 4, 5, 8) if n >= scheme.minimum_valence()):
        dense, fast = certify(scheme, n), certify_structural(scheme, n)
        assert dense.status is fast.status is CrossCheckStatus.AGREE, (dense.message, fast.message)
        assert (fast.route, dense.route) == ("structural", "charpoly")
        assert (fast.distinct, fast.multiplicities) == (dense.distinct, dense.multiplicities)
        assert fast.multiplicities_certified == dense.multiplicities_certified
    for kind in KINDS:
        for n in (5, 6):
            wrong = _wrong(cf, kind)
            dense, fast = certify(scheme, n, closed_forms=wrong), certify_structural(scheme, n, closed_forms=wrong)
            assert dense.status is fast.status is CrossCheckStatus.DISAGREE, (kind, n, dense.message, fast.message)
            assert f"n = {n}" in fast.message


def test_injected_wrong_closed_form_fails_on_both_routes_of_the_command(capsys):
    """``run(..., closed_forms=...)``: the old ``--structural`` ignored the closed forms and passed; now both refuse."""
    wrong = _wrong(derived_closed_forms(CC), "dominant + 1e-40")
    for route in ([], ["--route", "charpoly"], ["--structural"]):
        args = build_parser().parse_args(["check", "--n", "3:5", "--certify", "--jobs", "1", "--json", *route])
        assert check_cmd.run(args, closed_forms=wrong) == 1
        rows = json.loads(capsys.readouterr().out)["rows"]
        assert [r["status"] for r in rows] == ["disagree"] * 3
        assert {r["route"] for r in rows} == {"charpoly" if route == ["--route", "charpoly"] else "structural"}
        assert all("Eq. 34 dominant" in r["message"] for r in rows)


def test_default_route_is_structural_and_named(capsys):
    assert main(["check", "--n", "1000", "--certify", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["summary"]["route"] == "structural" and data["summary"]["route_note"] is None
    (row,) = data["rows"]
    assert row["route"] == "structural" and row["distinct"] == 1002 and row["multiplicities_certified"]
    assert main(["check", "--n", "7", "--certify"]) == 0
    out = capsys.readouterr().out
    assert "structural route" in out.splitlines()[0] and "   7  agree" in out and " structural " in out


def test_structural_route_that_does_not_apply_falls_back_and_says_so(tmp_path, capsys):
    path = tmp_path / "edge.toml"
    path.write_text(N_DEPENDENT_EDGE)
    assert "depends on the valence n" in structural_obstacle(load_scheme(str(path)))
    with pytest.raises(NotApplicableError):
        certify_structural(load_scheme(str(path)), 5)
    assert main(["check", "--n", "5:6", "--certify", "--scheme", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["summary"]["route"] == "charpoly" and "does not apply" in data["summary"]["route_note"]
    assert {r["route"] for r in data["rows"]} == {"charpoly"}
    assert main(["check", "--n", "5", "--certify", "--scheme", str(path)]) == 0
    assert "note: the structural certificate does not apply" in capsys.readouterr().out
    for argv, why in ((["--route", "structural"], "--route structural: does not apply"),
                      (["--n", "600"], "the dense route (--route charpoly) goes up to N = 512, got 600")):
        argv = ["check", "--certify", "--scheme", str(path), *argv]
        if "--n" not in argv:
            argv += ["--n", "5"]
        assert main(argv) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and why in err and "Traceback" not in err


@pytest.mark.slow
def test_structural_route_proves_algebraic_centre_weights_exactly(tmp_path, capsys):
    """cos(2 pi/5) in the vertex rule: the dense route needs rational weights (one line, exit 2); the structural
    route compares E_0's characteristic polynomial with the closed forms in Q(zeta_10), and still refutes wrong ones."""
    path = tmp_path / "cos.toml"
    path.write_text(ALGEBRAIC_VERTEX)
    assert main(["check", "--n", "5", "--certify", "--route", "charpoly", "--scheme", str(path)]) == 2
    assert "not rational at n = 5" in capsys.readouterr().err
    assert main(["check", "--n", "5:7", "--certify", "--scheme", str(path), "--json", "--jobs", "1"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [(r["status"], r["route"], r["multiplicities_certified"]) for r in rows] == [("agree", "structural", True)] * 3
    scheme = load_scheme(str(path))
    for kind in KINDS:
        assert certify_structural(scheme, 5, closed_forms=_wrong(derived_closed_forms(scheme), kind)).status is CrossCheckStatus.DISAGREE


@pytest.mark.parametrize("argv, why", [
    (["--n", "600", "--certify", "--route", "charpoly"], "the dense route (--route charpoly) goes up to N = 512, got 600"),
    (["--n", "10001", "--certify"], "<= 10000"),
    (["--n", "129"], "numeric mode goes up to N = 128, got 129"),
    (["--n", "5", "--route", "structural"], "--route: give it with --certify"),
    (["--n", "5", "--certify", "--solver", "flint"], "--certify and --solver cannot be used together"),
    (["--n", "5", "--certify", "--route", "charpoly", "--structural"], "--route and --structural cannot be used together"),
    (["--n", "5", "--solver", "arb"], "invalid choice"),
])
def test_bounds_and_options_are_refused_in_one_line(capsys, argv, why):
    try:
        code = main(["check", *argv])
    except SystemExit as exc:
        code = exc.code
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and why in err, err


@pytest.mark.slow
@pytest.mark.parametrize("scheme", [CC, load_scheme(str(CORPUS / "lopsided.toml"))], ids=lambda s: s.name)
def test_flint_and_mpmath_numeric_routes_agree(scheme):
    for n in (4, 5, 6):
        a, b = numeric_check(scheme, n, dps=30, solver="flint"), numeric_check(scheme, n, dps=30, solver="mpmath")
        assert a.status is b.status is CrossCheckStatus.AGREE, (a.message, b.message)
        assert (a.solver, b.solver) == ("flint", "mpmath")
        assert len(a.matches) == len(b.matches)
        for m in a.matches:  # the same values (to 30 digits) with the same multiplicities
            x = m.eigenvalue
            assert any(abs(x.value - o.eigenvalue.value) < 1e-28 and x.multiplicity == o.eigenvalue.multiplicity for o in b.matches), x.text
    cf = derived_closed_forms(scheme)
    for kind in KINDS:
        wrong = _wrong(cf, kind)
        a, b = numeric_check(scheme, 5, dps=50, closed_forms=wrong, solver="flint"), numeric_check(scheme, 5, dps=50, closed_forms=wrong)
        expected = CrossCheckStatus.AGREE if kind == "both + 1e-60" else CrossCheckStatus.DISAGREE  # 1e-60: below 50 digits
        assert a.status is b.status is expected, (kind, a.message, b.message)


def test_flint_route_never_passes_a_cluster_it_cannot_resolve():
    """A Jordan block (one eigenvector, so no separating discs): undecided, never agree."""
    r = arb_numeric_check(JORDAN, 5, dps=30, max_dps=60)
    assert r.status is CrossCheckStatus.UNDECIDED and not r.ok and "no verdict" in r.message and "--solver mpmath" in r.message
    assert numeric_check(JORDAN, 5, dps=30, solver="mpmath").ok  # matched by the cluster's mean


def test_the_default_solver_hands_what_flint_leaves_undecided_to_mpmath():
    """The command's default: flint, then mpmath for a valence flint cannot decide; the row names the solver that decided."""
    (row,) = check_valences(JORDAN, [5], certified=False, dps=30, solver="auto", show_progress=False)
    assert row.ok and row.solver == "mpmath (flint undecided)"
    assert numeric_check(JORDAN, 5, dps=30, solver="auto").solver == "mpmath (flint undecided)"  # the API's the same
    (row,) = check_valences(catmull_clark(), [5], certified=False, dps=30, solver="auto", show_progress=False)
    assert row.ok and row.solver == "flint"


def test_numeric_command_names_its_solver(capsys):
    assert main(["check", "--n", "3:4", "--dps", "20", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["summary"]["solver"] == "flint" and {r["solver"] for r in data["rows"]} == {"flint"}
    assert main(["check", "--n", "4", "--dps", "20", "--solver", "mpmath"]) == 0
    assert "solver mpmath" in capsys.readouterr().out
    assert main(["check", "--n", "5", "--scheme", "loop", "--json"]) == 0  # the any-scheme route: LAPACK doubles
    data = json.loads(capsys.readouterr().out)
    assert data["summary"]["solver"] == data["rows"][0]["solver"] == "numpy"
    assert main(["check", "--n", "5", "--scheme", "loop", "--solver", "flint"]) == 2
    assert "--solver: the numeric check of triangle schemes" in capsys.readouterr().err


@pytest.mark.slow
def test_done_when_certified_3_to_256_by_the_structural_route(capsys):
    """Issue 24's command: every valence proved, multiplicities certified, each row naming the route."""
    assert main(["check", "--n", "3:256", "--certify", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert len(rows) == 254 and all(r["route"] == "structural" and r["multiplicities_certified"] for r in rows)
