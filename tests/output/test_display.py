"""Results in Jupyter (issue 34, item 2): ``_repr_html_`` short tables, ``_repr_latex_`` through ``symdecomp.aslatex``."""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest
import sympy as sp

import symdecomp
from symdecomp import artifact_indicators, c1_test, catmull_clark, check_claim, closed_form_spectrum, inspect_mesh, limit_masks_at
from symdecomp.errors import InvalidTypeError
from symdecomp.output.display import ROWS_SHOWN, ashtml, notebook_latex
from symdecomp.schemes.meshformats import read_mesh

ROOT = Path(__file__).resolve().parents[2]
CC = catmull_clark()


def _cells(table: str) -> list[list[str]]:
    """The rows of an HTML table, each a list of its cells' text."""
    return [[html.unescape(c) for c in re.findall(r"<t[dh]>(.*?)</t[dh]>", row)] for row in re.findall(r"<tr>(.*?)</tr>", table)]


def test_the_regular_masks_are_typeset_exactly():
    """At the regular valence 4 the position mask is the bicubic B-spline's 4/9, 1/9, 1/36 and lambda_1 = 1/2."""
    masks = limit_masks_at(CC, 4)
    assert masks._repr_latex_() == ("$$\\begin{array}{ll}\n\\text{valence } n & 4 \\\\\n\\lambda_1 & \\frac{1}{2} \\\\\n"
                                    "w_O & \\frac{4}{9} \\\\\nw_a & \\frac{1}{9} \\\\\nw_b & \\frac{1}{36}\n\\end{array}$$")
    rows = _cells(masks._repr_html_())
    assert [r[:2] for r in rows[1:]] == [["lambda_1", "1/2"], ["w_O", "4/9"], ["w_a", "1/9"], ["w_b", "1/36"]]
    assert sp.Rational(rows[2][1]) + 4 * sp.Rational(rows[3][1]) + 4 * sp.Rational(rows[4][1]) == 1  # the weights sum to 1


def test_the_spectrum_table_is_the_spectrum():
    spectrum = closed_form_spectrum(CC, 5)
    rows = _cells(spectrum._repr_html_())
    assert rows[0] == ["value", "mult", "frequencies k"]
    assert rows[1:] == [[e.text, str(e.multiplicity), ", ".join(map(str, e.frequencies))] for e in spectrum.eigenvalues]
    assert sum(int(r[1]) for r in rows[1:]) == 2 * 5 + 1
    assert "<caption>catmull-clark, valence n = 5: 11 eigenvalues, 7 distinct</caption>" in spectrum._repr_html_()
    assert spectrum._repr_latex_() == "$$" + symdecomp.aslatex(spectrum) + "$$"


def test_a_long_table_is_cut_and_counted():
    spectrum = closed_form_spectrum(CC, 40)
    rows = _cells(ashtml(spectrum))
    assert len(spectrum.eigenvalues) > ROWS_SHOWN and len(rows) == 1 + ROWS_SHOWN + 1
    assert rows[-1][0] == f"... {len(spectrum.eigenvalues) - ROWS_SHOWN} more"


def test_c1_verdict_and_its_bounds_escaped():
    result = c1_test(CC, 5)
    table = result._repr_html_()
    assert "|J| &gt;= (certified)" in table and ">=" not in table  # the reason's and the labels' ">=" are escaped
    rows = dict(tuple(r) for r in _cells(table)[1:])
    assert rows["verdict"] == "c1" and rows["winding number"] == "1" and float(rows["|J| >= (certified)"]) > 0
    latex = result._repr_latex_()
    assert latex.startswith("$$\\begin{array}{ll}\n\\text{verdict} & \\text{c1} \\\\\n\\lambda_1 & 0.5499883545")


def test_artifacts_and_a_claim():
    rows = dict(tuple(r) for r in _cells(artifact_indicators(CC, 5)._repr_html_())[1:])
    assert rows["regime"] == "unbounded" and rows["density"] == "sparse"
    result = check_claim("Eq. 34", CC)
    assert dict(tuple(r) for r in _cells(result._repr_html_())[1:])["status"] == "proved"
    latex = result._repr_latex_()
    assert latex.startswith("$$\\begin{array}{ll}\n\\text{status} & \\text{proved}")
    shown = [s for s in result.steps if s.expr is not None][: ROWS_SHOWN - 1]
    assert all(symdecomp.aslatex(s.expr) in latex for s in shown)


def test_a_mesh_inspection_gives_each_vertex_its_exact_limit():
    result = inspect_mesh(read_mesh(ROOT / "notebooks" / "data" / "valences-3-5-6.obj"), CC)
    latex = notebook_latex(result)
    first = result.vertices[0]
    assert f"{first.vertex} & {first.valence} & {symdecomp.aslatex(tuple(first.limit_exact))}" in latex
    rows = _cells(result._repr_html_())
    assert rows[0] == ["vertex", "valence", "limit position", "normal"] and rows[1][:2] == [str(first.vertex), str(first.valence)]


def test_other_objects_are_refused_in_one_line():
    with pytest.raises(InvalidTypeError, match="ashtml cannot render a dict"):
        ashtml({})


@pytest.mark.slow
def test_an_executed_notebook_shows_the_tables():
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(src) for src in (
        f"import sys; sys.path.insert(0, {str(ROOT)!r})\nimport symdecomp as sd",
        "sd.limit_masks_at(sd.catmull_clark(), 4)",
        "sd.c1_test(sd.catmull_clark(), 3)",
    )]
    nbclient.NotebookClient(nb, timeout=120, kernel_name="python3").execute()
    masks, c1 = (cell.outputs[0]["data"] for cell in nb.cells[1:])
    assert masks["text/html"].startswith("<table>") and "\\frac{1}{36}" in masks["text/latex"]
    assert "<td>verdict</td><td>c1</td>" in c1["text/html"] and c1["text/latex"].startswith("$$\\begin{array}")
