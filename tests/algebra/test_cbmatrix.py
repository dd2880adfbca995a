"""CB-matrices (Section 6): Prop. 6.1-6.3 and Remark 6.1 on matrices other than the subdivision matrix."""

import random

import pytest
import sympy as sp

from symdecomp.algebra.cbmatrix import (
    CBMatrix,
    NotCirculantBlockError,
    SymbolicCBMatrix,
    SymbolicCirculant,
    block_diagonalization,
    block_eigenvalue_matrix,
    cb_eigensystem,
    cb_matrix,
    cb_matrix_from,
    constant_blocks,
    lifted_vector,
    perturbed_block_eigenvalue_matrix,
)
from symdecomp.algebra.circulant import circ, circ_from_offsets, fourier_matrix
from symdecomp.errors import SymdecompError
from symdecomp.symbols import omega


def is_zero_matrix(M):
    """Exact: roots of unity rewritten in radicals, then expanded."""
    return all(sp.expand(sp.expand_complex(e)) == 0 for e in sp.Matrix(M))


def random_cb(K, m, seed):
    rng = random.Random(seed)
    return cb_matrix([[[sp.Rational(rng.randint(-9, 9), rng.randint(1, 7)) for _ in range(m)] for _ in range(K)] for _ in range(K)])


def test_matrix_is_made_of_the_circulant_blocks():
    B = cb_matrix([[[1, 2, 3], [4, 5, 6]], [[7, 8, 9], [0, 1, 0]]])
    M = B.matrix()
    assert M.shape == (6, 6)
    assert M[0:3, 3:6] == circ([4, 5, 6])
    assert M[3:6, 0:3] == circ([7, 8, 9])
    assert cb_matrix_from(M, 3) == B


@pytest.mark.parametrize("K,m,seed", [(2, 4, 0), (3, 4, 1), (2, 2, 2), (1, 4, 3), (3, 3, 4)])
def test_lift_identity_on_random_rational_cb_matrices(K, m, seed):
    """Eq. 49: B (a (x) v_k) = (E_k a) (x) v_k for every coefficient vector a and every k."""
    B = random_cb(K, m, seed)
    F = fourier_matrix(m)
    a = sp.symbols(f"a0:{K}")
    for k in range(m):
        v = list(F.row(k))
        lhs = sp.Matrix(B.matrix()) * sp.Matrix(lifted_vector(a, v))
        rhs = sp.Matrix(lifted_vector(list(sp.Matrix(block_eigenvalue_matrix(B, k)) * sp.Matrix(a)), v))
        assert is_zero_matrix(lhs - rhs)


@pytest.mark.parametrize("K,m,seed", [(2, 4, 5), (3, 2, 6), (2, 3, 7)])
def test_block_diagonalization(K, m, seed):
    """Remark 6.1: B P = P diag(E_0..E_{m-1}) and P is invertible."""
    B = random_cb(K, m, seed)
    bd = block_diagonalization(B)
    P = sp.Matrix(bd.basis)
    assert is_zero_matrix(sp.Matrix(B.matrix()) * P - P * sp.Matrix(bd.block_diagonal()))
    assert sp.expand(sp.expand_complex(P.det())) != 0


def test_eigensystem_is_a_basis_when_every_E_is_diagonalizable():
    B = random_cb(2, 4, 11)
    pairs = cb_eigensystem(B)
    vectors = []
    for value, _k, vecs in pairs:
        for V in vecs:
            assert sp.expand(sp.Matrix(B.matrix()) * V - value * V) == sp.zeros(8, 1)
            vectors.append(V)
    assert sp.Matrix.hstack(*vectors).rank(simplify=True) == 8


def test_non_diagonalizable_E_gives_non_diagonalizable_B():
    J = cb_matrix([[[1, 0, 0], [1, 0, 0]], [[0, 0, 0], [1, 0, 0]]])
    assert block_eigenvalue_matrix(J, 0) == sp.Matrix([[1, 1], [0, 1]])
    assert not sp.Matrix(J.matrix()).is_diagonalizable()


