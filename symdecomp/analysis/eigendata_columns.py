"""The eigenvectors of the patch matrix's 1-ring block, frequency by frequency (exact or Arb), on each lattice.

:mod:`symdecomp.analysis.eigendata` assembles the patch's eigen-data from these columns; which
columns, and what it may do with them, is declared per kind of regular patch in :data:`RING_EIGEN`.

**Quads** (Catmull-Clark). The 1-ring block ``S`` acts on ``(O, e_0, f_0, .., e_{N-1}, f_{N-1})``;
in the real Fourier basis it splits into a 3 x 3 rational block (``j = 0``), real 2 x 2 blocks
for ``0 < j < N/2`` and a rational 2 x 2 block at ``j = N/2`` (even ``N``).

**Triangles** (Loop). The 1-ring block ``S`` of the ``(N + 6)``-point patch
(:mod:`symdecomp.schemes.patch`) acts on ``(O, a_0, .., a_{N-1})``: the centre row
``(w_O, w_a, .., w_a)`` (exact in ``Q(zeta_2N)``: Loop's weights hold ``cos(2 pi/N)``), and the
circulant rows of the edge points ``a_i = eo O + sum_k ee[k] a_{i+k}`` (rational). In the real
Fourier basis of the ``a``'s it splits into

* frequency 0: the 2 x 2 block ``[[w_O, N w_a], [eo, sum_k ee[k]]]`` on ``(O, sum a)``, entries in
  ``Q(zeta_2N)``: eigenvalues by the quadratic formula in Arb (1 and, for Loop,
  ``(3/8 + cos(2 pi/N)/4)^2``), eigenvectors from the block's rows;
* frequency ``0 < j < N/2``: ``lam_j = sum_k ee[k] cos(2 pi j k/N)`` (real because the rule is
  mirror symmetric, ``ee[k] = ee[-k]``), twice, with the patterns ``cos(2 pi j k/N)`` and
  ``sin(2 pi j k/N)`` on ``a_k`` (0 on ``O``); left eigenvectors ``2/N`` times the same patterns;
* frequency ``N/2`` (even ``N``): ``sum_k ee[k] (-1)^k`` with the pattern ``(-1)^k`` (left: ``/N``).

Every column carries an exact test for a coincidence with a rational eigenvalue ``nu`` of the
regular block (decided in ``Q(zeta_2N)``, :mod:`symdecomp.algebra.cyclotomic`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, to_acb
from symdecomp.algebra.numbers import to_arb
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.algebra.small_eigen import biorthogonal as _biorthogonal
from symdecomp.algebra.small_eigen import rational_eigen as _rational_eigen
from symdecomp.analysis.fourier_patterns import PatternForm, _pattern, _steps
from symdecomp.errors import NotDiagonalizableError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.patch import PatchMatrices

__all__ = [
    "RingEigen", "RING_EIGEN", "quad_ring_columns", "triangle_ring_columns", "triangle_ring_weights",
    "column_group", "triangle_column_group", "circulant_weights",
]

arb = flint.arb


# ---------------------------------------------------------------------------------------------
# exact helpers



# ---------------------------------------------------------------------------------------------
# the 1-ring matrix as circulant blocks


_LAST_WEIGHTS: dict = {}


def circulant_weights(p: PatchMatrices) -> dict:
    """Circulant weights of the 1-ring block ``S``, checked exactly (circulant, mirror symmetric); the last
    patch's are kept (a valence reads them at two precisions). The dict is shared: read it, never change it."""
    if _LAST_WEIGHTS.get("patch") is not p:
        _LAST_WEIGHTS.clear()
        _LAST_WEIGHTS["weights"] = _circulant_weights(p)
        _LAST_WEIGHTS["patch"] = p
    return _LAST_WEIGHTS["weights"]


