"""What ``charpoly --plot`` and ``masks --plot`` draw, checked as mathematics: the drawn roots satisfy Vieta's
formulas for the printed polynomial; the drawn position mask sums to 1 and each tangent mask to 0 (a left
eigenvector of an eigenvalue other than 1 is orthogonal to the right eigenvector of 1, the constant vector)."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
import sympy as sp

from symdecomp.cli import main

pytest.importorskip("matplotlib")


def _drawn(monkeypatch, module: str) -> list:
    """Run the command's figure function and keep the figure instead of writing it."""
    figures: list = []
    monkeypatch.setattr(f"{module}.write_plot", lambda target, draw: figures.append(draw()) if target else None)
    return figures


def _roots(fig) -> list[tuple[complex, int]]:
    ax = fig.axes[0]
    dots = ax.collections[0]
    sizes = dots.get_sizes()
    return [(complex(x, y), round(s / 18)) for (x, y), s in zip(dots.get_offsets(), sizes)]


def _vieta(points, coefficients: list[complex]) -> None:
    """The drawn roots' product and sum against the polynomial's constant and next-to-leading terms, to 10 digits."""
    degree = sum(m for _, m in points)
    assert degree == len(coefficients) - 1
    product = math.prod(z**m for z, m in points)
    total = sum(z * m for z, m in points)
    lead = coefficients[0]
    assert abs(product - (-1) ** degree * coefficients[-1] / lead) <= 1e-10 * abs(coefficients[-1] / lead)
    assert abs(total + coefficients[1] / lead) <= 1e-10 * max(1.0, abs(coefficients[1] / lead))


def test_charpoly_draws_the_roots_of_the_printed_polynomial(tmp_path, monkeypatch, capsys):
    figures = _drawn(monkeypatch, "symdecomp.cli.charpoly_cmd")
    assert main(["charpoly", "5", "--json", "--plot", str(tmp_path / "roots.png")]) == 0
    printed = json.loads(capsys.readouterr().out)
    coefficients = [complex(Fraction(c)) for c in printed["coefficients"]]
    points = _roots(figures[0])
    _vieta(points, coefficients)
    assert len(coefficients) - 1 == 2 * 5 + 1  # degree: the matrix size
    assert any(abs(z - 1) < 1e-12 and m == 1 for z, m in points)  # the eigenvalue 1, simple


def test_charpoly_of_an_algebraic_polynomial_loop_at_seven(tmp_path, monkeypatch, capsys):
    from symdecomp.analysis.charpoly import ring_charpoly_exact
    from symdecomp.schemes.files import load_scheme

    figures = _drawn(monkeypatch, "symdecomp.cli.charpoly_cmd")
    assert main(["charpoly", "7", "--scheme", "loop", "--plot", str(tmp_path / "roots.svg")]) == 0
    capsys.readouterr()
    exact = ring_charpoly_exact(load_scheme("loop"), 7)[1]
    assert any(not c.is_Rational for c in exact)  # cos(2 pi/7) in the centre's weight
    _vieta(_roots(figures[0]), [complex(sp.N(c, 30)) for c in exact])


def test_free_weights_are_refused_before_the_work(tmp_path, monkeypatch, capsys):
    def boom(*args, **kwargs):
        raise AssertionError("the work started")

    monkeypatch.setattr("symdecomp.analysis.charpoly.closed_form_characteristic_polynomial", boom)
    assert main(["charpoly", "5", "--free-weights", "--plot", str(tmp_path / "roots.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--free-weights and --plot" in err and "no roots to draw" in err
    assert not (tmp_path / "roots.png").exists()


def _weights(fig) -> list[list[float]]:
    """Each panel's drawn weights (the colours of its points), the centre first."""
    return [list(ax.collections[0].get_array()) for ax in fig.axes if ax.get_title()]


@pytest.mark.parametrize("argv, points", [
    (["masks", "5"], 11),
    (["masks", "7", "--scheme", "loop"], 8),
    (["masks", "5", "--rings", "2"], 1 + 5 * 6),
])
def test_masks_draw_a_position_mask_summing_to_one_and_tangents_summing_to_zero(argv, points, tmp_path, monkeypatch,
                                                                                capsys):
    figures = _drawn(monkeypatch, "symdecomp.cli.masks_cmd")
    assert main([*argv, "--plot", str(tmp_path / "masks.png")]) == 0
    capsys.readouterr()
    position, *tangents = _weights(figures[0])
    assert len(position) == points and all(len(t) == points for t in tangents)
    assert abs(sum(position) - 1) < 1e-12  # the printed decimals (20 digits) rounded to floats
    assert all(abs(sum(t)) < 1e-12 for t in tangents)
    assert abs(tangents[0][1] - 1) < 1e-15 and abs(tangents[1][1]) < 1e-15  # the scaling: cos 0 = 1, sin 0 = 0 on a_0


def test_masks_draw_each_weight_at_its_point_of_the_regular_fan(tmp_path, monkeypatch, capsys):
    """The tangent masks are cos and sin of the angle on a_i: the point a_i drawn at that angle, its weight its x (resp.
    y) coordinate."""
    figures = _drawn(monkeypatch, "symdecomp.cli.masks_cmd")
    assert main(["masks", "7", "--plot", str(tmp_path / "masks.png")]) == 0
    capsys.readouterr()
    axes = [ax for ax in figures[0].axes if ax.get_title()]  # the panels, not their colour bars
    for k, ax in enumerate(axes[1:]):
        offsets, weights = ax.collections[0].get_offsets(), ax.collections[0].get_array()
        for (x, y), w in list(zip(offsets, weights))[1:8]:  # a_0..a_6, on the unit circle
            assert abs(math.hypot(x, y) - 1) < 1e-12 and abs((x, y)[k] - w) < 1e-12
