"""A table of bad command lines: each ends with exit code 2 and one line naming the problem.

They run in-process through ``main(argv)`` (fast); a few go through a real subprocess to
see what a user sees (no traceback, one line on stderr).
"""

import subprocess
import sys

import pytest

from symdecomp.cli import main

#: Bad integer spellings, tried in every integer argument below.
BAD_INTEGERS = ["5_0", "\uff15", "\u0665", "5.0", "0x5", "1e3", "", " ", "five", "5 ", "+", "--5",
                "30000000000000000000000000000", "-0x1", "5\n", "NaN", "inf", "\u00b2"]

#: (argv prefix, argv suffix, word the message names): an integer argument of each command.
INTEGER_SLOTS = [
    (["spectrum"], [], "argument N"),
    (["spectrum", "5", "--digits"], [], "--digits"),
    (["masks"], [], "argument N"),
    (["tune"], [], "argument N"),
    (["check", "--n"], [], "--n"),
    (["check", "--n", "3", "--dps"], [], "--dps"),
    (["oracle", "--levels"], [], "--levels"),
    (["charpoly"], [], "argument N"),
    (["c1", "--n"], [], "--n"),
    (["c1", "--n", "3", "--depth"], [], "--depth"),
]

#: Out of range values, with the word the message names.
OUT_OF_RANGE = [
    (["spectrum", "2"], "argument N"),
    (["spectrum", "0"], "argument N"),
    (["spectrum", "-1"], "argument N"),
    (["spectrum", "2001"], "argument N"),
    (["spectrum", "5", "--digits", "0"], "--digits"),
    (["spectrum", "5", "--digits", "1001"], "--digits"),
    (["masks", "1001"], "argument N"),
    (["masks", "5", "--digits", "100000"], "--digits"),
    (["charpoly", "301"], "argument N"),
    (["tune", "1001"], "argument N"),
    (["tune", "201", "--table"], "tune --table"),
    (["check", "--n", "3:1000000000"], "--n"),
    (["check", "--n", "2:5"], "--n"),
    (["check", "--n", "6:5"], "empty valence range"),
    (["check", "--n", "3:4:5"], "--n"),
    (["check", "--n", ":5"], "--n"),
    (["check", "--n", "3:"], "--n"),
    (["check", "--n", "129"], "numeric mode"),
    (["check", "--n", "3", "--dps", "4"], "--dps"),
    (["check", "--n", "3", "--dps", "1001"], "--dps"),
    (["check", "--n", "3", "--jobs", "0"], "--jobs"),
    (["check", "--n", "3", "--jobs", "257"], "--jobs"),
    (["oracle", "--levels", "1"], "--levels"),
    (["oracle", "--levels", "41"], "--levels"),
    (["oracle", "--n", "65"], "--n"),
    (["oracle", "--seed", "-1"], "--seed"),
    (["oracle", "--seed", "4294967296"], "--seed"),
    (["c1", "--n", "2"], "--n"),
    (["c1", "--n", "10001"], "--n"),
    (["c1", "--n", "3", "--depth", "13"], "--depth"),
    (["c1", "--n", "3", "--depth", "-1"], "--depth"),
    (["c1", "--n", "3", "--n", "4"], "more than once"),
]

