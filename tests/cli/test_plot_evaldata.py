"""``evaldata --plot``: the drawn eigenvalues are those of the file written, read back (Stam's file, a boundary vertex's
factors, a dual scheme's decomposition), rank by rank; 1 is the largest at every valence; nothing is gathered without
--plot; the same file as --out, or a bad target, is one line before any work."""

from __future__ import annotations

import json

import numpy as np
import pytest

from symdecomp.cli import main
from symdecomp.output.plotting.evaldata_chart import RANKS, eigenvalue_ranks

pytest.importorskip("matplotlib")


def _drawn(monkeypatch) -> list:
    figures: list = []
    monkeypatch.setattr("symdecomp.cli.evaldata_plot.write_plot", lambda target, draw: figures.append(draw()) if target else None)
    return figures


def _lines(fig) -> list[tuple[list, list]]:
    return [(list(line.get_xdata()), list(line.get_ydata())) for line in fig.axes[0].get_lines()]


def _expected(columns: dict) -> list[tuple[list, list]]:
    """The rank lines of ``columns`` (x -> eigenvalues), as the figure should draw them (real values: the values)."""
    ranked = {x: eigenvalue_ranks(v) for x, v in columns.items()}
    out = []
    for r in range(RANKS):
        xs = [x for x in ranked if len(ranked[x]) > r]
        if xs:
            out.append((xs, [complex(ranked[x][r]).real for x in xs]))
    return out


@pytest.mark.parametrize("fmt", ["binary", "json"])
def test_stams_file_draws_the_eigenvalues_it_holds(fmt, tmp_path, monkeypatch, capsys):
    from symdecomp.output.evaldata import read_binary, read_json

    figures = _drawn(monkeypatch)
    out = tmp_path / f"stam.{fmt}"
    assert main(["evaldata", "--n", "3:6", "--format", fmt, "--out", str(out), "--quiet", "--plot", str(tmp_path / "e.png")]) == 0
    capsys.readouterr()
    written = (read_binary if fmt == "binary" else read_json)(out)
    lines = _lines(figures[0])
    assert lines == _expected({n: [complex(v) for v in d.values] for n, d in written.items()})
    assert lines[0] == ([3, 4, 5, 6], [1.0] * 4)  # the eigenvalue 1 (affine invariance), the largest at every valence
    assert all(0 < y < 1 for y in lines[1][1])  # lambda_1: below 1, the limit exists


def test_a_boundary_vertex_draws_the_roots_of_its_written_factors(tmp_path, monkeypatch, capsys):
    figures = _drawn(monkeypatch)
    out = tmp_path / "sharp.json"
    assert main(["evaldata", "--boundary", "--k", "1:3", "--out", str(out), "--quiet", "--plot", str(tmp_path / "e.svg")]) == 0
    capsys.readouterr()
    doc = json.loads(out.read_text())
    roots = {v["k"]: [complex(z) for f in v["spectrum"] if len(f["factor"]) > 1
                      for z in np.roots([float(c) for c in reversed(f["factor"])])] for v in doc["vertices"]}
    lines = _lines(figures[0])
    assert lines == _expected(roots)
    assert all(abs(y - 1) < 1e-12 for y in lines[0][1]) and len(lines[0][1]) == 3  # 1, the largest at every K
    for k in (1, 2, 3):  # the boundary curve's cubic B-spline: 1/2 is drawn at every K
        assert any(abs(y - 0.5) < 1e-12 for xs, ys in lines for x, y in zip(xs, ys) if x == k)


def test_a_dual_scheme_draws_its_decomposition_written(tmp_path, monkeypatch, capsys):
    from symdecomp.output.dual_evaldata import read_dual_json

    figures = _drawn(monkeypatch)
    out = tmp_path / "dual.json"
    assert main(["evaldata", "--scheme", "doo-sabin", "--n", "3:4", "--out", str(out), "--quiet",
                 "--plot", str(tmp_path / "e.png")]) == 0
    capsys.readouterr()
    written = {n: [complex(float(z.real.mid()), float(z.imag.mid())) for b in d.decomposition for z in b.values]
               for n, d in read_dual_json(out).items()}
    assert _lines(figures[0]) == _expected(written)
    assert _lines(figures[0])[0][1] == [1.0, 1.0]


