"""The LaTeX output: aslatex, line breaking, the document, its drift and its compilation."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

from symdecomp.claims import CheckResult, Status, Step
from symdecomp.cli import main
from symdecomp.cli.derive_cmd import write_derivations
from symdecomp.output.latex import PREAMBLE, aslatex, derivation_files, display_math, section_file_name, text_latex
from symdecomp.output.texlayout import ATOM, LINE, SETTINGS, Names, latex, matrix_width, name_long_parts, size
from symdecomp.symbols import alpha, n, omega
from tests.output.latex_cases import long_product, long_sum, stress_pairs

COMMITTED = Path(__file__).resolve().parents[2] / "derivations"
PDFLATEX = shutil.which("pdflatex")
LATEXMK = shutil.which("latexmk")
needs_tex = pytest.mark.skipif(PDFLATEX is None, reason="no pdflatex (CI installs it in .ci/steps/20-latex.sh)")
#: Overfull boxes up to this width (pt) are tolerated; anything wider runs visibly into the margin.
OVERFULL_TOLERANCE_PT = 2.0

x, y = sp.symbols("x y")


# -- aslatex ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    "expr",
    [sp.Rational(3, 8) + alpha, omega**2 / n, sp.sqrt(5 * n**2 - 30 * n + 49), sp.Matrix([[1, x], [y, 2]]),
     sp.Piecewise((x, x > 0), (-x, True)), 1 + 2 * sp.I, sp.Abs(x)],
)
def test_sympy_objects_are_printed_by_sympy(expr):
    assert aslatex(expr) == sp.latex(expr, **SETTINGS)


def test_mapping_is_an_aligned_block():
    assert aslatex({x: sp.Rational(1, 2), y: sp.sqrt(2)}) == "\\begin{aligned}\nx &= \\frac{1}{2} \\\\\ny &= \\sqrt{2}\n\\end{aligned}"


def test_a_mapping_that_does_not_name_its_values_maps_them_in_sorted_order():
    eigenvalues = {sp.Integer(5): 1, sp.Integer(2): 2}  # eigenvalue -> multiplicity
    assert aslatex(eigenvalues) == "\\begin{aligned}\n2 &\\mapsto 2 \\\\\n5 &\\mapsto 1\n\\end{aligned}"
    assert "2 = 2" not in display_math(eigenvalues)


def test_unknown_objects_are_refused():
    with pytest.raises(TypeError, match="object"):
        aslatex(object())


def test_text_is_escaped_and_inline_math_kept():
    assert text_latex("a_i & b_i: 50% #1 ~ ^ {x} \\ $\\omega_n^j$") == (
        r"a\_\allowbreak{}i \& b\_\allowbreak{}i: 50\% \#1 \textasciitilde{} \textasciicircum{} \{x\} "
        r"\textbackslash{} $\omega_n^j$"
    )
    # & is a cell separator inside an environment, a character elsewhere
    assert text_latex("$\\begin{pmatrix} a & b \\end{pmatrix}$, $a & b$") == (
        "$\\begin{pmatrix} a & b \\end{pmatrix}$, $a \\& b$"
    )
    assert text_latex("as $$x_1$$ shows") == "as \n\\begin{dmath*}\nx_1\n\\end{dmath*}\n shows"
    assert text_latex("costs $5") == r"costs \$5"
    assert text_latex("as in Eq. 5, cf. Prop. 2.1. Then") == r"as in Eq.~5, cf.~Prop.~2.1. Then"
    # Unicode the preamble declares is kept (the stress document compiles with it); other as a code point
    assert text_latex("ω ≤ 1 — ok ☃, $ω + ☃$") == r"ω ≤ 1 — ok \texttt{[U+2603]}, $ω + \text{\texttt{[U+2603]}}$"
    assert "\\DeclareUnicodeCharacter{03C9}{\\ensuremath{\\omega}}" in PREAMBLE
    # a comment character inside inline math would swallow the rest of the line
    assert text_latex("$50% x$") == r"$50\% x$"


def test_a_long_inline_formula_becomes_a_display():
    wide = sp.latex(sp.expand((x + y + 1) ** 4))
    assert "\\begin{dmath*}" in text_latex(f"see ${wide}$ here")
    assert "\\begin{dmath*}" not in text_latex(f"see ${wide}$ here", displays=False)


# -- line breaking -----------------------------------------------------------------------


def _restored(expr, names: Names):
    """``expr`` with every name replaced by what it stands for (names may refer to earlier ones)."""
    for _ in range(len(names.parts) + 1):
        expr = expr.xreplace(names.parts)
    return expr


def _definitions(block: str) -> dict[str, str]:
    """The ``name = value`` displays after ``where`` in a block."""
    rows = re.findall(r"\\begin\{dmath\*\}\n(.*?) = (.*?)\n\\end\{dmath\*\}", block.split("where", 1)[1], re.S)
    return dict(rows)


def test_a_long_sum_is_left_to_tex_to_break():
    expr = long_sum()
    assert size(expr) > 10 * LINE
    block = display_math(expr, lhs=sp.Symbol("S"))
    assert block == "\\begin{dmath*}\nS = " + latex(expr) + "\n\\end{dmath*}\n"


def test_a_long_numerator_is_printed_as_a_factor_that_tex_can_break():
    block = display_math(long_sum() / (n + 3), lhs="Q")
    assert "Q = \\frac{1}{n + 3} \\left(" in block and "where" not in block


@pytest.mark.parametrize("wrap", [sp.sqrt, sp.cos, sp.exp, lambda e: 1 / e, lambda e: x / e + 1,
                                  lambda e: sp.Piecewise((e, x > 0), (0, True)), lambda e: sp.Tuple(e, e + 1)])
def test_a_long_part_tex_cannot_break_is_named_and_nothing_is_lost(wrap):
    expr = wrap(long_sum())
    names = Names()
    shown = name_long_parts(expr, names)
    assert names.parts and size(shown) < ATOM
    assert _restored(shown, names) == expr
    block = display_math(expr, lhs=sp.Symbol("F"))
    assert _definitions(block) == {latex(k): latex(name_long_parts(v, Names())) for k, v in names.parts.items()}


def test_a_fraction_of_long_products_keeps_its_numerator_and_denominator_whole():
    """The numerator of ``A B / D`` is no sub-tree of sympy's flat product: it is rebuilt, not lost."""
    names = Names()
    shown = name_long_parts(long_product(), names)
    assert _restored(shown, names) == long_product()
    assert size(shown) < ATOM and all(size(name_long_parts(v, Names())) > ATOM for v in names.parts.values())