#: Wrong options, repeated options, contradictions, unknown names.
MISUSE = [
    # an option the chosen mode would ignore is refused, not dropped
    (["evaldata", "--n", "3:4", "--out", "o.bin", "--digits", "50"], "--digits applies to --format json only"),
    (["evaldata", "--n", "3:4", "--out", "o.bin", "--format", "binary", "--digits", "50"], "--digits applies"),
    (["evaldata", "--n", "3:4", "--out", "o.json", "--format", "json", "--digits", "30", "--jobs", "2"], "computes the valences in one"),
    (["evaldata", "--n", "3:4", "--out", "o.json", "--format", "json", "--digits", "30", "--executor", "local"], "computes the valences in one"),
    (["evaldata", "--n", "3:4", "--out", "o.bin", "--json", "--json"], "more than once"),
    (["spectrum", "5", "--exact"], "--exact applies to the any-scheme route"),
    (["spectrum", "5", "--digits", "3", "--digits", "4"], "more than once"),
    (["spectrum", "5", "--json", "--json"], "more than once"),
    (["spectrum", "5", "--scheme", "catmull-clark", "--scheme", "catmull-clark"], "more than once"),
    (["check", "--n", "3", "--n", "4"], "more than once"),
    (["check", "--n", "3", "--certify", "--certify"], "more than once"),
    (["check", "--n", "3", "--certify", "--dps", "7"], "--certify and --dps"),
    (["check", "--n", "3", "--jobs", "2", "--jobs", "3"], "more than once"),
    (["oracle", "--levels", "3", "--levels", "4"], "more than once"),
    (["oracle", "--n", "3", "--n", "4"], "more than once"),
    (["tune", "5", "--table", "--table"], "more than once"),
    (["masks", "5", "--digits", "5", "--digits", "5"], "more than once"),
    (["charpoly", "5", "--free-weights", "--free-weights"], "more than once"),
    (["charpoly", "5", "--free-weights", "--scheme", "catmull-clark"], "--free-weights and --scheme"),
    (["claims", "--section", "9.9"], "known sections"),
    (["claims", "--section", ""], "known sections"),
    (["claims", "--section", "5.1.1"], "known sections"),
    (["claims", "--section", "5.", "--json"], "known sections"),
    (["claims", "--section", "2", "--section", "3"], "more than once"),
    (["claims", "--label", "no such claim"], "no claim labelled"),
    (["claims", "--json", "--json"], "more than once"),
    (["derive", "--label", "no such claim"], "no claim labelled"),
    (["derive", "--label", "Eq. 34", "--out", "x"], "--label and --out"),
    (["derive", "--label", "Eq. 34", "--json"], "--label and --json"),
    (["derive", "--out", ""], "--out"),
    (["derive", "--out", "/dev/null"], "not a directory"),
    (["derive", "--out", "/nonexistent-dir/derivations"], "does not exist"),
    (["derive", "--out", "a", "--out", "b"], "more than once"),
    (["spectrum", "5", "--scheme", "butterfly"], "unknown scheme"),
    (["spectrum", "5", "--scheme", ""], "unknown scheme"),
    (["spectrum", "5", "--scheme", "kobbelt-quad", "--json"], "'kobbelt-quad' is not shipped: its rule at an extraordinary"),
    (["c1", "--n", "5", "--scheme", "kobbelt-quad"], "'kobbelt-quad' is not shipped"),
    (["spectrum", "5", "--bogus"], "unrecognized arguments"),
    (["spectrum", "5", "6"], "unrecognized arguments"),
    (["spectrum"], "required"),
    (["check"], "required"),
    (["tune"], "required"),
    (["masks"], "required"),
    (["charpoly"], "required"),
    (["nonsense"], "invalid choice"),
    ([], "required"),
    (["--digits", "5"], "invalid choice"),
    (["spectrum", "--digits"], "expected one argument"),
    (["check", "--n"], "expected one argument"),
    (["oracle", "--seed", "1.5"], "--seed"),
]

#: argparse reads a value starting with '-' as an option: then the message names the missing value.
_OPTION_LIKE = ("expected one argument", "required", "unrecognized arguments")

CASES = (
    [(prefix + [bad] + suffix, (word,) + (_OPTION_LIKE if bad.startswith("-") else ()))
     for prefix, suffix, word in INTEGER_SLOTS for bad in BAD_INTEGERS]
    + OUT_OF_RANGE
    + MISUSE
)


def test_the_table_is_large():
    assert len(CASES) >= 150


@pytest.mark.parametrize("argv,word", CASES, ids=[" ".join(map(repr, a)) for a, _ in CASES])
def test_bad_invocation_is_one_line_and_exit_2(argv, word, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a derive that wrongly went ahead would write here, not into the checkout
    assert main(argv) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1, captured.err
    assert any(w in lines[0] for w in ((word,) if isinstance(word, str) else word)), lines[0]
    assert "Traceback" not in captured.err + captured.out
    assert not any(tmp_path.iterdir())


@pytest.mark.slow
@pytest.mark.parametrize(
    "argv",
    [["spectrum", "5_0"], ["check", "--n", "3:1000000000"], ["derive", "--out", ""], ["claims", "--section", "9.9"]],
)
def test_bad_invocation_through_a_real_process(argv):
    out = subprocess.run([sys.executable, "-m", "symdecomp", *argv], capture_output=True, text=True, timeout=300)
    assert out.returncode == 2
    assert len(out.stderr.strip().splitlines()) == 1
    assert "Traceback" not in out.stderr
