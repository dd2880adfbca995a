"""The certified roots of an exact polynomial, with their multiplicities: what ``charpoly --plot`` draws.

The polynomial is the one ``symdecomp charpoly`` prints: exact coefficients, rational (the closed form at a
valence) or algebraic (the product form at a valence whose centre weights hold cosines, e.g. Loop's). Its
factors are exact (FLINT's irreducible factors over Q, sympy's squarefree ``sqf_list`` over the coefficients'
number field); each factor's roots are isolated as certified Arb balls (FLINT's
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

    #: ``(ball, multiplicity)`` for each distinct root: each ball holds exactly one root of its factor (an irreducible
    #: factor over Q, a squarefree one over a number field), and distinct factors share no root.
    roots: tuple[tuple[flint.acb, int], ...]
    #: The index in :attr:`roots` of the root 1, decided exactly (``None``: 1 is not a root).
    one: int | None

    @property
    def one_is_root(self) -> bool:
        """Whether 1 is a root."""
        return self.one is not None

    @property
    def degree(self) -> int:
        """The degree: the multiplicities' sum."""
        return sum(m for _, m in self.roots)

    @property
    def lambda_1(self) -> flint.arb | None:
        """An upper bound of the largest modulus of the roots once the root 1 is taken away once (``None``: 1 is not a
        root, or no root is left): ``lambda_1``, the radius of the circle ``charpoly --plot`` draws."""
        if self.one is None:
            return None
        left = [z for i, (z, m) in enumerate(self.roots) if i != self.one or m > 1]
        return max((abs(z).upper() for z in left), key=float, default=None)


def _rational_roots(coefficients: Sequence[sp.Rational]) -> tuple[list[tuple[flint.acb, int]], int | None]:
    """The roots of the irreducible factors over Q (FLINT: factoring first is far faster than isolating the roots of
    the whole polynomial, e.g. 1 s against 50 s at degree 601), and the index of the root 1."""
    poly = flint.fmpq_poly([flint.fmpq(int(c.p), int(c.q)) for c in reversed(coefficients)])
    out: list[tuple[flint.acb, int]] = []
    one = None
    for factor, m in cast(list[Any], poly.factor()[1]):
        if factor.degree() == 1 and factor(1) == 0:
            one = len(out)
        # FLINT returns (ball, multiplicity) pairs (1 on an irreducible factor); its type stubs say balls
        out.extend((cast(tuple[flint.acb, int], pair)[0], int(m)) for pair in cast(list[Any], factor.complex_roots()))
    return out, one


def _algebraic_roots(coefficients: Sequence[sp.Expr], variable: sp.Symbol, digits: int) -> tuple[list[tuple[flint.acb, int]], int | None]:
    """The roots of the squarefree factors over the coefficients' number field, and the index of the root 1 (exact
    arithmetic in that field decides which factor holds it; of its isolated balls, the one containing 1)."""
    from symdecomp.algebra.compile import compile_expression

    poly = sp.Poly(list(coefficients), variable, extension=True)
    out: list[tuple[flint.acb, int]] = []
    one = None
    for factor, m in poly.sqf_list()[1]:
        balls = [flint.acb(compile_expression(c, (), "arb")()) for c in reversed(factor.all_coeffs())]
        try:
            roots = flint.acb_poly(balls).roots(tol=flint.arb(10) ** -digits)  # refined to about ``digits`` digits
        except ValueError as exc:  # not isolated at this precision: say so, never guess
            raise SymdecompError(f"the roots of a degree-{factor.degree()} factor were not isolated ({exc})") from None
        if factor.eval(1) == 0:
            at_one = [i for i, z in enumerate(roots) if z.contains(1)]
            if len(at_one) != 1:
                raise SymdecompError(f"the root 1 of a degree-{factor.degree()} factor was not told from its other roots")
            one = len(out) + at_one[0]
        out.extend((z, int(m)) for z in roots)
    return out, one


def polynomial_roots(coefficients: Sequence[sp.Expr], *, digits: int = 30) -> PolynomialRoots:
    """The roots of ``sum c_i x^(d - i)`` (``coefficients`` highest degree first, exact sympy numbers), certified to
    about ``digits`` digits."""
    if len(coefficients) < 2 or coefficients[0] == 0:
        raise SymdecompError("a polynomial of degree at least 1 (its leading coefficient nonzero) has roots")
    with flint.ctx.workprec(int(3.33 * digits) + 64):
        if all(isinstance(c, sp.Rational) for c in coefficients):
            roots, one = _rational_roots(coefficients)
        else:
            roots, one = _algebraic_roots(coefficients, sp.Dummy("x"), digits)
    return PolynomialRoots(tuple(roots), one)
