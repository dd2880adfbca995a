"""``masks --plot`` for the zoo's schemes and at sharp vertices, checked as mathematics: the drawn weights are the printed
ones; the position mask sums to 1 and each tangent mask to 0; a zoo scheme's tangent weights on class 0 point the way
their points sit (cos and sin of the angle, turned by half a sector around a dual scheme's centre face); a crease
curve's tangent weighs only points on the sharp edges. Where the command finds no mask, --plot says so in one line."""

from __future__ import annotations

import json
import math

import pytest

from symdecomp.cli import main

pytest.importorskip("matplotlib")


def _drawn(monkeypatch) -> list:
    figures: list = []
    monkeypatch.setattr("symdecomp.cli.masks_cmd.write_plot", lambda target, draw: figures.append(draw()) if target else None)
    return figures


def _panels(fig) -> dict:
    """Each panel's title -> (points, weights), the points in the order drawn."""
    return {ax.get_title(): ([tuple(p) for p in ax.collections[0].get_offsets()], list(ax.collections[0].get_array()))
            for ax in fig.axes if ax.get_title()}


@pytest.mark.parametrize("scheme, n, turn", [("doo-sabin", 5, 0.5), ("sqrt3", 5, 0.0), ("modified-butterfly", 4, 0.0),
                                             ("midedge", 5, 0.5)])
def test_a_zoo_scheme_draws_its_printed_masks_where_the_tangents_point(scheme, n, turn, tmp_path, monkeypatch, capsys):
    figures = _drawn(monkeypatch)
    assert main(["masks", str(n), "--scheme", scheme, "--json", "--plot", str(tmp_path / "masks.png")]) == 0
    printed = json.loads(capsys.readouterr().out)
    panels = _panels(figures[0])
    masks = {"position": printed["position"], "tangent 1": printed["tangents"][0], "tangent 2": printed["tangents"][1]}
    for title, mask in masks.items():
        expected = ([float(mask["O"])] if "O" in mask else []) + [float(w) for ws in mask["classes"].values() for w in ws]
        assert panels[title][1] == expected  # the printed decimals, in the printed order
    assert abs(sum(panels["position"][1]) - 1) < 1e-12
    assert all(abs(sum(panels[t][1])) < 1e-12 for t in ("tangent 1", "tangent 2"))
    start = 1 if "O" in printed["position"] else 0
    points = panels["tangent 1"][0][start:start + n]  # class 0, sectors 0..n-1
    for (x, y), c, s in zip(points, panels["tangent 1"][1][start:], panels["tangent 2"][1][start:]):
        gap = (math.atan2(y, x) - math.atan2(s, c)) / (2 * math.pi / n)  # in sectors
        assert abs(gap - turn - round(gap - turn)) < 1e-9 and abs(math.hypot(c, s) - 1) < 1e-12


@pytest.mark.parametrize("argv, curve", [(["3", "--boundary"], "boundary curve tangent"),
                                         (["2", "--crease", "3"], "crease curve tangent"),
                                         (["5", "--dart"], None)])
def test_a_sharp_vertex_draws_its_printed_masks_on_its_sectors(argv, curve, tmp_path, monkeypatch, capsys):
    figures = _drawn(monkeypatch)
    assert main(["masks", *argv, "--json", "--plot", str(tmp_path / "masks.svg")]) == 0
    printed = json.loads(capsys.readouterr().out)
    panels = _panels(figures[0])
    for mask in (printed["position"], *printed["tangents"]):
        points, weights = panels[mask["name"]]
        assert weights == [float(w) for w in mask["weights"].values()]
        assert points[0] == (0.0, 0.0) and len(points) == len(set(points))  # O at the centre, no two points on one place
    assert abs(sum(panels["position"][1]) - 1) < 1e-12
    if curve is not None:  # the crease curve's tangent: nonzero only on O's sharp edges, laid along the x axis
        points, weights = panels[curve]
        assert all(abs(y) < 1e-12 for (x, y), w in zip(points, weights) if w != 0)
        assert abs(sum(w * x for (x, _), w in zip(points, weights))) > 0.5


def test_no_mask_no_figure_one_line(tmp_path, capsys):
    assert main(["masks", "3", "--scheme", "midedge", "--plot", str(tmp_path / "masks.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no masks" in err and "multiplicity" in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("argv, work", [(["5", "--scheme", "doo-sabin"], "symdecomp.analysis.zoo_masks.zoo_masks"),
                                        (["2", "--boundary"], "symdecomp.analysis.masks.sharp_masks")])
def test_a_bad_target_is_one_line_before_the_work(argv, work, tmp_path, monkeypatch, capsys):
    def boom(*args, **kwargs):
        raise AssertionError("the work started")

    monkeypatch.setattr(work, boom)
    assert main(["masks", *argv, "--plot", str(tmp_path / "no" / "masks.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "does not exist" in err
    assert main(["masks", *argv, "--plot", str(tmp_path / "masks.jpg")]) == 2
    assert capsys.readouterr().err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []
