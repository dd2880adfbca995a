"""The certified roots of an exact polynomial, with their multiplicities: what ``charpoly --plot`` draws.

The polynomial is the one ``symdecomp charpoly`` prints: exact coefficients, rational (the closed form at a
valence) or algebraic (the product form at a valence whose centre weights hold cosines, e.g. Loop's). Its
squarefree decomposition is exact (FLINT's ``fmpq_poly.factor_squarefree`` over Q, sympy's ``sqf_list`` over the
coefficients' number field); each squarefree factor's roots are isolated as certified Arb balls (FLINT's
``complex_roots`` over Q; ``acb_poly.roots`` over a number field, its coefficients evaluated as balls), at a
precision scoped with ``flint.ctx.workprec``. An isolation that does not converge raises
:class:`~symdecomp.errors.SymdecompError` instead of returning balls that may overlap.

>>> import sympy as sp
>>> r = polynomial_roots([sp.Integer(1), sp.Rational(-5, 2), sp.Integer(2), sp.Rational(-1, 2)])  # (x - 1)^2 (x - 1/2)
>>> sorted((round(float(z.real.mid()), 12), m) for z, m in r.roots), r.one_is_root, float(r.lambda_1)
([(0.5, 1), (1.0, 2)], True, 1.0)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, cast

import flint
import sympy as sp

from symdecomp.errors import SymdecompError

__all__ = ["PolynomialRoots", "polynomial_roots"]


@dataclass(frozen=True)
class PolynomialRoots:
    """The distinct roots of an exact polynomial as certified balls, each with its multiplicity."""

    #: ``(ball, multiplicity)`` for each distinct root; the balls are pairwise disjoint.
    roots: tuple[tuple[flint.acb, int], ...]
    #: Whether 1 is a root (decided exactly: the polynomial vanishes at 1).
    one_is_root: bool

    @property
    def degree(self) -> int:
        """The degree: the multiplicities' sum."""
        return sum(m for _, m in self.roots)

    @property
    def lambda_1(self) -> flint.arb | None:
        """An upper bound of the largest modulus of the roots once the root 1 is taken away once (``None``: 1 is not a
        root, or no root is left): ``lambda_1``, the radius of the circle ``charpoly --plot`` draws."""
        if not self.one_is_root:
            return None
        left = [z for z, m in self.roots if m > 1 or not z.contains(1)]
        return max((abs(z).upper() for z in left), key=float, default=None)


def _rational_roots(coefficients: Sequence[sp.Rational]) -> list[tuple[flint.acb, int]]:
    poly = flint.fmpq_poly([flint.fmpq(int(c.p), int(c.q)) for c in reversed(coefficients)])
    # FLINT returns (ball, multiplicity) pairs; its type stubs say balls
    return [cast(tuple[flint.acb, int], pair) for pair in cast(list[Any], poly.complex_roots())]


def _algebraic_roots(coefficients: Sequence[sp.Expr], variable: sp.Symbol, digits: int) -> tuple[list[tuple[flint.acb, int]], bool]:
    """The roots over the coefficients' number field, and whether 1 is one (exact arithmetic in that field)."""
    from symdecomp.algebra.compile import compile_expression

    poly = sp.Poly(list(coefficients), variable, extension=True)
    out: list[tuple[flint.acb, int]] = []
    for factor, m in poly.sqf_list()[1]:
        balls = [flint.acb(compile_expression(c, (), "arb")()) for c in reversed(factor.all_coeffs())]
        try:
            roots = flint.acb_poly(balls).roots(tol=flint.arb(10) ** -digits)  # refined to about ``digits`` digits
        except ValueError as exc:  # not isolated at this precision: say so, never guess
            raise SymdecompError(f"the roots of a degree-{factor.degree()} factor were not isolated ({exc})") from None
        out.extend((z, int(m)) for z in roots)
    return out, poly.eval(1) == 0


def polynomial_roots(coefficients: Sequence[sp.Expr], *, digits: int = 30) -> PolynomialRoots:
    """The roots of ``sum c_i x^(d - i)`` (``coefficients`` highest degree first, exact sympy numbers), certified to
    about ``digits`` digits."""
    if len(coefficients) < 2 or coefficients[0] == 0:
        raise SymdecompError("a polynomial of degree at least 1 (its leading coefficient nonzero) has roots")
    with flint.ctx.workprec(int(3.33 * digits) + 64):
        if all(isinstance(c, sp.Rational) for c in coefficients):
            roots, one_is_root = _rational_roots(coefficients), sum(coefficients, sp.Integer(0)) == 0
        else:
            roots, one_is_root = _algebraic_roots(coefficients, sp.Dummy("x"), digits)
    return PolynomialRoots(tuple(roots), one_is_root)
