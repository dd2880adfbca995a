"""Section 4: the 1-ring 2n-gon, its components A^j, B^j, and M_k acting on concrete rings."""

import random

import mpmath
import numpy as np
import pytest
import sympy as sp

from symdecomp import catmull_clark, per_frequency_matrix_at
from symdecomp.schemes.ring import OneRing, ngon_amplitudes, one_ring_decomposition, subdivide


def random_ring(n, seed, exact=True):
    rng = random.Random(seed)
    point = lambda: [sp.Rational(rng.randint(-9, 9), rng.randint(1, 3)) for _ in range(3)]  # noqa: E731
    if exact:
        return OneRing.from_points(point(), [point() for _ in range(n)], [point() for _ in range(n)])
    g = np.random.default_rng(seed)
    return OneRing.from_points(g.normal(size=3), g.normal(size=(n, 3)), g.normal(size=(n, 3)))


@pytest.mark.slow
@pytest.mark.parametrize("n", [3, 4, 5])
def test_eq24_on_a_random_ring_exactly(n):
    d = one_ring_decomposition(random_ring(n, n))
    for j in range(2 * n):
        A, B = d.components(j)
        w = sp.exp(sp.pi * sp.I * sp.Rational(j, n))
        for a, b in zip(A, B):
            for x, y in zip(a, b):
                assert abs(sp.N(y - w * x, 40)) < 1e-35


@pytest.mark.parametrize("n", range(3, 9))
def test_M_k_moves_the_ngon_amplitudes_of_a_real_ring(n):
    cc = catmull_clark()
    ring = random_ring(n, 10 + n, exact=False)
    after = subdivide(cc, ring)
    before_amp, after_amp = ngon_amplitudes(ring), ngon_amplitudes(after)
    for k in range(1, n):
        M = np.array(per_frequency_matrix_at(cc, n, k).evalf(20).tolist(), dtype=complex)
        predicted = M @ np.array(before_amp[k])
        assert np.abs(predicted - np.array(after_amp[k])).max() < 1e-14


def test_exact_subdivision_of_the_regular_ring():
    # the regular (n = 4) planar grid ring with O lifted: O moves to 9/16 of its height (Eq. 45's first row)
    ring = OneRing.from_points((0, 0, 1), [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)], [(1, 1, 0), (-1, 1, 0), (-1, -1, 0), (1, -1, 0)])
    new = subdivide(catmull_clark(), ring)
    assert new.center == (0, 0, sp.Rational(9, 16))
    assert new.a[0] == (sp.Rational(1, 2), 0, sp.Rational(3, 8))
    assert new.b[0] == (sp.Rational(1, 2), sp.Rational(1, 2), sp.Rational(1, 4))


def test_mpmath_ring_keeps_precision():
    with mpmath.workdps(50):
        a = [[mpmath.mpf(k) / 7, 1, 0] for k in range(5)]
        b = [[0, mpmath.mpf(k) / 9, 1] for k in range(5)]
        ring = OneRing.from_points([mpmath.mpf(1) / 3] * 3, a, b)
        out = subdivide(catmull_clark(), ring, steps=2)
        a = [[sp.Rational(k, 7), 1, 0] for k in range(5)]
        b = [[0, sp.Rational(k, 9), 1] for k in range(5)]
        exact = subdivide(catmull_clark(), OneRing.from_points([sp.Rational(1, 3)] * 3, a, b), steps=2)
        assert abs(out.center[0] - mpmath.mpf(sp.Rational(exact.center[0]).p) / sp.Rational(exact.center[0]).q) < mpmath.mpf(10) ** -45


def test_ring_validation():
    from symdecomp import InvalidPolygonError

    with pytest.raises(InvalidPolygonError, match="as many face neighbours"):
        OneRing.from_points((0, 0, 0), [(1, 0, 0)] * 4, [(1, 1, 0)] * 3)
    with pytest.raises(ValueError, match="steps"):
        subdivide(catmull_clark(), random_ring(3, 1), steps=-1)
