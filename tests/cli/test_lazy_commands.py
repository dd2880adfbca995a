"""The command line starts without the computation: ``--help`` and ``--version`` import no analysis,
verify, claims or output module, and neither does any command module's ``register`` (issue 23, item 5).

Each check runs in a fresh interpreter, which reports the modules it has loaded; the time this
saves is measured in ``benchmarks/bench_startup.py``, not here.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CLI = ROOT / "symdecomp" / "cli"

#: The layers a parser must not need: what the commands compute with, imported when a command runs.
HEAVY = ("symdecomp.analysis", "symdecomp.verify", "symdecomp.claims", "symdecomp.output")


def _loaded(code: str) -> dict:
    """Run ``code`` in a fresh interpreter (this checkout first on the path); it leaves its report in ``report``."""
    script = f"import json, sys\nreport = {{}}\n{code}\nprint(json.dumps(report))\n"
    done = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def _heavy(modules) -> list[str]:
    return sorted(m for m in modules if m in HEAVY or m.startswith(tuple(f"{layer}." for layer in HEAVY)))


def test_the_heavy_test_can_fail():
    assert _heavy(["symdecomp.cli.common", "symdecomp.analysis.spectrum", "symdecomp.outputs"]) == ["symdecomp.analysis.spectrum"]


def test_importing_the_package_imports_only_its_errors():
    report = _loaded("import symdecomp\nreport['modules'] = sorted(m for m in sys.modules if m.startswith('symdecomp'))")
    assert report["modules"] == ["symdecomp", "symdecomp.errors"]


@pytest.mark.parametrize("argv", [["--version"], ["--help"], ["c1", "--help"], ["claims", "--help"], ["check", "--help"]])
def test_help_and_version_load_no_computation(argv):
    """What the program's child runs (``main``) and what its first process imports (``entry``'s modules)."""
    report = _loaded(
        "import contextlib, io\n"
        "import symdecomp.parallel\n"
        "from symdecomp.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()) as out:\n"
        f"    report['code'] = main({argv!r})\n"
        "report['out'] = out.getvalue()\n"
        "report['modules'] = sorted(sys.modules)\n"
    )
    assert report["code"] == 0
    assert report["out"].strip(), "nothing printed"
    assert _heavy(report["modules"]) == []
    assert "numpy" not in report["modules"]  # the parsers need none of it (matplotlib neither)


def _command_modules() -> list[str]:
    return sorted(p.stem for p in CLI.glob("*_cmd.py"))


def test_every_command_module_is_registered():
    """A new ``*_cmd.py`` is listed in ``COMMANDS`` (so it is in ``--help``, and the next test checks it)."""
    from symdecomp.cli import COMMANDS

    assert sorted(COMMANDS) == _command_modules()


def test_no_command_module_imports_the_computation_to_register():
    """Every command module, found by its file name: importing it and calling ``register`` loads no heavy layer;
    the first module that does is named. (Its heavy imports belong in its run functions.)"""
    report = _loaded(
        "import argparse, importlib\n"
        "sub = argparse.ArgumentParser().add_subparsers()\n"
        "report['after'] = {}\n"
        f"for name in {_command_modules()!r}:\n"
        "    importlib.import_module('symdecomp.cli.' + name).register(sub)\n"
        "    report['after'][name] = sorted(sys.modules)\n"
    )
    assert report["after"], "no command module found"
    for name, modules in report["after"].items():
        assert _heavy(modules) == [], f"symdecomp/cli/{name}.py imports the computation at import or in register()"
