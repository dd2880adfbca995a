"""The spectrum of the subdivision matrix at an interior vertex, per frequency: from the closed forms, and of any scheme's
K-ring from its factored frequency blocks.

The ``2n+1`` eigenvalues of the valence-``n`` subdivision matrix are

* the three eigenvalues of the ``3 x 3`` matrix of Eq. 43 (frequency ``k = 0``), and
* the two eigenvalues of ``M_k`` (Eq. 34) for each n-gon frequency ``k = 1..n-1``.

Both come from closed forms derived symbolically (:mod:`symdecomp.analysis.frequency`,
:mod:`symdecomp.analysis.tangent`); here they are evaluated with mpmath and grouped into distinct
values with multiplicities. Frequencies are n-gon frequencies ``k`` (the 2n-gon components
``j`` and ``j + n`` of Eq. 11 share ``M_{j mod n}``).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> sp4 = closed_form_spectrum(catmull_clark(), 4, digits=10)
>>> [(e.text, e.multiplicity, e.frequencies) for e in sp4.eigenvalues]
[('1.0', 1, (0,)), ('0.5', 2, (1, 3)), ('0.25', 3, (0, 2)), ('0.125', 2, (1, 3)), ('0.0625', 1, (0,))]

**Any rotationally symmetric scheme and** ``K``**-ring** (:func:`ring_spectrum`, certified, frequency by frequency).
The spectrum of the ``K``-ring matrix is that of ``E_0`` and of ``E(omega_n^k)``,
``k = 1..n-1`` (:func:`symdecomp.analysis.frequency.ring_blocks`). Their characteristic polynomials are
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
import mpmath
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value, matrix_rank, to_acb
from symdecomp.analysis.charpoly import COSK, Factor, frequency_factors
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.frequency import recursion_matrix, ring_blocks
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.errors import InvalidSchemeError, UnsupportedExpressionError
from symdecomp.schemes.full_matrix import parameter_values
from symdecomp.schemes.rings import CENTRE_WEIGHTS
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_digits, check_limit, check_valence

__all__ = ["Spectrum", "recursion_eigenvalues", "closed_form_spectrum", "format_value", "RingSpectrum", "ring_spectrum", "acb_text",
           "FactorRoots", "overlap_clusters", "ball_hull", "exact_root", "centre_values"]

W_O, W_A, W_B = CENTRE_WEIGHTS


@dataclass(frozen=True)
class Spectrum(NotebookDisplay):
    """The closed-form spectrum of a scheme's subdivision matrix at one valence."""

    #: The valence.
    n: int
    #: The scheme's name.
    scheme: str
    #: Significant digits of the printed values.
    digits: int
    #: Values were grouped as equal when they agreed to this many digits (computed at more).
    grouping_digits: int
    #: Distinct eigenvalues, in decreasing order of modulus (then real part).
    eigenvalues: tuple[Eigenvalue, ...]

    def as_json(self) -> dict:
        return {
            "n": self.n,
            "scheme": self.scheme,
            "digits": self.digits,
            "grouping_digits": self.grouping_digits,
            "eigenvalues": [e.as_json() for e in self.eigenvalues],
        }


@cached(scheme=check_scheme)
def recursion_eigenvalues(scheme: Scheme) -> tuple[sp.Expr, ...]:
    """The eigenvalues of the Eq. 43 matrix as closed forms in ``n`` (and the parameters).

    Derived from its characteristic polynomial; an affine scheme always has the factor
    ``lambda - 1`` (rows sum to 1), and the remaining quadratic is solved by radicals.
    """
    charpoly = (recursion_matrix(scheme).charpoly(LAM)).as_expr()
    quotient, remainder = sp.div(sp.Poly(charpoly, LAM), sp.Poly(LAM - 1, LAM))
    if sp.cancel(remainder.as_expr()) != 0:  # pragma: no cover - affinity is checked on construction
        raise ArithmeticError("the Eq. 43 matrix of an affine scheme must have the eigenvalue 1")
    # cancel/factor are exact normal forms of rational functions, and much cheaper than simplify
    q = sp.Poly(sp.together(quotient.as_expr()), LAM)
    a2, a1, a0 = [sp.cancel(c) for c in q.all_coeffs()]
    disc = sp.factor(sp.cancel(a1**2 - 4 * a2 * a0))
    return (
        sp.Integer(1),
        sp.factor(sp.cancel((-a1 + sp.sqrt(disc)) / (2 * a2))),
        sp.factor(sp.cancel((-a1 - sp.sqrt(disc)) / (2 * a2))),
    )


