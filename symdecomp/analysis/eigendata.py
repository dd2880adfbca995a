"""Certified eigenstructure of the patch matrix (Stam's exact-evaluation data): Catmull-Clark and Loop.

Written for the (2N+8)-point Catmull-Clark patch below; Loop's (N+6)-point patch
(:mod:`symdecomp.schemes.patch`) shares the whole assembly with its own 1-ring columns
(:mod:`symdecomp.analysis.eigendata_columns`) and a 5 x 5 regular block, and where its matrix
is not diagonalizable (N = 3) keeps the Jordan pairs (:attr:`PatchEigenData.jordan`) instead of
refusing.

The patch matrix (:func:`~symdecomp.schemes.patch.patch_matrices`) is block lower triangular,
``A = [[S, 0], [S11, S12]]``: ``S`` is the 1-ring matrix, ``S12`` the 7 x 7 matrix of the
regular points beyond the patch. Its eigenstructure is assembled from exact pieces:

* ``S`` is block circulant; in the real Fourier basis (``cos`` and ``sin`` of ``2 pi j k/N`` on
  ``e_k``, shifted by half a step on ``f_k``, which makes every block real because the rules
  are mirror symmetric) it splits into a 3 x 3 rational block (``j = 0``), real 2 x 2 blocks
  (``0 < j < N/2``) whose entries are cosines of rational multiples of pi, and for even ``N`` a
  rational 2 x 2 block (``j = N/2``). Rational blocks are diagonalized exactly (factored
  characteristic polynomial, exact null spaces); the others in Arb balls from the quadratic
  formula. Left eigenvectors come from the same blocks, normalized against the right ones, so
  ``V0^-1`` is written down, not computed by elimination.
* ``S12`` is rational: exact eigenvalues and eigenvectors ``W``.
* An eigenvector ``u0`` of ``S`` for ``lam`` extends to ``[u0; W (lam - D)^-1 W^-1 S11 u0]``;
  when ``lam`` equals an eigenvalue ``nu`` of ``S12`` (decided exactly, in a cyclotomic field)
  the matching component of ``W^-1 S11 u0`` must vanish exactly, else ``A`` is not
  diagonalizable and :class:`NotDiagonalizableError` says so.
* ``V^-1 = [[V0^-1, 0], [-C V0^-1, W^-1]]`` with ``C = (lam_k - nu_r)^-1 (W^-1 S11 V0)``.

Every number is an Arb ball containing the exact value, at a working precision chosen by the
caller; :func:`certified_eigendata` raises it until every entry rounds correctly to float64.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> data, arrays = certified_eigendata(catmull_clark(), 4)
>>> sorted(set(arrays.values.tolist()))
[0.015625, 0.03125, 0.0625, 0.125, 0.25, 0.5, 1.0]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import flint
import numpy as np

from symdecomp.algebra.numbers import to_arb, to_fmpq, to_fraction
from symdecomp.algebra.rounding import round_ball
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.algebra.small_eigen import rational_eigen as _rational_eigen
from symdecomp.analysis.eigendata_columns import RING_EIGEN
from symdecomp.analysis.fourier_patterns import trig_table
from symdecomp.errors import NotDiagonalizableError, PrecisionError
from symdecomp.parallel import ordered_map, pool_size
from symdecomp.schemes.patch import PatchMatrices, patch_matrices
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_bits, check_memory, check_valence

__all__ = [
    "NotDiagonalizableError", "PrecisionError", "PatchEigenData", "RoundedEigenData", "patch_eigendata", "certified_eigendata",
    "rounded_eigendata", "round_ball", "eigendata_cost", "check_eigendata_cost", "ZERO_PREC",
]  # NotDiagonalizableError, PrecisionError: from symdecomp.errors

arb, acb = flint.arb, flint.acb


@dataclass(frozen=True)
class PatchEigenData:
    """Eigenvalues, right eigenvectors ``V``, ``V^-1`` and the sub-patch tables, as Arb balls."""

    n: int
    prec: int
    values: tuple  # K arb
    vectors: flint.arb_mat  # V, K x K, column i belongs to values[i]
    inverse: flint.arb_mat  # V^-1
    phi: tuple  # three arb_mat, K x P: phi[k][i, l] = coefficient l of eigenfunction i on sub-patch k
    #: ``(i, c, gamma)``: ``A v_c = lam_c v_c + gamma v_i`` (``lam_i = lam_c``), so ``V^-1 A V = diag(values) + N``
    #: with ``N[i, c] = gamma``, ``N^2 = 0``: a Jordan pair (Loop at N = 3). Empty when ``A`` is diagonalizable.
    jordan: tuple = ()

    @property
    def size(self) -> int:
        return len(self.values)


@dataclass(frozen=True)
class RoundedEigenData:
    """The correctly rounded float64 arrays of one valence, in the data file's element order."""

    n: int
    values: np.ndarray  # (K,)
    inverse: np.ndarray  # (K, K): inverse[i, j]
    phi: np.ndarray  # (3, K, P): phi[k, i, l], P = 16 (quads) or 12 (triangles)
    jordan: tuple = ()  # (i, c, gamma) as in PatchEigenData, gamma correctly rounded


