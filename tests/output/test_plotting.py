"""symdecomp.output.plotting: the numbers behind the figures, labelled axes, clear errors."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.errors import InvalidValenceError
from symdecomp.symbols import alpha, beta

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")  # the figures are built without pyplot; no display is ever needed

from symdecomp.output.plotting import cbmatrix as cbplots  # noqa: E402
from symdecomp.output.plotting import polygons as pplots  # noqa: E402
from symdecomp.output.plotting import tangent as tplots  # noqa: E402

CC = sd.catmull_clark()


def _assert_labelled(fig):
    """Every axes that shows data has a title and labelled axes (z too, for 3-D axes)."""
    assert fig.get_suptitle() or all(ax.get_title() for ax in fig.axes)
    for ax in fig.axes:
        if not ax.axison:
            continue
        assert ax.get_title(), "an axes without a title"
        assert ax.get_xlabel() and ax.get_ylabel(), f"unlabelled axes in {ax.get_title()!r}"
        if hasattr(ax, "get_zlabel"):
            assert ax.get_zlabel(), f"3-D axes {ax.get_title()!r} has no z label"


@pytest.mark.slow
def test_invariant_ratios_exact_and_closed_form_agree():
    valences = range(3, 11)
    exact = np.array(tplots.invariant_ratios(CC, valences))
    numeric = np.array(tplots.invariant_ratios(CC, valences, exact=False))
    assert np.max(np.abs(exact - numeric)) < 1e-13
    assert abs(exact[1] - (1 + 1j)) < 1e-15  # n = 4: B^1 = (1 + i) A^1, the regular grid


def test_invariant_ratio_is_an_eigenvector_of_M1():
    # (1, r) is an eigenvector of the exact M_1 for the largest eigenvalue (Eq. 37-39).
    for n, r in zip((3, 5, 12), tplots.invariant_ratios(CC, (3, 5, 12), exact=False)):
        M = np.array(sd.per_frequency_matrix_at(CC, n, 1).evalf(20), dtype=complex)
        image = M @ np.array([1, r])
        lam = max(np.linalg.eigvals(M), key=abs)
        assert np.allclose(image, lam * np.array([1, r]), atol=1e-13)


def test_vertex_labels_group_coinciding_vertices():
    hexagon_v3 = np.exp(2j * np.pi * 3 * np.arange(6) / 6)
    assert pplots.vertex_labels(hexagon_v3) == {0: "0,2,4", 1: "1,3,5"}
    assert pplots.vertex_labels(np.exp(2j * np.pi * np.arange(5) / 5)) == {k: str(k) for k in range(5)}


def test_unmatched_eigenvalues_of_a_cb_matrix_plus_constant_blocks():
    """Prop. 6.3 on a concrete matrix: exactly K eigenvalues move, to those of E_0 + m T."""
    from symdecomp.algebra import cbmatrix

    R = sp.Rational
    B = cbmatrix.cb_matrix([[[R(1, 2), R(1, 4), 0, R(1, 4)], [R(1, 8), 0, 0, 0]], [[R(1, 4), 0, 0, R(1, 4)], [R(1, 3), 0, R(1, 6), 0]]])
    T = sp.Matrix([[R(1, 6), -R(1, 12)], [R(1, 12), R(1, 4)]])
    C = B + cbmatrix.constant_blocks(T, B.order)
    moved_to, moved_from = cbplots.unmatched_eigenvalues(cbplots.numeric_eigenvalues(B.matrix()), cbplots.numeric_eigenvalues(C.matrix()))
    assert len(moved_to) == len(moved_from) == 2
    predicted = cbplots.numeric_eigenvalues(cbmatrix.perturbed_block_eigenvalue_matrix(B, T))
    unmatched, _ = cbplots.unmatched_eigenvalues(predicted, moved_to)
    assert len(unmatched) == 0, f"moved to {moved_to}, predicted {predicted}"


def test_numeric_eigenvalues_are_sorted_and_real_when_real():
    ev = cbplots.numeric_eigenvalues(sp.Matrix([[sp.Rational(1, 4), 0, 0], [0, 1, 0], [0, 0, sp.Rational(1, 2)]]))
    assert list(ev) == [1, 0.5, 0.25]
    assert np.all(ev.imag == 0)


def test_bad_valence_is_named():
    with pytest.raises(InvalidValenceError):
        tplots.invariant_ring_figure(CC, valences=(2,))
    with pytest.raises(InvalidValenceError):
        tplots.tangent_eigenvalues_figure(CC, valences=(4,), sweep=(1, 4))


def test_sweep_needs_every_free_weight():
    with pytest.raises(ValueError, match="beta"):
        cbplots.vertex_weight_sweep_figure(sd.catmull_clark(alpha, beta), 4, alpha, [0, sp.Rational(1, 20)])


def test_figures_have_titles_and_labelled_axes():
    _assert_labelled(pplots.regular_polygons_figure((3, 4)))
    _assert_labelled(tplots.tangent_eigenvalues_figure(CC, valences=(3, 4), sweep=(3, 4, 5)))
    _assert_labelled(tplots.invariant_ring_figure(CC, valences=(4,)))
    _assert_labelled(tplots.invariant_ratio_sweep_figure(CC, valences=(3, 4, 5)))
    free = sd.catmull_clark(alpha, beta)
    _assert_labelled(cbplots.vertex_weight_sweep_figure(free, 4, alpha, [0, sp.Rational(1, 20)], fixed={beta: sp.Rational(1, 64)}))
    S = sd.subdivision_matrix(CC, 4)
    _assert_labelled(cbplots.eigenvalue_shift_figure(S, S, sp.Matrix([[1]]), title="same"))
    _assert_labelled(tplots.component_decay_figure(CC, 3, steps=2))


def test_geometry_figures_have_titles_and_labelled_axes():
    from symdecomp.algebra.polygons import decompose
    from symdecomp.analysis import elliptic, evolution
    from symdecomp.output.plotting import elliptic as eplots

    P = np.random.default_rng(0).normal(size=(5, 3))
    _assert_labelled(pplots.decomposition_figure(P, pplots.regular_components(decompose(P))))
    rings = evolution.subdivide_ring(CC, evolution.tangent_configuration(4, (1, 0, 0)), 2)
    _assert_labelled(pplots.ring_split_figure(rings[:2]))
    profile = evolution.elliptic_profile(CC, evolution.tangent_configuration(4, (0, 1, 1), stretch=0.2), 3)
    _assert_labelled(eplots.ellipses_figure(profile, range(1, 3)))
    _assert_labelled(eplots.nested_rings_figure(rings[1:], initial=rings[0], title="rings"))
    _assert_labelled(eplots.hyperbolic_rates_figure(CC, (3, 4)))
    _assert_labelled(eplots.defect_figure(elliptic.elliptic_defect_table(CC, (3, 4), digits=10)))
    _assert_labelled(eplots.tuned_weights_figure([3, 4], {"a": [sp.Rational(1, 9), None]}, standard=[1, 2]))
    control = evolution.quadric_ring_mesh(3, 2, "hyperbolic")
    _assert_labelled(eplots.mesh_surface_figure(evolution.refine_mesh(CC, control, 1), initial=control, title="surface"))


def test_regular_components_sum_to_the_polygon_and_are_regular():
    from symdecomp.algebra.polygons import decompose

    P = np.random.default_rng(3).normal(size=(6, 3))
    components = pplots.regular_components(decompose(P))
    assert np.max(np.abs(np.sum(components, axis=0) - P)) < 1e-14
    for j in (1, 2, 4, 5):
        c = components[j]
        sides = np.linalg.norm(np.roll(c, -1, axis=0) - c, axis=1)
        radii = np.linalg.norm(c, axis=1)
        assert np.ptp(sides) < 1e-12 and np.ptp(radii) < 1e-12  # a regular polygon about the origin


def test_characteristic_map_figure_and_its_ring():
    from symdecomp.output.plotting import characteristic as cplots

    curves = cplots.ring_curves(CC, 4, samples=3)
    # n = 4: the ring at level 1 is the grid [0, 1]^2 \ [0, 1/2)^2 in each quadrant: the inner boundary is |x|, |y| <= 1/2
    inner = np.concatenate(curves["inner"])
    assert np.max(np.abs(np.maximum(abs(inner.real), abs(inner.imag)) - 0.5)) < 1e-12
    assert len(curves["rays"]) == 4
    fig = cplots.characteristic_map_figure(CC, (3, 5))
    _assert_labelled(fig)
    assert "c1 (winding 1)" in fig.axes[0].get_title()
