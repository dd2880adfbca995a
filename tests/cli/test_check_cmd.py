"""``symdecomp check`` and the agreement of ``symdecomp spectrum --json`` with the full matrix."""

import dataclasses
import json

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.closed_forms import derived_closed_forms
from symdecomp.cli import build_parser, check_cmd, main
from symdecomp.schemes.full_matrix import characteristic_polynomial
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.numeric import full_matrix_eigenvalues

CC = catmull_clark()


def _wrong_dominant():
    cf = derived_closed_forms(CC)
    return dataclasses.replace(cf, frequency_k=(cf.frequency_k[0] + sp.Rational(1, 10**40), cf.frequency_k[1]))


def test_certified_range_passes(capsys):
    assert main(["check", "--n", "3:20", "--certify", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "18 valences: 18 agree" in out
    assert "  20  agree" in out


def test_numeric_single_valence_passes(capsys):
    assert main(["check", "--n", "5", "--dps", "25"]) == 0
    assert "1 valences: 1 agree" in capsys.readouterr().out


def test_json_output(capsys):
    assert main(["check", "--n", "3:6", "--certify", "--json", "--jobs", "2"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [row["n"] for row in data["rows"]] == [3, 4, 5, 6]
    assert all(row["status"] == "agree" and row["multiplicities_certified"] for row in data["rows"])
    assert data["rows"][1]["multiplicities"] == [1, 2, 3, 2, 1]
    assert data["summary"]["ok"] is True and data["summary"]["agree"] == 4


@pytest.mark.parametrize("certified", [True, False])
def test_injected_wrong_closed_form_fails_both_modes(capsys, certified):
    argv = ["check", "--n", "3:5", "--jobs", "1"] + (["--certify"] if certified else ["--dps", "50"])
    args = build_parser().parse_args(argv)
    assert check_cmd.run(args, closed_forms=_wrong_dominant()) == 1
    out = capsys.readouterr().out
    assert "FAILED n = 3: closed-form eigenvalue" in out and "FAILED n = 5:" in out
    assert "Eq. 34 dominant" in out


def test_bad_valence_range_is_an_argparse_error(capsys):
    assert main(["check", "--n", "2:5"]) == 2
    assert "valence" in capsys.readouterr().err


def _spectrum_json(n, capsys):
    assert main(["spectrum", str(n), "--json", "--digits", "30"]) == 0
    return json.loads(capsys.readouterr().out)


def _parse(text):
    return mpmath.mpc(complex(text.replace(" ", ""))) if "j" in text else mpmath.mpf(text)


@pytest.mark.parametrize("n", list(range(3, 17)))
def test_spectrum_json_agrees_with_full_matrix_roots(n, capsys):
    """Issue 2: ``spectrum N --json --digits 30`` against the roots of the exact chi_S (Arb), >= 25 digits."""
    data = _spectrum_json(n, capsys)
    chi = characteristic_polynomial(CC, n)
    with flint.ctx.workprec(256):
        roots = []  # (ball, multiplicity in chi_S), every distinct eigenvalue once
        for f, e in chi.numer().factor_squarefree()[1]:
            roots.extend((r, e) for r, _ in f.complex_roots())
        assert len(roots) == len(data["eigenvalues"])
        with mpmath.workdps(60):
            refs = [
                mpmath.mpc(mpmath.mpf(r.real.mid().str(50, radius=False)), mpmath.mpf(r.imag.mid().str(50, radius=False)))
                for r, _ in roots
            ]
            used = set()
            for entry in data["eigenvalues"]:
                v = _parse(entry["value"])
                best = min(range(len(roots)), key=lambda i: abs(refs[i] - v))
                assert abs(refs[best] - v) < mpmath.mpf(10) ** -25 * max(1, abs(v))
                assert entry["multiplicity"] == roots[best][1]
                used.add(best)
            assert len(used) == len(roots)


@pytest.mark.slow
@pytest.mark.parametrize("n", list(range(3, 17)))
def test_spectrum_json_agrees_with_mpmath_eig(n, capsys):
    """Issue 2 again, against mpmath.eig of the full matrix at 60 digits."""
    data = _spectrum_json(n, capsys)
    with mpmath.workdps(60):
        eigs = [mpmath.mpmathify(e) for e in full_matrix_eigenvalues(CC, n, 60)]
        for entry in data["eigenvalues"]:
            v = _parse(entry["value"])
            close = [e for e in eigs if abs(e - v) < mpmath.mpf(10) ** -25]
            assert len(close) == entry["multiplicity"]
        assert sum(e["multiplicity"] for e in data["eigenvalues"]) == 2 * n + 1


@pytest.mark.slow
def test_done_when_certified_3_to_64(capsys):
    assert main(["check", "--n", "3:64", "--certify"]) == 0


@pytest.mark.slow
def test_done_when_numeric_3_to_32_at_60_digits(capsys):
    assert main(["check", "--n", "3:32", "--dps", "60"]) == 0


@pytest.mark.slow
def test_certified_256(capsys):
    assert main(["check", "--n", "256", "--certify"]) == 0


def test_too_few_digits_is_an_argparse_error(capsys):
    assert main(["check", "--n", "3", "--dps", "3"]) == 2
    assert "argument --dps: expected an integer >= 5 and <= 1000, got 3" in capsys.readouterr().err
