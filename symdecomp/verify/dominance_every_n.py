"""Which second-order part dominates on fine rings, for every valence: the hyperbolic one from a valence on.

On ring ``m`` near an extraordinary vertex the elliptic (frequency 0) and hyperbolic (frequency 2) parts of generic
input scale like ``mu_0^m`` and ``mu_2^m``, ``mu_j`` the largest eigenvalue of frequency ``j`` after 1 and ``lambda_1``
(:func:`~symdecomp.verify.second_order_spectrum.dominant_part` at one valence). "The hyperbolic part dominates for every
``n >= first``" is proved here as: for every such ``n`` the hyperbolic eigenvalue ``lambda_2`` (frequencies 2 and
``n - 2``) exceeds in modulus every eigenvalue after 1 and ``lambda_1``: the frequency-0 ones, the other frequencies'
and the outer ring's. What is reused, and what is new:

* the other frequencies: ``lambda_2`` is the dominant eigenvalue of ``M(t)`` at ``t = cos(4 pi/n)``, which increases
  with ``t`` (steps S1-S3 of :func:`~symdecomp.verify.c1_every_n.spectral_every_n`, Sturm sequences in ``t``), so the
  frequencies ``3..n-3`` (``t`` smaller) are below it, and the other root of ``M`` is smaller in modulus;
* on quads (``M`` is ``2 x 2``) the frequency-0 roots and the outer ring's eigenvalues against ``lambda_2``, by a bound
  on the cosine that is exact to order ``1/n^2`` (``cos(4 pi/n) >= 1 - 8 (22/7)^2/n^2``) and signs of rational
  functions of ``n``, certified one valence at a time below the start of those signs:
  :func:`~symdecomp.verify.regime_cause.hyperbolic_cause_on_quads`, reused as it is (it does not assume the regime);
* on triangles (``M`` is ``1 x 1``, ``lambda(t)`` a polynomial) the frequency-0 eigenvalue besides 1, ``e_0 = tr E_0 -
  1``, derived from the vertex rule: where it is a function of ``s = cos(2 pi/n)`` alone (Loop's weight makes it
  ``lambda_1^2``, so the comparison is the regime's ``lambda_2 > lambda_1^2``), ``lambda(2 s^2 - 1) -+ e_0 > 0`` and
  ``lambda(2 s^2 - 1)`` above the outer ring on ``[s_0, 1]`` by Sturm sequences (``s_0`` a rational just below
  ``cos(2 pi/first)``); where it is a rational function of ``n`` alone, the quads' bound on the cosine and signs in
  ``n``, with the valences below the signs' start certified one by one.

Anything else (rules in ``n`` beyond the vertex rule, a frequency-0 eigenvalue mixing ``n`` and ``cos(2 pi/n)``, a
sign that fails) leaves the step ``open``, with the reason.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.algebraic_sign import rational_between
from symdecomp.algebra.valence_signs import positive_from, sign_on_interval
from symdecomp.analysis.characteristic import outer_charpoly
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.verify.c1_every_n import EveryNStep, T, laurent_in_t, tangent_steps
from symdecomp.verify.regime_cause import MAX_CERTIFIED, _start, hyperbolic_cause_on_quads

__all__ = ["hyperbolic_dominates_from"]

S = sp.Symbol("s", real=True)  # cos(2 pi/n)


def hyperbolic_dominates_from(scheme: Scheme, first: int) -> EveryNStep:
    """For every ``n >= first`` the hyperbolic eigenvalue exceeds every eigenvalue after 1 and ``lambda_1``, the
    frequency-0 ones among them: a ``proved`` step, or an ``open`` one saying why not (module docstring)."""
    check_scheme(scheme)
    M, E0 = (sp.Matrix(m) for m in one_ring_matrices(scheme))
    if M.has(N) or scheme.parameters:
        return _open(first, "the 1-ring's rules other than the vertex rule depend on n, or the scheme has free parameters")
    try:
        if M.rows == 2:
            if not all(_rational(e) for e in E0):
                return _open(first, "E_0 is not a rational function of n (the bound in n needs one)")
            step = hyperbolic_cause_on_quads(scheme, first)
            return step if step is not None else _open(first, (
                "the frequency-0 roots are not shown below rho(1 - 8 (22/7)^2/n^2) for every n from a start at most "
                f"{MAX_CERTIFIED} past {first}, or a valence before that start is not certified hyperbolic"))
        if M.rows == 1 and E0.rows == 2:
            return _on_triangles(scheme, first, M, E0)
    except NotApplicableError as error:
        return _open(first, str(error))
    return _open(first, f"a {M.rows} x {M.rows} block M with a {E0.rows} x {E0.rows} block E_0 has no argument for every n")


def _rational(expr: sp.Expr) -> bool:
    """Whether ``expr`` is a rational function of ``n`` alone (no cosine of ``n``, no other symbol)."""
    return bool(sp.sympify(expr, strict=True).free_symbols <= {N} and sp.cancel(expr).is_rational_function(N))


def _open(first: int, why: str) -> EveryNStep:
    return EveryNStep(f"for n >= {first} the hyperbolic part is not shown to dominate for every n: {why}", "open",
                      (first, None))


def _beyond(expr: sp.Expr, first: int) -> sp.Expr | None:
    """``expr`` for ``n >= first``: the pieces of a vertex rule given at single small valences (``Eq(n, k)``, ``k <
    first``) dropped; ``None`` when a piece's condition is anything else."""
    def piece(*args: sp.Basic) -> sp.Expr:
        for value, condition in args:
            if condition is sp.true:
                return sp.sympify(value, strict=True)
            if not (isinstance(condition, sp.Eq) and set(condition.args) - {N} and condition.has(N)
                    and all(a == N or (a.is_Integer and a < first) for a in condition.args)):
                raise NotApplicableError(f"the vertex rule's piece for {condition} is not one small valence")
        raise NotApplicableError("the vertex rule has no piece for every n")

    try:
        return expr.replace(lambda e: isinstance(e, sp.Piecewise), lambda e: piece(*e.args))
    except NotApplicableError:
        return None


