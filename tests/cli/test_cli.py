"""The command line as a user would try it."""

import json
import subprocess
import sys

import pytest

from symdecomp.cli import main


def test_help_for_every_command(capsys):
    from symdecomp.cli import COMMANDS, build_parser

    parser = build_parser()
    names = [a for a in parser._subparsers._group_actions[0].choices]
    assert len(names) == len(COMMANDS)
    for name in names:
        try:
            main([name, "--help"])
        except SystemExit as exc:
            assert exc.code == 0
        assert "usage: symdecomp " + name in capsys.readouterr().out


def test_spectrum_text_output(capsys):
    assert main(["spectrum", "4", "--digits", "5"]) == 0
    out = capsys.readouterr().out
    assert "9 eigenvalues, 5 distinct" in out
    assert any(line.split() == ["0.25", "3", "0,", "2"] for line in out.splitlines())


def test_spectrum_json_schema(capsys):
    assert main(["spectrum", "6", "--json", "--digits", "12"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) >= {"n", "scheme", "eigenvalues"}
    assert sum(e["multiplicity"] for e in data["eigenvalues"]) == 13
    assert data["eigenvalues"][0] == {"value": "1.0", "multiplicity": 1, "frequencies": [0]}


@pytest.mark.slow
def test_module_entry_point_and_broken_pipe():
    out = subprocess.run([sys.executable, "-m", "symdecomp", "spectrum", "5", "--digits", "8"], capture_output=True, text=True, check=True)
    assert out.stdout.startswith("catmull-clark, valence n = 5: 11 eigenvalues")
    piped = subprocess.run(
        f"{sys.executable} -m symdecomp spectrum 40 | head -n 1", shell=True, capture_output=True, text=True
    )
    assert "Traceback" not in piped.stderr
