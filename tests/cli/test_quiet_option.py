"""Issue 34, item 3: ``--quiet`` on every command that shows progress (``inspect``, ``oracle``, ``evaldata``,
``report``, ``tune``, ``refine``; ``design`` shows none). The plain interval is patched to 0 s, so that each run
below prints a progress line on stderr without ``--quiet`` (the test that it would) and none with it.

``oracle`` runs without OpenSubdiv (the bridge and the comparison replaced: what is under test is the loop's
display, not the comparison); ``report`` likewise replaces the document's sections' work and its HTML.
"""

from __future__ import annotations

import types

import pytest

from symdecomp.cli import main
from symdecomp.cli.progress import PLAIN_LINE
from tests.cli.test_inspect_cmd import MODEL


@pytest.fixture(autouse=True)
def every_item_a_line(monkeypatch):
    monkeypatch.setattr("symdecomp.cli.progress.PLAIN_INTERVAL", 0.0)


@pytest.fixture
def no_opensubdiv(monkeypatch):
    monkeypatch.setattr("symdecomp.verify.opensubdiv.load_bridge", lambda *a, **k: None)
    monkeypatch.setattr("symdecomp.verify.oracle.comparison", lambda lattice: (
        lambda n, levels, seed: types.SimpleNamespace(as_json=lambda: {"n": n}, agrees=True)))


@pytest.fixture
def light_report(monkeypatch):
    def build_report(scheme, valences, *, budget, sections):
        return list(sections)  # the work is each section in turn, through the progress display

    monkeypatch.setattr("symdecomp.output.report.build_report", build_report)
    monkeypatch.setattr("symdecomp.output.report_html.report_html", lambda sections: f"<p>{len(sections)} sections</p>")


COMMANDS = {
    "inspect": lambda tmp: ["inspect", str(MODEL), "--json"],
    "inspect --vertices": lambda tmp: ["inspect", str(MODEL), "--vertices", "--json"],
    "oracle": lambda tmp: ["oracle", "--n", "3:5", "--json"],
    "evaldata": lambda tmp: ["evaldata", "--n", "3:4", "--jobs", "1", "--out", str(tmp / "e.dat"), "--json"],
    "evaldata --boundary": lambda tmp: ["evaldata", "--boundary", "--k", "1:2", "--format", "json",
                                        "--out", str(tmp / "e.json"), "--json"],
    "report": lambda tmp: ["report", "catmull-clark", "--n", "3", "--out", str(tmp / "r.html")],
    "tune --table": lambda tmp: ["tune", "5", "--table", "--json"],
    "refine": lambda tmp: ["refine", str(MODEL), "--steps", "2", "--out", str(tmp / "r.obj"), "--json"],
}


@pytest.mark.usefixtures("no_opensubdiv", "light_report")
@pytest.mark.parametrize("name", COMMANDS)
def test_quiet_leaves_stderr_empty_where_progress_would_print(name, tmp_path, capsys):
    argv = COMMANDS[name](tmp_path)
    assert main(argv) == 0
    shown = capsys.readouterr().err.splitlines()
    assert shown and all(PLAIN_LINE.fullmatch(line) for line in shown), shown
    assert main([*argv, "--quiet"]) == 0
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize("command", ["inspect", "oracle", "evaldata", "report", "tune", "refine"])
def test_quiet_is_in_the_help_and_given_once(command, capsys):
    assert main([command, "--help"]) == 0
    assert "--quiet" in capsys.readouterr().out
    assert main([command, "--quiet", "--quiet"]) == 2
    assert "--quiet: given more than once" in capsys.readouterr().err
