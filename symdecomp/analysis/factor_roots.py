"""The roots of a frequency block's factors at a valence: certified balls, clusters of equal values, closed forms, Jordan blocks.

:func:`~symdecomp.analysis.charpoly.frequency_factors` factors each block's characteristic polynomial once,
symbolically; here a factor's roots are read at a valence (:class:`FactorRoots`: closed forms compiled once, or the
roots of the factor's Arb polynomial), grouped into distinct values by overlapping balls (:func:`overlap_clusters`,
:func:`ball_hull`), written exactly at a frequency (:func:`exact_root`: ``omega`` written with cosines), and a repeated
value's Jordan blocks decided from exact ranks over ``Q(zeta_2n)`` (:func:`jordan_sizes`, :func:`jordan_partition`).
The interior vertex's ``K``-ring spectrum (:func:`~symdecomp.analysis.spectrum.ring_spectrum`) and the zoo's
(:mod:`symdecomp.analysis.zoo_spectrum`, :mod:`symdecomp.analysis.zoo_large_spectrum`) are read with them.

>>> import flint, sympy as sp
>>> from symdecomp.symbols import omega
>>> exact_root(omega + 1 / omega, 1, 4, {})
0
>>> [len(g) for g in overlap_clusters([(flint.acb(1),), (flint.acb(2),), (flint.acb(1),)])]
[2, 1]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, cyclotomic_value, matrix_rank
from symdecomp.analysis.charpoly import COSK, Factor, FrequencyFactors
from symdecomp.analysis.frequency import RingBlocks
from symdecomp.errors import InternalError, InvalidSchemeError
from symdecomp.schemes.rings import CENTRE_WEIGHTS
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA

__all__ = ["FactorRoots", "overlap_clusters", "ball_hull", "exact_root", "centre_values", "jordan_sizes", "jordan_partition"]

W_O, W_A, W_B = CENTRE_WEIGHTS

#: A root as the spectra hold it: ``(ball, frequency, factor index, root index)``.
RootItem = tuple[flint.acb, int, int, int]


def centre_values(scheme: Scheme, n: int) -> tuple[dict[sp.Symbol, sp.Expr], dict[sp.Symbol, Cyclotomic]]:
    """The centre weights at ``n``: exact sympy values and Cyclotomic values, by symbol."""
    v = scheme.vertex_rule
    exact: dict[sp.Symbol, sp.Expr] = {}
    field: dict[sp.Symbol, Cyclotomic] = {}
    for s, w in ((W_A, v.each_a), (W_B, v.each_b)):
        exact[s] = sp.sympify(w, strict=True).subs(N, n)
        try:
            field[s] = cyclotomic_value(w, {N: n})
        except ValueError as exc:
            raise InvalidSchemeError(f"scheme {scheme.name!r}: vertex weight {w} at n = {n} is not exact in a cyclotomic field ({exc})") from None
    return exact, field


def _evaluator(expr: sp.Expr, variables: tuple[sp.Symbol, ...]) -> Callable[..., Any]:
    return compile_expression(sp.sympify(expr, strict=True), variables, "arb")


class FactorRoots:
    """Roots of the factors at a frequency as Arb balls (closed forms compiled once)."""

    def __init__(self, factors: tuple[Factor, ...], variables: tuple[sp.Symbol, ...]):
        self.factors = factors
        self.variables = variables
        self.closed: list[list[Callable[..., Any]] | None] = [
            [_evaluator(r, variables) for r in f.roots] if f.roots is not None else None for f in factors
        ]
        self.coeffs: list[list[Callable[..., Any]] | None] = [
            None if f.roots is not None else [_evaluator(c, variables) for c in reversed(sp.Poly(f.poly, LAM).all_coeffs())]
            for f in factors
        ]

    def at(self, args: Sequence[object]) -> list[tuple[flint.acb, int, int]]:
        """``[(ball, factor index, root index)]`` with each root repeated by the factor's exponent."""
        out: list[tuple[flint.acb, int, int]] = []
        for i, f in enumerate(self.factors):
            closed, coeffs = self.closed[i], self.coeffs[i]
            if closed is not None:
                balls = [g(*args) for g in closed]
            elif coeffs is not None:
                poly = flint.acb_poly([flint.acb(c(*args)) for c in coeffs])
                balls = list(poly.roots())
            else:
                raise InternalError(f"factor {i}: neither closed-form roots nor coefficients")
            for j, b in enumerate(balls):
                out += [(flint.acb(b), i, j)] * f.exponent
        return out


