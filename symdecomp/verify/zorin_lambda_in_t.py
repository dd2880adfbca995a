"""Zorin's spectral conditions for every valence when ``lambda_1`` depends on ``n``: ``lambda_1 = lambda(t)``, ``t = cos(2 pi/n)``.

The route of :mod:`symdecomp.verify.c1_zorin_every_n` reads ``p_k(x) = det(x I - B_k)`` from a primal zoo scheme's
structural blocks, with coefficients polynomials in ``t``. Where no root of ``p_1`` is the same for every ``n`` but a
factor of ``p_1`` is linear in ``x`` (sqrt(3): ``p_1 = x - (2 + 2 t)/9``), ``lambda_1(n) = lambda(t)`` at
``t = cos(2 pi/n)``, a rational function of ``t`` derived from that factor (never typed), and the steps become:

* ``lambda-one``: ``lambda(t)`` is the linear factor's root largest at ``t_0`` (a rational ``t_0 <= cos(2 pi/N0)``,
  :func:`~symdecomp.verify.c1_uniform.t_lower_bound`), real, with ``0 < lambda(t) < 1`` on ``[t_0, 1]`` (the signs of
  numerator and denominator by Sturm sequences);
* ``frequency-zero``, ``frequency-one``, ``frequency-exceptional``: the Schur-Cohn test on ``p(lambda(t) y)``
  (cleared of ``lambda``'s denominator), polynomials in ``t`` on ``[t_0, 1)``, as for a constant ``lambda_1``; the
  frequency-0 block's ``cos(2 pi q/n)`` read as ``T_q(t)``;
* ``other-frequencies`` (this module): at ``k = 2..n-2`` the block's ``t_k = cos(2 pi k/n)`` is *another* number than
  ``lambda_1``'s ``t``, with ``t_k < t``. Write ``p(x; s) = (x - lambda(s))^m r(x; s)``, ``s = t_k``. Where ``m > 0``:
  ``lambda`` increases on ``[-1, 1]`` (its derivative's numerator and denominator positive) and
  ``lambda(-1) + lambda(t_0) > 0``, so ``|lambda(s)| < lambda(t)`` for every ``-1 <= s < t``. The rest ``r``: every
  root below ``lambda(t_0)`` in modulus for every ``s`` in ``[-1, 1]`` (Schur-Cohn with that rational radius), and
  ``lambda(t) >= lambda(t_0)`` for ``t >= t_0`` (``lambda`` increasing on ``[t_0, 1]``).

A sign not shown in the last step leaves it ``open`` with the reason (the bound ``lambda(t_0)`` is only sufficient); a
Schur-Cohn polynomial of the exact steps that is negative gives a computed witness
(:func:`~symdecomp.verify.every_n_signs.decide_positive`).
"""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.schur_cohn import schur_cohn_conditions
from symdecomp.algebra.valence_signs import sign_on_interval
from symdecomp.errors import InvalidInputError
from symdecomp.verify.c1_every_n import EveryNStep, T

__all__ = ["linear_roots", "scaled_deltas", "varying_lambda_one", "other_frequencies_in_t"]

X = sp.Symbol("x")
S = sp.Symbol("s", real=True)  # cos(2 pi k/n) at another frequency, as printed


def linear_roots(p: sp.Expr) -> list[sp.Expr]:
    """The roots of the factors of ``p`` (in ``x``, coefficients in ``t``) that are linear in ``x``: rational in ``t``.

    >>> linear_roots(sp.expand((9 * X - 2 * T - 2) * (X**2 + 1)))
    [2*t/9 + 2/9]
    """
    out = []
    for f, _ in sp.factor_list(sp.expand(p), X)[1]:
        if sp.degree(f, X) == 1:
            a, b = sp.Poly(f, X).all_coeffs()
            out.append(sp.cancel(-b / a))
    return out