def _circulant_weights(p: PatchMatrices) -> dict:
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
    """One eigenvector of ``S``: value, its entries in ``V0`` (``right``), its row of ``V0^-1`` (``left``), exact data.

    ``right`` and ``left`` are lists of balls, or :class:`~symdecomp.analysis.fourier_patterns.PatternForm` s (then ``right_form`` and
    ``left_form``), made into lists when first read whole; :meth:`right_at` and :meth:`left_at` read one entry."""

    __slots__ = ("value", "_right", "_left", "right_form", "left_form", "exact_value", "exact_check")

    def __init__(self, value, right, left, exact_value=None, exact_check=None):
        self.value, self.exact_value, self.exact_check = value, exact_value, exact_check
        self.right_form = right if isinstance(right, PatternForm) else None
        self.left_form = left if isinstance(left, PatternForm) else None
        self._right = None if self.right_form else right
        self._left = None if self.left_form else left

    @property
    def right(self) -> list:
        if self._right is None:
            self._right = self.right_form.entries()
        return self._right

    @property
    def left(self) -> list:
        if self._left is None:
            self._left = self.left_form.entries()
        return self._left

    def right_at(self, i: int):
        return self._right[i] if self._right is not None else self.right_form.at(i)

    def left_at(self, i: int):
        return self._left[i] if self._left is not None else self.left_form.at(i)



def _frequency_columns(w: dict, n: int, j: int, table: list, balls: dict | None = None) -> list[_Column]:
    """The four eigenvectors of ``S`` at frequencies ``j`` and ``n - j`` (``0 < j < n/2``); ``balls``: ``w``'s
    weights as balls (:func:`_weight_balls`, made once per valence), else converted here."""
    balls = balls or _weight_balls(w)
    b_ee, b_ef, b_fe, b_ff = _block_entries(balls, n, j, lambda m: table[(2 * m) % (4 * n)])
    roots = _real_eigenvalues(b_ee, b_ef, b_fe, b_ff, f"valence {n}, frequency {j}: complex eigenvalues (the data file holds real ones)")
    cols = []
    for lam in roots:
        pick, z = _choose([b_ef, lam - b_ee], [lam - b_ff, b_fe])
        _, y = _choose([b_fe, lam - b_ee], [lam - b_ff, b_ef])
        (y,) = _biorthogonal([z], [y], arb(n))
        check = _exact_frequency_check(w, n, j, pick)
        for fn in ("cos", "sin"):
            right = _pattern(table, n, j, fn, z[0], z[1])
            left = _pattern(table, n, j, fn, 2 * y[0], 2 * y[1])
            cols.append(_Column(lam, right, left, None, check))
    return cols


def _weight_balls(w: dict) -> dict:
    """The circulant weights that :func:`_block_entries` reads, as balls."""
    return {key: {k: to_arb(x) for k, x in w[key].items()} for key in ("ee", "ef", "fe", "ff")}


def _real_eigenvalues(a00, a01, a10, a11, complex_message: str) -> tuple:
    """The eigenvalues of a 2 x 2 block of balls, larger first, once they are certainly real and distinct."""
    t, d = a00 + a11, a00 * a11 - a01 * a10
    disc = t * t - 4 * d
    if disc < 0:
        raise NotDiagonalizableError(complex_message)
    if not disc > 0:
        raise _NeedPrecision
    return (t + disc.sqrt()) / 2, (t - disc.sqrt()) / 2


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


_EXACT_PAIRS: dict = {}


def _exact_pairs(block: list[list], scale) -> list[tuple]:
    """``(lam, z, y)``: the exact eigenvalues of a rational block with right and biorthogonal left eigenvectors,
    kept for the last few blocks (a valence reads its columns at two precisions). An irrational eigenvalue comes
    as a ball at the current precision, so the precision is part of the key: a ball kept from 256 bits made
    the 1200-bit columns 256-bit ones, and every zero they were to prove fell to an ``O(N^3)`` exact solve."""
    key = (tuple(map(tuple, block)), scale, flint.ctx.prec)
    if key not in _EXACT_PAIRS:
        if len(_EXACT_PAIRS) > 8:
            _EXACT_PAIRS.clear()
        pairs = []
        for lam, right, left in _rational_eigen(block):
            pairs += [(lam, z, y) for z, y in zip(right, _biorthogonal(right, left, scale))]
        _EXACT_PAIRS[key] = pairs
    return _EXACT_PAIRS[key]


