"""The curvature regime at an extraordinary vertex for every valence: per valence up to a point, in n beyond it.

The regime compares ``|mu|``, the largest eigenvalue after 1 and ``lambda_1``, with ``lambda_1^2``
(:mod:`symdecomp.analysis.curvature_regime`). The curvature is unbounded as soon as *some* eigenvalue other than 1
and ``lambda_1`` exceeds ``lambda_1^2`` in modulus; the hyperbolic one, the dominant eigenvalue of ``M`` at frequency
2, is the candidate. With ``s = cos(2 pi/n)``, ``lambda_1 = rho(s)`` and ``lambda_2 = rho(2 s^2 - 1)`` (``rho`` the
dominant eigenvalue of ``M(t)``, ``t = cos(2 pi j/n)``; :mod:`symdecomp.verify.c1_every_n`), so

    f(s) = rho(2 s^2 - 1) - rho(s)^2 > 0 for every s in [s_0, 1]

proves the regime unbounded for every ``n`` with ``cos(2 pi/n) >= s_0``: on triangles (``M`` is ``1 x 1``) ``f`` is a
polynomial and Sturm sequences decide it exactly; on quads (``rho = (tr + sqrt(disc))/2``) the interval ``[s_0, 1]``
(``n = oo`` included) is covered by Arb balls, bisected until each ball's enclosure of ``f`` is positive: a proof over
the continuum, not a sample. ``s_0`` is a rational below ``cos(2 pi/N)``; the valences below ``N`` keep their
certified per-valence regimes (:func:`~symdecomp.verify.second_order_spectrum.second_order_eigenstructure`). This
proves the regime; which part causes it is :func:`hyperbolic_cause_from` (on quads, where Catmull-Clark's elliptic and
hyperbolic eigenvalues meet at ``n = oo``, by a bound in ``n``: :mod:`symdecomp.verify.regime_cause`).
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.algebraic_sign import rational_between
from symdecomp.algebra.numbers import to_arb
from symdecomp.algebra.valence_signs import sign_on_interval
from symdecomp.analysis.curvature_regime import CurvatureRegime
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.verify.c1_every_n import EveryNStep, T, laurent_in_t

__all__ = ["RegimeEveryN", "unbounded_from", "regime_every_n"]

#: Deepest bisection of ``[s_0, 1]`` (2^18 balls at most).
MAX_DEPTH = 18


@dataclass(frozen=True)
class RegimeEveryN:
    """The regime at every valence: a certified one per valence below ``first_proved``, unbounded from there on."""

    scheme: str
    #: ``(n, regime)`` for the valences certified one by one.
    per_valence: tuple[tuple[int, str], ...]
    #: The valence from which the regime is proved unbounded for every larger one (``None``: not proved).
    first_proved: int | None
    steps: tuple[EveryNStep, ...]

    def as_json(self) -> dict:
        return {"scheme": self.scheme, "per_valence": [{"n": k, "regime": r} for k, r in self.per_valence],
                "unbounded_from": self.first_proved, "steps": [s.as_json() for s in self.steps]}


def _rho(tr, disc):
    return (tr + disc.sqrt()) / 2


def _positive_on(f, lo: flint.arb, hi: flint.arb, depth: int = 0) -> bool:
    """``f(ball) > 0`` on every ball of a bisection of ``[lo, hi]`` (Arb)."""
    ball = flint.arb((lo + hi) / 2, (hi - lo) / 2)
    value = f(ball)
    if value > 0:
        return True
    if depth >= MAX_DEPTH or value < 0:  # certainly negative (a ball that straddles 0, or a nan, is split)
        return False
    mid = (lo + hi) / 2
    return _positive_on(f, lo, mid, depth + 1) and _positive_on(f, mid, hi, depth + 1)


def unbounded_from(scheme: Scheme, first: int) -> EveryNStep | None:
    """The regime is unbounded for every ``n >= first`` (``lambda_2 > lambda_1^2``), or ``None`` where not shown."""
    check_scheme(scheme)
    M = sp.Matrix(one_ring_matrices(scheme)[0])
    if M.has(N) or scheme.parameters:
        return None
    s = sp.Symbol("s", real=True)
    # a rational just below cos(2 pi/first) (and above cos(2 pi/(first - 1)), which is further below): the interval starts there
    s0 = rational_between(sp.cos(2 * sp.pi / first) - sp.Rational(1, 10**4), sp.cos(2 * sp.pi / first))
    if M.rows == 1:
        lam = laurent_in_t(M[0, 0])
        f = sp.expand(lam.subs(T, 2 * s**2 - 1) - lam.subs(T, s) ** 2)
        if not (sign_on_interval(f, s, s0, 1) and sign_on_interval(lam.subs(T, s), s, s0, 1)):
            return None
        how = f"lambda_2 - lambda_1^2 = {f} > 0 for s = cos(2 pi/n) in [{s0}, 1] (Sturm sequences; lambda_1 > 0 there)"
    else:
        tr, det = laurent_in_t(M.trace()), laurent_in_t(M.det())
        disc = sp.expand(tr**2 - 4 * det)
        if not sign_on_interval(disc, T, -1, 1, strict=False):
            return None
        coefficients = [[to_arb(c) for c in reversed(sp.Poly(p, T).all_coeffs())] for p in (tr, disc)]

        def poly(cs, x):
            out = flint.arb(0)
            for c in reversed(cs):
                out = out * x + c
            return out

        def f(x):
            t2 = 2 * x * x - 1
            lam1 = _rho(poly(coefficients[0], x), poly(coefficients[1], x))
            return _rho(poly(coefficients[0], t2), poly(coefficients[1], t2)) - lam1 * lam1

        with flint.ctx.workprec(128):
            if not _positive_on(f, to_arb(s0), flint.arb(1)):
                return None
        how = (f"rho(2 s^2 - 1) - rho(s)^2 > 0 for s = cos(2 pi/n) in [{s0}, 1], rho = (tr + sqrt(disc))/2 with tr = {tr}, "
               f"disc = {sp.factor(disc)} (Arb balls covering the interval, n = oo included)")
    return EveryNStep(f"for every n >= {first} the hyperbolic eigenvalue exceeds lambda_1^2, so the curvature is unbounded: "
                      + how, "proved", (first, None))


def hyperbolic_cause_from(scheme: Scheme, first: int) -> EveryNStep | None:
    """For every ``n >= first`` the largest eigenvalue after 1 and ``lambda_1`` is the hyperbolic one (frequencies 2,
    n - 2), or ``None`` where not shown. On quads: :func:`~symdecomp.verify.regime_cause.hyperbolic_cause_on_quads`. On
    triangles (``M`` is ``1 x 1``): ``lambda(t)`` increases with ``t`` (the other
    frequencies are below frequency 2), ``lambda_2`` exceeds the outer ring's eigenvalues on ``[s_0, 1]``, and the
    frequency-0 eigenvalue besides 1 is ``lambda_1^2`` identically (below ``lambda_2`` by :func:`unbounded_from`)."""
    from symdecomp.analysis.characteristic import outer_charpoly
    from symdecomp.verify.c1_every_n import spectral_every_n

    M = sp.Matrix(one_ring_matrices(scheme)[0])
    if M.has(N) or unbounded_from(scheme, first) is None:
        return None
    if M.rows == 2:  # rho has a square root: the frequency-0 roots against a bound in n (symdecomp.verify.regime_cause)
        from symdecomp.verify.regime_cause import hyperbolic_cause_on_quads

        return hyperbolic_cause_on_quads(scheme, first)
    if M.rows != 1:
        return None
    if not all(step.status == "proved" for step in spectral_every_n(scheme)):
        return None
    lam, s, x = laurent_in_t(M[0, 0]), sp.Symbol("s", real=True), sp.Symbol("x")
    radius = max((abs(r) for r in sp.Poly(list(outer_charpoly(scheme.lattice)), x).all_roots()), key=float)
    s0 = rational_between(sp.cos(2 * sp.pi / first) - sp.Rational(1, 10**4), sp.cos(2 * sp.pi / first))
    if not (sign_on_interval(sp.diff(lam, T), T, -1, 1) and sign_on_interval(lam.subs(T, 2 * s**2 - 1) - radius, s, s0, 1)):
        return None
    return EveryNStep(f"for every n >= {first} the hyperbolic eigenvalue is the largest after 1 and lambda_1: lambda(t) = {lam} "
                      f"increases with t (frequencies 3..n-3 are below), lambda_2 > {radius} (the outer ring) for s in "
                      f"[{s0}, 1], and the frequency-0 eigenvalue besides 1 is lambda_1^2 < lambda_2", "proved", (first, None))


def regime_every_n(scheme: Scheme, last: int = 16) -> RegimeEveryN:
    """Certified regimes at ``n = 3..`` until the unbounded regime is proved for every larger ``n`` (at most ``last``)."""
    from symdecomp.verify.second_order_spectrum import second_order_eigenstructure

    rows: list[tuple[int, str]] = []
    lo = max(3, scheme.minimum_valence())
    for k in range(lo, last + 1):
        regime = second_order_eigenstructure(scheme, k).regime
        if regime is CurvatureRegime.NOT_APPLICABLE:
            raise NotApplicableError(f"scheme {scheme.name!r}: the curvature regime does not apply at n = {k}")
        if regime is CurvatureRegime.UNBOUNDED and k > lo and (step := unbounded_from(scheme, k)) is not None:
            certified = EveryNStep("the regime at each valence, certified (Arb balls; ties exact): "
                                   + ", ".join(f"{m}: {r}" for m, r in rows), "verified", (lo, k - 1))
            cause = hyperbolic_cause_from(scheme, k)  # which part makes it unbounded, where that is shown for every n
            return RegimeEveryN(scheme.name, tuple(rows), k, (certified, step) + ((cause,) if cause else ()))
        rows.append((k, regime.value))
    certified = EveryNStep("the regime at each valence, certified: " + ", ".join(f"{m}: {r}" for m, r in rows),
                           "verified", (lo, last))
    return RegimeEveryN(scheme.name, tuple(rows), None, (certified, EveryNStep(
        f"no argument for every n beyond the certified valences (the unbounded regime is not shown from any n <= {last} on)", "open",
        (last + 1, None))))
