"""Values worked out by hand, each next to the equation it comes from.

Everything else in the test suite checks identities (for every ``n``, or against an
independent computation); these pin a few numbers a reader can redo on paper, so that a
change which keeps the identities but shifts a convention still shows. Catmull-Clark with the
standard vertex weights unless said otherwise; ``n = 4`` is the regular bicubic B-spline case.
"""

import flint
import sympy as sp

from symdecomp.algebra.circulant import circ, circulant_eigenvalue, fourier_row
from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial
from symdecomp.analysis.elliptic import eq44_ratio, recursion_eigenvector
from symdecomp.analysis.frequency import per_frequency_matrix_at, recursion_matrix
from symdecomp.analysis.masks import limit_masks_at
from symdecomp.analysis.tangent import invariant_ratio_at, tangent_eigenvalues
from symdecomp.schemes.full_matrix import characteristic_polynomial
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix

R = sp.Rational
CC = catmull_clark()


def test_eq2_fourier_row_at_n_4():
    """Eq. 2-3: row 1 of F_4 is (1, i, i^2, i^3), omega_4 = i."""
    assert fourier_row(4, 1) == [1, sp.I, -1, -sp.I]
    assert fourier_row(4, 2) == [1, -1, 1, -1]


def test_eq7_eq8_circulant_and_its_eigenvalue():
    """Eq. 7: row r of circ(c_0, .., c_3) starts with c_{-r}; Eq. 8: eigenvalue c_0 + c_1 omega + c_{-1}/omega.

    For c = (1/2, 1/4, 0, 1/4) on v_1 of the 4-gon: 1/2 + i/4 - i/4 = 1/2; on v_2: 1/2 - 1/4 - 1/4 = 0.
    """
    assert circ([R(1, 2), R(1, 4), 0, R(1, 4)]).row(1).tolist() == [[R(1, 4), R(1, 2), R(1, 4), 0]]
    offsets = {0: R(1, 2), 1: R(1, 4), -1: R(1, 4)}
    assert circulant_eigenvalue(offsets, 4, 1) == R(1, 2)
    assert circulant_eigenvalue(offsets, 4, 2) == 0


def test_eq16_standard_vertex_rule_at_n_5():
    """Eq. 16: O -> (1 - 7/(4n)) O + 3/(2n^2) sum a_i + 1/(4n^2) sum b_i; at n = 5: 13/20, 3/50, 1/100."""
    S = subdivision_matrix(CC, 5)
    assert (S[0, 0], S[0, 1], S[0, 6]) == (R(13, 20), R(3, 50), R(1, 100))


def test_eq14_eq15_rows_at_n_4():
    """Eq. 14: a_i -> 3/8 O + 3/8 a_i + 1/16 (a_{i-1} + a_{i+1} + b_{i-1} + b_i); Eq. 15: b_i -> (O + a_i + a_{i+1} + b_i)/4."""
    S = subdivision_matrix(CC, 4)
    # row of a_0 in the order (O, a_0..a_3, b_0..b_3): b_{-1} = b_3
    assert S.row(1).tolist() == [[R(3, 8), R(3, 8), R(1, 16), 0, R(1, 16), R(1, 16), 0, 0, R(1, 16)]]
    assert S.row(5).tolist() == [[R(1, 4), R(1, 4), R(1, 4), 0, 0, R(1, 4), 0, 0, 0]]


def test_eq33_per_frequency_matrix_at_n_4_j_1():
    """Eq. 33 at omega = i: [[3/8 + (i - i)/16, (1 - i)/16], [(1 + i)/4, 1/4]]."""
    M = per_frequency_matrix_at(CC, 4, 1)
    assert sp.expand(M - sp.Matrix([[R(3, 8), (1 - sp.I) / 16], [(1 + sp.I) / 4, R(1, 4)]])) == sp.zeros(2, 2)


