"""``symdecomp report``: bad arguments are one line and exit 2 before any work; the documents are the same bytes twice.

The whole documents (Catmull-Clark and Loop at 3:8, a scheme file) take tens of seconds each: they are
``slow``; a PDF needs pdflatex and is skipped without it.
"""

from __future__ import annotations

import hashlib
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from symdecomp.cli import main
from symdecomp.cli.progress import PLAIN_LINE
from symdecomp.output import report_tex

CORPUS = Path(__file__).resolve().parents[1] / "corpus"
needs_pdflatex = pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")


@pytest.mark.parametrize("argv, names", [
    (["loop", "--n", "3:5", "--out", "r.txt"], "--out"),
    (["loop", "--n", "3:5", "--out", "report"], "--out"),
    (["loop", "--n", "3:17", "--out", "r.html"], "--n"),
    (["loop", "--n", "2:5", "--out", "r.html"], "--n"),
    (["loop", "--n", "5:3", "--out", "r.html"], "--n"),
    (["loop", "--n", "3:5"], "--out"),
    (["loop", "--out", "r.html"], "--n"),
    (["no-such-scheme", "--n", "3", "--out", "r.html"], "SCHEME"),
    (["loop", "--n", "3", "--out", "r.html", "--budget", "0"], "--budget"),
    (["loop", "--n", "3", "--out", "r.html", "--n", "4"], "--n"),
    (["loop", "--n", "3", "--out", "no/such/dir/r.html"], "--out"),
])
def test_bad_arguments(argv, names, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["report", *argv]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and names in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_output_without_suffix_refused(capsys, tmp_path):
    assert main(["report", "loop", "--n", "3", "--out", str(tmp_path)]) == 2
    assert "no suffix is not a report format" in capsys.readouterr().err


def test_output_checked_before_the_work(capsys, tmp_path, monkeypatch):
    """A directory named like a report is refused at once: no section is computed."""
    (tmp_path / "r.html").mkdir()
    monkeypatch.setattr("symdecomp.output.report.build_report", lambda *a, **k: pytest.fail("the work started"))
    assert main(["report", "loop", "--n", "3", "--out", str(tmp_path / "r.html")]) == 2
    assert "is a directory" in capsys.readouterr().err


def test_missing_pdflatex_is_one_line_exit_3(capsys, tmp_path, monkeypatch):
    """Without pdflatex a PDF cannot be made: said before the work, exit 3 (an optional component is missing)."""
    monkeypatch.setattr(report_tex.shutil, "which", lambda name: None)
    monkeypatch.setattr("symdecomp.output.report.build_report", lambda *a, **k: pytest.fail("the work started"))
    assert main(["report", "loop", "--n", "3", "--out", str(tmp_path / "r.pdf")]) == 3
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "pdflatex is not installed" in err and ".html" in err
    assert not (tmp_path / "r.pdf").exists()


def test_help_names_the_formats(capsys):
    assert main(["report", "--help"]) == 0
    out = capsys.readouterr().out
    assert all(fmt in out for fmt in (".pdf", ".html", ".tex", "pdflatex"))


def _twice(tmp_path: Path, argv: list[str], suffix: str) -> bytes:
    digests = []
    for k in range(2):
        out = tmp_path / f"run{k}" / f"report{suffix}"
        out.parent.mkdir()
        done = subprocess.run([sys.executable, "-m", "symdecomp", "report", *argv, "--out", str(out)],
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
        assert done.stdout.strip() == str(out)
        assert all(PLAIN_LINE.fullmatch(line) for line in done.stderr.splitlines()), done.stderr  # progress lines only
        digests.append(hashlib.sha256(out.read_bytes()).hexdigest())
    assert digests[0] == digests[1]
    return out.read_bytes()


@pytest.mark.slow
@needs_pdflatex
@pytest.mark.parametrize("scheme, valences", [("catmull-clark", "3:8"), ("loop", "3:8"), (str(CORPUS / "lopsided.toml"), "4:8")],
                         ids=["catmull-clark", "loop", "file"])
def test_pdf_twice_the_same_bytes(scheme, valences, tmp_path):
    pdf = _twice(tmp_path, [scheme, "--n", valences], ".pdf")
    assert pdf.startswith(b"%PDF") and b"CreationDate" not in pdf and str(tmp_path).encode() not in pdf
    assert b"/ID [<> <>]" in pdf or b"/ID" not in pdf


@pytest.mark.slow
def test_html_twice_the_same_bytes(tmp_path):
    page = _twice(tmp_path, ["loop", "--n", "3:8"], ".html").decode("utf-8")
    assert page.startswith("<!DOCTYPE html>") and "<math" in page and "<svg" in page and "http" not in page.split("<svg")[0]


@pytest.mark.slow
def test_tex_with_figures_next_to_it(tmp_path):
    out = tmp_path / "my report $x$.tex"
    assert main(["report", "loop", "--n", "3:4", "--out", str(out)]) == 0
    tex = out.read_text(encoding="utf-8")
    figures = sorted(p.name for p in tmp_path.iterdir() if p.suffix == ".pdf")
    assert figures == ["my_report__x_-characteristic-map.pdf", "my_report__x_-eigen-polygons.pdf", "my_report__x_-height-field.pdf"]
    assert all("\\includegraphics[width=\\linewidth,height=0.4\\textheight,keepaspectratio]{%s}" % f in tex for f in figures)


def test_missing_matplotlib_is_one_line_exit_3(capsys, tmp_path, monkeypatch):
    def missing():
        raise ImportError("no matplotlib")

    monkeypatch.setattr("symdecomp.output.plotting._mpl.require_matplotlib", missing)
    monkeypatch.setattr("symdecomp.output.report.build_report", lambda *a, **k: pytest.fail("the work started"))
    assert main(["report", "loop", "--n", "3", "--out", str(tmp_path / "r.html")]) == 3
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "symdecomp[report]" in err


@pytest.mark.slow
@needs_pdflatex
def test_a_report_from_a_hostile_scheme_file_compiles_and_reads_no_file(tmp_path):
    """Issue 25, item 1, for ``report``: a scheme file whose name inputs a file if TeX reads it as TeX; the
    document compiles, shows the name literally, and pdflatex reads no file but its own (its -recorder list)."""
    doc = tmp_path / "doc"
    doc.mkdir()
    (doc / "secret.tex").write_text("LEAKED SECRET\n")  # where pdflatex runs, so \input{secret} would find it
    text = (CORPUS / "catmull-clark.toml").read_text()
    path = tmp_path / "hostile.toml"
    path.write_text(text.replace('name = "catmull-clark"', "name = 'c $\\input{secret}$ z # 50% ^_^ ~ & {}'"))
    assert main(["report", str(path), "--n", "3:3", "--out", str(doc / "r.tex"), "--budget", "10"]) == 0
    run = subprocess.run(["pdflatex", "-recorder", "-interaction=nonstopmode", "-halt-on-error", "r.tex"], cwd=doc,
                         capture_output=True, text=True, timeout=300)
    log = (doc / "r.log").read_text(errors="replace")
    assert run.returncode == 0 and (doc / "r.pdf").stat().st_size > 0, log[-2000:]
    read = (doc / "r.fls").read_text(errors="replace")
    assert "secret" not in read and "LEAKED" not in log and "Undefined control sequence" not in log
    assert "\\textbackslash{}input\\{" in (doc / "r.tex").read_text(encoding="utf-8")
