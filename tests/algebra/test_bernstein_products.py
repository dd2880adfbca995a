"""Bernstein products by Kronecker substitution agree with the products written as loops over all pairs."""

from __future__ import annotations

import random
from math import comb

import flint
import pytest

from symdecomp.algebra.bernstein import net_scale, net_sum, tensor_derivative, tensor_product, triangle_product
from symdecomp.algebra.triangle_bezier import bezier_indices, bezier_product
from symdecomp.verify.bezier import jacobian_net


def _net(rng, p, q):
    return [[flint.arb(flint.fmpq(rng.randint(-50, 50), rng.randint(1, 9))) for _ in range(q + 1)] for _ in range(p + 1)]


def _loop_product(f, g, df, dg):
    """The definition: h_ab = sum f_ik g_i'k' C(p1,i) C(p2,i') C(q1,k) C(q2,k') / (C(P,a) C(Q,b))."""
    (p1, q1), (p2, q2) = df, dg
    out = [[flint.arb(0) for _ in range(q1 + q2 + 1)] for _ in range(p1 + p2 + 1)]
    for i in range(p1 + 1):
        for k in range(q1 + 1):
            for i2 in range(p2 + 1):
                for k2 in range(q2 + 1):
                    w = flint.fmpq(comb(p1, i) * comb(p2, i2) * comb(q1, k) * comb(q2, k2), comb(p1 + p2, i + i2) * comb(q1 + q2, k + k2))
                    out[i + i2][k + k2] += w * f[i][k] * g[i2][k2]
    return out


@pytest.mark.parametrize("df, dg", [((1, 3), (5, 5)), ((2, 3), (3, 2)), ((6, 8), (8, 6)), ((0, 2), (3, 0))])
def test_tensor_product_is_the_convolution_of_scaled_coefficients(df, dg):
    rng = random.Random(sum(df) * 31 + sum(dg))
    f, g = _net(rng, *df), _net(rng, *dg)
    fast, slow = tensor_product(f, g, df, dg), _loop_product(f, g, df, dg)
    for a, b in zip(fast, slow):
        for x, y in zip(a, b):
            assert x.overlaps(y) and abs(x - y) < 1e-12 * (1 + abs(y))


def test_the_jacobian_from_products_is_the_c1_tests_jacobian_net():
    rng = random.Random(5)
    x, y = _net(rng, 3, 3), _net(rng, 3, 3)
    xu, xv = tensor_derivative(x, (3, 3), "u"), tensor_derivative(x, (3, 3), "v")
    yu, yv = tensor_derivative(y, (3, 3), "u"), tensor_derivative(y, (3, 3), "v")
    ours = net_sum(tensor_product(xu, yv, (2, 3), (3, 2)), net_scale(tensor_product(yu, xv, (2, 3), (3, 2)), -1))
    for a, b in zip(ours, jacobian_net(x, y)):
        for p, q in zip(a, b):
            assert p.overlaps(q) and abs(p - q) < 1e-12 * (1 + abs(q))


@pytest.mark.parametrize("df, dg", [(4, 6), (8, 8), (2, 0)])
def test_triangle_product_agrees_with_the_pairwise_product(df, dg):
    rng = random.Random(df * 7 + dg)
    f = [flint.arb(flint.fmpq(rng.randint(-40, 40), rng.randint(1, 7))) for _ in bezier_indices(df)]
    g = [flint.arb(flint.fmpq(rng.randint(-40, 40), rng.randint(1, 7))) for _ in bezier_indices(dg)]
    for x, y in zip(triangle_product(f, g, df, dg), bezier_product(f, g, df, dg)):
        assert x.overlaps(y) and abs(x - y) < 1e-12 * (1 + abs(y))
