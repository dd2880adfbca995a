"""Reif's spectral conditions for C1, certified per frequency in Arb (with exact steps where they decide).

The conditions (Reif 1995; Peters and Reif 2008, Section 5.1) on the ``(6n + 1) x (6n + 1)``
2-ring subdivision matrix whose eigenvectors generate the characteristic map
(:mod:`symdecomp.analysis.characteristic`):

1. 1 is an eigenvalue, simple;
2. the next largest eigenvalue in modulus, ``lambda``, is real, of algebraic and geometric
   multiplicity 2, and strictly larger in modulus than every other eigenvalue.

The matrix is block-circulant, so its spectrum is the union over frequencies ``j`` of the
spectra of ``B_j``; each ``B_j`` is block lower triangular, so that is the union of the spectra
of the 1-ring blocks (the exact ``3 x 3`` Eq. 43 matrix at ``j = 0``, the ``2 x 2`` ``M_j``
otherwise) and of the outer blocks ``S_j`` (the regular rules). The eigenvalues of ``M_j``
(and those of ``M_{n-j} = conj(M_j)``) are enclosed from its trace and determinant; those of
``S_j`` are bounded by ``||S_j^k||_inf^{1/k}`` (``k = 1, 2, 4``). If ``lambda`` is a simple root of
``M_j`` for some ``0 < j < n/2`` and strictly dominates everything else, it has algebraic and
geometric multiplicity 2 (one eigenvector at ``j``, one at ``n - j``). ``lambda`` is real when
the trace and determinant of ``M_j`` are real (exactly: Laurent polynomials in ``omega``
symmetric under ``omega -> 1/omega``) and the discriminant is positive. At ``j = 0`` everything
is exact: the Eq. 43 characteristic polynomial is ``(x - 1) q(x)`` over ``Q``, a double root of
``q`` is rational and its Jordan block is found by exact ranks. Balls of two frequencies that
overlap at the top are compared exactly (characteristic polynomials over ``Q(e^{2 pi i / n})``,
reduced modulo the cyclotomic polynomial): equal values make ``lambda``'s multiplicity larger than
2 (not C1), which no precision would separate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import flint
import sympy as sp

from symdecomp.analysis.characteristic import check_applicable, frequency_block
from symdecomp.analysis.defective import jordan_block_size
from symdecomp.analysis.frequency import per_frequency_matrix, recursion_matrix
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_valence

__all__ = ["Eigen", "SpectralResult", "spectral_conditions", "ball_text", "float_down", "round_down"]

_X = sp.Symbol("x")


def ball_text(ball, digits: int = 6) -> str:
    """A ball as a short decimal (real part if the imaginary part may be 0)."""
    if isinstance(ball, flint.acb):
        if ball.imag.contains(0):
            ball = ball.real
        else:
            return f"{ball.real.str(digits, radius=False)} {'+' if ball.imag > 0 else '-'} {abs(ball.imag).str(digits, radius=False)}i"
    return ball.str(digits, radius=False)


def float_down(x: flint.arb) -> float:
    """A float ``<=`` every point of the ball ``x`` (its lower end, rounded down, not to nearest)."""
    value = float(x.lower())
    return value if flint.arb(value) <= x.lower() else math.nextafter(value, -math.inf)


def round_down(x: float, digits: int = 4) -> float:
    """``x > 0`` rounded *down* to ``digits`` significant digits, so that a lower bound stays one when printed.

    >>> round_down(0.27999076), round_down(0.25)
    (0.2799, 0.25)
    """
    scale = 10 ** (digits - 1 - math.floor(math.log10(x)))
    return math.floor(x * scale) / scale


@dataclass(frozen=True)
class Eigen:
    """An eigenvalue (ball) of the 2-ring matrix with the frequency it comes from."""

    value: flint.acb
    frequency: int
    #: Number of copies in the full matrix (frequencies ``j`` and ``n - j``).
    multiplicity: int
    #: A double root of the Eq. 43 block with a Jordan block (geometric multiplicity 1).
    defective: bool = False
    #: Index of the root within its block (0: the larger in modulus).
    root: int = 0
    #: One of two complex conjugate roots of the same block (real trace and determinant): equal moduli.
    pair: bool = False


@dataclass(frozen=True)
class SpectralResult:
    """The outcome of the spectral test at one valence."""

    n: int
    #: ``'ok'``, ``'not-c1'`` or ``'undecided'``.
    status: str
    reason: str
    #: The subdominant eigenvalue (``None`` if not determined).
    subdominant: Eigen | None = None
    #: Lower bound of ``|lambda| - max |other eigenvalue|`` (``None`` unless ``status == 'ok'``).
    gap: float | None = None
    #: Upper bound of the largest modulus of the other eigenvalues.
    second: float | None = None


@lru_cache(maxsize=32)
def _symmetric_trace_det(scheme: Scheme) -> tuple[sp.Expr, sp.Expr]:
    M = per_frequency_matrix(scheme)
    return sp.expand(M.trace()), sp.expand(M.det())


def _real_at(scheme: Scheme, n: int) -> bool:
    """Whether trace and det of ``M_j`` are real for every ``j`` (symmetric Laurent polynomials in omega)."""
    return all(sp.expand((e - e.subs(OMEGA, 1 / OMEGA)).subs(N, n)) == 0 for e in _symmetric_trace_det(scheme))


def _quadratic_roots(t: flint.acb, d: flint.acb) -> tuple[flint.acb, flint.acb]:
    """The roots of ``x^2 - t x + d``, larger modulus first (midpoints; a double root gets two equal balls)."""
    disc = t * t - 4 * d
    if disc.real.contains(0) and disc.imag.contains(0):
        # near a double root: |sqrt(disc)| <= sqrt(|disc|), a far tighter ball than Arb's branch-cut-safe sqrt
        r = abs(disc).upper().sqrt().upper()
        root = flint.acb(flint.arb(0, r), flint.arb(0, r))
    elif disc.real < 0:
        root = flint.acb(0, 1) * (-disc).sqrt()  # away from the branch cut of sqrt: either root of disc will do
    else:
        root = disc.sqrt()
    a, b = (t + root) / 2, (t - root) / 2
    return (a, b) if abs(a).mid() >= abs(b).mid() else (b, a)


def _outer_bound(S: flint.acb_mat) -> flint.arb:
    """``min_k ||S^k||_inf^{1/k}`` for ``k = 1, 2, 4``: an upper bound of the spectral radius."""
    best, power = None, S
    for k in (1, 2, 4):
        if k > 1:
            power = power * power
        norm = max(sum((abs(power[r, c]) for c in range(power.ncols())), flint.arb(0)) for r in range(power.nrows()))
        bound = norm if k == 1 else norm.root(k)
        best = bound if best is None or bound.upper() < best.upper() else best
    return best


def _frequency_zero(scheme: Scheme, n: int) -> tuple[list[Eigen], str | None]:
    """The non-unit eigenvalues of Eq. 43 (exact where it matters); a failure reason if 1 is not simple."""
    A = sp.Matrix(recursion_matrix(scheme, n))
    p = sp.Poly((_X * sp.eye(3) - A).det(), _X)
    q, r = sp.div(p, sp.Poly(_X - 1, _X))
    if r.as_expr() != 0:
        return [], "1 is not an eigenvalue of the frequency-0 block (the rules are not affine)"
    if q.eval(1) == 0:
        return [], "the eigenvalue 1 is not simple: it is a double root of the frequency-0 block (Eq. 43)"
    coefficients = q.all_coeffs()
    if not all(sp.sympify(x).is_Rational for x in coefficients):
        raise InvalidSchemeError(
            f"scheme {scheme.name!r}: the C1 test needs rational weights at each valence; at n = {n} the frequency-0 "
            f"block has the characteristic polynomial {p.as_expr()}"
        )
    _, b, c = (sp.Rational(x) for x in coefficients)
    disc = b * b - 4 * c
    if disc == 0:
        mu = -b / 2
        ball = flint.acb(flint.fmpq(int(mu.p), int(mu.q)))
        defective = jordan_block_size(scheme, n, mu) == 2
        return [Eigen(ball, 0, 2, defective=defective)], None
    B, C = (flint.acb(flint.fmpq(int(x.p), int(x.q))) for x in (b, c))
    r1, r2 = _quadratic_roots(-B, C)
    pair = disc < 0
    return [Eigen(r1, 0, 1, root=0, pair=pair), Eigen(r2, 0, 1, root=1, pair=pair)], None


def _other_frequencies(scheme: Scheme, n: int) -> tuple[list[Eigen], list[tuple[int, flint.arb]]]:
    """The eigenvalues of ``M_j`` (``0 < j <= n/2``) and the bounds of the outer blocks ``S_j`` (``0 <= j <= n/2``)."""
    eigen, outer = [], []
    real = _real_at(scheme, n)
    for j in range(0, n // 2 + 1):
        B = frequency_block(scheme, n, j)
        S = flint.acb_mat([[B[2 + r, 2 + c] for c in range(4)] for r in range(4)])
        outer.append((j, _outer_bound(S)))
        if j == 0:
            continue
        t, d = B[0, 0] + B[1, 1], B[0, 0] * B[1, 1] - B[0, 1] * B[1, 0]
        mult = 1 if 2 * j == n else 2
        r1, r2 = _quadratic_roots(t, d)
        pair = real and (t * t - 4 * d).real < 0  # real trace and determinant: the roots are conjugate
        eigen += [Eigen(r1, j, mult, root=0, pair=pair), Eigen(r2, j, mult, root=1, pair=pair)]
    return eigen, outer


_Z = sp.Symbol("z")


def _exact_coefficients(scheme: Scheme, n: int, j: int) -> tuple[sp.Poly, sp.Poly] | None:
    """``(t, d)`` with ``x^2 - t x + d`` the characteristic polynomial of the block of frequency ``j``, exactly.

    ``t`` and ``d`` are polynomials in ``z = e^{2 pi i / n}`` reduced modulo the cyclotomic polynomial
    ``Phi_n`` (irreducible over Q, so a reduced polynomial is 0 iff its value at ``z`` is). At
    ``j = 0`` the block is the quotient ``q`` of Eq. 43 by ``x - 1``; ``None`` if it is not a quadratic.
    """
    phi = sp.Poly(sp.cyclotomic_poly(n, _Z), _Z)
    if j == 0:
        A = sp.Matrix(recursion_matrix(scheme, n))
        q = sp.div(sp.Poly((_X * sp.eye(3) - A).det(), _X), sp.Poly(_X - 1, _X))[0]
        if q.degree() != 2:
            return None
        _, b, c = q.all_coeffs()
        return sp.Poly(-b, _Z), sp.Poly(c, _Z)
    out = []
    for e in _symmetric_trace_det(scheme):
        num, den = sp.fraction(sp.together(sp.expand(e.subs(N, n))))
        # den = const * omega^k: divide by omega^k as multiplying by z^(j (n k - k)) = z^(-j k) mod z^n - 1
        k = sp.Poly(den, OMEGA).degree()
        const = sp.Poly(den, OMEGA).LC()
        value = sp.expand(num.subs(OMEGA, _Z**j) * _Z ** (j * k * (n - 1)) / const)
        out.append(sp.Poly(value, _Z).rem(phi))
    return out[0], out[1]


def _ball_at(poly: sp.Poly, n: int) -> flint.acb:
    from symdecomp.analysis.characteristic import omega_ball

    z = omega_ball(n, 1)
    return sum((flint.acb(flint.fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q))) * z**e for (e,), c in poly.terms()), flint.acb(0))


def _exactly_equal(scheme: Scheme, n: int, eigen: list[Eigen], e1: Eigen, e2: Eigen) -> bool:
    """Whether the (overlapping) balls ``e1`` and ``e2`` of two different frequencies hold the same eigenvalue, exactly.

    Monic quadratics ``x^2 - t_i x + d_i`` share a root iff they are equal or, with ``a = t_2 - t_1 != 0``,
    ``b = d_1 - d_2``, the root ``r = -b / a`` of their difference satisfies ``b^2 + t_1 a b + d_1 a^2 = 0``
    (exact, in ``Q(z)``); the shared root is ``e1`` and ``e2`` when ``r``'s ball misses both other roots.
    """
    p1, p2 = _exact_coefficients(scheme, n, e1.frequency), _exact_coefficients(scheme, n, e2.frequency)
    if p1 is None or p2 is None:
        return False
    siblings = [e for e in eigen if (e.frequency, e.root) in ((e1.frequency, 1 - e1.root), (e2.frequency, 1 - e2.root))]
    (t1, d1), (t2, d2) = p1, p2
    a, b = t2 - t1, d1 - d2
    if a.is_zero:
        if not b.is_zero:
            return False
        return all(not s.value.overlaps(e1.value) for s in siblings)  # the same polynomial: e1, e2 the same root
    if not (b * b + t1 * a * b + d1 * a * a).rem(sp.Poly(sp.cyclotomic_poly(n, _Z), _Z)).is_zero:
        return False
    r = -_ball_at(b, n) / _ball_at(a, n)
    return all(not s.value.overlaps(r) for s in siblings)


def spectral_conditions(scheme: Scheme, n: int) -> SpectralResult:
    """Reif's spectral conditions at valence ``n``, certified (see the module docstring)."""
    n = check_valence(n)
    check_applicable(scheme)
    eigen, failure = _frequency_zero(scheme, n)
    if failure:
        return SpectralResult(n, "not-c1", failure)
    more, outer = _other_frequencies(scheme, n)
    eigen += more
    dom = max(eigen, key=lambda e: abs(e.value).mid())
    top = abs(dom.value)
    # the conjugate of a non-real root of the same block has the same modulus: compare the pair as one
    others = [e for e in eigen if e is not dom and not (dom.pair and e.pair and e.frequency == dom.frequency)]
    tied = [e for e in others if not abs(e.value) < top and e.frequency != dom.frequency
            and _exactly_equal(scheme, n, eigen, dom, e)]
    others = [e for e in others if e not in tied]
    second = max([abs(e.value) for e in others] + [b for _, b in outer], key=lambda x: x.upper())
    for e in others:
        if not abs(e.value) < top:
            return SpectralResult(
                n, "undecided", f"the eigenvalues {ball_text(dom.value)} (frequency {dom.frequency}) and "
                f"{ball_text(e.value)} (frequency {e.frequency}) are not separated in modulus at this precision",
            )
    for j, bound in outer:
        if not bound < top:
            return SpectralResult(
                n, "undecided", f"the outer eigenvalues at frequency {j} are bounded only by {ball_text(bound)}, "
                f"not below |lambda| = {ball_text(top)}",
            )
    if not top < 1:
        return SpectralResult(
            # Arb's ``>=`` holds only when every point of the ball is >= 1 (an exact -1 at frequency 0 is)
            n, "not-c1" if top >= 1 else "undecided",
            f"the eigenvalue {ball_text(dom.value)} at frequency {dom.frequency} is not smaller than 1 in modulus", dom,
        )
    if tied:
        where = ", ".join(str(e.frequency) for e in [dom, *tied])
        total = dom.multiplicity + sum(e.multiplicity for e in tied)
        return SpectralResult(
            n, "not-c1", f"the largest eigenvalue after 1, {ball_text(dom.value)}, is exactly the same at frequencies "
            f"{where}: multiplicity {total}, not 2", dom,
        )
    gap = float_down((top - second).lower())
    if dom.pair:
        return SpectralResult(
            n, "not-c1", f"the largest eigenvalues after 1 are the complex conjugate pair {ball_text(dom.value)} at "
            f"frequency {dom.frequency}: the subdominant eigenvalue is not real", dom, gap, float(second.upper()),
        )
    if dom.frequency == 0 or 2 * dom.frequency == n:
        tangent = max((e for e in eigen if e.frequency == 1), key=lambda e: abs(e.value).mid())
        if dom.defective:
            what = "has algebraic multiplicity 2 but geometric multiplicity 1 (a Jordan block)"
        else:
            what = f"has multiplicity {dom.multiplicity}, not 2"
        return SpectralResult(
            n, "not-c1", f"the largest eigenvalue after 1 is {ball_text(dom.value)} at frequency {dom.frequency}, which "
            f"{what}; it exceeds the frequency-1 (tangent-plane) eigenvalue {ball_text(tangent.value)}",
            dom, gap, float(second.upper()),
        )
    return _real_subdominant(scheme, n, dom, gap, float(second.upper()))


def _real_subdominant(scheme: Scheme, n: int, dom: Eigen, gap: float, second: float) -> SpectralResult:
    """The verdict once ``dom`` (frequency ``0 < j < n/2``) is strictly dominant: ok iff it is certainly real and simple."""
    if dom.value.imag.contains(0) and _real_at(scheme, n):
        B = frequency_block(scheme, n, dom.frequency)
        t, d = B[0, 0] + B[1, 1], B[0, 0] * B[1, 1] - B[0, 1] * B[1, 0]
        disc = (t * t - 4 * d).real
        if disc > 0:
            return SpectralResult(n, "ok", f"lambda = {ball_text(dom.value)} at frequency {dom.frequency}, real, "
                                  f"multiplicity 2, gap >= {round_down(gap)}", dom, gap, second)
    if not dom.value.imag.contains(0):
        return SpectralResult(n, "not-c1", f"the subdominant eigenvalue {ball_text(dom.value)} at frequency {dom.frequency} is not real", dom)
    return SpectralResult(n, "undecided", f"could not show that the subdominant eigenvalue {ball_text(dom.value)} is real and simple", dom)
