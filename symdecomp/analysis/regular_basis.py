"""The regular patch's basis on each lattice: the bicubic B-spline (quads) and Loop's quartic box spline (triangles).

Each is given with its derivatives in three arithmetics: numpy float64 arrays over many local parameters, numpy object
arrays of mpmath numbers at the current precision, and one point in the arithmetic of its parameters (exact with
Fractions). The bicubic basis is the tensor product of the uniform cubic B-spline ``N_0..N_3``
(:func:`bspline_basis`; ``b_{a + 4 b}(s, t) = N_a(s) N_b(t)``); the box spline's 12 basis functions are
:func:`~symdecomp.schemes.box_spline.regular_patch`'s Bezier nets, differentiated as nets once
(:func:`~symdecomp.algebra.triangle_bezier.bezier_derivative`) and evaluated in Bernstein form (:func:`box_basis`,
:func:`box_exact`). The patch evaluators (:mod:`symdecomp.analysis.evaluation`,
:mod:`symdecomp.analysis.sector_evaluation`) read them.

>>> from fractions import Fraction
>>> sum(bicubic_exact(Fraction(1, 3), Fraction(1, 5), 0, 0)), sum(box_exact(Fraction(1, 3), Fraction(1, 5), 0, 0))
(Fraction(1, 1), Fraction(1, 1))
"""

from __future__ import annotations

from functools import lru_cache

import mpmath
import numpy as np

from symdecomp.algebra.triangle_bezier import bernstein, bezier_derivative
from symdecomp.schemes.box_spline import DEGREE, regular_patch

__all__ = ["bspline_basis", "box_basis", "bicubic_exact", "box_exact"]


def bspline_basis(t, derivative: int = 0):
    """The uniform cubic B-spline basis ``N_0..N_3`` (or a derivative) at ``t``: shape ``(4,) + t.shape``."""
    one = t * 0 + 1
    if derivative == 0:
        return np.array([(one - t) ** 3 / 6, (3 * t**3 - 6 * t**2 + 4 * one) / 6, (-3 * t**3 + 3 * t**2 + 3 * t + one) / 6, t**3 / 6])
    if derivative == 1:
        return np.array([-((one - t) ** 2) / 2, (9 * t**2 - 12 * t) / 6, (-9 * t**2 + 6 * t + 3 * one) / 6, t**2 / 2])
    return np.array([one - t, 3 * t - 2 * one, -3 * t + one, t])


@lru_cache(maxsize=16)
def _derivative_nets(ds: int, dt: int) -> tuple[tuple, ...]:
    """The exact Bezier nets of ``d^ds/ds d^dt/dt b_i`` (degree ``4 - ds - dt``), one per box-spline basis function."""
    rows = []
    for net in regular_patch().coefficients:
        net, degree = list(net), DEGREE
        for direction, times in (("u", ds), ("v", dt)):
            for _ in range(times):
                net, degree = bezier_derivative(net, degree, direction), degree - 1
        rows.append(tuple(net))
    return tuple(rows)


@lru_cache(maxsize=64)
def _derivative_matrix(ds: int, dt: int, kind: str, prec: int):
    """12 x (Bezier count) matrix: row ``i`` is the net of ``d^ds/ds d^dt/dt b_i`` (degree ``4 - ds - dt``)."""
    rows = _derivative_nets(ds, dt)
    if kind == "float":
        return np.array([[x.numerator / x.denominator for x in row] for row in rows])
    with mpmath.workprec(prec):
        return np.array([[mpmath.mpf(x.numerator) / x.denominator for x in row] for row in rows], dtype=object)


def box_basis(s, t, ds: int, dt: int, conv) -> np.ndarray:
    """``(P, 12)``: the derivative ``(ds, dt)`` of the 12 box-spline basis functions at the points ``(s, t)``.

    ``conv`` is ``float`` (numpy float64 arrays) or ``mpmath.mpf`` (object arrays at the current precision).
    """
    kind = "float" if conv is float else "mpf"
    D = _derivative_matrix(ds, dt, kind, mpmath.mp.prec if kind == "mpf" else 0)
    B = np.array(bernstein(DEGREE - ds - dt, s, t), dtype=object if kind == "mpf" else float)
    return (D @ B.reshape(D.shape[1], -1)).T


def bicubic_exact(s, t, ds: int, dt: int) -> list:
    """The 16 bicubic B-spline basis functions (or a derivative) at one point, in the arithmetic of ``s`` and ``t``
    (index ``a + 4 b``: ``N_a(s) N_b(t)``)."""
    bs, bt = bspline_basis(s, ds), bspline_basis(t, dt)
    return [bs[a] * bt[b] for b in range(4) for a in range(4)]


def box_exact(s, t, ds: int, dt: int) -> list:
    """The 12 quartic box-spline basis functions (or a derivative) at one point, in the arithmetic of ``s`` and ``t``
    (exact with Fractions)."""
    b = bernstein(DEGREE - ds - dt, s, t)
    return [sum((c * x for c, x in zip(net, b)), 0 * s) for net in _derivative_nets(ds, dt)]
