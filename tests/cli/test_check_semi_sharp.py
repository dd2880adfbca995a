"""Issue 35, item 21: ``check`` and ``--sharpness``. Both modes of ``check --k`` compare the refined matrix with the
mirror decomposition, which a semi-sharp vertex does not have: a finite sharpness is refused at once (before the
table's header, which used to print first), in one line naming the combination, and ``--help`` says so."""

import pytest

from symdecomp.cli import main


@pytest.mark.parametrize("argv, words", [
    (["--dart", "--sharpness", "1/2", "--certify"], "--sharpness 1/2 with check --dart (--certify)"),
    (["--dart", "--sharpness", "1/2"], "--sharpness 1/2 with check --dart (numeric mode)"),
    (["--crease", "2", "--sharpness", "0", "--certify"], "--sharpness 0 with check --crease (--certify)"),
    (["--crease", "2", "--sharpness", "5/2"], "--sharpness 5/2 with check --crease (numeric mode)"),
])
def test_a_finite_sharpness_is_refused_before_any_output(capsys, argv, words):
    assert main(["check", "--k", "3", *argv]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.startswith("symdecomp") and captured.err.count("\n") == 1 and words in captured.err
    assert "infinitely sharp edges only" in captured.err


def test_an_infinite_sharpness_is_still_certified(capsys):
    assert main(["check", "--k", "3", "--dart", "--sharpness", "inf", "--certify"]) == 0
    assert "1 vertices: 1 agree" in capsys.readouterr().out


def test_help_says_where_sharpness_applies(capsys):
    assert main(["check", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    entry = text.split("--sharpness S with")[-1]  # the option's entry, after the usage line
    assert "inf only (the default), in both modes" in entry and "refused before any output" in entry
