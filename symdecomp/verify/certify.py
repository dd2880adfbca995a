"""Certified cross-check: a proof, for one valence ``n``, that the closed forms are the spectrum.

The certificate is an exact polynomial identity. Let ``chi_S`` be the characteristic
polynomial of the full ``(2n+1) x (2n+1)`` subdivision matrix, computed exactly over ``Q``
by FLINT from the matrix built out of the rules (:mod:`symdecomp.schemes.full_matrix`; no block
structure). Let ``v_1..v_{2n+1}`` be the closed-form eigenvalues (:mod:`symdecomp.analysis.closed_forms`)
and ``C(lambda) = prod_i (lambda - v_i)`` their characteristic polynomial. The claim
"the closed forms are the eigenvalues, with multiplicities" is exactly ``chi_S = C``. It is
proved as follows.

1. *Symbolically, once per scheme.* For the two closed forms ``v_+(c, s), v_-(c, s)`` of
   ``M_k`` the elementary symmetric functions ``e_1 = v_+ + v_-`` and ``e_2 = v_+ v_-`` are
   expanded; the square roots and absolute values must cancel, leaving polynomials in
   ``c = cos(k pi/n)``, ``s = sin(k pi/n)``. These are rewritten, exactly, as Laurent
   polynomials in ``omega = exp(2 pi i k/n) = (c + i s)^2`` with rational coefficients (they
   must be even in ``(c, s)``). Likewise the three closed forms of Eq. 43 give the cubic
   ``F_0`` whose coefficients must simplify to rational functions of ``n``.
2. *Exactly, for each n.* ``C = F_0 * prod_{k=1}^{n-1} (lambda^2 - e_1(omega^k) lambda + e_2(omega^k))``.
   For a rational ``lambda_0`` the product over the ``n-1`` roots of unity ``omega != 1`` is a
   resultant, ``prod_k G(omega^k) = Res(1 + omega + ... + omega^{n-1}, G)`` for
   ``G(omega) = omega^m (lambda_0^2 - e_1 lambda_0 + e_2)``, up to the sign ``(-1)^{(n-1)m}``:
   an exact rational computed by FLINT. ``chi_S(lambda_0) = C(lambda_0)`` is checked at the
   ``2n+1`` points ``lambda_0 = 0, 1, ..., 2n``. Both sides are monic of degree ``2n+1``, so
   their difference has degree at most ``2n`` and ``2n+1`` roots: it is zero. QED.

Repeated eigenvalues (``n = 4``: ``1/4`` three times), defective ones (a Jordan block of the
Eq. 43 matrix) and ``k = n/2`` need no special care: the identity is between polynomials,
multiplicities included. The distinct values and their multiplicities are certified on top:
the squarefree part of ``chi_S`` (exact) gives the number of distinct eigenvalues; the closed
forms evaluated as Arb balls (rigorous enclosures) fall into as many disjoint clusters, so the
clusters are exactly the distinct eigenvalues and their sizes the multiplicities.

When the identity fails (or the symmetric functions do not reduce, so that it cannot be
formed), the offending eigenvalue is named with a rigorous reason: its Arb enclosure ``v``
makes ``chi_S(v)`` a ball that excludes 0 (``v`` is not an eigenvalue), or the closed forms put
more values into an isolating ball of a root of ``chi_S`` than that root's multiplicity. If
neither can be shown the result is ``undecided``, which is a failure.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> r = certify(catmull_clark(), 4)
>>> r.status.value, r.distinct, r.multiplicities
('agree', 5, (1, 2, 3, 2, 1))
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import partial
from typing import ClassVar

import flint
import sympy as sp

from symdecomp.algebra.clusters import overlap_groups
from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.analysis.eigenvalue import ClosedFormLabel
from symdecomp.analysis.spectrum import format_value
from symdecomp.errors import UnsupportedExpressionError
from symdecomp.schemes.full_matrix import characteristic_polynomial, parameter_values
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import n as N
from symdecomp.validate import cached, check_bits, check_digits, check_type, check_valence
from symdecomp.verify.result import CrossCheckResult, CrossCheckStatus

__all__ = ["SymmetricFunctions", "symmetric_functions", "Certificate", "certify", "closed_form_characteristic_value"]

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


@dataclass(frozen=True)
class Certificate(CrossCheckResult):
    """The certified cross-check of one valence.

    Status ``agree`` (proved), ``disagree`` (refuted, rigorously) or ``undecided`` (neither: a failure).
    """

    #: How the verdict was reached, e.g. ``"chi_S = C at 2n+1 points"``.
    method: str
    #: Number of distinct eigenvalues (from the squarefree part of ``chi_S``).
    distinct: int
    #: Multiplicities of the distinct eigenvalues, largest modulus first (certified if ``multiplicities_certified``).
    multiplicities: tuple[int, ...]
    #: The distinct closed-form values, as decimal strings.
    values: tuple[str, ...]
    #: Whether the grouping into distinct values is proved (Arb clusters = squarefree degree).
    multiplicities_certified: bool
    #: Bits of the largest coefficient numerator of ``chi_S``.
    height_bits: int
    #: Which proof: ``"charpoly"`` (the dense characteristic polynomial of the full matrix) or
    #: ``"structural"`` (the full matrix is the block matrix, entry by entry; no ``chi_S``).
    route: str = "charpoly"

    mode: ClassVar[str] = "certified"

    def details(self) -> dict:
        return {
            "route": self.route,
            "method": self.method,
            "distinct": self.distinct,
            "multiplicities": list(self.multiplicities),
            "multiplicities_certified": self.multiplicities_certified,
            "height_bits": self.height_bits,
        }


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


def certify(
    scheme: Scheme,
    n: int,
    *,
    parameters: Mapping | None = None,
    closed_forms: ClosedForms | None = None,
    digits: int = 20,
    max_prec: int = 4096,
) -> Certificate:
    """Prove (or rigorously refute) that the closed forms are the spectrum at valence ``n``.

    ``closed_forms``: the closed forms under test (default: the derived ones; the tests pass
    a wrong one). ``digits``: significant digits of the printed values. ``max_prec``: the
    largest Arb precision (bits) tried when clustering or refuting.
    """
    check_scheme(scheme)
    n = check_valence(n)
    digits = check_digits(digits)
    max_prec = check_bits(max_prec, "max_prec", minimum=128)
    subs = parameter_values(scheme, parameters)
    cf = closed_forms or derived_closed_forms(scheme)
    chi = characteristic_polynomial(scheme, n, subs)
    height = max(int(c.p).bit_length() for c in chi.coeffs())
    squarefree = chi.numer().factor_squarefree()[1]  # [(f, e)]: chi ~ prod f^e, f squarefree, coprime
    distinct = sum(f.degree() for f, _ in squarefree)
    identity, method = _polynomial_identity(chi, symmetric_functions(cf), n, subs)
    balls, clusters, prec, refutation = _separate_or_refute(cf, n, subs, chi, squarefree, identity, digits, max_prec)
    order = sorted(clusters, key=lambda cl: (-_mid_abs(balls[cl[0]]), -_mid_re(balls[cl[0]])))
    # the printed values: a square root of a vanishing discriminant (a defective eigenvalue)
    # is only known to half the working precision, so they are recomputed with room to spare
    accurate = flint.arb(10) ** (-(digits + 5))
    if any(b.rad() >= accurate for b in balls):
        balls = cf.values(n, subs, engine="arb", prec=max(2 * prec, 8 * digits + 128))
    certified = identity and len(clusters) == distinct
    if identity:
        note = "multiplicities certified" if certified else "distinct values not separated at the precision limit"
        status, message = CrossCheckStatus.AGREE, f"n = {n}: proved: {method}; {distinct} distinct eigenvalues, {note}"
    elif refutation is not None:
        status, message = CrossCheckStatus.DISAGREE, refutation
    else:
        status = CrossCheckStatus.UNDECIDED
        message = f"n = {n}: not certified ({method}), and no closed-form eigenvalue could be refuted at {max_prec} bits"
    return Certificate(
        n=n,
        scheme=scheme.name,
        status=status,
        method=method,
        distinct=distinct,
        multiplicities=tuple(len(cl) for cl in order),
        values=tuple(_text(balls[cl[0]], digits) for cl in order),
        multiplicities_certified=certified,
        height_bits=height,
        message=message,
    )


def _polynomial_identity(chi, sym: SymmetricFunctions, n: int, subs: dict) -> tuple[bool, str]:
    """Step 2 of the proof: whether ``chi_S = C`` (at ``2n+1`` points), and how that was decided."""
    if sym.frequency_zero is None or sym.trace is None or sym.determinant is None:
        return False, f"identity not formed: {sym.reason}"
    points = range(2 * n + 1)
    values = closed_form_characteristic_value(sym, n, subs, points)
    if values is None:
        return False, "symmetric functions not rational at this n"
    identity = all(chi(flint.fmpq(x)) == v for x, v in zip(points, values))
    return identity, f"chi_S = prod(closed-form factors) at {2 * n + 1} points" if identity else "chi_S != closed-form char. poly"


def _separate_or_refute(cf, n, subs, chi, squarefree, identity, digits, max_prec):
    """``(balls, clusters, prec, refutation)``: the closed forms as Arb balls, doubling the precision.

    When the identity holds, until the balls fall into as many clusters as ``chi_S`` has
    distinct roots; otherwise until one closed form is rigorously refuted. Either way at most
    up to ``max_prec`` bits.
    """
    labels = cf.eigenvalue_labels(n)
    prec, refutation = 128, None
    while True:
        balls = cf.values(n, subs, engine="arb", prec=prec)
        clusters = _clusters(balls)
        if identity:
            done = len(clusters) == sum(f.degree() for f, _ in squarefree)
        else:
            with flint.ctx.workprec(prec):
                refutation = _refute(chi, squarefree, balls, labels, n, digits)
            done = refutation is not None
        if done or prec >= max_prec:
            return balls, clusters, prec, refutation
        prec *= 2


def _mid_abs(z):
    return float(abs(z.mid()).mid())


def _mid_re(z):
    return float(z.real.mid())


def _text(ball, digits):
    import mpmath

    with mpmath.workdps(digits + 5):
        re = mpmath.mpf(ball.real.mid().str(digits + 5, radius=False))
        im = mpmath.mpf(0) if ball.imag.contains(0) else mpmath.mpf(ball.imag.mid().str(digits + 5, radius=False))
        value = re if im == 0 else mpmath.mpc(re, im)
        return format_value(value, digits)


def _clusters(balls) -> list[list[int]]:
    """Connected components of the overlap graph of the balls (equal values always overlap)."""
    return overlap_groups(balls, lambda a, b: a.overlaps(b), key=lambda b: float(b.real.lower()),
                          beyond=lambda a, b: b.real.lower() > a.real.upper())


def _describe(labels: list[ClosedFormLabel]) -> str:
    kinds = sorted({lab.label for lab in labels})
    ks = sorted({lab.frequency for lab in labels})
    return f"{'; '.join(kinds)}; k = {', '.join(map(str, ks))}"


def _nearest(squarefree, v) -> str:
    """``"; the nearest eigenvalue is ... at distance ..."``, from a rigorous root isolation."""
    product = flint.fmpz_poly(1)
    for f, _ in squarefree:
        product *= f
    roots = [r for r, _ in product.complex_roots()]
    if not roots:
        return ""
    best = min(roots, key=lambda r: float(abs(r - v).mid()))
    distance = abs(best - v)
    return f"; the nearest eigenvalue is {_text(best, 25)}, at distance {distance.mid().str(3, radius=False)}"


def _refute(chi, squarefree, balls, labels, n, digits) -> str | None:
    """A rigorous reason why the closed forms are not the spectrum, or ``None`` (at ``flint.ctx.prec``)."""
    polys = [flint.acb_poly([flint.acb(c) for c in f.coeffs()]) for f, _ in squarefree]
    # (a) a closed-form value at which every squarefree factor of chi_S is certainly nonzero
    # is not an eigenvalue
    for i, v in enumerate(balls):
        if all(not p(v).contains(0) for p in polys):
            return (
                f"n = {n}: closed-form eigenvalue {_text(v, digits)} ({_describe([labels[i]])}) is not an eigenvalue of "
                f"the full matrix: chi_S(v) != 0 (certified){_nearest(squarefree, v)}"
            )
    # (b) more closed-form values in an isolating ball of a root than its multiplicity. The
    # roots of the squarefree part are isolated together, so each ball holds exactly one
    # eigenvalue; a closed-form value inside it is that eigenvalue or no eigenvalue at all.
    product = flint.fmpz_poly(1)
    for f, _ in squarefree:
        product *= f
    if product.degree() < 1:
        return None
    roots = [ball for ball, _ in product.complex_roots()]
    mids = [flint.acb(r.mid()) for r in roots]
    radii = [r.rad() for r in roots]
    for i, ball in enumerate(roots):
        owners = [e for (f, e), p in zip(squarefree, polys) if p(ball).contains(0)]
        if len(owners) != 1:
            continue
        # a square around the root that meets no other isolating ball holds no other eigenvalue
        separation = min(
            ((abs(mids[i] - mids[j]) - 2 * radii[j]).lower() for j in range(len(roots)) if j != i),
            default=flint.arb(1),
        )
        half_side = flint.arb(separation.mid() / 2)
        if not half_side > 2 * radii[i]:
            continue
        square = flint.acb(flint.arb(ball.real.mid(), half_side), flint.arb(ball.imag.mid(), half_side))
        inside = [k for k, v in enumerate(balls) if square.contains(v)]
        if len(inside) > owners[0]:
            return (
                f"n = {n}: {len(inside)} closed-form eigenvalues lie at the eigenvalue {_text(ball, digits)} "
                f"({_describe([labels[k] for k in inside])}), whose multiplicity in the full matrix is {owners[0]} (certified)"
            )
    return None
