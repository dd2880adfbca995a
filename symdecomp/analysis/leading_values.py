"""The leading eigenvalues of a boundary, crease or corner vertex from its blocks, in O(log k) per vertex.

Zorin's test at a sharp vertex (:mod:`symdecomp.verify.c1_mirror_blocks`) reads only the largest eigenvalues: ``1``,
``lambda_1``, ``lambda_2`` and a bound of all the others. :func:`~symdecomp.analysis.block_values.structural_values`
gives every value (O(k) blocks); here the crease block, the last modes and the sine blocks ``j <= head`` are read
exactly as there (equal values joined exactly), and the sine blocks ``j > head`` are bounded together. Their eigenvalues
are the roots of ``x^2 - t(c) x + d(c)`` (the block's trace and determinant, polynomials in ``c = cos(pi j/k)`` and
``c_k = cos(pi/k)``) for ``c`` in ``[-1, cos(pi (head + 1)/k)]``, and every root of such a quadratic with real ``t, d``
has ``|x| <= |t|/2 + sqrt(|t^2/4 - d|)``: for real roots this is the larger root's modulus; for complex ones
``|x| = sqrt(d) = sqrt(a^2 + b^2) <= a + b`` with ``a = |t|/2``, ``b = sqrt(d - a^2)``. On 1 x 1 blocks (triangles) the
value is ``t`` itself. The bound is evaluated in Arb on pieces of the interval, bisected until each piece's bound is
below the target (the head's ``|lambda_2|``) or a budget of pieces is spent: near ``c = 1`` the pieces shrink like
``1/k^2``, so the work grows like ``log k``, not ``k``.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> lead = leading_values(catmull_clark(), SharpVertex.boundary(1000, "quad"))
>>> [v.exact for v in lead.values[:2]], bool(lead.tail < abs(lead.values[2].ball))
(['1', '(t + sqrt(t**2 - 4*d))/2 with t = c/8 + 5/8, d = 1/16, c = cos(pi/1000)'], True)
"""

from __future__ import annotations

from dataclasses import dataclass

import flint

from symdecomp.analysis.block_values import block_values, checked_polynomials, eval_arb, layout, poly_terms
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.schemes.scheme import check_scheme

__all__ = ["LeadingValues", "leading_values", "HEAD", "MAX_PIECES"]

#: Sine blocks read exactly (``j = 1..HEAD``): the subdominant ones of every scheme tried are ``j = 1, 2``.
HEAD = 3
#: Most pieces of ``c`` the tail's bound is evaluated on, per sector.
MAX_PIECES = 512


@dataclass(frozen=True)
class LeadingValues:
    """The largest eigenvalues of a sharp vertex's one-step matrix and a bound of the others."""

    #: The distinct eigenvalues of the crease block, the last modes and the sine blocks ``j <= head``, largest first.
    values: tuple[Eigenvalue, ...]
    #: An upper bound (``flint.arb``, exact) of the modulus of every other eigenvalue; ``None`` when there is none.
    tail: object
    #: The sine blocks read exactly are ``j = 1..head``.
    head: int


def _target(values: list[Eigenvalue]):
    """The lower bound of ``|lambda_2|``: the third modulus counted with multiplicity (after ``1``), else 0."""
    moduli = [abs(v.ball).lower() for v in values for _ in range(v.multiplicity)]
    return flint.arb(moduli[2]) if len(moduli) > 2 else flint.arb(0)


def _piece_bound(terms: tuple, quad: bool, c, ck):
    t = eval_arb(terms[0], c, ck)
    bound = abs(t) if not quad else abs(t) / 2 + abs(t * t / 4 - eval_arb(terms[1], c, ck)).sqrt()
    return flint.arb(bound.upper())


def tail_bound(polys: tuple, k: int, head: int, target, prec: int = 128):
    """An upper bound of ``|x|`` over the eigenvalues of the sine blocks ``j = head+1..k-1`` of a sector of ``k`` faces
    (module docstring), refined until it is below ``target`` or :data:`MAX_PIECES` pieces are spent."""
    tr, det, quad = polys
    terms = (poly_terms(tr, k), poly_terms(det, k))
    with flint.ctx.workprec(prec):
        ck = flint.arb.cos_pi_fmpq(flint.fmpq(1, k))
        top = flint.arb(flint.arb.cos_pi_fmpq(flint.fmpq(head + 1, k)).upper())
        pieces, worst, spent = [(flint.arb(-1), top)], flint.arb(0), 0
        while pieces:
            lo, hi = pieces.pop()
            bound = _piece_bound(terms, quad, lo.union(hi), ck)
            spent += 1
            if bound < target or spent >= MAX_PIECES:
                worst = bound if bound > worst else worst
                continue
            mid = flint.arb(((lo + hi) / 2).mid())
            pieces += [(lo, mid), (mid, hi)]
    return worst


def leading_values(scheme, vertex, *, head: int = HEAD, prec: int = 256) -> LeadingValues:
    """The leading eigenvalues of a boundary, crease or corner vertex (module docstring); refused
    (:class:`~symdecomp.errors.NotApplicableError`) where :func:`~symdecomp.analysis.block_values.structural_values` is."""
    scheme = check_scheme(scheme)
    lay = layout(scheme, vertex)
    values = block_values(scheme, lay, prec, head)
    target, tail = _target(values), None
    for k in lay.sectors:
        if k - 1 > head:
            bound = tail_bound(checked_polynomials(scheme), k, head, target)
            tail = bound if tail is None or bound > tail else tail
    return LeadingValues(tuple(values), tail, head)
