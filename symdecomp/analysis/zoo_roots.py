"""Roots of a polynomial with repeated roots, certified: Yun's squarefree factorisation over ``Q(zeta_L)``.

A factor of a block's characteristic polynomial is irreducible over the generic field (``omega`` a
symbol), but at one frequency it may have repeated roots (the modified butterfly at the regular valence),
where Arb's root finder cannot converge. Its coefficients there are exact numbers of a cyclotomic field
(:func:`~symdecomp.algebra.cyclotomic.cyclotomic_value`), so the polynomial is split exactly,
``p = prod_i s_i^i`` with squarefree, pairwise coprime ``s_i`` (Yun's algorithm, gcds in ``Q(zeta_L)[x]``),
and the roots of each ``s_i`` are isolated by Arb with the multiplicity ``i``.

sympy writes ``cos(r pi)`` for some ``r`` as radicals (``cos(pi/8) = sqrt(sqrt(2)/4 + 1/2)``, ``cos(2 pi/5) = (sqrt(5) -
1)/4``), which a cyclotomic field does not read; :func:`cosine_form` writes each such radical back as the cosines it
came from (each identity is sympy's own evaluation of a cosine, solved for its one new radical), so that the values
at valences such as 5, 8, 10, 12 and 16 are numbers of ``Q(zeta_L)`` again.

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> [(r.real.mid().str(3), m) for r, m in squarefree_roots([1, -1, sp.Rational(1, 4)], 8)]  # (x - 1/2)^2
[('0.500', 2)]
"""

from __future__ import annotations

import functools

import flint
import sympy as sp

from symdecomp.algebra.cos_field import _divmod, _gcd
from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, cyclotomic_value, to_acb
from symdecomp.algebra.number_field import FieldElement

__all__ = ["squarefree_roots", "cosine_form", "real_cosine_form"]

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


def _radicals(e: sp.Expr) -> set[sp.Expr]:
    return {p for p in e.atoms(sp.Pow) if not p.exp.is_Integer and not p.free_symbols}


@functools.lru_cache(maxsize=32)
def _radical_cosines(n: int) -> dict[sp.Expr, sp.Expr]:
    """``{radical: its value in cosines}`` for the radicals sympy writes ``cos(a pi/L)`` with, ``L`` a small
    denominator or ``n``, ``2n``: each cosine whose evaluation has one radical not yet known gives that radical."""
    values = []
    for L in sorted({2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, n, 2 * n}):
        for a in range(1, L):
            e = sp.cos(sp.pi * sp.Rational(a, L))
            if _radicals(e):
                values.append((e, sp.cos(sp.pi * sp.Rational(a, L), evaluate=False)))
    known: dict[sp.Expr, sp.Expr] = {}
    found = True
    while found:
        found = False
        for e, cosine in values:
            unknown = [p for p in _radicals(e) if p not in known]
            if len(unknown) != 1:
                continue
            d = sp.Dummy("r")
            linear = sp.expand(e.xreplace({unknown[0]: d}).xreplace(known))
            slope = sp.diff(linear, d)
            if slope == 0 or slope.has(d):
                continue
            known[unknown[0]] = (cosine - sp.expand(linear - slope * d)) / slope
            found = True
    return known


def cosine_form(value: sp.Expr, n: int) -> sp.Expr:
    """``value`` with the radicals sympy writes cosines with replaced by those cosines (module docstring); ``value``
    unchanged when it has a radical that is not one of them.

    >>> cosine_form(sp.sqrt(5) / 4 - sp.Rational(1, 4), 5)  # cos(2 pi/5)
    -1/2 + cos(pi/5)
    """
    radicals = _radicals(sp.sympify(value, strict=True))
    if not radicals:
        return value
    known = _radical_cosines(n)
    if not radicals <= set(known):
        return value
    return sp.expand(value.xreplace(known))


def real_cosine_form(x: Cyclotomic) -> sp.Expr | None:
    """A real number ``x`` of ``Q(zeta_N)`` as ``a_0 + sum_k a_k cos(2 pi k/N)``, ``k = 1 .. d - 1``, rational ``a_k``
    (``d = phi(N)/2``: the cosines ``cos(2 pi k/N) = T_k(cos(2 pi/N))`` are a basis of the real subfield, so the form is
    unique); ``None`` when ``x`` is not real (not its own conjugate). The cosines are left unevaluated, as
    :func:`cosine_form` writes them.

    >>> field = CyclotomicField(16)
    >>> real_cosine_form(field.zeta(1) + field.zeta(-1) + field.zeta(2) / 2 + field.zeta(-2) / 2)
    cos(pi/4) + 2*cos(pi/8)
    """
    if x != x.conjugate():
        return None
    field, N = x.field, x.field.N
    size = max(1, field.phi.degree())
    d = max(1, size // 2) if N > 2 else 1
    columns = [(field.zeta(k) + field.zeta(-k)) / 2 if k else field(1) for k in range(d)]
    def vector(c: Cyclotomic) -> list[sp.Rational]:
        coeffs = c.poly.coeffs() + [0] * (size - len(c.poly.coeffs()))
        return [sp.Rational(int(flint.fmpq(q).p), int(flint.fmpq(q).q)) for q in coeffs[:size]]
    A = sp.Matrix([vector(c) for c in columns]).T
    solution, params = A.gauss_jordan_solve(sp.Matrix(vector(x)))
    assert not params, "the cosines are a basis of the real subfield"
    return sp.Add(*(a * (sp.cos(sp.pi * sp.Rational(2 * k, N), evaluate=False) if k else 1)
                    for k, a in enumerate(solution) if a != 0))
