"""Block structure of the K-ring subdivision matrix, for symbolic valence and frequency.

By rotational symmetry the ``K``-ring matrix of :mod:`symdecomp.schemes.rings`, with its rows
in :meth:`~symdecomp.schemes.rings.RingMatrix.block_order`, is bordered by the centre and has
``K' x K'`` circulant blocks of order ``n`` (``K'`` vertex classes per sector):

    S = [[w_O, w^T (x) 1^T], [c (x) 1, (C_pq)]].

Each block is banded (its stencils reach a fixed number of sectors), so it is given by a few
offsets independent of ``n``. As in Prop. 6.2 and Remark 6.1 the spectrum splits into

* frequency ``k = 0``: the ``(K'+1) x (K'+1)`` matrix ``E_0 = [[w_O, n w^T], [c, C(1)]]``;
* frequency ``k = 1..n-1``: the ``K' x K'`` matrix ``E(omega) = (sum_l c^pq_l omega^l)`` at
  ``omega = omega_n^k``, ``C(omega)`` the matrix of block symbols.

The blocks are *read off* the matrix built by exact refinement at one valence ``n_0`` (with the
centre weights kept as symbols) and checked against the refinement at ``n_0 + 1`` and
``n_0 + 2``: the blocks must reproduce those matrices entry by entry, or an error says so.

>>> from symdecomp.schemes.loop import loop
>>> b = ring_blocks(loop(), 1)
>>> b.frequency_matrix()
Matrix([[omega/8 + 3/8 + 1/(8*omega)]])
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.numbers import to_sympy
from symdecomp.errors import InvalidSchemeError, SymdecompError
from symdecomp.schemes.lattice import Lattice
from symdecomp.schemes.rings import CENTRE_WEIGHTS, EDGE_WEIGHTS, RingMatrix, check_rings, ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached

__all__ = ["RingBlocks", "ring_blocks", "read_blocks"]


@dataclass(frozen=True)
class RingBlocks:
    """The bordered circulant-block form of the ``K``-ring matrix, for every valence."""

    scheme: str
    lattice: Lattice
    rings: int
    #: The vertex classes ``(u, v)`` of a sector.
    classes: tuple[tuple[int, int], ...]
    #: ``w_O``: the weight of the centre in the new centre, in terms of :data:`CENTRE_WEIGHTS`.
    centre: sp.Expr
    #: ``w_q``: the weight of each vertex of class ``q`` in the new centre (same symbols).
    centre_row: tuple[sp.Expr, ...]
    #: ``c_p``: the weight of the centre in each new vertex of class ``p``.
    centre_column: tuple[sp.Expr, ...]
    #: ``offsets[p][q]``: ``{l: c_l}``, the block ``C_pq`` is ``sum_l c_l P^l`` (``P`` the cyclic shift).
    offsets: tuple[tuple[tuple[tuple[int, sp.Expr], ...], ...], ...]
    #: The scheme's centre weights: :data:`CENTRE_WEIGHTS` symbol -> expression in ``n``.
    weights: tuple[tuple[sp.Symbol, sp.Expr], ...]

    @property
    def class_count(self) -> int:
        return len(self.classes)

    def frequency_matrix(self, omega=OMEGA) -> sp.ImmutableMatrix:
        """``E(omega)``: the ``K' x K'`` matrix of block symbols (frequencies ``k != 0``)."""
        K, omega = self.class_count, sp.sympify(omega, strict=True)
        return sp.ImmutableMatrix(K, K, lambda p, q: sp.Add(*[c * omega**l for l, c in self.offsets[p][q]]))

    def frequency_zero_matrix(self, n=N, *, symbolic_weights: bool = False) -> sp.ImmutableMatrix:
        """``E_0 = [[w_O, n w^T], [c, C(1)]]``; the centre weights as symbols or as the scheme's (in ``n``)."""
        C1 = self.frequency_matrix(1).subs(N, n)
        subs = {} if symbolic_weights else {s: w.subs(N, n) for s, w in self.weights}
        top = [self.centre.xreplace(subs)] + [n * w.xreplace(subs) for w in self.centre_row]
        rows = [top] + [[sp.sympify(self.centre_column[p], strict=True).subs(N, n)] + list(C1.row(p)) for p in range(self.class_count)]
        return sp.ImmutableMatrix(rows)

    def full_matrix(self, n: int, weights: dict | None = None) -> sp.ImmutableMatrix:
        """The concrete matrix in block order, rebuilt from the blocks (to compare with a refinement)."""
        K = self.class_count
        subs = weights if weights is not None else {s: w.subs(N, n) for s, w in self.weights}
        M = sp.zeros(1 + K * n, 1 + K * n)
        M[0, 0] = self.centre.xreplace(subs)
        for q in range(K):
            for s in range(n):
                M[0, 1 + q * n + s] = self.centre_row[q].xreplace(subs)
        for p in range(K):
            for s in range(n):
                M[1 + p * n + s, 0] = sp.sympify(self.centre_column[p], strict=True).subs(N, n)
                for q in range(K):
                    for l, c in self.offsets[p][q]:
                        M[1 + p * n + s, 1 + q * n + (s + l) % n] += sp.sympify(c, strict=True).subs(N, n)
        return sp.ImmutableMatrix(M)


