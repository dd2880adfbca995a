"""The report's content is the library's: what ``spectrum``, ``masks`` and ``c1`` print, and it obeys the identities
those numbers obey (the eigenvalues sum to the trace of the exact subdivision matrix, the position mask to 1).

Most tests build a few sections only (:func:`build_report` takes the list), at small valences, so that they run
in seconds; the whole document is built by the command's tests (tests/cli/test_report_cmd.py).
"""

from __future__ import annotations

import json
import re
from fractions import Fraction
from pathlib import Path

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.claims import Verbatim
from symdecomp.cli import main
from symdecomp.errors import InvalidInputError, InvalidTypeError, SymdecompError
from symdecomp.output.report import (
    MAX_VALENCES,
    Table,
    build_report,
    c1_section,
    figures_section,
    masks_section,
    scheme_section,
    shape_section,
    spectrum_section,
)
from symdecomp.output.report_html import report_html, tex_math_html
from symdecomp.output.report_tex import report_latex

HOSTILE = "$\\input{/etc/passwd}$ <script>alert(1)</script> \\end{document} % & # _ ^ ~ --> ]]>"


def _rows(report, title: str) -> tuple:
    section = next(s for s in report.sections if s.title == title)
    return next(b for b in section.blocks if isinstance(b, Table)).rows


def _command_json(capsys, *argv) -> object:
    main(list(argv))
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("scheme", [sd.catmull_clark(), sd.loop()], ids=["catmull-clark", "loop"])
def test_spectrum_table_is_spectrum_commands(scheme, capsys):
    """Each valence's rows: the values and multiplicities ``spectrum N`` prints, summing to the trace of the exact matrix."""
    report = build_report(scheme, [3, 5], sections=(spectrum_section,))
    rows = _rows(report, "Spectrum")
    for n in (3, 5):
        mine = [(sp.Float(r[1], 30), int(r[2])) for r in rows if r[0] == str(n)]
        theirs = _command_json(capsys, "spectrum", str(n), "--scheme", scheme.name, "--json")["eigenvalues"]
        assert [m for _, m in mine] == [e["multiplicity"] for e in theirs]
        for (value, _), e in zip(mine, theirs):
            assert abs(value - sp.Float(e["value"], 30)) <= sp.Float(10) ** -9 * max(1, abs(value))
        trace = sd.subdivision_matrix(scheme, n).trace()  # exact: the sum of the eigenvalues with multiplicity
        assert abs(sum(v * m for v, m in mine) - trace) < 1e-8 * (2 * n + 1)


def test_loop_spectrum_exact_values_are_eigenvalues():
    """The exact column of a triangle scheme: each value is a root of the exact 1-ring matrix's characteristic polynomial."""
    report = build_report(sd.loop(), [5], sections=(spectrum_section,))
    matrix = sd.subdivision_matrix(sd.loop(), 5)
    lam = sp.Symbol("lam")
    charpoly = matrix.charpoly(lam).as_expr()
    for row in _rows(report, "Spectrum"):
        assert sp.simplify(charpoly.subs(lam, row[4])) == 0
        assert abs(sp.N(row[4], 20) - sp.Float(row[1], 20)) < 1e-9


@pytest.mark.parametrize("scheme", [sd.catmull_clark(), sd.loop()], ids=["catmull-clark", "loop"])
def test_masks_are_masks_commands(scheme, capsys):
    """The weights are ``masks N --digits 6``'s, and the position mask sums to 1."""
    report = build_report(scheme, [4, 5], sections=(masks_section,))
    rows = _rows(report, "Limit and tangent masks")
    for n in (4, 5):
        position = next(r for r in rows if r[0] == str(n))
        data = _command_json(capsys, "masks", str(n), "--scheme", scheme.name, "--digits", "6", "--json")
        assert position[1] == data["subdominant"]
        assert str(position[2]) == "certified subdominant" and data["lambda_1_subdominant"] is True
        weights = [float(w) for w in re.findall(r"-?\d+\.\d+(?:e-?\d+)?", position[3])]
        assert weights[0] == float(data["position"]["O"])
        assert abs(sum(weights) - 1) < 1e-4  # O + the n weights of each class, six digits each


