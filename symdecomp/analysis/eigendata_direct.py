"""One valence of the eigen-data file rounded straight from the frequency columns, without the ``K x K`` ball matrices.

:func:`~symdecomp.analysis.eigendata.certified_eigendata` builds ``V``, ``V^-1`` and the
sub-patch tables as Arb matrices (the API's :class:`~symdecomp.analysis.eigendata.PatchEigenData`)
and then rounds them. The data file needs less: the 1-ring rows of ``V^-1`` are the left
eigenvectors of the frequency columns as they come; the lower block is one product of the
regular block's rows with them; and the sub-patch tables read ``V`` on the few rows the
sub-patches and the refined points beyond them use, so ``V`` is never built whole.
:func:`rounded_valence` rounds those balls, sharpens the entries that do not round with the same
steps as :func:`~symdecomp.analysis.eigendata.certified_eigendata` (the lower block exactly,
sub-patch zeros proved at 1200 bits, eigenvectors solved again at 1200 bits, each for its own row
only), and falls back to ``certified_eigendata`` (the whole valence at rising precision) only when
an entry still does not round. A correctly rounded float64 is unique, so either way the file's
bytes are the same.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.analysis.eigendata import certified_eigendata
>>> prec, rounded = rounded_valence(catmull_clark(), 5)
>>> whole = certified_eigendata(catmull_clark(), 5)[1]
>>> all((a.view("u8") == b.view("u8")).all() for a, b in zip((rounded.inverse, rounded.phi), (whole.inverse, whole.phi)))
True
"""

from __future__ import annotations

from dataclasses import dataclass

import flint

from symdecomp.algebra.numbers import to_arb
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.analysis.eigendata import (
    RoundedEigenData,
    _av_row,
    _outer_coefficients,
    _regular_part,
    _ring_columns,
    _round_all,
    _sparse_times,
    certified_eigendata,
)
from symdecomp.errors import PrecisionError
from symdecomp.schemes.patch import PatchMatrices, patch_matrices
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_bits, check_valence

__all__ = ["rounded_valence"]

arb = flint.arb


class _Cells:
    """A table of balls addressed ``[i, j]``, row by row: what the rounding and sharpening steps read and write."""

    __slots__ = ("rows",)

    def __init__(self, rows: list[list[flint.arb]]):
        self.rows = rows

    def __getitem__(self, ij: tuple[int, int]) -> flint.arb:
        return self.rows[ij[0]][ij[1]]

    def __setitem__(self, ij: tuple[int, int], x: flint.arb) -> None:
        self.rows[ij[0]][ij[1]] = x

    def ncols(self) -> int:
        return len(self.rows[0])

    def entries(self) -> list[flint.arb]:
        """The balls row by row (``arb_mat.entries``' order)."""
        return [x for row in self.rows for x in row]


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


def _direct(p: PatchMatrices, prec: int) -> _DirectData:
    """The balls of ``values``, ``V^-1`` and the sub-patch tables at ``prec`` bits (inside its ``workprec``)."""
    from symdecomp.analysis.eigendata import _g_rows

    k0, size = p.ring_size, p.size
    r = size - k0
    cols = _ring_columns(p, prec)
    nus, wmat, winv = _regular_part(p)
    read = _read_rows(p, _g_rows(p, winv))
    v0 = {i: [col.right[i] for col in cols] for i in read if i < k0}
    dmat, jordan = _outer_coefficients(p, cols, nus, winv, v0)
    lower = (-(flint.arb_mat(dmat) * flint.arb_mat([col.left for col in cols]))).tolist()
    v1 = (flint.arb_mat(wmat) * flint.arb_mat(dmat)).tolist()
    wa, wia = flint.arb_mat(wmat).tolist(), flint.arb_mat(winv).tolist()
    zeros = [arb(0)] * r
    vrows = {i: v0[i] + zeros if i < k0 else v1[i - k0] + wa[i - k0] for i in read if i < size}
    values = tuple(col.value for col in cols) + tuple(to_arb(nu) for nu in nus)
    beyond = {idx: _sparse_times(p.sparse[idx], vrows, size) for sub in p.subpatches for idx in sub if idx >= size}
    phi = []
    for sub in p.subpatches:
        table = [_av_row(vrows[idx], values, jordan) if idx < size else beyond[idx] for idx in sub]
        phi.append(_Cells([list(row) for row in zip(*table)]))
    inverse = _Cells([col.left + zeros for col in cols] + [lower[i] + wia[i] for i in range(r)])
    return _DirectData(p.n, prec, values, inverse, tuple(phi), tuple(jordan), _Unused())


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
            data = _direct(p, prec)
        rounded = _round_all(data, p)  # type: ignore[arg-type]  # the same fields, duck-typed
    except (_NeedPrecision, PrecisionError):
        rounded = None
    if rounded is not None:
        return prec, rounded
    whole, rounded = certified_eigendata(scheme, n, prec)
    return whole.prec, rounded
