"""The spectrum of a StencilScheme at valence ``n``, frequency by frequency, as a :class:`RingSpectrum`.

The blocks (:mod:`symdecomp.analysis.zoo_blocks`) are factored as
:func:`symdecomp.analysis.spectrum.ring_spectrum` factors a 1-ring scheme's: ``det(lambda I - B(omega))``
once, symbolically in ``omega``, and ``det(lambda I - B_0)``. The entries are exact numbers at
the valence (rationals, or cosines of rational multiples of ``pi`` and the radicals sympy writes
them with); each irrational atom is a symbol while factoring, so a factor is an identity for its
exact value too. A factor of degree ``<= 2`` gives closed-form roots (exact); the roots of a higher
one are isolated by certified Arb balls (``acb_poly.roots``). Values are grouped by overlapping
balls, and the result is the one eigenvalue type of spectra, :class:`~symdecomp.analysis.eigenvalue.Eigenvalue` in a
:class:`RingSpectrum` (``rings`` is the neighbourhood's depth), so ``spectrum --json`` keeps its shape.
The Jordan structure is decided by :mod:`symdecomp.analysis.zoo_jordan` (:func:`zoo_spectrum`'s ``jordan``).

>>> import sympy as sp
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, StencilScheme, J, M
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> ds = StencilScheme("doo-sabin", "quad", "dual", (KindRules("corner", (Rule((corner,)),)),))
>>> [(e.exact, e.multiplicity) for e in zoo_spectrum(ds, 5, digits=10).eigenvalues][:3]
[(1, 1), (1/2, 2), (1/4, 7)]
"""

from __future__ import annotations

from collections.abc import Iterable

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import cyclotomic_value
from symdecomp.analysis.charpoly import COSK, Factor, irreducible_factors
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.factor_roots import FactorRoots, ball_hull, exact_root, overlap_clusters
from symdecomp.analysis.spectrum import RingSpectrum, acb_text
from symdecomp.analysis.zoo_blocks import ZooBlocks, zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_roots import cosine_form, real_cosine_form, squarefree_roots
from symdecomp.errors import NotApplicableError, PrecisionError
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_type, check_valence

__all__ = ["zoo_spectrum", "spectrum_of_blocks", "irrational_atoms", "structural_applies", "COSINE_FORM_UP_TO"]

#: The valences whose exact values are read back from sympy's radicals to cosines (past them the structural route's
#: values are cosines already, and the table of radicals would cost O(n) cosine evaluations).
COSINE_FORM_UP_TO = 64


def irrational_atoms(exprs: Iterable[sp.Expr]) -> dict[sp.Dummy, sp.Expr]:
    """``{symbol: exact value}`` for the cosines, sines and radicals in ``exprs`` (each a fresh symbol)."""
    atoms: set[sp.Expr] = set()
    for e in exprs:
        e = sp.sympify(e, strict=True)
        atoms |= e.atoms(sp.cos, sp.sin)
        atoms |= {p for p in e.atoms(sp.Pow) if not p.exp.is_Integer and not p.free_symbols}
    ordered = sorted(atoms, key=sp.default_sort_key)
    return {sp.Dummy(f"g{i}"): a for i, a in enumerate(ordered)}


def _cosine_generator(atoms: dict[sp.Dummy, sp.Expr]) -> tuple[dict[sp.Dummy, sp.Expr], dict[sp.Dummy, sp.Expr]] | None:
    """``({g: T_m(c)}, {c: cos(2 pi/L)})`` when every atom is ``cos(r pi)`` with a rational ``r`` (``cos(2 pi m/L) =
    T_m(cos(2 pi/L))``, Chebyshev); ``None`` otherwise."""
    if len(atoms) < 2:
        return None
    ratios = []
    for a in atoms.values():
        r = a.args[0] / sp.pi if isinstance(a, sp.cos) else None
        if r is None or not r.is_Rational:
            return None
        ratios.append(r / 2)
    L = int(sp.ilcm(*[r.q for r in ratios]))
    c = sp.Dummy("c")
    return {g: sp.chebyshevt(int(r * L), c) for g, r in zip(atoms, ratios)}, {c: sp.cos(2 * sp.pi / L)}


def _generic(M: sp.Matrix, atoms: dict[sp.Dummy, sp.Expr]) -> sp.Matrix:
    back = {a: g for g, a in atoms.items()}
    return M.applyfunc(lambda e: sp.expand(sp.sympify(e, strict=True).xreplace(back)))


