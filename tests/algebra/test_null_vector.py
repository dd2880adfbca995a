"""The one certified null vector of a ball matrix (eigenvectors and left eigenvectors in Arb)."""

import flint
import pytest

from symdecomp.algebra.null_vector import null_vector


def _shifted(rows, value):
    m = len(rows)
    return flint.acb_mat([[flint.acb(rows[r][c]) - (value if r == c else 0) for c in range(m)] for r in range(m)])


@pytest.mark.parametrize("first", [None, 0, 2])
def test_the_null_vector_of_a_matrix_at_its_simple_eigenvalue(first):
    # the circulant with rows (2, 1, 0): eigenvalue 3 (eigenvector (1, 1, 1)) is simple
    rows = [[2, 1, 0], [0, 2, 1], [1, 0, 2]]
    x = null_vector(_shifted(rows, flint.acb(3)), first=first)
    assert x is not None and x[first or 0] == 1
    assert all(abs(x[i] - 1).upper() < 1e-12 for i in range(3))  # (1, 1, 1), scaled by the fixed coordinate


def test_a_left_null_vector_is_the_transposes():
    # y (M - 1) = 0 for M = [[1/2, 1/2], [1/4, 3/4]]: y = (1, 2) (up to scale), the stationary weights
    A = _shifted([[flint.fmpq(1, 2), flint.fmpq(1, 2)], [flint.fmpq(1, 4), flint.fmpq(3, 4)]], flint.acb(1))
    y = null_vector(A.transpose(), first=0)
    assert y[0] == 1 and (y[1] - 2).contains(0) and abs(y[1] - 2).upper() < 1e-12
    residual = flint.acb_mat([y]) * A
    assert all(residual[0, c].contains(0) for c in range(2))


def test_no_null_vector_of_a_matrix_that_is_certainly_invertible():
    assert null_vector(flint.acb_mat([[1, 0], [0, 1]])) is None
