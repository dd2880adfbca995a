"""C1 at an extraordinary vertex for every valence: the spectral conditions proved in n, the map per valence.

Reif's sufficient test (:mod:`symdecomp.verify.c1`) has two parts. Its spectral conditions are statements about the
per-frequency matrices ``M(omega)`` of the 1-ring, the frequency-0 block ``E_0`` and the outer ring's blocks (the
regular rules), and they are decided here for every ``n >= 3`` at once, exactly:

* with ``t = cos(2 pi j/n)`` the trace and determinant of ``M`` are polynomials in ``t`` (mirror-symmetric rules), and
  ``lambda_1`` is the dominant eigenvalue at ``t_1 = cos(2 pi/n)``, which runs through ``[-1/2, 1)``;
* S1, S2: the eigenvalues of ``M`` are real and distinct, the other root smaller in modulus, on ``[-1, 1]``
  (discriminant and trace positive: Sturm sequences, :func:`~symdecomp.algebra.valence_signs.sign_on_interval`);
* S3: the dominant eigenvalue increases with ``t`` on ``[-1, 1]`` (its derivative ``(tr' + disc'/(2 sqrt(disc)))/2``:
  ``tr' > 0`` and ``disc' >= 0``, or ``4 disc tr'^2 - disc'^2 > 0``), so at every other frequency ``j`` (``t_j < t_1``)
  the spectral radius is smaller than ``lambda_1``: ``lambda_1`` is a double eigenvalue (``j = 1, n - 1``) and
  strictly larger than the rest of the tangent spectrum;
* S4: ``lambda_1 < 1`` and ``lambda_1`` above the outer ring's eigenvalues (constants of the regular rules), as signs of
  polynomials in ``t`` on ``[-1/2, 1]``;
* S5: the eigenvalues of ``E_0`` besides 1 below ``lambda_1``: the exact tail bound of Proposition 5.1
  (:func:`~symdecomp.analysis.dominance.tail_bound`, beyond its ``N0``) on quads; on triangles, the elliptic eigenvalue
  equal to ``lambda_1^2`` identically (Loop's weight), which is below ``lambda_1 < 1``.

The other part, that the characteristic map is regular and injective, is certified per valence by Reif's test at each
``n = 3..last`` (:func:`~symdecomp.verify.c1.c1_test`), and proved for every ``n >= N0`` at once where the exact
argument closes (:func:`~symdecomp.verify.c1_uniform.uniform_map`: the map's control nets as polynomials in
``t = cos(2 pi/n)`` and ``lambda_1``, stretched by ``1/sin(2 pi/n)`` so that they converge as ``n`` grows, their
Jacobian's Bezier coefficients and the inner boundary's wedge decided by Sturm sequences on ``[cos(2 pi/N0), 1]``).
With ``N0 <= last + 1`` and the spectral conditions proved the result is ``proved`` for every ``n``; otherwise it is
``verified`` for ``3..last`` and the map is open beyond (the step says which sign was not shown). A valence where the
test fails refutes C1 with that concrete ``n``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.valence_signs import sign_on_interval
from symdecomp.analysis.characteristic import outer_charpoly
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached
from symdecomp.verify.c1_uniform import UniformMapResult

__all__ = ["EveryNStep", "EveryNResult", "laurent_in_t", "spectral_every_n", "c1_every_n", "lambda_one", "tangent_steps"]

T = sp.Symbol("t", real=True)  # cos(2 pi j/n)
HALF = sp.Rational(-1, 2)  # t_1 = cos(2 pi/n) at n = 3
#: The names of the characteristic map's steps, in the order of :attr:`UniformMapResult.facts` when it is proved.
MAP_STEPS = ("map-scale", "map-regular", "map-injective")


@dataclass(frozen=True)
class EveryNStep:
    """One step of the argument."""

    #: What the step shows, in words (formulas as sympy's ``str``).
    text: str
    #: ``proved`` (for every n it covers), ``verified`` (each valence of a range), ``open`` or ``failed``.
    status: str
    #: The valences it covers: ``(first, None)`` for every ``n >= first``, ``(first, last)`` for a range.
    valences: tuple[int, int | None]
    #: What the step is, a stable key a program reads (``real-distinct``, ``monotone``, ``map-regular``, ...).
    name: str = ""
    #: The computed objects the step rests on, ``(symbol in LaTeX, value)``, in the order the derivations print them.
    formulas: tuple[tuple[str, object], ...] = ()

    def as_json(self) -> dict:
        return {**({"name": self.name} if self.name else {}), "text": self.text, "status": self.status,
                "valences": list(self.valences)}


@dataclass(frozen=True)
class EveryNResult:
    """C1 for every valence: what is proved, verified, open, or the first valence where it fails."""

    scheme: str
    #: ``proved`` (every n), ``verified`` (3..last, spectral conditions for every n), ``refuted`` or ``undecided``.
    status: str
    #: One line: the conclusion.
    summary: str
    steps: tuple[EveryNStep, ...]
    #: The valences Reif's test certified one by one.
    certified: tuple[int, int]
    #: The first valence where C1 fails (a concrete counterexample), or ``None``.
    failure: int | None = None
    #: The characteristic map for every ``n`` from some valence on (:class:`~symdecomp.verify.c1_uniform.UniformMapResult`),
    #: or ``None`` where it was not tried (a failure, or the spectral conditions not proved).
    uniform: UniformMapResult | None = None

    def as_json(self) -> dict:
        return {"scheme": self.scheme, "status": self.status, "summary": self.summary, "certified": list(self.certified),
                "failure": self.failure, "steps": [s.as_json() for s in self.steps]}


def laurent_in_t(expr) -> sp.Expr:
    """A Laurent polynomial in ``omega``, symmetric under ``omega -> 1/omega``, as a polynomial in ``t = cos(angle)``
    (``omega^k + omega^-k = 2 T_k(t)``); :class:`NotApplicableError` where it is not symmetric or not Laurent.
    The one reading of the per-frequency blocks in ``t``, shared by the every-n routes.

    >>> from symdecomp.symbols import omega
    >>> laurent_in_t(3 + omega**2 + omega**-2)
    4*t**2 + 1
    """
    expr = sp.expand(sp.sympify(expr, strict=True))
    terms: dict[int, sp.Expr] = {}
    for term in sp.Add.make_args(expr):
        coeff, power = term.as_coeff_exponent(OMEGA)
        if coeff.has(OMEGA) or not power.is_Integer:
            raise NotApplicableError(f"{expr} is not a Laurent polynomial in omega")
        terms[int(power)] = terms.get(int(power), 0) + coeff
    if any(sp.expand(terms.get(-k, 0) - c) != 0 for k, c in terms.items()):
        raise NotApplicableError("the rules are not mirror symmetric: M(omega) is not a function of cos(2 pi j/n)")
    return sp.expand(terms.get(0, 0) + sum(2 * c * sp.chebyshevt(k, T) for k, c in terms.items() if k > 0))


def _positive(expr, lo, hi) -> bool:
    try:
        return bool(sign_on_interval(sp.expand(expr), T, lo, hi))  # None (not a polynomial in t): not shown
    except InvalidInputError:
        return False


def tangent_steps(M: sp.Matrix, radius: sp.Expr) -> list[EveryNStep]:
    """S1-S4 of :func:`spectral_every_n` for a 1 x 1 or 2 x 2 frequency block ``M(t)`` (``t = cos(2 pi j/n)``) and the
    outer ring's spectral radius ``radius``: ``(name, text, shown, formulas)`` per step (formulas: what the derivations
    print). Also read by :mod:`symdecomp.verify.dominance_every_n`, which needs the same tangent steps."""
    if M.rows == 1:
        lam = laurent_in_t(M[0, 0])
        checks = [
            ("monotone", f"the eigenvalue of M at t = cos(2 pi j/n) is {lam}, increasing in t (slope {sp.diff(lam, T)}) and "
             "positive on [-1, 1]: lambda_1 (t = cos(2 pi/n)) is double (j = 1, n - 1) and larger than every other frequency's",
             _positive(sp.diff(lam, T), -1, 1) and _positive(lam, -1, 1), ((r"\lambda(t)", lam), (r"\lambda'(t)", sp.diff(lam, T)))),
            ("bounds", f"lambda_1 < 1 and lambda_1 > {radius} (the outer ring's eigenvalues): {1 - lam} > 0 and {lam - radius} > 0 "
             "on [-1/2, 1]", _positive(1 - lam, HALF, 1) and _positive(lam - radius, HALF, 1),
             ((r"1 - \lambda(t)", 1 - lam), (r"\lambda(t) - \rho_S", lam - radius), (r"\rho_S", radius))),
        ]
    else:
        tr, det = laurent_in_t(M.trace()), laurent_in_t(M.det())
        disc = sp.expand(tr**2 - 4 * det)
        d_tr, d_disc = sp.diff(tr, T), sp.diff(disc, T)
        increasing = _positive(d_tr, -1, 1) and (bool(sign_on_interval(d_disc, T, -1, 1, strict=False))
                                                 or _positive(4 * disc * d_tr**2 - d_disc**2, -1, 1))
        p = lambda x: sp.expand(x**2 - tr * x + det)  # noqa: E731 - det(xI - M(t))
        checks = [
            ("real-distinct", f"tr M(t) = {tr} is positive on [-1, 1] and its discriminant {sp.factor(disc)} on (-1, 1] (0 at "
             "t = -1 at most: the frequency n/2): real eigenvalues, distinct at every frequency but n/2, the other one smaller "
             "in modulus", bool(sign_on_interval(disc, T, -1, 1, strict=False)) and _positive(disc, sp.Rational(-1, 2), 1)
             and _positive(tr, -1, 1), ((r"\operatorname{tr} M(t)", tr), (r"\det M(t)", det), (r"\Delta(t)", sp.factor(disc)))),
            ("monotone", "the dominant eigenvalue (tr + sqrt(disc))/2 increases with t on [-1, 1] (tr' > 0, and disc' >= 0 or "
             "4 disc tr'^2 > disc'^2): lambda_1 (t = cos(2 pi/n)) is double (j = 1, n - 1) and larger than every other "
             "frequency's", increasing, ((r"\operatorname{tr}' M(t)", d_tr), (r"\Delta'(t)", sp.factor(d_disc)),
                                         (r"4 \Delta (\operatorname{tr}')^2 - (\Delta')^2", sp.factor(4 * disc * d_tr**2 - d_disc**2)))),
            ("bounds", f"lambda_1 < 1 (det(I - M) = {p(1)} > 0 and tr < 2) and lambda_1 > {radius}, the outer ring's largest "
             f"eigenvalue (tr/2 > {radius}, or det({radius} I - M) < 0), on [-1/2, 1]",
             _positive(p(1), HALF, 1) and _positive(2 - tr, HALF, 1)
             and (_positive(tr - 2 * radius, HALF, 1) or _positive(-p(radius), HALF, 1)),
             ((r"\det(I - M(t))", p(1)), (r"\rho_S", radius), (r"\det(\rho_S I - M(t))", p(radius)))),
        ]
    # a sign not shown by Sturm sequences (it may fail, or not be decidable here) computes no valence where C1 fails: open
    return [EveryNStep(text, "proved" if ok else "open", (3, None), name, formulas) for name, text, ok, formulas in checks]


def _frequency_zero_step(scheme: Scheme, M: sp.Matrix, E0: sp.Matrix) -> EveryNStep:
    """S5: the eigenvalues of ``E_0`` besides 1 below ``lambda_1`` for every ``n`` (from where it is shown)."""
    if M.rows == 1:
        other = sp.expand(E0.trace() - 1)  # E_0 is 2 x 2 with the eigenvalue 1
        # zero as a rational function of t = cos(2 pi/n) and n taken apart is zero for every n (no simplify needed)
        identical = sp.cancel(other.subs(sp.cos(2 * sp.pi / N), T) - laurent_in_t(M[0, 0]) ** 2) == 0
        lam1 = M[0, 0].subs(OMEGA, sp.exp(2 * sp.pi * sp.I / N))
        defect = 0 if identical else sp.simplify(sp.expand((other - lam1**2).rewrite(sp.cos)))
        if defect == 0:
            return EveryNStep("the eigenvalue of E_0 besides 1 equals lambda_1^2 for every n (the vertex weight), and "
                              "0 < lambda_1 < 1: it is below lambda_1", "proved", (3, None), "frequency-zero",
                              ((r"\mu_0(n)", other), (r"\mu_0(n) - \lambda_1^2", defect)))
        return EveryNStep(f"the eigenvalue of E_0 besides 1 is not lambda_1^2 (difference {defect}); no argument for every n",
                          "open", (3, None), "frequency-zero", ((r"\mu_0(n)", other), (r"\mu_0(n) - \lambda_1^2", defect)))
    from symdecomp.analysis.dominance import tail_bound

    tail = tail_bound(scheme)
    if tail is None:
        return EveryNStep("no exact tail bound for the eigenvalues of E_0 besides 1 (Proposition 5.1's argument does not "
                          "apply)", "open", (3, None), "frequency-zero")
    return EveryNStep("the eigenvalues of E_0 besides 1 are below lambda_1: cos(pi/n) >= 1 - 5/n^2 "
                      f"and the signs of {len(tail.facts)} rational functions of n (Proposition 5.1's tail bound)",
                      "proved", (tail.start, None), "frequency-zero",
                      tuple((f"f_{{{k}}}(n)", fact) for k, fact in enumerate(dict.fromkeys(tail.facts), 1)))


def lambda_one(scheme: Scheme) -> sp.Expr | None:
    """``lambda_1`` as a closed form in ``n``: the dominant eigenvalue of the frequency-1 block ``M(t)`` (the larger root
    of ``x^2 - tr x + det`` for a 2 x 2 block) at ``t = cos(2 pi/n)``; ``None`` where ``M`` is not a function of ``t``
    alone (free parameters, an edge rule in ``n``).

    >>> from symdecomp.schemes.loop import loop
    >>> lambda_one(loop())
    cos(2*pi/n)/4 + 3/8
    """
    if scheme.parameters:
        return None
    M = sp.Matrix(one_ring_matrices(scheme)[0])
    if M.has(N):
        return None
    try:
        if M.rows == 1:
            lam = laurent_in_t(M[0, 0])
        else:
            tr, det = laurent_in_t(M.trace()), laurent_in_t(M.det())
            lam = (tr + sp.sqrt(sp.expand(tr**2 - 4 * det))) / 2
    except NotApplicableError:
        return None
    return lam.subs(T, sp.cos(2 * sp.pi / N))


def spectral_every_n(scheme: Scheme) -> tuple[EveryNStep, ...]:
    """The spectral conditions of Reif's test as statements for every ``n`` (module docstring)."""
    return _spectral_every_n(scheme)