def spectrum_of_blocks(blocks: ZooBlocks, *, digits: int = 20, exact: bool = True, depth: int = 1, mesh: str = "") -> RingSpectrum:
    """The eigenvalues of the matrix whose blocks are ``blocks`` (see the module docstring)."""
    digits = check_digits(digits)
    n, K = blocks.n, blocks.class_count
    B, B0 = blocks.frequency_matrix(), blocks.frequency_zero_matrix()
    atoms = irrational_atoms(list(B) + list(B0))
    Bg, B0g = _generic(sp.Matrix(B), atoms), _generic(sp.Matrix(B0), atoms)
    one = _cosine_generator(atoms)
    if one is not None:  # every atom a cosine: one generator c = cos(2 pi/L), far fewer variables to factor over
        chebyshev, atoms = one
        Bg, B0g = (X.applyfunc(lambda e: sp.expand(e.xreplace(chebyshev))) for X in (Bg, B0g))
    gens = tuple(atoms)
    other = irreducible_factors((LAM * sp.eye(K) - Bg).det(method="berkowitz"), (LAM, OMEGA)) if n > 1 else ()
    zero = irreducible_factors((LAM * sp.eye(B0g.shape[0]) - B0g).det(method="berkowitz"), (LAM,))
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        g_balls = [_arb_value(a) for a in atoms.values()]
        items = [(b, 0, i, j) for b, i, j in _roots_at(FactorRoots(zero, gens), tuple(g_balls), {}, atoms, n, prec)]
        roots = FactorRoots(other, (OMEGA, COSK, *gens))
        for k in range(1, n):
            w = flint.acb(flint.arb(flint.fmpq(2 * k, n))).exp_pi_i()
            at = {OMEGA: sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)), COSK: sp.cos(2 * sp.pi * sp.Rational(k, n))}
            items += [(b, k, i, j) for b, i, j in _roots_at(roots, (w, w.real, *g_balls), at, atoms, n, prec)]
        groups = overlap_clusters(items)
        groups.sort(key=lambda g: (-float(items[g[0]][0].abs_upper()), -float(items[g[0]][0].real.mid())))
        entries = [_entry(items, g, zero, other, n, atoms, digits, exact) for g in groups]
    size = B0.shape[0] + K * (n - 1)
    return RingSpectrum(blocks.scheme, mesh, n, depth, size, digits, tuple(entries))


