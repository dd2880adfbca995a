"""The oracle command without OpenSubdiv: a clear message and exit status 3, no traceback."""


import symdecomp.verify.opensubdiv as osd
from symdecomp.cli import main


def test_oracle_without_the_bridge(monkeypatch, capsys):
    def unavailable(build=True):
        raise osd.BridgeUnavailableError("OpenSubdiv bridge unavailable: the OpenSubdiv headers are not installed")

    monkeypatch.setattr(osd, "load_bridge", unavailable)
    assert main(["oracle", "--n", "4"]) == 3
    assert "OpenSubdiv" in capsys.readouterr().err


def test_oracle_rejects_bad_arguments(capsys):
    assert main(["oracle", "--n", "2:5"]) == 2
    assert "valence" in capsys.readouterr().err
    assert main(["oracle", "--n", "4", "--levels", "1"]) == 2


def test_oracle_takes_catmull_clark_and_loop_only(capsys):
    assert main(["oracle", "--n", "4", "--scheme", "loop-warren"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Catmull-Clark and Loop with their standard weights" in err
