"""symdecomp.output.plotting.boundary: the polylines are eigenvectors of the exact sector matrix, Jordan chains are real."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis.mirror import sector_decomposition
from symdecomp.schemes.loop import loop

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from symdecomp.output.plotting import boundary  # noqa: E402

SCHEMES = {"catmull-clark": sd.catmull_clark(), "loop": loop()}


def _exact_matrix(scheme, k) -> sp.Matrix:
    return sector_decomposition(scheme, k).matrix


@pytest.mark.parametrize("name", SCHEMES)
@pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 6])
def test_modes_are_eigenvectors_of_the_exact_matrix(name, k):
    scheme = SCHEMES[name]
    modes = boundary.sector_modes(scheme, k)
    S = np.array(_exact_matrix(scheme, k).evalf(30).tolist(), dtype=float)
    assert len(modes) == S.shape[0]  # one vector per eigenvalue with multiplicity: the decomposition is complete
    values = sorted(m.value_float for m in modes)
    assert np.allclose(values, sorted(np.linalg.eigvals(S).real), atol=1e-6)  # a Jordan block perturbs at sqrt(eps)
    for m in modes:
        residual = S @ m.vector - m.value_float * m.vector
        if m.eigenvector:
            assert np.max(np.abs(residual)) < 1e-12, (m.block, m.j, m.value)
        else:  # a Jordan chain: (S - lambda) v is an eigenvector for lambda, not 0
            assert np.max(np.abs(residual)) > 1e-3
            assert np.max(np.abs(S @ residual - m.value_float * residual)) < 1e-12


@pytest.mark.parametrize("name", SCHEMES)
@pytest.mark.parametrize("k", [1, 3, 4, 5])
def test_jordan_chains_are_where_the_exact_matrix_is_defective(name, k):
    scheme = SCHEMES[name]
    S = _exact_matrix(scheme, k)
    modes = boundary.sector_modes(scheme, k)
    for value in {m.value for m in modes if m.block == "crease"}:
        A = S - value * sp.eye(S.rows)
        geometric = S.rows - A.rank()
        algebraic = S.rows - (A ** S.rows).rank()
        chain = any(not m.eigenvector for m in modes if m.value == value)
        assert chain == (geometric < algebraic), (value, geometric, algebraic)


@pytest.mark.parametrize("name", SCHEMES)
def test_sine_polylines_vanish_on_the_sharp_edges_and_crease_ones_are_mirror_symmetric(name):
    k = 5
    scheme = SCHEMES[name]
    for m in boundary.sector_modes(scheme, k):
        a = m.vector[1:k + 2]
        if m.block == "crease":
            if m.eigenvector:
                assert np.allclose(a, a[::-1]) or np.allclose(a, -a[::-1])
        else:
            assert abs(m.vector[0]) < 1e-14 and abs(a[0]) < 1e-14 and abs(a[-1]) < 1e-14
            # frequency j: a_i = A sin(j pi i/k), so a_(k-i) = (-1)^(j+1) a_i
            assert np.allclose(a[::-1], (-1) ** (m.j + 1) * a)


def test_polylines_figure_has_a_panel_per_block_with_labels():
    fig = boundary.sector_polylines_figure(SCHEMES["catmull-clark"], 4)
    shown = [ax for ax in fig.axes if ax.axison]
    assert len(shown) == 1 + 3 + 1  # crease, sine j = 1..3, face j = 4
    for ax in shown:
        assert ax.get_title() and ax.get_xlabel() and ax.get_ylabel()
        assert any("lambda" in t.get_text() for t in ax.get_legend().get_texts())
