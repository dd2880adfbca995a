"""Jordan block sizes of a StencilScheme's eigenvalues, exactly, from the frequency blocks.

Frequencies are independent (different Fourier subspaces), so the Jordan blocks of a value are those
of each frequency block ``B_k`` at the value. Where the value is exact and it and the block's entries
are numbers of a cyclotomic field ``Q(zeta_12n)`` (rationals, cosines of rational multiples of ``pi``),
the sizes follow from exact ranks of the powers of ``B_k - lambda I``
(:func:`~symdecomp.analysis.factor_roots.jordan_partition`, over
:class:`~symdecomp.algebra.cyclotomic.CyclotomicField`); the ranks also prove that the value has the
multiplicity the balls gave it at that frequency (a radical sympy wrote a cosine with is read back as that cosine,
:func:`~symdecomp.analysis.zoo_roots.cosine_form`). Otherwise (another radical, a root of a factor of degree > 2
repeated at one frequency) the structure is left unknown (``None``).

>>> import sympy as sp
>>> from symdecomp.analysis.zoo_blocks import zoo_blocks
>>> from symdecomp.analysis.zoo_matrix import zoo_matrix
>>> from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, StencilScheme, J, M
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> ds = StencilScheme("doo-sabin", "quad", "dual", (KindRules("corner", (Rule((corner,)),)),))
>>> b = zoo_blocks(zoo_matrix(ds, 4))
>>> [(e.exact, e.jordan) for e in with_jordan(b, spectrum_of_blocks(b)).eigenvalues][:3]
[(1, (1,)), (1/2, (1, 1)), (1/4, (1, 1, 1, 1, 1))]
"""

from __future__ import annotations

import dataclasses

import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.factor_roots import jordan_partition
from symdecomp.analysis.spectrum import RingSpectrum
from symdecomp.analysis.zoo_blocks import ZooBlocks
from symdecomp.analysis.zoo_roots import cosine_form

__all__ = ["with_jordan", "jordan_by_frequency"]


def jordan_by_frequency(blocks: ZooBlocks, e: Eigenvalue, field: CyclotomicField | None = None) -> dict[int, tuple[int, ...]] | None:
    """``{k: Jordan block sizes of e in B_k}`` at each of ``e``'s frequencies, exactly (module docstring), or ``None``
    where that is not decided."""
    field = field or CyclotomicField(12 * blocks.n)
    by_k: dict[int, int] = {}
    for k, _, _ in e.members:
        by_k[k] = by_k.get(k, 0) + 1
    out: dict[int, tuple[int, ...]] = {}
    n = blocks.n
    for k, m in sorted(by_k.items()):
        if m == 1:  # a simple root at its frequency: one block of size 1
            out[k] = (1,)
            continue
        if e.exact is None:
            return None
        B = blocks.frequency_zero_matrix() if k == 0 else blocks.frequency_matrix(sp.exp(2 * sp.pi * sp.I * sp.Rational(k, n)))
        try:
            value = cyclotomic_value(cosine_form(e.exact, n), field=field)
            A = [[cyclotomic_value(cosine_form(B[r, c], n), field=field) - (value if r == c else 0) for c in range(B.shape[1])]
                 for r in range(B.shape[0])]
        except ValueError:
            return None
        found = jordan_partition(A, m)
        if sum(found) != m:
            return None  # the value's multiplicity at k is not what the balls said: leave it undecided
        out[k] = tuple(found)
    return out


def _sizes(blocks: ZooBlocks, e: Eigenvalue, field: CyclotomicField) -> tuple[int, ...] | None:
    by_k = jordan_by_frequency(blocks, e, field)
    return None if by_k is None else tuple(sorted((s for sizes in by_k.values() for s in sizes), reverse=True))


def with_jordan(blocks: ZooBlocks, spectrum: RingSpectrum) -> RingSpectrum:
    """``spectrum`` with each value's Jordan block sizes, where they are decided exactly (module docstring)."""
    field = CyclotomicField(12 * blocks.n)
    entries = tuple(dataclasses.replace(e, jordan=_sizes(blocks, e, field)) for e in spectrum.eigenvalues)
    return dataclasses.replace(spectrum, eigenvalues=entries)
