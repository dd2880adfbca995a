"""Spectra of any rotationally symmetric scheme, K-ring, frequency by frequency.

The spectrum of the ``K``-ring matrix is that of ``E_0`` and of ``E(omega_n^k)``,
``k = 1..n-1`` (:mod:`symdecomp.analysis.ring_blocks`). Their characteristic polynomials are
factored once, symbolically (:func:`~symdecomp.analysis.charpoly.frequency_factors`): ``det(lambda I - E(omega))`` over ``Q(omega)``, and
``det(lambda I - E_0)`` over ``Q(n, w_a, w_b)`` with the centre weights as symbols (and
``w_O = 1 - n w_a - n w_b``, the vertex rule being affine). A factor of degree ``<= 2`` in
``lambda`` has closed-form roots; a higher one has roots that are exact algebraic numbers
(roots of an exact polynomial with coefficients in a cyclotomic field), isolated at a
valence by certified Arb balls (``acb_poly.roots``). All values are computed as Arb balls
(the centre weights, e.g. Loop's ``cos(2 pi/n)``, enter exactly through
:func:`~symdecomp.algebra.cyclotomic.cyclotomic_value`) and grouped into distinct values by
overlapping balls; multiplicities count roots. A factor that is repeated (symbolically) or a
cluster fed by one frequency twice is tested for a Jordan block: exactly, when the matrix
and the value are rational there, otherwise the Jordan structure is reported unknown.

>>> from symdecomp.schemes.loop import loop
>>> sp7 = ring_spectrum(loop(), 7, digits=8)
>>> [(e.text, e.multiplicity) for e in sp7.eigenvalues][:3]
[('1.0', 1), ('0.53087245', 2), ('0.31936977', 2)]
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value, matrix_rank, to_acb
from symdecomp.analysis.charpoly import COSK, Factor, frequency_factors
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.ring_blocks import ring_blocks
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.rings import CENTRE_WEIGHTS
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_limit, check_valence

__all__ = ["RingSpectrum", "ring_spectrum", "acb_text"]

W_O, W_A, W_B = CENTRE_WEIGHTS
@dataclass(frozen=True)
class RingSpectrum:
    scheme: str
    mesh: str
    n: int
    rings: int
    size: int
    digits: int
    eigenvalues: tuple[Eigenvalue, ...]

    def as_json(self) -> dict:
        return {
            "n": self.n,
            "scheme": self.scheme,
            "mesh": self.mesh,
            "rings": self.rings,
            "size": self.size,
            "digits": self.digits,
            "eigenvalues": [e.as_json(exact=True) for e in self.eigenvalues],
        }


def acb_text(z, digits: int) -> str:
    """A ball's midpoint as decimal text with ``digits`` significant digits (``a+bj`` if complex)."""
    import mpmath

    from symdecomp.analysis.spectrum import format_value

    with mpmath.workdps(digits + 10):
        re = mpmath.mpf(z.real.mid().str(digits + 10, radius=False))
        if z.imag.contains(0):
            return format_value(re, digits)
        return format_value(mpmath.mpc(re, mpmath.mpf(z.imag.mid().str(digits + 10, radius=False))), digits)


def _centre_values(scheme: Scheme, n: int) -> tuple[dict, dict]:
    """The centre weights at ``n``: exact sympy values and Cyclotomic values, by symbol."""
    v = scheme.vertex_rule
    exact, field = {}, {}
    for s, w in ((W_A, v.each_a), (W_B, v.each_b)):
        exact[s] = sp.sympify(w, strict=True).subs(N, n)
        try:
            field[s] = cyclotomic_value(w, {N: n})
        except ValueError as exc:
            raise InvalidSchemeError(f"scheme {scheme.name!r}: vertex weight {w} at n = {n} is not exact in a cyclotomic field ({exc})") from None
    return exact, field


def _evaluator(expr: sp.Expr, variables):
    return compile_expression(sp.sympify(expr, strict=True), variables, "arb")


