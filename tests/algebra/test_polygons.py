"""Eq. 5-6: decomposition into planar regular polygons, exact, numpy and mpmath."""

import random

import mpmath
import numpy as np
import pytest
import sympy as sp

from symdecomp.algebra.circulant import fourier_matrix
from symdecomp.algebra.polygons import coplanar_pairs, decompose


def random_rational_polygon(n, seed):
    rng = random.Random(seed)
    return sp.Matrix([[sp.Rational(rng.randint(-20, 20), rng.randint(1, 6)) for _ in range(3)] for _ in range(n)])


@pytest.mark.parametrize("n", range(3, 13))
def test_exact_reconstruction(n):
    P = random_rational_polygon(n, n)
    assert decompose(P).reconstruct() == P


@pytest.mark.parametrize("n", [3, 6, 9])
def test_exact_amplitudes_solve_eq5(n):
    # P = F_n^T z (columns of F_n^T are the polygons v_j): check with sympy's own matrix solve at 40 digits
    P = random_rational_polygon(n, 100 + n)
    d = decompose(P)
    F = fourier_matrix(n)
    for k in range(3):
        z = sp.Matrix([d.amplitudes[j][k] for j in range(n)])
        residual = (F.T * z - P[:, k]).evalf(40)
        assert max(abs(x) for x in residual) < 1e-35


def test_real_pairs_are_planar_regular_and_coplanar():
    rng = np.random.default_rng(7)
    for n in range(3, 11):
        P = rng.normal(size=(n, 3))
        d = decompose(P)
        assert np.abs(d.reconstruct() - P).max() < 1e-13
        for j, k in coplanar_pairs(n):
            first, second = d.planar_pair(j)
            assert (first.frequency, second.frequency) == (j, k)
            f1, f2 = np.array(first.f1), np.array(first.f2)
            assert abs(f1 @ f2) < 1e-13 and abs(f1 @ f1 - 1) < 1e-13 and abs(f2 @ f2 - 1) < 1e-13
            normal = np.cross(f1, f2)
            V1, V2 = np.array(first.vertices()), np.array(second.vertices())
            # both components lie in the plane spanned by f1, f2 (coplanar) and are regular (all equal radii)
            assert np.abs(V1 @ normal).max() < 1e-13 and np.abs(V2 @ normal).max() < 1e-13
            radii = np.linalg.norm(V1, axis=1)
            assert np.ptp(radii) < 1e-12
            assert np.abs(V1 + V2 - d.pair_polygon(j)).max() < 1e-13


def test_mpmath_precision_is_the_callers():
    P = [[mpmath.mpf(1) / 3, 0, 1], [0, mpmath.mpf(2) / 7, 0], [-1, 0, mpmath.mpf(5) / 11], [0, -1, 0], [1, 1, 1]]
    with mpmath.workdps(80):
        d = decompose(P)
        back = d.reconstruct()
        err = max(abs(back[i, k] - P[i][k]) for i in range(5) for k in range(3))
        assert err < mpmath.mpf(10) ** -75
        first, second = d.planar_pair(2)
        Q = d.pair_polygon(2)
        dev = max(abs(p[k] + q[k] - Q[m, k]) for m, (p, q) in enumerate(zip(first.vertices(), second.vertices())) for k in range(3))
        assert dev < mpmath.mpf(10) ** -75


def test_exact_planar_pair_matches_pair_polygon_to_40_digits():
    P = random_rational_polygon(5, 3)
    d = decompose(P)
    first, second = d.planar_pair(1)
    Q = d.pair_polygon(1)
    for m, (p, q) in enumerate(zip(first.vertices(), second.vertices())):
        for k in range(3):
            assert abs(sp.N(p[k] + q[k] - Q[m, k], 50)) < 1e-40


def test_degenerate_pairs():
    # a polygon on a line through the origin: each real pair is a segment; planes still get an orthonormal frame
    P = sp.Matrix([[k, 2 * k, 0] for k in (1, -2, 3, 0, -2)])
    d = decompose(P)
    assert d.reconstruct() == P
    first, second = d.planar_pair(1)
    f1, f2 = (sp.Matrix(first.f1), sp.Matrix(first.f2))
    assert sp.simplify(f1.dot(f2)) == 0 and sp.simplify(f1.dot(f1)) == 1 and sp.simplify(f2.dot(f2)) == 1


def test_complex_polygon():
    P = [1, 2j, 3, 4 + 1j, -1]
    d = decompose(np.array(P))
    assert np.abs(d.reconstruct() - np.array(P)).max() < 1e-13
    exact = [1, 2 * sp.I, 3, 4 + sp.I, -1]
    assert list(decompose(exact).reconstruct()) == exact
