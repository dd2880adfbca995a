"""Small exact eigen-decompositions: rational matrices, their null spaces, biorthogonal left bases.

Used for the blocks of structured matrices (a few rows each): eigenvalues from the factored
characteristic polynomial (exact for linear factors, Arb balls for the roots of the others),
eigenvectors from exact null spaces (or adjugate columns in Arb for irrational roots of 2 x 2
and 3 x 3 blocks), and left bases rescaled so that ``left . right = identity``.

>>> from fractions import Fraction as F
>>> [(lam, len(r)) for lam, r, _ in rational_eigen([[F(1, 4), F(0)], [F(0), F(1, 4)]])]
[(Fraction(1, 4), 2)]
"""

from __future__ import annotations

from fractions import Fraction

import flint

from symdecomp.algebra.numbers import to_arb, to_fmpq, to_fraction
from symdecomp.errors import NotDiagonalizableError

__all__ = ["NotDiagonalizableError", "NeedPrecision", "rational_eigen", "nullspace", "biorthogonal"]

arb = flint.arb


# Private control flow, not an error of the package: the eigen-data builders catch it and retry at a
# higher precision (an exhausted cap becomes symdecomp.errors.PrecisionError).
class NeedPrecision(Exception):
    """A ball was too wide to decide a sign at the working precision (raise it and retry)."""


def rational_eigen(m: list[list[Fraction]]):
    """Exact eigen-decomposition of a small rational matrix: ``[(value, right basis, left basis)]``.

    Values of irrational factors come as Arb balls with Arb eigenvectors (sizes 2 and 3 only).
    Raises :class:`NotDiagonalizableError` if a null space is smaller than the multiplicity.
    """
    size = len(m)
    mat = flint.fmpq_mat(size, size, [to_fmpq(x) for row in m for x in row])
    _, factors = mat.charpoly().factor()
    out = []
    for poly, mult in factors:
        if poly.degree() == 1:
            lam = -to_fraction(poly[0]) / to_fraction(poly[1])
            shifted = [[m[i][j] - (lam if i == j else 0) for j in range(size)] for i in range(size)]
            right, left = nullspace(shifted), nullspace([list(r) for r in zip(*shifted)])
            if len(right) != mult:
                raise NotDiagonalizableError(f"eigenvalue {lam} has multiplicity {mult} but {len(right)} eigenvectors")
            out.append((lam, right, left))
            continue
        if mult != 1:
            raise NotDiagonalizableError(f"repeated irrational eigenvalues (factor {poly}) are not supported")
        for root, _ in poly.complex_roots():
            if not root.imag.contains(0):
                raise NotDiagonalizableError(f"complex eigenvalue {root}: the data file holds real eigenvalues only")
            lam = root.real
            shifted = [[to_arb(m[i][j]) - (lam if i == j else 0) for j in range(size)] for i in range(size)]
            out.append((lam, [_adjugate_null(shifted)], [_adjugate_null([list(r) for r in zip(*shifted)])]))
    return out


def nullspace(m: list[list[Fraction]]) -> list[list[Fraction]]:
    rows, cols = len(m), len(m[0])
    r, rank = flint.fmpq_mat(rows, cols, [to_fmpq(x) for row in m for x in row]).rref()
    pivots, basis = [], []
    for i in range(rank):
        pivots.append(next(j for j in range(cols) if r[i, j] != 0))
    for free in (j for j in range(cols) if j not in pivots):
        v = [Fraction(0)] * cols
        v[free] = Fraction(1)
        for i, p in enumerate(pivots):
            v[p] = -to_fraction(r[i, free])
        basis.append(v)
    return basis


def _adjugate_null(m: list[list[arb]]) -> list[arb]:
    """A null vector of a rank-deficient 2 x 2 or 3 x 3 Arb matrix: its largest adjugate column."""
    size = len(m)
    if size == 2:
        cands = [[m[0][1], -m[0][0]], [m[1][1], -m[1][0]]]
    elif size == 3:
        cands = []
        for a, b in ((0, 1), (0, 2), (1, 2)):
            u, v = m[a], m[b]
            cands.append([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]])
    else:
        raise NotDiagonalizableError(f"irrational eigenvalues of a {size} x {size} rational block are not supported")
    best = max(cands, key=lambda c: sum(abs(float(x.mid())) for x in c))
    if all(x.contains(0) for x in best):
        raise NeedPrecision
    return best


def biorthogonal(right: list, left: list, scale) -> list:
    """Rescale the left basis so that ``scale * (left_i . right_j) = delta_ij`` (exact or Arb)."""
    if len(right) == 1:
        dot = sum((a * b for a, b in zip(left[0], right[0])), 0) * scale
        if isinstance(dot, arb) and dot.contains(0):
            raise NeedPrecision
        return [[y / dot for y in left[0]]]
    gram = flint.fmpq_mat(len(left), len(right), [to_fmpq(sum(a * b for a, b in zip(l_, r)) * scale) for l_ in left for r in right])
    g = gram.inv()
    coeff = [[to_fraction(g[i, k]) for k in range(len(left))] for i in range(len(left))]
    return [[sum((coeff[i][k] * left[k][c] for k in range(len(left))), Fraction(0)) for c in range(len(left[0]))] for i in range(len(left))]
