"""An analytic tail bound for Proposition 5.1: ``lambda_1(n) > |mu(n)|`` for every ``n >= N0``.

``lambda_1(n)`` is the dominant eigenvalue of ``M_1``, a function of ``c = cos(pi/n)``; ``mu(n)`` are the
eigenvalues of the Eq. 43 block other than 1, the roots of a quadratic ``q(lambda)`` with coefficients
rational in ``n``. The argument, exact throughout:

1. ``cos x >= 1 - x^2/2`` and ``pi^2/2 < 5`` give ``c >= c_lo = 1 - 5/n^2 > 0``; where the dominant
   eigenvalue increases with ``c > 0`` (checked by the caller), ``lambda_1(n) >= dominant(c_lo)``.
2. ``P(lambda) = lambda^2 - tr(c_lo) lambda + det(c_lo)`` is negative strictly between its roots, so
   ``P(rho) < 0`` gives ``rho < dominant(c_lo)``.
3. For ``rho`` the largest root of ``q(lambda)`` and of ``q(-lambda)`` (so ``rho`` covers ``mu`` and ``-mu``),
   ``P(rho) = r1 rho + r0`` (the remainder of ``P`` modulo the quadratic) and the sign of ``r1 rho + r0`` is
   decided by comparing ``rho`` with the rational ``-r0/r1``: the sign of the quadratic there and of its
   vertex. A root at most 0 is below ``lambda_1 > 0`` already.

Every comparison is the sign of a rational function of ``n``, constant beyond the largest real root of its
numerator and denominator (isolated exactly by ``Poly.intervals``). ``N0`` is the first integer beyond all of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from symdecomp.analysis.frequency import recursion_matrix
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import cos_jtheta, n
from symdecomp.symbols import lam as LAM

__all__ = ["TailBound", "tail_bound"]

#: The lower bound for ``cos(pi/n)`` used beyond ``N0``.
COS_LOWER = 1 - sp.Integer(5) / n**2


@dataclass(frozen=True)
class TailBound:
    """``lambda_1(n) > |mu(n)|`` for every ``n >= start``; ``facts`` are the rational functions shown positive there."""

    start: int
    facts: tuple[sp.Expr, ...]


# Private control flow, not an error of the package: stops the search for an eventual sign and is
# caught inside this module.
class _Undecided(Exception):
    pass


def _eventual_sign(expr: sp.Expr, facts: list, starts: list) -> int:
    """The sign of ``expr`` (rational in ``n``) for all large ``n``; records where it is constant."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    sign = 1
    for part in (num, den):
        poly = sp.Poly(part, n)
        if poly.is_zero:
            raise _Undecided("a comparison is identically zero")
        roots = [iv[1] for (iv, _) in poly.intervals()] if poly.degree() > 0 else []
        starts.append(math.floor(max(roots, default=0)) + 1)
        sign *= 1 if poly.LC() > 0 else -1
    facts.append(sp.cancel(sign * expr))
    return sign


def _largest_root_below_dominant(quadratic: sp.Poly, P: tuple,  facts: list, starts: list) -> None:
    a2, a1, a0 = quadratic.all_coeffs()
    if _eventual_sign(a1**2 - 4 * a2 * a0, facts, starts) < 0:
        raise _Undecided("the Eq. 43 eigenvalues are not real for large n")
    vertex = -a1 / (2 * a2)
    if _eventual_sign(a2 * a0, facts, starts) > 0 and _eventual_sign(-vertex, facts, starts) > 0:
        return  # both roots negative: the largest one is below lambda_1 > 0
    _, p1, p0 = P  # P is monic: P - quadratic/a2 is the remainder r1*lambda + r0
    r1, r0 = sp.cancel(p1 - a1 / a2), sp.cancel(p0 - a0 / a2)
    if r1 == 0:
        raise _Undecided("the remainder of the characteristic polynomial is constant")
    u = -r0 / r1
    at_u = a2 * quadratic.as_expr().subs(LAM, u)
    if _eventual_sign(r1, facts, starts) > 0:  # need rho < u: the quadratic positive at u, u right of the vertex
        ok = _eventual_sign(at_u, facts, starts) > 0 and _eventual_sign(u - vertex, facts, starts) > 0
    else:  # need rho > u: the quadratic negative at u, or u left of the vertex
        ok = _eventual_sign(at_u, facts, starts) < 0 or _eventual_sign(vertex - u, facts, starts) > 0
    if not ok:
        raise _Undecided("an Eq. 43 eigenvalue is not below the lower bound of lambda_1")


def tail_bound(scheme: Scheme) -> TailBound | None:
    """The tail bound for ``scheme`` (mirror-symmetric, no parameters), or ``None`` where the argument does not apply."""
    ev = tangent_eigenvalues(scheme)
    P = tuple(sp.cancel(c) for c in sp.Poly(ev.characteristic_polynomial.subs(cos_jtheta, COS_LOWER), LAM).all_coeffs())
    charpoly = sp.Poly(recursion_matrix(scheme).charpoly(LAM).as_expr(), LAM)
    quotient, remainder = sp.div(charpoly, sp.Poly(LAM - 1, LAM))
    if sp.cancel(remainder.as_expr()) != 0 or quotient.degree() != 2:
        return None
    q = sp.Poly([sp.cancel(c) for c in quotient.all_coeffs()], LAM)
    if len(P) != 3 or P[0] != 1 or not set().union(*(sp.sympify(c, strict=True).free_symbols for c in (*P, *q.all_coeffs()))) <= {n}:
        return None
    facts: list = []
    starts: list = [3]
    try:
        for quadratic in (q, sp.Poly(q.as_expr().subs(LAM, -LAM), LAM)):
            _largest_root_below_dominant(quadratic, P, facts, starts)
    except _Undecided:
        return None
    return TailBound(max(starts), tuple(facts))