def _positive(expr: sp.Expr, low: sp.Expr, high: sp.Expr) -> bool:
    """A rational function of ``t`` positive on ``[low, high]``: numerator and denominator of one strict sign (Sturm)."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    try:
        return any(bool(sign_on_interval(sign * num, T, low, high)) and bool(sign_on_interval(sign * den, T, low, high))
                   for sign in (1, -1))
    except InvalidInputError:
        return False


def scaled_deltas(poly: sp.Expr, lam: sp.Expr) -> tuple[sp.Expr, ...]:
    """The Schur-Cohn polynomials of ``poly(lam y)``, ``lam = a/b`` rational in ``t`` and positive: of
    ``b^d poly((a/b) y)``, whose coefficients are polynomials in ``t`` (a positive multiple: the same roots)."""
    num, den = sp.fraction(sp.cancel(lam))
    p = sp.Poly(poly, X)
    d = p.degree()
    y = sp.Symbol("y")
    scaled = sp.expand(sum(c * num**j * den ** (d - j) * y**j for j, c in enumerate(reversed(p.all_coeffs()))))
    return schur_cohn_conditions(sp.Poly(scaled, y))


def varying_lambda_one(p1: sp.Expr, lam: sp.Expr, t0: sp.Expr, start: int) -> EveryNStep:
    """The ``lambda-one`` step for ``lambda_1 = lambda(t)`` (module docstring): in ``(0, 1)`` on ``[t_0, 1]``, or open."""
    where = (start, None)
    formulas = ((r"p_1(x)", p1), (r"\lambda_1(t)", lam))
    if not (_positive(lam, t0, 1) and _positive(1 - lam, t0, 1)):
        return EveryNStep(f"lambda_1 = {lam} at t = cos(2 pi/n), from det(x I - B_1) = {sp.factor(p1)}: not shown in (0, 1) "
                          f"for t in [{t0}, 1]", "open", where, "lambda-one", formulas)
    return EveryNStep(f"lambda_1 = {lam} at t = cos(2 pi/n): the root of det(x I - B_1) = {sp.factor(p1)} that is rational "
                      f"in t, largest at t = {t0} <= cos(2 pi/{start}); real, and in (0, 1) for t in [{t0}, 1] (Sturm "
                      "sequences)", "proved", where, "lambda-one", formulas)


def _split(other: sp.Expr, lam: sp.Expr) -> tuple[int, sp.Expr]:
    """``(m, r)``: ``other = (x - lam)^m r`` with ``r`` not divisible by ``x - lam`` (over ``Q(t)``)."""
    field = sp.QQ.frac_field(T)
    rest, factor = sp.Poly(other, X, domain=field), sp.Poly(X - lam, X, domain=field)
    m = 0
    while rest.degree() > 0:
        q, r = sp.div(rest, factor)
        if not r.is_zero:
            break
        rest, m = q, m + 1
    return m, sp.expand(sp.cancel(rest.as_expr()))


def other_frequencies_in_t(other: sp.Expr, lam: sp.Expr, t0: sp.Expr, start: int, reach: int) -> EveryNStep:
    """The ``other-frequencies`` step for ``lambda_1 = lambda(t)`` (module docstring): ``proved``, or ``open`` with the
    sign that was not shown."""
    name, where = "other-frequencies", (start, None)
    what = f"every other k ({reach + 1} <= k <= n - {reach + 1}, s = cos(2 pi k/n) < t = cos(2 pi/n))"
    m, rest = _split(other, lam)
    shown = sp.factor(sp.expand(other).subs(T, S))
    slope = sp.cancel(sp.diff(lam, T))
    low = sp.cancel(lam.subs(T, t0))
    formulas: list[tuple[str, object]] = [(r"p(x; s)", shown), (r"m", sp.Integer(m)), (r"r(x; s)", rest.subs(T, S)),
                                          (r"\lambda'(t)", slope), (r"\lambda(t_0)", low)]
    parts = []
    if m:
        if not (_positive(slope, -1, 1) and sp.cancel(lam.subs(T, -1) + low) > 0):
            return EveryNStep(f"{what}: det(x I - B) = {shown} has the root lambda(s) = {lam.subs(T, S)} but lambda is "
                              "not shown increasing on [-1, 1] with "
                              f"lambda(-1) + lambda({t0}) > 0", "open", where, name, tuple(formulas))
        times = "" if m == 1 else f" ({m} times)"
        parts.append(f"its root lambda(s) = {lam.subs(T, S)}{times} is below lambda(t) in modulus: lambda' = {slope} > 0 on [-1, 1] and "
                     f"lambda(-1) + lambda({t0}) = {sp.cancel(lam.subs(T, -1) + low)} > 0")
    if sp.degree(rest, X) > 0:
        deltas = schur_cohn_conditions(sp.Poly(rest, X), low) if low > 0 else ()
        formulas += [(rf"\delta_{{{j}}}(s)", d.subs(T, S)) for j, d in enumerate(deltas, 1)]
        increasing = m > 0 or _positive(slope, t0, 1)
        if not (deltas and increasing and all(_positive(d, -1, 1) for d in deltas)):
            return EveryNStep(f"{what}: det(x I - B) = {shown}: the roots of {rest.subs(T, S)} are not shown below "
                              f"lambda({t0}) = {low} for s in [-1, 1] (Schur-Cohn, Sturm), with lambda increasing on "
                              f"[{t0}, 1]", "open", where, name, tuple(formulas))
        parts.append(f"the roots of r = {rest.subs(T, S)} are below lambda({t0}) = {low} <= lambda(t) for every s in [-1, 1] (the "
                     f"{len(deltas)} Schur-Cohn polynomials positive; lambda increasing on [{t0}, 1])")
    if not parts:
        return EveryNStep(f"{what}: det(x I - B) = {shown} is constant", "proved", where, name, tuple(formulas))
    return EveryNStep(f"{what}: det(x I - B) = {shown}; " + "; ".join(parts), "proved", where, name,
                      tuple(formulas))