def test_a_power_of_a_long_sum_is_left_to_tex_and_equal_parts_share_a_name():
    names = Names()
    assert name_long_parts(long_sum() ** 3, names) == long_sum() ** 3 and not names.parts
    shown = name_long_parts(sp.sqrt(long_sum()) + sp.cos(long_sum()), names)
    assert shown == sp.sqrt(sp.Symbol("xi_1")) + sp.cos(sp.Symbol("xi_1"))


def test_an_object_sympy_cannot_print_is_reported_in_the_document():
    step = Step("a power of a Piecewise", sp.Pow(sp.Piecewise((x, x > 0), (y, True)), 2, evaluate=False))
    assert "\\finding{sderror}{Not printed}" in aslatex(step)


def test_a_wide_matrix_has_its_long_entries_named_and_listed():
    wide = sp.Matrix(3, 3, lambda r, c: sp.expand((omega ** (r - c) + alpha + r) ** 2 / (r + c + 2)))
    block = display_math(wide, lhs=sp.Symbol("W"))
    head, definitions = block.split("where")
    named = re.findall(r"m_\{(\d)(\d)\}", head)
    assert named
    shown = wide.copy()
    for r, c in named:
        shown[int(r) - 1, int(c) - 1] = sp.Symbol("m_{%s%s}" % (r, c))
    assert head == "\\[\nW = %s\n\\]\n" % latex(sp.ImmutableMatrix(shown)) and matrix_width(shown) + 4 <= LINE
    for r, c in named:
        assert "m_{%s%s} = %s\n" % (r, c, latex(wide[int(r) - 1, int(c) - 1])) in definitions


