"""Every error of the command line is one line in one form (issue 34): ``symdecomp: error: MESSAGE``, whether
the parser finds it (then the line ends naming the command's ``--help``) or the command raises it while it runs."""

from __future__ import annotations

import pytest

from symdecomp.cli import build_parser, main
from symdecomp.cli.common import ERROR_PREFIX, Once, error_line


def _repeated_options():
    """For each subcommand, one of its options that may be given once, given twice: a flag, or ``--out`` (never
    written: the parser refuses the repetition before any command runs)."""
    import argparse

    (action,) = [a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction)]
    out = []
    for name, parser in action.choices.items():
        once = {a.option_strings[-1]: a for a in parser._actions if isinstance(a, Once)}
        flags = [option for option, a in once.items() if a.nargs == 0]
        argv = [flags[0]] * 2 if flags else ["--out", "never-written.pdf"] * 2 if "--out" in once else None
        out.append((name, argv))
    return out


@pytest.mark.parametrize(("command", "argv"), _repeated_options())
def test_a_usage_error_of_every_command_is_one_line_in_the_one_form(command, argv, capsys):
    assert argv is not None, f"symdecomp {command}: no option to repeat"
    assert main([command, *argv]) == 2
    assert capsys.readouterr().err == f"symdecomp: error: argument {argv[0]}: given more than once (see 'symdecomp {command} --help')\n"


def test_an_error_raised_while_a_command_runs_has_the_same_form(tmp_path, capsys):
    missing = tmp_path / "missing.obj"
    assert main(["inspect", str(missing)]) == 2
    assert capsys.readouterr().err == f"symdecomp: error: {missing}: cannot read the file (No such file or directory)\n"


def test_the_top_level_parser_has_the_same_form(capsys):
    assert main([]) == 2
    assert capsys.readouterr().err == "symdecomp: error: the following arguments are required: COMMAND (see 'symdecomp --help')\n"


def test_an_error_line_is_one_line():
    assert ERROR_PREFIX == "symdecomp: error: "
    assert error_line(ValueError("a\n  b\tc ")) == "symdecomp: error: a b c"