def _rational_columns(w: dict, n: int, j: int) -> list[_Column]:
    """Eigenvectors of ``S`` at frequency 0 (3 x 3 block) or ``n/2`` (2 x 2 block in the (-1)^k basis)."""
    if j == 0:
        block = [[w["oo"], n * w["oe"], n * w["of"]], [w["eo"], sum(w["ee"].values()), sum(w["ef"].values())],
                 [w["fo"], sum(w["fe"].values()), sum(w["ff"].values())]]
    else:
        alt = lambda d: sum((x * (-1) ** k for k, x in d.items()), Fraction(0))  # noqa: E731
        block = [[alt(w["ee"]), alt(w["ef"])], [alt(w["fe"]), alt(w["ff"])]]
    cols = []
    for lam, z, y in _exact_pairs(block, 1 if j == 0 else n):
        if j == 0:  # (O; e_k, f_k) = (z0; z1, z2) for every k
            head_r, period_r, head_l, period_l, reps = z[0], [z[1], z[2]], y[0], [y[1] / n, y[2] / n], n
        else:  # (-1)^k (z0, z1) on (e_k, f_k): a period of two steps (n is even)
            head_r, period_r, head_l, period_l, reps = 0, [z[0], z[1], -z[0], -z[1]], 0, [y[0], y[1], -y[0], -y[1]], n // 2
        full_r = [head_r] + period_r * reps
        exact = lam if isinstance(lam, Fraction) else None
        check = None
        if exact is not None:
            check = lambda nu, g, lam=lam, r=full_r: None if nu != lam else sum(x * r[c] for c, x in g.items() if c < len(r)) == 0  # noqa: E731
        right_balls = [to_arb(head_r)] + [to_arb(x) for x in period_r] * reps  # the period's balls, shared
        left_balls = [to_arb(head_l)] + [to_arb(x) for x in period_l] * reps
        cols.append(_Column(to_arb(lam), right_balls, left_balls, exact, check))
    return cols