def format_value(value, digits: int) -> str:
    """A decimal string with ``digits`` significant digits; complex as ``a+bj`` (Python syntax)."""
    if isinstance(value, mpmath.mpc):
        if value.imag == 0:
            value = value.real
        else:
            re = mpmath.nstr(value.real, digits, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)
            im = mpmath.nstr(abs(value.imag), digits, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)
            return f"{re}{'-' if value.imag < 0 else '+'}{im}j"
    return mpmath.nstr(value, digits, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)


def _numeric(expr: sp.Expr, subs: dict, dps: int):
    value = sp.N(expr.subs(subs), dps + 5)
    re, im = value.as_real_imag()
    with mpmath.workdps(dps):
        re_m = mpmath.mpf(sp.Float(re, dps + 5)._mpf_) if re != 0 else mpmath.mpf(0)
        im_m = mpmath.mpf(sp.Float(im, dps + 5)._mpf_) if im != 0 else mpmath.mpf(0)
        return re_m if im_m == 0 else mpmath.mpc(re_m, im_m)


def _frequency_values(ev, n: int, subs: dict, work: int) -> list[tuple]:
    """``(dominant, subdominant)`` of ``M_k`` for ``k = 1..n-1``, each to ``work`` digits.

    The closed forms are compiled once (:func:`~symdecomp.algebra.compile.compile_expression`)
    and evaluated at ``c = cos(k pi/n)``, ``s = sin(k pi/n)`` with twice the working precision
    (plus a margin), so that a square root of a discriminant that vanishes (a double eigenvalue)
    is still right to ``work`` digits and groups as one value. A closed form the compiler does
    not know is evaluated by sympy instead (slower, same digits).
    """
    exprs = [sp.sympify(e, strict=True).xreplace(subs) for e in (ev.dominant, ev.subdominant)]
    try:
        compiled = [compile_expression(e, (cos_jtheta, sin_jtheta, N)) for e in exprs]
    except UnsupportedExpressionError:
        out = []
        for k in range(1, n):
            angle = sp.pi * sp.Rational(k, n)
            point = {cos_jtheta: sp.cos(angle), sin_jtheta: sp.sin(angle), N: n}
            out.append(tuple(_numeric(e, point, work) for e in exprs))
        return out
    out = []
    with mpmath.workdps(2 * work + 10):
        nn = mpmath.mpf(n)
        for k in range(1, n):
            angle = mpmath.pi * k / n
            c, s = mpmath.cos(angle), mpmath.sin(angle)
            values = [f(c, s, nn) for f in compiled]
            out.append(tuple(_rounded(v, work) for v in values))
    return out


def _rounded(value, work: int):
    """An mpmath value at ``work`` digits (real when its imaginary part is zero at that precision)."""
    value = mpmath.mpmathify(value)
    with mpmath.workdps(work):
        if isinstance(value, mpmath.mpc):
            re, im = +value.real, +value.imag
            return re if abs(im) <= mpmath.mpf(10) ** (-work) * max(1, abs(re)) else mpmath.mpc(re, im)
        return +value


