"""The eigen-data's float64s: every entry correctly rounded, and the entries that do not round at the working
precision sharpened one by one instead of the whole valence recomputed.

Symmetries make some entries exactly 0, and a ball around 0 rounds to 0.0 only inside ``(-2^-1075, 2^-1075)``,
at over 1075 bits. :func:`_round_all` rounds what it can and sends the rest here: ``V^-1``'s lower-left block
exactly (:func:`_sharpen_lower_block`, one rational solve per row), the sub-patch tables' zeros proved at
:data:`~symdecomp.analysis.eigendata.ZERO_PREC` bits column by column (:func:`_sharpen_subpatch_zeros`), and the
eigenvectors whose entries still do not round solved again at that precision, each with its own frequency group
(:func:`_replace_columns`). :func:`~symdecomp.analysis.eigendata.certified_eigendata` and
:mod:`symdecomp.analysis.eigendata_direct` round through :func:`_round_all`.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any, TypeAlias

import flint
import numpy as np

from symdecomp.algebra.numbers import to_arb, to_fmpq
from symdecomp.algebra.rounding import round_ball, round_balls, round_shared_balls
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.analysis.eigendata import ZERO_PREC, PatchEigenData, RoundedEigenData, _g_rows, _regular_part
from symdecomp.analysis.eigendata_columns import RING_EIGEN
from symdecomp.analysis.fourier_patterns import LazyTable
from symdecomp.schemes.patch import PatchMatrices

__all__: list[str] = []  # the steps of certified_eigendata and of the direct path, not an API of their own

arb = flint.arb
#: An entry ``(i, j)`` of ``V^-1``.
Entry: TypeAlias = tuple[int, int]
#: An entry ``(k, i, l)`` of the sub-patch tables.
TableEntry: TypeAlias = tuple[int, int, int]


def _round_all(data: PatchEigenData, p: PatchMatrices | None = None, inverse: list[float | None] | np.ndarray | None = None,
               phi_rounded: np.ndarray | None = None) -> RoundedEigenData | None:
    """Every entry correctly rounded, or None. With ``p``, entries that do not round are first
    sharpened (:func:`_sharpen_lower_block`, :func:`_sharpen_subpatch_zeros`, then
    :func:`_replace_columns`) and rounded again; ``data`` then holds the sharper balls. ``inverse``:
    ``V^-1`` already rounded, row-major (a list with None, or an array with NaN, where it did not round),
    else rounded here; ``phi_rounded`` likewise the sub-patch tables, flat, NaN where an entry did not round."""
    size, width = data.size, data.phi[0].ncols()
    values = round_shared_balls(data.values)  # a frequency's cosine and sine columns share their eigenvalue's ball
    if isinstance(inverse, np.ndarray) and np.isnan(inverse).any():  # NaN: not rounded; an array stays one only whole
        inverse = [None if x != x else x for x in inverse.tolist()]
    inverse = round_balls(data.inverse.entries()) if inverse is None else inverse
    if phi_rounded is None:
        phi = round_balls([x for t in data.phi for x in t.entries()])
    else:
        phi = [None if x != x else x for x in phi_rounded.tolist()]  # NaN: not rounded
    jordan = tuple((i, c, round_ball(g)) for i, c, g in data.jordan)
    if None in values or any(g is None for _, _, g in jordan):
        return None
    whole = isinstance(inverse, np.ndarray)  # every entry rounded (above)
    bad_inverse = [divmod(q, size) for q, x in enumerate(inverse) if x is None] if not whole and None in inverse else []
    bad_phi = [(q // (size * width), q // width % size, q % width) for q, x in enumerate(phi) if x is None] if None in phi else []
    if (bad_inverse or bad_phi) and p is not None:
        inverse = inverse.tolist() if isinstance(inverse, np.ndarray) else inverse  # rows may be replaced: a list again
        _sharpen_lower_block(p, data, bad_inverse)
        _sharpen_subpatch_zeros(p, data, bad_phi)
        bad_inverse, bad_phi = _reround(data, inverse, phi, bad_inverse, bad_phi)
        if (bad_inverse or bad_phi) and _replace_columns(p, data, bad_inverse, bad_phi):
            rows = {i for i, _ in bad_inverse} | {i for _, i, _ in bad_phi}
            _reround(data, inverse, phi, [(i, j) for i in rows for j in range(size)],
                     [(k, i, l) for k in range(3) for i in rows for l in range(width)])
    if (not isinstance(inverse, np.ndarray) and None in inverse) or None in phi:
        return None
    return RoundedEigenData(
        data.n, np.array(values), np.array(inverse).reshape(size, size), np.array(phi).reshape(3, size, width), jordan
    )


def _reround(data: PatchEigenData, inverse: list[float | None], phi: list[float | None], bad_inverse: list[Entry],
             bad_phi: list[TableEntry]) -> tuple[list[Entry], list[TableEntry]]:
    """Round the listed entries of ``data`` again into the flat lists; return those that still do not round."""
    size, width = data.size, data.phi[0].ncols()
    for i, j in bad_inverse:
        inverse[i * size + j] = round_ball(data.inverse[i, j])
    for k, i, l in bad_phi:
        phi[(k * size + i) * width + l] = round_ball(data.phi[k][i, l])
    return ([(i, j) for i, j in bad_inverse if inverse[i * size + j] is None],
            [(k, i, l) for k, i, l in bad_phi if phi[(k * size + i) * width + l] is None])


def _replace_columns(p: PatchMatrices, data: PatchEigenData, bad_inverse: list[Entry], bad_phi: list[TableEntry]) -> bool:
    """Replace, in ``data``, the eigenvectors whose entries do not round by the same ones at :data:`ZERO_PREC` bits.

    For each 1-ring eigenvector ``i`` with an entry that did not round (in row ``i`` of ``V^-1``
    or of a sub-patch table), its frequency group alone is solved again at ``ZERO_PREC`` bits
    (:attr:`~symdecomp.analysis.eigendata_columns.RingEigen.group`: ``O(N)`` work) and column ``i``
    of ``V``, row ``i`` of ``V^-1`` and row ``i`` of the three sub-patch tables are taken from it
    together. That keeps ``V^-1 A V`` diagonal: an eigenvector scaled otherwise comes with its left
    eigenvector scaled inversely, and the other columns do not change. False, and ``data``
    unchanged, when ``A`` has Jordan pairs (their ``gamma`` depends on the scaling), an entry
    outside those rows does not round, or the precision does not suffice; the caller then
    recomputes everything.
    """
    k0, size = p.ring_size, data.size
    rows = sorted({i for i, _ in bad_inverse} | {i for _, i, _ in bad_phi})
    if data.jordan or any(i >= k0 for i in rows):
        return False
    new = {}
    with flint.ctx.workprec(ZERO_PREC):
        ring, table, pieces = p.lattice.select(RING_EIGEN, "ring eigen-data columns"), LazyTable(p.n), _column_pieces(p)
        w = ring.weights(p)
        for i in rows:
            try:
                cols, off = ring.group(p, w, table, i, ZERO_PREC)
            except _NeedPrecision:
                return False
            column = _column_at(p, cols[off], *pieces)
            if column is None:
                return False
            new[i] = (cols[off].left, *column)
    for i, (left, vcol, phi_rows) in new.items():
        for j in range(size):
            data.inverse[i, j] = left[j] if j < k0 else arb(0)
            data.vectors[j, i] = vcol[j]
        for k, row in enumerate(phi_rows):
            for l, x in enumerate(row):
                data.phi[k][i, l] = x
    return True


def _column_pieces(p: PatchMatrices) -> tuple[Any, ...]:
    """What :func:`_column_at` needs of the regular block, at the current precision: ``nus``, ``W`` as balls, ``W^-1 S11``."""
    nus, wmat, winv = _regular_part(p)
    return nus, flint.arb_mat(wmat), _g_rows(p, winv)


def _column_at(p: PatchMatrices, col: Any, nus: Any, wa: Any, g_rows: Any) -> tuple[Any, ...] | None:
    """``(V column, sub-patch rows)`` of the patch eigenvector that extends the 1-ring eigenvector ``col``
    (``[u0; W D]``, ``D_r = (W^-1 S11 u0)_r/(lam - nu_r)``), or None where ``lam = nu_r`` is not decided
    or is a Jordan pair. ``O(N)`` work: the column alone, at the current precision."""
    size, d = p.size, []
    for r, nu in enumerate(nus):
        gap = col.value - to_arb(nu)
        coeff = sum((to_arb(x) * col.right[c] for c, x in g_rows[r].items()), arb(0))
        if not gap.contains(0):
            d.append(coeff / gap)
        elif col.exact_check is not None and col.exact_check(nu, g_rows[r]):
            d.append(arb(0))
        else:
            return None
    vcol = list(col.right) + (wa * flint.arb_mat([[x] for x in d])).entries()

    def at(idx: int) -> Any:
        return col.value * vcol[idx] if idx < size else sum((to_arb(x) * vcol[c] for c, x in p.sparse[idx].items()), arb(0))

    return vcol, [[at(idx) for idx in rows] for rows in p.subpatches]


def _sharpen_lower_block(p: PatchMatrices, data: PatchEigenData, entries: list[Entry]) -> None:
    """Replace the balls of ``V^-1``'s lower-left block that do not round by their exact rational values.

    Row ``r`` of that block is ``-D V0^-1 = -g_r (S - nu_r)^-1`` (``g = W^-1 S11``; the sum of
    ``u_c l_c/(lam_c - nu_r)`` over the eigenvectors of ``S`` is the resolvent), an exact
    rational row when ``S`` is rational and ``nu_r`` not one of its eigenvalues: one exact solve.
    Entries that cancel to 0 by symmetry are the ones that need this (a ball around 0 rounds to
    0.0 only inside ``(-2^-1075, 2^-1075)``, i.e. at over 1075 bits). Anything else is left alone.
    """
    k0, size = p.ring_size, p.size
    bad = {(i, j) for i, j in entries if i >= k0 and j < k0}
    if not bad or any(not isinstance(w, Fraction) for row in p.sparse[:k0] for w in row.values()):
        return
    nus, _, winv = _regular_part(p)
    S = flint.fmpq_mat(k0, k0)
    for i in range(k0):
        for c, x in p.sparse[i].items():
            S[i, c] = to_fmpq(x)
    for r in sorted({i - k0 for i, _ in bad}):
        g = flint.fmpq_mat(k0, 1)
        for i in range(size - k0):
            for c, x in p.sparse[k0 + i].items():
                if c < k0:
                    g[c, 0] -= winv[r, i] * to_fmpq(x)
        M = S.transpose()
        for i in range(k0):
            M[i, i] -= to_fmpq(nus[r])
        try:
            y = M.solve(g)
        except ZeroDivisionError:  # nu_r is an eigenvalue of S: leave it to the working precision
            continue
        for i, j in bad:
            if i == k0 + r:
                data.inverse[i, j] = arb(y[j, 0])


def _sharpen_subpatch_zeros(p: PatchMatrices, data: PatchEigenData, bad: list[TableEntry], prec: int = 1200) -> None:
    """Replace the sub-patch table balls around 0 that do not round by exact zeros, where 1200 bits prove them 0.

    ``bad``: the entries ``(k, i, l)`` that did not round. Entry ``(k, i, l)`` is linear in the
    eigenvector ``v_i``, so whether it is 0 does not depend on the scaling: the column alone is
    recomputed at ``prec`` bits (:func:`_column_at`), and an entry is replaced only when its new
    ball lies inside ``(-2^-1075, 2^-1075)``; everything else is left to the caller. Quads only.
    """
    if not p.lattice.select(RING_EIGEN, "ring eigen-data columns").sharpen or data.jordan:
        return
    k0 = p.ring_size
    if not bad or any(i >= k0 or not data.phi[k][i, l].contains(0) for k, i, l in bad):
        return
    tiny = arb(2) ** -1075
    with flint.ctx.workprec(prec):
        ring, table, pieces = p.lattice.select(RING_EIGEN, "ring eigen-data columns"), LazyTable(p.n), _column_pieces(p)
        w = ring.weights(p)
        for i in sorted({i for _, i, _ in bad}):
            try:
                cols, off = ring.group(p, w, table, i, prec)
            except _NeedPrecision:
                return
            column = _column_at(p, cols[off], *pieces)
            if column is None:
                return
            for k, i2, l in bad:
                if i2 != i:
                    continue
                val = column[1][k][l]
                if not (val.contains(0) and abs(val) < tiny):
                    return
                data.phi[k][i, l] = arb(0)
