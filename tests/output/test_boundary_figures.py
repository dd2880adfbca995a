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


# ---------------------------------------------------------------- the characteristic map of a sector


def _vertex():
    from symdecomp.schemes.sector import SharpVertex

    return SharpVertex


def _ring_matrix(scheme, vertex, rings=3):
    from symdecomp.schemes.sector import sharp_subdivision_matrix

    return np.array(sharp_subdivision_matrix(scheme, vertex, rings=rings).evalf(30).tolist(), dtype=float)


@pytest.mark.parametrize("name, k, angle", [("catmull-clark", 1, sp.pi / 2), ("catmull-clark", 3, 3 * sp.pi / 2),
                                            ("loop", 2, sp.pi / 2), ("loop", 4, 4 * sp.pi / 3)])
def test_the_map_is_an_eigenvector_pair_of_the_ring_matrix(name, k, angle):
    scheme = SCHEMES[name]
    vertex = _vertex().corner(k, scheme.lattice, angle)
    m = boundary.sector_characteristic_map(scheme, vertex, levels=1)
    S = _ring_matrix(scheme, vertex)
    l1, l2 = m.eigenvalues
    for part, lam in ((m.ring.real, l1), (m.ring.imag, l2)):
        assert np.max(np.abs(S @ part - lam * part)) < 1e-10
    assert l1 >= l2 and all(x <= l2 + 1e-9 for x in m.spectrum[2:])


def test_the_regular_corner_maps_onto_a_quarter_plane_of_equal_squares():
    """Catmull-Clark, one face at a corner: the bicubic spline of the regular grid; its map is linear."""
    m = boundary.sector_characteristic_map(SCHEMES["catmull-clark"], _vertex().corner(1, sd.QUAD, sp.pi / 2), levels=3)
    assert m.eigenvalues == pytest.approx((0.5, 0.5)) and m.folded == 0 and not m.defective
    assert len(m.faces) == 4**3
    assert np.allclose(np.abs(m.areas), np.abs(m.areas[0]))  # a linear map: every refined square has the same image
    directions = {round(float(np.angle(e[np.argmax(np.abs(e))])), 9) for e in m.sharp_edges}
    assert len(directions) == 2 and abs(abs(np.diff(sorted(directions))[0]) - np.pi / 2) < 1e-9


def test_a_regular_boundary_maps_its_boundary_onto_one_line():
    """Loop, three faces at a boundary: the regular boundary; the two boundary curves continue each other."""
    m = boundary.sector_characteristic_map(SCHEMES["loop"], _vertex().boundary(3, sd.TRIANGLE), levels=2)
    points = np.concatenate(m.sharp_edges)
    assert np.max(np.abs(points.real)) < 1e-9  # the mirror axis is the x axis; the boundary is the y axis
    assert m.folded == 0


def test_corner_figure_titles_name_the_eigenvalues():
    fig = boundary.corner_maps_figure([SCHEMES["catmull-clark"]], [(1, sp.pi / 2), (3, 3 * sp.pi / 2)], levels=1)
    titles = [ax.get_title() for ax in fig.axes]
    assert "0.5797" in titles[1] and "lambda_3 = lambda_2" in titles[1]
    assert all(ax.get_xlabel() and ax.get_ylabel() for ax in fig.axes)


# ---------------------------------------------------------------- the subdominant eigenvalues over k


@pytest.mark.parametrize("name", SCHEMES)
def test_subdominant_eigenvalues_are_those_of_the_refined_matrix(name):
    scheme = SCHEMES[name]
    for k in (2, 3, 5):
        vertex = _vertex().boundary(k, scheme.lattice)
        inner = vertex.one_ring_size()
        ev = sorted(np.linalg.eigvals(_ring_matrix(scheme, vertex, rings=2)[:inner, :inner]).real, reverse=True)
        assert boundary.subdominant_eigenvalues(scheme, vertex) == pytest.approx(tuple(ev[1:3]), abs=1e-9)


@pytest.mark.parametrize("name", SCHEMES)
def test_standard_boundary_rules_pass_the_curve_eigenvalue_where_the_closed_form_says(name):
    from symdecomp.analysis.mirror_threshold import boundary_eigenvalue, first_exceeding

    scheme = SCHEMES[name]
    half = float(boundary_eigenvalue(scheme))
    above = [k for k in range(1, 9) if boundary.subdominant_eigenvalues(scheme, _vertex().boundary(k, scheme.lattice))[0] > half + 1e-6]
    assert above == list(range(first_exceeding(scheme).first, 9))


def test_subdominant_figure_marks_the_boundary_curve():
    fig = boundary.subdominant_figure([(SCHEMES["catmull-clark"], SCHEMES["catmull-clark"])], ks=range(1, 4))
    assert len(fig.axes) == len(boundary.SECTOR_KINDS)
    for ax in fig.axes:
        assert any("boundary curve: 1/2" in t.get_text() for t in ax.get_legend().get_texts())
        assert ax.get_title() and ax.get_xlabel() and ax.get_ylabel()