@cached(8, scheme=check_scheme)  # asked by the C1 claim, c1 --every-n and the curvature regime's cause, of one scheme
def _spectral_every_n(scheme: Scheme) -> tuple[EveryNStep, ...]:
    if scheme.parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters; give them values first")
    M, E0 = one_ring_matrices(scheme)
    if M.has(N):
        raise NotApplicableError(f"scheme {scheme.name!r}: its edge rule depends on n, so M is not a function of cos(2 pi j/n) "
                                 "alone; the valences are tested one by one")
    coeffs = outer_charpoly(scheme.lattice)
    x = sp.Symbol("x")
    radius = max((abs(r) for r in sp.Poly(list(coeffs), x).all_roots()), key=lambda r: float(r)) if coeffs else sp.Integer(0)
    return tuple(tangent_steps(sp.Matrix(M), radius)) + (_frequency_zero_step(scheme, sp.Matrix(M), sp.Matrix(E0)),)


def _fails_from(scheme: Scheme, first: int, certify) -> EveryNStep | None:
    """C1 fails at every ``n >= first`` (``first`` a certified failure), or ``None`` where that is not shown.

    ``lambda_1(n)`` stays below its limit ``L`` (it increases with ``t = cos(2 pi/n) < 1``, step S3); a rational
    ``L' > L`` and the frequency-0 quadratic ``q`` (the Eq. 43 block besides 1, rational in ``n``) with ``q(L') < 0`` or
    ``q(-L') < 0`` for every ``n >= N'`` give an eigenvalue of modulus above ``L' > lambda_1(n)`` there (Sturm
    sequences); the valences ``first..N' - 1`` are certified failures one by one."""
    from symdecomp.algebra.algebraic_sign import rational_between
    from symdecomp.algebra.valence_signs import positive_from

    M, E0 = (sp.Matrix(m) for m in one_ring_matrices(scheme))
    x = sp.Symbol("x")
    if M.has(N):  # an edge rule in n: lambda_1 has no limit of this form
        return None
    try:
        tr, det = laurent_in_t(M.trace()).subs(T, 1), laurent_in_t(M.det()).subs(T, 1)
        limit = max(sp.Poly(x**2 - tr * x + det if M.rows == 2 else x - tr, x).all_roots(), key=lambda r: float(r))
        q, rest = sp.div(sp.Poly(E0.charpoly(x).as_expr(), x), sp.Poly(x - 1, x))
        bound = rational_between(limit, limit + sp.Rational(1, 10**4))
    except (NotApplicableError, sp.PolynomialError, ArithmeticError, NotImplementedError):
        return None
    if not rest.is_zero or q.as_expr().free_symbols - {x, N}:
        return None
    for sign in (1, -1):
        value = sp.cancel(-q.as_expr().subs(x, sign * bound))  # positive: q(sign L') < 0
        numerator, denominator = (sp.Poly(e, N) for e in sp.fraction(value))
        roots = [r for poly in (numerator, denominator) if poly.degree() > 0 for r in poly.real_roots()]
        start = max(first, int(sp.ceiling(max(roots, default=first))) + 1)
        if start > first + 10**4 or not positive_from(value, N, start):
            continue
        if all(certify(k).verdict == "not-c1" for k in range(first, start)):
            return EveryNStep(f"C1 fails at every n >= {first}: certified at n = {first}..{start - 1}, and for n >= {start} "
                              f"q({sign * bound}) < 0 (q = det(x I - E_0)/(x - 1), a rational function of n: Sturm sequences), "
                              f"so E_0 has an eigenvalue beyond {sign * bound}, larger in modulus than lambda_1(n) < "
                              f"lim lambda_1 = {limit}", "proved", (first, None), "fails-from",
                              ((r"q(x)", q.as_expr()), (r"\lim_{n \to \infty} \lambda_1", limit), ("L'", sign * bound),
                               (r"-q(L')", value), ("N'", sp.Integer(start))))
    return None


