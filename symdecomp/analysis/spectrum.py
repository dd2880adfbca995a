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
from symdecomp.algebra.cyclotomic import to_acb
from symdecomp.analysis.charpoly import COSK, frequency_factors
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.factor_roots import FactorRoots, ball_hull, centre_values, exact_root, jordan_sizes, overlap_clusters
from symdecomp.analysis.frequency import recursion_matrix, ring_blocks
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.errors import UnsupportedExpressionError
from symdecomp.schemes.full_matrix import parameter_values
from symdecomp.schemes.rings import CENTRE_WEIGHTS
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_digits, check_limit, check_valence

__all__ = ["Spectrum", "recursion_eigenvalues", "closed_form_spectrum", "format_value", "RingSpectrum", "ring_spectrum", "acb_text"]

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
