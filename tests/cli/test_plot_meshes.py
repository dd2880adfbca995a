"""``refine --plot`` and ``design --plot`` draw what the command wrote and printed: the refined mesh's 4^K faces per
quad over the control mesh's edges, the designed net with the limit point and the normal the command reports."""

from __future__ import annotations

import json

import numpy as np
import pytest

from symdecomp.cli import main
from symdecomp.schemes.meshformats import read_mesh
from tests.cli.test_inspect_cmd import MODEL

pytest.importorskip("matplotlib")


@pytest.fixture
def drawn(monkeypatch):
    """The figures the command writes with --plot, in order (each after it was laid out and saved)."""
    import symdecomp.output.plotting._mpl as mpl

    figures, save = [], mpl.figure_bytes

    def keep(fig, fmt, **options):
        figures.append(fig)
        return save(fig, fmt, **options)

    monkeypatch.setattr(mpl, "figure_bytes", keep)
    return figures


def _collections(fig):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    (ax,) = fig.axes
    faces = [c for c in ax.collections if isinstance(c, Poly3DCollection)]
    edges = [c for c in ax.collections if isinstance(c, Line3DCollection)]
    return ax, faces, edges


@pytest.mark.parametrize("steps", [1, 2])
def test_refine_draws_4_to_the_k_faces_per_quad_over_the_control_meshs_edges(steps, tmp_path, capsys, drawn):
    control = read_mesh(MODEL)
    assert {len(f) for f in control.faces} == {4}
    assert main(["refine", str(MODEL), "--steps", str(steps), "--out", str(tmp_path / "r.obj"), "--json",
                 "--plot", str(tmp_path / "r.png")]) == 0
    summary = json.loads(capsys.readouterr().out)
    ax, (faces,), (edges,) = _collections(drawn[0])
    assert len(faces.get_paths()) == 4**steps * len(control.faces) == summary["faces"]
    # a closed quad mesh has E = 2F edges (V - E + F = 2 is then V = F + 2, as the model's 36 vertices and 34 faces)
    assert len(edges.get_segments()) == 2 * len(control.faces) and len(control.points) == len(control.faces) + 2
    assert "drawn" not in ax.get_title()


def test_refine_draws_an_even_sample_past_its_limit_and_says_so(tmp_path, capsys, drawn, monkeypatch):
    monkeypatch.setattr("symdecomp.output.plotting.refine_figure.MAX_REFINED_FACES", 100)
    assert main(["refine", str(MODEL), "--out", str(tmp_path / "r.obj"), "--plot", str(tmp_path / "r.svg")]) == 0
    ax, (faces,), _ = _collections(drawn[0])
    assert len(faces.get_paths()) == 4 * 34 // 2 <= 100  # every 2nd of the 136 faces
    assert "(68 of the 136 faces drawn: one in 2, at most 100)" in ax.get_title()


def test_the_help_names_the_limit_the_figure_draws(capsys):
    from symdecomp.output.plotting.refine_figure import MAX_REFINED_FACES

    assert main(["refine", "--help"]) == 0
    assert f"at most {MAX_REFINED_FACES} faces" in " ".join(capsys.readouterr().out.split())


def _line(ax, label: str) -> np.ndarray:
    (line,) = [line for line in ax.get_lines() if line.get_label() == label]
    return np.array(line.get_data_3d(), dtype=float).T


@pytest.mark.parametrize("scheme, n", [("catmull-clark", 5), ("loop", 6)])
def test_design_draws_the_printed_limit_point_and_normal_on_the_written_net(scheme, n, tmp_path, capsys, drawn):
    out = tmp_path / "ring.obj"
    assert main(["design", "--scheme", scheme, "--n", str(n), "--normal", "1,1,2", "--position", "1,2,3", "--elliptic", "1/2",
                 "--out", str(out), "--json", "--plot", str(tmp_path / "ring.png")]) == 0
    data = json.loads(capsys.readouterr().out)
    net = read_mesh(out)
    ax, (faces,), _ = _collections(drawn[0])
    assert len(faces.get_paths()) == len(net.faces)  # every face of a 2-ring has a corner in the 1-ring
    (limit,) = _line(ax, "limit point")
    assert np.allclose(limit, data["position"], rtol=0, atol=1e-12) and np.allclose(limit, (1, 2, 3), rtol=0, atol=1e-12)
    (centre,) = _line(ax, "O (centre vertex)")
    assert (centre == net.points_array[data["vertex"]]).all()
    start, end = _line(ax, "limit normal")
    direction = (end - start) / np.linalg.norm(end - start)
    assert (start == limit).all()
    assert np.allclose(direction, data["normal"], rtol=0, atol=1e-12)
    assert np.allclose(direction, np.array([1, 1, 2]) / np.sqrt(6), rtol=0, atol=1e-12)  # the prescribed normal
    for k in (1, 2):
        t0, t1 = _line(ax, f"tangent t{k} (direction)")
        assert abs((t1 - t0) @ direction) < 1e-12 * np.linalg.norm(t1 - t0)  # in the tangent plane


def test_a_redesign_draws_the_faces_around_the_vertex_and_its_new_normal(tmp_path, capsys, drawn):
    out = tmp_path / "model.obj"
    assert main(["design", "--mesh", str(MODEL), "--vertex", "11", "--normal", "0,0,1", "--out", str(out), "--json",
                 "--plot", str(tmp_path / "model.svg")]) == 0
    data = json.loads(capsys.readouterr().out)
    mesh = read_mesh(out)
    ax, (faces,), _ = _collections(drawn[0])
    touching = [f for f in mesh.faces if set(f) & set(data["ring"])]
    assert len(faces.get_paths()) == len(touching) < len(mesh.faces)
    start, end = _line(ax, "limit normal")
    assert np.allclose((end - start) / np.linalg.norm(end - start), (0, 0, 1), rtol=0, atol=1e-12)


def test_plot_and_out_naming_one_file_is_refused_before_the_work(tmp_path, capsys, monkeypatch):
    def boom(*args, **kwargs):
        raise AssertionError("the work started")

    monkeypatch.setattr("symdecomp.analysis.design.design_ring", boom)
    same = tmp_path / "ring.png"
    assert main(["design", "--n", "5", "--normal", "0,0,1", "--out", str(same), "--format", "obj", "--plot", str(same)]) == 2
    assert capsys.readouterr().err == (f"symdecomp: error: --plot {same}: the same file as --out; the figure and the mesh "
                                       "need two files\n")
    assert not same.exists()
