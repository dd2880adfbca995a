"""The eigen-decomposition of a rational matrix over ``Q``, one block per irreducible factor of its characteristic polynomial.

``A W = W B`` with ``W = (W_1 .. W_r)`` a basis of the generalized eigenspaces ``ker q_i(A)^e_i`` and ``B`` block
diagonal, so that ``A^m C = sum_i W_i B_i^m (W^-1 C)_i`` exactly (Stam's expansion, also where ``A`` is not
diagonalizable: a block is then a Jordan block, or a real block of conjugate roots); the roots of each ``q_i`` are
given as complex Arb balls. Everything is exact (FLINT ``fmpq_mat``); each block's invariance is checked.

>>> import flint
>>> blocks = decomposition(flint.fmpq_mat([[1, 1], [0, 1]]))
>>> [(b.factor, b.multiplicity, b.eigenvectors) for b in blocks]
[((-1, 1), 2, 1)]
"""

from __future__ import annotations

from dataclasses import dataclass

import flint

from symdecomp.errors import InternalError

__all__ = ["PrimaryBlock", "decomposition", "rational_nullspace"]


@dataclass(frozen=True)
class PrimaryBlock:
    """One block of the eigen-decomposition over ``Q``: the generalized eigenspace of a factor ``q^e``."""

    #: ``q``: integer coefficients, constant term first (irreducible over ``Q``).
    factor: tuple[int, ...]
    #: ``e``: its multiplicity in the characteristic polynomial.
    multiplicity: int
    #: Independent eigenvectors per root (``e`` when the block is diagonalizable).
    eigenvectors: int
    #: ``W_i``: ``K x (deg q * e)``, a basis of ``ker q(A)^e`` (columns).
    basis: flint.fmpq_mat
    #: ``B_i``: ``A`` on that basis, ``A W_i = W_i B_i``.
    block: flint.fmpq_mat
    #: The rows of ``W^-1`` that give this block's coordinates of ``C``.
    left: flint.fmpq_mat
    #: The roots of ``q`` as complex Arb balls (sorted by modulus, largest first).
    values: tuple




def rational_nullspace(m: flint.fmpq_mat) -> flint.fmpq_mat:
    """A basis of ``ker m`` (columns), from the reduced row echelon form."""
    r, rank = m.rref()
    cols = m.ncols()
    pivots = [next(j for j in range(cols) if r[i, j] != 0) for i in range(rank)]
    free = [j for j in range(cols) if j not in pivots]
    out = flint.fmpq_mat(cols, len(free))
    for c, j in enumerate(free):
        out[j, c] = 1
        for i, p in enumerate(pivots):
            out[p, c] = -r[i, j]
    return out


def _poly_at(q, a: flint.fmpq_mat) -> flint.fmpq_mat:
    size = a.nrows()
    value = flint.fmpq_mat(size, size)
    for c in reversed(q.coeffs()):  # Horner
        value = value * a
        for i in range(size):
            value[i, i] += c
    return value


def _roots(q) -> tuple:
    roots = q.numer().complex_roots()
    return tuple(sorted((z for z, _ in roots), key=lambda z: -abs(z).mid()))


def decomposition(a: flint.fmpq_mat) -> tuple[PrimaryBlock, ...]:
    """The eigen-decomposition of ``A`` over ``Q`` (module docstring), blocks sorted by factor; exact."""
    size = a.nrows()
    _, factors = a.charpoly().factor()
    parts = []
    for q, e in sorted(factors, key=lambda f: (f[0].degree(), [int(c) for c in f[0].numer().coeffs()])):
        qa = _poly_at(q, a)
        power = qa
        for _ in range(e - 1):
            power = power * qa
        basis = rational_nullspace(power)
        if basis.ncols() != q.degree() * e:
            raise InternalError(f"the generalized eigenspace of {q} has dimension {basis.ncols()}, not {q.degree() * e}")
        eigenvectors = 1 if e == 1 else (size - qa.rref()[1]) // q.degree()
        parts.append((q, e, eigenvectors, basis))
    w = flint.fmpq_mat(size, size)
    col = 0
    for *_, basis in parts:
        for i in range(size):
            for j in range(basis.ncols()):
                w[i, col + j] = basis[i, j]
        col += basis.ncols()
    winv = w.inv()
    b_all = winv * a * w  # block diagonal: each generalized eigenspace is invariant (checked below)
    out, col = [], 0
    for q, e, g, basis in parts:
        d = basis.ncols()
        left = flint.fmpq_mat(d, size, [winv[col + i, j] for i in range(d) for j in range(size)])
        block = _columns(b_all, col, d)
        if basis * block != a * basis:
            raise InternalError(f"the generalized eigenspace of {q} is not invariant")
        out.append(PrimaryBlock(tuple(int(c) for c in q.numer().coeffs()), e, g, basis, block, left, _roots(q)))
        col += d
    return tuple(out)


def _columns(m: flint.fmpq_mat, col: int, d: int) -> flint.fmpq_mat:
    return flint.fmpq_mat(d, d, [m[col + i, col + j] for i in range(d) for j in range(d)])
