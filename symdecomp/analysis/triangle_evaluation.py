"""The triangle (Loop) side of the patch evaluator: sub-patch location, box-spline basis, limit masks.

:class:`~symdecomp.analysis.evaluation.PatchEvaluator` evaluates the Loop patch ``(O, a_0, a_1)``
next to a valence-``N`` vertex (order and sub-patches: :mod:`symdecomp.schemes.triangle_patch`)
for ``u, v >= 0``, ``u + v <= 1`` other than ``(0, 0)``:

* ``n = floor(-log2(u + v)) + 1``, ``(x, y) = 2^n (u, v)`` (so ``1 < x + y <= 2``);
* sub-patch ``k`` and local ``(s, t)`` (:func:`locate_triangle`): ``x >= 1``: ``k = 0``,
  ``(x - 1, y)``; else ``y >= 1``: ``k = 2``, ``(x, y - 1)``; else ``k = 1`` (upside down),
  ``(1 - x, 1 - y)``, and derivatives change sign once per order (``sigma = -1``);
* ``s(u, v) = sum_i lam_i^(n-1) (sum_l Phi_k[i, l] b_l(s, t)) (V^-1 C)_i`` with the 12 quartic
  box-spline basis functions ``b_l`` (:func:`~symdecomp.schemes.box_spline.regular_patch`,
  evaluated in Bernstein-Bezier form; derivatives from the derivative nets, :func:`box_basis`).

At ``(0, 0)`` the limit point and the tangent plane come from the eigen-data itself
(:func:`eigen_masks`): the eigenvalue-1 eigenvector is constant (``Phi_0[0, l]``), so the limit
position mask is ``Phi_0[0, 0]`` times row 0 of ``V^-1``; rows 2 and 3 (frequency 1, the
``cos`` and ``sin`` patterns) are the two tangent masks, turning from ``a_0`` to ``a_1`` like
``(u, v)``, so their images' cross product points along ``du x dv``.
"""

from __future__ import annotations

from functools import lru_cache

import mpmath
import numpy as np

from symdecomp.algebra.numbers import to_mpf
from symdecomp.algebra.triangle_bezier import bernstein, bezier_derivative
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.box_spline import DEGREE, regular_patch
from symdecomp.schemes.scheme import Scheme

__all__ = ["locate_triangle", "box_basis", "eigen_masks", "check_regular_patch"]


def locate_triangle(x, y, xp=None):
    """``(k, s, t, sigma)`` for ``1 < x + y <= 2`` (scalars, or numpy arrays with ``xp=numpy``)."""
    if xp is not None:
        k = xp.where(x >= 1, 0, xp.where(y >= 1, 2, 1))
        s = xp.where(k == 0, x - 1, xp.where(k == 2, x, 1 - x))
        t = xp.where(k == 0, y, xp.where(k == 2, y - 1, 1 - y))
        return k, s, t, xp.where(k == 1, -1.0, 1.0)
    if x >= 1:
        return 0, x - 1, y, 1
    if y >= 1:
        return 2, x, y - 1, 1
    return 1, 1 - x, 1 - y, -1


@lru_cache(maxsize=64)
def _derivative_matrix(ds: int, dt: int, kind: str, prec: int):
    """12 x (Bezier count) matrix: row ``i`` is the net of ``d^ds/ds d^dt/dt b_i`` (degree ``4 - ds - dt``)."""
    rows = []
    for net in regular_patch().coefficients:
        net, degree = list(net), DEGREE
        for direction, times in (("u", ds), ("v", dt)):
            for _ in range(times):
                net, degree = bezier_derivative(net, degree, direction), degree - 1
        rows.append(net)
    if kind == "float":
        return np.array([[x.numerator / x.denominator for x in row] for row in rows])
    with mpmath.workprec(prec):
        return np.array([[to_mpf(x) for x in row] for row in rows], dtype=object)


def box_basis(s, t, ds: int, dt: int, conv) -> np.ndarray:
    """``(P, 12)``: the derivative ``(ds, dt)`` of the 12 box-spline basis functions at the points ``(s, t)``.

    ``conv`` is ``float`` (numpy float64 arrays) or ``mpmath.mpf`` (object arrays at the current precision).
    """
    kind = "float" if conv is float else "mpf"
    D = _derivative_matrix(ds, dt, kind, mpmath.mp.prec if kind == "mpf" else 0)
    B = np.array(bernstein(DEGREE - ds - dt, s, t), dtype=object if kind == "mpf" else float)
    return (D @ B.reshape(D.shape[1], -1)).T


def eigen_masks(values, inverse, phi) -> tuple[np.ndarray, np.ndarray]:
    """``(position mask, (cos, sin) tangent masks)`` of the centre from Loop eigen-data (any number type)."""
    if not (abs(values[0] - 1) < 1e-9 and abs(values[2] - values[3]) < 1e-9 * (1 + abs(values[2]))):
        raise InvalidSchemeError("the eigen-data is not in the triangle patch's order (1 first, then the frequency-1 pair)")
    return phi[0][0, 0] * inverse[0], np.array([inverse[2], inverse[3]])


def check_regular_patch(scheme: Scheme) -> None:
    """Raise unless the scheme's regular patch is the one the evaluator uses (Loop's quartic box spline)."""
    if regular_patch(scheme).coefficients != regular_patch().coefficients:
        raise NotApplicableError(f"scheme {scheme.name!r}: its regular patch is not Loop's box spline; the evaluator does not support it")
