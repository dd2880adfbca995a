"""The spectrum of a StencilScheme at a large valence, from its structural blocks: ``O(n)`` per valence.

The structural form (:mod:`symdecomp.analysis.zoo_structure`) gives the block of frequency ``k`` as a
matrix in ``omega``, ``n`` and the families' symbols ``sigma_t``. Its characteristic polynomial is factored
*once*, over those quantities as independent variables (the cosines and radicals of ``n`` in the centre's
weights each a variable too), as :func:`symdecomp.analysis.spectrum.ring_spectrum` factors a 1-ring scheme's in
``omega``: an identity in the variables holds at every value of them. At a valence ``n`` and a frequency
``k`` each factor's roots are then closed forms (degree ``<= 2``) evaluated in Arb, or isolated by Arb
(``acb_poly.roots``); a factor with a repeated root at one frequency cannot be isolated there, and the
caller is told so (:class:`~symdecomp.errors.PrecisionError`).

>>> import flint
>>> from symdecomp.schemes.stencil_files import load_zoo
>>> f = structural_factors(load_zoo("doo-sabin"))
>>> with flint.ctx.workprec(128):
...     balls = frequency_balls(f, 1000, 1)
>>> sorted(str(b.real.mid())[:6] for b, _, _ in balls)
['0.0625', '0.1250', '0.2500', '0.5000']
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.analysis.charpoly import COSK, Factor, irreducible_factors
from symdecomp.analysis.factor_roots import FactorRoots
from symdecomp.analysis.zoo_structure import ZooStructure, zoo_structure
from symdecomp.errors import PrecisionError
from symdecomp.schemes.stencils import N, StencilScheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import omega as OMEGA

__all__ = ["StructuralFactors", "structural_factors", "frequency_balls", "proved_distinct_groups"]


@dataclass(frozen=True)
class StructuralFactors:
    """The factored characteristic polynomials of a scheme's structural blocks, for every valence."""

    structure: ZooStructure
    #: ``{variable: expression in n}``: the cosines and radicals of ``n`` in the blocks, each a variable.
    atoms: dict[sp.Symbol, sp.Expr]
    #: The factors at frequency 0 (the bordered block).
    zero: tuple[Factor, ...]
    #: The factors at the other frequencies, in ``omega`` (or ``c_k = cos(2 pi k/n)``).
    other: tuple[Factor, ...]

    @functools.cached_property
    def _evaluators(self) -> tuple[FactorRoots, FactorRoots, list[Any]]:
        variables = (N, *self.structure.sigma, *self.atoms)
        atoms = [compile_expression(e, (N,), "arb") for e in self.atoms.values()]
        return FactorRoots(self.zero, variables), FactorRoots(self.other, (OMEGA, COSK, *variables)), atoms


def _atoms(exprs: list[sp.Expr]) -> dict[sp.Symbol, sp.Expr]:
    found: set[sp.Expr] = set()
    for e in exprs:
        found |= {a for a in sp.sympify(e, strict=True).atoms(sp.cos, sp.sin) if a.has(N)}
        found |= {p for p in sp.sympify(e, strict=True).atoms(sp.Pow) if not p.exp.is_Integer and p.has(N)}
    return {sp.Symbol(f"g{i}"): a for i, a in enumerate(sorted(found, key=sp.default_sort_key))}


def _bordered(st: ZooStructure) -> sp.Matrix:
    B1 = sp.Matrix(st.block.subs(OMEGA, 1))
    if not st.has_centre:
        return B1
    K = st.class_count
    top = sp.Matrix([list(st.border[:K + 1])])
    return sp.Matrix.vstack(top, sp.Matrix.hstack(sp.Matrix(list(st.border[K + 1:])), B1))


def structural_factors(scheme: StencilScheme) -> StructuralFactors:
    """Factor ``det(lambda I - B)`` of the structural blocks once (module docstring)."""
    return _structural_factors(zoo_structure(scheme))


@functools.lru_cache(maxsize=16)
def _structural_factors(st: ZooStructure) -> StructuralFactors:
    at_zero = {sig: sp.sympify(s.value(0), strict=True).xreplace({s.size: N}) for sig, s in zip(st.sigma, st.symbols)}
    # at k = 0 the symbols are their values there (in n): the factoring sees, e.g., the root 1 of an affine scheme
    B, B0 = sp.Matrix(st.block), _bordered(st).xreplace(at_zero)
    atoms = _atoms(list(B) + list(B0))
    back = {a: g for g, a in atoms.items()}
    Bg, B0g = (X.applyfunc(lambda e: sp.expand(sp.sympify(e, strict=True).xreplace(back))) for X in (B, B0))
    variables = (N, *st.sigma, *atoms)
    other = irreducible_factors((LAM * sp.eye(Bg.shape[0]) - Bg).det(method="berkowitz"), (LAM, OMEGA, *variables))
    zero = irreducible_factors((LAM * sp.eye(B0g.shape[0]) - B0g).det(method="berkowitz"), (LAM, *variables))
    return StructuralFactors(st, atoms, zero, other)


def frequency_balls(factors: StructuralFactors, n: int, k: int) -> list[tuple[flint.acb, int, int]]:
    """``[(ball, factor index, root index)]``: the eigenvalues of the block of frequency ``k`` at valence ``n``, each
    repeated by its factor's exponent, at the working precision. :class:`PrecisionError` if a root cannot be isolated."""
    zero, other, atoms = factors._evaluators
    nb = flint.acb(n)
    values = (nb, *factors.structure.sigma_values(n, k), *(g(nb) for g in atoms))
    if k == 0:
        roots, args = zero, values
    else:
        w = flint.acb(flint.arb(flint.fmpq(2 * k, n))).exp_pi_i()
        roots, args = other, (w, w.real, *values)
    try:
        return [(b, i, j) for b, i, j in roots.at(args) if isinstance(b, flint.acb)]  # Arb balls, each of them
    except ValueError:
        raise PrecisionError(f"n = {n}, frequency {k}: a factor has a repeated root there (Arb cannot isolate it)") from None


def _sweep(items: list[tuple[flint.acb, object]], part: str) -> list[list[int]]:
    """Indices grouped where the ``part`` (``"real"``/``"imag"``) intervals overlap, transitively (a sweep)."""
    def interval(i: int) -> tuple[float, float]:
        x = getattr(items[i][0], part)
        return float(x.lower()), float(x.upper())
    order = sorted(range(len(items)), key=interval)
    groups: list[list[int]] = []
    reach = float("-inf")
    for i in order:
        lo, hi = interval(i)
        if not groups or lo > reach:
            groups.append([i])
            reach = hi
        else:
            groups[-1].append(i)
            reach = max(reach, hi)
    return groups


def proved_distinct_groups(items: list[tuple[flint.acb, object]]) -> list[list[int]]:
    """Groups of balls, apart in their real, then imaginary, projections (``O(m log m)`` for ``m`` balls, where pairwise
    overlap tests would cost ``m^2``); largest modulus first. Float bounds: a caller that proves distinctness checks the
    groups' exact hulls apart."""
    out: list[list[int]] = []
    for g in _sweep(items, "real"):
        sub = [items[i] for i in g]
        out += [[g[j] for j in h] for h in _sweep(sub, "imag")]
    out.sort(key=lambda g: (-float(items[g[0]][0].abs_upper()), -float(items[g[0]][0].real.mid())))
    return out