def quad_ring_columns(p: PatchMatrices, table) -> list:
    """The ``2n + 1`` eigenvectors of the 1-ring block: ``j = 0``, then 4 per ``0 < j < n/2``, then ``n/2``."""
    n, w = p.n, circulant_weights(p)
    cols, balls = _rational_columns(w, n, 0), _weight_balls(w)
    for j in range(1, (n + 1) // 2):
        cols += _frequency_columns(w, n, j, table, balls)
    if n % 2 == 0:
        cols += _rational_columns(w, n, n // 2)
    return cols


def column_group(p: PatchMatrices, w: dict, table: list, i: int):
    """``(columns, offset)``: the frequency group of 1-ring column ``i``, recomputed at the current precision.

    ``w``: :func:`circulant_weights`; ``table``: :func:`~symdecomp.analysis.fourier_patterns.trig_table` or a
    :class:`~symdecomp.analysis.fourier_patterns.LazyTable`."""
    n, J = p.n, (p.n + 1) // 2 - 1
    if i < 3:
        return _rational_columns(w, n, 0), i
    if i - 3 < 4 * J:
        return _frequency_columns(w, n, 1 + (i - 3) // 4, table), (i - 3) % 4
    return _rational_columns(w, n, n // 2), i - 3 - 4 * J


# ---------------------------------------------------------------------------------------------
# triangles


def triangle_ring_weights(p) -> dict:
    """``{"oo", "oa", "eo", "ee"}`` of the 1-ring block, checked exactly (circulant, mirror symmetric, rotation invariant)."""
    n = p.n
    oo = p.sparse[0].get(0, Fraction(0))
    oa = p.sparse[0].get(1, Fraction(0))
    if any(p.sparse[0].get(1 + i, Fraction(0)) != oa for i in range(n)) or any(c > n for c in p.sparse[0]):
        raise NotDiagonalizableError(f"the centre rule at valence {n} is not rotation invariant")

    def split(i):  # (weight on O, {offset k: nonzero weight on a_{i+k}}): O(nonzeros) per row
        row = p.sparse[1 + i]
        if any(c > n for c, w in row.items() if w != 0):
            raise NotDiagonalizableError(f"the 1-ring of valence {n} depends on points beyond it: not block triangular")
        return row.get(0, Fraction(0)), {(c - 1 - i) % n: w for c, w in row.items() if c >= 1 and w != 0}

    eo, ee = split(0)
    if any(split(i) != (eo, ee) for i in range(1, n)):
        raise NotDiagonalizableError(f"the 1-ring matrix at valence {n} is not circulant")
    if any(ee.get(-k % n, 0) != x for k, x in ee.items()):
        raise NotDiagonalizableError(f"the edge rule at valence {n} is not mirror symmetric (the Fourier blocks are not real)")
    return dict(oo=oo, oa=oa, eo=eo, ee=ee)


def _ball(x, prec: int) -> arb:
    return to_acb(x, prec).real if isinstance(x, Cyclotomic) else to_arb(x)


def _pick(pairs: list[list], zero) -> list:
    """The candidate vector with the larger entries (a ball vector must not be all 0)."""
    if zero is not None:  # exact: the first nonzero candidate
        return next((v for v in pairs if any(x != zero for x in v)), None)
    best = max(pairs, key=lambda v: sum(abs(float(x.mid())) for x in v))
    if all(x.contains(0) for x in best):
        raise _NeedPrecision
    return best


def _frequency_zero(w: dict, n: int, prec: int) -> list[_Column]:
    b00, b01, b10, b11 = w["oo"], n * w["oa"], w["eo"], sum(w["ee"].values(), Fraction(0))
    a00, a01, a10, a11 = (_ball(x, prec) for x in (b00, b01, b10, b11))
    roots = _real_eigenvalues(a00, a01, a10, a11, f"valence {n}, frequency 0: complex eigenvalues")
    field = CyclotomicField(2 * n)

    def check(nu: Fraction, g: dict):
        e00, e01, e10, e11 = (field(x) if not isinstance(x, Cyclotomic) else x for x in (b00, b01, b10, b11))
        if nu * nu - (e00 + e11) * nu + (e00 * e11 - e01 * e10) != 0:
            return None
        z = _pick([[e01, nu - e00], [nu - e11, e10]], field(0))
        if z is None:  # the block is nu times the identity: every vector is an eigenvector
            return all(x == 0 for x in g.values())
        return g.get(0, 0) * z[0] + sum((x * z[1] for c, x in g.items() if 1 <= c <= n), field(0)) == 0

    cols = []
    for lam in roots:
        z = _pick([[a01, lam - a00], [lam - a11, a10]], None)
        y = _pick([[a10, lam - a00], [lam - a11, a01]], None)
        dot = y[0] * z[0] + y[1] * z[1]
        if dot.contains(0):
            raise _NeedPrecision
        right = [z[0]] + [z[1]] * n
        left = [y[0] / dot] + [y[1] / (n * dot)] * n
        cols.append(_Column(lam, right, left, None, check))
    return cols


def _frequency_check(w: dict, n: int, j: int):
    """Exact test, in ``Q(zeta_2n)``, of ``lam_j = nu`` and of ``g . u = 0`` for the cos and sin patterns together."""

    def check(nu: Fraction, g: dict):
        field = CyclotomicField(2 * n)
        zeta = lambda m: field.zeta(m % (2 * n))  # noqa: E731
        lam = sum(((zeta(2 * j * k) + zeta(-2 * j * k)) * (x / 2) for k, x in w["ee"].items()), field(0))
        if lam != nu:
            return None
        return sum((x * zeta(2 * j * (c - 1)) for c, x in g.items() if 1 <= c <= n), field(0)) == 0

    return check


def triangle_ring_columns(p, table: list, prec: int) -> list:
    """The ``n + 1`` eigenvectors of the 1-ring block: frequency 0, then ``(cos, sin)`` for ``j = 1..``, then ``n/2``.

    ``table[m] = cos(pi m/(2n))`` (:func:`~symdecomp.analysis.fourier_patterns.trig_table`).
    """
    n = p.n
    w = triangle_ring_weights(p)
    cols = _frequency_zero(w, n, prec)
    for j in range(1, (n + 1) // 2):
        cols += _triangle_frequency(w, n, j, table)
    if n % 2 == 0:
        cols += _triangle_alternating(w, n)
    return cols


def triangle_column_group(p, w: dict, table, i: int, prec: int):
    """``(columns, offset)``: the frequency group of 1-ring column ``i`` on triangles, at the current precision
    (``w``: :func:`triangle_ring_weights`; ``table``: :func:`~symdecomp.analysis.fourier_patterns.trig_table` or a
    :class:`~symdecomp.analysis.fourier_patterns.LazyTable`)."""
    n = p.n
    if i < 2:
        return _frequency_zero(w, n, prec), i
    if i - 2 < 2 * ((n + 1) // 2 - 1):
        return _triangle_frequency(w, n, 1 + (i - 2) // 2, table), (i - 2) % 2
    return _triangle_alternating(w, n), 0


def _triangle_frequency(w: dict, n: int, j: int, table) -> list[_Column]:
    """The cos and sin columns of frequency ``0 < j < n/2``."""
    lam = sum((to_arb(x) * table[(4 * j * k) % (4 * n)] for k, x in w["ee"].items()), arb(0))
    check = _frequency_check(w, n, j)
    cols = []
    coef, one, two_n = np.zeros(n + 1, dtype=np.int64), arb(1), arb(2) / n
    for shift in (0, -n):  # cos, then sin (= cos shifted by a quarter turn)
        index = np.concatenate([[-1], (4 * j * np.arange(n) + shift) % (4 * n)])
        wave = (j, shift, _steps(n + 1, 2))
        cols.append(_Column(lam, PatternForm((one,), coef, index, table, wave), PatternForm((two_n,), coef, index, table, wave),
                            None, check))
    return cols


def _triangle_alternating(w: dict, n: int) -> list[_Column]:
    """The column of frequency ``n/2`` (even ``n``): the pattern ``(-1)^k``."""
    lam = sum((x * (-1) ** k for k, x in w["ee"].items()), Fraction(0))

    def check(nu, g, lam=lam):
        return None if nu != lam else sum((x * (-1) ** (c - 1) for c, x in g.items() if 1 <= c <= n), Fraction(0)) == 0

    sign = [arb((-1) ** k) for k in range(n)]
    return [_Column(to_arb(lam), [arb(0)] + sign, [arb(0)] + [x / n for x in sign], None, check)]


# ---------------------------------------------------------------------------------------------
# per lattice


@dataclass(frozen=True)
class RingEigen:
    """The 1-ring block's eigen-data on one lattice."""

    #: ``(patch matrices, trig table, prec) -> columns``: the eigenvectors of the 1-ring block, frequency by frequency.
    columns: Callable
    #: Whether a defective eigenvalue shared with the regular block is kept as a Jordan pair (else refused).
    jordan: bool
    #: Whether sub-patch entries around 0 can be proved 0 column by column (:func:`column_group`).
    sharpen: bool
    #: ``patch matrices -> w``: the 1-ring block's weights, checked (what :attr:`group` reads).
    weights: Callable
    #: ``(patch matrices, w, table, i, prec) -> (columns, offset)``: the frequency group of column ``i`` alone.
    group: Callable


RING_EIGEN = {
    BICUBIC: RingEigen(lambda p, table, prec: quad_ring_columns(p, table), jordan=False, sharpen=True,
                    weights=circulant_weights, group=lambda p, w, table, i, prec: column_group(p, w, table, i)),
    BOX_SPLINE: RingEigen(triangle_ring_columns, jordan=True, sharpen=False, weights=triangle_ring_weights, group=triangle_column_group),
}
