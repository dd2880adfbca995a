"""Hyperbolic properties (Section 5.3): the ``j = 2`` components against ``lambda_1^2``.

The components ``A^2, A^{2n-2}, B^2, B^{2n-2}`` move by ``M_2`` (Eq. 33 at ``j = 2``). For a
quadratic (hyperbolic paraboloid) limit shape, their part perpendicular to the tangent
plane has to shrink like ``lambda_1^2``: the dominant eigenvalue ``lambda_2`` of ``M_2`` should
equal the square of the dominant eigenvalue ``lambda_1`` of ``M_1``.

:func:`hyperbolic_ring` builds the paper's configuration with only hyperbolic components
off the tangent plane; :func:`iterate_hyperbolic_ring` iterates it with the exact
subdivision matrix in ``Q(zeta_4n)`` and compares with the prediction from ``M_1`` and ``M_2``.

>>> from symdecomp.schemes import catmull_clark
>>> hyperbolic_equality(catmull_clark()).valences
(4,)
>>> it = iterate_hyperbolic_ring(catmull_clark(), 5, steps=3)
>>> it.matches_prediction, it.elliptic_component_zero
(True, True)
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import flint
import mpmath
import sympy as sp

from .cyclotomic import CyclotomicField
from .elliptic import tangent_lambda
from .errors import check_valence
from .frequency import COS, per_frequency_matrix
from .schemes import Scheme, subdivision_matrix
from .symbols import n as N
from .symbols import omega as OMEGA
from .tangent import tangent_eigenvalues

__all__ = [
    "hyperbolic_lambda",
    "hyperbolic_defect",
    "HyperbolicEquality",
    "hyperbolic_equality",
    "hyperbolic_ring",
    "HyperbolicIteration",
    "iterate_hyperbolic_ring",
]


def hyperbolic_lambda(scheme: Scheme) -> sp.Expr:
    """``lambda_2(n)``: the dominant eigenvalue of ``M_2`` (Eq. 34 with ``c = cos(2 pi/n)``)."""
    return tangent_lambda(scheme, 2)


def hyperbolic_defect(scheme: Scheme) -> sp.Expr:
    """``lambda_2(n) - lambda_1(n)^2``: zero when the hyperbolic part shrinks with quadratic speed."""
    return hyperbolic_lambda(scheme) - tangent_lambda(scheme, 1) ** 2


@dataclass(frozen=True)
class HyperbolicEquality:
    """Where ``lambda_2 = lambda_1^2`` holds, decided for every ``n``."""

    #: A polynomial in ``c = cos(pi/n)`` vanishing wherever ``lambda_2 = lambda_1^2`` (a resultant).
    polynomial: sp.Expr
    #: Its real roots ``c`` in ``[1/2, 1)``.
    roots: tuple[sp.Expr, ...]
    #: The valences where ``lambda_2 = lambda_1^2`` exactly.
    valences: tuple[int, ...]


@lru_cache(maxsize=None)
def hyperbolic_equality(scheme: Scheme) -> HyperbolicEquality:
    """Decide ``lambda_2 = lambda_1^2`` for all ``n``.

    ``lambda_1`` is a root ``L`` of the characteristic polynomial of ``M_1`` (in ``c``) and
    ``lambda_2`` a root of that of ``M_2``, whose coefficients are polynomials in
    ``cos(2 pi/n) = 2c^2 - 1``. Substituting ``lambda_2 = L^2`` and taking the resultant in ``L``
    leaves a polynomial in ``c``; only its roots in ``[1/2, 1)`` can be valences, and each
    candidate is checked exactly.
    """
    c = sp.Symbol("c", positive=True)
    L = sp.Symbol("L", positive=True)
    ev = tangent_eigenvalues(scheme)
    char1 = sp.expand(ev.characteristic_polynomial.subs({COS: c, sp.Symbol("lambda"): L}))
    char2 = sp.expand(ev.characteristic_polynomial.subs({COS: 2 * c**2 - 1, sp.Symbol("lambda"): L**2}))
    polynomial = sp.factor(sp.resultant(char2, char1, L))
    defect = hyperbolic_defect(scheme)
    roots, valences = [], []
    for root in sp.Poly(polynomial, c).real_roots():
        if sp.Rational(1, 2) <= root < 1:
            roots.append(root)
            with mpmath.workdps(50):
                m = mpmath.pi / mpmath.acos(mpmath.mpf(sp.N(root, 60)))
                k = int(mpmath.nint(m))
                if abs(m - k) < mpmath.mpf(10) ** -40 and sp.simplify(defect.subs(N, k)) == 0:
                    valences.append(k)
    return HyperbolicEquality(polynomial, tuple(dict.fromkeys(roots)), tuple(sorted(set(valences))))


def hyperbolic_ring(n: int, height=1) -> sp.ImmutableMatrix:
    """The paper's 1-ring with only hyperbolic components off the tangent plane (Section 5.3).

    ``O`` is at the origin, on the plane of ``A^1, A^{2n-1}, B^1, B^{2n-1}`` (the regular convex
    2n-gon in the ``xy``-plane), so the elliptic input of Eq. 43 is zero; a real combination of
    ``v_2`` and ``v_{2n-2}`` (the 2n-gon's frequency 2) is added along ``z``, perpendicular to
    the ring. Vertex ``k`` of the 2n-gon is ``(cos(pi k/n), sin(pi k/n), height*cos(2 pi k/n))``;
    ``a_i`` is vertex ``2i`` and ``b_i`` vertex ``2i + 1``. Rows in the order
    ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` of :func:`~symdecomp.schemes.subdivision_matrix`.
    """
    n = check_valence(n)
    height = sp.sympify(height)

    def vertex(k):
        return [sp.cos(sp.pi * k / n), sp.sin(sp.pi * k / n), height * sp.cos(2 * sp.pi * k / n)]

    rows = [[0, 0, 0]] + [vertex(2 * i) for i in range(n)] + [vertex(2 * i + 1) for i in range(n)]
    return sp.ImmutableMatrix(rows)


@dataclass(frozen=True)
class HyperbolicIteration:
    """The hyperbolic ring under the exact subdivision matrix, against the per-frequency prediction."""

    #: The valence.
    n: int
    #: Number of subdivision steps.
    steps: int
    #: Whether ``S^k ring`` equals the prediction from ``M_1^k`` (tangent) and ``M_2^k`` (normal) for every ``k``, exactly.
    matches_prediction: bool
    #: Whether ``O`` and the centroids of the ``a``'s and ``b``'s stay at height 0 (no elliptic component), exactly.
    elliptic_component_zero: bool
    #: ``|X_2^(k)| / |X_1^(k)|^2`` for ``k = 0..steps``: normal amplitude over squared tangent amplitude.
    normal_over_tangent_squared: tuple[object, ...]
    #: ``lambda_2/lambda_1^2``, the predicted asymptotic growth factor of that ratio per step.
    predicted_factor: object


def _conj(F: CyclotomicField, p) -> flint.fmpq_poly:
    total = flint.fmpq_poly([0])
    for k, a in enumerate(p.coeffs()):
        if a != 0:
            total += F.zeta(-k) * a
    return F.reduce(total)


def _modulus(F: CyclotomicField, p) -> mpmath.mpf:
    z = mpmath.exp(2j * mpmath.pi / F.m)
    return abs(sum(mpmath.mpf(int(a.p)) / int(a.q) * z**k for k, a in enumerate(p.coeffs())))


def iterate_hyperbolic_ring(scheme: Scheme, n: int, steps: int = 4, *, digits: int = 30) -> HyperbolicIteration:
    """Iterate :func:`hyperbolic_ring` (height 1) with the exact matrix and compare with the prediction.

    Exact arithmetic in ``Q(zeta_4n)``: the tangent coordinates ``x + i y`` of ``a_i``, ``b_i`` are
    ``X_1 omega^i``, ``Y_1 omega^i`` with ``(X_1, Y_1) = M_1^k (1, omega_2n)``; the heights are
    ``Re(X_2 omega^(2i))``, ``Re(Y_2 omega^(2i))`` with ``(X_2, Y_2) = M_2^k (1, omega_2n^2)``.
    """
    n = check_valence(n)
    if steps < 0:
        raise ValueError(f"steps must be >= 0, got {steps}")
    F = CyclotomicField(4 * n)
    S = subdivision_matrix(scheme, n)
    zero, half = F.rational(0), F.rational(1, 2)
    x = [zero] + [F.cos(2 * (2 * i)) for i in range(n)] + [F.cos(2 * (2 * i + 1)) for i in range(n)]
    y = [zero] + [F.sin(2 * (2 * i)) for i in range(n)] + [F.sin(2 * (2 * i + 1)) for i in range(n)]
    z = [zero] + [F.cos(4 * (2 * i)) for i in range(n)] + [F.cos(4 * (2 * i + 1)) for i in range(n)]

    M = per_frequency_matrix(scheme)

    def block(j):
        return [[F.from_laurent(_laurent(M[r, s]), 4 * j) for s in range(2)] for r in range(2)]

    M1, M2 = block(1), block(2)
    X1, Y1 = F.rational(1), F.zeta(2)  # (1, omega_2n)
    X2, Y2 = F.rational(1), F.zeta(4)  # (1, omega_2n^2)
    i_unit = F.zeta(n)
    ok, flat = True, True
    ratios = []
    with mpmath.workdps(digits + 10):
        for k in range(steps + 1):
            if k:
                x, y, z = F.matvec(S, x), F.matvec(S, y), F.matvec(S, z)
                X1, Y1 = F.reduce(M1[0][0] * X1 + M1[0][1] * Y1), F.reduce(M1[1][0] * X1 + M1[1][1] * Y1)
                X2, Y2 = F.reduce(M2[0][0] * X2 + M2[0][1] * Y2), F.reduce(M2[1][0] * X2 + M2[1][1] * Y2)
            for i in range(n):
                for idx, (amp1, amp2) in ((1 + i, (X1, X2)), (1 + n + i, (Y1, Y2))):
                    t = F.mul(amp1, F.zeta(4 * i))
                    tc = _conj(F, t)
                    px, py = F.mul(t + tc, half), F.mul(F.mul(t - tc, half), -i_unit)
                    h = F.mul(amp2, F.zeta(8 * i))
                    pz = F.mul(h + _conj(F, h), half)
                    ok &= F.is_zero(x[idx] - px) and F.is_zero(y[idx] - py) and F.is_zero(z[idx] - pz)
            flat &= F.is_zero(x[0]) and F.is_zero(y[0]) and F.is_zero(z[0])
            flat &= F.is_zero(sum(z[1 : n + 1], zero)) and F.is_zero(sum(z[n + 1 :], zero))
            ratios.append(_modulus(F, X2) / _modulus(F, X1) ** 2)
        lam1 = mpmath.mpf(sp.Float(sp.N(tangent_lambda(scheme, 1).subs(N, n), digits + 10), digits + 10)._mpf_)
        lam2 = mpmath.mpf(sp.Float(sp.N(hyperbolic_lambda(scheme).subs(N, n), digits + 10), digits + 10)._mpf_)
        factor = lam2 / lam1**2
    return HyperbolicIteration(n, steps, bool(ok), bool(flat), tuple(ratios), factor)


def _laurent(expr) -> dict[int, sp.Expr]:
    from .frequency import _laurent_terms

    return {k: v for k, v in _laurent_terms(sp.expand(expr)).items() if v != 0}