# ---------------------------------------------------------------------------------------------
# assembly


_REGULAR: dict = {}


def _regular_part(p: PatchMatrices):
    """:func:`_regular_part_of` ``p``'s regular block, remembered by its entries (the same 7 x 7 or 5 x 5 for every N)."""
    k0, r = p.ring_size, p.size - p.ring_size
    key = tuple(tuple(p.sparse[k0 + i].get(k0 + j, Fraction(0)) for j in range(r)) for i in range(r))
    if key not in _REGULAR:
        if len(_REGULAR) > 8:
            _REGULAR.clear()
        _REGULAR[key] = _regular_part_of([list(row) for row in key])
    return _REGULAR[key]


def _regular_part_of(s12: list[list]):
    """Exact eigenvalues ``nu``, eigenvectors ``W`` and ``W^-1`` of the regular block ``S12`` (7 x 7 quads, 5 x 5 triangles)."""
    r = len(s12)
    nus, columns = [], []
    for lam, right, _ in _rational_eigen(s12):
        if not isinstance(lam, Fraction):
            raise NotDiagonalizableError(f"the regular block has an irrational eigenvalue {lam}: not supported")
        for z in right:
            nus.append(lam)
            columns.append(z)
    w = flint.fmpq_mat(r, r, [to_fmpq(columns[c][i]) for i in range(r) for c in range(r)])
    return nus, w, w.inv()


def patch_eigendata(scheme: Scheme, n: int, prec: int = 128) -> PatchEigenData:
    """The eigenstructure of the patch matrix at valence ``n`` in Arb balls at ``prec`` bits.

    Raises :class:`NotDiagonalizableError` when there is no eigenvector basis, and
    :class:`PrecisionError` when ``prec`` is too low to decide a sign on the way. ``prec``: ``16..MAX_BITS`` bits.
    """
    check_scheme(scheme)
    n, prec = check_valence(n), check_bits(prec)
    try:
        with flint.ctx.workprec(prec):
            return _eigendata(patch_matrices(scheme, n), prec)
    except _NeedPrecision:
        raise PrecisionError(f"valence {n}: {prec} bits do not separate the eigenvalues") from None


