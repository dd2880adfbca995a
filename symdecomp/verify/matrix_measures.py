"""Measures between the toolkit's exact one-step matrix of a level and OpenSubdiv's (doubles).

The sector comparisons of :mod:`symdecomp.verify.oracle` take them level by level: the largest entry of the
difference, taken exactly at :data:`DIGITS` digits (:func:`difference`); for every eigenvalue of either matrix the
smallest singular value of the other minus it (:func:`spectrum_distance`: the distance to the nearest matrix with that
eigenvalue, robust at Jordan blocks); our exact limit mask, stationary at the last level and pulled back through the
levels before (:func:`limit_masks`); the spans of our left eigenvectors that OpenSubdiv's derivative masks must lie in
(:func:`left_spans`, :func:`tangent_residual`).
"""

from __future__ import annotations

import mpmath
import numpy as np

__all__ = ["DIGITS", "floats", "difference", "fixed_row", "limit_masks", "spectrum_distance", "left_spans", "tangent_residual"]


#: Digits of our exact matrices' values in the comparisons (the difference with a double is then exact to 1e-50).
DIGITS = 50


def floats(m: mpmath.matrix) -> np.ndarray:
    """The matrix rounded to doubles."""
    return np.array(m.tolist(), dtype=float)


def difference(m: mpmath.matrix, doubles: np.ndarray) -> float:
    """``max |m - doubles|`` at :data:`DIGITS` digits (each double taken exactly)."""
    with mpmath.workdps(DIGITS):
        return float(max(abs(m[r, c] - mpmath.mpf(float(doubles[r, c]))) for r in range(m.rows) for c in range(m.cols)))


def fixed_row(m: mpmath.matrix) -> list | None:
    """The left eigenvector of eigenvalue 1 of ``m`` with sum 1 (to :data:`DIGITS` digits); None unless unique."""
    n = m.rows
    with mpmath.workdps(DIGITS):
        system = m.T - mpmath.eye(n)
        system[n - 1, :] = mpmath.ones(1, n)  # the equations are dependent (rows of m sum to 1): one gives way to the sum
        if abs(mpmath.det(system)) < mpmath.mpf(10) ** (-DIGITS // 2):
            return None
        row = mpmath.lu_solve(system, mpmath.matrix([0] * (n - 1) + [1]))
        return [row[i] for i in range(n)]


def limit_masks(mats: list) -> list:
    """Our limit mask of the vertex at every level: stationary at the last, pulled back through the levels before."""
    last = fixed_row(mats[-1])
    if last is None:
        return [None] * len(mats)
    masks = [last]
    with mpmath.workdps(DIGITS):
        for m in reversed(mats[:-1]):
            row = mpmath.matrix([masks[0]]) * m
            masks.insert(0, [row[0, c] for c in range(row.cols)])
    return masks


def spectrum_distance(ours: np.ndarray, theirs: np.ndarray) -> float:
    """For every eigenvalue of either matrix, the smallest singular value of the other minus it; the largest."""
    eye = np.eye(len(ours))
    worst = 0.0
    for a, b in ((ours, theirs), (theirs, ours)):
        for lam in np.linalg.eigvals(a):
            worst = max(worst, float(np.linalg.svd(b - lam * eye, compute_uv=False)[-1]))
    return worst


def left_spans(ours: np.ndarray, planes: int) -> tuple[np.ndarray, np.ndarray]:
    """Columns spanning our left eigenvectors (a) of the largest eigenvalues below 1 (``planes + 1`` of them
    with their multiplicities: the tangent plane of the surface, or of each side of a crease, which share
    the crease's direction) and (b) of eigenvalue 1/2 (a crease curve's tangent)."""
    values, vectors = np.linalg.eig(ours.T)
    order = np.argsort(-np.abs(values))
    rest = [i for i in order if abs(values[i] - 1) > 1e-9]
    chosen, count = [], 0
    while rest and count < planes + 1:
        top = abs(values[rest[0]])
        group = [i for i in rest if abs(abs(values[i]) - top) < 1e-9]
        chosen += group
        count += len(group)
        rest = [i for i in rest if i not in group]
    half = [i for i in order if abs(values[i] - 0.5) < 1e-9]
    plane, curve = (np.hstack([vectors[:, c].real, vectors[:, c].imag]) for c in (chosen, half))
    return plane, curve


def tangent_residual(span: np.ndarray, mask: np.ndarray) -> float:
    """Relative distance of one of OpenSubdiv's derivative masks from ``span``."""
    u, sv, _ = np.linalg.svd(span, full_matrices=False)
    q = u[:, sv > 1e-9 * max(sv.max(initial=0.0), 1e-300)]
    return float(np.linalg.norm(mask - q @ (q.T @ mask)) / np.linalg.norm(mask))
