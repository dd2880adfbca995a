"""Zorin's spectral conditions for every valence when ``lambda_1`` is a constant algebraic number, not a rational.

The route of :mod:`symdecomp.verify.c1_zorin_every_n` reads ``p_1(x) = det(x I - B_1)`` from a primal zoo scheme's
structural blocks. Where the largest root of ``p_1`` is a root of a factor of degree ``>= 2`` with rational
coefficients (independent of ``t = cos(2 pi/n)``: the same number at every ``n``), ``lambda_1`` is that root, derived
from the factor (never typed) and kept exact as a root of its minimal polynomial ``m`` over ``Q``, with an isolating
Arb ball from FLINT's certified roots of ``m``. The steps then run in ``Q(lambda_1)``:

* ``lambda-one``: ``lambda_1`` real, in ``(0, 1)`` (its ball, refined until it decides);
* the Schur-Cohn test with radius ``lambda_1``: ``p(lambda_1 y)`` has coefficients in ``Q[t][lambda_1]``; each
  ``delta_j`` is reduced modulo ``m(lambda_1)``, so it is ``0`` exactly when its reduction is the zero polynomial
  (``m`` is irreducible over ``Q``, hence over ``Q(t)``); at ``k = +-1`` ``p_k`` is first divided by
  ``x - lambda_1`` in ``Q[t][lambda_1][x]``, which leaves the conjugates of ``lambda_1`` among the roots to compare;
* a sign of ``delta(t, lambda_1)`` on ``[t_0, 1)``: where ``delta`` does not depend on ``t`` it is a number of
  ``Q(lambda_1)``, nonzero unless its reduction is ``0``, and its sign is that of its Arb ball once the ball excludes
  ``0`` (raising the precision, which ends for a nonzero number); where it does, the norm
  ``N(t) = Res_lambda(m(lambda), delta(t, lambda))`` (a polynomial over ``Q``) vanishes wherever ``delta(t, lambda_1)``
  does, so without a root of ``N`` in ``[t_0, 1)`` (Sturm) the sign on the range is the sign at ``t_0``.

A ``delta`` that is negative gives a witness valence from Arb at ``t = cos(2 pi k/n)``; a sign not shown otherwise
leaves the step ``open`` with the reason. A factor of degree ``>= 2`` whose coefficients depend on ``t`` is not
handled here: where one holds the largest root the ``lambda-one`` step says so and stays ``open``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.schur_cohn import schur_cohn_conditions
from symdecomp.errors import PrecisionError
from symdecomp.schemes.stencils import N
from symdecomp.verify.c1_every_n import EveryNStep, T
from symdecomp.verify.every_n_signs import WITNESS_SEARCH

__all__ = ["LAMBDA", "AlgebraicRadius", "algebraic_radius", "constant_roots", "field_deltas", "field_positive",
           "higher_factors_in_t", "larger_in_t", "algebraic_lambda_one"]

X = sp.Symbol("x")
#: ``lambda_1`` as it appears in the reduced Schur-Cohn polynomials (a polynomial in it of degree below ``m``'s).
LAMBDA = sp.Symbol("lambda_1", positive=True)
#: The highest precision (bits) tried before a sign in ``Q(lambda_1)`` is reported as not separated.
MAX_BITS = 1 << 12


@dataclass(frozen=True)
class AlgebraicRadius:
    """``lambda_1`` as an exact real algebraic number: a root of its minimal polynomial, isolated by a ball."""

    #: ``lambda_1`` as sympy writes it (radicals for a quadratic, ``CRootOf`` otherwise): for display.
    value: sp.Expr
    #: The minimal polynomial over ``Q``, in :data:`LAMBDA`, monic.
    minimal: sp.Poly
    #: An approximation of ``lambda_1`` closer to it than to any other root of :attr:`minimal` (picks its ball).
    near: complex

    def ball(self, prec: int = 128) -> flint.arb:
        """A certified real ball around ``lambda_1`` at ``prec`` bits: FLINT isolates the roots of the minimal
        polynomial (squarefree) in disjoint balls, and ``lambda_1``'s is the one nearest :attr:`near`."""
        with flint.ctx.workprec(prec):
            ball: flint.arb = +min(_roots(self.minimal), key=lambda r: abs(complex(r.mid()) - self.near)).real
            return ball