def _roots_at(roots: FactorRoots, args: tuple[object, ...], at: dict[sp.Symbol, sp.Expr], atoms: dict[sp.Dummy, sp.Expr], n: int,
              prec: int) -> list[tuple[flint.acb, int, int]]:
    """``[(ball, factor index, root index)]`` at one frequency (``args`` its Arb values, ``at`` its exact ones), each
    root repeated by the factor's exponent: closed forms evaluated, other roots isolated by Arb to ``2^(-prec/2)``, and a
    factor with a repeated root there split exactly (:func:`squarefree_roots`; root index ``-1``)."""
    tol = flint.arb(2) ** (-(prec // 2))
    out: list[tuple[flint.acb, int, int]] = []
    for i, f in enumerate(roots.factors):
        closed, coeffs = roots.closed[i], roots.coeffs[i]
        if closed is not None:
            balls = [(flint.acb(g(*args)), j) for j, g in enumerate(closed)]
        else:
            assert coeffs is not None  # a factor without closed forms has compiled coefficients
            poly = flint.acb_poly([flint.acb(c(*args)) for c in coeffs])
            try:
                balls = [(flint.acb(b), j) for j, b in enumerate(poly.roots(tol=tol))]
            except ValueError:  # a repeated root at this frequency: Arb's root finder does not converge
                coefficients = [sp.sympify(c, strict=True).xreplace({**at, **atoms}) for c in sp.Poly(f.poly, LAM).all_coeffs()]
                try:
                    split = squarefree_roots(coefficients, 12 * n, prec=prec)
                except ValueError as exc:
                    raise PrecisionError(f"n = {n}: a factor of a frequency block has a repeated root, and its coefficients are "
                                         f"not numbers of Q(zeta_{12 * n}) to split it exactly ({exc})") from None
                balls = [(b, -1) for b, m in split for _ in range(m)]
        out += [(b, i, j) for b, j in balls for _ in range(f.exponent)]
    return out


def _arb_value(value: sp.Expr) -> flint.acb:
    from symdecomp.algebra.compile import compile_expression

    return flint.acb(compile_expression(value, (), "arb")())


_X = sp.Dummy("x")


def _reduced(value: sp.Expr, ball: flint.acb, n: int = 0) -> sp.Expr:
    """``value`` as a rational when it is one (exactly, in a cyclotomic field); a complex form of a real value (``exp(i
    ...)`` terms) as a quadratic surd when its minimal polynomial has degree 2 (the root nearest ``ball``: they are apart),
    else, when it is a number of a cyclotomic field, as rational multiples of cosines (:func:`~symdecomp.analysis.zoo_roots.
    real_cosine_form`).
    At a valence ``n`` up to :data:`COSINE_FORM_UP_TO`, the radicals sympy wrote cosines with are read back as those
    cosines first (:func:`~symdecomp.analysis.zoo_roots.cosine_form`: ``cos(pi/8)``, not ``sqrt(sqrt(2)/4 + 1/2)``)."""
    if value.is_Rational:
        return value
    try:  # exact in Q(zeta_N): rational when its reduced polynomial is constant
        x = cyclotomic_value(cosine_form(value, n) if 0 < n <= COSINE_FORM_UP_TO else value)
    except ValueError:
        x = None
    if x is not None and x.poly.degree() <= 0:
        return sp.Rational(int(x.poly[0].p), int(x.poly[0].q))
    cosines = real_cosine_form(x) if x is not None else None  # a real value of the field: rational cosines, no exponentials
    if not value.has(sp.I):  # real forms (cosines, radicals) are kept unless the cosines' basis writes them shorter
        return cosines if cosines is not None and sp.count_ops(cosines) < sp.count_ops(value) else value
    if sp.count_ops(value) > 80:
        return cosines if cosines is not None else value  # minimal polynomials of large ones cost minutes
    p = sp.Poly(sp.minimal_polynomial(value, _X), _X)
    if p.degree() > 2:
        return cosines if cosines is not None else value
    mid = complex(float(ball.real.mid()), float(ball.imag.mid()))
    return min(sp.roots(p, _X), key=lambda r: abs(complex(r.evalf(30)) - mid))  # a rational quadratic's root: (a + sqrt(d))/b


def _entry(items: list[tuple[flint.acb, int, int, int]], group: list[int], zero: tuple[Factor, ...], other: tuple[Factor, ...],
           n: int, atoms: dict[sp.Dummy, sp.Expr], digits: int, exact: bool) -> Eigenvalue:
    b, k, i, j = items[group[0]]
    assert isinstance(b, flint.acb)
    f = (zero if k == 0 else other)[i]
    value = None
    if exact and f.roots is not None and j >= 0:
        value = _reduced(sp.expand(exact_root(f.roots[j], k, n, atoms)), b, n)
    shown = b if not isinstance(value, sp.Rational) else flint.acb(flint.fmpq(int(value.p), int(value.q)))
    return Eigenvalue(  # a rational value is shown as itself (0, not the midpoint of a ball around it)
        value=b, text=acb_text(shown, digits), multiplicity=len(group), frequencies=tuple(sorted({items[x][1] for x in group})),
        exact=value, factor=f.poly.xreplace(atoms), jordan=None, members=tuple(sorted(items[x][1:] for x in group)),
        hull=ball_hull([items[x][0] for x in group]),
    )


def structural_applies(scheme: StencilScheme, n: int) -> bool:
    """Whether valence ``n`` is past the structural form's reading and checks, and the scheme's centre rules have it."""
    from symdecomp.analysis.zoo_structure import READ_AT, zoo_structure

    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    if check_valence(n) <= READ_AT + 3:
        return False
    try:
        zoo_structure(scheme)
    except NotApplicableError:
        return False
    return True


def zoo_spectrum(scheme: StencilScheme, n: int, depth: int | None = None, *, digits: int = 20, exact: bool = True,
                 jordan: bool = True) -> RingSpectrum:
    """The eigenvalues of ``scheme``'s subdivision matrix at valence ``n`` (over its steps), by frequency.

    ``jordan``: decide the Jordan block sizes where they can be decided exactly (:mod:`symdecomp.analysis.zoo_jordan`).
    Beyond the valences the structural form is read and checked at, from that form
    (:mod:`symdecomp.analysis.zoo_large_spectrum`: ``O(n)``, no factoring at the valence); a given ``depth`` takes the
    explicit matrix.
    """
    from symdecomp.analysis.zoo_jordan import with_jordan

    if depth is None and structural_applies(scheme, n):
        from symdecomp.analysis.zoo_large_spectrum import structural_spectrum

        return structural_spectrum(scheme, n, digits=digits, exact=exact, jordan=jordan)
    zm = zoo_matrix(scheme, n, depth)
    blocks = zoo_blocks(zm)
    spectrum = spectrum_of_blocks(blocks, digits=digits, exact=exact or jordan, depth=zm.depth, mesh=scheme.lattice)
    return with_jordan(blocks, spectrum) if jordan else spectrum
