"""``spectrum --plot`` and ``c1 --plot`` for the zoo's schemes (issue 30): every family and a user's file draws, a PNG of
the figure's size (inches times the dpi of ``figure_bytes``) or an SVG, the same bytes on a second run, with ``--json``
too; a bad target is refused before the work."""

from __future__ import annotations

import json
import struct

import pytest

from symdecomp.cli import main
from symdecomp.schemes.stencil_files import ZOO_FILES

pytest.importorskip("matplotlib")

#: A Doo-Sabin variant as a user writes it: other corner weights at every face but the regular quad (the extra term
#: (m - 4) (delta_j0 - 1/m)/64 sums to 0 over the corners and vanishes at m = 4).
VARIANT = """name = "my-doo-sabin"
mesh = "quad"
topology = "dual"

[[corner]]
terms = [
  {walk = "", weight = "KroneckerDelta(j, 0)/4 + (3 + 2*cos(2*pi*j/m))/(4*m) + (m - 4)*(KroneckerDelta(j, 0) - 1/m)/64", over = "face"},
]
"""

MAGIC = {"png": b"\x89PNG\r\n\x1a\n", "svg": b"<?xml"}


@pytest.fixture
def schemes(tmp_path):
    """The zoo's families by name, and the user's file by its path."""
    path = tmp_path / "my-doo-sabin.toml"
    path.write_text(VARIANT)
    return [*ZOO_FILES, str(path)]


def _png_size(data: bytes) -> tuple[int, int]:
    """Width and height from the PNG's IHDR chunk."""
    assert data.startswith(MAGIC["png"]) and data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


def _twice(argv: list[str], path, capsys) -> bytes:
    """Run ``argv --plot path`` twice; the two files' bytes must be equal."""
    out = []
    for _ in range(2):
        path.unlink(missing_ok=True)
        code = main([*argv, "--plot", str(path)])
        assert code in (0, 1) and capsys.readouterr().err == ""  # c1: exit 1 unless every valence is certified
        out.append(path.read_bytes())
    assert out[0] == out[1]
    return out[0]


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["png", "svg"])
def test_spectrum_plot_draws_every_family_the_same_bytes(schemes, fmt, tmp_path, capsys):
    for scheme in schemes:
        data = _twice(["spectrum", "4", "--scheme", scheme, "--digits", "6"], tmp_path / f"spectrum.{fmt}", capsys)
        if fmt == "png":
            assert _png_size(data) == (750, 450)  # new_figure(7.5, 4.5) at 100 dpi
        else:
            assert data.startswith(MAGIC["svg"]) and b'width="540pt" height="324pt"' in data  # 7.5 x 4.5 inches
            assert b"neighbourhood of depth" in data  # the zoo's title (matplotlib keeps each text as a comment)


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_c1_plot_draws_every_family_the_same_bytes(schemes, tmp_path, capsys):
    """One valence: one map panel, the figure 2 x 3.7 by 7.2 inches."""
    for scheme in schemes:
        data = _twice(["c1", "--n", "4", "--scheme", scheme, "--quiet"], tmp_path / "c1.png", capsys)
        assert _png_size(data) == (740, 720)


def test_c1_plot_svg_with_json(tmp_path, capsys):
    path = tmp_path / "c1.svg"
    assert main(["c1", "--n", "3:4", "--scheme", "midedge", "--quiet", "--json", "--plot", str(path)]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]  # n = 3 by the Jordan chain's map (Reif's conditions fail), n = 4 by Reif's test
    assert [(r["n"], r["verdict"]) for r in rows] == [(3, "c1"), (4, "c1")]
    assert path.read_bytes().startswith(MAGIC["svg"])


def test_spectrum_plot_with_json(tmp_path, capsys):
    path = tmp_path / "s.png"
    assert main(["spectrum", "4", "--scheme", "sqrt3", "--json", "--plot", str(path)]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["command"] == "spectrum" and _png_size(path.read_bytes()) == (750, 450)


@pytest.mark.parametrize("argv, work", [
    (["spectrum", "4", "--scheme", "doo-sabin"], "symdecomp.analysis.zoo_spectrum.zoo_spectrum"),
    (["c1", "--n", "4", "--scheme", "sqrt3"], "symdecomp.parallel.ordered_map"),
])
def test_a_bad_target_is_refused_before_the_work(argv, work, tmp_path, monkeypatch, capsys):
    def boom(*args, **kwargs):
        raise AssertionError("the work started")

    monkeypatch.setattr(work, boom)
    assert main([*argv, "--plot", str(tmp_path / "figure.jpg")]) == 2
    assert capsys.readouterr().err == (f"symdecomp: error: --plot {tmp_path / 'figure.jpg'}: the file name must end in .png, "
                                       ".svg or .pdf (the format of the figure)\n")


@pytest.mark.slow
def test_check_and_artifacts_plot_for_the_zoo(tmp_path, capsys):
    """``check --certify --plot`` (the certified chart: distinct eigenvalues proved per valence) and ``artifacts --plot``
    (the regime chart; the zoo's rows give lambda_1^2 exact) draw as for catmull-clark, the same bytes twice."""
    data = _twice(["check", "--n", "4:5", "--certify", "--scheme", "midedge", "--quiet", "--jobs", "1"], tmp_path / "c.png", capsys)
    assert _png_size(data) == (750, 450)
    data = _twice(["artifacts", "--n", "4:5", "--scheme", "midedge", "--quiet", "--jobs", "1"], tmp_path / "a.png", capsys)
    assert _png_size(data) == (750, 600)


def test_check_of_the_zoo_runs_on_the_pool_and_refuses_what_it_would_ignore(capsys):
    """--jobs and --executor choose the pool as for catmull-clark (the same rows with 1 worker and 2); the options of the
    other mode and of the 1-ring's routes were accepted and ignored: now one line each, exit code 2."""
    outs = []
    for jobs in ("1", "2"):
        assert main(["check", "--n", "4:5", "--certify", "--scheme", "doo-sabin", "--quiet", "--json", "--jobs", jobs]) == 0
        outs.append(json.loads(capsys.readouterr().out)["rows"])
    assert outs[0] == outs[1] and [r["status"] for r in outs[0]] == ["agree", "agree"]
    for option, text in ((["--dps", "30"], "--dps: not used for --scheme doo-sabin (a scheme of the zoo): the certified check is exact"),
                         (["--route", "charpoly"], "--route: not used for --scheme doo-sabin (a scheme of the zoo): the zoo's "
                          "certificate chooses its route itself"),
                         (["--structural"], "--structural: not used for --scheme doo-sabin"),
                         (["--solver", "mpmath"], "--solver: not used for --scheme doo-sabin")):
        assert main(["check", "--n", "4", "--certify", "--scheme", "doo-sabin", *option]) == 2
        err = capsys.readouterr().err.splitlines()
        assert len(err) == 1 and err[0].startswith(f"symdecomp: error: {text}")
