"""symdecomp.analysis.evolution: rings iterated by the exact matrix, and the geometry of Sections 4-5 on them."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis import evolution
from symdecomp.errors import InvalidPolygonError, InvalidValenceError
from symdecomp.symbols import alpha, beta

CC = sd.catmull_clark()


def _random_ring(n, seed=0):
    rng = np.random.default_rng(seed)
    return evolution.one_ring(rng.normal(size=3), rng.normal(size=(n, 3)), rng.normal(size=(n, 3)))


@pytest.mark.parametrize("n", [3, 5, 8])
def test_one_step_is_the_exact_matrix(n):
    rng = np.random.default_rng(n)
    ring = rng.integers(-5, 6, size=(2 * n + 1, 3))
    exact = sd.subdivision_matrix(CC, n) * sp.Matrix(ring)
    numeric = evolution.subdivide_ring(CC, ring.astype(float), 1)[1]
    assert np.max(np.abs(np.array(exact.evalf(20), dtype=float) - numeric)) < 1e-13


def test_as_ring_array_accepts_the_ring_types_of_the_package():
    from symdecomp.schemes.ring import OneRing, subdivide

    ring = OneRing.from_points((0, 0, 1), [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)], [(1, 1, 0), (-1, 1, 0), (-1, -1, 0), (1, -1, 0)])
    ours = evolution.subdivide_ring(CC, ring, 3)[-1]
    theirs = evolution.as_ring_array(subdivide(CC, ring, 3))
    assert np.max(np.abs(ours - theirs)) < 1e-15
    assert evolution.as_ring_array(sd.hyperbolic_ring(3)).shape == (7, 3)


def test_ring_polygon_round_trip_is_eq_10_and_12():
    ring = _random_ring(4)
    P = evolution.ring_polygon(ring)
    O, a, b = evolution.split_ring(ring)
    assert np.array_equal(P[0::2], a) and np.array_equal(P[1::2], b)
    assert np.array_equal(evolution.ring_from_polygon(O, P), ring)


@pytest.mark.parametrize("n, j", [(4, 1), (5, 2), (6, 3), (7, 1)])
def test_components_stay_planar_and_parallel(n, j):
    """Proposition 4.1 on a random ring's 2n-gon component with O off its plane, over 4 steps."""
    from symdecomp.algebra.polygons import decompose

    ring = _random_ring(n, seed=10 * n + j)
    O = ring[0]
    component = decompose(evolution.ring_polygon(ring)).pair_polygon(j)
    rings = evolution.subdivide_ring(CC, evolution.ring_from_polygon(O, component), 4)
    normal = np.cross(*np.linalg.svd(component - component.mean(axis=0))[2][:2])
    for r in rings[1:]:
        _, a, b = evolution.split_ring(r)
        for poly in (a, b):
            heights = (poly - poly.mean(axis=0)) @ normal
            assert np.max(np.abs(heights)) < 1e-12 * max(1.0, np.abs(poly).max())


def test_inscribed_ellipse_has_the_axes_of_eq_40():
    n = 7
    w1, wm1 = 1.3 * np.exp(0.4j), 0.5 * np.exp(-1.1j)
    omega = np.exp(2j * np.pi * np.arange(n) / n)
    z = w1 * omega + wm1 / omega + (0.2 - 0.3j)
    polygon = np.column_stack([z.real, z.imag, np.full(n, 0.7)])
    ellipse = evolution.inscribed_ellipse(polygon)
    major, minor = ellipse.semi_axes()
    assert abs(major - (abs(w1) + abs(wm1))) < 1e-13
    assert abs(minor - abs(abs(w1) - abs(wm1))) < 1e-13
    on_curve = ellipse.center + np.outer(np.cos(2 * np.pi * np.arange(n) / n), ellipse.u) + np.outer(
        np.sin(2 * np.pi * np.arange(n) / n), ellipse.v
    )
    assert np.max(np.abs(on_curve - polygon)) < 1e-13
    assert np.allclose(np.abs(ellipse.normal()), [0, 0, 1])


def test_regular_case_has_nice_elliptic_properties():
    """n = 4 (Eq. 45): d_b/d_a -> 2 = squared scale ratio, and kappa settles."""
    profile = evolution.elliptic_profile(CC, evolution.tangent_configuration(4, (0, 1, 1)), 14)
    assert abs(profile.distance_b[-1] / profile.distance_a[-1] - 2) < 1e-7
    scale = (profile.ellipses_b[-1].scale() / profile.ellipses_a[-1].scale()) ** 2
    assert abs(scale - 2) < 1e-7
    assert abs(profile.kappa_a[-1] / profile.kappa_a[-2] - 1) < 1e-7


def test_valence_six_grows_kappa_at_mu_over_lambda1_squared():
    profile = evolution.elliptic_profile(CC, evolution.tangent_configuration(6, (0, 1, 1)), 14)
    mu = float(sp.N(sd.recursion_eigenvalues(CC)[1].subs(sd.symbols.n, 6), 20))
    lam1 = max(abs(complex(sp.N(v))) for v in sd.tangent_eigenvalues(CC).at(6, 1))
    assert abs(profile.kappa_a[-1] / profile.kappa_a[-2] - mu / lam1**2) < 1e-6


