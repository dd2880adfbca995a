"""A null vector of a ball matrix, certified: the one solve behind eigenvectors and left eigenvectors in Arb.

At an eigenvalue ``lambda`` of geometric multiplicity one, ``A = M - lambda I`` has rank ``m - 1``; given as a
matrix of Arb balls around it (the eigenvalue itself a ball), ``A`` is not singular to the machine, so its
null vector is found by fixing one coordinate to 1 and solving the other ``m - 1`` from ``m - 1`` of the rows
(a square ball solve, which fails loudly, with ``ZeroDivisionError``, when it cannot certify the solution).
A left null vector (``y A = 0``) is the null vector of ``A``'s transpose.

>>> import flint
>>> A = flint.acb_mat([[1, -1], [2, -2]])
>>> [str(x) for x in null_vector(A)]
['1.00000000000000', '1.00000000000000']
"""

from __future__ import annotations

import itertools

import flint

__all__ = ["null_vector"]


def null_vector(A: flint.acb_mat, first: int | None = None) -> list[flint.acb] | None:
    """A vector ``x`` with one coordinate 1 and ``A x`` a ball around 0, or ``None`` (no square subsystem is solvable,
    or the row left out does not hold: ``A`` is certainly not singular).

    The coordinate set to 1 is ``first`` if given (e.g. the one a caller normalizes by), else the first that works;
    for each, the row left out is the same index first, then the others in order.
    """
    m = A.nrows()
    if m == 1:
        return [flint.acb(1)]
    columns = [first] + [j for j in range(m) if j != first] if first is not None else list(range(m))
    for j, i in itertools.chain.from_iterable(((j, i) for i in [j] + [r for r in range(m) if r != j]) for j in columns):
        rows = [r for r in range(m) if r != i]
        others = [c for c in range(m) if c != j]
        try:
            x = flint.acb_mat([[A[r, c] for c in others] for r in rows]).solve(flint.acb_mat([[-A[r, j]] for r in rows]))
        except ZeroDivisionError:
            continue
        vec = [flint.acb(0)] * m
        vec[j] = flint.acb(1)
        for t, c in enumerate(others):
            vec[c] = x[t, 0]
        # the row left out holds too only if A is singular (rank m - 1) somewhere in its balls
        return vec if sum((A[i, c] * vec[c] for c in range(m)), flint.acb(0)).contains(0) else None
    return None
