"""Matrices with circulant blocks (CB-matrices, Section 6: Prop. 6.1-6.3, Remark 6.1).

A *CB-matrix* is a ``K x K`` block matrix whose blocks ``C_pq`` are ``m x m`` circulants.
Every circulant of order ``m`` has the regular polygons ``v_k`` (rows of the Fourier matrix,
Eq. 2) as eigenvectors (Prop. 2.1), so for every frequency ``k``

    ``B (x (x) v_k) = (E_k x) (x) v_k``,   ``(E_k)_pq`` = eigenvalue of ``C_pq`` on ``v_k``

for *every* coefficient vector ``x`` (Prop. 6.2 and Eq. 46-50 are the case ``E_k x = lambda x``).
The ``K m`` vectors ``e_p (x) v_k`` form a basis, so ``B`` is similar to the block-diagonal
matrix ``diag(E_0, ..., E_{m-1})`` (Remark 6.1), and adding blocks that are constant
matrices ``t_pq J`` (``J`` all ones) changes only ``E_0``, into ``E_0 + m T`` (Prop. 6.3),
because ``J v_k = 0`` for ``k != 0`` and ``J v_0 = m v_0`` (Prop. 6.1).

Two representations:

* :class:`CBMatrix`: concrete order ``m``, each block given by its first row (exact rationals
  or sympy expressions);
* :class:`SymbolicCirculant` / :class:`SymbolicCBMatrix`: symbolic order ``n``, each block a
  banded circulant (offsets, as in :mod:`symdecomp.algebra.circulant`) plus a multiple of ``J``.

>>> R = sp.Rational
>>> B = cb_matrix([[[R(1, 2), R(1, 4), 0], [1, 0, 0]], [[0, 0, 1], [R(1, 3), 0, 0]]])
>>> B.block_count, B.order
(2, 3)
>>> block_eigenvalue_matrix(B, 0)
Matrix([
[3/4,   1],
[  1, 1/3]])
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.circulant import _offsets, _sequence, circ, coefficient, fourier_matrix, fourier_row, generating_polynomial
from symdecomp.errors import FrequencyOutOfRangeError, InvalidExpressionError, InvalidTypeError, NotCirculantBlockError
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_int, check_valence

__all__ = [
    "CBMatrix",
    "cb_matrix",
    "cb_matrix_from",
    "block_eigenvalue_matrix",
    "lifted_vector",
    "BlockDiagonalization",
    "block_diagonalization",
    "cb_eigensystem",
    "constant_blocks",
    "perturbed_block_eigenvalue_matrix",
    "SymbolicCirculant",
    "SymbolicCBMatrix",
]


def _cb(cb) -> CBMatrix:
    if not isinstance(cb, CBMatrix):
        raise InvalidTypeError(f"expected a CBMatrix (see cb_matrix), got {type(cb).__name__}")
    return cb


def _exact(value, where: str) -> sp.Expr:
    try:
        return coefficient(value, where)
    except InvalidExpressionError as exc:
        raise NotCirculantBlockError(str(exc)) from None


@dataclass(frozen=True)
class CBMatrix:
    """A ``K x K`` matrix of circulant blocks of order ``m`` (concrete ``m``)."""

    #: ``rows[p][q]`` is the first row ``(c_0, ..., c_{m-1})`` of the block ``C_pq``
    #: (convention of Eq. 7: entry ``(r, s)`` of the block is ``c_{(s-r) mod m}``).
    rows: tuple[tuple[tuple[sp.Expr, ...], ...], ...]

    @property
    def block_count(self) -> int:
        """``K``, the number of block rows (and block columns)."""
        return len(self.rows)

    @property
    def order(self) -> int:
        """``m``, the order of each circulant block."""
        return len(self.rows[0][0])

    def block(self, p: int, q: int) -> sp.ImmutableMatrix:
        """The circulant block ``C_pq`` as a matrix."""
        return circ(self.rows[p][q])

    def matrix(self) -> sp.ImmutableMatrix:
        """The full ``Km x Km`` matrix."""
        blocks = [[self.block(p, q) for q in range(self.block_count)] for p in range(self.block_count)]
        return sp.ImmutableMatrix(sp.BlockMatrix(blocks).as_explicit())

    def __add__(self, other: CBMatrix) -> CBMatrix:
        if not isinstance(other, CBMatrix) or (other.block_count, other.order) != (self.block_count, self.order):
            return NotImplemented
        return CBMatrix(
            tuple(
                tuple(tuple(a + b for a, b in zip(ra, rb)) for ra, rb in zip(row_a, row_b))
                for row_a, row_b in zip(self.rows, other.rows)
            )
        )


def cb_matrix(blocks: Sequence[Sequence[Sequence]]) -> CBMatrix:
    """Build a :class:`CBMatrix` from the first rows of its blocks (``blocks[p][q]``)."""
    blocks = [[_sequence(first, "a block's first row") for first in _sequence(row, "a row of blocks")]
              for row in _sequence(blocks, "blocks")]
    K = len(blocks)
    if K == 0 or any(len(row) != K for row in blocks):
        raise NotCirculantBlockError(f"a CB-matrix needs a square K x K array of blocks, got rows of lengths {[len(r) for r in blocks]}")
    m = len(blocks[0][0])
    if m == 0:
        raise NotCirculantBlockError("circulant blocks need order m >= 1")
    rows = []
    for p, row in enumerate(blocks):
        out = []
        for q, first in enumerate(row):
            if len(first) != m:
                raise NotCirculantBlockError(f"block ({p}, {q}) has order {len(first)}, the others {m}")
            out.append(tuple(_exact(c, f"block ({p}, {q})") for c in first))
        rows.append(tuple(out))
    return CBMatrix(tuple(rows))


def cb_matrix_from(matrix, order: int) -> CBMatrix:
    """Read a square matrix as a CB-matrix with blocks of the given order; every block must be circulant."""
    M = matrix if isinstance(matrix, sp.MatrixBase) else _constants(matrix)
    order = check_valence(order, minimum=1)
    if M.rows != M.cols or M.rows % order:
        raise NotCirculantBlockError(f"a {M.rows} x {M.cols} matrix is not square with blocks of order {order}")
    K = M.rows // order
    blocks = []
    for p in range(K):
        row = []
        for q in range(K):
            block = M[p * order:(p + 1) * order, q * order:(q + 1) * order]
            first = [block[0, s] for s in range(order)]
            if sp.Matrix(circ(first)) != block:
                raise NotCirculantBlockError(f"block ({p}, {q}) of the matrix is not circulant")
            row.append(first)
        blocks.append(row)
    return cb_matrix(blocks)


def block_eigenvalue_matrix(cb: CBMatrix, k: int) -> sp.ImmutableMatrix:
    """The ``K x K`` matrix ``E`` of Prop. 6.2 for the eigenvector ``v_k`` of the circulants.

    ``e_pq`` is the eigenvalue of ``C_pq`` on ``v_k``: ``sum_l c_l omega_m^(k l)`` (Eq. 8-9).
    """
    m = _cb(cb).order
    k = check_int(k, "frequency k", minimum=0, maximum=m - 1, error=FrequencyOutOfRangeError)
    w = fourier_row(m, k)
    return sp.ImmutableMatrix(
        cb.block_count,
        cb.block_count,
        lambda p, q: sp.expand(sum((c * wl for c, wl in zip(cb.rows[p][q], w)), sp.Integer(0))),
    )


def lifted_vector(coefficients: Sequence, v: Sequence) -> sp.ImmutableMatrix:
    """``V = (alpha_0 v, ..., alpha_{K-1} v)`` of Prop. 6.2 (the Kronecker product ``alpha (x) v``)."""
    coefficients = [coefficient(a, f"coefficient {i}") for i, a in enumerate(_sequence(coefficients, "coefficients"))]
    v = [coefficient(x, f"vertex {i} of v") for i, x in enumerate(_sequence(v, "v"))]
    return sp.ImmutableMatrix([a * x for a in coefficients for x in v])


@dataclass(frozen=True)
class BlockDiagonalization:
    """``P^{-1} B P = D`` with ``D = diag(E_0, ..., E_{m-1})`` (Remark 6.1)."""

    #: Columns ``e_p (x) v_k``, ordered by frequency ``k`` and then block ``p``.
    basis: sp.ImmutableMatrix
    #: The block-eigenvalue matrices ``E_0, ..., E_{m-1}`` of Prop. 6.2.
    frequency_matrices: tuple[sp.ImmutableMatrix, ...]

    def block_diagonal(self) -> sp.ImmutableMatrix:
        """``diag(E_0, ..., E_{m-1})``."""
        return sp.ImmutableMatrix(sp.diag(*self.frequency_matrices))


def block_diagonalization(cb: CBMatrix) -> BlockDiagonalization:
    """The Fourier basis of Remark 6.1 and the block-eigenvalue matrices ``E_k`` of ``cb``."""
    _cb(cb)
    K, m = cb.block_count, cb.order
    F = fourier_matrix(m) if m > 1 else sp.ImmutableMatrix([[1]])
    columns = []
    for k in range(m):
        v = [F[k, s] for s in range(m)]
        for p in range(K):
            columns.append(lifted_vector([1 if r == p else 0 for r in range(K)], v))
    basis = sp.ImmutableMatrix.hstack(*columns)
    return BlockDiagonalization(basis, tuple(block_eigenvalue_matrix(cb, k) for k in range(m)))


def cb_eigensystem(cb: CBMatrix) -> list[tuple[sp.Expr, int, list[sp.ImmutableMatrix]]]:
    """Eigenvalues and eigenvectors ``alpha (x) v_k`` of a CB-matrix from its ``E_k`` (Prop. 6.2).

    Returns ``[(eigenvalue, frequency k, [eigenvectors]), ...]`` with one entry per eigenvalue of
    each ``E_k``. By Remark 6.1 the eigenvectors form a basis of the whole space exactly when
    every ``E_k`` is diagonalizable; :func:`block_diagonalization` shows why.
    """
    _cb(cb)
    out = []
    m = cb.order
    F = fourier_matrix(m) if m > 1 else sp.ImmutableMatrix([[1]])
    for k in range(m):
        v = [F[k, s] for s in range(m)]
        for value, _mult, vectors in sp.Matrix(block_eigenvalue_matrix(cb, k)).eigenvects():
            out.append((value, k, [lifted_vector(list(a), v) for a in vectors]))
    return out


def constant_blocks(T, order: int) -> CBMatrix:
    """The block matrix ``A`` of Prop. 6.3: block ``(p, q)`` is ``m x m`` with every entry ``t_pq``."""
    T = _constants(T)
    order = check_valence(order, minimum=1)
    if T.rows != T.cols:
        raise NotCirculantBlockError(f"the matrix of constants must be square, got {T.rows} x {T.cols}")
    return cb_matrix([[[T[p, q]] * order for q in range(T.cols)] for p in range(T.rows)])


def _constants(T) -> sp.Matrix:
    """A square matrix of exact constants ``t_pq`` (text parsed, never evaluated)."""
    if isinstance(T, sp.MatrixBase):
        rows = T.tolist()
    else:
        rows = [_sequence(r, "a row of T") for r in _sequence(T, "T")]
    if not rows or len({len(r) for r in rows}) != 1:
        raise NotCirculantBlockError(f"the matrix of constants T must be a non-empty rectangular array, got rows of lengths {[len(r) for r in rows]}")
    return sp.Matrix([[_exact(t, f"T[{p}][{q}]") for q, t in enumerate(r)] for p, r in enumerate(rows)])


def perturbed_block_eigenvalue_matrix(cb: CBMatrix, T) -> sp.ImmutableMatrix:
    """``E_0 + m T`` (Prop. 6.3, where the paper writes ``E_1``): the block-eigenvalue matrix ``E_0`` of ``cb + A``.

    The eigenvalues of ``cb + constant_blocks(T, m)`` are those of ``E_1, ..., E_{m-1}``
    (unchanged) and the ``K`` eigenvalues of this matrix.
    """
    _cb(cb)
    T = _constants(T)
    if T.shape != (cb.block_count, cb.block_count):
        raise NotCirculantBlockError(f"T must be {cb.block_count} x {cb.block_count}, got {T.rows} x {T.cols}")
    return sp.ImmutableMatrix(block_eigenvalue_matrix(cb, 0) + cb.order * T)


# --- symbolic order -------------------------------------------------------------------------


@dataclass(frozen=True)
class SymbolicCirculant:
    """An ``n x n`` circulant for symbolic ``n``: a banded part plus a multiple of ``J``.

    ``C = circ_from_offsets(offsets, n) + constant * J``. Its eigenvalue on ``v_k`` is
    ``p(omega)`` for ``k != 0`` and ``p(1) + n*constant`` for ``k = 0`` (Prop. 2.1 and 6.1),
    with ``p`` the generating polynomial of the offsets.
    """

    #: Pairs ``(k, c_k)`` of the banded part, sorted by offset (offsets distinct mod ``n``).
    offsets: tuple[tuple[int, sp.Expr], ...]
    #: The coefficient of the all-ones matrix ``J``.
    constant: sp.Expr = sp.Integer(0)

    @classmethod
    def from_offsets(cls, offsets: Mapping[int, object], constant=0) -> SymbolicCirculant:
        return cls(tuple(sorted(_offsets(offsets).items())), coefficient(constant, "constant"))

    def symbol(self) -> sp.Expr:
        """The generating polynomial ``p(omega)`` of the banded part (Eq. 9)."""
        return generating_polynomial(dict(self.offsets))

    def eigenvalue(self, *, zero_frequency: bool, order=N) -> sp.Expr:
        """The eigenvalue on ``v_k``: ``p(omega)`` if ``k != 0``, ``p(1) + n*constant`` if ``k = 0``."""
        if zero_frequency:
            return sp.expand(self.symbol().subs(OMEGA, 1) + order * self.constant)
        return self.symbol()

    def row_sum(self, order=N) -> sp.Expr:
        """Each row sums to ``p(1) + n*constant``."""
        return self.eigenvalue(zero_frequency=True, order=order)

    def at(self, n: int) -> sp.ImmutableMatrix:
        """The concrete ``n x n`` matrix."""
        from symdecomp.algebra.circulant import circ_from_offsets

        n = check_valence(n, minimum=1)
        banded = circ_from_offsets({k: w.subs(N, n) for k, w in self.offsets}, n)
        return sp.ImmutableMatrix(banded + sp.ones(n, n) * self.constant.subs(N, n))

    def minus_constant(self, value) -> SymbolicCirculant:
        """``C - value*J``."""
        return SymbolicCirculant(self.offsets, sp.expand(self.constant - coefficient(value, "value")))


@dataclass(frozen=True)
class SymbolicCBMatrix:
    """A ``K x K`` matrix of :class:`SymbolicCirculant` blocks of symbolic order ``n``."""

    #: ``blocks[p][q]`` is the block ``C_pq``.
    blocks: tuple[tuple[SymbolicCirculant, ...], ...]

    @property
    def block_count(self) -> int:
        return len(self.blocks)

    def block_eigenvalue_matrix(self, *, zero_frequency: bool, order=N) -> sp.ImmutableMatrix:
        """``E`` of Prop. 6.2: in ``omega`` for ``k != 0``, or the ``k = 0`` matrix (with ``n``)."""
        return sp.ImmutableMatrix(
            [[b.eigenvalue(zero_frequency=zero_frequency, order=order) for b in row] for row in self.blocks]
        )

    def at(self, n: int) -> sp.ImmutableMatrix:
        """The concrete ``Kn x Kn`` matrix."""
        return sp.ImmutableMatrix(sp.BlockMatrix([[b.at(n) for b in row] for row in self.blocks]).as_explicit())

    def concrete(self, n: int) -> CBMatrix:
        """The :class:`CBMatrix` at a concrete order."""
        return cb_matrix_from(self.at(n), n)