def test_hyperbolic_configuration_decays_at_the_rate_of_m2():
    n = 5
    ring = evolution.as_ring_array(sd.hyperbolic_ring(n, sp.Rational(1, 2)))
    O, a, b = evolution.split_ring(ring)
    assert abs(O[2]) < 1e-15 and abs(a[:, 2].mean()) < 1e-15 and abs(b[:, 2].mean()) < 1e-15
    rings = evolution.subdivide_ring(CC, ring, 30)  # the other eigenvalue of M_2 is 0.54 of it: slow
    height = [np.abs(r[:, 2] - r[0, 2]).max() for r in rings]
    rate = max(abs(complex(sp.N(v))) for v in sd.tangent_eigenvalues(CC).at(n, 2))
    assert abs(height[-1] / height[-2] - rate) < 1e-6


def test_components_n_plus_minus_one_are_not_filtered_out():
    """Remark 5.1 says the 2n-gon components n-1, n+1 are filtered out; they shrink at lambda_1."""
    from symdecomp.output.plotting.tangent import component_decay

    n = 5
    table = component_decay(CC, n, 20)
    for j in (1, n - 1, n + 1, 2 * n - 1):
        assert table[j, -1] > 0.3 and abs(table[j, -1] / table[j, -2] - 1) < 1e-6
    for j in (2, 3, 2 * n - 2):
        assert table[j, -1] < 1e-3


def test_bad_input_is_named():
    with pytest.raises(InvalidPolygonError):
        evolution.one_ring([0, 0, 0], np.zeros((4, 3)), np.zeros((5, 3)))
    with pytest.raises(InvalidValenceError):
        evolution.one_ring([0, 0, 0], np.zeros((2, 3)), np.zeros((2, 3)))
    with pytest.raises(InvalidPolygonError):
        evolution.split_ring(np.zeros((8, 3)))
    with pytest.raises(InvalidPolygonError):
        evolution.one_ring([0, 0, 0], np.full((4, 3), np.nan), np.zeros((4, 3)))
    with pytest.raises(ValueError, match="free parameters"):
        evolution.subdivide_ring(sd.catmull_clark(alpha, beta), _random_ring(4), 1)
    with pytest.raises(ValueError, match="steps"):
        evolution.subdivide_ring(CC, _random_ring(4), -1)
    with pytest.raises(InvalidPolygonError):
        evolution.inscribed_ellipse(np.zeros((5, 3)))


def test_tangent_configuration_is_on_the_ellipse_of_eq_40():
    ring = evolution.tangent_configuration(5, (0, 1, 2), radius=2.0, stretch=0.25)
    O, a, b = evolution.split_ring(ring)
    assert O.tolist() == [0, 0, 0] and np.allclose(a[:, 2], 1) and np.allclose(b[:, 2], 2)
    for poly in (a, b):
        major, minor = evolution.inscribed_ellipse(poly).semi_axes()
        assert abs(major - 2.5) < 1e-13 and abs(minor - 1.5) < 1e-13


@pytest.mark.parametrize("kind", ["hyperbolic", "elliptic"])
def test_quadric_meshes_have_only_the_stated_components(kind):
    """Out of the plane, the 1-ring of the hyperbolic mesh has only frequency 2, the elliptic one only 0."""
    from symdecomp.schemes.refinement import central_rings

    n = 5
    mesh = evolution.quadric_ring_mesh(n, 2, kind, 0.5)
    ring = np.array(central_rings(mesh, CC, 0, 0)[0], dtype=float)
    _, a, b = evolution.split_ring(ring)
    for heights in (a[:, 2], b[:, 2]):
        amplitudes = np.abs(np.fft.fft(heights)) / n
        keep = {2, n - 2} if kind == "hyperbolic" else {0}
        assert all(amplitudes[k] < 1e-14 for k in range(n) if k not in keep)
        assert any(amplitudes[k] > 0.1 for k in keep)
    assert ring[0, 2] == 0


def test_refine_mesh_agrees_with_the_matrix_on_the_central_ring():
    from symdecomp.schemes.refinement import central_rings

    mesh = evolution.quadric_ring_mesh(5, 2, "hyperbolic", 0.5)
    refined = evolution.refine_mesh(CC, mesh, 1)
    start = np.array(central_rings(mesh, CC, 0, 0)[0], dtype=float)
    after = evolution.subdivide_ring(CC, start, 1)[1]
    # the refined centre is the vertex point of vertex 0; its value is the first row of S start
    assert any(np.allclose(np.array(v, dtype=float), after[0], atol=1e-14) for v in refined.values.values())
    with pytest.raises(ValueError, match="kind"):
        evolution.quadric_ring_mesh(5, 2, "parabolic")
    with pytest.raises(ValueError, match="levels"):
        evolution.refine_mesh(CC, mesh, -1)
