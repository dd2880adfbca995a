"""The spectral conditions of Zorin's test for every valence, from the structural blocks (primal schemes of the zoo).

The matrix of a primal scheme of the zoo on its invariant neighbourhood depends on the valence ``n`` only through the
rules at the centre (:mod:`symdecomp.analysis.zoo_structure`): at frequency ``k`` its block is ``B(omega)``, a
Laurent polynomial matrix in ``omega = exp(2 pi i k/n)`` and the centre families' symbols ``sigma(k)``, which take
one value at every frequency but a few exceptional ones (the modified butterfly's weights ``s_j`` are a cosine sum of
frequencies ``0, +-1, +-2``; :mod:`symdecomp.analysis.zoo_symbols`). With the mirror symmetry the coefficients of
``p_k(x) = det(x I - B_k)`` are polynomials in ``t = cos(2 pi k/n)``, and the conditions are, for every ``n`` from
the valence ``N0`` the form holds from:

* ``lambda-one``: ``lambda_1`` is the largest root of ``p_1`` among the roots of its factors linear in ``x`` and of
  its factors with rational coefficients, derived from the factors of ``p_1``, never typed: a rational constant (the
  same for every ``n``), real and in ``(0, 1)``; a constant algebraic number, for which
  :mod:`symdecomp.verify.zorin_lambda_algebraic` runs the steps in ``Q(lambda_1)``; or a rational function
  ``lambda(t)`` of ``t = cos(2 pi/n)`` (sqrt(3)), for which :mod:`symdecomp.verify.zorin_lambda_in_t` gives this step
  and the other frequencies' (below ``lambda(t)`` at ``s = cos(2 pi k/n) < t``, another number than ``t``); a factor
  of higher degree with coefficients in ``Q(t)`` holding a larger root leaves it ``open``, naming the factor;
* ``frequency-one``: at ``k = 1`` and ``k = -1``, ``p_k = (x - lambda_1) r_k`` with every root of ``r_k`` of modulus
  ``< lambda_1`` (``lambda_1`` simple there, so double overall), for ``t = cos(2 pi/n)`` in ``[t_0, 1)``;
* ``frequency-zero``: ``p_0 = (x - 1) r_0`` (the centre's row bordering the block) with every root of ``r_0`` of
  modulus ``< lambda_1`` (1 simple);
* ``frequency-exceptional``: at each other exceptional frequency (``k = +-2``) every root of ``p_k`` below ``lambda_1`` in
  modulus, ``t = cos(2 pi/n)`` in ``[t_0, 1)``;
* ``other-frequencies``: at every other frequency every root of ``p(x)`` below ``lambda_1``, for ``t`` in ``[-1, 1)``
  (``k = 3..n-3`` reach ``t <= cos(6 pi/n) < 1``).

Each "every root below ``lambda_1``" is the Schur-Cohn test of :func:`~symdecomp.algebra.schur_cohn.schur_cohn_conditions`
on ``p(lambda_1 y)``: finitely many polynomials in ``t``, each shown positive on its range by Sturm sequences, on the
half-open range where one vanishes only at ``t = 1`` (no frequency reaches it). Where one is not positive, the
computed witness is a ``t`` where it is not, and a valence ``n`` and frequency ``k`` where the block has an eigenvalue
of modulus ``>= lambda_1`` (certified in Arb). That shows the proof's ``lambda_1`` is not the dominant eigenvalue at
``n``, not that C1 fails (another eigenvalue may be the subdominant one of a C1 scheme): the step fails only where the
per-valence route's spectral conditions refute C1 at that ``n`` (a dominant eigenvalue not real, not double, not of one
pair of frequencies), citing them; otherwise it is ``open``, and :func:`c1_zorin_every_n` asks Zorin's test at a
witness beyond the certified valences, refuting with that ``n`` where it fails. The valences ``3..N0-1`` (``n = 3, 4`` have rules of
their own) are the per-valence route's spectral conditions (:func:`~symdecomp.verify.zoo_characteristic.spectral_conditions`).

This is the spectral half of C1. The characteristic map is certified per valence by Zorin's test
(:mod:`symdecomp.verify.c1_zorin`) for ``n = 3..last`` and is **not** proved for every ``n`` here, so the verdict for
every ``n`` (:func:`c1_zorin_every_n`) is ``undecided`` with that reason, never ``proved`` from the spectrum alone, and
``refuted`` only with a valence where the per-valence route refutes C1.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING

import sympy as sp

from symdecomp.algebra.schur_cohn import schur_cohn_conditions
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.stencils import N, StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_int, check_type
from symdecomp.verify.c1_every_n import EveryNResult, EveryNStep, T, c1_every_n, laurent_in_t
from symdecomp.verify.c1_uniform import t_lower_bound
from symdecomp.verify.every_n_signs import Decision, decide_positive
from symdecomp.verify.result import C1Verdict

if TYPE_CHECKING:
    from symdecomp.analysis.zoo_structure import ZooStructure
    from symdecomp.verify.c1_spectrum import SpectralResult
    from symdecomp.verify.c1_zoo import ZooC1Result

__all__ = ["FrequencyPolynomials", "frequency_polynomials", "zorin_lambda_one", "zorin_spectral_every_n", "c1_zorin_every_n"]

X = sp.Symbol("x")


class FrequencyPolynomials:
    """``p_k(x) = det(x I - B_k)`` for every ``n >= start``: ``{k: p}`` at the exceptional frequencies (in ``x`` and
    ``t = cos(2 pi/n)``; at ``k = 0`` the block bordered by the centre, in ``x`` and maybe ``n``) and ``other`` (in
    ``x`` and ``t = cos(2 pi k/n)``) at every other ``k``."""

    def __init__(self, at: dict[int, sp.Expr], other: sp.Expr, start: int) -> None:
        self.at = at
        self.other = other
        self.start = start
        #: The largest exceptional ``|k|``: every ``k`` with ``p < |k| < n - p`` is "other".
        self.reach = max(abs(k) for k in at)


def _sigma(st: ZooStructure, k: int | None) -> dict[sp.Symbol, sp.Expr]:
    return {sig: (s.otherwise if k is None else s.value(k)).subs(s.size, N) for sig, s in zip(st.sigma, st.symbols)}


def _coefficients_in_t(p: sp.Expr, what: str) -> sp.Expr:
    """``p`` (in ``x``, Laurent in ``omega``, maybe ``cos(2 pi q/n)``) with each coefficient a polynomial in ``t``."""
    from symdecomp.verify.c1_dual_every_n import in_t

    out = sp.Integer(0)
    for (power,), c in sp.Poly(sp.expand(p), X).terms():
        try:
            ct = in_t(laurent_in_t(c))
        except NotApplicableError as exc:
            raise NotApplicableError(f"{what}: {exc}") from None
        if ct is None or ct.has(N) or not sp.fraction(sp.cancel(ct))[1].is_number:
            raise NotApplicableError(f"{what}: the coefficient {c} of det(x I - B) is no polynomial in t alone")
        out += sp.expand(ct) * X**power
    return sp.expand(out)


def frequency_polynomials(scheme: StencilScheme) -> FrequencyPolynomials:
    """``det(x I - B_k)`` from the scheme's structural blocks (module docstring); :class:`NotApplicableError` (one line)
    where the blocks have no such form (a family that is no cosine sum, rules that are not mirror symmetric)."""
    from symdecomp.analysis.zoo_structure import zoo_structure

    check_type(scheme, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('modified-butterfly')")
    st = zoo_structure(scheme)
    if not st.has_centre:
        raise NotApplicableError(f"scheme {scheme.name!r}: no centre vertex (a dual scheme: c1_dual_every_n)")
    B = sp.Matrix(st.block)
    exceptional = sorted({k for s in st.symbols for k in s.at} | {-1, 0, 1}, key=lambda k: (abs(k), k))
    at: dict[int, sp.Expr] = {}
    for k in exceptional:
        Bk = B.xreplace(_sigma(st, k)).subs(OMEGA, OMEGA**k)
        if k == 0:
            b = [sp.sympify(e, strict=True).xreplace(_sigma(st, 0)) for e in st.border]
            K = st.class_count
            Bk = sp.Matrix([[b[0], *b[1:K + 1]]] + [[b[K + 1 + c], *Bk.subs(OMEGA, 1)[c, :]] for c in range(K)])
            at[0] = sp.expand(sp.factor(Bk.charpoly(X).as_expr()))
        else:
            at[k] = _coefficients_in_t(Bk.charpoly(X).as_expr(), f"frequency {k}")
    other = _coefficients_in_t(B.xreplace(_sigma(st, None)).charpoly(X).as_expr(), "every other frequency")
    return FrequencyPolynomials(at, other, st.valid_from)


def _lambda_one(polys: FrequencyPolynomials) -> tuple[sp.Expr | None, EveryNStep]:
    """``lambda_1``: the root of ``p_1`` of largest modulus at ``t_0`` (:func:`t_lower_bound`) among the roots of its
    factors linear in ``x`` (the same for every ``n``, or rational in ``t``:
    :mod:`symdecomp.verify.zorin_lambda_in_t`) and of its factors with rational coefficients (a constant algebraic
    number: :mod:`symdecomp.verify.zorin_lambda_algebraic`); ``None`` with the reason. The choice is a candidate: the
    other steps prove every other root below it, or fail."""
    from symdecomp.verify.zorin_lambda_algebraic import algebraic_lambda_one, constant_roots, larger_in_t
    from symdecomp.verify.zorin_lambda_in_t import linear_roots, varying_lambda_one

    p1 = polys.at[1]
    t0 = t_lower_bound(polys.start)
    roots = linear_roots(p1) + constant_roots(p1)
    lam = max(roots, key=lambda r: (abs(complex(r.subs(T, t0))), abs(complex(r.subs(T, 1)))), default=None)
    where = (polys.start, None)
    beyond = larger_in_t(p1, lam if lam is not None else sp.Integer(0), t0)
    if beyond is not None:
        return None, EveryNStep(f"lambda_1 from det(x I - B_1) = {sp.factor(p1)}: its largest root is a root of the factor "
                                f"{sp.factor(beyond)}, of degree {sp.degree(beyond, X)} in x with coefficients depending on "
                                "t (algebraic over Q(t)): not handled", "open", where, "lambda-one", ((r"p_1(x)", p1),))
    if lam is not None and lam.has(T):
        return lam, varying_lambda_one(p1, lam, t0, polys.start)
    if lam is not None and not lam.is_Rational:
        radius, step = algebraic_lambda_one(p1, lam, polys.start)
        return (lam if radius is not None else None), step
    if lam is None or not (0 < lam < 1):
        why = ("p_1 has no factor linear in x or with rational coefficients" if lam is None else
               f"the root {lam} is not in (0, 1)")
        return None, EveryNStep(f"lambda_1 from det(x I - B_1) = {sp.factor(p1)}: {why}", "open", where, "lambda-one",
                                ((r"p_1(x)", p1),))
    return lam, EveryNStep(f"lambda_1 = {lam}: the largest root of det(x I - B_1) = {sp.factor(p1)} that is the same for "
                           "every n", "proved", where, "lambda-one", ((r"p_1(x)", p1), (r"\lambda_1", lam)))


def _disc_step(name: str, what: str, poly: sp.Expr, lam: sp.Expr, low: sp.Expr, witness_k: int | None,
               start: int, reach: int, *, divide: bool = False) -> EveryNStep:
    """Every root of ``poly`` (divided by ``x - lam`` first where ``divide``) of modulus ``< lam`` on ``[low, 1)``
    (Schur-Cohn, Sturm; in ``Q(lambda_1)`` for an irrational ``lam``), or the computed witness."""
    from symdecomp.verify.zorin_lambda_algebraic import algebraic_radius, field_deltas, field_positive

    radius = None if lam.is_Rational or lam.has(T) else algebraic_radius(lam)
    if divide and radius is None:
        poly = sp.div(sp.Poly(poly, X), sp.Poly(X - lam, X))[0].as_expr()
    if lam.has(T):  # lambda_1(t) > 0 on the range (the lambda-one step): the unit disc of the scaled polynomial
        from symdecomp.verify.zorin_lambda_in_t import scaled_deltas

        deltas = scaled_deltas(poly, lam)
    else:
        deltas = schur_cohn_conditions(sp.Poly(poly, X), lam) if radius is None else field_deltas(poly, radius, divide=divide)
    formulas = tuple((rf"\delta_{{{j}}}(t)", d) for j, d in enumerate(deltas, 1))
    results: list[Decision] = []
    for d in deltas:
        r = (decide_positive(d, low, start=start, frequency=witness_k, reach=reach) if radius is None else
             Decision(*field_positive(d, radius, low, start=start, frequency=witness_k, reach=reach)))
        results.append(r)
        if r.status != "proved":
            break
    notes = "; ".join(r.note for r in results if r.note)
    constant = sp.Poly(poly, X).free_symbols <= {X}
    free = " (no coefficient depends on t)" if constant else ""
    scale = "lambda_1(t)" if lam.has(T) else lam if radius is None else f"({lam})"
    shown = (f"the {len(deltas)} Schur-Cohn polynomials of p({scale} y) are positive" if deltas else
             "it has no root (degree 0)")
    text = (f"{what}: det(x I - B) = {sp.factor(poly)}{free}; every root below lambda_1 = {lam} in modulus: "
            f"{shown}") + (f" ({notes})" if notes else "")
    last = results[-1] if results else None
    if last is None or last.status == "proved":
        return EveryNStep(text, "proved", (start, None), name, formulas)
    if last.status == "failed":
        return EveryNStep(f"{what}: det(x I - B) = {sp.factor(poly)} has a root of modulus >= lambda_1 = {lam}: "
                          f"{last.note}", "failed", (last.n, last.n) if last.n else (start, None), name, formulas)
    return EveryNStep(f"{what}: {last.note}", "open", (start, None), name, formulas)


def _zero_in_t(p0: sp.Expr) -> sp.Expr:
    """``det(x I - B_0)`` with each ``cos(2 pi q/n)`` as ``T_q(t)``, ``t = cos(2 pi/n)`` (as it is where it mixes them
    with ``n``)."""
    from symdecomp.verify.c1_dual_every_n import in_t

    out = in_t(p0)
    return p0 if out is None else sp.expand(out)


def _own_rules(scheme: StencilScheme) -> str:
    """``"; n = 3, 4 have rules of their own"`` for the valences the scheme's rules name (none: ``""``).

    >>> from symdecomp.schemes.stencil_files import load_zoo
    >>> _own_rules(load_zoo("modified-butterfly")), _own_rules(load_zoo("sqrt3"))
    ('; n = 3, 4 have rules of their own', '')
    """
    own = scheme.own_valences
    if not own:
        return ""
    return f"; n = {', '.join(map(str, own))} {'has rules of its' if len(own) == 1 else 'have rules of their'} own"


def _spectral_at(scheme: StencilScheme, n: int) -> SpectralResult:
    """The per-valence route's spectral conditions at ``n`` (exact factors of each block, certified gap): a
    :class:`~symdecomp.verify.c1_spectrum.SpectralResult`."""
    from symdecomp.analysis.zoo_matrix import zoo_matrix
    from symdecomp.analysis.zoo_spectrum import zoo_spectrum
    from symdecomp.verify.zoo_characteristic import real_matrix, spectral_conditions

    return spectral_conditions(zoo_spectrum(scheme, n, None, jordan=False), n, real_matrix=real_matrix(zoo_matrix(scheme, n)))


def _against_per_valence(scheme: StencilScheme, step: EveryNStep, seen: dict[int, SpectralResult]) -> EveryNStep:
    """A failed step of the proof for every ``n`` against the per-valence route at its witness valence.

    A root of modulus ``>= lambda_1`` shows that the proof's ``lambda_1`` (a root of a factor of ``p_1``) is not
    the dominant eigenvalue there; it does not disprove C1 by itself: another eigenvalue (another root of ``p_1``,
    another frequency) may be the subdominant one of a C1 scheme. The step stays ``failed`` only where C1 is refuted at
    that valence: the per-valence route's spectral conditions fail (a dominant eigenvalue not real, not double, not of
    one pair of frequencies ``j, n - j``), or they hold with ``j != 1`` (:func:`_winding`); otherwise it is ``open``
    with what the per-valence route found. A step without a witness is checked at its first valence; ``seen``: the
    spectral results by valence, computed once."""
    from symdecomp.verify.result import C1Verdict

    if step.status != "failed":
        return step
    n = step.valences[1] if step.valences[1] is not None else step.valences[0]
    r = seen[n] = seen.get(n) or _spectral_at(scheme, n)
    why = r.reason if r.status is C1Verdict.NOT_C1 else _winding(r) if r.status is C1Verdict.C1 else None
    if why is not None:
        return replace(step, text=f"{step.text}; at n = {n} the per-valence route refutes C1: {why}", valences=(n, n))
    found = ("its spectral conditions hold (the subdominant eigenvalue is another one, of frequencies 1, n - 1)"
             if r.status is C1Verdict.C1 else f"it is undecided ({r.reason})")
    return replace(step, status="open", text=f"{step.text}; this shows that the proof's lambda_1 is not the dominant "
                   f"eigenvalue at n = {n}, not that C1 fails: at n = {n} the per-valence route finds {found}",
                   valences=(n, n) if step.valences[1] is not None else step.valences)


def _winding(r: SpectralResult) -> str | None:
    """Why a real double subdominant eigenvalue of frequencies ``j, n - j`` with ``j != 1`` excludes C1, or ``None``.

    Its eigenvectors make the characteristic map commute with the rotation by one sector up to the rotation by
    ``2 pi j/n``, so the image of a loop around the centre winds ``j`` times modulo ``n``: never ``+-1`` for
    ``2 <= j <= n - 2``, and a regular, injective characteristic map, which C1 needs (Reif's and Zorin's necessary
    condition), winds once."""
    low = min(r.subdominant.frequencies) if r.subdominant is not None else 1
    if low == 1:
        return None
    return (f"the subdominant eigenvalue (real, double) is of the frequencies {low}, {r.n - low}, not "
            f"1, n - 1: its characteristic map winds {low} times modulo n = {r.n} around the centre, so it is not "
            "injective, which C1 needs")


def _per_valence(scheme: StencilScheme, start: int) -> EveryNStep | None:
    """The valences below the structural form's: the per-valence route's spectral conditions, exactly certified."""
    from symdecomp.verify.result import C1Verdict

    if start <= 3:
        return None
    regular = lattice(scheme.lattice).regular_valence
    for n in (n for n in range(3, start) if n != regular):
        r = _spectral_at(scheme, n)
        if r.status is not C1Verdict.C1:
            return EveryNStep(r.reason, "failed" if r.status is C1Verdict.NOT_C1 else "open", (n, n),
                              "below-structural")
    return EveryNStep(f"n = 3..{start - 1} but {regular} (below the structural form's first valence{_own_rules(scheme)}): "
                      "the spectral conditions certified valence by valence (exact factors of each block); "
                      f"n = {regular} is the regular vertex, whose rules Zorin's test checks on their own", "verified",
                      (3, start - 1), "below-structural")


def _witness_beyond(spectral: tuple[EveryNStep, ...], last: int, certify: Callable[[int], ZooC1Result]
                    ) -> tuple[int, EveryNStep, str] | None:
    """``(n, step, reason)``: an open step's witness valence beyond ``last`` (the valences ``3..last`` are certified
    already) where the per-valence test ``certify(n)`` refutes C1, the first such; ``None`` where none does."""
    for step in spectral:
        n = step.valences[1]
        if step.status == "open" and n is not None and n == step.valences[0] and n > last:
            r = certify(n)
            if r.verdict == C1Verdict.NOT_C1:
                return n, step, r.reason
    return None


def _map_open(scheme: StencilScheme, polys: FrequencyPolynomials | None) -> str:
    """The open map step's text: what of the map part for every ``n`` is derived
    (:mod:`symdecomp.verify.zorin_eigenvector_every_n`) and what remains."""
    from symdecomp.verify.zorin_eigenvector_every_n import every_n_eigenvector, remaining

    lead = "regularity and injectivity of the characteristic map beyond the certified valences are open: "
    try:
        return lead + remaining(every_n_eigenvector(scheme, polys=polys))
    except NotApplicableError as exc:
        return lead + f"the frequency-1 eigenvector on Zorin's neighbourhood has no closed form for every n here ({exc})"


def zorin_lambda_one(scheme: StencilScheme, polys: FrequencyPolynomials | None = None) -> sp.Expr | None:
    """``lambda_1`` for every ``n`` from the structural form (the ``lambda-one`` step): a constant, or a closed form in
    ``n`` (``cos(2 pi/n)`` for ``t``), or ``None`` where none is derived; ``polys``: the scheme's
    :func:`frequency_polynomials` where the caller has them already."""
    try:
        lam = _lambda_one(polys or frequency_polynomials(scheme))[0]
    except NotApplicableError:
        return None
    return None if lam is None else lam.subs(T, sp.cos(2 * sp.pi / N))


def zorin_spectral_every_n(scheme: StencilScheme, *, per_valence: bool = True,
                           polys: FrequencyPolynomials | None = None) -> tuple[EveryNStep, ...]:
    """The spectral conditions for every ``n`` (module docstring), each step with its status and witness; without
    ``per_valence`` the valences below the structural form are left to the caller (each costs an exact spectrum);
    ``polys``: the scheme's :func:`frequency_polynomials` where the caller has them already (they are not cached)."""
    polys = polys or frequency_polynomials(scheme)
    start, reach = polys.start, polys.reach
    lam, first = _lambda_one(polys)
    steps = [first]
    if first.status != "proved":
        lam = None
    if lam is not None:
        t0 = t_lower_bound(start)
        at0 = _zero_in_t(polys.at[0]) if lam.has(T) else polys.at[0]
        p0, rest = sp.div(sp.Poly(at0, X), sp.Poly(X - 1, X))
        if not rest.is_zero:
            steps.append(EveryNStep(f"1 is not a root of det(x I - B_0) = {sp.factor(polys.at[0])}", "failed",
                                    (start, None), "frequency-zero"))
        else:
            steps.append(_disc_step("frequency-zero", "k = 0, besides the eigenvalue 1", p0.as_expr(), lam, t0, 0, start,
                                    reach))
        for k in (1, -1):
            steps.append(_disc_step("frequency-one", f"k = {k}, besides lambda_1 (simple at this frequency)", polys.at[k],
                                    lam, t0, k, start, reach, divide=True))
        for k in (k for k in polys.at if abs(k) > 1):
            steps.append(_disc_step("frequency-exceptional", f"k = {k}", polys.at[k], lam, t0, k, start, reach))
        if lam.has(T):
            from symdecomp.verify.zorin_lambda_in_t import other_frequencies_in_t

            steps.append(other_frequencies_in_t(polys.other, lam, t0, start, reach))
        else:
            steps.append(_disc_step("other-frequencies", f"every other k ({reach + 1} <= k <= n - {reach + 1}, "
                                    "t = cos(2 pi k/n) in [-1, 1))", polys.other, lam, sp.Integer(-1), None, start, reach))
    seen: dict[int, SpectralResult] = {}
    steps = [_against_per_valence(scheme, s, seen) for s in steps]
    below = _per_valence(scheme, start) if per_valence else None
    return tuple(steps) + ((below,) if below else ())


