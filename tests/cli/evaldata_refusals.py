"""The one check every ``evaldata`` bad-input table runs: exit 2, one line naming the problem, no file written."""

from symdecomp.cli import main


def assert_refused(argv: list[str], message: str, tmp_path, capsys) -> None:
    """``evaldata argv --out x.json`` exits 2 with ``message`` in one stderr line, no traceback, and writes nothing."""
    out = tmp_path / "x.json"
    assert main(["evaldata", *argv, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and "\n" not in err and "Traceback" not in err
    assert not out.exists()
