"""C1 and the curvature regime for every valence in the derivations (c1-every-n.tex), the report and c1 --every-n --json."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest
import sympy as sp

from symdecomp.analysis.characteristic_uniform import uniform_nets
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.cli import main
from symdecomp.cli.json_envelope import json_schema
from symdecomp.output.every_n_derivations import EVERY_N_FILE, every_n_files, every_n_latex, every_n_proofs
from symdecomp.output.latex import derivation_files
from symdecomp.output.report import build_report, every_n_section
from symdecomp.output.report_every_n import CERTIFIED as REPORT_CERTIFIED
from symdecomp.output.report_tex import report_latex
from symdecomp.output.texlayout import latex
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.c1_every_n import laurent_in_t
from symdecomp.verify.c1_uniform import jacobian_coefficients

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "corpus"
SCHEMES = {"catmull-clark": catmull_clark(), "loop": loop()}


def _flat(tex: str) -> str:
    """Whitespace as TeX reads it (the source is wrapped at spaces)."""
    return " ".join(tex.split())


def _section(text: str, name: str) -> str:
    """One scheme's subsection of the file, its whitespace flattened."""
    start = text.index("\\subsection*{%s}" % name)
    end = text.find("\\subsection*{", start + 1)
    return _flat(text[start:] if end < 0 else text[start:end])


@pytest.fixture(scope="module")
def document() -> str:
    return every_n_files()[EVERY_N_FILE]


@pytest.mark.slow
def test_the_committed_file_is_the_generated_one_and_main_inputs_it(document):
    """Drift: regenerating gives the committed bytes (`python -m symdecomp derive`); main.tex inputs it after the claims."""
    assert (ROOT / "derivations" / EVERY_N_FILE).read_text(encoding="utf-8") == document
    main_tex = (ROOT / "derivations" / "main.tex").read_text(encoding="utf-8")
    assert main_tex.index("\\input{beyond-2}") < main_tex.index("\\input{c1-every-n}") < main_tex.index("\\end{document}")


@pytest.mark.parametrize("name", SCHEMES)
def test_each_scheme_states_c1_and_the_regime_for_every_n_as_the_proof_found(document, name):
    section = _section(document, name)
    result, regime = every_n_proofs(SCHEMES[name])
    assert result.status == "proved"
    assert "\\emph{The surface is $C^1$ at an extraordinary vertex of every valence $n \\ge 3$.}" in section
    # every step of the proof appears, under the name --json gives it, in the proof's order
    positions = [section.index("\\item[%s] %s" % (s.name, s.status)) for s in result.steps]
    assert positions == sorted(positions) and len(positions) == len(result.steps) >= 7
    assert f"unbounded for every $n \\ge {regime.first_proved}$" in section


@pytest.mark.parametrize("name", SCHEMES)
def test_the_formulas_are_sympys_printing_of_the_computed_objects(document, name):
    """The trace (or eigenvalue) of M(t), the count of the Jacobian's Bezier coefficients: the scheme's, as sympy prints them."""
    scheme, section = SCHEMES[name], _section(document, name)
    M = sp.Matrix(one_ring_matrices(scheme)[0])
    if M.rows == 2:
        disc = sp.factor(laurent_in_t(M.trace()) ** 2 - 4 * laurent_in_t(M.det()))
        assert _flat("\\Delta(t) = " + latex(disc)) in section
    else:
        assert _flat("\\lambda(t) = " + latex(laurent_in_t(M[0, 0]))) in section
    nets = uniform_nets(scheme)
    count = len(jacobian_coefficients(nets, scheme.lattice))
    assert f"There are {count} coefficients; the Sturm counts of $(U, V)$" in section
    assert f"{count} with 0 and 0 real roots" in section  # no sign change: each coefficient keeps its sign
    uniform = every_n_proofs(scheme)[0].uniform
    assert f"The boundary has {uniform.coefficients - count} control points" in section  # the wedge's points
    # the eigenvalue's quadratic (Loop: linear) as the map's nets use it
    assert _flat("0 = " + latex(nets.quadratic.as_expr())) in section
    assert not re.search(r"(?<![\\\w])lambda_1|sqrt\(|\*\*", section)  # no ASCII math in the typeset proof


