"""The subdivision matrix as a bordered CB-matrix and the reduction ``S -> S'`` (Section 6).

In the vertex order ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` the subdivision matrix is

    ``S = [[s, r_a 1^T, r_b 1^T], [c_a 1, C_1, C_2], [c_b 1, C_3, C_4]]``

with circulant blocks ``C_1..C_4`` (read off the edge and face rules) and the vertex rule in
the first row (``r_a = alpha``, ``r_b = beta``). The paper removes the eigenvalue 1 by two
operations: *add all columns to the first* and *subtract the first row from all the
others*. Here they are carried out on the block form, for symbolic ``n``: the column
operation is ``S -> S Q`` with ``Q = I + w e_0^T`` (``w`` = indicator of rows ``1..2n``), the row
operation is ``-> Q^{-1} (S Q)`` with ``Q^{-1} = I - w e_0^T`` (``e_0^T w = 0``). So
``S' = Q^{-1} S Q`` is *similar* to ``S``, not merely of equal determinant.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.symbols import alpha, beta
>>> r = reduce_first_column(subdivision_block_form(catmull_clark(alpha, beta)))
>>> r.reduced.column
(0, 0)
>>> [[b.constant for b in row] for row in r.reduced.body.blocks]
[[-alpha, -beta], [-alpha, -beta]]
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.cbmatrix import SymbolicCBMatrix, SymbolicCirculant
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = [
    "BorderedCBMatrix",
    "subdivision_block_form",
    "add_columns_to_first",
    "subtract_first_row",
    "Reduction",
    "reduce_first_column",
    "reduction_similarity",
]


@dataclass(frozen=True)
class BorderedCBMatrix:
    """``[[corner, r_0 1^T, ..., r_{K-1} 1^T], [c_0 1, C_00, ...], ...]`` for symbolic ``n``."""

    #: The ``(0, 0)`` entry.
    corner: sp.Expr
    #: ``r_q``: the first row is constant (``r_q``) on block column ``q``.
    row: tuple[sp.Expr, ...]
    #: ``c_p``: the first column is constant (``c_p``) on block row ``p``.
    column: tuple[sp.Expr, ...]
    #: The ``K x K`` circulant blocks.
    body: SymbolicCBMatrix

    def at(self, n: int) -> sp.ImmutableMatrix:
        """The concrete ``(Kn+1) x (Kn+1)`` matrix."""
        n = check_valence(n, minimum=1)
        sub = lambda e: sp.sympify(e, strict=True).subs(N, n)  # noqa: E731
        first_row = sp.Matrix([[sub(self.corner)] + [sub(r) for r in self.row for _ in range(n)]])
        first_col = sp.Matrix([sub(c) for c in self.column for _ in range(n)])
        return sp.ImmutableMatrix(sp.Matrix.vstack(first_row, sp.Matrix.hstack(first_col, sp.Matrix(self.body.at(n)))))


def subdivision_block_form(scheme: Scheme) -> BorderedCBMatrix:
    """The subdivision matrix of ``scheme`` as a bordered CB-matrix, symbolic in ``n`` (Section 6)."""
    check_scheme(scheme)
    v = scheme.vertex_rule
    body = SymbolicCBMatrix(
        (
            (SymbolicCirculant.from_offsets(dict(scheme.edge_rule.a)), SymbolicCirculant.from_offsets(dict(scheme.edge_rule.b))),
            (SymbolicCirculant.from_offsets(dict(scheme.face_rule.a)), SymbolicCirculant.from_offsets(dict(scheme.face_rule.b))),
        )
    )
    return BorderedCBMatrix(v.center, (v.each_a, v.each_b), (scheme.edge_rule.center, scheme.face_rule.center), body)


def add_columns_to_first(M: BorderedCBMatrix) -> BorderedCBMatrix:
    """Add every column to the first one: each first-column entry becomes its row's sum."""
    corner = sp.expand(M.corner + N * sum(M.row, sp.Integer(0)))
    column = tuple(
        sp.expand(c + sum((b.row_sum() for b in blocks), sp.Integer(0))) for c, blocks in zip(M.column, M.body.blocks)
    )
    return BorderedCBMatrix(corner, M.row, column, M.body)


def subtract_first_row(M: BorderedCBMatrix) -> BorderedCBMatrix:
    """Subtract the first row from every other row: ``c_p -> c_p - corner``, ``C_pq -> C_pq - r_q J``."""
    column = tuple(sp.simplify(c - M.corner) for c in M.column)
    body = SymbolicCBMatrix(tuple(tuple(b.minus_constant(r) for b, r in zip(blocks, M.row)) for blocks in M.body.blocks))
    return BorderedCBMatrix(M.corner, M.row, column, body)


@dataclass(frozen=True)
class Reduction:
    """The two steps from ``S`` to ``S'`` (Section 6)."""

    #: ``S`` as a bordered CB-matrix.
    original: BorderedCBMatrix
    #: After adding all columns to the first (first column = row sums).
    after_columns: BorderedCBMatrix
    #: ``S'``: after subtracting the first row from the others.
    reduced: BorderedCBMatrix

    @property
    def lower_right(self) -> SymbolicCBMatrix:
        """The CB-block ``L`` of ``S'``; ``det(xI - S) = (x - corner') det(xI - L)`` when the column is 0."""
        return self.reduced.body


def reduce_first_column(M: BorderedCBMatrix) -> Reduction:
    """Carry out the paper's two operations on the block form; the rows must have a common sum.

    The first column of ``S'`` is ``(rho, 0, ..., 0)`` exactly when every row of ``S`` sums to
    ``rho`` (for an affine scheme ``rho = 1``); otherwise the reduction does not separate an
    eigenvalue and an error is raised.
    """
    step1 = add_columns_to_first(M)
    step2 = subtract_first_row(step1)
    if any(c != 0 for c in step2.column):
        raise InvalidSchemeError(
            f"the rows of the matrix do not all sum to {step1.corner}: first column of S' is {step2.column}, not 0"
        )
    return Reduction(M, step1, step2)


def reduction_similarity(size: int) -> tuple[sp.ImmutableMatrix, sp.ImmutableMatrix]:
    """``(Q, Q^{-1})``: ``S Q`` adds all columns to the first, ``Q^{-1} M`` subtracts the first row from the others."""
    size = check_valence(size, minimum=1)
    Q = sp.eye(size)
    P = sp.eye(size)
    for i in range(1, size):
        Q[i, 0] = 1
        P[i, 0] = -1
    return sp.ImmutableMatrix(Q), sp.ImmutableMatrix(P)