def test_a_matrix_of_many_short_columns_is_shown_in_blocks_of_columns():
    small = sp.Matrix(9, 9, lambda r, c: sp.Rational(r + 1, c + 3))
    assert display_math(small, lhs="S") == "\\[\nS = %s\n\\]\n" % latex(small)
    many = sp.Matrix(4, 40, lambda r, c: sp.Rational(r + 1, c + 3))
    block = display_math(many, lhs="S")
    ranges = [(int(a), int(b)) for a, b in re.findall(r"\$S\$, columns (\d+) to (\d+):", block)]
    assert len(ranges) >= 2 and ranges[0][0] == 1 and ranges[-1][1] == 40
    assert all(b + 1 == a for (_, b), (a, _) in zip(ranges, ranges[1:]))  # every column once, in order
    for a, b in ranges:
        block_columns = many[:, a - 1:b]
        assert latex(sp.ImmutableMatrix(block_columns)) in block
        assert matrix_width(block_columns) <= LINE


# -- claims as LaTeX -----------------------------------------------------------------------


def test_a_refuted_claim_is_boxed_with_its_counterexample():
    result = CheckResult(Status.REFUTED, "ratio is 0/0", counterexample="at $n = 4$, j_2 & 100%")
    tex = aslatex(result)
    assert tex.startswith("\\finding{sdrefuted}")
    assert r"at $n = 4$, j\_\allowbreak{}2 \& 100\%" in tex


def test_a_corrected_claim_shows_the_correction_and_steps_print_via_sympy():
    step = Step("the row sums to", 1 + (n - 1) * (alpha + alpha), sp.Symbol("s"))
    result = CheckResult(Status.CORRECTED, "not affine", steps=(step,), correction="centre $1 - n\\alpha$")
    tex = aslatex(result)
    assert "\\finding{sdcorrected}" in tex and "centre $1 - n\\alpha$" in tex
    assert "s = " + sp.latex(step.expr) in tex


def test_status_and_scope_of_a_verified_claim():
    tex = aslatex(CheckResult(Status.VERIFIED, "exact", valences=(3, 64)))
    assert "\\status{verified}" in tex and "$n = 3, \\dots, 64$" in tex


@pytest.mark.slow
def test_the_document_mirrors_the_papers_sections_and_is_deterministic():
    pairs = stress_pairs()
    files = derivation_files(pairs)
    assert files == derivation_files(list(reversed(pairs)))
    assert list(files) == sorted(files)
    assert set(files) == {"main.tex"} | {section_file_name(s) for s in ("2", "4", "5.1", "5.2", "6")}
    main_tex = files["main.tex"]
    # the summary comes first, then the sections in the paper's order
    order = [main_tex.index(s) for s in ("Summary of the claims", "\\input{section-2}", "\\input{section-4}",
                                         "Evolution of the eigencomponents", "\\input{section-5-1}",
                                         "\\input{section-5-2}", "\\input{section-6}")]
    assert order == sorted(order)
    assert "\\subsection{Tangent plane properties}" in files["section-5-1.tex"]
    assert "\\setcounter{section}{3}\n\\section{1-ring decomposition" in files["section-4.tex"]
    assert "\\claimheading{claim:proposition-5-9}{Proposition~5.9}" in files["section-5-1.tex"]


