"""Hyperbolic properties (Section 5.3): the ``j = 2`` components against ``lambda_1^2``.

The components ``A^2, A^{2n-2}, B^2, B^{2n-2}`` move by ``M_2`` (Eq. 33 at ``j = 2``). For a
quadratic (hyperbolic paraboloid) limit shape, their part perpendicular to the tangent
plane has to shrink like ``lambda_1^2``: the dominant eigenvalue ``lambda_2`` of ``M_2`` should
equal the square of the dominant eigenvalue ``lambda_1`` of ``M_1``.

:func:`hyperbolic_ring` builds the paper's configuration with only hyperbolic components
off the tangent plane; :func:`iterate_hyperbolic_ring` iterates it with the exact
subdivision matrix in ``Q(zeta_4n)`` and compares with the prediction from ``M_1`` and ``M_2``.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> hyperbolic_equality(catmull_clark()).valences
(4,)
>>> it = iterate_hyperbolic_ring(catmull_clark(), 5, steps=3)
>>> it.matches_prediction, it.elliptic_component_zero
(True, True)
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.algebra.numbers import to_fraction
from symdecomp.analysis.elliptic import tangent_lambda
from symdecomp.analysis.frequency import per_frequency_matrix, valences_at_roots
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.errors import InvalidInputError
from symdecomp.expressions import exact_value
from symdecomp.schemes.scheme import Scheme, check_scheme, subdivision_matrix
from symdecomp.symbols import cos_jtheta, cos_theta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.validate import cached, check_digits, check_levels, check_valence

__all__ = [
    "hyperbolic_lambda",
    "hyperbolic_defect",
    "HyperbolicEquality",
    "hyperbolic_equality",
    "hyperbolic_ring",
    "HyperbolicIteration",
    "iterate_hyperbolic_ring",
    "apply_rational_matrix",
]

#: Most subdivision steps :func:`iterate_hyperbolic_ring` takes (exact numbers grow with every step).
MAX_STEPS = 100


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


@cached(scheme=check_scheme)
def hyperbolic_equality(scheme: Scheme) -> HyperbolicEquality:
    """Decide ``lambda_2 = lambda_1^2`` for all ``n``.

    ``lambda_1`` is a root ``L`` of the characteristic polynomial of ``M_1`` (in ``c``) and
    ``lambda_2`` a root of that of ``M_2``, whose coefficients are polynomials in
    ``cos(2 pi/n) = 2c^2 - 1``. Substituting ``lambda_2 = L^2`` and taking the resultant in ``L``
    leaves a polynomial in ``c``; only its roots in ``[1/2, 1)`` can be valences, and each
    candidate is checked exactly.
    """
    c = cos_theta
    L = sp.Symbol("L", positive=True)
    ev = tangent_eigenvalues(scheme)
    char1 = sp.expand(ev.characteristic_polynomial.subs({cos_jtheta: c, LAM: L}))
    char2 = sp.expand(ev.characteristic_polynomial.subs({cos_jtheta: 2 * c**2 - 1, LAM: L**2}))
    polynomial = sp.factor(sp.resultant(char2, char1, L))
    defect = hyperbolic_defect(scheme)
    roots, valences = valences_at_roots(polynomial, c, lambda k: sp.simplify(defect.subs(N, k)) == 0)
    return HyperbolicEquality(polynomial, roots, valences)


def hyperbolic_ring(n: int, height=1) -> sp.ImmutableMatrix:
    """The paper's 1-ring with only hyperbolic components off the tangent plane (Section 5.3).

    ``O`` is at the origin, on the plane of ``A^1, A^{2n-1}, B^1, B^{2n-1}`` (the regular convex
    2n-gon in the ``xy``-plane), so the elliptic input of Eq. 43 is zero; a real combination of
    ``v_2`` and ``v_{2n-2}`` (the 2n-gon's frequency 2) is added along ``z``, perpendicular to
    the ring. Vertex ``k`` of the 2n-gon is ``(cos(pi k/n), sin(pi k/n), height*cos(2 pi k/n))``;
    ``a_i`` is vertex ``2i`` and ``b_i`` vertex ``2i + 1``. Rows in the order
    ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` of :func:`~symdecomp.schemes.scheme.subdivision_matrix`.
    """
    n = check_valence(n)
    height = exact_value(height, argument="height")

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


def apply_rational_matrix(matrix: sp.MatrixBase, vector: list) -> list:
    """``matrix @ vector`` for a rational sympy matrix and cyclotomic-field elements (exact).

    For ``vector^T @ matrix`` pass ``matrix.T``.
    """
    rows, cols = matrix.shape
    if cols != len(vector):
        raise InvalidInputError(f"matrix has {cols} columns but the vector has {len(vector)} entries")
    out = []
    for r in range(rows):
        acc = None
        for s_ in range(cols):
            w = matrix[r, s_]
            if w != 0:
                term = vector[s_] * to_fraction(w)
                acc = term if acc is None else acc + term
        out.append(acc if acc is not None else vector[0] * 0)
    return out


def _laurent_in(K: CyclotomicField, expr, unit: int):
    """A Laurent polynomial in ``omega`` (rational coefficients) at ``omega = zeta^unit``."""
    total = K(0)
    for k, c in _laurent(expr).items():
        total = total + K.zeta(unit * k) * K(sp.Rational(c))
    return total


def iterate_hyperbolic_ring(scheme: Scheme, n: int, steps: int = 4, *, digits: int = 30) -> HyperbolicIteration:
    """Iterate :func:`hyperbolic_ring` (height 1) with the exact matrix and compare with the prediction.

    Exact arithmetic in ``Q(zeta_4n)``: the tangent coordinates ``x + i y`` of ``a_i``, ``b_i`` are
    ``X_1 omega^i``, ``Y_1 omega^i`` with ``(X_1, Y_1) = M_1^k (1, omega_2n)``; the heights are
    ``Re(X_2 omega^(2i))``, ``Re(Y_2 omega^(2i))`` with ``(X_2, Y_2) = M_2^k (1, omega_2n^2)``.
    """
    check_scheme(scheme)
    n, digits = check_valence(n), check_digits(digits)
    steps = check_levels(steps, "steps", maximum=MAX_STEPS, reason="the exact numbers grow with every step")
    S = subdivision_matrix(scheme, n)
    K = CyclotomicField(4 * n)

    def cos(k):  # cos(2 pi k/(4n))
        return (K.zeta(k) + K.zeta(-k)) / 2

    def sin(k):
        return (K.zeta(k) - K.zeta(-k)) / (2 * K.i)

    zero = K(0)
    x = [zero] + [cos(2 * (2 * i)) for i in range(n)] + [cos(2 * (2 * i + 1)) for i in range(n)]
    y = [zero] + [sin(2 * (2 * i)) for i in range(n)] + [sin(2 * (2 * i + 1)) for i in range(n)]
    z = [zero] + [cos(4 * (2 * i)) for i in range(n)] + [cos(4 * (2 * i + 1)) for i in range(n)]

    M = per_frequency_matrix(scheme).subs(N, n)  # an edge rule in n: at this valence (a question at one valence)
    M1 = [[_laurent_in(K, M[r, c], 4) for c in range(2)] for r in range(2)]
    M2 = [[_laurent_in(K, M[r, c], 8) for c in range(2)] for r in range(2)]
    X1, Y1 = K(1), K.zeta(2)  # (1, omega_2n)
    X2, Y2 = K(1), K.zeta(4)  # (1, omega_2n^2)
    ok, flat = True, True
    ratios = []
    with mpmath.workdps(digits + 10):
        for k in range(steps + 1):
            if k:
                x, y, z = apply_rational_matrix(S, x), apply_rational_matrix(S, y), apply_rational_matrix(S, z)
                X1, Y1 = M1[0][0] * X1 + M1[0][1] * Y1, M1[1][0] * X1 + M1[1][1] * Y1
                X2, Y2 = M2[0][0] * X2 + M2[0][1] * Y2, M2[1][0] * X2 + M2[1][1] * Y2
            for i in range(n):
                for idx, (amp1, amp2) in ((1 + i, (X1, X2)), (1 + n + i, (Y1, Y2))):
                    t = amp1 * K.zeta(4 * i)  # x + i y of the vertex
                    h = amp2 * K.zeta(8 * i)
                    ok &= x[idx] == t.real() and y[idx] == t.imag() and z[idx] == h.real()
            flat &= x[0] == 0 and y[0] == 0 and z[0] == 0
            flat &= sum(z[1 : n + 1], zero) == 0 and sum(z[n + 1 :], zero) == 0
            ratios.append(abs(X2.to_mpc()) / abs(X1.to_mpc()) ** 2)
        lam1, lam2 = (_mp(e.subs(N, n), digits + 10) for e in (tangent_lambda(scheme, 1), hyperbolic_lambda(scheme)))
        factor = lam2 / lam1**2
        factor = factor.real if factor.imag == 0 else factor  # complex where an edge rule in n makes M_1's roots complex
    return HyperbolicIteration(n, steps, bool(ok), bool(flat), tuple(ratios), factor)


def _mp(expr, dps: int):
    """A number as an mpmath value at ``dps`` digits (``mpc`` if it is not real)."""
    re, im = sp.N(expr, dps).as_real_imag()
    return mpmath.mpc(*(mpmath.mpf(sp.Float(x, dps)._mpf_) for x in (re, im)))


def _laurent(expr) -> dict[int, sp.Expr]:
    from symdecomp.analysis.frequency import _laurent_terms

    return {k: v for k, v in _laurent_terms(sp.expand(expr)).items() if v != 0}