def _eigendata(p: PatchMatrices, prec: int) -> PatchEigenData:
    n, k0, size = p.n, p.ring_size, p.size
    r = size - k0
    cols = _ring_columns(p, prec)
    assert len(cols) == k0
    nus, wmat, winv = _regular_part(p)
    right_rows = [list(r) for r in zip(*(col.right for col in cols))]  # V0 as rows
    dmat, jordan = _outer_coefficients(p, cols, nus, winv, right_rows)
    v0inv = flint.arb_mat([col.left for col in cols])
    lower = (-(flint.arb_mat(dmat) * v0inv)).tolist()
    v1 = (flint.arb_mat(wmat) * flint.arb_mat(dmat)).tolist()
    wa, wia = flint.arb_mat(wmat).tolist(), flint.arb_mat(winv).tolist()
    zeros = [arb(0)] * r
    vec_rows = [row + zeros for row in right_rows] + [v1[i] + wa[i] for i in range(r)]
    inv_rows = [col.left + zeros for col in cols] + [lower[i] + wia[i] for i in range(r)]
    values = tuple(col.value for col in cols) + tuple(to_arb(nu) for nu in nus)
    # rows of the refined points beyond the K control points: sparse rows times V
    beyond = _sparse_times(list(p.sparse[size:]), vec_rows, size)
    phi = []
    for rows in p.subpatches:
        cols_k = [_av_row(vec_rows[idx], values, jordan) if idx < size else beyond[idx - size] for idx in rows]
        phi.append(flint.arb_mat(cols_k).transpose())
    return PatchEigenData(n, prec, values, flint.arb_mat(vec_rows), flint.arb_mat(inv_rows), tuple(phi), tuple(jordan))


def _av_row(v_row: list, values, jordan) -> list:
    """A row of ``A V = V (diag(values) + N)``."""
    out = [lam * x for lam, x in zip(values, v_row)]
    for i, c, gamma in jordan:
        out[c] = out[c] + gamma * v_row[i]
    return out


def _ring_columns(p: PatchMatrices, prec: int) -> list:
    """The eigenvectors of the 1-ring block, frequency by frequency (:mod:`symdecomp.analysis.eigendata_columns`)."""
    return p.lattice.select(RING_EIGEN, "ring eigen-data columns").columns(p, trig_table(p.n), prec)


def _sparse_times(sparse: list[dict], rows: Sequence | Mapping, size: int) -> list[list]:
    """``[sum_c row[c] rows[c] for row in sparse]``: sparse rows times the rows they name (a list of rows, or only
    those in a dict), as one Arb matrix product over the named rows (FLINT's loop, not Python's)."""
    used = sorted({c for row in sparse for c in row})
    if not used:
        return [[arb(0)] * size for _ in sparse]
    weights = flint.arb_mat([[to_arb(row[c]) if c in row else 0 for c in used] for row in sparse])
    return (weights * flint.arb_mat([rows[c] for c in used])).tolist()


def _g_rows(p: PatchMatrices, winv) -> list[dict]:
    """The rows of ``W^-1 S11`` (exact, sparse)."""
    k0, r = p.ring_size, p.size - p.ring_size
    s11 = flint.fmpq_mat(r, k0)
    for i in range(r):
        for c, x in p.sparse[k0 + i].items():
            if c < k0:
                s11[i, c] = to_fmpq(x)
    g_exact = winv * s11
    return [{c: to_fraction(g_exact[i, c]) for c in range(k0) if g_exact[i, c] != 0} for i in range(r)]


def _outer_coefficients(p: PatchMatrices, cols, nus, winv, right_rows, g_rows: list[dict] | None = None) -> tuple[list, list]:
    """``(D, jordan)``: ``D[r][c] = (W^-1 S11 u_c)_r / (lam_c - nu_r)``; where ``lam_c = nu_r`` (decided
    exactly) ``D[r][c] = 0``, and a nonzero ``gamma = (W^-1 S11 u_c)_r`` is a Jordan pair ``(k0 + r, c, gamma)``
    (triangle patches; a quad patch that is not diagonalizable is refused). ``g_rows``: :func:`_g_rows` of ``p``
    and ``winv`` where the caller has made them already (they are exact: the same rows either way)."""
    n, k0 = p.n, p.ring_size
    g_rows = _g_rows(p, winv) if g_rows is None else g_rows
    dmat, jordan = [], []
    coeffs = _sparse_times(g_rows, right_rows, k0)
    for r, nu in enumerate(nus):
        coeff, ball, row = coeffs[r], to_arb(nu), []
        for c, col in enumerate(cols):
            gap = col.value - ball
            if not gap.contains(0):
                row.append(coeff[c] / gap)
                continue
            verdict = col.exact_check(nu, g_rows[r]) if col.exact_check else None
            if verdict is None:
                raise _NeedPrecision
            if not verdict and p.lattice.select(RING_EIGEN, "ring eigen-data columns").jordan:
                jordan.append((k0 + r, c, coeff[c]))
            elif not verdict:
                raise NotDiagonalizableError(
                    f"valence {n}: the eigenvalue {nu} of the 1-ring and of the regular block has fewer eigenvectors "
                    "than its multiplicity (the patch matrix is not diagonalizable)"
                )
            row.append(arb(0))
        dmat.append(row)
    return dmat, jordan