def c1_every_n(scheme: Scheme | StencilScheme, last: int = 64, *, progress: Callable[[int], None] | None = None, certify=None,
               spectral_steps: Callable[[], tuple[EveryNStep, ...]] | None = None, map_every_n=None, fails_from=None,
               first: int | None = None) -> EveryNResult:
    """C1 for every valence as far as it is shown (module docstring): the spectral conditions for every ``n``, Reif's
    test at ``n = 3..last`` (``certify(n)``: a :class:`~symdecomp.verify.c1.C1Result`; by default :func:`c1_test`).

    Another route (a dual scheme's, :mod:`symdecomp.verify.c1_dual_every_n`) gives its own ``spectral_steps()``, its
    ``map_every_n(lo, last)`` (a :class:`UniformMapResult`), ``fails_from(k, certify)`` and ``first`` valence."""
    from symdecomp.verify.c1 import c1_test

    certify = certify or (lambda k: c1_test(scheme, k))
    lo = max(3, scheme.minimum_valence()) if first is None else first
    try:
        spectral = spectral_steps() if spectral_steps else spectral_every_n(scheme)
    except NotApplicableError as exc:
        spectral = (EveryNStep(str(exc), "open", (lo, None), "spectral"),)
    for k in range(lo, last + 1):
        r = certify(k)
        if progress:
            progress(k)
        if r.verdict != "c1":
            step = EveryNStep(r.reason, "failed" if r.verdict == "not-c1" else "open", (k, k), "reif-at-n")
            if r.verdict != "not-c1":
                return EveryNResult(scheme.name, "undecided", f"Reif's test is undecided at n = {k}", spectral + (step,),
                                    (lo, k - 1))
            tail = fails_from(k, certify) if fails_from else None if map_every_n else _fails_from(scheme, k, certify)
            summary = (f"C1 holds exactly for n = {lo}..{k - 1} (certified) and fails for every n >= {k}: the exact threshold"
                       if tail is not None and k > lo else f"C1 fails at n = {k}: {r.reason}")
            return EveryNResult(scheme.name, "refuted", summary, spectral + (step,) + ((tail,) if tail else ()), (lo, k - 1), k)
    tail = max((s.valences[0] for s in spectral if s.status == "proved"), default=lo)
    spectral_ok = all(s.status == "proved" for s in spectral) and tail <= last + 1
    uniform = (map_every_n or (lambda lo, last: _uniform_map(scheme, lo, last)))(lo, last) if spectral_ok else None
    steps = spectral + (
        # the range is the step's valences, printed beside its text: the text says what holds at each of them
        EveryNStep("Reif's test at each valence: the spectral conditions and a regular, injective characteristic map, "
                   "certified (Arb balls; exact at frequency 0)", "verified", (lo, last), "reif-per-valence"),
    )
    if uniform is not None and uniform.status == "proved":
        steps += tuple(EveryNStep(fact, "proved", (uniform.first, None), name) for name, fact in zip(MAP_STEPS, uniform.facts))
        return EveryNResult(scheme.name, "proved", f"C1 for every n >= {lo}: the spectral conditions proved for every n, the "
                            f"characteristic map regular and injective for every n >= {uniform.first} (exact signs in "
                            f"t = cos(2 pi/n)), Reif's test certified at n = {lo}..{last}", steps, (lo, last), uniform=uniform)
    why = ("no bound on its control net that holds for every large n is derived" if uniform is None else
           f"{uniform.facts[-1]} (the nets' exact signs in t = cos(2 pi/n) for n >= {last + 1})")
    steps += (EveryNStep(f"regularity and injectivity of the characteristic map beyond the certified valences are open: {why}", "open",
                         (last + 1, None), "map-open"),)
    what = ("the spectral conditions hold for every n >= 3 (proved); " if spectral_ok else
            "the spectral conditions are not proved for every n; ")
    return EveryNResult(scheme.name, "verified", f"C1 certified for n = {lo}..{last}; {what}the characteristic map is open "
                        f"beyond n = {last}", steps, (lo, last), uniform=uniform)


def _uniform_map(scheme: Scheme, lo: int, last: int):
    """The characteristic map for every ``n >= first`` (:func:`~symdecomp.verify.c1_uniform.uniform_map`), from the
    smallest ``first`` of a few tried that closes the argument; the last one tried (``last + 1``) when none does."""
    from symdecomp.verify.c1_uniform import uniform_map

    result = None
    for first in sorted({f for f in (lo, 4, 6, 8, 16, 32, last + 1) if lo <= f <= last + 1}):
        result = uniform_map(scheme, first)
        if result.status == "proved":
            return result
    return result