@pytest.mark.parametrize("seed", range(3))
def test_constant_blocks_change_only_frequency_zero(seed):
    """Prop. 6.3 (corrected): det(xI - (B + A)) = det(xI - E_0 - mT) prod_{k>0} det(xI - E_k)."""
    x = sp.Symbol("x")
    m = 4
    B = random_cb(2, m, 20 + seed)
    rng = random.Random(seed)
    T = sp.Matrix(2, 2, lambda i, j: sp.Rational(rng.randint(-5, 5), rng.randint(1, 4)))
    C = B + constant_blocks(T, m)
    lhs = sp.Matrix(C.matrix()).charpoly(x).as_expr()
    rhs = (x * sp.eye(2) - perturbed_block_eigenvalue_matrix(B, T)).det()
    for k in range(1, m):
        rhs *= (x * sp.eye(2) - block_eigenvalue_matrix(B, k)).det()
    assert sp.expand(lhs - rhs) == 0
    assert perturbed_block_eigenvalue_matrix(B, T) == block_eigenvalue_matrix(C, 0)


def test_constant_matrix_prop61_corrected():
    c = sp.Symbol("c")
    for k in range(3, 7):
        ev = sp.Matrix(circ([c] * k)).eigenvals()
        assert ev == {k * c: 1, 0: k - 1}


def test_symbolic_circulant_matches_concrete():
    C = SymbolicCirculant.from_offsets({-1: sp.Rational(1, 16), 0: sp.Rational(3, 8), 1: sp.Rational(1, 16)}, -sp.Rational(1, 5))
    for n in (3, 5, 8):
        expected = sp.Matrix(circ_from_offsets({-1: sp.Rational(1, 16), 0: sp.Rational(3, 8), 1: sp.Rational(1, 16)}, n)) - sp.ones(n, n) / 5
        assert sp.Matrix(C.at(n)) == expected
        assert C.row_sum(order=n) == sum(expected.row(0))
    assert C.eigenvalue(zero_frequency=False) == sp.Rational(3, 8) + omega / 16 + 1 / (16 * omega)


def test_symbolic_cb_frequency_matrices_match_concrete():
    blocks = (
        (SymbolicCirculant.from_offsets({0: 1, 1: 2}, 3), SymbolicCirculant.from_offsets({-1: 5})),
        (SymbolicCirculant.from_offsets({0: 7}, -1), SymbolicCirculant.from_offsets({1: 1, -1: 1}, sp.Rational(1, 2))),
    )
    S = SymbolicCBMatrix(blocks)
    concrete = S.concrete(4)
    assert sp.Matrix(block_eigenvalue_matrix(concrete, 0)) == sp.Matrix(S.block_eigenvalue_matrix(zero_frequency=True, order=4))
    for k in (1, 2, 3):
        symbolic = S.block_eigenvalue_matrix(zero_frequency=False).subs(omega, sp.I**k)
        assert sp.expand(sp.Matrix(block_eigenvalue_matrix(concrete, k)) - symbolic) == sp.zeros(2, 2)


def test_bad_input_is_named():
    with pytest.raises(NotCirculantBlockError, match="not circulant"):
        cb_matrix_from(sp.Matrix([[1, 2, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]), 2)
    with pytest.raises(NotCirculantBlockError, match="order"):
        cb_matrix([[[1, 2], [1, 2, 3]], [[1, 2], [1, 2]]])
    with pytest.raises(NotCirculantBlockError, match="float"):
        cb_matrix([[[0.5, 1]]])
    with pytest.raises(NotCirculantBlockError, match="square"):
        cb_matrix([[[1, 2], [1, 2]]])
    with pytest.raises(SymdecompError, match="frequency"):
        block_eigenvalue_matrix(random_cb(2, 3, 0), 3)
    assert isinstance(random_cb(2, 3, 0), CBMatrix)


def test_lift_identity_with_symbolic_blocks():
    """Prop. 6.2 for a CB-matrix with fully symbolic circulant blocks (2 x 2 blocks of order 3)."""
    B = cb_matrix([[[sp.Symbol(f"c{p}{q}{l}") for l in range(3)] for q in range(2)] for p in range(2)])
    a = sp.symbols("a0:2")
    F = fourier_matrix(3)
    for k in range(3):
        v = list(F.row(k))
        lhs = sp.Matrix(B.matrix()) * sp.Matrix(lifted_vector(a, v))
        rhs = sp.Matrix(lifted_vector(list(sp.Matrix(block_eigenvalue_matrix(B, k)) * sp.Matrix(a)), v))
        assert is_zero_matrix(lhs - rhs)
