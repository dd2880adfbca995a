"""The one progress display (issue 34, item 3): tqdm's bar on a terminal, plain timed lines otherwise, ``--quiet``."""

from __future__ import annotations

import io
import itertools

import pytest

from symdecomp.cli import main
from symdecomp.cli.progress import PLAIN_INTERVAL, PLAIN_LINE, plain_line, progress


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def _clock(step: float):
    """A clock that advances ``step`` seconds each time it is read."""
    ticks = itertools.count()
    return lambda: step * next(ticks)


def test_a_terminal_gets_a_bar_with_rate_and_time_left():
    stream = _Terminal()
    assert list(progress(range(4), 4, "c1", stream=stream, unit="valence")) == [0, 1, 2, 3]
    text = stream.getvalue()
    assert text.startswith("\rc1:   0%|") and "| 4/4 [" in text and "valence/s]" in text and text.endswith("\n")


def test_a_pipe_gets_a_plain_line_every_interval_and_a_last_one():
    """4 s per item (the clock is read once at the start and once per item): lines after items 3, 6 and 9, and at the end."""
    stream = io.StringIO()
    assert list(progress(range(10), 10, "check", stream=stream, clock=_clock(4.0))) == list(range(10))
    assert PLAIN_INTERVAL == 10.0
    assert stream.getvalue().splitlines() == [
        "check: 3/10 (30 %), 0.25 it/s, 00:12 elapsed, about 00:28 left",
        "check: 6/10 (60 %), 0.25 it/s, 00:24 elapsed, about 00:16 left",
        "check: 9/10 (90 %), 0.25 it/s, 00:36 elapsed, about 00:04 left",
        "check: 10/10 (100 %), 0.23 it/s, 00:44 elapsed",
    ]
    assert all(PLAIN_LINE.fullmatch(line) for line in stream.getvalue().splitlines())
    assert not PLAIN_LINE.fullmatch("symdecomp: error: --n: expected a valence")


def test_a_short_run_on_a_pipe_prints_nothing_and_disabled_prints_nothing():
    stream = io.StringIO()
    assert list(progress("abc", 3, "quick", stream=stream, clock=_clock(1.0))) == ["a", "b", "c"]
    assert stream.getvalue() == ""
    terminal = _Terminal()
    assert list(progress("abc", 3, "quiet", stream=terminal, enabled=False)) == ["a", "b", "c"]
    assert terminal.getvalue() == ""


def test_plain_line_says_the_time_left_in_minutes():
    assert plain_line("inspect", 30, 120, 600.0, "vertex") == "inspect: 30/120 (25 %), 0.05 vertex/s, 10:00 elapsed, about 30:00 left"


@pytest.mark.parametrize("argv", [["c1", "--n", "3:4"], ["artifacts", "--n", "3"], ["check", "--n", "3"],
                                  ["claims", "--label", "Eq. 34"]])
def test_long_commands_take_quiet_once(argv, capsys):
    assert main([*argv, "--quiet"]) == 0
    assert capsys.readouterr().err == ""
    assert main([*argv, "--quiet", "--quiet"]) == 2
    assert "--quiet: given more than once" in capsys.readouterr().err