def _fmpq_poly(poly: sp.Poly) -> flint.fmpq_poly:
    return flint.fmpq_poly([to_fmpq(c) for c in reversed(poly.all_coeffs())])


def _roots(poly: sp.Poly) -> list[flint.acb]:
    """The complex roots of ``poly`` (rational coefficients) in disjoint certified balls at the working precision."""
    pairs: Any = _fmpq_poly(poly).complex_roots()  # (ball, multiplicity) pairs; the stubs say balls
    return [ball for ball, _ in pairs]


def algebraic_radius(value: sp.Expr) -> AlgebraicRadius:
    """``value`` (an algebraic number free of ``t``) with its minimal polynomial and which of its roots it is."""
    minimal = sp.Poly(sp.minimal_polynomial(value, LAMBDA), LAMBDA, domain=sp.QQ).monic()
    return AlgebraicRadius(value, minimal, complex(sp.N(value, 40)))


def constant_roots(p1: sp.Expr) -> list[sp.Expr]:
    """The roots of the factors of ``p1`` of degree ``>= 2`` in ``x`` whose coefficients are rational (free of ``t``).

    >>> constant_roots(sp.expand((8 * X - 1) * (16 * X**2 - 8 * X - 1)))
    [1/4 - sqrt(2)/4, 1/4 + sqrt(2)/4]
    """
    return [r for f, _ in sp.factor_list(sp.expand(p1), X)[1]
            if sp.degree(f, X) >= 2 and not f.has(T) for r in sp.Poly(f, X).all_roots()]


def higher_factors_in_t(p1: sp.Expr) -> list[sp.Expr]:
    """The factors of ``p1`` of degree ``>= 2`` in ``x`` whose coefficients depend on ``t`` (not handled here)."""
    return [f for f, _ in sp.factor_list(sp.expand(p1), X)[1] if sp.degree(f, X) >= 2 and f.has(T)]


def _reduce(expr: sp.Expr, radius: AlgebraicRadius) -> sp.Expr:
    """``expr`` (polynomial in :data:`LAMBDA` with coefficients in ``Q[t, n]``) modulo the minimal polynomial."""
    gens = (LAMBDA, *sorted(sp.expand(expr).free_symbols - {LAMBDA}, key=str))
    p = sp.Poly(sp.expand(expr), *gens)
    m = sp.Poly(radius.minimal.as_expr(), *gens)
    return sp.expand(sp.rem(p, m).as_expr())


def field_deltas(poly: sp.Expr, radius: AlgebraicRadius, *, divide: bool = False) -> tuple[sp.Expr, ...]:
    """The Schur-Cohn polynomials of ``poly(lambda_1 y)`` (``poly`` divided by ``x - lambda_1`` first where
    ``divide``), each reduced modulo ``m(lambda_1)``: polynomials in ``t`` (or ``n``) and :data:`LAMBDA`."""
    coefficients = [sp.expand(c) for c in sp.Poly(sp.expand(poly), X).all_coeffs()]
    if divide:  # synthetic division by x - lambda_1; the remainder is p(lambda_1), 0 in Q(lambda_1)
        quotient = [coefficients[0]]
        for c in coefficients[1:]:
            quotient.append(_reduce(c + LAMBDA * quotient[-1], radius))
        if _reduce(quotient.pop(), radius) != 0:
            raise ValueError(f"lambda_1 = {radius.value} is not a root of {sp.factor(poly)}")
        coefficients = quotient
    y = sp.Symbol("y")
    d = len(coefficients) - 1
    scaled = sp.Poly(sum(_reduce(c * LAMBDA ** (d - j), radius) * y ** (d - j) for j, c in enumerate(coefficients)), y)
    if scaled.degree() < 1:
        return ()
    return tuple(_reduce(delta, radius) for delta in schur_cohn_conditions(scaled))