@pytest.mark.slow
def test_the_bytes_do_not_depend_on_the_hash_seed(tmp_path):
    """Printing order comes from sympy's sort keys, not from set or dict iteration order."""
    script = (
        "import hashlib; from tests.output.latex_cases import stress_pairs; "
        "from symdecomp.output.latex import derivation_files; "
        "print(hashlib.sha256(repr(sorted(derivation_files(stress_pairs()).items())).encode()).hexdigest())"
    )
    root = Path(__file__).resolve().parents[2]
    digests = {
        subprocess.run([sys.executable, "-c", script], cwd=root, capture_output=True, text=True, check=True,
                       env={**os.environ, "PYTHONHASHSEED": seed}).stdout
        for seed in ("1", "2")
    }
    assert len(digests) == 1


# -- the command and the committed files ------------------------------------------------------


def _differences(expected: Path, actual: Path) -> list[str]:
    """Files that differ between two directories of .tex files (missing, extra or changed)."""
    a = {p.name: p.read_bytes() for p in expected.glob("*.tex")}
    b = {p.name: p.read_bytes() for p in actual.glob("*.tex")}
    return sorted(name for name in a.keys() | b.keys() if a.get(name) != b.get(name))


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_derive_writes_the_files_and_removes_only_its_own_stale_ones(tmp_path, capsys):
    (tmp_path / "section-9.tex").write_text("stale")
    (tmp_path / "notes.tex").write_text("mine")
    assert main(["derive", "--out", str(tmp_path), "--json"]) == 0
    assert not (tmp_path / "section-9.tex").exists()
    assert (tmp_path / "notes.tex").read_text() == "mine"
    assert (tmp_path / "main.tex").read_text().startswith("% Generated by `symdecomp derive`")
    assert '"' in capsys.readouterr().out