def _signed(l: int, n: int) -> int:
    l %= n
    return l - n if l > n // 2 else l


def read_blocks(S: RingMatrix, scheme: Scheme) -> RingBlocks:
    """Read the block form off a refinement matrix built with ``symbolic_centre=True``."""
    n, classes = S.n, S.classes()
    K = len(classes)
    order = S.block_order()
    position = {r: i for i, r in enumerate(order)}
    rows = [dict() for _ in order]
    for r, row in enumerate(S.rows):
        rows[position[r]] = {position[c]: to_sympy(x) for c, x in row.items()}

    def uniform(values, what):
        values = set(values)
        if len(values) != 1:
            raise SymdecompError(f"the {what} is not the same in every sector: the matrix is not rotationally symmetric")
        return values.pop()

    centre = rows[0].get(0, sp.Integer(0))
    centre_row = tuple(uniform([rows[0].get(1 + q * n + s, sp.Integer(0)) for s in range(n)], "centre row") for q in range(K))
    centre_column = tuple(uniform([rows[1 + p * n + s].get(0, sp.Integer(0)) for s in range(n)], "centre column") for p in range(K))
    offsets = []
    for p in range(K):
        block_row = []
        for q in range(K):
            first = {_signed(c - 1 - q * n, n): x for c, x in rows[1 + p * n].items() if c and (c - 1) // n == q}
            block_row.append(tuple(sorted(first.items())))
        offsets.append(tuple(block_row))
    edges = {s: sp.sympify(w, strict=True) for s, w in S.weights.items() if s in EDGE_WEIGHTS}
    if edges:  # the edge rule at the centre's valence, as an expression in n (the model)
        centre_column = tuple(sp.sympify(x, strict=True).xreplace(edges) for x in centre_column)
        offsets = [tuple(tuple((l, sp.sympify(c, strict=True).xreplace(edges)) for l, c in block) for block in row) for row in offsets]
    v = scheme.vertex_rule
    weights = tuple(zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)))
    return RingBlocks(scheme.name, scheme.lattice, S.rings, classes, centre, centre_row, centre_column, tuple(offsets), weights)


@cached(32, scheme=check_scheme, rings=check_rings)
def ring_blocks(scheme: Scheme, rings: int = 1) -> RingBlocks:
    """The block form of ``scheme``'s ``rings``-ring matrix, read at one valence and checked at two more.

    The centre's vertex rule enters through :data:`CENTRE_WEIGHTS`. An edge rule that depends on ``n`` is read, as
    the model says (:class:`~symdecomp.schemes.scheme.Scheme`), at the centre's valence on the edges at the centre
    and at the regular valence elsewhere: its weights at the centre are kept as
    :data:`~symdecomp.schemes.rings.EDGE_WEIGHTS` while reading and then replaced by their expressions in ``n``, so
    the blocks are expressions in ``omega`` and ``n`` (in ``omega`` alone when the rules do not depend on ``n``).
    """
    n0 = 4 * rings + 7
    if n0 == scheme.lattice.regular_valence:  # pragma: no cover - 4K + 7 is odd
        n0 += 1
    blocks = read_blocks(ring_subdivision_matrix(scheme, n0, rings, symbolic_centre=True), scheme)
    for n in (n0 + 1, n0 + 2):
        S = ring_subdivision_matrix(scheme, n, rings, symbolic_centre=True)
        order = S.block_order()
        symbols = {s: s for s in CENTRE_WEIGHTS}
        built = blocks.full_matrix(n, symbols).subs(N, n)
        edges = {s: sp.sympify(w, strict=True).subs(N, n) for s, w in S.weights.items() if s in EDGE_WEIGHTS}
        refined = sp.zeros(S.size, S.size)
        for r, row in enumerate(S.rows):
            for c, x in row.items():
                refined[r, c] = sp.sympify(to_sympy(x), strict=True).xreplace(edges).subs(N, n)
        if refined.extract(order, order) != built:
            raise InvalidSchemeError(
                f"scheme {scheme.name!r}: the {rings}-ring matrix at n = {n} is not the banded block form read at n = {n0}"
            )
    return blocks