def closed_form_spectrum(scheme: Scheme, n: int, *, digits: int = 30, parameters: dict | None = None) -> Spectrum:
    """Evaluate the closed-form eigenvalues at valence ``n`` and group them with multiplicities.

    Values are computed at ``digits + 30`` significant digits and grouped when they agree to
    ``digits + 15``; each closed form is an explicit radical, so coincidences (``n = 4`` has
    ``1/4`` three times) are exact up to that rounding. ``parameters`` gives values for free
    parameters of the scheme (e.g. ``{alpha: ..., beta: ...}``).
    """
    n = check_scheme(scheme).fitting_valence(check_limit(check_valence(n), "closed_form_spectrum(n)", "valence n"))
    digits = check_digits(digits)
    subs = parameter_values(scheme, parameters)
    work = digits + 30
    raw: list[tuple[object, int]] = []
    for expr in recursion_eigenvalues(scheme):
        raw.append((_numeric(expr, {N: n, **subs}, work), 0))
    ev = tangent_eigenvalues(scheme)
    for k, pair in zip(range(1, n), _frequency_values(ev, n, subs, work)):
        raw.extend((value, k) for value in pair)
    with mpmath.workdps(work):
        tol = mpmath.mpf(10) ** (-(digits + 15))
        raw.sort(key=lambda vk: (-abs(vk[0]), -mpmath.re(vk[0]), -mpmath.im(vk[0])))
        groups: list[list[tuple[object, int]]] = []
        for value, k in raw:
            if groups and abs(groups[-1][0][0] - value) <= tol * max(1, abs(value)):
                groups[-1].append((value, k))
            else:
                groups.append([(value, k)])
        entries = tuple(
            Eigenvalue(
                value=g[0][0],
                text=format_value(g[0][0], digits),
                multiplicity=len(g),
                frequencies=tuple(sorted({k for _, k in g})),
            )
            for g in groups
        )
    return Spectrum(n=n, scheme=scheme.name, digits=digits, grouping_digits=digits + 15, eigenvalues=entries)


@dataclass(frozen=True)
class RingSpectrum:
    """The factored spectrum of a scheme's ``K``-ring matrix at one valence (:func:`ring_spectrum`)."""

    #: The scheme's name.
    scheme: str
    #: The scheme's mesh (``"quad"``, ``"triangle"``).
    mesh: str
    #: The valence.
    n: int
    #: The ring depth ``K``.
    rings: int
    #: The matrix's size (``1 + K' n``, ``K'`` vertex classes per sector).
    size: int
    #: Significant digits of the printed values.
    digits: int
    #: Distinct eigenvalues (certified balls), in decreasing order of modulus (then real part).
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
    with mpmath.workdps(digits + 10):
        re = mpmath.mpf(z.real.mid().str(digits + 10, radius=False))
        if z.imag.contains(0):
            return format_value(re, digits)
        return format_value(mpmath.mpc(re, mpmath.mpf(z.imag.mid().str(digits + 10, radius=False))), digits)


def centre_values(scheme: Scheme, n: int) -> tuple[dict, dict]:
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


class FactorRoots:
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


def overlap_clusters(items):
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


def exact_root(root: sp.Expr, k: int, n: int, weights: dict) -> sp.Expr:
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
    exact_w, field_w = centre_values(scheme, n)
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        zero = FactorRoots(ff.zero, (N, W_A, W_B))
        other = FactorRoots(ff.other, (OMEGA, COSK, N))  # N: an edge rule in n is read at the centre's valence (the model)
        wa, wb = (to_acb(field_w[s], prec) for s in (W_A, W_B))
        items = [(b, 0, i, j) for b, i, j in zero.at((flint.acb(n), wa, wb))]
        for k in range(1, n):
            w = flint.acb(flint.arb(flint.fmpq(2 * k, n))).exp_pi_i()
            items += [(b, k, i, j) for b, i, j in other.at((w, w.real, flint.acb(n)))]
        groups = overlap_clusters(items)
        groups.sort(key=lambda g: (-float(items[g[0]][0].abs_upper()), -float(items[g[0]][0].real.mid())))
        entries = []
        for g in groups:
            b, k, i, j = items[g[0]]
            factors = ff.zero if k == 0 else ff.other
            f = factors[i]
            value = None
            if exact and f.roots is not None:
                value = exact_root(f.roots[j], k, n, exact_w)
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
                    hull=ball_hull([items[x][0] for x in g]),
                )
            )
    size = 1 + blocks.class_count * n
    return RingSpectrum(scheme.name, scheme.mesh, n, rings, size, digits, tuple(entries))


def ball_hull(balls):
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
