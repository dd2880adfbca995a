"""The regular Loop patch (quartic box spline in Bezier form) and triangular Bernstein arithmetic."""

import random
from fractions import Fraction

import pytest
import sympy as sp

from symdecomp.algebra.triangle_bezier import bernstein, bezier_derivative, bezier_indices, bezier_product, bezier_value
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.box_spline import BOX_POINTS, LATTICE_RAYS, refined_limits, regular_patch
from symdecomp.schemes.loop import loop, triangle_scheme
from symdecomp.schemes.mesh import triangle_ring_mesh
from symdecomp.symbols import n as N

F = Fraction


def test_partition_of_unity_and_linear_precision():
    p = regular_patch()
    assert [sum(col) for col in zip(*p.coefficients)] == [1] * 15
    # sum_i b_i(u, v) * (lattice point i) = (u, v): the Bezier net of a linear function is its domain points
    for axis in (0, 1):
        net = p.bezier_net([F(pt[axis]) for pt in BOX_POINTS])
        assert net == [F(i[1 + axis], 4) for i in bezier_indices(4)]


def test_corners_are_the_regular_limit_mask():
    p = regular_patch()
    assert p.mask == (F(1, 2), F(1, 12))
    corners = {(0, 0): 0, (1, 0): bezier_indices(4).index((0, 4, 0)), (0, 1): bezier_indices(4).index((0, 0, 4))}
    for corner, k in corners.items():
        for pt, row in zip(BOX_POINTS, p.coefficients):
            d = (pt[0] - corner[0], pt[1] - corner[1])
            want = p.mask[0] if d == (0, 0) else p.mask[1] if d in LATTICE_RAYS else 0
            assert row[k] == want, (corner, pt)


def test_agrees_with_refined_limits_of_random_values():
    rnd = random.Random(3)
    values = {}

    def vals(s, u, v):
        (x0, y0), (x1, y1) = LATTICE_RAYS[s % 6], LATTICE_RAYS[(s + 1) % 6]
        q = (u * x0 + v * x1, u * y0 + v * y1)
        values.setdefault(q, F(rnd.randint(-1000, 1000), 7))
        return (F(q[0]), F(q[1]), values[q])

    mesh = triangle_ring_mesh(6, 3, vals)
    p = regular_patch()
    net = p.bezier_net([values[q] for q in BOX_POINTS])
    limits = refined_limits(loop(), 3, mesh)
    assert len(limits) == 45
    for (i, j), (want,) in limits.items():
        assert bezier_value(net, 4, F(i, 8), F(j, 8)) == want


def test_a_scheme_whose_regular_patch_is_not_quartic_is_refused():
    odd = triangle_scheme("odd", sp.Rational(1, 2) / N)  # beta(6) = 1/12 instead of Loop's 1/16
    with pytest.raises(InvalidSchemeError, match="not a quartic"):
        regular_patch(odd)


def test_bezier_derivative_and_product_against_sympy():
    u, v = sp.symbols("u v")
    rnd = random.Random(1)
    f = [sp.Rational(rnd.randint(-9, 9), 5) for _ in bezier_indices(3)]
    g = [sp.Rational(rnd.randint(-9, 9), 7) for _ in bezier_indices(2)]
    fu, fv, gu = (bezier_value(net, d, u, v) for net, d in ((f, 3), (f, 3), (g, 2)))
    F3, G2 = fu, gu
    assert sp.expand(bezier_value(bezier_derivative(f, 3, "u"), 2, u, v) - sp.diff(F3, u)) == 0
    assert sp.expand(bezier_value(bezier_derivative(f, 3, "v"), 2, u, v) - sp.diff(fv, v)) == 0
    assert sp.expand(bezier_value(bezier_product(f, g, 3, 2), 5, u, v) - F3 * G2) == 0
    assert sp.expand(sum(bernstein(4, u, v)) - 1) == 0
