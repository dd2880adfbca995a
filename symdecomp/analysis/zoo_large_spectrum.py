"""The spectrum of a StencilScheme at a large valence from its structural blocks, with exact values where cheap.

:func:`structural_spectrum` is :func:`~symdecomp.analysis.zoo_spectrum.zoo_spectrum`'s route beyond the valences
the structural form is read and checked at (:mod:`symdecomp.analysis.zoo_structure`): the block factors are
factored once for every ``n`` (:mod:`symdecomp.analysis.zoo_large`), so a valence costs ``O(n)`` Arb evaluations
instead of factoring a block of degree ``n/2`` in ``omega``. Each distinct value keeps its exact closed form when
its factor has one (degree ``<= 2``: the families' symbols and the rational eigenvalues), written at its
frequency, and its certified ball otherwise; Jordan blocks are decided exactly, as for the explicit route
(:mod:`symdecomp.analysis.zoo_jordan`), on the exact blocks of the form (:class:`ExactBlocks`).

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> s = structural_spectrum(load_zoo("doo-sabin"), 64, digits=10)
>>> [(e.exact, e.multiplicity, len(e.jordan)) for e in s.eigenvalues][:4], s.size
([(1, 1, 1), (1/2, 2, 2), (1/4, 125, 65), (1/8, 64, 64)], 256)
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.factor_roots import ball_hull, exact_root
from symdecomp.analysis.spectrum import RingSpectrum, acb_text
from symdecomp.analysis.zoo_blocks import signed_offset
from symdecomp.analysis.zoo_large import StructuralFactors, frequency_balls, proved_distinct_groups, structural_factors
from symdecomp.analysis.zoo_structure import ZooStructure
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.stencils import N, StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_valence

__all__ = ["ExactBlocks", "structural_spectrum"]


def _symbols_at(st: ZooStructure, n: int, k: int) -> dict[sp.Symbol, sp.Expr]:
    """``{sigma_t: its exact value}`` at valence ``n`` and frequency ``k``."""
    ks = signed_offset(k, n)
    return {sig: sp.sympify(s.value(ks), strict=True).subs(s.size, n) for sig, s in zip(st.sigma, st.symbols)}


@dataclass(frozen=True)
class ExactBlocks:
    """The structural form's exact blocks at one valence, as :mod:`symdecomp.analysis.zoo_jordan` reads them."""

    structure: ZooStructure
    n: int

    def frequency_matrix(self, omega: sp.Expr) -> sp.ImmutableMatrix:
        """The block at ``omega = zeta^k`` (``k`` from ``omega``'s argument)."""
        q = sp.simplify(sp.arg(omega) / (2 * sp.pi) * self.n)  # omega is exp(2 pi i k/n), given exactly: q is k exactly
        if not q.is_Integer:
            raise InvalidInputError(f"omega must be exp(2 pi i k/{self.n}) for an integer k, got {omega}")
        k = int(q) % self.n
        at = {OMEGA: omega, N: self.n, **_symbols_at(self.structure, self.n, k)}
        return sp.ImmutableMatrix(self.structure.block.xreplace(at))

    def frequency_zero_matrix(self) -> sp.ImmutableMatrix:
        """The frequency-0 block, bordered by the centre when there is one."""
        from symdecomp.analysis.zoo_large import _bordered

        at = {OMEGA: 1, N: self.n, **_symbols_at(self.structure, self.n, 0)}
        return sp.ImmutableMatrix(_bordered(self.structure).xreplace(at))


def _exact(factors: StructuralFactors, n: int, k: int, i: int, j: int, ball: flint.acb) -> sp.Expr | None:
    from symdecomp.analysis.zoo_spectrum import _reduced

    f = (factors.zero if k == 0 else factors.other)[i]
    if f.roots is None:
        return None
    root = f.roots[j].xreplace(factors.atoms).xreplace(_symbols_at(factors.structure, n, k))
    return _reduced(sp.expand(exact_root(root, k, n, {})), ball)


def structural_spectrum(scheme: StencilScheme, n: int, *, digits: int = 20, exact: bool = True, jordan: bool = True) -> RingSpectrum:
    """The eigenvalues of ``scheme``'s matrix at valence ``n`` from its structural blocks (module docstring)."""
    n, digits = check_valence(n), check_digits(digits)
    factors = structural_factors(scheme)
    st = factors.structure
    prec = max(128, 4 * digits + 64)
    with flint.ctx.workprec(prec):
        items = [(b, (k, i, j)) for k in range(n) for b, i, j in frequency_balls(factors, n, k)]
        entries = []
        for g in proved_distinct_groups(items):  # type: ignore[arg-type]
            ball, (k, i, j) = items[g[0]]
            members = tuple(sorted(items[x][1] for x in g))
            f = (factors.zero if k == 0 else factors.other)[i]
            entries.append(Eigenvalue(
                value=ball, text=acb_text(ball, digits), multiplicity=len(g), frequencies=tuple(sorted({m[0] for m in members})),
                exact=_exact(factors, n, k, i, j, ball) if exact or jordan else None, factor=f.poly.xreplace(factors.atoms),
                members=members, hull=ball_hull([items[x][0] for x in g])))
    size = st.class_count * n + st.has_centre
    spectrum = RingSpectrum(scheme.name, scheme.lattice, n, st.depth, size, digits, tuple(entries))
    if not jordan:
        return spectrum
    from symdecomp.analysis.zoo_jordan import with_jordan

    return with_jordan(ExactBlocks(st, n), spectrum)  # type: ignore[arg-type]  # the blocks as zoo_jordan reads them