@pytest.mark.slow
def test_a_scheme_whose_c1_fails_from_n_10_gets_its_exact_threshold():
    """tests/corpus/tuned-at-ev.toml: C1 certified at 3..9, fails at every n >= 10 (the proof's fails-from step)."""
    scheme = load_scheme(str(CORPUS / "tuned-at-ev.toml"))
    result, _ = every_n_proofs(scheme)
    section = _flat(every_n_latex(scheme))
    assert (result.status, result.failure) == ("refuted", 10)
    assert ("\\emph{The surface is $C^1$ at an extraordinary vertex of valence $n = 3, \\dots, 9$ and at no valence "
            "$n \\ge 10$: the exact threshold is $n = 10$.}") in section
    assert "every valence $n \\ge 3$" not in section
    tail = next(s for s in result.steps if s.name == "fails-from")
    assert "\\item[fails-from] proved, $n \\ge 10$." in section
    assert _flat("q(x) = " + latex(dict(tail.formulas)["q(x)"])) in section


@pytest.mark.slow
def test_two_runs_give_the_same_bytes():
    """Deterministic: a fresh process, another hash seed, the same file."""
    script = ("import sys; from symdecomp.output.every_n_derivations import every_n_files; "
              "sys.stdout.write(every_n_files()['c1-every-n.tex'])")
    runs = {subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, check=True,
                           env={**os.environ, "PYTHONHASHSEED": seed}).stdout
            for seed in ("1", "2")}
    assert len(runs) == 1


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="no pdflatex (CI installs it in .ci/steps/20-latex.sh)")
def test_the_section_compiles_in_the_document_and_fits_the_page(document, tmp_path):
    files = {**derivation_files([], (EVERY_N_FILE,)), EVERY_N_FILE: document}
    assert "\\input{c1-every-n}" in files["main.tex"]
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "main.tex"], cwd=tmp_path,
                         capture_output=True, text=True, timeout=300)
    log = (tmp_path / "main.log").read_text(errors="replace")
    assert run.returncode == 0, "\n".join(re.findall(r"^!.*", log, re.M))
    assert [w for w in re.findall(r"Overfull \\hbox \((\d+(?:\.\d+)?)pt", log) if float(w) > 2.0] == []


def test_the_report_has_the_section():
    report = build_report(loop(), [5], sections=(every_n_section,))
    (section,) = report.sections
    tex = _flat(report_latex(report)[0])
    result, regime = every_n_proofs(loop(), REPORT_CERTIFIED)
    assert ("reif-per-valence", f"$n = 3, \\dots, {REPORT_CERTIFIED}$") in [(str(r[0]), r[2]) for r in section.blocks[1].rows]
    assert section.title == "Every valence: C1 and the curvature regime"
    assert "every valence $n \\ge 3$" in tex and f"unbounded for every $n \\ge {regime.first_proved}$" in tex
    assert [str(row[0]) for row in section.blocks[1].rows] == [s.name for s in result.steps]


def test_c1_every_n_json_validates_and_names_each_step(capsys):
    assert main(["c1", "--every-n", "--scheme", "loop", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    jsonschema.validate(data, json_schema())
    assert [s["name"] for s in data["steps"]] == ["monotone", "bounds", "frequency-zero", "reif-per-valence", "map-scale",
                                                  "map-regular", "map-injective"]
    # a refutation from n = 10 on names its steps too: the failure at 10 and the proof for every larger n
    assert main(["c1", "--every-n", "--scheme", str(CORPUS / "tuned-at-ev.toml"), "--json", "--quiet"]) == 1
    refuted = json.loads(capsys.readouterr().out)
    jsonschema.validate(refuted, json_schema())
    assert refuted["status"] == "refuted" and [s["name"] for s in refuted["steps"]][-2:] == ["reif-at-n", "fails-from"]
    unnamed = {**data, "steps": [{k: v for k, v in data["steps"][0].items() if k != "name"}]}
    with pytest.raises(jsonschema.ValidationError, match="'name' is a required property"):
        jsonschema.validate(unnamed, json_schema())
