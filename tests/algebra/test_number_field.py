"""Exact left eigenspaces over Q(lambda) (symdecomp.algebra.number_field), checked by exact arithmetic in the field."""

from __future__ import annotations

import flint
import pytest

from symdecomp.algebra.number_field import FieldElement, element_ball, left_eigenspace, root_expression, to_sympy_vector
from symdecomp.errors import InvalidInputError


def _residual(S, p, w):
    lam = FieldElement(flint.fmpq_poly([0, 1]) % p, p)
    out = []
    for j in range(S.ncols()):
        acc = FieldElement(flint.fmpq_poly([]), p)
        for i in range(S.nrows()):
            acc = acc + w[i] * FieldElement(flint.fmpq_poly([S[i, j]]), p)
        out.append(acc - lam * w[j])
    return out


def test_the_companion_matrix_of_an_irreducible_cubic():
    p = flint.fmpq_poly([-2, 0, 0, 1])  # x^3 - 2
    S = flint.fmpq_mat([[0, 1, 0], [0, 0, 1], [2, 0, 0]])
    (w,) = left_eigenspace(S, p)
    assert not any(_residual(S, p, w))
    with flint.ctx.workprec(128):
        root = flint.acb(flint.arb(2) ** (flint.arb(1) / 3))
        values = [element_ball(x, root) for x in w]
        assert all(abs(v).mid() > 0 for v in values)


def test_a_double_rational_eigenvalue_has_two_reduced_vectors_in_the_given_order():
    S = flint.fmpq_mat([[1, 0, 0], [flint.fmpq(1, 2), flint.fmpq(1, 2), 0], [flint.fmpq(1, 2), 0, flint.fmpq(1, 2)]])
    p = flint.fmpq_poly([flint.fmpq(-1, 2), 1])
    space = left_eigenspace(S, p, order=[1, 2, 0])
    assert [[x.poly for x in v] for v in space] == [[-1, 1, 0], [-1, 0, 1]]
    assert all(not any(_residual(S, p, v)) for v in space)


def test_a_root_that_is_no_eigenvalue_has_no_eigenvector():
    S = flint.fmpq_mat([[1, 0], [0, 2]])
    assert left_eigenspace(S, flint.fmpq_poly([-2, 0, 1])) == []


def test_quadratic_closed_forms_and_inverses():
    p = flint.fmpq_poly([-1, -1, 1])
    assert str(root_expression(p, 1)) == "1/2 + sqrt(5)/2"
    x = FieldElement(flint.fmpq_poly([3, 2]), p)
    assert (x * x.inverse()).poly == 1
    w = [FieldElement(flint.fmpq_poly([0, 1]), p)]
    assert to_sympy_vector(w, p, 0)[0] == root_expression(p, 0)


@pytest.mark.parametrize("p", [flint.fmpq_poly([1, -2, 1]), flint.fmpq_poly([2]), flint.fmpq_poly([-1, 0, 0, 1])])
def test_a_reducible_or_constant_modulus_is_refused(p):
    with pytest.raises(InvalidInputError, match="irreducible"):
        left_eigenspace(flint.fmpq_mat([[1, 0, 0], [0, 1, 0], [0, 0, 1]]), p)
