"""Tangent-plane behaviour: closed-form eigenvalues and eigenvectors of ``M_j`` (Section 5.1).

The eigenvalues are derived from the characteristic polynomial of the per-frequency matrix
(Eq. 33) rewritten in ``c = cos(j*theta)``, ``theta = pi/n`` (Eq. 34). The *dominant* one is
the root with the larger value, which for a real discriminant means ``+ sqrt`` with ``|c|``.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> ev = tangent_eigenvalues(catmull_clark())
>>> ev.dominant
c**2/8 + sqrt(c**2 + 4)*Abs(c)/8 + 1/4
>>> ev.trace, ev.determinant
(c**2/4 + 1/2, 1/16)
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.analysis.frequency import laurent_to_cos, per_frequency_matrix
from symdecomp.errors import FrequencyOutOfRangeError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_frequency, check_int, check_valence

__all__ = [
    "TangentEigenvalues",
    "tangent_eigenvalues",
    "complex_at",
    "eigenvector_second_component",
    "invariant_ratio",
    "invariant_ratio_at",
    "invariant_ratio_limit",
]


@dataclass(frozen=True)
class TangentEigenvalues:
    """The two eigenvalues of ``M_j`` in closed form, in ``c = cos(j*theta)`` (Eq. 34)."""

    #: ``trace(M_j)`` in ``c`` (and ``s = sin(j*theta)`` for a non-symmetric scheme).
    trace: sp.Expr
    #: ``det(M_j)`` in ``c``.
    determinant: sp.Expr
    #: ``trace^2 - 4 det``, factored.
    discriminant: sp.Expr
    #: The characteristic polynomial ``lambda^2 - trace*lambda + det``.
    characteristic_polynomial: sp.Expr
    #: ``(trace + sqrt(discriminant))/2``: the larger eigenvalue when the discriminant is >= 0.
    dominant: sp.Expr
    #: ``(trace - sqrt(discriminant))/2``.
    subdominant: sp.Expr

    def at(self, n: int, j: int) -> tuple[sp.Expr, sp.Expr]:
        """The two exact eigenvalues at a concrete valence ``n`` and frequency ``0 <= j < 2n``."""
        n = check_valence(n)
        j = check_frequency(j, n)
        subs = {cos_jtheta: sp.cos(sp.pi * sp.Rational(j, n)), sin_jtheta: sp.sin(sp.pi * sp.Rational(j, n))}
        return self.dominant.subs(subs), self.subdominant.subs(subs)


@cached(scheme=check_scheme)
def tangent_eigenvalues(scheme: Scheme) -> TangentEigenvalues:
    """Derive the closed-form eigenvalues of ``M_j`` for ``scheme`` (Eq. 34)."""
    M = per_frequency_matrix(scheme)
    trace = laurent_to_cos(M.trace())
    det = laurent_to_cos(sp.expand(M.det()))
    disc = sp.factor(sp.expand(trace**2 - 4 * det))
    root = sp.sqrt(disc)
    charpoly = sp.expand(LAM**2 - trace * LAM + det)
    return TangentEigenvalues(
        trace=trace,
        determinant=det,
        discriminant=disc,
        characteristic_polynomial=charpoly,
        dominant=sp.expand(trace / 2 + root / 2),
        subdominant=sp.expand(trace / 2 - root / 2),
    )


def complex_at(scheme: Scheme, n: int) -> bool:
    """Whether ``M_1`` has complex eigenvalues at valence ``n``: its discriminant (Eq. 34) is negative at
    ``c = cos(pi/n)``, decided exactly (then the real closed forms of the masks do not apply)."""
    n = check_valence(n)
    disc = tangent_eigenvalues(scheme).discriminant.subs(cos_jtheta, sp.cos(sp.pi / n))
    return bool(disc.is_negative)


def eigenvector_second_component(scheme: Scheme, eigenvalue: sp.Expr = LAM) -> sp.Expr:
    """Second component of the eigenvector ``(1, y)`` of ``M_j`` from its second row (Eq. 36-37).

    ``m21 X + (m22 - lambda) Y = 0`` gives ``y = m21/(lambda - m22)``. Undefined where
    ``lambda = m22`` (for Catmull-Clark: ``lambda = 1/4``, i.e. ``cos(j*theta) = 0``).
    """
    M = per_frequency_matrix(scheme)
    return M[1, 0] / (eigenvalue - M[1, 1])


def invariant_ratio(scheme: Scheme) -> sp.Expr:
    """``B^j / A^j`` on the dominant eigenvector of ``M_j`` (Eq. 39), in ``omega`` and ``c``.

    The paper writes it as the ``r`` with ``A^j = r B^j``; the value it prints for ``n = 4``
    (``1 + i``) is ``B^1/A^1``, which is what this returns (see the claim "Eq. 39").
    """
    return eigenvector_second_component(scheme, tangent_eigenvalues(scheme).dominant)


def _omega_and_cos(n, j):
    return {OMEGA: sp.exp(2 * sp.pi * sp.I * j / n), cos_jtheta: sp.cos(sp.pi * j / n), sin_jtheta: sp.sin(sp.pi * j / n)}


def invariant_ratio_at(scheme: Scheme, n: int, j: int = 1) -> sp.Expr:
    """The exact ratio of Eq. 39 at a concrete ``n`` and ``0 <= j < 2n``, simplified (radicals, no guessing)."""
    n = check_valence(n)
    j = check_frequency(j, n)
    value = invariant_ratio(scheme).subs(_omega_and_cos(sp.Integer(n), sp.Integer(j)))
    if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise FrequencyOutOfRangeError(f"the ratio of Eq. 39 is undefined at n = {n}, j = {j} (lambda = m22 there)")
    return sp.radsimp(sp.simplify(sp.expand_complex(value)))


def invariant_ratio_limit(scheme: Scheme, j: int = 1) -> sp.Expr:
    """``lim_{n -> oo}`` of the ratio of Eq. 39 at fixed ``j``, computed by ``sympy.limit``."""
    check_scheme(scheme)
    j = check_int(j, "frequency j", minimum=1, error=FrequencyOutOfRangeError)
    m = sp.Symbol("m", positive=True)
    value = invariant_ratio(scheme).subs(_omega_and_cos(m, sp.Integer(j)))
    return sp.simplify(sp.limit(value, m, sp.oo))
