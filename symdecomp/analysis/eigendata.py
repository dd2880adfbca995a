"""Certified eigenstructure of the patch matrix (Stam's exact-evaluation data): Catmull-Clark and Loop.

Written for the (2N+8)-point Catmull-Clark patch below; Loop's (N+6)-point patch
(:mod:`symdecomp.schemes.patch`) shares the whole assembly with its own 1-ring columns
(:mod:`symdecomp.analysis.ring_eigendata`) and a 5 x 5 regular block, and where its matrix
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

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.numbers import to_arb, to_fmpq, to_fraction
from symdecomp.algebra.rounding import round_ball, round_balls
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.algebra.small_eigen import rational_eigen as _rational_eigen
from symdecomp.analysis.fourier_patterns import LazyTable, trig_table
from symdecomp.analysis.ring_eigendata import RING_EIGEN
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
    """The eigenvectors of the 1-ring block, frequency by frequency (:mod:`symdecomp.analysis.ring_eigendata`)."""
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


def _outer_coefficients(p: PatchMatrices, cols, nus, winv, right_rows) -> tuple[list, list]:
    """``(D, jordan)``: ``D[r][c] = (W^-1 S11 u_c)_r / (lam_c - nu_r)``; where ``lam_c = nu_r`` (decided
    exactly) ``D[r][c] = 0``, and a nonzero ``gamma = (W^-1 S11 u_c)_r`` is a Jordan pair ``(k0 + r, c, gamma)``
    (triangle patches; a quad patch that is not diagonalizable is refused)."""
    n, k0 = p.n, p.ring_size
    g_rows = _g_rows(p, winv)
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


# ---------------------------------------------------------------------------------------------
# correct rounding


def _round_all(data: PatchEigenData, p: PatchMatrices | None = None, inverse: list | None = None) -> RoundedEigenData | None:
    """Every entry correctly rounded, or None. With ``p``, entries that do not round are first
    sharpened (:func:`_sharpen_lower_block`, :func:`_sharpen_subpatch_zeros`, then
    :func:`_replace_columns`) and rounded again; ``data`` then holds the sharper balls. ``inverse``:
    ``V^-1`` already rounded (row by row, None where it did not round), else rounded here."""
    size, width = data.size, data.phi[0].ncols()
    values = round_balls(data.values)
    inverse = round_balls(data.inverse.entries()) if inverse is None else inverse
    phi = round_balls([x for t in data.phi for x in t.entries()])
    jordan = tuple((i, c, round_ball(g)) for i, c, g in data.jordan)
    if None in values or any(g is None for _, _, g in jordan):
        return None
    bad_inverse = [divmod(q, size) for q, x in enumerate(inverse) if x is None] if None in inverse else []
    bad_phi = [(q // (size * width), q // width % size, q % width) for q, x in enumerate(phi) if x is None] if None in phi else []
    if (bad_inverse or bad_phi) and p is not None:
        _sharpen_lower_block(p, data, bad_inverse)
        _sharpen_subpatch_zeros(p, data, bad_phi)
        bad_inverse, bad_phi = _reround(data, inverse, phi, bad_inverse, bad_phi)
        if (bad_inverse or bad_phi) and _replace_columns(p, data, bad_inverse, bad_phi):
            rows = {i for i, _ in bad_inverse} | {i for _, i, _ in bad_phi}
            _reround(data, inverse, phi, [(i, j) for i in rows for j in range(size)],
                     [(k, i, l) for k in range(3) for i in rows for l in range(width)])
    if None in inverse or None in phi:
        return None
    return RoundedEigenData(
        data.n, np.array(values), np.array(inverse).reshape(size, size), np.array(phi).reshape(3, size, width), jordan
    )


def _reround(data: PatchEigenData, inverse: list, phi: list, bad_inverse, bad_phi) -> tuple[list, list]:
    """Round the listed entries of ``data`` again into the flat lists; return those that still do not round."""
    size, width = data.size, data.phi[0].ncols()
    for i, j in bad_inverse:
        inverse[i * size + j] = round_ball(data.inverse[i, j])
    for k, i, l in bad_phi:
        phi[(k * size + i) * width + l] = round_ball(data.phi[k][i, l])
    return ([(i, j) for i, j in bad_inverse if inverse[i * size + j] is None],
            [(k, i, l) for k, i, l in bad_phi if phi[(k * size + i) * width + l] is None])


#: The precision of :func:`_replace_columns`: a ball around an exact 0 rounds (to 0.0) only
#: inside ``(-2^-1075, 2^-1075)``.
ZERO_PREC = 1200


def _replace_columns(p: PatchMatrices, data: PatchEigenData, bad_inverse, bad_phi) -> bool:
    """Replace, in ``data``, the eigenvectors whose entries do not round by the same ones at :data:`ZERO_PREC` bits.

    For each 1-ring eigenvector ``i`` with an entry that did not round (in row ``i`` of ``V^-1``
    or of a sub-patch table), its frequency group alone is solved again at ``ZERO_PREC`` bits
    (:attr:`~symdecomp.analysis.ring_eigendata.RingEigen.group`: ``O(N)`` work) and column ``i``
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


def _column_pieces(p: PatchMatrices) -> tuple:
    """What :func:`_column_at` needs of the regular block, at the current precision: ``nus``, ``W`` as balls, ``W^-1 S11``."""
    nus, wmat, winv = _regular_part(p)
    return nus, flint.arb_mat(wmat), _g_rows(p, winv)


