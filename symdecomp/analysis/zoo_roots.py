"""Roots of a polynomial with repeated roots, certified: Yun's squarefree factorisation over ``Q(zeta_L)``.

A factor of a block's characteristic polynomial is irreducible over the generic field (``omega`` a
symbol), but at one frequency it may have repeated roots (the modified butterfly at the regular valence),
where Arb's root finder cannot converge. Its coefficients there are exact numbers of a cyclotomic field
(:func:`~symdecomp.algebra.cyclotomic.cyclotomic_value`), so the polynomial is split exactly,
``p = prod_i s_i^i`` with squarefree, pairwise coprime ``s_i`` (Yun's algorithm, gcds in ``Q(zeta_L)[x]``),
and the roots of each ``s_i`` are isolated by Arb with the multiplicity ``i``.

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> [(r.real.mid().str(3), m) for r, m in squarefree_roots([1, -1, sp.Rational(1, 4)], 8)]  # (x - 1/2)^2
[('0.500', 2)]
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.cos_field import _divmod, _gcd
from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, cyclotomic_value, to_acb
from symdecomp.algebra.number_field import FieldElement

__all__ = ["squarefree_roots"]

Poly = list[FieldElement]


def _derivative(a: Poly, modulus: flint.fmpq_poly) -> Poly:
    return [FieldElement(c.poly * i, modulus) for i, c in enumerate(a)][1:]


def _trim(a: Poly) -> Poly:
    a = list(a)
    while a and not a[-1]:
        a.pop()
    return a


def _minus(a: Poly, b: Poly, modulus: flint.fmpq_poly) -> Poly:
    zero = FieldElement(flint.fmpq_poly([]), modulus)
    size = max(len(a), len(b))
    return _trim([(a[i] if i < len(a) else zero) - (b[i] if i < len(b) else zero) for i in range(size)])


def _yun(a: Poly, modulus: flint.fmpq_poly) -> list[tuple[Poly, int]]:
    """``[(s_i, i)]`` with ``a = prod s_i^i`` (up to a constant), each ``s_i`` squarefree."""
    da = _derivative(a, modulus)
    b = _gcd(a, da, modulus)
    c, _ = _divmod(a, b, modulus)
    d = _minus(_divmod(da, b, modulus)[0], _derivative(c, modulus), modulus)
    out, i = [], 1
    while len(_trim(c)) > 1:
        s = _gcd(c, d, modulus) if d else [x * c[-1].inverse() for x in _trim(c)]
        c, _ = _divmod(c, s, modulus)
        d = _minus(_divmod(d, s, modulus)[0], _derivative(c, modulus), modulus) if d else []
        if len(s) > 1:
            out.append((s, i))
        i += 1
    return out


def squarefree_roots(coefficients: list[sp.Expr], order: int, *, prec: int = 128) -> list[tuple[flint.acb, int]]:
    """``[(ball, multiplicity)]``: the roots of the polynomial with exact ``coefficients`` (leading first) in ``Q(zeta_order)``.

    :class:`ValueError` if a coefficient is not a number of that field.
    """
    field = CyclotomicField(order)
    modulus = field.phi
    a = _trim([FieldElement(cyclotomic_value(c, field=field).poly, modulus) for c in reversed(coefficients)])
    out = []
    with flint.ctx.workprec(prec):
        for s, multiplicity in _yun(a, modulus):
            poly = flint.acb_poly([to_acb(Cyclotomic(field, c.poly), prec) for c in s])
            out += [(flint.acb(r), multiplicity) for r in poly.roots()]
    return out