def _on_triangles(scheme: Scheme, first: int, M: sp.Matrix, E0: sp.Matrix) -> EveryNStep:
    """Triangles: ``lambda(t)`` increasing, ``lambda_2`` above the outer ring and above ``|e_0|`` (module docstring)."""
    lam, x, outer = laurent_in_t(M[0, 0]), sp.Symbol("x"), outer_charpoly(scheme.lattice)
    if outer is None:
        return _open(first, "the outer ring's eigenvalues are not known for this lattice")
    radius = max((abs(r) for r in sp.Poly(list(outer), x).all_roots()), key=float)
    # S1-S4 of spectral_every_n; its S5 (E_0 below lambda_1) is not needed: e_0 < lambda_2 < lambda_1 is shown below
    if not all(step.status == "proved" for step in tangent_steps(M, radius)):
        return _open(first, "the tangent steps (lambda(t) increasing, lambda_1 below 1 and above the outer ring) are not proved")
    e0 = _beyond(sp.expand(E0.trace() - 1), first)  # E_0 is 2 x 2 with the eigenvalue 1
    if e0 is None:
        return _open(first, "the vertex rule is piecewise in n beyond single small valences")
    e0 = sp.expand(e0.subs(sp.cos(2 * sp.pi / N), S))
    s0 = rational_between(sp.cos(2 * sp.pi / first) - sp.Rational(1, 10**4), sp.cos(2 * sp.pi / first))
    lam2 = sp.expand(lam.subs(T, 2 * S**2 - 1))
    head = f"for every n >= {first} the hyperbolic eigenvalue is the largest after 1 and lambda_1: lambda(t) = {lam} " \
           "increases with t (frequencies 3..n-3 are below), "
    if not sign_on_interval(lam2 - radius, S, s0, 1):
        return _open(first, f"lambda_2 = {lam2} is not above the outer ring's {radius} for s = cos(2 pi/n) in [{s0}, 1]")
    if not e0.has(N):
        if not (sign_on_interval(lam2 - e0, S, s0, 1) and sign_on_interval(lam2 + e0, S, s0, 1)):
            return _open(first, f"lambda_2 = {lam2} > |e_0| = |{e0}| is not shown for s = cos(2 pi/n) in [{s0}, 1] (Sturm)")
        return EveryNStep(head + f"lambda_2 = {lam2} exceeds the outer ring's {radius} and |e_0|, e_0 = {e0} the "
                          f"frequency-0 eigenvalue besides 1, for s = cos(2 pi/n) in [{s0}, 1] (Sturm sequences)",
                          "proved", (first, None))
    if e0.has(S) or not _rational(e0):
        return _open(first, f"the frequency-0 eigenvalue {e0} is neither a polynomial in s = cos(2 pi/n) nor rational in n")
    return _rational_in_n(scheme, first, lam, e0, head)


def _rational_in_n(scheme: Scheme, first: int, lam: sp.Expr, e0: sp.Expr, head: str) -> EveryNStep:
    """``e_0`` rational in ``n``: ``lambda_2 >= lambda(t_n)``, ``t_n = 1 - 8 (22/7)^2/n^2 <= cos(4 pi/n)``, against
    ``|e_0|`` by signs in ``n`` from their start; the valences from ``first`` to that start certified one by one."""
    from symdecomp.verify.second_order_spectrum import second_order_eigenstructure

    t_n = 1 - 8 * sp.Rational(22, 7) ** 2 / N**2
    r = sp.cancel(lam.subs(T, t_n))
    signs = [sp.cancel(r - e0), sp.cancel(r + e0), sp.cancel(t_n + 1)]
    start = max(first, _start(signs))
    if start - first > MAX_CERTIFIED or not all(positive_from(e, N, start) for e in signs):
        return _open(first, f"lambda(t_n) > |e_0| = |{e0}| is not shown for every n from a start at most {MAX_CERTIFIED} "
                     f"past {first}")
    below = range(first, start)
    if any(second_order_eigenstructure(scheme, k).cause != "hyperbolic" for k in below):
        return _open(first, f"a valence of {first}..{start - 1} is not certified hyperbolic")
    certified = f"; at n = {first}..{start - 1} certified one by one (Arb balls)" if len(below) else ""
    return EveryNStep(head + f"and for n >= {start} lambda_2 >= lambda(t_n) = {r} exceeds |e_0| = |{e0}|, t_n = {t_n} <= "
                      f"cos(4 pi/n) (signs of rational functions of n){certified}", "proved", (first, None))
