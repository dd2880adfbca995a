"""Certified eigenstructure of the patch matrix (Stam's exact-evaluation data): Catmull-Clark and Loop.

Written for the (2N+8)-point Catmull-Clark patch below; Loop's (N+6)-point patch
(:mod:`symdecomp.schemes.triangle_patch`) shares the whole assembly with its own 1-ring columns
(:mod:`symdecomp.analysis.triangle_eigendata`) and a 5 x 5 regular block, and where its matrix
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

from dataclasses import dataclass
from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.algebra.rounding import round_ball
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.algebra.small_eigen import NotDiagonalizableError
from symdecomp.algebra.small_eigen import arb_value as _arb
from symdecomp.algebra.small_eigen import biorthogonal as _biorthogonal
from symdecomp.algebra.small_eigen import fmpq_value as _fq
from symdecomp.algebra.small_eigen import rational_eigen as _rational_eigen
from symdecomp.errors import InternalError
from symdecomp.schemes.patch import PatchMatrices, patch_matrices
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import check_valence

__all__ = [
    "NotDiagonalizableError",  # from symdecomp.algebra.small_eigen
    "PrecisionError",
    "PatchEigenData",
    "RoundedEigenData",
    "patch_eigendata",
    "certified_eigendata",
    "rounded_eigendata",
    "round_ball",
]

arb, acb = flint.arb, flint.acb


class PrecisionError(InternalError):
    """A ball stayed too wide to decide a sign or round correctly, up to the precision cap."""


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
# exact helpers


def _trig_pi(m: int, den: int, fn: str) -> arb:
    """``cos`` or ``sin`` of ``pi m/den``, exact when the value is rational."""
    q = Fraction(m, den) % 2
    if fn == "sin":
        q = (q - Fraction(1, 2)) % 2
    exact = {Fraction(0): 1, Fraction(1): -1, Fraction(1, 2): 0, Fraction(3, 2): 0}
    exact.update({Fraction(1, 3): Fraction(1, 2), Fraction(5, 3): Fraction(1, 2)})
    exact.update({Fraction(2, 3): Fraction(-1, 2), Fraction(4, 3): Fraction(-1, 2)})
    if q in exact:
        return _arb(exact[q])
    return arb.cos_pi_fmpq(_fq(q))


# ---------------------------------------------------------------------------------------------
# the 1-ring matrix as circulant blocks


def _circulant(p: PatchMatrices) -> dict:
    """Circulant weights of the 1-ring block ``S``, checked exactly (circulant, mirror symmetric)."""
    n = p.n

    def split(row, i):
        ee, ef = {}, {}
        for c, w in row.items():
            if c == 0 or w == 0:
                continue
            if c > 2 * n:
                raise NotDiagonalizableError(f"the 1-ring of valence {n} depends on points beyond it: not block triangular")
            target = ee if c % 2 else ef
            target[((c - 1) // 2 - i) % n] = w
        return row.get(0, Fraction(0)), ee, ef

    eo, ee, ef = split(p.sparse[1], 0)
    fo, fe, ff = split(p.sparse[2], 0)
    for i in range(n):
        if split(p.sparse[1 + 2 * i], i) != (eo, ee, ef) or split(p.sparse[2 + 2 * i], i) != (fo, fe, ff):
            raise NotDiagonalizableError(f"the 1-ring matrix at valence {n} is not block circulant")
    oo, oe, of = split(p.sparse[0], 0)
    if any(oe.get(k, 0) != oe.get(0, 0) for k in range(n)) or any(of.get(k, 0) != of.get(0, 0) for k in range(n)):
        raise NotDiagonalizableError(f"the centre rule at valence {n} is not rotation invariant")
    mirror = all(
        ee.get(k, 0) == ee.get(-k % n, 0)
        and ef.get(k, 0) == ef.get((-1 - k) % n, 0)
        and fe.get(k, 0) == fe.get((1 - k) % n, 0)
        and ff.get(k, 0) == ff.get(-k % n, 0)
        for k in range(n)
    )
    if not mirror:
        raise NotDiagonalizableError(f"the 1-ring rules at valence {n} are not mirror symmetric (the Fourier blocks are not real)")
    return dict(oo=oo, oe=oe.get(0, Fraction(0)), of=of.get(0, Fraction(0)), eo=eo, ee=ee, ef=ef, fo=fo, fe=fe, ff=ff)


def _block_entries(w: dict, n: int, j: int, cos, conv=lambda x: x):
    """``(b_ee, b_ef, b_fe, b_ff)`` of frequency ``j`` with ``cos(m)`` = cos(pi m/n) in some arithmetic."""
    b_ee = sum((conv(x) * cos(2 * j * k) for k, x in w["ee"].items()), 0)
    b_ef = sum((conv(x) * cos(j * (2 * k + 1)) for k, x in w["ef"].items()), 0)
    b_fe = sum((conv(x) * cos(j * (2 * k - 1)) for k, x in w["fe"].items()), 0)
    b_ff = sum((conv(x) * cos(2 * j * k) for k, x in w["ff"].items()), 0)
    return b_ee, b_ef, b_fe, b_ff


def _choose(a: list, b: list) -> tuple[int, list]:
    pick = 0 if sum(abs(float(x.mid())) for x in a) >= sum(abs(float(x.mid())) for x in b) else 1
    v = (a, b)[pick]
    if all(x.contains(0) for x in v):
        raise _NeedPrecision
    return pick, v


class _Column:
    """One eigenvector of ``S``: value, its entries in ``V0``, its row of ``V0^-1``, exact data."""

    __slots__ = ("value", "right", "left", "exact_value", "exact_check")

    def __init__(self, value, right, left, exact_value=None, exact_check=None):
        self.value, self.right, self.left = value, right, left
        self.exact_value, self.exact_check = exact_value, exact_check


def _trig_table(n: int) -> list:
    """``cos(pi m/(2n))`` for ``m = 0..4n-1``: cos(pi m/n) is entry ``2m``, sin(pi m/n) entry ``2m - n``."""
    return [_trig_pi(m, 2 * n, "cos") for m in range(4 * n)]


def _pattern(table: list, n: int, j: int, fn: str, ce, cf) -> list:
    """``[0, ce T(2jk), cf T(j(2k+1)), ...]``: a Fourier pattern on ``(O, e_0, f_0, ...)``."""
    shift = 0 if fn == "cos" else -n
    out = [arb(0)]
    for k in range(n):
        out.append(ce * table[(4 * j * k + shift) % (4 * n)])
        out.append(cf * table[(2 * j * (2 * k + 1) + shift) % (4 * n)])
    return out


def _frequency_columns(w: dict, n: int, j: int, table: list) -> list[_Column]:
    """The four eigenvectors of ``S`` at frequencies ``j`` and ``n - j`` (``0 < j < n/2``)."""
    b_ee, b_ef, b_fe, b_ff = _block_entries(w, n, j, lambda m: table[(2 * m) % (4 * n)], _arb)
    t, d = b_ee + b_ff, b_ee * b_ff - b_ef * b_fe
    disc = t * t - 4 * d
    if disc < 0:
        raise NotDiagonalizableError(f"valence {n}, frequency {j}: complex eigenvalues (the data file holds real ones)")
    if not disc > 0:
        raise _NeedPrecision
    cols = []
    for lam in ((t + disc.sqrt()) / 2, (t - disc.sqrt()) / 2):
        pick, z = _choose([b_ef, lam - b_ee], [lam - b_ff, b_fe])
        _, y = _choose([b_fe, lam - b_ee], [lam - b_ff, b_ef])
        (y,) = _biorthogonal([z], [y], arb(n))
        check = _exact_frequency_check(w, n, j, pick)
        for fn in ("cos", "sin"):
            right = _pattern(table, n, j, fn, z[0], z[1])
            left = _pattern(table, n, j, fn, 2 * y[0], 2 * y[1])
            cols.append(_Column(lam, right, left, None, check))
    return cols


def _exact_frequency_check(w: dict, n: int, j: int, pick: int):
    """Exact test, in Q(zeta_2n), of a coincidence ``lam = nu`` and of ``g . u0 = 0`` for both patterns."""

    def check(nu: Fraction, g: dict):
        field = CyclotomicField(2 * n)
        zeta = lambda m: field.zeta(m % (2 * n))  # noqa: E731
        b_ee, b_ef, b_fe, b_ff = _block_entries(w, n, j, lambda m: (zeta(m) + zeta(-m)) / 2)
        if nu * nu - (b_ee + b_ff) * nu + (b_ee * b_ff - b_ef * b_fe) != 0:
            return None
        ze, zf = (b_ef, nu - b_ee) if pick == 0 else (nu - b_ff, b_fe)
        total = field(0)
        for c, x in g.items():
            if 1 <= c <= 2 * n:
                k = (c - 1) // 2
                total = total + x * (ze * zeta(2 * j * k) if c % 2 else zf * zeta(j * (2 * k + 1)))
        return total == 0

    return check


def _rational_columns(w: dict, n: int, j: int) -> list[_Column]:
    """Eigenvectors of ``S`` at frequency 0 (3 x 3 block) or ``n/2`` (2 x 2 block in the (-1)^k basis)."""
    if j == 0:
        block = [[w["oo"], n * w["oe"], n * w["of"]], [w["eo"], sum(w["ee"].values()), sum(w["ef"].values())],
                 [w["fo"], sum(w["fe"].values()), sum(w["ff"].values())]]
    else:
        alt = lambda d: sum((x * (-1) ** k for k, x in d.items()), Fraction(0))  # noqa: E731
        block = [[alt(w["ee"]), alt(w["ef"])], [alt(w["fe"]), alt(w["ff"])]]
    cols = []
    for lam, right, left in _rational_eigen(block):
        left = _biorthogonal(right, left, 1 if j == 0 else n)
        for z, y in zip(right, left):
            if j == 0:
                full_r = [z[0]] + [z[1], z[2]] * n
                full_l = [y[0]] + [y[1] / n, y[2] / n] * n
            else:
                full_r = [0] + [(-1) ** k * v for k in range(n) for v in (z[0], z[1])]
                full_l = [0] + [(-1) ** k * v for k in range(n) for v in (y[0], y[1])]
            exact = lam if isinstance(lam, Fraction) else None
            check = None
            if exact is not None:
                check = lambda nu, g, lam=lam, r=full_r: None if nu != lam else sum(x * r[c] for c, x in g.items() if c < len(r)) == 0  # noqa: E731
            cols.append(_Column(_arb(lam), [_arb(x) for x in full_r], [_arb(x) for x in full_l], exact, check))
    return cols


# ---------------------------------------------------------------------------------------------
# assembly


def _fraction(x: flint.fmpq) -> Fraction:
    return Fraction(int(x.p), int(x.q))


def _regular_part(p: PatchMatrices):
    """Exact eigenvalues ``nu``, eigenvectors ``W`` and ``W^-1`` of the regular block ``S12`` (7 x 7 quads, 5 x 5 triangles)."""
    k0, r = p.ring_size, p.size - p.ring_size
    s12 = [[p.sparse[k0 + i].get(k0 + j, Fraction(0)) for j in range(r)] for i in range(r)]
    nus, columns = [], []
    for lam, right, _ in _rational_eigen(s12):
        if not isinstance(lam, Fraction):
            raise NotDiagonalizableError(f"the regular block has an irrational eigenvalue {lam}: not supported")
        for z in right:
            nus.append(lam)
            columns.append(z)
    w = flint.fmpq_mat(r, r, [_fq(columns[c][i]) for i in range(r) for c in range(r)])
    return nus, w, w.inv()


def patch_eigendata(scheme: Scheme, n: int, prec: int = 128) -> PatchEigenData:
    """The eigenstructure of the patch matrix at valence ``n`` in Arb balls at ``prec`` bits.

    Raises :class:`NotDiagonalizableError` when there is no eigenvector basis, and
    :class:`PrecisionError` when ``prec`` is too low to decide a sign on the way.
    """
    n = check_valence(n)
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
    values = tuple(col.value for col in cols) + tuple(_arb(nu) for nu in nus)
    # rows of the refined points beyond the K control points: sparse rows times V
    beyond = [_sparse_times(p.sparse[i], vec_rows, size) for i in range(size, len(p.sparse))]
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
    """The eigenvectors of the 1-ring block, frequency by frequency (quads here, triangles in
    :mod:`symdecomp.analysis.triangle_eigendata`)."""
    n = p.n
    table = _trig_table(n)
    if p.mesh == "triangle":
        from symdecomp.analysis.triangle_eigendata import triangle_ring_columns

        return triangle_ring_columns(p, table, prec)
    w = _circulant(p)
    cols = _rational_columns(w, n, 0)
    for j in range(1, (n + 1) // 2):
        cols += _frequency_columns(w, n, j, table)
    if n % 2 == 0:
        cols += _rational_columns(w, n, n // 2)
    return cols


def _sparse_times(row: dict, rows: list, size: int) -> list:
    out = [arb(0)] * size
    for c, x in row.items():
        w = _arb(x)
        out = [o + w * y for o, y in zip(out, rows[c])]
    return out


def _outer_coefficients(p: PatchMatrices, cols, nus, winv, right_rows) -> tuple[list, list]:
    """``(D, jordan)``: ``D[r][c] = (W^-1 S11 u_c)_r / (lam_c - nu_r)``; where ``lam_c = nu_r`` (decided
    exactly) ``D[r][c] = 0``, and a nonzero ``gamma = (W^-1 S11 u_c)_r`` is a Jordan pair ``(k0 + r, c, gamma)``
    (triangle patches; a quad patch that is not diagonalizable is refused)."""
    n, k0, r = p.n, p.ring_size, p.size - p.ring_size
    s11 = flint.fmpq_mat(r, k0)
    for i in range(r):
        for c, x in p.sparse[k0 + i].items():
            if c < k0:
                s11[i, c] = _fq(x)
    g_exact = winv * s11
    g_rows = [{c: _fraction(g_exact[i, c]) for c in range(k0) if g_exact[i, c] != 0} for i in range(r)]
    dmat, jordan = [], []
    for r, nu in enumerate(nus):
        coeff = _sparse_times(g_rows[r], right_rows, k0)
        row = []
        for c, col in enumerate(cols):
            gap = col.value - _arb(nu)
            if not gap.contains(0):
                row.append(coeff[c] / gap)
                continue
            verdict = col.exact_check(nu, g_rows[r]) if col.exact_check else None
            if verdict is None:
                raise _NeedPrecision
            if not verdict and p.mesh == "triangle":
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



def _round_all(data: PatchEigenData) -> RoundedEigenData | None:
    size = data.size
    with flint.ctx.workprec(128):  # ``+x`` rounds a ball to 128 bits (still containing it): cheaper to inspect
        values = [round_ball(+v) for v in data.values]
        inverse = [round_ball(+x) for x in data.inverse.entries()]
        phi = [round_ball(+x) for t in data.phi for x in t.entries()]
        jordan = tuple((i, c, round_ball(+g)) for i, c, g in data.jordan)
    if None in values or None in inverse or None in phi or any(g is None for _, _, g in jordan):
        return None
    width = data.phi[0].ncols()
    return RoundedEigenData(
        data.n, np.array(values), np.array(inverse).reshape(size, size), np.array(phi).reshape(3, size, width), jordan
    )


def certified_eigendata(scheme: Scheme, n: int, prec: int = 1200, max_prec: int = 1 << 14) -> tuple[PatchEigenData, RoundedEigenData]:
    """The eigen-data at valence ``n`` at the lowest precision (doubling from ``prec``) that rounds it all.

    The default start, 1200 bits, is what the exact zeros need (symmetries make many entries 0,
    and a ball around 0 rounds to 0.0 only inside ``(-2^-1075, 2^-1075)``).

    Every float64 returned is the correctly rounded value of the exact number, whose Arb ball
    is returned too. Raises :class:`PrecisionError` past ``max_prec`` bits.
    """
    while True:
        try:
            data = patch_eigendata(scheme, n, prec)
            rounded = _round_all(data)
        except PrecisionError:
            rounded = None
        if rounded is not None:
            return data, rounded
        if prec >= max_prec:
            raise PrecisionError(f"valence {n}: the eigen-data did not round correctly at {prec} bits")
        # Exact zeros (symmetries) round only once the ball is inside (-2^-1075, 2^-1075).
        prec = max(2 * prec, 1200)


def _rounded_one(args) -> tuple[int, RoundedEigenData]:
    scheme, n = args
    data, rounded = certified_eigendata(scheme, n)
    return data.prec, rounded


def rounded_eigendata(scheme: Scheme, ns, jobs: int = 1):
    """Yield ``(precision, RoundedEigenData)`` for the valences ``ns`` in order, on ``jobs`` processes."""
    tasks = [(scheme, n) for n in ns]
    if jobs <= 1 or len(tasks) < 2:
        yield from map(_rounded_one, tasks)
        return
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=jobs) as pool:
        # largest valences first keeps both processes busy; results come back in order
        futures = {n: pool.submit(_rounded_one, t) for t, n in sorted(zip(tasks, ns), key=lambda tn: -tn[1])}
        for n in ns:
            yield futures[n].result()