def test_eq34_subdominant_eigenvalue_at_n_4_is_one_half():
    """Eq. 34 at c = cos(pi/4) = sqrt(2)/2: 1/4 + 1/16 + (sqrt(2)/8) sqrt(9/8) = 5/16 + 3/16 = 1/2.

    The other root: det M_1 = 3/32 - (1 - i)(1 + i)/64 = 1/16, so lambda_2 = (1/16)/(1/2) = 1/8.
    """
    dominant, subdominant = tangent_eigenvalues(CC).at(4, 1)
    assert sp.simplify(dominant - R(1, 2)) == 0
    assert sp.simplify(subdominant - R(1, 8)) == 0


def test_eq39_ratio_at_n_4_is_one_plus_i():
    """Eq. 39 at n = 4: on the dominant eigenvector (1, y) of M_1, y = (lambda - 3/8)/((1 - i)/16) = 2/(1 - i) = 1 + i."""
    assert invariant_ratio_at(CC, 4, 1) == 1 + sp.I


def test_eq45_recursion_matrix_at_n_4():
    """Eq. 45 (printed in full): the Eq. 43 matrix at n = 4."""
    assert recursion_matrix(CC, 4) == sp.Matrix([[R(9, 16), R(3, 8), R(1, 16)], [R(3, 8), R(1, 2), R(1, 8)], [R(1, 4), R(1, 2), R(1, 4)]])


def test_eq44_eq45_eigenvector_and_ratio_at_n_4():
    """Eq. 44-45: for mu = 1/4 the eigenvector is proportional to (-2, 1, 4), so (u_b - u_O)/(u_a - u_O) = 6/3 = 2.

    Check by hand: rows 2 and 3 of T - I/4 are (3/8, 1/4, 1/8) and (1/4, 1/2, 0); both vanish on (-2, 1, 4).
    """
    u = recursion_eigenvector(CC, R(1, 4), 4)
    assert u.cross(sp.Matrix([-2, 1, 4])) == sp.zeros(3, 1)
    assert eq44_ratio(CC, R(1, 4), 4) == 2


def test_regular_limit_masks_at_n_4():
    """Limit masks of the regular bicubic B-spline: position (16 : 4 : 1)/36 = 4/9, 1/9, 1/36 (tensor square of (1, 4, 1)/6).

    The tangent mask weights a_0 : b_0 as 1 : 1/4 (the first derivative of the cubic B-spline's limit
    stencil (-1, 0, 1) times (1, 4, 1)/6 on the other axis).
    """
    m = limit_masks_at(CC, 4)
    assert m.position == (R(4, 9),) + (R(1, 9),) * 4 + (R(1, 36),) * 4
    assert sp.simplify(m.subdominant - R(1, 2)) == 0
    assert sp.simplify(m.tangents[0][1]) == 1 and sp.simplify(m.tangents[0][5] - R(1, 4)) == 0


def test_section_6_characteristic_polynomial_at_n_4():
    """Section 6 at n = 4: eigenvalues 1, 1/2 (x2), 1/4 (x3), 1/8 (x2), 1/16.

    From Eq. 45 (1, 1/4, 1/16: its trace is 21/16 = 1 + 1/4 + 1/16 and its determinant 1/64),
    M_1 and M_3 (1/2, 1/8 each, as above) and M_2 = I/4 (omega = -1: 3/8 - 1/8 = 1/4, 0, 0, 1/4).
    """
    x = flint.fmpq_poly([0, 1])
    expected = (x - 1) * (x - flint.fmpq(1, 2)) ** 2 * (x - flint.fmpq(1, 4)) ** 3
    expected *= (x - flint.fmpq(1, 8)) ** 2 * (x - flint.fmpq(1, 16))
    assert characteristic_polynomial(CC, 4) == expected
    assert closed_form_characteristic_polynomial(CC).at(4) == expected
    assert per_frequency_matrix_at(CC, 4, 2) == sp.eye(2) / 4