def _column_at(p: PatchMatrices, col, nus, wa, g_rows) -> tuple | None:
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
    at = lambda idx: col.value * vcol[idx] if idx < size else sum((to_arb(x) * vcol[c] for c, x in p.sparse[idx].items()), arb(0))  # noqa: E731
    return vcol, [[at(idx) for idx in rows] for rows in p.subpatches]


def _sharpen_lower_block(p: PatchMatrices, data: PatchEigenData, entries) -> None:
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


def _sharpen_subpatch_zeros(p: PatchMatrices, data: PatchEigenData, bad, prec: int = 1200) -> None:
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


def certified_eigendata(scheme: Scheme, n: int, prec: int = 256, max_prec: int = 1 << 14) -> tuple[PatchEigenData, RoundedEigenData]:
    """The eigen-data at valence ``n`` at the lowest precision (from ``prec``, then 1200, doubling) that rounds it all.

    Symmetries make some entries exactly 0, and a ball around 0 rounds to 0.0 only inside
    ``(-2^-1075, 2^-1075)``. Those in ``V^-1``'s lower-left block are computed exactly instead
    (:func:`_sharpen_lower_block`), and those in the sub-patch tables are proved 0 column by
    column at 1200 bits (:func:`_sharpen_subpatch_zeros`), so Catmull-Clark rounds at the 256-bit
    start; anything left (Loop's cyclotomic 1-ring) is taken, eigenvector by eigenvector, from one
    solve at 1200 bits (:func:`_replace_columns`), and only what still does not round (Loop's
    Jordan pairs at N = 3) makes the next try a whole one at 1200 bits.

    Every float64 returned is the correctly rounded value of the exact number, whose Arb ball
    is returned too. Raises :class:`PrecisionError` past ``max_prec`` bits (both ``16..MAX_BITS``).
    """
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
#: bytes per entry of the ``K x K`` matrices of one valence (256 bits); CPU seconds per valence,
#: ``a K^2 + b K^3``; per number written at ``D > 17`` digits (1200-bit balls).
_BASE_BYTES, _ENTRY_BYTES, _SECONDS, _DECIMAL_SECONDS = 120 << 20, 1600, (9e-6, 3e-8), 3e-5


def eigendata_cost(scheme: Scheme, nmax: int, jobs: int = 1, digits: int = 17) -> tuple[int, float]:
    """``(bytes, seconds)``: the estimated peak memory and wall-clock time of the data file for valences ``3..nmax``.

    ``jobs`` processes each hold one valence at a time (finished valences wait for their turn in
    the main process); ``digits > 17``: the decimal JSON form, from wider balls, one process.
    """
    p = patch_matrices(scheme, 3)
    extra, width = p.size - p.ring_size, len(p.subpatches[0])
    sizes = [scheme.lattice.one_ring_size(n) + extra for n in range(3, nmax + 1)]
    numbers = [k * k + k + 3 * width * k for k in sizes]
    workers = 1 if digits > 17 else max(1, min(jobs, len(sizes)))
    if digits > 17:  # balls of max(1200, 3.33 D + 64) bits, one process, a text per number
        scale = max(ZERO_PREC, 3.33 * digits + 64) / 256
        peak = _BASE_BYTES + (_ENTRY_BYTES * scale + 2 * (digits + 60)) * sizes[-1] ** 2
        seconds = sum(scale * (_SECONDS[0] * k * k + _SECONDS[1] * k**3) for k in sizes)
        return int(peak), seconds + _DECIMAL_SECONDS * scale * 256 / ZERO_PREC * sum(numbers)
    peak = _BASE_BYTES * (1 + (workers if workers > 1 else 0)) + workers * _ENTRY_BYTES * sizes[-1] ** 2
    held = 8 * sum(numbers) if workers > 1 else 0
    seconds = sum(_SECONDS[0] * k * k + _SECONDS[1] * k**3 for k in sizes) / workers
    return int(peak + held), seconds


def check_eigendata_cost(scheme: Scheme, nmax: int, jobs: int = 1, digits: int = 17) -> tuple[int, float]:
    """:func:`eigendata_cost`, refused (:class:`~symdecomp.errors.ResourceLimitError`, naming the estimate)
    when the memory exceeds the limit of :func:`symdecomp.validate.check_memory`."""
    memory, seconds = eigendata_cost(scheme, nmax, jobs, digits)
    hours = f"{seconds / 3600:.1f} h" if seconds > 3600 else f"{seconds:.0f} s"
    check_memory(memory, f"the eigen-data for valences 3..{nmax} ({jobs} processes; about {hours} of computing)")
    return memory, seconds


def _rounded_one(n: int, scheme: Scheme) -> tuple[int, RoundedEigenData]:
    from symdecomp.analysis.eigendata_direct import rounded_valence  # it builds on this module

    return rounded_valence(scheme, n)


def rounded_eigendata(scheme: Scheme, ns, jobs: int = 1, executor="local"):
    """Yield ``(precision, RoundedEigenData)`` for the valences ``ns`` in order, on at most ``jobs`` processes.

    The pool is :func:`symdecomp.parallel.ordered_map` (``executor``: ``"local"``, ``"dask"`` or
    ``"dask=ADDRESS"``); the largest valences are handed out first, to keep every worker busy.
    Refused before any work when the memory estimate is beyond the limit (:func:`check_eigendata_cost`).
    """
    ns = list(ns)
    if ns:
        check_eigendata_cost(scheme, max(ns), pool_size(jobs, len(ns)))
    yield from ordered_map(_rounded_one, ns, shared={"scheme": scheme}, jobs=jobs, executor=executor, cost=lambda n: n)