@pytest.fixture
def temporary_claims(monkeypatch):
    """Two claims registered for one test: a refuted one in 5.3 and one whose check crashes."""
    from symdecomp.claims import REGISTRY, Claim

    def refuted(scheme):
        return CheckResult(Status.REFUTED, "0/0 at $j = n/2$", counterexample="n = 4, j = 2",
                           steps=(Step("the determinant", sp.Matrix([[1, omega], [omega, 1]]).det(), "D"),))

    def crashes(scheme):
        raise ZeroDivisionError("division by zero")

    # labels no real claim uses, so the cached results of the real checks stay valid
    monkeypatch.setitem(REGISTRY, "Eq. 998", Claim("Eq. 998", "5.3", "A refuted one", "as printed", refuted, order=998))
    monkeypatch.setitem(REGISTRY, "Eq. 999", Claim("Eq. 999", "5.3", "A crashing one", "as printed", crashes, order=999))
    yield


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_derive_prints_one_claim_and_reports_failed_checks(temporary_claims, tmp_path, capsys):
    assert main(["derive", "--label", "Eq. 998"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("\\claimheading{claim:eq-998}{Eq.~998}{A refuted one}")
    assert "\\finding{sdrefuted}" in out and "D = " + sp.latex(1 - omega**2) in out
    assert main(["derive", "--label", "Eq. 1000"]) == 2
    assert "no claim labelled Eq. 1000" in capsys.readouterr().err
    assert main(["derive", "--out", str(tmp_path), "--no-progress"]) == 1  # Eq. 999 did not run
    assert "Eq. 999" in capsys.readouterr().err
    section = (tmp_path / "section-5-3.tex").read_text()
    assert "\\subsection{Hyperbolic properties}" in section and "\\finding{sderror}" in section
    assert "\\section{Evolution of the eigencomponents}" in (tmp_path / "main.tex").read_text()


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_committed_derivations_match_the_registry(tmp_path):
    """Drift: regenerating gives the committed bytes (run `symdecomp derive` after changing a check)."""
    write_derivations(tmp_path)
    again = tmp_path / "again"
    write_derivations(again)
    assert _differences(tmp_path, again) == []
    assert _differences(COMMITTED, tmp_path) == [], "derivations/ is stale: run `python -m symdecomp derive`"


def test_the_drift_check_catches_a_hand_edit(tmp_path):
    edited = tmp_path / "edited"
    shutil.copytree(COMMITTED, edited)
    target = edited / "main.tex"
    target.write_text(target.read_text() + "% a hand edit\n")
    assert _differences(COMMITTED, edited) == ["main.tex"]


# -- compiling ------------------------------------------------------------------------------------


def _compile(directory: Path) -> str:
    """Compile main.tex as a user would (latexmk -pdf, else pdflatex twice); return the log.

    Fails on a LaTeX error."""
    flags = ["-interaction=nonstopmode", "-halt-on-error"]
    runs = [[LATEXMK, "-pdf", *flags, "main.tex"]] if LATEXMK else [[PDFLATEX, *flags, "main.tex"]] * 2
    for command in runs:
        run = subprocess.run(command, cwd=directory, capture_output=True, text=True, timeout=300)
        log = (directory / "main.log").read_text(errors="replace")
        assert run.returncode == 0, "LaTeX error:\n" + "\n".join(re.findall(r"^!.*(?:\n.*){0,3}", log, re.M))
    return log


def _overfull(log: str) -> list[str]:
    return [m.group(0) for m in re.finditer(r"Overfull \\hbox \((\d+(?:\.\d+)?)pt too wide\).*", log)
            if float(m.group(1)) > OVERFULL_TOLERANCE_PT]


@pytest.mark.slow
@needs_tex
def test_the_stress_document_compiles_and_nothing_runs_past_the_margin(tmp_path):
    for name, text in derivation_files(stress_pairs()).items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    log = _compile(tmp_path)
    assert _overfull(log) == []
    warnings = " ".join(re.findall(r"LaTeX Warning:.*", log))
    assert "undefined" not in warnings and "multiply defined" not in warnings
    assert (tmp_path / "main.pdf").stat().st_size > 0


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
@needs_tex
def test_the_derivations_of_the_registry_compile(tmp_path):
    write_derivations(tmp_path)
    log = _compile(tmp_path)
    assert _overfull(log) == []


@needs_tex
def test_the_overfull_check_sees_a_formula_that_runs_into_the_margin(tmp_path):
    """The compile tests can fail: an unbroken long sum is reported."""
    unbroken = "\\[\n" + sp.latex(long_sum()) + "\n\\]\n"
    (tmp_path / "main.tex").write_text(
        derivation_files([])["main.tex"].replace("\\end{document}", unbroken + "\\end{document}")
    )
    assert len(_overfull(_compile(tmp_path))) == 1


def test_findings_typeset_objects_as_math_and_words_as_text():
    import sympy as sp

    from symdecomp.claims import Text
    from symdecomp.output.latex import findings_latex

    lam = sp.Symbol("lambda_1")
    finding = Text("at n = 3 the eigenvalue ", sp.sqrt(5) / 4 + lam, " exceeds 50% of it")
    tex = findings_latex(finding)
    assert r"\sqrt{5}" in tex and r"\lambda_{1}" in tex and r"50\%" in tex
    assert str(finding) == "at n = 3 the eigenvalue lambda_1 + sqrt(5)/4 exceeds 50% of it"


# -- findings as mathematics ------------------------------------------------------------------

#: ASCII mathematics that a finding must not print as text (its formulas are sympy objects).
_ASCII_MATH = re.compile(r"lambda|omega|sqrt|\\textasciicircum|\*\*")
_FINDING = re.compile(
    r"(?:\\finding\{|\\textbf\{Status:\})(.*?)(?=\\textbf\{Derivation\.\}|\\claimheading|\\(?:sub)*section\{|\Z)", re.S
)
_MATH = re.compile(r"\\begin\{(dmath|dgroup)\*\}.*?\\end\{\1\*\}|\\\[.*?\\\]|(?<!\\)\$.*?(?<!\\)\$", re.S)


def _ascii_math_in_findings(files: dict[str, str]) -> list[str]:
    """The words of the findings (evidence, counterexample, correction; math removed) that spell a formula in ASCII."""
    found = []
    for name, tex in sorted(files.items()):
        for finding in _FINDING.findall(tex):
            words = _MATH.sub(" ", finding)
            found += ["%s: %s" % (name, m.group(0)) for m in _ASCII_MATH.finditer(words)]
    return found


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_the_findings_of_the_registry_typeset_their_formulas(tmp_path):
    """Issue 10: no lambda_, omega^ or sqrt( as text in the findings of the regenerated document."""
    write_derivations(tmp_path)
    files = {p.name: p.read_text(encoding="utf-8") for p in tmp_path.glob("*.tex")}
    assert sum(len(_FINDING.findall(t)) for t in files.values()) >= 50  # every claim has one
    assert _ascii_math_in_findings(files) == []


#: Branches of the checks that only other schemes reach (tests/claims/test_mutations.py): their findings typeset
#: their formulas too, including the reasons a claim is not applicable.
OTHER_SCHEME_BRANCHES = [
    ("moved", "Eq. 14-15"),
    ("moved", "Eq. 17-21"),
    ("wide", "Eq. 51"),
    ("wide", "Tuning weights (after Eq. 51)"),
    ("asymmetric", "Eq. 42"),
    ("asymmetric", "Proposition 5.2"),
    ("complex weights", "Proposition 4.2"),
    ("2n-gon smoothing", "Eq. 35-37"),
    ("2n-gon smoothing", "Eq. 38"),
    ("loop", "1-ring suffices (after Eq. 51)"),
    ("loop", "Larger neighbourhoods (after Eq. 51)"),
    ("bilinear", "Larger neighbourhoods (after Eq. 51)"),
]


@pytest.mark.parametrize("name, label", OTHER_SCHEME_BRANCHES, ids=[f"{a} / {b}" for a, b in OTHER_SCHEME_BRANCHES])
def test_the_findings_on_other_schemes_typeset_their_formulas(name, label):
    from symdecomp.claims import check_claim, get_claim
    from tests.claims.test_mutations import scheme

    result = check_claim(label, scheme(name))
    assert result.status is not Status.ERROR
    assert _ascii_math_in_findings(derivation_files([(get_claim(label), result)])) == []


@pytest.mark.slow
@pytest.mark.parametrize("name", ["moved", "O fixed", "2n-gon smoothing", "wide", "balanced rings"])
def test_every_finding_on_the_mutated_schemes_typesets_its_formulas(name):
    from symdecomp.claims import all_claims, check_claim
    from tests.claims.test_mutations import scheme

    # the two certified cross-checks (C1, the spectrum) take minutes per scheme; their findings are checked on
    # Catmull-Clark above
    slow = {"C1 (Reif's test)", "Spectrum (Eq. 34, Eq. 43)"}
    pairs = [(c, check_claim(c.label, scheme(name))) for c in all_claims() if c.label not in slow]
    assert _ascii_math_in_findings(derivation_files(pairs)) == []


def test_the_findings_check_catches_a_formula_written_as_text():
    from symdecomp.claims import Claim, Text

    lam1 = sp.Symbol("lambda_1")

    def pair(result):
        return (Claim("Eq. 997", "5.1", "t", "s", lambda: result), result)

    plain = CheckResult(Status.REFUTED, "the ratio", counterexample="n = 4: lambda_1 = sqrt(5)/8 and omega^2 = -1")
    typeset = CheckResult(Status.REFUTED, "the ratio", counterexample=Text("n = 4: ", sp.Eq(lam1, sp.sqrt(5) / 8)))
    words = ("lambda", "sqrt", "omega", "\\textasciicircum")
    assert _ascii_math_in_findings(derivation_files([pair(plain)])) == ["section-5-1.tex: " + w for w in words]
    assert _ascii_math_in_findings(derivation_files([pair(typeset)])) == []