#: The precision at which an exact 0 is proved (a ball around it rounds to 0.0 only inside
#: ``(-2^-1075, 2^-1075)``): the sharpening steps' (:mod:`symdecomp.analysis.eigendata_sharpen`).
ZERO_PREC = 1200


def certified_eigendata(scheme: Scheme, n: int, prec: int = 256, max_prec: int = 1 << 14) -> tuple[PatchEigenData, RoundedEigenData]:
    """The eigen-data at valence ``n`` at the lowest precision (from ``prec``, then 1200, doubling) that rounds it all.

    Symmetries make some entries exactly 0, and a ball around 0 rounds to 0.0 only inside
    ``(-2^-1075, 2^-1075)``. Those in ``V^-1``'s lower-left block are computed exactly instead
    (:mod:`symdecomp.analysis.eigendata_sharpen`), and those in the sub-patch tables are proved 0 column by
    column at 1200 bits, so Catmull-Clark rounds at the 256-bit
    start; anything left (Loop's cyclotomic 1-ring) is taken, eigenvector by eigenvector, from one
    solve at 1200 bits, and only what still does not round (Loop's
    Jordan pairs at N = 3) makes the next try a whole one at 1200 bits.

    Every float64 returned is the correctly rounded value of the exact number, whose Arb ball
    is returned too. Raises :class:`PrecisionError` past ``max_prec`` bits (both ``16..MAX_BITS``).
    """
    from symdecomp.analysis.eigendata_sharpen import _round_all  # it builds on this module

    check_scheme(scheme)
    n, prec, max_prec = check_valence(n), check_bits(prec), check_bits(max_prec, "max_prec")
    while True:
        try:
            data = patch_eigendata(scheme, n, prec)
            rounded = _round_all(data, patch_matrices(scheme, n))
        except PrecisionError:
            rounded = None
        if rounded is not None:
            return data, rounded
        if prec >= max_prec:
            raise PrecisionError(f"valence {n}: the eigen-data did not round correctly at {prec} bits")
        # Exact zeros (symmetries) round only once the ball is inside (-2^-1075, 2^-1075).
        prec = max(2 * prec, 1200)


#: Calibration of :func:`eigendata_cost` (x86_64, 2026-12): a process with the package loaded; peak
#: bytes per entry of the ``K x K`` matrices of one valence (256 bits); CPU seconds per valence of the file's
#: path (:mod:`symdecomp.analysis.eigendata_direct`), ``a K + b K^2 + c K^3``, fitted to Catmull-Clark and Loop at
#: N = 3..128, 256 and 500 (the cubic term is Catmull-Clark's past N = 128; Loop stays below it); CPU seconds per
#: valence of the dense path at ``D > 17`` digits, ``a K^2 + b K^3`` at 256 bits, and per number written (1200-bit balls).
_BASE_BYTES, _ENTRY_BYTES = 120 << 20, 1600
_SECONDS, _DENSE_SECONDS, _DECIMAL_SECONDS = (2e-4, 2e-7, 4e-9), (9e-6, 3e-8), 3e-5


#: Bytes of JSON text a number at most: a quoted shortest round-trip float64 and its comma (``"-1.2345678901234567e-100",``).
_TEXT_BYTES = 27


