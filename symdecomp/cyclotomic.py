"""Exact arithmetic in the cyclotomic field ``Q(zeta_m)``, for checks against the exact matrices.

The coordinates of a regular polygon (``cos(2 pi k/m)``, ``sin(2 pi k/m)``, the roots of unity
``omega_n^j``) all lie in ``Q(zeta_m)`` for a suitable ``m``. An element is kept as a
polynomial in ``x = zeta_m`` with rational coefficients reduced modulo the cyclotomic
polynomial ``Phi_m`` (python-flint), so that "is zero" is decided exactly, with no
floating point and no sympy simplification.

>>> F = CyclotomicField(8)
>>> z = F.zeta()
>>> F.is_zero(z**4 + 1)
True
>>> F.is_zero(F.cos(1) ** 2 - F.rational(1, 2))
True
"""

from __future__ import annotations

from fractions import Fraction

import flint
import sympy as sp

from .errors import check_valence

__all__ = ["CyclotomicField"]


class CyclotomicField:
    """``Q(zeta_m)``: elements are ``flint.fmpq_poly`` in ``zeta_m`` reduced mod ``Phi_m``."""

    def __init__(self, m: int):
        self.m = check_valence(m, minimum=1)
        self.modulus = flint.fmpq_poly(flint.fmpz_poly.cyclotomic(self.m).coeffs())

    def reduce(self, p: flint.fmpq_poly) -> flint.fmpq_poly:
        return p % self.modulus

    def rational(self, num, den=1) -> flint.fmpq_poly:
        """The rational number ``num/den`` (or a sympy/Fraction rational) as a field element."""
        q = sp.Rational(num, den)
        return flint.fmpq_poly([flint.fmpq(int(q.p), int(q.q))])

    def zeta(self, power: int = 1) -> flint.fmpq_poly:
        """``zeta_m^power`` (any integer power)."""
        coeffs = [0] * (power % self.m) + [1]
        return self.reduce(flint.fmpq_poly(coeffs))

    def cos(self, k: int) -> flint.fmpq_poly:
        """``cos(2 pi k/m) = (zeta^k + zeta^-k)/2``."""
        return self.reduce((self.zeta(k) + self.zeta(-k)) * flint.fmpq(1, 2))

    def sin(self, k: int) -> flint.fmpq_poly:
        """``sin(2 pi k/m)``; needs ``4 | m`` so that ``i = zeta_m^(m/4)`` is in the field."""
        if self.m % 4:
            raise ValueError(f"sin needs the imaginary unit: Q(zeta_{self.m}) has it only when 4 divides {self.m}")
        minus_i = self.zeta(-self.m // 4)
        return self.reduce((self.zeta(k) - self.zeta(-k)) * minus_i * flint.fmpq(1, 2))

    def from_laurent(self, terms: dict[int, object], unit_power: int = 1) -> flint.fmpq_poly:
        """``sum_k c_k zeta^(unit_power*k)`` for rational ``c_k`` (a Laurent polynomial in a root of unity)."""
        total = flint.fmpq_poly([0])
        for k, c in terms.items():
            total += self.zeta(unit_power * k) * self.rational(c)
        return self.reduce(total)

    def mul(self, p, q) -> flint.fmpq_poly:
        return self.reduce(p * q)

    def is_zero(self, p) -> bool:
        return self.reduce(p) == 0

    def matvec(self, matrix: sp.MatrixBase, vector: list) -> list:
        """``matrix @ vector`` for a rational sympy matrix and a list of field elements (exact)."""
        rows, cols = matrix.shape
        if cols != len(vector):
            raise ValueError(f"matrix has {cols} columns but the vector has {len(vector)} entries")
        out = []
        for r in range(rows):
            acc = flint.fmpq_poly([0])
            for s in range(cols):
                w = matrix[r, s]
                if w != 0:
                    acc += vector[s] * _fmpq(w)
            out.append(self.reduce(acc))
        return out

    def vecmat(self, vector: list, matrix: sp.MatrixBase) -> list:
        """``vector^T @ matrix`` (a row vector times a rational matrix), exact."""
        return self.matvec(matrix.T, vector)


def _fmpq(value) -> flint.fmpq:
    q = sp.Rational(value) if not isinstance(value, Fraction) else sp.Rational(value.numerator, value.denominator)
    if not q.is_Rational:  # pragma: no cover - sympy raises before this
        raise TypeError(f"{value!r} is not rational")
    return flint.fmpq(int(q.p), int(q.q))
