"""Midedge at a triangle through 1/4's Jordan chains, against the matrix built in the quotient tests.

The matrix, mesh and labels are :mod:`tests.verify.test_c1_four_direction_quotient`'s (exact, sympy). What is checked
here: the chain the route reports satisfies the chain identities and the power formula exactly; the level-m normal of
a net on the chains is ``16 m^2 4^-2m (c_x x c_y) J(chi)`` plus terms of lower order in ``m``, exactly (its second
difference in ``m``); the verdict; and a relabelled matrix with the same Jordan structure whose map folds.
"""

from fractions import Fraction as F

import pytest
import sympy as sp

from symdecomp.schemes.four_direction import four_direction_patch
from symdecomp.verify.bezier import triangle_jacobian_net
from symdecomp.verify.c1_four_direction_jordan import jordan_chain_verdict, leading_scale
from symdecomp.verify.c1_four_direction_quotient import quotient_test, ring_evaluation, rotation_matrix
from symdecomp.verify.result import C1Verdict
from tests.verify.test_c1_dual import local_mesh
from tests.verify.test_c1_four_direction_quotient import MIDEDGE, exact_matrix

QUARTER = sp.Rational(1, 4)


@pytest.fixture(scope="module")
def patch():
    return four_direction_patch(MIDEDGE)


@pytest.fixture(scope="module")
def midedge_3(patch):
    S, order = exact_matrix(3)
    return S, order, quotient_test(local_mesh(3), order, S, patch, 3)


def _column(values):
    return sp.Matrix([sp.Rational(v.numerator, v.denominator) for v in values])


def _sympy(matrix):
    return sp.Matrix(matrix.nrows(), matrix.ncols(), lambda i, j: sp.Rational(int(matrix[i, j].p), int(matrix[i, j].q)))


def test_the_chain_is_e_the_eigenvector_and_g_its_start(midedge_3):
    S, order, found = midedge_3
    g, e = (_column(v) for v in found.chain)
    A = S - QUARTER * sp.eye(len(order))
    assert found.chain_length == 2 and e != sp.zeros(len(order), 1) and A * g - e == sp.zeros(len(order), 1)
    assert A * e == sp.zeros(len(order), 1) and A * g != sp.zeros(len(order), 1)  # the map is of e, not of g
    R = _sympy(rotation_matrix(local_mesh(3).labels, order, 3))
    assert (R ** 2 + R + sp.eye(len(order))) * e == sp.zeros(len(order), 1)  # frequencies 1, 2
    for m in range(1, 5):  # S^m g = 4^-m g + m 4^-(m-1) e, and leading_scale is m 4^-(m-1)
        assert S ** m * g - (QUARTER ** m * g + leading_scale(QUARTER, 2, m) * e) == sp.zeros(len(order), 1)
        assert leading_scale(QUARTER, 2, m) == m * QUARTER ** (m - 1)


def _normal_nets(coefficients, triangles):
    """The normal's Bernstein nets (degree 2) on each triangle: the Jacobians of the coordinate pairs (y, z), (z, x), (x, y)."""
    out = []
    for t in range(triangles):
        rows = [[coefficients[6 * t + i, k] for i in range(6)] for k in range(3)]
        out.append([triangle_jacobian_net(rows[a], rows[b], 2) for a, b in ((1, 2), (2, 0), (0, 1))])
    return out


def test_the_normal_s_leading_term_is_m_squared_times_the_chain_map_s_jacobian(midedge_3, patch):
    """On ``p = c_x g + c_y (R g + g/2) + c_a a`` (``a`` a frequency-0 eigenvector of 1/4), ``16^m N_m`` is a quadratic in
    ``m`` whose second difference is ``2 * 16 (c_x x c_y) J(e, R e + e/2)``, exactly, on every triangle of the ring."""
    S, order, found = midedge_3
    size = len(order)
    g, e = (_column(v) for v in found.chain)
    R = _sympy(rotation_matrix(local_mesh(3).labels, order, 3))
    E = _sympy(ring_evaluation(local_mesh(3), order, patch))
    averaged = ((sp.eye(size) + R + R ** 2) * v for v in (S - QUARTER * sp.eye(size)).nullspace())
    a = next(v for v in averaged if v != sp.zeros(size, 1))  # frequency 0
    cx, cy, ca = sp.Matrix([[1, 2, 0]]), sp.Matrix([[0, 1, 3]]), sp.Matrix([[5, -1, 2]])
    net = g * cx + (R * g + g / 2) * cy + a * ca  # rows: control points, columns: x, y, z
    scaled = [_normal_nets(4 ** m * E * S ** m * net, E.rows // 6) for m in range(5)]  # 16^m N_m
    chi = E * sp.Matrix.hstack(e, R * e + e / 2)
    cross = cx.cross(cy)
    for t in range(E.rows // 6):
        J = triangle_jacobian_net([chi[6 * t + i, 0] for i in range(6)], [chi[6 * t + i, 1] for i in range(6)], 2)
        for k in range(3):
            levels = [scaled[m][t][k] for m in range(5)]
            for m in range(3):  # second differences: 32 (c_x x c_y)_k J; third differences vanish
                second = [levels[m + 2][i] - 2 * levels[m + 1][i] + levels[m][i] for i in range(len(J))]
                assert all(s - 32 * cross[k] * j == 0 for s, j in zip(second, J))
    assert any(x != 0 for x in J) and cross != sp.zeros(1, 3)


def test_midedge_s_chain_map_is_regular_and_gives_c1(midedge_3):
    _, _, found = midedge_3
    verdict, reason = jordan_chain_verdict(found)
    assert verdict is C1Verdict.C1 and found.ring.winding_number == found.ring.jacobian_sign
    assert found.ring.jacobian_lower_bound > 0.0065 and "(almost every control net)" in reason


def test_a_relabelled_matrix_with_the_same_jordan_structure_folds_the_chain_map(midedge_3, patch):
    """Swapping the points of orbits (1, 1) and (2, 2) in every sector is a similarity commuting with the rotation, so
    the Jordan structure by frequency is the same; the ring's functions see other control points, and the chains' map
    folds: not C1."""
    S, order, found = midedge_3
    index = {v: i for i, v in enumerate(order)}
    swap = {(1, 1): (2, 2), (2, 2): (1, 1)}
    T = sp.zeros(len(order), len(order))
    for v in order:
        T[index[(v[0], *swap.get(v[1:], v[1:]))], index[v]] = 1
    mutated = quotient_test(local_mesh(3), order, T * S * T.T, patch, 3)
    assert mutated.spectrum.jordan == found.spectrum.jordan and mutated.spectrum.vanishing == ()
    assert mutated.chain_length == 2 and mutated.ring.status == "changes"
    verdict, reason = jordan_chain_verdict(mutated)
    assert verdict is C1Verdict.NOT_C1 and "J(chi) changes sign (the patch of vertex (" in reason


def test_without_a_chain_the_route_has_nothing_to_read(patch):
    S, order = exact_matrix(3, F(3, 4))  # 5/8 subdominant, no Jordan block
    found = quotient_test(local_mesh(3), order, S, patch, 3)
    assert found.conditions_hold and found.chain is None and jordan_chain_verdict(found) is None
