"""Where a component of the 1-ring starts relative to the eigenvectors of ``M_j`` (Eq. 35-38, Remark 5.1).

The component ``j`` of the 1-ring 2n-gon (Eq. 11) has ``B^j = zeta A^j`` with
``zeta = omega_2n^j = exp(i pi j/n)`` (Eq. 24), and it moves by ``M(omega)`` with
``omega = zeta^2`` (Eq. 33). Its amplitudes start as the vector ``(1, zeta)``. That vector is
an eigenvector of ``M(zeta^2)`` exactly when the residual

    ``R(zeta) = m10 + m11 zeta - (m00 + m01 zeta) zeta``

vanishes; the eigenvalue is then ``m00 + m01 zeta``. ``R`` is a Laurent polynomial in
``zeta``: with rational weights it vanishes at a root of unity of order ``m`` iff the
cyclotomic polynomial ``Phi_m`` divides it, and only finitely many ``m`` can (``phi(m)`` is
at most its degree). So the frequencies where a component starts on a single eigenvector are
found exactly, for every valence at once.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> start = initial_vector_condition(catmull_clark())
>>> start.orders                      # only at zeta = +-i: j = n/2 (even n)
(4,)
>>> sorted({p.n for p in start.points(10)})   # the valences up to 10 where some component is affected
[4, 6, 8, 10]
"""

from __future__ import annotations

from dataclasses import dataclass
from math import gcd

import mpmath
import sympy as sp

from symdecomp.analysis.frequency import per_frequency_matrix
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached

__all__ = ["ZETA", "InitialVectorCondition", "StartPoint", "initial_vector_condition", "root_of_unity_orders", "vanishes_at_root_of_unity"]

#: ``zeta = omega_2n^j``, the ratio ``B^j / A^j`` of a component of the 1-ring (Eq. 24).
ZETA = sp.Symbol("zeta")


def _polynomial(expr: sp.Expr) -> tuple[sp.Poly, int]:
    """``expr`` (a Laurent polynomial in zeta) as ``zeta^shift * poly``: the polynomial and ``shift``."""
    expr = sp.expand(expr)
    if expr == 0:
        return sp.Poly(0, ZETA), 0
    low = min(int(sp.Poly(sp.expand(term * ZETA**64), ZETA).monoms()[0][0]) - 64 for term in sp.Add.make_args(expr))
    return sp.Poly(sp.expand(expr * ZETA ** (-low)), ZETA), low


def root_of_unity_orders(expr: sp.Expr) -> tuple[int, ...] | None:
    """The orders ``m`` of the roots of unity at which ``expr`` (Laurent in ZETA, rational coefficients) vanishes.

    ``None`` when ``expr`` is identically zero (it vanishes everywhere).

    >>> root_of_unity_orders(ZETA**2 + 1), root_of_unity_orders(ZETA**3 - 1), root_of_unity_orders(ZETA - 2)
    ((4,), (1, 3), ())
    """
    poly, _ = _polynomial(expr)
    if poly.is_zero:
        return None
    if not all(c.is_Rational for c in poly.all_coeffs()):
        raise NotApplicableError("the condition has coefficients that are not rational numbers (weights depending on n or on parameters)")
    orders = set()
    for factor, _ in sp.factor_list(poly.as_expr(), ZETA)[1]:
        d = sp.degree(factor, ZETA)
        for m in range(1, 2 * d * d + 3):
            if sp.totient(m) == d and sp.expand(sp.Poly(factor, ZETA).monic().as_expr() - sp.cyclotomic_poly(m, ZETA)) == 0:
                orders.add(m)
    return tuple(sorted(orders))


def vanishes_at_root_of_unity(expr: sp.Expr, order: int) -> bool:
    """True when the Laurent polynomial ``expr`` in ZETA is zero at the primitive roots of unity of ``order``."""
    poly, _ = _polynomial(expr)
    remainder = sp.rem(poly, sp.Poly(sp.cyclotomic_poly(order, ZETA), ZETA))
    return all(sp.simplify(c) == 0 for c in remainder.all_coeffs())


