"""``oracle --plot``: the drawn disagreements are the printed ones, level by level, and shrink at the printed rates;
the exact rows are drawn in units of double precision's epsilon; a bad target, --kind and a missing bridge write
nothing."""

from __future__ import annotations

import json
import math

import jsonschema
import pytest

import symdecomp.verify.opensubdiv as osd
from symdecomp.cli import main
from symdecomp.cli.json_envelope import json_schema
from symdecomp.output.plotting.oracle_chart import EPSILON

pytest.importorskip("matplotlib")


def _bridge() -> None:
    try:
        osd.load_bridge()
    except osd.BridgeUnavailableError:
        pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed")


def _drawn(monkeypatch) -> list:
    figures: list = []
    monkeypatch.setattr("symdecomp.cli.oracle_cmd.write_plot", lambda target, draw: figures.append(draw()) if target else None)
    return figures


def _boom(*args, **kwargs):
    raise AssertionError("the work started")


@pytest.mark.parametrize("scheme", ["loop", "catmull-clark"])
def test_the_drawn_disagreements_are_the_printed_ones_shrinking_at_the_printed_rates(scheme, tmp_path, monkeypatch,
                                                                                     capsys):
    _bridge()
    figures = _drawn(monkeypatch)
    assert main(["oracle", "--n", "5", "--levels", "5", "--scheme", scheme, "--json", "--quiet",
                 "--plot", str(tmp_path / "oracle.png")]) == 0
    out = json.loads(capsys.readouterr().out)
    jsonschema.validate(out, json_schema())
    printed = {r["n"]: r for r in out["rows"]}
    panels = {ax.get_title(): ax for ax in figures[0].axes if ax.get_visible()}
    limit_rows = [(n, p) for n, r in printed.items() for p in r["predictions"] if p["kind"] == "limit"]
    assert limit_rows
    for n, p in limit_rows:
        lines = panels[p["name"]].get_lines()
        k = [line.get_label() for line in lines].index(f"n = {n}")
        measured, reference = lines[k].get_ydata(), lines[k + 1].get_ydata()
        assert lines[k].get_xdata()[-1] == 5 and measured[-1] == p["disagreement"]  # the printed number, the last level
        ratios = [b / a for a, b in zip(measured, measured[1:])]
        if p["observed_rate"] is not None:  # the printed seen rate is one of the drawn steps
            assert any(abs(q - p["observed_rate"]) <= 1e-12 * p["observed_rate"] for q in ratios)
        assert all(abs(b / a - p["rate"]) <= 1e-12 for a, b in zip(reference, reference[1:]))  # the predicted slope
        assert reference[0] == measured[0]
        # --json carries the same numbers the figure draws, level by level
        assert [e["level"] for e in p["per_level"]] == list(lines[k].get_xdata())
        assert [e["disagreement"] for e in p["per_level"]] == list(measured) and len(measured) >= 2
    assert all(q["per_level"] == [] for r in printed.values() for q in r["predictions"] if q["kind"] == "exact")
    bars = panels["exact rows, against double precision"].containers
    exact = {(n, q["name"]): q["disagreement"] for n, r in printed.items() for q in r["predictions"] if q["kind"] == "exact"}
    drawn = {(math.floor(b.get_x() + 0.4 + 1e-9), c.get_label()): b.get_height() * EPSILON for c in bars for b in c.patches}
    assert drawn.keys() == exact.keys()
    assert all(math.isclose(drawn[key], exact[key], rel_tol=1e-12, abs_tol=0) for key in exact)


def test_a_bad_target_is_one_line_before_the_bridge(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(osd, "load_bridge", _boom)
    assert main(["oracle", "--n", "4", "--plot", str(tmp_path / "no" / "oracle.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "does not exist" in err
    assert main(["oracle", "--n", "4", "--plot", str(tmp_path / "oracle.gif")]) == 2
    assert capsys.readouterr().err.count("\n") == 1
    assert main(["oracle", "--kind", "boundary", "--k", "2", "--plot", str(tmp_path / "oracle.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "--kind" in err
    assert list(tmp_path.iterdir()) == []


def test_without_the_bridge_no_figure_is_written(tmp_path, monkeypatch, capsys):
    def unavailable(build=True):
        raise osd.BridgeUnavailableError("OpenSubdiv bridge unavailable: the OpenSubdiv headers are not installed")

    monkeypatch.setattr(osd, "load_bridge", unavailable)
    assert main(["oracle", "--n", "4", "--plot", str(tmp_path / "oracle.svg")]) == 3
    assert "OpenSubdiv" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