@pytest.mark.parametrize("scheme", [sd.catmull_clark(), sd.loop()], ids=["catmull-clark", "loop"])
def test_c1_table_is_c1_commands(scheme, capsys):
    report = build_report(scheme, [3, 4, 5], sections=(c1_section,))
    rows = _rows(report, "C1 at the extraordinary vertex")
    theirs = _command_json(capsys, "c1", "--n", "3:5", "--scheme", scheme.name, "--json", "--jobs", "1")["rows"]
    assert [(r[0], r[1], str(r[4])) for r in rows] == [(str(t["n"]), t["verdict"], t["reason"]) for t in theirs]
    assert all(abs(float(r[2]) - t["lambda"]) < 1e-9 for r, t in zip(rows, theirs))


def test_closed_forms_evaluate_to_the_table():
    """The displayed closed forms of Eq. 34, evaluated at c = cos(pi/n), are the table's frequency-1 eigenvalues."""
    report = build_report(sd.catmull_clark(), [5], sections=(spectrum_section,))
    blocks = report.sections[0].blocks
    formulas = {str(b.lhs): b.expr for b in blocks if hasattr(b, "lhs")}
    rows = _rows(report, "Spectrum")
    frequency_one = [sp.Float(r[1], 20) for r in rows if "1" in r[3].split(", ")]
    c = sd.symbols.cos_jtheta
    for name in ("lambda_k^+", "lambda_k^-"):
        value = sp.N(formulas[name].subs(c, sp.cos(sp.pi / 5)), 20)
        assert min(abs(value - v) for v in frequency_one) < 1e-9


@pytest.mark.parametrize("scheme", [sd.catmull_clark(), sd.loop()], ids=["catmull-clark", "loop"])
def test_shape_table_is_artifacts_commands(scheme, capsys):
    """The rows are ``artifacts --json``'s: regime, mu to the 6 digits shown, its frequency; and the regime is what
    |mu| against lambda_1^2 says (bounded: equal, zero: below, unbounded: above);
    the regular valence bounded, regular density, spacing 1."""
    report = build_report(scheme, [3, 4, 5, 6], sections=(shape_section,))
    header = report.sections[0].blocks[1].header
    rows = [dict(zip(header, (str(c) for c in r))) for r in _rows(report, "Curvature and shape")]
    theirs = _command_json(capsys, "artifacts", "--n", "3:6", "--scheme", scheme.name, "--json", "--jobs", "1")["rows"]
    assert [r["$n$"] for r in rows] == [str(t["n"]) for t in theirs]
    for mine, t in zip(rows, theirs):
        curvature = t["curvature"]
        assert mine["regime"] == curvature["regime"] and mine["cause"] == (curvature["cause"] or "-")
        assert mine["freq"] == ",".join("outer" if e["frequency"] is None else str(e["frequency"]) for e in curvature["mu"])
        mu = float(mine["$\\mu$"].rstrip("?"))
        assert abs(mu - float(curvature["mu"][0]["value"])) <= 5e-6 * abs(mu)
        square = float(mine["$\\lambda_1^2$"])
        assert abs(float(mine["$\\lambda_1$"]) ** 2 - square) <= 1e-5 * square
        if mine["regime"] == "unbounded":
            assert abs(mu) > square
        elif mine["regime"] == "zero":
            assert abs(mu) < square
        else:
            assert mine["regime"] == "bounded" and abs(abs(mu) - square) <= 1e-5 * square
        if t["n"] == scheme.lattice.regular_valence:
            assert mine["regime"] == "bounded" and mine["density"] == "regular" and mine["spacing"] == "1"


def test_shape_section_draws_the_height_field():
    report = build_report(sd.catmull_clark(), [3, 5], sections=(shape_section,))
    figure = report.sections[0].blocks[-1]
    assert figure.name == "height-field" and len(figure.figure.axes) >= 2  # a panel per valence shown (and colour bars)


@pytest.fixture(scope="module")
def hostile_report():
    scheme = sd.catmull_clark()
    hostile = sd.Scheme(HOSTILE, scheme.edge_rule, scheme.face_rule, scheme.vertex_rule)
    return build_report(hostile, [3], sections=(scheme_section, c1_section, figures_section))


@pytest.mark.slow
def test_hostile_name_is_text_in_latex(hostile_report):
    tex, figures = report_latex(hostile_report)
    assert "\\input{" not in tex and "\\end{document} %" not in tex
    assert tex.count("\\end{document}") == 1 and tex.rstrip().endswith("\\end{document}")
    assert "\\$\\textbackslash{}input\\{" in tex
    assert all(b"passwd" not in data for data in figures.values())


def test_hostile_name_is_text_in_html(hostile_report):
    page = report_html(hostile_report)
    assert "<script>" not in page and "passwd}$ &lt;script&gt;alert(1)&lt;/script&gt;" in page
    assert "--> ]]>" not in page
    assert page.count("<!--") == page.count("-->")


@pytest.mark.slow
def test_html_twice_the_same():
    """Two builds, fresh figures each time: the same bytes (no random SVG ids, no dates)."""
    first = build_report(sd.loop(), [3], sections=(scheme_section, shape_section, figures_section))
    second = build_report(sd.loop(), [3], sections=(scheme_section, shape_section, figures_section))
    assert report_html(first) == report_html(second) == report_html(first)  # saved again: laid out once, not again


@pytest.mark.slow
def test_latex_twice_the_same():
    first = build_report(sd.loop(), [3, 4], sections=(scheme_section, figures_section))
    second = build_report(sd.loop(), [3, 4], sections=(scheme_section, figures_section))
    assert report_latex(first) == report_latex(second)


def test_html_figures_are_inline_svg_with_their_own_ids():
    page = report_html(build_report(sd.loop(), [3], sections=(figures_section,)))
    ids = re.findall(r'\bid="([^"]+)"', page)
    assert len(ids) == len(set(ids)) > 0
    assert "<?xml" not in page and page.count("<svg") == page.count("</svg>") >= 2
    for ref in set(re.findall(r'(?:href="#|url\(#)([^")]+)', page)):
        assert ref in ids


def test_tex_math_html():
    assert tex_math_html("A^{2n-j}") == '<span class="m">A<sup>2n-j</sup></span>'
    assert tex_math_html("x_ij") == '<span class="m">x<sub>i</sub>j</span>'
    assert tex_math_html("\\unknown<") == '<span class="m">unknown&lt;</span>'


@pytest.mark.parametrize("valences, error", [
    ([2], InvalidInputError), ([MAX_VALENCES + 1], InvalidInputError), ([], InvalidInputError),
    ([3.0], SymdecompError), ([Fraction(3)], SymdecompError), ("3", InvalidInputError), (None, InvalidInputError),
])
def test_bad_valences(valences, error):
    with pytest.raises(error):
        build_report(sd.catmull_clark(), valences, sections=())


@pytest.mark.parametrize("scheme", [None, "catmull-clark", 5])
def test_bad_scheme(scheme):
    with pytest.raises((InvalidTypeError, InvalidInputError)):
        build_report(scheme, [3], sections=())


def test_report_name_is_verbatim():
    assert isinstance(build_report(sd.loop(), [3], sections=()).scheme, Verbatim)


def test_scheme_beyond_reifs_test_says_so(capsys):
    """A scheme whose regular patches are not splines the C1 test knows: the section says why, as ``c1`` does (exit 2)."""
    lopsided = sd.schemes.files.load_scheme(str(Path(__file__).resolve().parents[1] / "corpus" / "lopsided.toml"))
    report = build_report(lopsided, [4], sections=(c1_section, figures_section))
    (c1_text,) = report.sections[0].blocks
    assert main(["c1", "--n", "4", "--scheme", str(Path(__file__).resolve().parents[1] / "corpus" / "lopsided.toml")]) == 2
    assert c1_text.parts[0] == "Not applicable: " and c1_text.parts[1] in capsys.readouterr().err
    assert [getattr(b, "name", None) for b in report.sections[1].blocks] == [None, "eigen-polygons"]


def test_shape_section_not_applicable_says_why(capsys):
    """lopsided's regular rules are not Catmull-Clark's: the section gives the reason ``artifacts`` gives (exit 2)."""
    path = str(Path(__file__).resolve().parents[1] / "corpus" / "lopsided.toml")
    report = build_report(sd.schemes.files.load_scheme(path), [4, 5], sections=(shape_section,))
    (text,) = report.sections[0].blocks
    assert main(["artifacts", "--n", "4", "--scheme", path]) == 2
    assert text.parts[0] == "Not applicable: " and str(text.parts[1]) in capsys.readouterr().err
    assert "Catmull-Clark" in str(text.parts[1])
    assert "not applicable" in report_html(report).lower()


def test_shape_section_with_free_parameters_says_why():
    from symdecomp.schemes.files import load_scheme

    scheme = load_scheme(str(Path(__file__).resolve().parents[1] / "corpus" / "free-vertex.toml"))
    (text,) = build_report(scheme, [5], sections=(shape_section,)).sections[0].blocks
    with pytest.raises(sd.NotApplicableError) as exc:
        sd.artifact_indicators(scheme, 5)
    assert text.parts == ("Not applicable: ", str(exc.value)) and "free parameters alpha, beta" in str(exc.value)