class _Roots:
    """Roots of the factors at a frequency as Arb balls (closed forms compiled once)."""

    def __init__(self, factors: tuple[Factor, ...], variables):
        self.factors = factors
        self.variables = variables
        self.closed = [[_evaluator(r, variables) for r in f.roots] if f.roots is not None else None for f in factors]
        self.coeffs = [
            None if f.roots is not None else [_evaluator(c, variables) for c in reversed(sp.Poly(f.poly, LAM).all_coeffs())]
            for f in factors
        ]

    def at(self, args) -> list[tuple[object, int, int]]:
        """``[(ball, factor index, root index)]`` with each root repeated by the factor's exponent."""
        out = []
        for i, f in enumerate(self.factors):
            if self.closed[i] is not None:
                balls = [g(*args) for g in self.closed[i]]
            else:
                poly = flint.acb_poly([flint.acb(c(*args)) for c in self.coeffs[i]])
                balls = list(poly.roots())
            for j, b in enumerate(balls):
                out += [(flint.acb(b), i, j)] * f.exponent
        return out


def _clusters(items):
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


def _exact_root(root: sp.Expr, k: int, n: int, weights: dict) -> sp.Expr:
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


def ring_spectrum(scheme: Scheme, n: int, rings: int = 1, *, digits: int = 20, exact: bool = True, jordan: bool = True) -> RingSpectrum:
    """The eigenvalues of the ``rings``-ring matrix at valence ``n``, from the frequency factors.

    ``exact``: attach exact closed forms to the values (costs a little sympy per value).
    ``jordan``: decide the Jordan structure of repeated values (exact ranks; ``None`` if not asked).
    """
    n = check_scheme(scheme).fitting_valence(check_limit(check_valence(n), "ring_spectrum(n)", "valence n"))
    digits = check_digits(digits)
    blocks = ring_blocks(scheme, rings)
    ff = frequency_factors(blocks)
    exact_w, field_w = _centre_values(scheme, n)
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        zero = _Roots(ff.zero, (N, W_A, W_B))
        other = _Roots(ff.other, (OMEGA, COSK, N))  # N: an edge rule in n is read at the centre's valence (the model)
        wa, wb = (to_acb(field_w[s], prec) for s in (W_A, W_B))
        items = [(b, 0, i, j) for b, i, j in zero.at((flint.acb(n), wa, wb))]
        for k in range(1, n):
            w = flint.acb(flint.arb(flint.fmpq(2 * k, n))).exp_pi_i()
            items += [(b, k, i, j) for b, i, j in other.at((w, w.real, flint.acb(n)))]
        groups = _clusters(items)
        groups.sort(key=lambda g: (-float(items[g[0]][0].abs_upper()), -float(items[g[0]][0].real.mid())))
        entries = []
        for g in groups:
            b, k, i, j = items[g[0]]
            factors = ff.zero if k == 0 else ff.other
            f = factors[i]
            value = None
            if exact and f.roots is not None:
                value = _exact_root(f.roots[j], k, n, exact_w)
            entries.append(
                Eigenvalue(
                    value=b,
                    text=acb_text(b, digits),
                    multiplicity=len(g),
                    frequencies=tuple(sorted({items[x][1] for x in g})),
                    exact=value,
                    factor=f.poly.xreplace({N: n}) if k == 0 else f.poly,
                    jordan=_jordan(blocks, ff, items, g, n, exact_w) if jordan else None,
                    members=tuple(sorted(items[x][1:] for x in g)),
                    hull=_hull([items[x][0] for x in g]),
                )
            )
    size = 1 + blocks.class_count * n
    return RingSpectrum(scheme.name, scheme.mesh, n, rings, size, digits, tuple(entries))


def _hull(balls):
    """A ball (a square around the first midpoint) holding every ball of ``balls``."""
    centre = balls[0].mid()
    radius = max(((abs(b.mid() - centre) + b.rad()).upper() for b in balls), key=float)
    return flint.acb(flint.arb(centre.real, radius), flint.arb(centre.imag, radius))


def _jordan(blocks, ff, items, group, n, weights) -> tuple[int, ...] | None:
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
        sizes += _partition(A, len(members))
    return tuple(sorted(sizes, reverse=True))


def _partition(A, m: int) -> list[int]:
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