def overlap_clusters(items: Sequence[RootItem]) -> list[list[int]]:
    """Group balls that overlap (transitively); items are ``(ball, ...)`` tuples."""
    order = sorted(range(len(items)), key=lambda i: (float(items[i][0].real.mid()), float(items[i][0].imag.mid())))
    groups: list[list[int]] = []
    for i in order:
        ball = items[i][0]
        for g in groups[-4:]:  # sorted by midpoint: overlapping balls are neighbours
            if any(items[j][0].overlaps(ball) for j in g):
                g.append(i)
                break
        else:
            groups.append([i])
    return groups


def exact_root(root: sp.Expr, k: int, n: int, weights: Mapping[sp.Symbol, sp.Expr]) -> sp.Expr:
    """A closed-form root at frequency ``k``: ``omega -> exp(2 pi i k/n)`` written with cosines."""
    expr = sp.sympify(root, strict=True).xreplace({N: sp.Integer(n), COSK: sp.cos(2 * sp.pi * sp.Rational(k, n)), **weights})
    if not expr.has(OMEGA):
        return sp.sympify(expr, strict=True)
    numer, denom = sp.fraction(sp.together(expr))
    radical = any(not p.exp.is_Integer for p in numer.atoms(sp.Pow))
    if denom.free_symbols <= {OMEGA} and sp.Poly(denom, OMEGA).is_monomial and not radical:
        poly = sp.Poly(sp.expand(numer), OMEGA)
        shift = sp.Poly(denom, OMEGA).degree()
        terms = {m[0] - shift: c / sp.Poly(denom, OMEGA).LC() for m, c in poly.terms()}
        if all(terms.get(-p, 0) == c for p, c in terms.items()):  # symmetric: a cosine polynomial
            return sp.Add(*[c * (sp.cos(2 * sp.pi * p * k / n) if p else 1) for p, c in terms.items()])
    return expr.xreplace({OMEGA: sp.exp(2 * sp.pi * sp.I * k / n)})


def ball_hull(balls: Sequence[flint.acb]) -> flint.acb:
    """A ball (a square around the first midpoint) holding every ball of ``balls``."""
    centre = balls[0].mid()
    radius = max(((abs(b.mid() - centre) + b.rad()).upper() for b in balls), key=float)
    return flint.acb(flint.arb(centre.real, radius), flint.arb(centre.imag, radius))


def jordan_sizes(blocks: RingBlocks, ff: FrequencyFactors, items: Sequence[RootItem], group: Sequence[int], n: int,
                 weights: Mapping[sp.Symbol, sp.Expr]) -> tuple[int, ...] | None:
    """Jordan block sizes of a cluster, exactly (ranks over ``Q(zeta_2n)``); ``None`` if not decidable.

    Frequencies are independent (different Fourier subspaces), so the blocks are those of each
    frequency matrix at the value. A value is handled when its closed form lies in ``Q(zeta_2n)``
    there; otherwise (a radical, a root of a factor of degree > 2) a value repeated at one
    frequency is left undecided (``None``).
    """
    by_k: dict[int, list[int]] = {}
    for x in group:
        by_k.setdefault(items[x][1], []).append(x)
    sizes: list[int] = []
    field = CyclotomicField(2 * n)
    for k, members in sorted(by_k.items()):
        if len(members) == 1:
            sizes.append(1)
            continue
        _, _, i, j = items[members[0]]
        f = (ff.zero if k == 0 else ff.other)[i]
        if f.roots is None:
            return None
        at = {N: sp.Integer(n), COSK: sp.cos(2 * sp.pi * sp.Rational(k, n)), OMEGA: sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)), **weights}
        E = blocks.frequency_zero_matrix(n) if k == 0 else blocks.frequency_matrix()
        try:
            value = cyclotomic_value(sp.sympify(f.roots[j], strict=True).xreplace(at), field=field)
            A = [[cyclotomic_value(sp.sympify(E[r, c], strict=True).xreplace(at), field=field) - (value if r == c else 0) for c in range(E.shape[1])]
                 for r in range(E.shape[0])]
        except ValueError:
            return None
        sizes += jordan_partition(A, len(members))
    return tuple(sorted(sizes, reverse=True))


def jordan_partition(A: list[list[Cyclotomic]], m: int) -> list[int]:
    """Jordan block sizes of the eigenvalue 0 of ``A`` (algebraic multiplicity ``m``) from exact ranks."""
    size = len(A)
    ranks, P = [size], [row[:] for row in A]
    for _ in range(m):
        ranks.append(matrix_rank(P))
        if ranks[-1] == ranks[-2] or size - ranks[-1] >= m:
            break  # the ranks are stable from here on
        P = [[sum((P[r][t] * A[t][c] for t in range(size)), A[0][0] * 0) for c in range(size)] for r in range(size)]
    ranks += [ranks[-1]] * (m + 1 - len(ranks))
    more = [ranks[i] - ranks[i + 1] for i in range(m)]  # number of blocks of size > i
    return [i + 1 for i in range(m) for _ in range(more[i] - (more[i + 1] if i + 1 < m else 0))]
