"""``--plot FILE`` on c1, spectrum, artifacts, check, masks, charpoly, refine and design (issue 34, item 1): the
same bytes every run, in the format of the extension, refused before the work for a bad target, one line when
matplotlib is missing."""

from __future__ import annotations

import pytest

from symdecomp.cli import main
from tests.cli.test_inspect_cmd import MODEL

pytest.importorskip("matplotlib")

#: A small run of each command that draws, interior and sharp.
CASES = {
    "c1": ["c1", "--n", "3:5"],
    "c1 --boundary": ["c1", "--boundary", "--k", "2:3"],
    "spectrum": ["spectrum", "6"],
    "spectrum --scheme loop": ["spectrum", "5", "--scheme", "loop"],
    "spectrum --crease": ["spectrum", "3", "--crease", "2"],
    "artifacts": ["artifacts", "--n", "3:6"],
    "check": ["check", "--n", "3:5"],
    "check --certify": ["check", "--n", "3:5", "--certify"],
    "check --boundary": ["check", "--boundary", "--k", "1:3", "--certify"],
    "refine": ["refine", str(MODEL), "--steps", "2", "--out", "{tmp}/refined.obj"],
    "design": ["design", "--n", "5", "--normal", "1,1,2", "--position", "1,2,3", "--elliptic", "1/2", "--hyperbolic", "1/4",
               "--out", "{tmp}/ring.obj"],
    "design --mesh": ["design", "--mesh", str(MODEL), "--vertex", "11", "--normal", "0,0,1", "--out", "{tmp}/model.obj"],
    "masks": ["masks", "5"],
    "masks --scheme loop --rings 2": ["masks", "6", "--scheme", "loop", "--rings", "2"],
    "charpoly": ["charpoly", "5"],
    "charpoly --scheme loop": ["charpoly", "7", "--scheme", "loop"],
    "evaldata": ["evaldata", "--n", "3:4", "--out", "{tmp}/stam.bin", "--quiet"],
    "evaldata --boundary": ["evaldata", "--boundary", "--k", "1:2", "--out", "{tmp}/sharp.json", "--quiet"],
}

#: How each format's file starts.
MAGIC = {"png": b"\x89PNG\r\n\x1a\n", "svg": b"<?xml", "pdf": b"%PDF-"}


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["png", "svg"])
@pytest.mark.parametrize("argv", CASES.values(), ids=CASES.keys())
def test_two_runs_draw_the_same_bytes(argv, fmt, tmp_path, capsys):
    files = [tmp_path / f"first.{fmt}", tmp_path / f"second.{fmt}"]
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]  # the mesh a command writes with its figure
    for path in files:
        assert main([*argv, "--plot", str(path)]) == 0
        assert capsys.readouterr().out  # the text is printed as without --plot
    first, second = (path.read_bytes() for path in files)
    assert first.startswith(MAGIC[fmt]) and len(first) > 1000
    assert first == second
    if fmt == "svg":
        assert b"<dc:date>" not in first and b"symdecomp" in first


def test_a_pdf_by_its_extension_and_without_a_date(tmp_path, capsys):
    out = tmp_path / "Spectrum.PDF"
    assert main(["spectrum", "5", "--plot", str(out)]) == 0
    data = out.read_bytes()
    assert data.startswith(MAGIC["pdf"]) and b"CreationDate" not in data and b"/Creator (symdecomp)" in data


def _refuse(monkeypatch, where: str) -> None:
    """Make the computation of a command fail loudly, so that a refusal must come before it."""
    def boom(*args, **kwargs):
        raise AssertionError("the work started")

    monkeypatch.setattr(where, boom)


@pytest.mark.parametrize("argv, work", [
    (["c1", "--n", "3:4"], "symdecomp.parallel.ordered_map"),
    (["c1", "--boundary", "--k", "2"], "symdecomp.parallel.ordered_map"),
    (["spectrum", "5"], "symdecomp.analysis.spectrum.closed_form_spectrum"),
    (["spectrum", "2", "--boundary"], "symdecomp.analysis.spectrum.sharp_levels"),
    (["artifacts", "--n", "3"], "symdecomp.cli.artifacts_cmd.ordered_map"),
    (["check", "--n", "3"], "symdecomp.cli.check_cmd.check_valences"),
    (["check", "--boundary", "--k", "2", "--certify"], "symdecomp.verify.certify.certify_sharp"),
    (["refine", str(MODEL), "--out", "{tmp}/refined.obj"], "symdecomp.schemes.meshformats.read_mesh"),
    (["design", "--n", "5", "--normal", "0,0,1", "--out", "{tmp}/ring.obj"], "symdecomp.analysis.design.design_ring"),
    (["design", "--mesh", str(MODEL), "--vertex", "11", "--normal", "0,0,1", "--out", "{tmp}/model.obj"],
     "symdecomp.schemes.meshformats.read_mesh"),
    (["masks", "5"], "symdecomp.cli.masks_cmd.lambda_1_subdominance"),
    (["masks", "5", "--scheme", "sqrt3"], "symdecomp.analysis.zoo_masks.zoo_masks"),
    (["masks", "2", "--crease", "3"], "symdecomp.analysis.masks.sharp_masks"),
    (["charpoly", "5"], "symdecomp.analysis.charpoly.closed_form_characteristic_polynomial"),
    (["evaldata", "--n", "3:4", "--out", "{tmp}/stam.bin"], "symdecomp.cli.evaldata_cmd.rounded_eigendata"),
    (["charpoly", "5", "--rings", "2"], "symdecomp.analysis.charpoly.ring_charpoly_exact"),
])
def test_a_bad_target_is_refused_before_the_work(argv, work, tmp_path, monkeypatch, capsys):
    _refuse(monkeypatch, work)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    assert main([*argv, "--plot", str(tmp_path / "figure.jpg")]) == 2
    assert capsys.readouterr().err == (f"symdecomp: error: --plot {tmp_path / 'figure.jpg'}: the file name must end in .png, "
                                       ".svg or .pdf (the format of the figure)\n")
    assert main([*argv, "--plot", str(tmp_path / "no" / "figure.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "does not exist" in err
    (tmp_path / "dir.svg").mkdir()
    assert main([*argv, "--plot", str(tmp_path / "dir.svg")]) == 2
    assert "is a directory" in capsys.readouterr().err
    assert not (tmp_path / "figure.jpg").exists() and list((tmp_path / "dir.svg").iterdir()) == []
    assert not list(tmp_path.glob("*.obj")) and not list(tmp_path.glob("*.bin"))  # refine, design, evaldata wrote nothing


def test_without_matplotlib_one_line_and_exit_3_before_the_work(tmp_path, monkeypatch, capsys):
    import symdecomp.output.plotting._mpl as mpl

    def missing():
        raise ImportError("no matplotlib")

    monkeypatch.setattr(mpl, "require_matplotlib", missing)
    _refuse(monkeypatch, "symdecomp.parallel.ordered_map")
    assert main(["c1", "--n", "3", "--plot", str(tmp_path / "c1.png")]) == 3
    assert capsys.readouterr().err == ("symdecomp: error: --plot needs matplotlib; install it with pip install "
                                       "'symdecomp[report]'\n")
