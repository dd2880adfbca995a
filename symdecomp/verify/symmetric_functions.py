"""The closed forms' symmetric functions, and the characteristic polynomial they give, exactly.

Step 1 of the certificate of the 1-ring closed forms (:mod:`symdecomp.verify.certify`), once per
scheme: for the two closed forms ``v_+(c, s), v_-(c, s)`` of ``M_k`` the elementary symmetric
functions ``e_1 = v_+ + v_-`` and ``e_2 = v_+ v_-`` are expanded; the square roots and absolute
values must cancel, leaving polynomials in ``c = cos(k pi/n)``, ``s = sin(k pi/n)``, rewritten
exactly as Laurent polynomials in ``omega = exp(2 pi i k/n) = (c + i s)^2`` with rational
coefficients (:func:`symmetric_functions`); the three closed forms of Eq. 43 give the cubic
``F_0`` whose coefficients must simplify to rational functions of ``n``. Step 2, at each valence:
the closed forms' characteristic polynomial ``C(lambda)`` at rational points, by resultants over
the roots of unity (:func:`closed_form_characteristic_value`), and the identity ``chi_S = C``
at ``2n+1`` points (:func:`closed_form_identity`). The O(n) route
(:mod:`symdecomp.verify.structural`) and the claims of Section 6 use the same two steps.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import partial

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.closed_forms import ClosedForms
from symdecomp.errors import UnsupportedExpressionError
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import n as N
from symdecomp.validate import cached, check_type

__all__ = ["SymmetricFunctions", "symmetric_functions", "closed_form_characteristic_value", "closed_form_identity"]

_ETA = sp.Symbol("eta")


@dataclass(frozen=True)
class SymmetricFunctions:
    """Step 1 of the proof: the closed forms' symmetric functions, as exact polynomials."""

    #: Coefficients ``(e_1, e_2, e_3)`` of ``F_0 = lambda^3 - e_1 lambda^2 + e_2 lambda - e_3`` in ``n``.
    frequency_zero: tuple[sp.Expr, ...] | None
    #: ``e_1 = v_+ + v_-`` as ``{power of omega: coefficient in n}``.
    trace: dict | None
    #: ``e_2 = v_+ v_-`` as ``{power of omega: coefficient in n}``.
    determinant: dict | None
    #: Why the identity cannot be formed, when one of the above is ``None``.
    reason: str = ""
    #: Exact evaluators of the coefficients, by expression; not part of the value.
    _compiled: dict = field(default_factory=dict, init=False, repr=False, compare=False, hash=False)

    def rational_at(self, expr: sp.Expr, at: dict):
        """``expr`` at ``{n: .., parameter: ..}`` as an ``fmpq``, or ``None`` if it is not rational there."""
        variables = tuple(sorted(at, key=str))
        key = (expr, variables)
        if key not in self._compiled:
            try:
                self._compiled[key] = compile_expression(expr, variables, "fmpq")
            except UnsupportedExpressionError:
                self._compiled[key] = None
        f = self._compiled[key]
        values = [sp.sympify(at[v], strict=True) for v in variables]
        if f is not None and all(v.is_Rational for v in values):
            try:
                return f(*(to_fmpq(v) for v in values))
            except (UnsupportedExpressionError, ZeroDivisionError):
                pass
        return _rational(expr, at)