def test_a_crease_draws_its_decomposition_written(tmp_path, monkeypatch, capsys):
    from symdecomp.output.sector_evaldata import read_sector_json

    figures = _drawn(monkeypatch)
    out = tmp_path / "crease.json"
    assert main(["evaldata", "--crease", "--k", "2", "--out", str(out), "--quiet", "--plot", str(tmp_path / "e.png")]) == 0
    capsys.readouterr()
    written = {sectors[0]: [complex(float(z.real.mid()), float(z.imag.mid())) for b in d.decomposition for z in b.values]
               for (_, sectors), d in read_sector_json(out).items()}
    lines = _lines(figures[0])
    assert lines == _expected(written) and lines[0] == ([2], [1.0])


@pytest.mark.parametrize("argv, drawn", [
    (["oracle"], ["'limit' row", "shrink rate", "epsilon"]),
    (["evaldata"], ["eigenvalues of the data written", "one line per rank", "same file as --out"]),
    (["masks"], ["sharp vertex's sectors", "zoo's neighbourhood", "n-gon's corners"]),
])
def test_help_names_what_is_drawn(argv, drawn, capsys):
    assert main([*argv, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    plot = text[text.index("--plot FILE"):]
    assert all(words in plot for words in drawn)


def test_nothing_is_gathered_without_plot(tmp_path, monkeypatch, capsys):
    def boom(*args, **kwargs):
        raise AssertionError("gathered without --plot")

    for name in ("piece_values", "factor_roots"):
        monkeypatch.setattr(f"symdecomp.cli.evaldata_cmd.{name}", boom)
    assert main(["evaldata", "--n", "3:4", "--out", str(tmp_path / "stam.bin"), "--quiet"]) == 0
    assert main(["evaldata", "--boundary", "--k", "1", "--out", str(tmp_path / "sharp.json"), "--quiet"]) == 0
    capsys.readouterr()


@pytest.mark.parametrize("argv", [["--n", "3:4"], ["--boundary", "--k", "1"], ["--crease", "--k", "2"],
                                  ["--scheme", "doo-sabin", "--n", "3"]])
def test_plot_on_out_or_a_bad_target_is_one_line_before_the_work(argv, tmp_path, monkeypatch, capsys):
    def boom(*args, **kwargs):
        raise AssertionError("the work started")

    for work in ("symdecomp.cli.evaldata_cmd.rounded_eigendata", "symdecomp.analysis.subpatch_data.sharp_patch_data",
                 "symdecomp.analysis.sector_evaldata.sector_evaldata", "symdecomp.analysis.dual_evaldata.dual_evaldata"):
        monkeypatch.setattr(work, boom)
    out = tmp_path / "data.png"
    assert main(["evaldata", *argv, "--out", str(out), "--plot", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "the same file as --out" in err
    assert main(["evaldata", *argv, "--out", str(tmp_path / "d.json"), "--plot", str(tmp_path / "no" / "e.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "does not exist" in err
    assert main(["evaldata", *argv, "--out", str(tmp_path / "d.json"), "--plot", str(tmp_path / "e.bmp")]) == 2
    assert capsys.readouterr().err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []


def test_the_plot_reads_a_binary_piece_through_the_files_reader(tmp_path, capsys):
    """``piece_values`` of each valence's piece, as the command writes it, are the eigenvalues the file's reader gives
    (one decoder of the layout); the pieces are the file's bytes after Nmax, and a short piece is refused."""
    from symdecomp.cli.evaldata_plot import piece_values
    from symdecomp.errors import EvalDataFileError
    from symdecomp.output.evaldata import binary_valence, read_binary

    out = tmp_path / "stam.bin"
    assert main(["evaldata", "--n", "3:5", "--format", "binary", "--out", str(out), "--quiet"]) == 0
    capsys.readouterr()
    read = read_binary(out)
    pieces = [binary_valence(read[n]) for n in (3, 4, 5)]
    assert b"".join(p.data for p in pieces) == out.read_bytes()[4:]
    for p in pieces:
        values = piece_values(p)
        assert values == [complex(v) for v in read[p.n].values] and len(values) == 2 * p.n + 8
        assert max(values, key=abs) == 1.0  # affine invariance: the eigenvalue 1, the largest
    with pytest.raises(EvalDataFileError, match="valence 4"):
        piece_values(type(pieces[1])(4, pieces[1].data[:-8]))