def _arb_at(delta: sp.Expr, t: flint.arb, lam: flint.arb) -> flint.arb:
    """``delta(t, lambda_1)`` in Arb."""
    value = flint.arb(0)
    for (i, j), c in sp.Poly(delta, T, LAMBDA).terms():
        value += flint.arb(to_fmpq(c)) * t**i * lam**j
    return value


def _constant_sign(delta: sp.Expr, radius: AlgebraicRadius) -> int:
    """The sign of ``delta(lambda_1)`` in ``Q(lambda_1)``, exactly (module docstring)."""
    if delta == 0:
        return 0
    prec = 64
    while prec <= MAX_BITS:
        with flint.ctx.workprec(prec):
            value = _arb_at(delta, flint.arb(0), radius.ball(prec))
            if value > 0:
                return 1
            if value < 0:
                return -1
        prec *= 2
    raise PrecisionError(f"the sign of {delta} at lambda_1 = {radius.value} is not separated from 0 at {MAX_BITS} bits")


def _witness(delta: sp.Expr, radius: AlgebraicRadius, start: int, frequency: int | None, reach: int
             ) -> tuple[int, int] | None:
    """``(n, k)``: a valence ``n >= start`` and frequency ``k`` of the range where ``delta`` is negative (Arb)."""
    with flint.ctx.workprec(128):
        lam = radius.ball(128)
        for n in range(start, start + WITNESS_SEARCH):
            for k in (range(reach + 1, n - reach) if frequency is None else (frequency,)):
                t = flint.arb(flint.fmpq(2 * (k if frequency is None else 1), n)).cos_pi()
                if _arb_at(delta, t, lam) < 0:
                    return n, k
    return None


def _zero_free(delta: sp.Expr, norm: sp.Poly, radius: AlgebraicRadius, low: sp.Expr) -> bool:
    """``delta(t, lambda_1) != 0`` for every ``t`` in ``[low, 1)``: it vanishes only at roots of its norm; each real
    root of the norm in the range (isolated in FLINT's balls) is excluded where ``delta``'s Arb value there excludes 0
    (a root of the norm that belongs to a conjugate of ``lambda_1``), ``t = 1`` where it is one (not in the range)."""
    core = sp.Poly(sp.quo(norm, sp.gcd(norm, norm.diff(T))), T)  # squarefree: its roots are simple, isolated
    one_is_root = core.eval(1) == 0
    for prec in (128, 512, MAX_BITS):
        with flint.ctx.workprec(prec):
            lam, pending = flint.acb(radius.ball(prec)), []
            for r in _roots(core):
                if not r.imag.contains(0) or r.real > 1 or r.real < flint.arb(to_fmpq(low)):
                    continue  # not real, or outside the range
                if one_is_root and r.real.contains(1):
                    continue  # the root t = 1 itself (the balls are disjoint): outside [low, 1)
                value = flint.acb(0)
                for (i, j), c in sp.Poly(delta, T, LAMBDA).terms():
                    value += flint.acb(to_fmpq(c)) * r**i * lam**j
                if value.contains(0):
                    pending.append(r)
            if not pending:
                return True
    return False