@dataclass(frozen=True)
class StartPoint:
    """A frequency where the component starts on one eigenvector of ``M_j``."""

    #: The valence and the component ``j`` (``zeta = exp(i pi j/n)``).
    n: int
    j: int
    #: ``M_j`` is a multiple of the identity there (every vector is an eigenvector; Eq. 36-37 read 0/0).
    scalar: bool
    #: The eigenvalue of the eigenvector the component starts on, and the other eigenvalue.
    eigenvalue: sp.Expr
    other: sp.Expr
    #: ``|eigenvalue| < |other|``: the component has no part on the dominant eigenvector.
    below_dominant: bool


@dataclass(frozen=True)
class InitialVectorCondition:
    """When does the initial vector ``(1, zeta)`` lie on an eigenvector of ``M(zeta^2)``?"""

    scheme: Scheme
    #: ``R(zeta)``: zero exactly where it does.
    residual: sp.Expr
    #: The eigenvalue there, ``m00 + m01 zeta``.
    eigenvalue: sp.Expr
    #: The trace of ``M(zeta^2)`` (the other eigenvalue is the trace minus the eigenvalue).
    trace: sp.Expr
    #: Orders of the roots of unity ``zeta`` where ``R`` vanishes (``None``: everywhere).
    orders: tuple[int, ...] | None

    def holds_at(self, n: int, j: int) -> bool:
        """Exactly: does component ``j`` of valence ``n`` start on an eigenvector?"""
        order = 2 * n // gcd(j, 2 * n)
        return self.orders is None or order in self.orders

    def point(self, n: int, j: int, *, dps: int = 50) -> StartPoint:
        """The eigenvalues at component ``j`` of valence ``n`` (where :meth:`holds_at`)."""
        zeta = sp.exp(sp.I * sp.pi * sp.Rational(j, n))
        M = per_frequency_matrix(self.scheme).subs(OMEGA, ZETA**2)
        order = 2 * n // gcd(j, 2 * n)
        off = [sp.expand(M[0, 1]), sp.expand(M[1, 0]), sp.expand(M[0, 0] - M[1, 1])]
        scalar = all(vanishes_at_root_of_unity(e, order) for e in off)
        lam = sp.expand(self.eigenvalue.subs(N, n))
        other = sp.expand(self.trace.subs(N, n) - lam)
        # |x(zeta)|^2 = x(zeta) x(1/zeta) on the unit circle (real weights): equal moduli is an exact test
        modulus_gap = sp.expand(lam * lam.subs(ZETA, 1 / ZETA) - other * other.subs(ZETA, 1 / ZETA))
        below = False
        if not scalar and not vanishes_at_root_of_unity(modulus_gap, order):
            with mpmath.workdps(dps):
                below = sp.N(modulus_gap.subs(ZETA, zeta), dps).as_real_imag()[0] < 0
        exact = lambda e: sp.simplify(e.subs(ZETA, zeta))  # noqa: E731
        return StartPoint(n, j, scalar, exact(lam), exact(other), bool(below))

    def points(self, last: int, *, frequencies=None) -> list[StartPoint]:
        """Every ``(n, j)`` with ``3 <= n <= last`` (``j`` in ``frequencies(n)``, default ``1..2n-1``
        without ``n``) where the component starts on an eigenvector."""
        out = []
        for n in range(3, last + 1):
            for j in frequencies(n) if frequencies else [k for k in range(1, 2 * n) if k != n]:
                if self.holds_at(n, j):
                    out.append(self.point(n, j))
        return out


@cached(scheme=check_scheme)
def initial_vector_condition(scheme: Scheme) -> InitialVectorCondition:
    """The exact condition for ``(1, zeta)`` to be an eigenvector of ``M(zeta^2)`` (module docstring)."""
    M = per_frequency_matrix(scheme).subs(OMEGA, ZETA**2)
    lam = sp.expand(M[0, 0] + M[0, 1] * ZETA)
    residual = sp.expand(M[1, 0] + M[1, 1] * ZETA - lam * ZETA)
    trace = sp.expand(M[0, 0] + M[1, 1])
    return InitialVectorCondition(scheme, residual, lam, trace, root_of_unity_orders(residual))
