"""Example CB-matrices and names shared by the Section 6 claims (generic, random rational, banded of symbolic order)."""

from __future__ import annotations

import random

import sympy as sp

from symdecomp.algebra.cbmatrix import cb_matrix
from symdecomp.algebra.circulant import mode_eigenvalue_derivation
from symdecomp.claims.notation import Kron
from symdecomp.symbols import omega as OMEGA


def _nc(name: str) -> sp.Symbol:
    """A matrix or vector, by name (products of names keep their order)."""
    return sp.Symbol(name, commutative=False)


_kron = Kron


_det = sp.Function("det")

M_SYM = sp.Symbol("m", integer=True, positive=True)


def _random_cb(K: int, m: int, seed: int):
    rng = random.Random(seed)
    return cb_matrix([[[sp.Rational(rng.randint(-9, 9), rng.randint(1, 7)) for _ in range(m)] for _ in range(K)] for _ in range(K)])


def _generic_cb(K: int, m: int):
    return cb_matrix([[[sp.Symbol(f"c{p}{q}_{l}") for l in range(m)] for q in range(K)] for p in range(K)])


def _banded_symbolic_identity(K: int):
    """Row ``i`` of block row ``p`` of ``B (alpha (x) v)`` minus ``(E alpha)_p omega^i``, symbolic order."""
    coeffs = sp.symbols(f"a0:{K}")
    i = sp.Symbol("i", integer=True)
    residues = []
    for p in range(K):
        row = sp.Integer(0)
        e_alpha = sp.Integer(0)
        for q in range(K):
            offsets = {l: sp.Symbol(f"c{p}{q}_{l % 7}") for l in (-1, 0, 1, 2)}
            block_row, eig = mode_eigenvalue_derivation(offsets)
            row += coeffs[q] * block_row
            e_alpha += eig * coeffs[q]
        residues.append(sp.expand(sp.powsimp(sp.expand(row / OMEGA**i)) - e_alpha))
    return residues


def _blockwise_product_residues(K: int) -> list:
    """Block ``p`` of ``B V`` minus ``sum_q alpha_q C_pq v``: ``K x K`` blocks of symbolic order ``m``, ``V`` the
    block column ``(alpha_0 v; ...; alpha_{K-1} v)`` of Eq. 46."""
    v = sp.MatrixSymbol("v", M_SYM, 1)
    coefficients = sp.symbols(f"alpha0:{K}")
    blocks = [[sp.MatrixSymbol(f"C{p}{q}", M_SYM, M_SYM) for q in range(K)] for p in range(K)]
    product = sp.block_collapse(sp.BlockMatrix(blocks) * sp.BlockMatrix([[a * v] for a in coefficients]))
    residues = [sp.simplify(product.blocks[p, 0] - sum((coefficients[q] * blocks[p][q] * v for q in range(K)), sp.ZeroMatrix(M_SYM, 1)))
                for p in range(K)]
    return [sp.Integer(0) if isinstance(r, sp.ZeroMatrix) else r for r in residues]


def invertible(M: sp.Matrix) -> bool:
    """Whether a square matrix of closed forms is invertible: its determinant's Arb enclosure excludes 0 (a proof), else
    sympy's exact rank decides (the closed forms hold radicals over Q(i): an exact rank with simplification takes seconds)."""
    import flint

    from symdecomp.algebra.compile import UnsupportedExpressionError, compile_expression

    try:
        with flint.ctx.workprec(128):
            if not flint.acb_mat([[compile_expression(e, (), "arb")() for e in row] for row in M.tolist()]).det().contains(0):
                return True
    except UnsupportedExpressionError:
        pass
    return M.rank(simplify=True) == M.rows
