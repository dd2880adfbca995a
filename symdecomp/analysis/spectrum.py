"""The spectrum of the subdivision matrix: at an interior vertex per frequency, from the closed forms and of any scheme's
K-ring from its factored frequency blocks; at a boundary, crease, corner or dart vertex by the blocks of its mirror.

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

**A boundary, crease, corner or dart vertex** (:func:`sharp_spectrum`, exact, each eigenvalue named by its block).
The eigenvalues are those of the one-step matrix ``S`` of the vertex's 1-ring built by exact refinement
(:func:`~symdecomp.schemes.sector.exact_sharp_matrix`, or over ``Q(cos(pi/k))`` for rules with ``cos(theta_k)``
weights: :attr:`SharpSpectrum.field`), found part by part (:mod:`symdecomp.analysis.triangular_eigen`: the crease
block and each sector), each a root of an irreducible rational factor, with its exact multiplicity. Each is then named
by the block of the mirror decomposition (:func:`~symdecomp.analysis.mirror.sector_spectrum`) that has it: the crease
block, the sine block ``j`` of a sector of ``k`` faces (``theta = pi j/k``), its last mode (``j = k`` on quads:
``b_i = (-1)^i``), or at a dart the symmetric (cosine) part. The names are matched by value (a block eigenvalue's
40-digit value to the nearest certified root, :mod:`symdecomp.analysis.block_names`); that the blocks *are* the spectrum, with multiplicities, is what
``check --certify`` proves (:mod:`symdecomp.verify.certify`). From :data:`STRUCTURAL_FROM` faces on, the values come
from the blocks alone, O(k), without the matrix (:mod:`symdecomp.analysis.block_values`). Semi-sharp edges (finite
sharpness) have no mirror decomposition: their eigenvalues are named by part only, at each refinement level whose
matrix differs from the level before, until the sharpness has decayed to 0 (:func:`sharp_levels`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import flint
import mpmath
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cos_field import field_name
from symdecomp.algebra.cyclotomic import to_acb
from symdecomp.analysis.block_names import block_names, exact_text
from symdecomp.analysis.charpoly import COSK, frequency_factors
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.factor_roots import FactorRoots, ball_hull, centre_values, exact_root, jordan_sizes, overlap_clusters
from symdecomp.analysis.frequency import recursion_matrix, ring_blocks
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.analysis.triangular_eigen import merge
from symdecomp.errors import InvalidInputError, NotApplicableError, UnsupportedExpressionError
from symdecomp.schemes.full_matrix import parameter_values
from symdecomp.schemes.rings import CENTRE_WEIGHTS
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_digits, check_limit, check_valence

__all__ = ["Spectrum", "recursion_eigenvalues", "closed_form_spectrum", "format_value", "RingSpectrum", "ring_spectrum", "acb_text",
           "SharpSpectrum", "sharp_spectrum", "sharp_levels"]

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
                    jordan=jordan_sizes(blocks, ff, items, g, n, exact_w) if jordan else None,
                    members=tuple(sorted(items[x][1:] for x in g)),
                    hull=ball_hull([items[x][0] for x in g]),
                )
            )
    size = 1 + blocks.class_count * n
    return RingSpectrum(scheme.name, scheme.mesh, n, rings, size, digits, tuple(entries))


@dataclass(frozen=True)
class SharpSpectrum:
    """The spectrum of one sharp vertex at one refinement level."""

    scheme: str
    #: The vertex (a :class:`~symdecomp.schemes.sector.SharpVertex`).
    vertex: object
    level: int
    #: The sharpness at this level (``math.inf``, a ``Fraction``).
    sharpness: object
    size: int
    #: Whether the names come from the mirror decomposition (else from the parts of the matrix).
    decomposed: bool
    #: The distinct eigenvalues (a certified ball each, its decimal text, its multiplicity), each with its ``blocks`` as
    #: text: the blocks of the mirror decomposition that have it (``"crease"``, ``"sine j=1 (theta = pi/5)"``, ...), or
    #: the parts of the matrix (``"crease"``, ``"sector 1"``, ``"whole"``) when there is no decomposition; and its
    #: ``exact`` form as text: a closed form, or ``"root i of <irreducible polynomial>"``.
    entries: tuple[Eigenvalue, ...]
    #: The field of the matrix's entries: ``"Q"``, or ``"Q(cos(pi/k))"`` for rules with ``cos(theta_k)`` weights.
    field: str = "Q"
    #: ``"dense"`` (the matrix's characteristic polynomial) or ``"structural"`` (the mirror decomposition's blocks).
    route: str = "dense"

    def as_json(self) -> dict:
        s = self.sharpness
        return {"level": self.level, "sharpness": "inf" if s == math.inf else str(s), "size": self.size, "field": self.field,
                "decomposed": self.decomposed, "route": self.route, "eigenvalues": [_entry_json(e) for e in self.entries]}


def _entry_json(e: Eigenvalue) -> dict:
    return {"value": e.text, "multiplicity": e.multiplicity, "blocks": list(e.blocks), "exact": e.exact}


#: From this many faces on, ``route="auto"`` takes the structural route (where it applies).
STRUCTURAL_FROM = 9
_ROUTES = ("auto", "dense", "structural")


def sharp_spectrum(scheme: Scheme, vertex, *, level: int = 0, digits: int = 20, route: str = "auto") -> SharpSpectrum:
    """The exact spectrum of ``vertex`` at refinement ``level``, each eigenvalue named by its block (module docstring).

    ``route``: ``"dense"`` (the matrix built by refinement, its characteristic polynomial factored), ``"structural"``
    (the mirror decomposition's blocks, O(k): :mod:`symdecomp.analysis.block_values`; refused where it does not
    apply), or ``"auto"``: structural from :data:`STRUCTURAL_FROM` faces on where it applies, else dense.
    """
    from symdecomp.analysis.triangular_eigen import sharp_values

    scheme, digits = check_scheme(scheme), check_digits(digits)
    if route not in _ROUTES:
        raise InvalidInputError(f"route: expected one of {', '.join(_ROUTES)}, got {route!r:.40}")
    here = vertex.at_level(level)
    if route == "structural" or (route == "auto" and here.faces >= STRUCTURAL_FROM and here.sharpness == math.inf):
        try:
            return _structural_spectrum(scheme, vertex, level, digits)
        except NotApplicableError:
            if route == "structural":
                raise
    S, _, values = sharp_values(scheme, vertex, level=level, prec=max(256, 4 * digits + 64))
    values = merge(values)
    named = block_names(scheme, here, values) if here.sharpness == math.inf else None
    entries = []
    with flint.ctx.workprec(4 * digits + 64):
        for v in values:
            blocks = tuple(named[0][v.key]) if named else tuple(v.part.split(", "))
            text = acb_text(v.ball, digits)
            entries.append(replace(v, text=text, blocks=blocks, exact=exact_text(v, named[1][v.key] if named else [])))
    return SharpSpectrum(scheme.name, vertex, level, here.sharpness, S.nrows(), named is not None, tuple(entries),
                         field_name(S))


def _structural_spectrum(scheme: Scheme, vertex, level: int, digits: int) -> SharpSpectrum:
    """:func:`sharp_spectrum` from the blocks of the mirror decomposition (no matrix of the vertex)."""
    from symdecomp.analysis.block_values import structural_values
    from symdecomp.analysis.triangular_eigen import near_weight

    here = vertex.at_level(level)
    values, size = structural_values(scheme, here, prec=max(256, 4 * digits + 64))
    entries = []
    with flint.ctx.workprec(4 * digits + 64):
        for v in values:
            names: list[str] = []
            for e in v.blocks:
                if e.name(here) not in names:
                    names.append(e.name(here))
            entries.append(replace(v, text=acb_text(v.ball, digits), blocks=tuple(names)))
    irrational = sorted(k for k in set(here.sectors) if near_weight(scheme, here, k) is not None)
    field = f"Q({', '.join(f'cos(pi/{k})' for k in irrational)})" if irrational else "Q"
    return SharpSpectrum(scheme.name, vertex, level, here.sharpness, size, True, tuple(entries), field, "structural")


def sharp_levels(scheme: Scheme, vertex, *, digits: int = 20) -> list[SharpSpectrum]:
    """The spectra at level 0 and at each later level whose matrix differs from the one before, until the
    sharpness has decayed to 0 (one spectrum for infinitely sharp edges)."""
    from symdecomp.analysis.triangular_eigen import sharp_matrix
    from symdecomp.schemes.sector import MAX_LEVEL

    out = [sharp_spectrum(scheme, vertex, digits=digits)]
    if vertex.sharpness == math.inf:
        return out
    previous = sharp_matrix(scheme, vertex)
    for level in range(1, MAX_LEVEL + 1):
        S = sharp_matrix(scheme, vertex, level=level)
        if S != previous:
            out.append(sharp_spectrum(scheme, vertex, level=level, digits=digits))
            previous = S
        if vertex.at_level(level).sharpness == 0:
            break
    return out