def eigendata_cost(scheme: Scheme, nmax: int, jobs: int = 1, digits: int = 17, text: bool = False) -> tuple[int, float]:
    """``(bytes, seconds)``: the estimated peak memory and wall-clock time of the data file for valences ``3..nmax``.

    ``jobs`` processes each hold one valence at a time (finished valences wait for their turn in
    the main process: 8 bytes a number, or as JSON text with ``text``, :data:`_TEXT_BYTES`);
    ``digits > 17``: the decimal JSON form, from wider balls, one process.
    """
    p = patch_matrices(scheme, 3)
    extra, width = p.size - p.ring_size, len(p.subpatches[0])
    sizes = [scheme.lattice.one_ring_size(n) + extra for n in range(3, nmax + 1)]
    numbers = [k * k + k + 3 * width * k for k in sizes]
    workers = 1 if digits > 17 else max(1, min(jobs, len(sizes)))
    if digits > 17:  # balls of max(1200, 3.33 D + 64) bits, one process, a text per number
        scale = max(ZERO_PREC, 3.33 * digits + 64) / 256
        peak = _BASE_BYTES + (_ENTRY_BYTES * scale + 2 * (digits + 60)) * sizes[-1] ** 2
        seconds = sum(scale * (_DENSE_SECONDS[0] * k * k + _DENSE_SECONDS[1] * k**3) for k in sizes)
        return int(peak), seconds + _DECIMAL_SECONDS * scale * 256 / ZERO_PREC * sum(numbers)
    peak = _BASE_BYTES * (1 + (workers if workers > 1 else 0)) + workers * _ENTRY_BYTES * sizes[-1] ** 2
    held = (_TEXT_BYTES if text else 8) * sum(numbers) if workers > 1 else 0
    a, b, c = _SECONDS
    seconds = sum(a * k + b * k * k + c * k**3 for k in sizes) / workers
    return int(peak + held), seconds


def check_eigendata_cost(scheme: Scheme, nmax: int, jobs: int = 1, digits: int = 17, text: bool = False) -> tuple[int, float]:
    """:func:`eigendata_cost`, refused (:class:`~symdecomp.errors.ResourceLimitError`, naming the estimate)
    when the memory exceeds the limit of :func:`symdecomp.validate.check_memory`."""
    memory, seconds = eigendata_cost(scheme, nmax, jobs, digits, text)
    hours = f"{seconds / 3600:.1f} h" if seconds > 3600 else f"{seconds:.0f} s"
    check_memory(memory, f"the eigen-data for valences 3..{nmax} ({jobs} processes; about {hours} of computing)")
    return memory, seconds


def _rounded_one(n: int, scheme: Scheme, encode: Callable | None = None) -> tuple[int, Any]:
    from symdecomp.analysis.eigendata_direct import rounded_valence  # it builds on this module

    prec, rounded = rounded_valence(scheme, n)
    return prec, rounded if encode is None else encode(rounded)


def rounded_eigendata(scheme: Scheme, ns, jobs: int = 1, executor="local", encode: Callable | None = None):
    """Yield ``(precision, RoundedEigenData)`` for the valences ``ns`` in order, on at most ``jobs`` processes.

    The pool is :func:`symdecomp.parallel.ordered_map` (``executor``: ``"local"``, ``"dask"`` or
    ``"dask=ADDRESS"``); the largest valences are handed out first, to keep every worker busy.
    ``encode``: a module-level function of a :class:`RoundedEigenData` (the file's text or bytes of the valence),
    applied where the valence is computed, and its result yielded instead: the workers write the file's pieces
    in parallel, and the largest valences, done first, do not wait to be encoded one by one at the end.
    Refused before any work when the memory estimate is beyond the limit (:func:`check_eigendata_cost`).
    """
    from symdecomp.analysis import eigendata_direct  # noqa: F401 - imported once here, before the workers fork

    ns = list(ns)
    if ns:
        check_eigendata_cost(scheme, max(ns), pool_size(jobs, len(ns)))
    shared = {"scheme": scheme} if encode is None else {"scheme": scheme, "encode": encode}
    yield from ordered_map(_rounded_one, ns, shared=shared, jobs=jobs, executor=executor, cost=lambda n: n)
