"""``report`` for a scheme of the zoo: its spectrum (against the whole matrix) and its C1 verdicts."""

from __future__ import annotations

import pytest
import sympy as sp

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.cli import main
from symdecomp.errors import InvalidInputError, InvalidTypeError
from symdecomp.output.report import Table
from symdecomp.output.report_zoo import build_zoo_report
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_to_text
from symdecomp.symbols import lam


def _table(report, title):
    [section] = [s for s in report.sections if s.title == title]
    [table] = [b for b in section.blocks if isinstance(b, Table)]
    return table


def test_doo_sabins_spectrum_rows_are_the_whole_matrixs_eigenvalues():
    """At n = 4 (rational): the rows' eigenvalues and multiplicities are the roots of the whole matrix's charpoly."""
    report = build_zoo_report(load_zoo("doo-sabin"), [4])
    rows = {row[1]: int(row[2]) for row in _table(report, "The spectrum").rows}
    S = sp.Matrix(zoo_matrix(load_zoo("doo-sabin"), 4).matrix)
    assert rows == sp.roots(sp.Poly((lam * sp.eye(S.rows) - S).det(method="berkowitz"), lam))


def test_doo_sabin_is_c1_at_the_valences_of_the_report():
    """The report's C1 rows are the dual route's verdicts: c1, subdominant 1/2, winding number 1."""
    rows = _table(build_zoo_report(load_zoo("doo-sabin"), [3, 5]), "C1 at the extraordinary element").rows
    assert [(r[0], r[1], r[2], r[3]) for r in rows] == [("3", "c1", "0.5", "1"), ("5", "c1", "0.5", "1")]


@pytest.mark.slow
def test_sqrt3_says_two_steps_and_c1_by_zorins_test():
    report = build_zoo_report(load_zoo("sqrt3"), [3])
    [row] = _table(report, "C1 at the extraordinary element").rows
    assert row[1] == "c1" and row[3] == "1" and str(row[4]).startswith("lambda = 0.111111 (frequency 1")  # (1/3)^2
    first = report.sections[0].blocks[0].parts
    assert "after 2 steps: the matrices, spectra and verdicts are those of 2 steps" in first[-1]
    spectrum = {row[1]: int(row[2]) for row in _table(report, "The spectrum").rows if row[0] == "3"}
    assert spectrum[sp.Rational(1, 9)] == 2  # (1/3)^2: the subdominant pair over the two steps


def test_build_zoo_report_refuses_other_input():
    with pytest.raises(InvalidTypeError, match="build_zoo_report takes a scheme of the zoo"):
        build_zoo_report("doo-sabin", [3])
    with pytest.raises(InvalidInputError, match="valences: expected at least one valence"):
        build_zoo_report(load_zoo("doo-sabin"), [])


def test_report_of_a_zoo_file_twice_the_same_bytes(tmp_path, capsys):
    """A user's file in the zoo's format (Midedge renamed) gets the zoo report; the same bytes each time."""
    text = stencil_scheme_to_text(load_zoo("midedge")).replace('name = "midedge"', 'name = "my-midedge"')
    assert 'name = "my-midedge"' in text
    scheme = tmp_path / "mine.toml"
    scheme.write_text(text)
    outs = [tmp_path / "a.html", tmp_path / "b.html"]
    for out in outs:
        assert main(["report", str(scheme), "--n", "4", "--out", str(out), "--quiet"]) == 0
    html = outs[0].read_text()
    assert html == outs[1].read_text()
    assert "Report on the subdivision scheme my-midedge" in html and "giving the scheme" in html
    assert "undecided" in html  # Midedge's regular part is not the biquadratic B-spline: no patch for Reif's test


def test_report_tex_of_a_zoo_scheme_has_no_figures(tmp_path):
    out = tmp_path / "ds.tex"
    assert main(["report", "doo-sabin", "--n", "3", "--out", str(out), "--quiet"]) == 0
    tex = out.read_text()
    assert "\\section{C1 at the extraordinary element}" in tex and "\\includegraphics" not in tex
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ds.tex"]
    assert "Scheme doo-sabin, a dual scheme on the quad lattice" in tex


def test_a_zoo_file_with_a_free_parameter_is_refused_in_one_line(tmp_path, capsys):
    text = stencil_scheme_to_text(load_zoo("doo-sabin")).replace('name = "doo-sabin"', 'name = "ds-a"\nparameters = ["a"]')
    text = text.replace("KroneckerDelta(0, j)/4", "a*KroneckerDelta(0, j)/4 + (1 - a)/(4*m)")
    assert "a*KroneckerDelta" in text
    path = tmp_path / "ds-a.toml"
    path.write_text(text)
    out = tmp_path / "r.html"
    assert main(["report", str(path), "--n", "3", "--out", str(out), "--quiet"]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "symdecomp: error: scheme 'ds-a' has free parameters ['a']; a report needs their values for the spectrum: write "
        "them into the scheme file"]
    assert not out.exists()
