"""Figures of symdecomp.output.plotting.shape: labelled panels whose numbers are the certificate's."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import symdecomp as sd
from symdecomp.errors import InvalidInputError

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from symdecomp.output.plotting import shape as splots  # noqa: E402
from symdecomp.verify.shape import shape_chart  # noqa: E402

CC, LOOP = sd.catmull_clark(), sd.loop()


def _labelled(fig) -> bool:
    return all(ax.get_title() and ax.get_xlabel() and ax.get_ylabel() for ax in fig.axes)


def test_regular_hyperbolic_height_is_the_real_part_of_z_squared():
    """Loop at n = 6, t = 0: h_2c = Re((2 chi)^2) up to a constant (x^2 - y^2 has no B-spline correction), K < 0 everywhere."""
    ring = splots.height_field_samples(LOOP, 6, "hyperbolic", samples=4)
    d = ring["h"] - 4 * (ring["x"] ** 2 - ring["y"] ** 2)
    assert d.max() - d.min() < 1e-12 and (ring["k"] < 0).all()


def test_sampled_curvature_signs_agree_with_the_verdicts():
    assert (splots.height_field_samples(LOOP, 24, samples=7)["k"] > 0).all()
    k = splots.height_field_samples(LOOP, 25, samples=13)["k"]
    assert k.min() < 0 < k.max()


def test_figures_have_titles_and_labelled_axes_and_say_what_is_not_determined():
    fig = splots.height_field_figure(CC, (4, 5), "hyperbolic", samples=4)
    assert _labelled(fig)
    assert fig.axes[0].get_title() == "n = 4: not determined"
    assert fig.axes[1].get_title().startswith("n = 5: hyperbolic")
    chart = shape_chart(CC, 5, ratios=[0, Fraction(1, 2), 1], angles=[0])
    fig = splots.shape_chart_figure([chart])
    assert _labelled(fig) and "mu_2 = 0.3401" in fig.axes[0].get_title()
    colours = [p.get_facecolor() for p in fig.axes[0].patches]
    want = [matplotlib.colors.to_rgba(splots.KIND_COLOURS[k]) for k in ("elliptic", "hybrid", "hyperbolic")]
    assert [tuple(np.round(c, 6)) for c in colours] == [tuple(np.round(c, 6)) for c in want]


def test_bad_figure_arguments_are_named():
    with pytest.raises(InvalidInputError, match="kind must be"):
        splots.height_field_samples(CC, 5, "parabolic")
    with pytest.raises(InvalidInputError, match="charts must be"):
        splots.shape_chart_figure([])
