"""The 1-ring under repeated subdivision steps (Section 5: "Evolution of the eigencomponents").

A 1-ring is stored as one array of shape ``(2n+1, d)`` in the vertex order of the subdivision
matrix, ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` (:func:`symdecomp.schemes.vertex_order`), with ``d``
coordinates per point (``d = 3`` for R^3; complex entries are allowed, e.g. planar rings as
complex numbers). One subdivision step is the exact matrix of the scheme applied to it.

>>> from symdecomp.schemes import catmull_clark
>>> ring = one_ring([0, 0, 1], [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]],
...                 [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0]])
>>> after = subdivide_ring(catmull_clark(), ring, steps=1)[-1]
>>> O, a, b = split_ring(after)
>>> float(O[2]), a[:, 2].tolist(), b[:, 2].tolist()   # heights: 9/16, 3/8 and 1/4 of O's
(0.5625, [0.375, 0.375, 0.375, 0.375], [0.25, 0.25, 0.25, 0.25])
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .errors import InvalidPolygonError, check_valence
from .schemes import Scheme, subdivision_matrix

__all__ = ["one_ring", "split_ring", "subdivide_ring", "subdivision_matrix_numeric", "fourier_coefficients"]


def one_ring(center, a, b) -> np.ndarray:
    """Stack ``O``, the ``a_i`` and the ``b_i`` into the ``(2n+1, d)`` array of a 1-ring."""
    O = np.atleast_1d(np.asarray(center))
    a = np.asarray(a)
    b = np.asarray(b)
    if a.ndim == 1:
        a = a[:, None]
    if b.ndim == 1:
        b = b[:, None]
    if a.shape != b.shape or a.shape[1:] != O.shape:
        raise InvalidPolygonError(
            f"a 1-ring needs as many a's as b's, each with as many coordinates as O: got O {O.shape}, a {a.shape}, b {b.shape}"
        )
    check_valence(len(a))
    ring = np.vstack([O[None, :], a, b])
    if not np.all(np.isfinite(ring)):
        raise InvalidPolygonError("a 1-ring has non-finite coordinates")
    return ring


def split_ring(ring) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(O, a, b)`` of a ``(2n+1, d)`` ring array: the centre, the ``a_i`` and the ``b_i``."""
    ring = np.asarray(ring)
    if ring.ndim == 1:
        ring = ring[:, None]
    if ring.shape[0] % 2 != 1 or ring.shape[0] < 7:
        raise InvalidPolygonError(f"a 1-ring array has 2n+1 >= 7 rows (O, a's, b's), got {ring.shape[0]}")
    n = (ring.shape[0] - 1) // 2
    return ring[0], ring[1 : n + 1], ring[n + 1 :]


@lru_cache(maxsize=64)
def subdivision_matrix_numeric(scheme: Scheme, n: int) -> np.ndarray:
    """The exact subdivision matrix of ``scheme`` at valence ``n``, rounded once to double precision."""
    if scheme.parameters:
        raise ValueError(f"scheme {scheme.name!r} has free parameters {list(map(str, scheme.parameters))}; substitute them first")
    return np.array(subdivision_matrix(scheme, check_valence(n)).evalf(20), dtype=float)


def subdivide_ring(scheme: Scheme, ring, steps: int = 1) -> list[np.ndarray]:
    """The ring and its images after ``1..steps`` subdivision steps (a list of ``steps + 1`` arrays)."""
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
        raise ValueError(f"steps must be a non-negative integer, got {steps!r}")
    ring = np.asarray(ring)
    split_ring(ring)
    n = (ring.shape[0] - 1) // 2
    S = subdivision_matrix_numeric(scheme, n)
    out = [ring]
    for _ in range(steps):
        out.append(S @ out[-1])
    return out


def fourier_coefficients(polygon) -> np.ndarray:
    """The coefficients ``z_k`` of ``P = sum_k z_k v_k`` (Eq. 5) for an ``(m,)`` or ``(m, d)`` polygon.

    Row ``k`` of the result is ``z_k`` (a point of ``C^d``): ``p_i = sum_k z_k omega_m^(k i)``.

    >>> np.round(fourier_coefficients(np.exp(2j * np.pi * np.arange(5) / 5)), 12) + 0
    array([0.+0.j, 1.+0.j, 0.+0.j, 0.+0.j, 0.+0.j])
    """
    P = np.asarray(polygon, dtype=complex)
    return np.fft.fft(P, axis=0) / P.shape[0]

