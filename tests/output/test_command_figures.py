"""The figures of ``--plot`` (issue 34, item 1) show the numbers of the results the commands print."""

from __future__ import annotations

import math

import pytest

from symdecomp import artifact_indicators, c1_test, catmull_clark, closed_form_spectrum, numeric_check
from symdecomp.output.plotting.c1_figures import c1_figure
from symdecomp.output.plotting.check_chart import check_figure
from symdecomp.output.plotting.regime_chart import regime_figure
from symdecomp.output.plotting.spectrum_chart import spectrum_figure
from symdecomp.symbols import n as N

pytest.importorskip("matplotlib")
CC = catmull_clark()


def _offsets(ax) -> list[tuple[float, float]]:
    return [tuple(map(float, p)) for c in ax.collections for p in c.get_offsets()]


def test_the_spectrum_figure_has_each_eigenvalue_at_each_of_its_frequencies():
    spectrum = closed_form_spectrum(CC, 6)
    (ax,) = spectrum_figure(spectrum).axes
    expected = sorted((k, float(e.value)) for e in spectrum.eigenvalues for k in e.frequencies)
    assert sorted(_offsets(ax)) == pytest.approx(expected)
    assert len(expected) == 2 * 6 + 1 - 1  # frequency 0 gives three eigenvalues, each other frequency two: 3 + 2 * 5


def test_the_regime_chart_compares_mu_with_lambda_1_squared():
    rows = [artifact_indicators(CC, n).as_json() for n in (3, 4, 5)]
    top, bottom = regime_figure("catmull-clark", rows).axes
    ratios = [y for _, y in _offsets(bottom)]
    expected = [float(r["curvature"]["mu"][0]["value"]) / float(r["curvature"]["lambda1_squared"]) for r in rows]
    assert ratios == pytest.approx(expected)
    assert ratios[0] < 1 and ratios[1] == pytest.approx(1, abs=1e-9) and ratios[2] > 1  # zero, bounded, unbounded


def test_the_check_figure_shows_the_digits_of_agreement():
    rows = [numeric_check(CC, n, dps=30).as_json() for n in (3, 4)]
    (ax,) = check_figure("catmull-clark", rows).axes
    deviations = [y for x, y in _offsets(ax)[:2]]
    assert deviations == pytest.approx([-math.log10(float(r["max_deviation"])) for r in rows])
    assert min(deviations) > 30  # agreement beyond the digits asked for


def test_the_c1_figure_says_why_a_valence_has_no_map():
    """alpha = beta = 0 at valence 3: the frequency-0 eigenvalue dominates, so there is no characteristic map."""
    broken = catmull_clark(3 * (N - 3) / 32, (N - 3) / 64)
    rows = [c1_test(broken, 3).as_json(), c1_test(CC, 4).as_json()]
    fig = c1_figure(broken, rows)
    first, second, bounds = fig.axes
    assert first.get_title() == "n = 3: not-c1" and first.texts[0].get_text().startswith("no characteristic map:")
    assert second.get_title() == "n = 4: c1" and len(second.lines) > 10 and not second.texts
    assert [y for _, y in _offsets(bounds)][:1] == pytest.approx([rows[1]["jacobian_lower_bound"]])
