"""One Schur-Cohn polynomial's sign for every valence, exactly, or the valence that shows it fails.

The every-n proofs of the zoo (:mod:`symdecomp.verify.c1_zorin_every_n`, :mod:`symdecomp.verify.zorin_lambda_in_t`,
:mod:`symdecomp.verify.zorin_lambda_algebraic`) reduce "every root below ``lambda_1``" to finitely many polynomials in
``t = cos(2 pi k/n)`` (or rational functions of ``n`` at ``k = 0``) that must be positive on a half-open range.
:func:`decide_positive` shows it by Sturm sequences (:mod:`symdecomp.algebra.valence_signs`), or computes the witness:
a ``t`` in the range where the polynomial is not positive, and a valence ``n`` and frequency ``k`` whose ``t`` makes it
negative, certified in Arb (searched over :data:`WITNESS_SEARCH` valences from the first one the form holds at).
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.valence_signs import positive_from, sign_on_interval
from symdecomp.schemes.stencils import N
from symdecomp.verify.c1_every_n import T

__all__ = ["WITNESS_SEARCH", "Decision", "decide_positive"]


#: How far the search for a valence where a failed condition shows goes beyond the first valence of the form.
WITNESS_SEARCH = 64


@dataclass(frozen=True)
class Decision:
    """One Schur-Cohn polynomial's sign on its range: ``proved`` positive, ``failed`` (with a witness) or ``open``."""

    status: str
    #: The half-open range, or the witness ``t`` and valence, in words.
    note: str = ""
    #: A valence where the block has an eigenvalue of modulus ``>= lambda_1`` (certified), when one was found.
    n: int | None = None


def _arb_value(poly: sp.Poly, t: flint.arb) -> flint.arb:
    value = flint.arb(0)
    for c in poly.all_coeffs():
        value = value * t + flint.arb(to_fmpq(c))
    return value


def _search(poly: sp.Poly, start: int, frequency: int | None, reach: int) -> tuple[int, int] | None:
    """``(n, k)``: a valence ``n >= start`` and frequency ``k`` in the range whose ``t`` makes ``poly`` negative (Arb)."""
    with flint.ctx.workprec(128):
        for n in range(start, start + WITNESS_SEARCH):
            ks = range(reach + 1, n - reach) if frequency is None else (frequency,)
            for k in ks:
                t = flint.arb(flint.fmpq(2 * k, n)).cos_pi() if frequency is None else flint.arb(flint.fmpq(2, n)).cos_pi()
                if _arb_value(poly, t) < 0:
                    return n, k
    return None


def _search_mixed(expr: sp.Expr, start: int) -> int | None:
    """A valence ``n >= start`` where ``expr`` (in ``n`` and ``t``) is negative at ``t = cos(2 pi/n)`` (Arb)."""
    with flint.ctx.workprec(128):
        for n in range(start, start + WITNESS_SEARCH):
            if _arb_value(sp.Poly(sp.cancel(expr.subs(N, n)), T), flint.arb(flint.fmpq(2, n)).cos_pi()) < 0:
                return n
    return None


def _witness_t(poly: sp.Poly, low: sp.Expr) -> sp.Expr:
    """A ``t`` in ``[low, 1)`` where ``poly`` is not positive: a rational where one is found, else a root."""
    if poly.eval(low) <= 0:
        return low
    roots = [r for r in poly.real_roots() if low <= r < 1]
    for a, b in (iv for iv, _ in poly.intervals(eps=sp.Rational(1, 10**6))):
        for x in (sp.Rational(a), sp.Rational(b)):
            if low <= x < 1 and poly.eval(x) < 0:
                return x
    return roots[0]


def decide_positive(expr: sp.Expr, low: sp.Expr, *, start: int, frequency: int | None, reach: int) -> Decision:
    """``expr > 0`` for every ``t`` in ``[low, 1)`` (a polynomial in ``t``), or for every ``n >= start`` (a rational
    function of ``n``, at ``k = 0``), exactly; where it is not, the witness (module docstring)."""
    expr = sp.expand(expr)
    if expr.has(N):
        if expr.has(T):
            bad = _search_mixed(expr, start)
            return (Decision("failed", f"the Schur-Cohn polynomial {sp.factor(expr)} is negative at n = {bad}, t = "
                             f"cos(2 pi/{bad}) (Arb)", bad) if bad else Decision("open", f"{expr} mixes n and t"))
        if positive_from(expr, N, start):
            return Decision("proved")
        bad = next((n for n in range(start, start + WITNESS_SEARCH) if expr.subs(N, n) <= 0), None)
        return Decision("failed", f"{expr} <= 0 at n = {bad}" if bad else f"{expr} is not positive for every n >= {start}", bad)
    if expr == 0:  # a root exactly on the circle |x| = lambda_1 at every t: every valence is a witness
        k = reach + 1 if frequency is None else frequency
        return Decision("failed", f"the Schur-Cohn polynomial is 0 for every t: a root of modulus exactly lambda_1 at every "
                        f"n >= {start} (the first: n = {start}, k = {k})", start)
    poly = sp.Poly(expr, T)
    if sign_on_interval(expr, T, low, 1):
        return Decision("proved")
    if poly.eval(1) == 0 and poly.eval(low) > 0 and poly.count_roots(low, 1) == 1:
        return Decision("proved", f"one of them vanishes at t = 1 only, which no frequency reaches: positive on [{low}, 1)")
    t = _witness_t(poly, low)
    found = _search(poly, start, frequency, reach)
    where = (f"; at n = {found[0]}, k = {found[1]} (t = cos(2 pi {found[1] if frequency is None else 1}/{found[0]})) "
             "the Schur-Cohn polynomial is negative (Arb)" if found else
             f"; no valence n = {start}..{start + WITNESS_SEARCH - 1} has its t where it is negative")
    return Decision("failed", f"the Schur-Cohn polynomial {sp.factor(expr)} is {'negative' if poly.eval(t) < 0 else '0'} "
                    f"at t = {t}{where}", found[0] if found else None)
