"""The eigenvectors of the Catmull-Clark patch's 1-ring block, frequency by frequency (exact or Arb).

The 1-ring block ``S`` acts on ``(O, e_0, f_0, .., e_{N-1}, f_{N-1})``; in the real Fourier basis
it splits into a 3 x 3 rational block (``j = 0``), real 2 x 2 blocks for ``0 < j < N/2`` and a
rational 2 x 2 block at ``j = N/2`` (even ``N``); see :mod:`symdecomp.analysis.eigendata`, which
assembles the patch's eigen-data from these columns (Loop's counterpart:
:mod:`symdecomp.analysis.triangle_eigendata`).
"""

from __future__ import annotations

from fractions import Fraction

import flint

from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.algebra.numbers import to_arb, to_fmpq
from symdecomp.algebra.small_eigen import NeedPrecision as _NeedPrecision
from symdecomp.algebra.small_eigen import biorthogonal as _biorthogonal
from symdecomp.algebra.small_eigen import rational_eigen as _rational_eigen
from symdecomp.errors import NotDiagonalizableError
from symdecomp.schemes.patch import PatchMatrices

__all__ = ["quad_ring_columns", "column_group", "LazyTable", "trig_table", "circulant_weights"]

arb = flint.arb


# ---------------------------------------------------------------------------------------------
# exact helpers


#: ``q`` (in units of pi, mod 2) -> the exact value of ``cos(pi q)`` where it is rational.
_EXACT_COS = {
    Fraction(0): 1, Fraction(1): -1, Fraction(1, 2): 0, Fraction(3, 2): 0,
    Fraction(1, 3): Fraction(1, 2), Fraction(5, 3): Fraction(1, 2), Fraction(2, 3): Fraction(-1, 2), Fraction(4, 3): Fraction(-1, 2),
}  # fmt: skip


def _trig_pi(m: int, den: int, fn: str) -> arb:
    """``cos`` or ``sin`` of ``pi m/den``, exact when the value is rational."""
    if fn == "sin":
        m, den = 2 * m - den, 2 * den  # sin(pi m/den) = cos(pi (m/den - 1/2))
    q = Fraction(m % (2 * den), den)
    if q in _EXACT_COS:
        return to_arb(_EXACT_COS[q])
    return arb.cos_pi_fmpq(to_fmpq(q))


# ---------------------------------------------------------------------------------------------
# the 1-ring matrix as circulant blocks


def circulant_weights(p: PatchMatrices) -> dict:
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


class LazyTable:
    """``_trig_table(n)`` computed entry by entry on first use (a few columns need few entries)."""

    def __init__(self, n: int):
        self.n, self.cache = n, {}

    def __getitem__(self, m: int):
        if m not in self.cache:
            self.cache[m] = _trig_pi(m, 2 * self.n, "cos")
        return self.cache[m]


def trig_table(n: int) -> list:
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
    b_ee, b_ef, b_fe, b_ff = _block_entries(w, n, j, lambda m: table[(2 * m) % (4 * n)], to_arb)
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
            cols.append(_Column(to_arb(lam), [to_arb(x) for x in full_r], [to_arb(x) for x in full_l], exact, check))
    return cols


def quad_ring_columns(p: PatchMatrices, table) -> list:
    """The ``2n + 1`` eigenvectors of the 1-ring block: ``j = 0``, then 4 per ``0 < j < n/2``, then ``n/2``."""
    n, w = p.n, circulant_weights(p)
    cols = _rational_columns(w, n, 0)
    for j in range(1, (n + 1) // 2):
        cols += _frequency_columns(w, n, j, table)
    if n % 2 == 0:
        cols += _rational_columns(w, n, n // 2)
    return cols


def column_group(p: PatchMatrices, w: dict, table: list, i: int):
    """``(columns, offset)``: the frequency group of 1-ring column ``i``, recomputed at the current precision.

    ``w``: :func:`circulant_weights`; ``table``: :func:`trig_table` or a :class:`LazyTable`."""
    n, J = p.n, (p.n + 1) // 2 - 1
    if i < 3:
        return _rational_columns(w, n, 0), i
    if i - 3 < 4 * J:
        return _frequency_columns(w, n, 1 + (i - 3) // 4, table), (i - 3) % 4
    return _rational_columns(w, n, n // 2), i - 3 - 4 * J
