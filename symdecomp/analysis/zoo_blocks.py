"""The frequency blocks of a StencilScheme's subdivision matrix, from its neighbourhood's orbit labelling.

The rotation by one sector permutes the labelled points ``(s, c) -> (s + 1, c)`` and fixes the
centre, and the scheme commutes with it, so the matrix is block circulant around a border: with
``A_d[c, c']`` the weight of point ``(s + d, c')`` in new point ``(s, c)`` (the same for every
``s``, checked exactly), the frequency-``k`` block is ``B_k = sum_d A_d zeta^(dk)``
(``zeta = e^(2 pi i/n)``), and the centre enters only at ``k = 0``:
``B_0 = [[w_O, sum_s w_(s, c')], [c_c, B(1)]]``. The spectrum of the matrix is that of ``B_0``
and of ``B_k``, ``k = 1..n-1``. :meth:`ZooBlocks.frequency_matrix` gives ``B(omega)`` with ``omega``
a symbol, the offsets ``d`` taken in ``(-n/2, n/2]``, as :func:`symdecomp.analysis.frequency.ring_blocks` does.

>>> import sympy as sp
>>> from symdecomp.analysis.zoo_matrix import zoo_matrix
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, StencilScheme, J, M
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> ds = StencilScheme("doo-sabin", "quad", "dual", (KindRules("corner", (Rule((corner,)),)),))
>>> b = zoo_blocks(zoo_matrix(ds, 6))
>>> b.class_count, b.frequency_matrix(1)[0, 0]
(4, 1)
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.analysis.zoo_matrix import ZooMatrix
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.stencil_rows import is_zero
from symdecomp.symbols import omega as OMEGA

__all__ = ["ZooBlocks", "zoo_blocks", "signed_offset"]


def signed_offset(d: int, n: int) -> int:
    """``d`` modulo ``n`` in ``(-n/2, n/2]``."""
    d %= n
    return d - n if d > n // 2 else d


@dataclass(frozen=True)
class ZooBlocks:
    """The bordered block-circulant form of a StencilScheme's matrix at one valence."""

    #: The scheme's name.
    scheme: str
    n: int
    #: Whether there is a fixed centre point (vertex-centred).
    has_centre: bool
    #: ``{d: A_d}``: the class-by-class blocks by sector offset ``d`` (signed).
    offsets: dict[int, sp.Matrix]
    #: ``w_O``: the centre's weight in the new centre (0 without a centre).
    centre: sp.Expr
    #: ``w_c'`` summed over the sectors: the weight of class ``c'`` in the new centre.
    centre_row: tuple[sp.Expr, ...]
    #: ``c_c``: the centre's weight in each new point of class ``c``.
    centre_column: tuple[sp.Expr, ...]

    @property
    def class_count(self) -> int:
        return len(self.centre_column)

    def frequency_matrix(self, omega: sp.Expr = OMEGA) -> sp.ImmutableMatrix:
        """``B(omega) = sum_d A_d omega^d`` (``omega = zeta^k`` gives the block of frequency ``k``)."""
        K = self.class_count
        total = sp.zeros(K, K)
        for d, A in self.offsets.items():
            total += A * sp.sympify(omega, strict=True) ** d
        return sp.ImmutableMatrix(total.applyfunc(sp.expand))

    def frequency_zero_matrix(self) -> sp.ImmutableMatrix:
        """``B_0``: the frequency-0 block, bordered by the centre when there is one."""
        B1 = self.frequency_matrix(1)
        if not self.has_centre:
            return B1
        top = sp.Matrix([[self.centre, *self.centre_row]])
        bottom = sp.Matrix.hstack(sp.Matrix(self.centre_column), B1)
        return sp.ImmutableMatrix(sp.Matrix.vstack(top, bottom))


def _same(a: sp.Expr, b: sp.Expr) -> bool:
    return a == b or is_zero(a - b)


def zoo_blocks(zm: ZooMatrix) -> ZooBlocks:
    """Read the blocks off ``zm``'s matrix, checking exactly that it commutes with the rotation."""
    nb, S, n = zm.neighbourhood, zm.matrix, zm.n
    index = nb.index()
    K = len(nb.classes)
    at = {nb.labels[v]: index[v] for v in nb.order if v != nb.centre}
    offsets = {signed_offset(d, n): sp.Matrix(K, K, [S[at[(0, c)], at[(d, e)]] for c in range(K) for e in range(K)]) for d in range(n)}
    offsets = {d: A for d, A in offsets.items() if any(x != 0 for x in A)}
    for s in range(1, n):
        for (t, c), i in at.items():
            if t != s:
                continue
            for (u, e), j in at.items():
                if not _same(S[i, j], S[at[(0, c)], at[((u - s) % n, e)]]):
                    raise InvalidSchemeError(f"scheme {zm.scheme!r}: the matrix at n = {n} does not commute with the rotation")
    if nb.centre is None:
        return ZooBlocks(zm.scheme, n, False, offsets, sp.Integer(0), (), tuple(sp.Integer(0) for _ in range(K)))
    o = index[nb.centre]
    row = tuple(sp.expand(sum(S[o, at[(s, c)]] for s in range(n))) for c in range(K))
    column = tuple(S[at[(0, c)], o] for c in range(K))
    return ZooBlocks(zm.scheme, n, True, offsets, S[o, o], row, column)
