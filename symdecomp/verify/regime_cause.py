"""The hyperbolic cause of unbounded curvature for every valence on quads: frequency 0 below frequency 2, in ``n``.

On quads (``M`` is ``2 x 2``) the hyperbolic eigenvalue is ``lambda_2 = rho(cos(4 pi/n))``, ``rho = (tr + sqrt(disc))/2``
the dominant eigenvalue of ``M(t)``, increasing in ``t`` (step S3 of :mod:`symdecomp.verify.c1_every_n`). The
frequency-0 eigenvalues besides 1 are the roots of ``q(x) = det(x I - E_0)/(x - 1) = x^2 + b(n) x + c(n)``, rational
in ``n`` (the vertex rule). Catmull-Clark's meet ``lambda_2`` as ``n -> oo`` (at ``(3 + sqrt(5))/8``), but from
different sides and at different rates (``1/n`` against ``1/n^2``), so a bound on ``cos`` that is exact to order
``1/n^2`` separates them:

* ``cos x >= 1 - x^2/2`` and ``pi < 22/7`` give ``cos(4 pi/n) >= t_n = 1 - 8 (22/7)^2 / n^2``, so
  ``lambda_2 >= r_n = rho(t_n)`` (``t_n >= -1``);
* both roots of ``q`` have modulus below ``r_n`` exactly when ``|c| < r_n^2`` and ``q(r_n) > 0 < q(-r_n)`` (the Jury
  conditions of a real quadratic); ``r_n`` above the outer ring's eigenvalues too;
* each condition, reduced by ``r^2 = tr r - det``, is ``U(n) + V(n) sqrt(D(n))`` with rational functions ``U``, ``V``,
  ``D`` (``D = disc(t_n)``): positive when ``U, V > 0``, or ``U > 0 > V`` and ``U^2 - V^2 D > 0``, or ``V > 0 > U`` and
  ``V^2 D - U^2 > 0``, each for every ``n >= start`` (:func:`~symdecomp.algebra.valence_signs.positive_from`, ``start``
  past the real roots of every numerator and denominator).

The valences between the regime's first unbounded one and ``start`` are certified one by one
(:func:`~symdecomp.verify.second_order_spectrum.second_order_eigenstructure`: the cause is the hyperbolic part).
"""

from __future__ import annotations

import functools

import sympy as sp
from sympy.polys.polyerrors import BasePolynomialError

from symdecomp.algebra.valence_signs import positive_from
from symdecomp.analysis.characteristic import outer_charpoly
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence
from symdecomp.verify.c1_every_n import EveryNStep, T, laurent_in_t

__all__ = ["frequency_zero_below_hyperbolic", "hyperbolic_cause_on_quads"]

#: Valences certified one by one at most, between the regime's first unbounded valence and the exact argument's start.
MAX_CERTIFIED = 200


def _start(exprs) -> int:
    """A valence past every real root of the numerators and denominators of ``exprs`` (rational functions of ``n``)."""
    roots = [r for e in exprs for part in sp.fraction(sp.cancel(e)) for r in sp.Poly(part, N).real_roots()
             if sp.Poly(part, N).degree() > 0]
    return max(3, int(sp.floor(max(roots, default=0))) + 1)


def _nonzero(e) -> bool:
    """Whether ``e`` is not zero: a rational function of ``n`` over ``Q`` is zero when ``cancel`` makes it so; any other
    expression is left to ``simplify``."""
    numerator, _ = sp.fraction(sp.cancel(e))
    try:
        return not sp.Poly(numerator, N, domain=sp.QQ).is_zero
    except BasePolynomialError:
        return sp.simplify(e) != 0


def _root_sign(U, V, D, start: int) -> bool:
    """``U + V sqrt(D) > 0`` for every ``n >= start`` (module docstring)."""
    pos = lambda e: _nonzero(e) and positive_from(sp.cancel(e), N, start)  # noqa: E731
    if sp.cancel(V) == 0:
        return pos(U)
    square = sp.cancel(U**2 - V**2 * D)
    return (pos(U) and pos(V)) or (pos(U) and pos(-V) and pos(square)) or (pos(V) and pos(-U) and pos(-square))


