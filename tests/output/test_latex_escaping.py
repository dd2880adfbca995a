"""Text from outside the package (a scheme file's name and parameters) is typeset literally, never read as TeX."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest
import sympy as sp

from symdecomp import Scheme, catmull_clark
from symdecomp.claims import Text, Verbatim, check_claim, get_claim
from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError
from symdecomp.output.latex import derivation_files, findings_latex, text_latex
from symdecomp.schemes.files import load_scheme, scheme_from_text
from symdecomp.symbols import Parameter

PDFLATEX = shutil.which("pdflatex")
needs_tex = pytest.mark.skipif(PDFLATEX is None, reason="no pdflatex (CI installs it in .ci/steps/20-latex.sh)")

#: Claims whose findings quote the scheme's name or its parameters, each checked in well under a second.
C1 = "C1 (Reif's test)"
QUOTING = ("Eq. 16", "Section 3: symmetry", "Proposition 5.1", "Remark 5.1", C1)

RULES = """
[edge]
O = "3/8"
a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }
b = { "-1" = "1/16", "0" = "1/16" }
[face]
O = "1/4"
a = { "0" = "1/4", "1" = "1/4" }
b = { "0" = "1/4" }
[vertex]
b = "1/(4*n**2)"
"""


def _hostile(tmp_path: Path, *, parameter: bool = True) -> Path:
    """A scheme file whose name inputs ``secret.tex`` (written next to the document) if TeX reads it; its
    parameter ``gammascr`` is what sympy alone would print as an undefined ``\\mathscr``."""
    (tmp_path / "doc").mkdir()
    (tmp_path / "doc" / "secret.tex").write_text("LEAKED SECRET\n")
    vertex = 'a = "3/(2*n**2) + gammascr*(n - 4)"' if parameter else 'a = "3/(2*n**2)"'
    head = "name = 'c $\\input{secret}$ z # 50% ^_^ ~ & {}'\n" + ('parameters = ["gammascr"]\n' if parameter else "")
    path = tmp_path / "hostile.toml"
    path.write_text(head + RULES.replace('[vertex]\n', f"[vertex]\n{vertex}\n"))
    return path


def _pdflatex(folder: Path) -> tuple[str, str]:
    """Compile main.tex once with the recorder on; return the log and the list of files TeX read (.fls)."""
    run = subprocess.run([PDFLATEX, "-recorder", "-interaction=nonstopmode", "-halt-on-error", "main.tex"], cwd=folder,
                         capture_output=True, text=True, timeout=300)
    log = (folder / "main.log").read_text(errors="replace")
    assert run.returncode == 0, "LaTeX error:\n" + "\n".join(re.findall(r"^!.*(?:\n.*){0,3}", log, re.M))
    return log, (folder / "main.fls").read_text(errors="replace")


def _assert_literal(files: dict[str, str], name: str) -> None:
    tex = " ".join("".join(files.values()).split())  # the source's line breaks are spaces to TeX
    assert " ".join(text_latex(Verbatim(repr(name))).split()) in tex  # the name, each character escaped
    assert "\\input{" not in tex.replace("\\input{section-", "")
    assert "mathscr" not in tex and "gammascr" in tex


# --- the rendering ----------------------------------------------------------------------------------


def test_verbatim_text_is_escaped_character_by_character():
    hostile = "c $\\input{/etc/passwd}$ z $$\\def\\x{1}$$ 50% # & ~ ^ _ { }"
    tex = text_latex(Verbatim(hostile))
    assert "$" not in tex.replace("\\$", "") and "\\input" not in tex and "\\def" not in tex
    assert tex.count("\\$") == 6 and tex.count("\\textbackslash{}") == 3
    # the same words as prose written by the package: the $...$ is a formula there
    assert "$\\input{/etc/passwd}$" in text_latex("c $\\input{/etc/passwd}$ z")
    assert findings_latex(Text("the scheme ", Verbatim(hostile), " at ", sp.Rational(1, 2))).startswith("the scheme c \\$")
    assert str(Text("scheme ", Verbatim(hostile))) == "scheme " + hostile  # a terminal prints it as given


def test_the_findings_of_a_hostile_scheme_quote_its_name_literally(tmp_path):
    scheme = load_scheme(_hostile(tmp_path))
    pairs = [(get_claim(label), check_claim(label, scheme)) for label in QUOTING]
    assert all(scheme.name in str(r.evidence) or "gammascr" in str(r.evidence) for _, r in pairs)
    _assert_literal(derivation_files(pairs), scheme.name)


def test_parameter_names_print_as_names_never_as_commands():
    names = {"gamma2": "\\gamma_{2}", "xscr": "xscr", "xhat": "xhat", "Lambda": "\\Lambda", "t_k": "t_{k}",
             "alphaprime": "alphaprime", "w1_a": "w_{1 a}"}
    for name, tex in names.items():
        assert sp.latex(Parameter(name)) == tex
    assert sp.latex(Parameter("a\\input{x}")) == "ainputx"  # outside the schemes' names: the markup dropped
    with pytest.raises(InvalidSchemeError, match="parameter name .* is not an identifier"):
        catmull_clark(sp.Symbol("a}\\input{x"), None)


@pytest.mark.parametrize("name", ["two\nlines", "bell\a", "tab\there", " "])
def test_a_scheme_name_is_one_line_of_printable_text(name):
    cc = catmull_clark()
    with pytest.raises(InvalidSchemeError, match="name must be"):
        Scheme(name, cc.edge_rule, cc.face_rule, cc.vertex_rule)
    with pytest.raises(InvalidSchemeError, match="name must be"):
        scheme_from_text(f"name = {json.dumps(name)}\n" + RULES.replace("[vertex]\n", '[vertex]\na = "3/(2*n**2)"\n'))


# --- compiled -----------------------------------------------------------------------------------------


@needs_tex
def test_a_document_from_a_hostile_scheme_file_compiles_and_reads_no_file(tmp_path):
    scheme = load_scheme(_hostile(tmp_path))
    pairs = [(get_claim(label), check_claim(label, scheme)) for label in QUOTING if label != C1]
    # without parameters Reif's test runs, and its evidence names the scheme as it is (the case of the issue)
    concrete = Scheme(scheme.name, *catmull_clark().stencils(), catmull_clark().vertex_rule)
    pairs.append((get_claim(C1), check_claim(C1, concrete)))
    assert "Reif's test certified" in str(pairs[-1][1].evidence) and scheme.name in str(pairs[-1][1].evidence)
    out = tmp_path / "doc"
    files = derivation_files(pairs)
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    log, read = _pdflatex(out)
    assert "secret" not in read and "LEAKED" not in log
    assert "Undefined control sequence" not in log and (out / "main.pdf").stat().st_size > 0


@needs_tex
@pytest.mark.slow
def test_derive_for_a_hostile_scheme_file_writes_a_document_that_reads_no_file(tmp_path):
    """Every claim, through the command: whatever a check quotes from the scheme is typeset literally."""
    path = _hostile(tmp_path, parameter=False)
    out = tmp_path / "doc"
    assert main(["derive", "--scheme", str(path), "--out", str(out), "--no-progress"]) in (0, 1)
    files = {p.name: p.read_text() for p in out.iterdir()}
    inputs = re.findall(r"\\input\{([^}]*)\}", "".join(files.values()))
    assert inputs and all(f"{name}.tex" in files for name in inputs)  # only the document's own files
    log, read = _pdflatex(out)
    assert "secret" not in read and "LEAKED" not in log
