"""The reduction S -> S' (Section 6) derived on the block form, against the explicit row/column operations."""

import pytest
import sympy as sp

from symdecomp.analysis.reduction import BorderedCBMatrix, reduce_first_column, reduction_similarity, subdivision_block_form
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import alpha, beta

SCHEME = catmull_clark(alpha, beta)


def explicit_operations(S):
    """Add all columns to the first, then subtract the first row from the others, entry by entry."""
    M = sp.Matrix(S)
    for c in range(1, M.cols):
        M[:, 0] = M[:, 0] + M[:, c]
    for r in range(1, M.rows):
        M[r, :] = M[r, :] - M[0, :]
    return M.applyfunc(sp.expand)


@pytest.mark.parametrize("n", range(3, 9))
def test_block_form_is_the_subdivision_matrix(n):
    assert sp.expand(sp.Matrix(subdivision_block_form(SCHEME).at(n)) - subdivision_matrix(SCHEME, n)) == sp.zeros(2 * n + 1, 2 * n + 1)


@pytest.mark.parametrize("n", range(3, 9))
def test_reduced_matrix_is_what_the_operations_give(n):
    S = sp.Matrix(subdivision_matrix(SCHEME, n))
    red = reduce_first_column(subdivision_block_form(SCHEME))
    Sp = sp.Matrix(red.reduced.at(n))
    assert explicit_operations(S) == Sp.applyfunc(sp.expand)
    Q, Qinv = reduction_similarity(2 * n + 1)
    assert sp.Matrix(Q) * sp.Matrix(Qinv) == sp.eye(2 * n + 1)
    assert (sp.Matrix(Qinv) * S * sp.Matrix(Q) - Sp).applyfunc(sp.expand) == sp.zeros(2 * n + 1, 2 * n + 1)
    # first column (1, 0, ..., 0); the lower-right block is [[C1 - A, C2 - B], [C3 - A, C4 - B]]
    assert list(Sp[:, 0]) == [1] + [0] * (2 * n)
    assert Sp[1, 1] == S[1, 1] - alpha and Sp[1, n + 1] == S[1, n + 1] - beta
    assert Sp[n + 1, 1] == S[n + 1, 1] - alpha and Sp[n + 1, n + 1] == S[n + 1, n + 1] - beta


def test_charpoly_of_S_equals_that_of_S_prime_with_free_weights():
    x = sp.Symbol("x")
    n = 3
    S = sp.Matrix(subdivision_matrix(SCHEME, n))
    Sp = sp.Matrix(reduce_first_column(subdivision_block_form(SCHEME)).reduced.at(n))
    assert sp.expand(S.charpoly(x).as_expr() - Sp.charpoly(x).as_expr()) == 0


def test_symbolic_block_form():
    red = reduce_first_column(subdivision_block_form(SCHEME))
    assert red.after_columns.corner == 1 and red.after_columns.column == (1, 1)
    assert red.reduced.row == (alpha, beta)
    assert [[b.constant for b in row] for row in red.lower_right.blocks] == [[-alpha, -beta], [-alpha, -beta]]


def test_rows_with_different_sums_are_rejected():
    form = subdivision_block_form(SCHEME)
    bad = BorderedCBMatrix(sp.Integer(2), form.row, form.column, form.body)
    with pytest.raises(InvalidSchemeError, match="do not all sum"):
        reduce_first_column(bad)