def frequency_zero_below_hyperbolic(scheme: Scheme) -> tuple[int, str] | None:
    """``(start, how)``: for every ``n >= start`` the frequency-0 eigenvalues besides 1, and the outer ring's, are smaller
    in modulus than ``lambda_2``; ``None`` where not shown (not quads, rules in ``n`` beyond the vertex rule, a vertex rule
    that is not rational in ``n``, such as one with ``cos(2 pi/n)``)."""
    M, E0 = (sp.Matrix(m) for m in one_ring_matrices(scheme))
    x = sp.Symbol("x")
    if M.rows != 2 or M.has(N) or scheme.parameters:
        return None
    q, rest = sp.div(sp.Poly(E0.charpoly(x).as_expr(), x), sp.Poly(x - 1, x))
    if not rest.is_zero or q.degree() != 2 or q.as_expr().free_symbols - {x, N}:
        return None
    _, b, c = (sp.cancel(k / q.LC()) for k in q.all_coeffs())
    if not all(e.is_rational_function(N) for e in (b, c)):  # e.g. cos(2 pi/n) in the vertex rule: no signs in n here
        return None
    t_n = 1 - 8 * sp.Rational(22, 7) ** 2 / N**2
    tr, det = (laurent_in_t(f).subs(T, t_n) for f in (M.trace(), M.det()))
    D = sp.cancel(tr**2 - 4 * det)
    radius = max((abs(r) for r in sp.Poly(list(outer_charpoly(scheme.lattice)), x).all_roots()), key=float)
    # r^2 = tr r - det: each condition as U + V r, then r = (tr + sqrt(D))/2
    conditions = {"r^2 - c": (-det - c, tr), "r^2 + c": (c - det, tr), "q(r)": (c - det, tr + b),
                  "q(-r)": (c - det, tr - b), "r - radius": (-radius, sp.Integer(1))}
    split = {k: (sp.cancel(u + v * tr / 2), sp.cancel(v / 2)) for k, (u, v) in conditions.items()}
    exprs = [e for u, v in split.values() for e in (u, v, u**2 - v**2 * D)] + [D, t_n + 1]
    start = _start(exprs)
    if not (positive_from(D, N, start) and positive_from(t_n + 1, N, start)):
        return None
    if not all(_root_sign(u, v, D, start) for u, v in split.values()):
        return None
    how = (f"for n >= {start} the roots of q(x) = {sp.factor(q.as_expr() / q.LC())} (frequency 0 besides 1) and the outer "
           f"ring's eigenvalues ({radius} at most) are smaller in modulus than r_n = rho(t_n) <= lambda_2, t_n = {t_n} "
           "<= cos(4 pi/n): |c| < r_n^2, q(r_n) > 0 and q(-r_n) > 0, each U + V sqrt(D) with rational functions of n "
           "(signs for every n >= " + str(start) + ")")
    return start, how


def hyperbolic_cause_on_quads(scheme: Scheme, first: int) -> EveryNStep | None:
    """For every ``n >= first`` the largest eigenvalue after 1 and ``lambda_1`` is the hyperbolic one (quads): exact from
    :func:`frequency_zero_below_hyperbolic`'s start, certified per valence before it; ``None`` where not shown. Computed
    once per ``(scheme, first)``: the curvature regime's claim and the shape's
    (:mod:`symdecomp.verify.dominance_every_n`) ask the same in one worker."""
    return _cause_on_quads(check_scheme(scheme), check_valence(first, argument="first"))


@functools.lru_cache(maxsize=16)  # private: the public function checks the arguments before the lookup
def _cause_on_quads(scheme: Scheme, first: int) -> EveryNStep | None:
    from symdecomp.verify.c1_every_n import spectral_every_n
    from symdecomp.verify.second_order_spectrum import second_order_eigenstructure

    shown = frequency_zero_below_hyperbolic(scheme)
    if shown is None or shown[0] - first > MAX_CERTIFIED:
        return None
    start, how = shown
    if not all(step.status == "proved" for step in spectral_every_n(scheme)[:2]):  # rho increasing, the other roots smaller
        return None
    below = range(first, start)
    if any(second_order_eigenstructure(scheme, k).cause != "hyperbolic" for k in below):
        return None
    certified = f"; at n = {first}..{start - 1} certified one by one (Arb balls)" if len(below) else ""
    return EveryNStep(f"for every n >= {first} the hyperbolic eigenvalue is the largest after 1 and lambda_1: rho(t) "
                      f"increases with t (frequencies 3..n-3 are below frequency 2), and {how}{certified}", "proved",
                      (first, None))