def field_positive(delta: sp.Expr, radius: AlgebraicRadius, low: sp.Expr, *, start: int, frequency: int | None,
                   reach: int) -> tuple[str, str, int | None]:
    """``(status, note, n)``: ``delta(t, lambda_1) > 0`` for every ``t`` in ``[low, 1)`` is ``proved``, ``failed``
    (with a witness valence where one is found) or ``open`` (module docstring)."""
    if delta.has(N):
        return "open", f"the Schur-Cohn polynomial {delta} mixes n and lambda_1", None
    if delta == 0:
        k = reach + 1 if frequency is None else frequency
        return ("failed", f"the Schur-Cohn polynomial is 0: a root of modulus exactly lambda_1 at every n >= {start} "
                f"(the first: n = {start}, k = {k})", start)
    if delta.has(T):
        norm = sp.Poly(sp.resultant(radius.minimal.as_expr(), delta, LAMBDA), T)
        at_low = _constant_sign(_reduce(delta.subs(T, low), radius), radius)
        if at_low > 0 and _zero_free(delta, norm, radius, low):
            return ("proved", f"its norm over Q(lambda_1), {sp.factor(norm.as_expr())}, has no root in [{low}, 1) where "
                    f"it vanishes, and it is positive at t = {low}", None)
    elif _constant_sign(delta, radius) > 0:
        return "proved", "", None
    found = _witness(delta, radius, start, frequency, reach)
    if found is None:
        return ("open", f"the Schur-Cohn polynomial {delta} (lambda_1 = {radius.value}) is not shown positive for t in "
                f"[{low}, 1), and no valence n = {start}..{start + WITNESS_SEARCH - 1} has its t where it is negative", None)
    n, k = found
    return ("failed", f"the Schur-Cohn polynomial {delta} (lambda_1 = {radius.value}) is negative at n = {n}, k = {k} "
            f"(t = cos(2 pi {k if frequency is None else 1}/{n}), Arb)", n)


def larger_in_t(p1: sp.Expr, lam: sp.Expr, t0: sp.Expr) -> sp.Expr | None:
    """A factor of ``p1`` of degree ``>= 2`` with coefficients in ``Q(t)`` that has a root of modulus above
    ``lambda_1`` at ``t_0`` or at ``t = 1`` (Arb balls, separated): its root would be ``lambda_1``, algebraic over
    ``Q(t)``, which no step here handles; ``None`` where there is none."""
    for f in higher_factors_in_t(p1):
        for t in (t0, sp.Integer(1)):
            with flint.ctx.workprec(128):
                bound = _value_ball(lam.subs(T, t))
                if any(abs(r) > abs(bound) for r in _roots(sp.Poly(f.subs(T, t), X))):
                    return f
    return None


def _value_ball(value: sp.Expr) -> flint.arb:
    """A certified ball around the real algebraic number ``value`` (a rational or a root of a factor of ``p_1``)."""
    if value.is_Rational:
        return flint.arb(to_fmpq(value))
    return algebraic_radius(value).ball(flint.ctx.prec)


def algebraic_lambda_one(p1: sp.Expr, lam: sp.Expr, start: int) -> tuple[AlgebraicRadius | None, EveryNStep]:
    """The ``lambda-one`` step for a constant algebraic ``lambda_1`` (module docstring): real and in ``(0, 1)``,
    certified by its isolating ball, or ``open`` with the reason."""
    where, formulas = (start, None), [(r"p_1(x)", p1), (r"\lambda_1", lam)]
    if not lam.is_real:
        return None, EveryNStep(f"lambda_1 from det(x I - B_1) = {sp.factor(p1)}: its largest root {lam} is not real",
                                "open", where, "lambda-one", tuple(formulas))
    radius = algebraic_radius(lam)
    formulas.append((r"m(\lambda_1)", radius.minimal.as_expr()))
    if not (_constant_sign(LAMBDA, radius) > 0 and _constant_sign(1 - LAMBDA, radius) > 0):
        return None, EveryNStep(f"lambda_1 = {lam} from det(x I - B_1) = {sp.factor(p1)}: not in (0, 1)", "open", where,
                                "lambda-one", tuple(formulas))
    return radius, EveryNStep(
        f"lambda_1 = {lam}: the largest root of det(x I - B_1) = {sp.factor(p1)}, a root of its factor with rational "
        f"coefficients {sp.factor(radius.minimal.as_expr().subs(LAMBDA, X))} (the same for every n), in (0, 1) (an isolating "
        "Arb ball); the other steps compare in Q(lambda_1)", "proved", where, "lambda-one", tuple(formulas))