def c1_zorin_every_n(scheme: StencilScheme, last: int = 16, *, progress: Callable[[int], None] | None = None,
                     certify: Callable[[int], ZooC1Result] | None = None, max_depth: int = 6,
                     per_valence: bool = True, polys: FrequencyPolynomials | None = None) -> EveryNResult:
    """C1 for every valence as far as it is shown: the spectral steps for every ``n``, Zorin's test at ``3..last``
    (``certify(n)``, by default :func:`~symdecomp.verify.c1_zoo.c1_zoo`); the map is not proved for every ``n``, so the
    verdict is ``undecided`` (or ``refuted`` with a valence where the per-valence route refutes C1: Zorin's test, or the
    spectral conditions at a failed step's witness). ``polys``: the scheme's
    :func:`frequency_polynomials` where the caller has them already."""
    from symdecomp.verify.c1_zoo import c1_zoo

    check_type(scheme, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('modified-butterfly')")
    last = check_int(last, "last", minimum=3)
    certify = certify or (lambda k: c1_zoo(scheme, k, max_depth=max_depth))
    try:
        polys = polys or frequency_polynomials(scheme)
        spectral = zorin_spectral_every_n(scheme, per_valence=per_valence, polys=polys)
    except NotApplicableError as exc:
        spectral = (EveryNStep(f"the spectral conditions for every n are not read: {exc}", "open", (3, None), "spectral"),)
    result = c1_every_n(scheme, last, progress=progress, certify=certify, spectral_steps=lambda: spectral,
                        map_every_n=lambda lo, last: None, fails_from=lambda k, certify: None, first=3)
    steps = tuple(replace(s, text="Zorin's test at each valence: the spectral conditions and a regular, injective "
                          "characteristic map, certified (Arb balls)")
                  if s.name == "reif-per-valence" else replace(s, text=_map_open(scheme, polys))
                  if s.name == "map-open" else s for s in result.steps)
    failed = [s for s in spectral if s.status == "failed"]
    if result.status == "refuted":
        return replace(result, steps=steps)
    if failed:  # each one refuted by the per-valence route at its valence (_against_per_valence), whatever 3..last gave
        n = failed[0].valences[0]
        return replace(result, steps=steps, status="refuted", failure=n, summary=f"C1 fails at n = {n}: {failed[0].text}")
    if result.status == "undecided" and result.certified[1] < last:
        return replace(result, steps=steps)
    refuted = _witness_beyond(spectral, last, certify)
    if refuted is not None:
        n, step, reason = refuted
        return replace(result, steps=steps + (EveryNStep(reason, "failed", (n, n), "zorin-at-witness"),), status="refuted",
                       failure=n, summary=f"C1 fails at n = {n}, where Zorin's test refutes it ({reason}); the proof's step "
                       f"{step.name} had found that valence: {step.text}")
    shown = all(s.status in ("proved", "verified") for s in spectral)
    spectral_text = ("the spectral conditions hold for every n (proved for n >= "
                     f"{max(s.valences[0] for s in spectral)}, certified per valence below)" if shown else
                     "the spectral conditions are not shown for every n")
    return replace(result, steps=steps, status="undecided",
                   summary=f"{spectral_text}; the characteristic map is certified by Zorin's test at n = 3..{last} only "
                           "and not proved for every n, so C1 for every n is undecided")