def _to_laurent(expr: sp.Expr):
    """Rewrite a polynomial in ``c, s`` as a Laurent polynomial in ``omega``; ``None`` if impossible."""
    expr = sp.expand(expr)
    if expr.has(sp.Abs) or any(
        isinstance(p, sp.Pow) and not p.exp.is_Integer and p.base.has(cos_jtheta, sin_jtheta) for p in expr.atoms(sp.Pow)
    ):
        return None
    z = sp.expand(expr.subs({cos_jtheta: (_ETA + 1 / _ETA) / 2, sin_jtheta: (_ETA - 1 / _ETA) / (2 * sp.I)}))
    terms: dict = {}
    for term in sp.Add.make_args(z):
        coeff, power = term.as_coeff_exponent(_ETA)
        if coeff.has(_ETA) or not power.is_Integer:
            return None
        terms[int(power)] = terms.get(int(power), sp.Integer(0)) + coeff
    out = {}
    for power, coeff in terms.items():
        coeff = sp.cancel(coeff)
        if coeff == 0:
            continue
        if power % 2 or coeff.has(sp.I) or coeff.has(cos_jtheta, sin_jtheta):
            return None
        out[power // 2] = coeff
    return out


def _has_radical(expr: sp.Expr) -> bool:
    return any(not p.exp.is_Integer for p in expr.atoms(sp.Pow))


def _rational_function(expr: sp.Expr) -> sp.Expr:
    """A symmetric function of radicals reduced to a rational function (``simplify`` if need be)."""
    fast = sp.factor(sp.cancel(sp.expand(sp.radsimp(sp.expand(expr)))))
    return fast if not _has_radical(fast) else sp.factor(sp.simplify(sp.radsimp(sp.expand(expr))))


@cached(32, cf=partial(check_type, kind=ClosedForms, argument="closed forms", hint="derived_closed_forms(scheme)"))
def symmetric_functions(cf: ClosedForms) -> SymmetricFunctions:
    """Step 1 of the proof (see the module docstring), cached per set of closed forms."""
    reasons = []
    v_plus, v_minus = cf.frequency_k
    trace = _to_laurent(sp.expand(v_plus + v_minus))
    det = _to_laurent(sp.expand(v_plus * v_minus))
    if trace is None:
        reasons.append(f"{cf.names[0]} + {cf.names[1]} = {sp.simplify(v_plus + v_minus)} is not a polynomial in cos, sin")
    if det is None:
        reasons.append(f"{cf.names[0]} * {cf.names[1]} does not reduce to a polynomial in cos, sin")
    zero = None
    if len(cf.frequency_zero) == 3:
        r = cf.frequency_zero
        e = (r[0] + r[1] + r[2], r[0] * r[1] + r[0] * r[2] + r[1] * r[2], r[0] * r[1] * r[2])
        zero = tuple(_rational_function(x) for x in e)
    else:
        reasons.append(f"Eq. 43 has 3 eigenvalues, the closed forms give {len(cf.frequency_zero)}")
    return SymmetricFunctions(zero, trace, det, "; ".join(reasons))


def _rational(expr: sp.Expr, subs: dict):
    value = expr.subs(subs) if expr.free_symbols else expr
    if not value.is_Rational:
        value = sp.radsimp(sp.simplify(value))
    if not value.is_Rational:
        return None
    return to_fmpq(value)


def closed_form_characteristic_value(sym: SymmetricFunctions, n: int, subs: dict, points) -> list | None:
    """``C(lambda_0)`` exactly for each rational ``lambda_0`` in ``points`` (step 2), or ``None``.

    ``None`` when the symmetric functions are not rational at this ``n``.
    """
    at = {N: n, **subs}
    zero = [sym.rational_at(e, at) for e in sym.frequency_zero]
    trace = {p: sym.rational_at(c, at) for p, c in sym.trace.items()}
    det = {p: sym.rational_at(c, at) for p, c in sym.determinant.items()}
    if None in zero or None in trace.values() or None in det.values():
        return None
    low = min([0, *trace, *det])
    high = max([0, *trace, *det])
    shift = -low  # G(omega) = omega^shift * (lambda^2 - e_1 lambda + e_2)
    cyclotomic = flint.fmpq_poly([1] * n)  # 1 + omega + ... + omega^(n-1): the roots omega^k, k = 1..n-1
    sign = -1 if ((n - 1) * shift) % 2 else 1
    e1, e2, e3 = zero
    out = []
    for lam in points:
        lam = flint.fmpq(lam)
        coeffs = [flint.fmpq(0)] * (high - low + 1)
        coeffs[shift] += lam * lam
        for p, c in trace.items():
            coeffs[p + shift] -= c * lam
        for p, c in det.items():
            coeffs[p + shift] += c
        G = flint.fmpq_poly(coeffs)
        rest = cyclotomic.resultant(G) * sign
        f0 = ((lam - e1) * lam + e2) * lam - e3
        out.append(f0 * rest)
    return out


def closed_form_identity(chi, sym: SymmetricFunctions, n: int, subs: dict) -> tuple[bool, str]:
    """Step 2 of the proof: whether ``chi_S = C`` (at ``2n+1`` points), and how that was decided."""
    if sym.frequency_zero is None or sym.trace is None or sym.determinant is None:
        return False, f"identity not formed: {sym.reason}"
    points = range(2 * n + 1)
    values = closed_form_characteristic_value(sym, n, subs, points)
    if values is None:
        return False, "symmetric functions not rational at this n"
    identity = all(chi(flint.fmpq(x)) == v for x, v in zip(points, values))
    return identity, f"chi_S = prod(closed-form factors) at {2 * n + 1} points" if identity else "chi_S != closed-form char. poly"
