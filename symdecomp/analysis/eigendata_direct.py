"""One valence of the eigen-data file rounded straight from the frequency columns, without the ``K x K`` ball matrices.

:func:`~symdecomp.analysis.eigendata.certified_eigendata` builds ``V``, ``V^-1`` and the
sub-patch tables as Arb matrices (the API's :class:`~symdecomp.analysis.eigendata.PatchEigenData`)
and then rounds them. The data file needs less: the 1-ring rows of ``V^-1`` are the left
eigenvectors of the frequency columns as they come; the lower block is one product of the
regular block's rows with them; and the sub-patch tables read ``V`` on the few rows the
sub-patches and the refined points beyond them use, so ``V`` is never built whole.
:func:`rounded_valence` rounds those: the 1-ring rows of ``V^-1`` all at once from their factors
(:func:`_round_ring_rows`), the rest ball by ball. Entries that do not round are sharpened alone: the
sub-patch tables' zeros of a mirror symmetry are exact (:mod:`symdecomp.analysis.eigendata_zeros`), the
lower block's likewise where a mirror makes them, else from the columns at 1200 bits
(:func:`_lower_at_zero_prec`), the tables' and the
1-ring rows' with :func:`~symdecomp.analysis.eigendata.certified_eigendata`'s steps (sub-patch
zeros proved at 1200 bits, eigenvectors solved again at 1200 bits, each for its own row); only
when an entry still does not round is the whole valence taken from ``certified_eigendata`` at
rising precision. A correctly rounded float64 is unique, so either way the file's
bytes are the same.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.analysis.eigendata import certified_eigendata
>>> prec, rounded = rounded_valence(catmull_clark(), 5)
>>> whole = certified_eigendata(catmull_clark(), 5)[1]
>>> all((a.view("u8") == b.view("u8")).all() for a, b in zip((rounded.inverse, rounded.phi), (whole.inverse, whole.phi)))
True
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import flint
import numpy as np

from symdecomp.algebra.numbers import to_arb
from symdecomp.algebra.rounding import round_ball, round_balls, round_products, round_shared_balls, split_balls
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.analysis.eigendata import (
    RoundedEigenData,
    _av_row,
    _outer_coefficients,
    _regular_part,
    _ring_columns,
    _sparse_times,
    certified_eigendata,
)
from symdecomp.analysis.eigendata_columns import RING_EIGEN
from symdecomp.analysis.eigendata_sharpen import _round_all
from symdecomp.analysis.eigendata_zeros import lower_mirror_zeros, mirror_zeros
from symdecomp.analysis.fourier_patterns import LazyTable, TrigTable
from symdecomp.errors import PrecisionError
from symdecomp.schemes.patch import PatchMatrices, patch_matrices
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_bits, check_valence

__all__ = ["rounded_valence"]

arb = flint.arb


class _Cells:
    """A table of balls addressed ``[i, j]``, row by row: what the rounding and sharpening steps read and write.
    A row given as None is made by ``fill(i)`` when first read."""

    __slots__ = ("rows", "fill")

    def __init__(self, rows: list[list[flint.arb] | None], fill: Callable[[int], list[flint.arb]] | None = None):
        self.rows, self.fill = rows, fill

    def row(self, i: int) -> list[flint.arb]:
        row = self.rows[i]
        if row is None:
            assert self.fill is not None
            row = self.rows[i] = self.fill(i)
        return row

    def __getitem__(self, ij: tuple[int, int]) -> flint.arb:
        return self.row(ij[0])[ij[1]]

    def __setitem__(self, ij: tuple[int, int], x: flint.arb) -> None:
        self.row(ij[0])[ij[1]] = x

    def ncols(self) -> int:
        return len(self.row(0))

    def entries(self) -> list[flint.arb]:
        """The balls row by row (``arb_mat.entries``' order)."""
        return [x for i in range(len(self.rows)) for x in self.row(i)]


class _Unused:
    """``V``: not part of the file; a replaced eigenvector's new column is dropped."""

    def __setitem__(self, ij: tuple[int, int], x: flint.arb) -> None:
        pass


@dataclass(frozen=True)
class _DirectData:
    """The balls the file needs, laid out as :class:`~symdecomp.analysis.eigendata.PatchEigenData`'s."""

    n: int
    prec: int
    values: tuple[flint.arb, ...]
    inverse: _Cells
    phi: tuple[_Cells, ...]  # three, K x P
    jordan: tuple[tuple[int, int, flint.arb], ...]
    vectors: _Unused

    @property
    def size(self) -> int:
        return len(self.values)


def _read_rows(p: PatchMatrices, g_rows: list[dict[int, object]]) -> set[int]:
    """The rows of ``V`` that the coefficients ``D`` (through ``W^-1 S11``) and the sub-patch tables read."""
    rows = {c for g in g_rows for c in g}
    for sub in p.subpatches:
        for idx in sub:
            rows.update([idx] if idx < p.size else p.sparse[idx])
    return rows


def _direct(p: PatchMatrices, prec: int) -> tuple[_DirectData, np.ndarray, np.ndarray]:
    """The balls of ``values``, ``V^-1`` (its 1-ring rows made only where read) and the sub-patch tables at
    ``prec`` bits (inside its ``workprec``), ``V^-1`` rounded (:func:`_round_ring_rows`, then the lower block)
    and the tables rounded (each point's row of ``A V`` once), flat, row-major, NaN where an entry did not round
    (a correctly rounded entry is finite)."""
    from symdecomp.analysis.eigendata import _g_rows

    k0, size = p.ring_size, p.size
    r = size - k0
    cols = _ring_columns(p, prec)
    nus, wmat, winv = _regular_part(p)
    g_rows = _g_rows(p, winv)
    read = _read_rows(p, g_rows)
    v0 = {i: [col.right_at(i) for col in cols] for i in read if i < k0}
    dmat, jordan = _outer_coefficients(p, cols, nus, winv, v0, g_rows)
    lower = _lower_by_waves(cols, dmat)
    if lower is None:
        lower = (-(flint.arb_mat(dmat) * flint.arb_mat([col.left for col in cols]))).tolist()
    v1 = (flint.arb_mat(wmat) * flint.arb_mat(dmat)).tolist()
    wa, wia = flint.arb_mat(wmat).tolist(), flint.arb_mat(winv).tolist()
    zeros = [arb(0)] * r
    vrows = {i: v0[i] + zeros if i < k0 else v1[i - k0] + wa[i - k0] for i in read if i < size}
    values = tuple(col.value for col in cols) + tuple(to_arb(nu) for nu in nus)
    outside = sorted({idx for sub in p.subpatches for idx in sub if idx >= size})
    beyond = dict(zip(outside, _sparse_times([p.sparse[idx] for idx in outside], vrows, size)))
    # a point shared by sub-patches has one row of A V, made and rounded once (half the tables' entries are repeats)
    points = sorted({idx for sub in p.subpatches for idx in sub})
    av = {idx: _av_row(vrows[idx], values, jordan) if idx < size else beyond[idx] for idx in points}
    phi = [_Cells([list(row) for row in zip(*[av[idx] for idx in sub])]) for sub in p.subpatches]
    by_point = np.array(round_balls([x for idx in points for x in av[idx]]), dtype=float).reshape(len(points), size)
    place = {idx: q for q, idx in enumerate(points)}
    phi_rounded = np.stack([by_point[[place[idx] for idx in sub]].T for sub in p.subpatches])  # (3, K, P), NaN: not rounded
    for k, i, l in mirror_zeros(p, cols, nus, wmat, g_rows) if not jordan else ():
        if phi[k][i, l].contains(0):  # exact by the symmetry: the ball needs no 1200 bits to round to 0.0
            phi[k][i, l], phi_rounded[k, i, l] = arb(0), 0.0
    lower_rows: list[list[flint.arb] | None] = [lower[i] + wia[i] for i in range(r)]
    ring_rows: list[list[flint.arb] | None] = [None] * k0
    inverse = _Cells(ring_rows + lower_rows, lambda i: cols[i].left + zeros)
    lower_rounded = np.array(round_balls([x for row in lower_rows if row is not None for x in row]), dtype=float)
    rounded = np.concatenate([_round_ring_rows(cols, size).ravel(), lower_rounded])  # NaN: not rounded (None)
    for i, j in lower_mirror_zeros(p, cols, g_rows) if not jordan else ():
        if np.isnan(rounded[i * size + j]) and inverse[i, j].contains(0):  # exact by the symmetry
            inverse[i, j], rounded[i * size + j] = arb(0), 0.0
    # the lower block's 1-ring columns that did not round, found in one array test (an index test per entry was
    # about 3 per cent of Catmull-Clark's N = 3..128)
    lower_left = np.isnan(rounded[k0 * size:].reshape(r, size)[:, :k0])
    bad = [(k0 + i, j) for i, j in np.argwhere(lower_left).tolist()]
    for (i, j), x in _lower_at_zero_prec(p, bad).items():
        inverse[i, j], rounded[i * size + j] = x, round_ball(x)  # None (not rounded) is stored as NaN
    return _DirectData(p.n, prec, values, inverse, tuple(phi), tuple(jordan), _Unused()), rounded, phi_rounded.ravel()


def _wave_layout(cols: list[Any]) -> tuple[list[int], list[int], list[tuple[int, int, np.ndarray]]] | None:
    """``(waves, others, groups)``: the columns whose left rows are waves of one shared table and one layout
    (:attr:`~symdecomp.analysis.fourier_patterns.PatternForm.wave`, each checked against its ``index``), the other
    columns, and the entries of a row by ``(coefficient, half step)``: ``(e, eps, points)`` with ``points[k]``
    the entry at ``steps = 2k + eps``, ``k = 0..n-1``. None when the rows are not of that form."""
    waves = [c for c, col in enumerate(cols) if col.left_form is not None and col.left_form.wave is not None]
    if not waves:
        return None
    first = cols[waves[0]].left_form
    table, coef, steps = first.table, first.coef, first.wave[2]
    if not isinstance(table, list) or len(table) % 4:
        return None
    period = len(table)
    forms = [cols[c].left_form for c in waves]
    if any(f.table is not table or f.wave[2] is not steps and not np.array_equal(f.wave[2], steps)
           or f.wave[1] % period not in (0, period - period // 4) for f in forms):
        return None
    # every wave's coefficients and indices checked at once against its frequency and shift
    js, shifts = (np.array([f.wave[m] for f in forms], dtype=np.int64)[:, None] for m in (0, 1))
    expected = np.where(steps[None, :] < 0, -1, (2 * js * steps[None, :] + shifts) % period)
    if not (np.array_equal(np.stack([f.coef for f in forms]), np.broadcast_to(coef, (len(forms), len(coef))))
            and np.array_equal(np.stack([f.index for f in forms]), expected)):
        return None
    n, groups = period // 4, []
    for e in sorted(set(coef[steps >= 0].tolist())):
        for eps in (0, 1):
            points = np.nonzero((steps >= 0) & (coef == e) & (steps % 2 == eps))[0]
            if len(points):
                if not np.array_equal(np.sort(steps[points]), 2 * np.arange(n) + eps):
                    return None
                groups.append((e, eps, points[np.argsort(steps[points])]))
    wave_set = set(waves)  # once: a set per column made this quadratic in N
    return waves, [c for c in range(len(cols)) if c not in wave_set], groups


def _lower_by_waves(cols: list[Any], dmat: list[list[flint.arb]]) -> list[list[flint.arb]] | None:
    """``V^-1``'s lower-left block ``-D V0^-1`` with the wave rows of ``V0^-1`` summed by discrete Fourier
    transforms (Arb's certified DFT, ``O(N log N)`` per row instead of ``O(N^2)``); None when the
    columns are not waves (:func:`_wave_layout`).

    A wave of frequency ``j`` at half step ``2k + eps`` is ``cos(2 pi j (k + eps/2)/n)`` (or the sine), so
    ``sum_j A_j cos + B_j sin`` over the columns is the real part of ``sum_j (A_j + i B_j) e^(-i pi j eps/n)
    e^(-2 pi i j k/n)``: entry ``k`` of the DFT of those coefficients. The other columns (the rational
    frequencies) are one small matrix product.
    """
    layout = _wave_layout(cols)
    if layout is None:
        return None
    waves, others, groups = layout
    table = cols[waves[0]].left_form.table
    period, k0 = len(table), len(cols)
    n, acb = period // 4, flint.acb
    # per wave column and group: its coefficient's slot j and its complex factor, ``x`` (the cosine, A_j) or ``i x``
    # (the sine, B_j), times the half step ``e^(-i pi j/n)`` where the group's points sit at odd half steps
    slots = [cols[c].left_form.wave[0] for c in waves]
    sine = [bool(cols[c].left_form.wave[1] % period) for c in waves]
    half_step = [acb(table[(2 * j) % period], -table[(2 * j - n) % period]) for j in range(n)]  # e^(-i pi j/n)
    factors = {}
    for e, eps, _ in groups:
        xs = [cols[c].left_form.scalars[e] for c in waves]
        zs = [acb(0, x) if s else acb(x) for x, s in zip(xs, sine)]
        factors[(e, eps)] = [z * half_step[j] for z, j in zip(zs, slots)] if eps else zs
    zero = arb(0)
    out = [[zero] * k0 for _ in dmat]
    sums, places = [], []  # per row and group: the coefficients to transform, and (row, points) to write
    for r, drow in enumerate(dmat):
        dw = [-drow[c] for c in waves]
        for e, eps, points in groups:
            coeffs: list[Any] = [None] * n  # (A_j + i B_j) e^(-i pi j eps/n), j = 0..n-1
            for d, z, j in zip(dw, factors[(e, eps)], slots):
                term = z * d
                coeffs[j] = term if coeffs[j] is None else coeffs[j] + term
            sums.append([acb(0) if x is None else x for x in coeffs])
            places.append((r, points.tolist()))
    for (r, points), values in zip(places, _real_parts_of_dfts(sums)):
        for p, value in zip(points, values):
            out[r][p] = value
    if others:
        rest = (-(flint.arb_mat([[drow[c] for c in others] for drow in dmat]) * flint.arb_mat([cols[c].left for c in others]))).tolist()
        out = [[x + y for x, y in zip(row, extra)] for row, extra in zip(out, rest)]
    return out


#: Lengths whose largest prime factor is at least this have two DFTs made in one (:func:`_real_parts_of_dfts`, about
#: 2 microseconds a point of Python arithmetic). Measured on the lower block's own sums (Catmull-Clark, N = 3..128):
#: about 12 ms a valence saved at the primes past 100 (Arb's DFT of such a length costs about 2 ms), within a
#: millisecond either way at the others (their sums, sparse in exact zeros, transform faster than random vectors).
PACK_FROM = 7


def _largest_prime_factor(n: int) -> int:
    factor, largest = 2, 1
    while factor * factor <= n:
        while n % factor == 0:
            largest, n = factor, n // factor
        factor += 1
    return max(largest, n)


def _real_parts_of_dfts(vectors: list[list[flint.acb]]) -> list[list[flint.arb]]:
    """The real parts of the DFTs (Arb's, ``X_k = sum_j x_j e^(-2 pi i j k/n)``) of vectors of one length ``n``.

    Where a transform of length ``n`` is slow (a prime factor from :data:`PACK_FROM`), two are made in one:
    with ``h_j = x_j + conj(x_(-j))`` (Hermitian), ``DFT(h) = X + conj(X) = 2 Re X`` is real, so
    ``DFT(h1 + i h2) = 2 Re X1 + 2i Re X2``, and the real and imaginary parts of one certified transform hold
    both (halving is exact). ``h1 + i h2 = u_j + conj(v_(-j))`` with ``u = x1 + i x2``, ``v = x1 - i x2``.
    """
    if not vectors:
        return []
    acb, n = flint.acb, len(vectors[0])
    if _largest_prime_factor(n) < PACK_FROM:
        return [[value.real for value in acb.dft(x)] for x in vectors]
    out, i = [], acb(0, 1)
    for a in range(0, len(vectors) - 1, 2):
        turned = [i * q for q in vectors[a + 1]]
        u = [p + q for p, q in zip(vectors[a], turned)]
        w = [(p - q).conjugate() for p, q in zip(vectors[a], turned)]
        both = acb.dft([u[j] + w[-j % n] for j in range(n)])
        out += [[z.real / 2 for z in both], [z.imag / 2 for z in both]]
    if len(vectors) % 2:
        out.append([value.real for value in acb.dft(vectors[-1])])
    return out


def _lower_at_zero_prec(p: PatchMatrices, entries: list[tuple[int, int]]) -> dict[tuple[int, int], flint.arb]:
    """The listed entries of ``V^-1``'s lower block from the frequency columns at
    :data:`~symdecomp.analysis.eigendata.ZERO_PREC` bits (empty where that precision does not separate the
    eigenvalues, or where ``lam_c = nu_r`` with a Jordan pair: the whole valence's path handles those).

    Row ``r`` of the block is ``-sum_c (g_r . u_c)/(lam_c - nu_r) l_c``, the resolvent of ``S`` at ``nu_r``
    applied to ``-g_r`` (``g = W^-1 S11``): it does not depend on how the eigenvectors are scaled, so the
    columns at the higher precision give the same exact entries. Zeros of the symmetries round (to 0.0)
    only at over 1075 bits; this costs ``O(N)`` balls for the columns and for each row, ``O(N)`` per entry,
    where the exact solve of :func:`~symdecomp.analysis.eigendata_sharpen._sharpen_lower_block` is ``O(N^3)``.
    """
    from symdecomp.analysis.eigendata import ZERO_PREC, _g_rows

    if not entries:
        return {}
    k0, out = p.ring_size, {}
    with flint.ctx.workprec(ZERO_PREC):
        try:
            # the few trig values the read entries need, not the whole table at 1200 bits
            cols = p.lattice.select(RING_EIGEN, "ring eigen-data columns").columns(p, LazyTable(p.n), ZERO_PREC)
        except _NeedPrecision:
            return {}
        nus, _, winv = _regular_part(p)
        g_rows = _g_rows(p, winv)
        for r in sorted({i - k0 for i, _ in entries}):
            g, nu = [(c, to_arb(x)) for c, x in g_rows[r].items()], to_arb(nus[r])
            d = []
            for col in cols:
                gap = col.value - nu
                if not gap.contains(0):
                    d.append(sum((x * col.right_at(c) for c, x in g), arb(0)) / gap)
                elif col.exact_check is not None and col.exact_check(nus[r], g_rows[r]):
                    d.append(arb(0))  # lam_c = nu_r exactly, and u_c adds nothing to row r
                else:
                    return {}
            for i, j in entries:
                if i == k0 + r:
                    out[(i, j)] = -sum((dc * col.left_at(j) for dc, col in zip(d, cols)), arb(0))
    return out


def _round_ring_rows(cols: list[Any], size: int) -> np.ndarray:
    """The 1-ring rows of ``V^-1`` rounded, ``k0 x size`` (NaN where an entry does not round: a correctly rounded
    entry is finite), kept as an array from the products to the file.

    Rows kept as :class:`~symdecomp.analysis.fourier_patterns.PatternForm` s (a scalar times a cosine of the
    trig table) are rounded all at once from their factors (:func:`~symdecomp.algebra.rounding.round_products`),
    the table split once; what that does not certify, and the other rows, are rounded ball by ball."""
    k0 = len(cols)
    out = np.zeros((k0, size))
    formed = [i for i, col in enumerate(cols) if col.left_form is not None]
    tables = {id(cols[i].left_form.table) for i in formed}
    if len(tables) > 1 or any(not isinstance(cols[i].left_form.table, list) for i in formed):
        formed = []  # factors from several tables, or a lazy one: ball by ball
    certified = np.ones((k0, size), dtype=bool)
    if formed:
        forms = [cols[i].left_form for i in formed]
        table = forms[0].table  # trig_table's splits a quarter of its balls; index -1 below: the exact 0
        c = np.concatenate([table.split() if isinstance(table, TrigTable) else split_balls(table), np.zeros((3, 1))], axis=1)
        width = max(len(f.scalars) for f in forms)
        s = np.zeros((3, len(forms), width))
        split = split_balls([x for f in forms for x in f.scalars])  # all the forms' scalars in one pass
        start = np.cumsum([0] + [len(f.scalars) for f in forms])
        for q, f in enumerate(forms):
            s[:, q, : len(f.scalars)] = split[:, start[q]: start[q + 1]]
        coef, index = np.stack([f.coef for f in forms]), np.stack([f.index for f in forms])
        vals, ok = round_products(s[:, np.arange(len(forms))[:, None], coef], c[:, index])
        out[formed, :k0], certified[formed, :k0] = vals, ok
    for i in set(range(k0)) - set(formed):
        out[i, :k0] = np.array(round_shared_balls(cols[i].left), dtype=float)  # None -> NaN; a period's balls repeat
    for i, j in zip(*np.nonzero(~certified)):
        x = round_ball(cols[i].left_form.at(j))
        out[i, j] = np.nan if x is None else x
    return out


def rounded_valence(scheme: Scheme, n: int, prec: int = 256) -> tuple[int, RoundedEigenData]:
    """``(precision, RoundedEigenData)``: valence ``n`` of the data file, every float64 correctly rounded.

    From the frequency columns at ``prec`` bits (:func:`_direct`), with the entries that do not
    round sharpened row by row; if any entry still does not round, the whole valence comes from
    :func:`~symdecomp.analysis.eigendata.certified_eigendata` at rising precision. Raises
    :class:`~symdecomp.errors.NotDiagonalizableError` as ``certified_eigendata`` does.
    """
    check_scheme(scheme)
    n, prec = check_valence(n), check_bits(prec)
    p = patch_matrices(scheme, n)
    try:
        with flint.ctx.workprec(prec):
            data, inverse, phi = _direct(p, prec)
        rounded = _round_all(data, p, inverse, phi)  # type: ignore[arg-type]  # the same fields, duck-typed
    except (_NeedPrecision, PrecisionError):
        rounded = None
    if rounded is not None:
        return prec, rounded
    whole, rounded = certified_eigendata(scheme, n, prec)
    return whole.prec, rounded
