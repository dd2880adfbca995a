"""Eigenvectors of the 1-ring block of a triangle scheme's patch matrix (Loop), exact or in Arb balls.

The 1-ring block ``S`` of the ``(N + 6)``-point Loop patch
(:mod:`symdecomp.schemes.triangle_patch`) acts on ``(O, a_0, .., a_{N-1})``: the centre row
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
regular block (decided in ``Q(zeta_2N)``, :mod:`symdecomp.algebra.cyclotomic`), as the
Catmull-Clark columns of :mod:`symdecomp.analysis.eigendata` do; the assembly there is shared.
"""

from __future__ import annotations

from fractions import Fraction

import flint

from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, to_acb
from symdecomp.algebra.numbers import to_arb
from symdecomp.algebra.small_eigen import NeedPrecision
from symdecomp.errors import NotDiagonalizableError

__all__ = ["triangle_ring_weights", "triangle_ring_columns"]

arb = flint.arb


def triangle_ring_weights(p) -> dict:
    """``{"oo", "oa", "eo", "ee"}`` of the 1-ring block, checked exactly (circulant, mirror symmetric, rotation invariant)."""
    n = p.n
    oo = p.sparse[0].get(0, Fraction(0))
    oa = p.sparse[0].get(1, Fraction(0))
    if any(p.sparse[0].get(1 + i, Fraction(0)) != oa for i in range(n)) or any(c > n for c in p.sparse[0]):
        raise NotDiagonalizableError(f"the centre rule at valence {n} is not rotation invariant")

    def split(i):
        row = p.sparse[1 + i]
        if any(c > n for c, w in row.items() if w != 0):
            raise NotDiagonalizableError(f"the 1-ring of valence {n} depends on points beyond it: not block triangular")
        return row.get(0, Fraction(0)), {k: row.get(1 + (i + k) % n, Fraction(0)) for k in range(n)}

    eo, ee = split(0)
    if any(split(i) != (eo, ee) for i in range(1, n)):
        raise NotDiagonalizableError(f"the 1-ring matrix at valence {n} is not circulant")
    if any(ee[k] != ee[-k % n] for k in range(n)):
        raise NotDiagonalizableError(f"the edge rule at valence {n} is not mirror symmetric (the Fourier blocks are not real)")
    return dict(oo=oo, oa=oa, eo=eo, ee={k: x for k, x in ee.items() if x != 0})


class _TriColumn:
    """One eigenvector of ``S`` (the interface :mod:`symdecomp.analysis.eigendata` assembles)."""

    __slots__ = ("value", "right", "left", "exact_value", "exact_check")

    def __init__(self, value, right, left, exact_check):
        self.value, self.right, self.left, self.exact_value, self.exact_check = value, right, left, None, exact_check


def _ball(x, prec: int) -> arb:
    return to_acb(x, prec).real if isinstance(x, Cyclotomic) else to_arb(x)


def _pick(pairs: list[list], zero) -> list:
    """The candidate vector with the larger entries (a ball vector must not be all 0)."""
    if zero is not None:  # exact: the first nonzero candidate
        return next((v for v in pairs if any(x != zero for x in v)), None)
    best = max(pairs, key=lambda v: sum(abs(float(x.mid())) for x in v))
    if all(x.contains(0) for x in best):
        raise NeedPrecision
    return best


def _frequency_zero(w: dict, n: int, prec: int) -> list[_TriColumn]:
    b00, b01, b10, b11 = w["oo"], n * w["oa"], w["eo"], sum(w["ee"].values(), Fraction(0))
    a00, a01, a10, a11 = (_ball(x, prec) for x in (b00, b01, b10, b11))
    t, d = a00 + a11, a00 * a11 - a01 * a10
    disc = t * t - 4 * d
    if disc < 0:
        raise NotDiagonalizableError(f"valence {n}, frequency 0: complex eigenvalues")
    if not disc > 0:
        raise NeedPrecision
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
    for lam in ((t + disc.sqrt()) / 2, (t - disc.sqrt()) / 2):
        z = _pick([[a01, lam - a00], [lam - a11, a10]], None)
        y = _pick([[a10, lam - a00], [lam - a11, a01]], None)
        dot = y[0] * z[0] + y[1] * z[1]
        if dot.contains(0):
            raise NeedPrecision
        right = [z[0]] + [z[1]] * n
        left = [y[0] / dot] + [y[1] / (n * dot)] * n
        cols.append(_TriColumn(lam, right, left, check))
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

    ``table[m] = cos(pi m/(2n))`` (:func:`~symdecomp.analysis.quad_eigendata.trig_table`).
    """
    n = p.n
    w = triangle_ring_weights(p)
    cols = _frequency_zero(w, n, prec)
    for j in range(1, (n + 1) // 2):
        lam = sum((to_arb(x) * table[(4 * j * k) % (4 * n)] for k, x in w["ee"].items()), arb(0))
        check = _frequency_check(w, n, j)
        for shift in (0, -n):  # cos, then sin (= cos shifted by a quarter turn)
            pattern = [table[(4 * j * k + shift) % (4 * n)] for k in range(n)]
            cols.append(_TriColumn(lam, [arb(0)] + pattern, [arb(0)] + [x * 2 / n for x in pattern], check))
    if n % 2 == 0:
        lam = sum((x * (-1) ** k for k, x in w["ee"].items()), Fraction(0))

        def check(nu, g, lam=lam):
            return None if nu != lam else sum((x * (-1) ** (c - 1) for c, x in g.items() if 1 <= c <= n), Fraction(0)) == 0

        sign = [arb((-1) ** k) for k in range(n)]
        cols.append(_TriColumn(to_arb(lam), [arb(0)] + sign, [arb(0)] + [x / n for x in sign], check))
    return cols
