"""The tuning figure's cells: a coloured cell's regime holds at its points, decided exactly."""

from fractions import Fraction

import pytest
import sympy as sp

from symdecomp.analysis.curvature_regime import CurvatureRegime as Regime
from symdecomp.analysis.tuning_region import tuning_region
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import alpha, beta

pytest.importorskip("matplotlib")

from symdecomp.output.plotting.tuning import _CODES, cell_regimes, figure_bytes, tuning_region_figure  # noqa: E402


def grid(lo, hi, cells):
    return [lo + (hi - lo) * Fraction(k, cells) for k in range(cells + 1)]


def test_coloured_cells_agree_with_exact_classification():
    region = tuning_region(catmull_clark(alpha, beta), 3)
    xs, ys = grid(Fraction(-2, 5), Fraction(7, 10), 22), grid(Fraction(-1, 2), Fraction(9, 10), 22)
    codes = cell_regimes(region, xs, ys)
    seen = set()
    for code in range(4):  # for each regime: its first, middle and last cell (row by row)
        cells = [(i, j) for i in range(22) for j in range(22) if codes[i, j] == code]
        for i, j in {cells[0], cells[len(cells) // 2], cells[-1]} if cells else ():
            regime = _CODES[code]
            seen.add(regime)
            for x, y in ((xs[j], ys[i]), (xs[j + 1], ys[i + 1]), ((xs[j] + xs[j + 1]) / 2, (ys[i] + ys[i + 1]) / 2)):
                assert region.classify((sp.Rational(x), sp.Rational(y))) is regime, (i, j)
    assert seen == {Regime.NOT_APPLICABLE, Regime.UNBOUNDED, Regime.ZERO}  # BOUNDED is a curve at n = 3: no whole cell
    # a boundary cell really meets a boundary: its corners are not all of one regime, or a form vanishes in it
    boundary = [(i, j) for i in range(22) for j in range(22) if codes[i, j] == 4]
    i, j = boundary[len(boundary) // 2]
    corners = {region.classify((sp.Rational(x), sp.Rational(y))) for x in xs[j:j + 2] for y in ys[i:i + 2]}
    assert len(corners) > 1


def test_figure_pdf_bytes_repeat():
    region = tuning_region(catmull_clark(alpha, beta), 4)
    points = {4: [("Catmull-Clark", (sp.Rational(3, 32), sp.Rational(1, 64)))]}
    first = figure_bytes(tuning_region_figure([region], points, cells=16), "pdf")
    assert first.startswith(b"%PDF") and first == figure_bytes(tuning_region_figure([region], points, cells=16), "pdf")
