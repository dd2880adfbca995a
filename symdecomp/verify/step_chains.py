"""A 1-ring pushed through single OpenSubdiv steps, chained, and its parts by frequency: the oracle's measurements.

The comparisons with OpenSubdiv (:mod:`symdecomp.verify.oracle`) feed OpenSubdiv one step at a time: the 1-ring read
back after a step is the next step's input mesh (the new 1-ring of an interior vertex depends only on its old
1-ring). Between steps the ring is translated to put ``O`` at the origin and scaled by a power of two
(:func:`renormalise`, exact), which keeps the shrinking components at full relative precision. A ring's part in the
frequencies ``j`` and ``n - j`` (real, so both together) is what a frequency's chain follows, projected back after
every step. Catmull-Clark's 1-ring is ``(O, a_0.., b_0..)`` on a quad ring mesh (:func:`quad_chain`), Loop's
``(O, a_0..)`` inside a triangle 2-ring mesh (:func:`loop_chain`); the comparisons read them per lattice.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from symdecomp.schemes.mesh import QuadMesh, ring_mesh, triangle_ring_mesh
from symdecomp.validate import check_valence

__all__ = ["random_ring", "ring_as_mesh", "fourier_components", "exact_step", "lsq_ratio", "renormalise",
           "ring_frequency_part", "Chain", "quad_chain", "centre_only", "loop_step", "triangle_frequency_part", "loop_chain"]


def random_ring(n: int, seed: int) -> tuple[tuple[float, ...], ...]:
    """A random 1-ring ``(O, a_0.., b_0..)`` in ``[-1, 1]^3`` (floats, reproducible from ``seed``)."""
    n = check_valence(n)
    rng = random.Random(f"symdecomp-oracle:{seed}:{n}")
    return tuple(tuple(rng.uniform(-1.0, 1.0) for _ in range(3)) for _ in range(2 * n + 1))


def ring_as_mesh(ring, n: int, rings: int = 1, seed: int = 0) -> QuadMesh:
    """A ``rings``-ring mesh whose 1-ring is ``ring`` (outer rings random)."""
    rng = random.Random(f"symdecomp-oracle-outer:{seed}:{n}")

    def value(s, u, v):
        if (u, v) == (0, 0):
            return ring[0]
        if (u, v) == (1, 0):
            return ring[1 + s]
        if (u, v) == (0, 1):  # pragma: no cover - ring_mesh labels these as (s+1, 1, 0)
            return ring[1 + (s + 1) % n]
        if (u, v) == (1, 1):
            return ring[1 + n + s]
        return tuple(rng.uniform(-1.0, 1.0) for _ in range(3))

    return ring_mesh(n, rings, value)


def fourier_components(ring: np.ndarray, n: int):
    """``(O, A, B)``: the centre and the ``n x 3`` complex arrays ``A[j] = (1/n) sum_i a_i omega^{-ij}``."""
    ring = np.asarray(ring, dtype=np.float64)
    a, b = ring[1 : 1 + n], ring[1 + n :]
    return ring[0], np.fft.fft(a, axis=0) / n, np.fft.fft(b, axis=0) / n


def exact_step(matrix, ring) -> np.ndarray:
    """The exact matrix (Fractions) times the ring of floats, each entry rounded once."""
    x = [[Fraction(float(c)) for c in p] for p in ring]
    out = []
    for row in matrix:
        acc = [Fraction(0)] * 3
        for w, p in zip(row, x):
            if w:
                for c in range(3):
                    acc[c] += w * p[c]
        out.append([float(c) for c in acc])
    return np.array(out)


def lsq_ratio(num: np.ndarray, den: np.ndarray):
    """The scalar ``r`` minimising ``|num - r den|`` (complex inner product)."""
    return complex(np.vdot(den, num) / np.vdot(den, den))


def renormalise(out: np.ndarray, offset, scale: float):
    """``(offset, scale, ring)`` after a step: ``O`` to the origin and magnitude about 1 (a power of two: exact).

    Real coordinates are ``offset + scale * stored``, before and after.
    """
    shift = out[0].copy()
    moved = out - shift
    size = float(np.max(np.abs(moved)))
    power = 2.0 ** (-math.floor(math.log2(size))) if size > 0 else 1.0
    return offset + scale * shift, scale / power, moved * power


def ring_frequency_part(ring: np.ndarray, n: int, j: int) -> np.ndarray:
    """The part of a real ring in the frequencies ``j`` and ``n - j`` (``j = 0``: ``O`` and the centroids)."""
    o, A, B = fourier_components(ring, n)
    keep = np.zeros(n, dtype=bool)
    keep[j % n] = keep[(n - j) % n] = True
    A = np.where(keep[:, None], A, 0)
    B = np.where(keep[:, None], B, 0)
    a = np.fft.ifft(A * n, axis=0).real
    b = np.fft.ifft(B * n, axis=0).real
    centre = o if j == 0 else np.zeros(3)
    return np.vstack([centre[None, :], a, b])


@dataclass(frozen=True)
class Chain:
    """A chain of single steps: per step the Fourier components before and after, the largest one-step
    disagreement with the exact matrix, the centre's distance to its limit, and what leaked into other frequencies."""

    steps: list
    one_step: float
    centre_errors: list
    leak: float


def quad_chain(ring, n, levels, matrix, *, limit=None, frequency=None) -> Chain:
    """Single OpenSubdiv steps, each fed the ring the previous one returned (renormalised)."""
    from symdecomp.verify.opensubdiv import osd_central_rings

    one_step, leak = 0.0, 0.0
    offset, scale = np.zeros(3), 1.0  # real coordinates = offset + scale * stored
    current = np.array(ring, dtype=np.float64)
    centre_errors = [] if limit is None else [float(np.max(np.abs(current[0] - limit)))]
    steps = []
    for _ in range(levels):
        out = osd_central_rings(ring_as_mesh(tuple(map(tuple, current)), n, 1), 0, 1).rings[1]
        predicted = exact_step(matrix, current)
        one_step = max(one_step, float(np.max(np.abs(predicted - out)) / max(1.0, np.max(np.abs(current)))))
        if frequency is not None:
            kept = ring_frequency_part(out, n, frequency)
            base = out[0] if frequency != 0 else np.zeros(3)
            # what OpenSubdiv put into other frequencies, relative to what it kept
            leak = max(leak, float(np.max(np.abs(out - kept - centre_only(base, n))) / np.max(np.abs(kept - centre_only(kept[0], n)))))
            out = kept if frequency == 0 else kept + centre_only(base, n)
        steps.append((fourier_components(current, n), fourier_components(out, n)))
        if limit is not None:
            centre_errors.append(float(np.max(np.abs(offset + scale * out[0] - limit))))
        offset, scale, current = renormalise(out, offset, scale)
    return Chain(steps, one_step, centre_errors, leak)


def centre_only(o: np.ndarray, n: int) -> np.ndarray:
    """The ring with every point at ``o`` (a translation)."""
    return np.tile(o, (2 * n + 1, 1))


def loop_step(ring: np.ndarray, n: int) -> np.ndarray:
    """One OpenSubdiv Loop step of the 1-ring ``(O, a_0..a_{n-1})`` (inside a 2-ring mesh)."""
    from symdecomp.verify.opensubdiv.loop import osd_loop_step

    def value(s, u, v):
        if (u, v) == (0, 0):
            return tuple(ring[0])
        if (u, v) == (1, 0):
            return tuple(ring[1 + s])
        return (0.0, 0.0, 0.0)  # the second ring does not enter the new 1-ring

    vertex, edge, _ = osd_loop_step(triangle_ring_mesh(n, 2, value), [(0, 1 + i) for i in range(n)])
    return np.array([vertex[0]] + list(edge))


def triangle_frequency_part(ring: np.ndarray, n: int, j: int) -> np.ndarray:
    """The part of a real 1-ring in the frequencies ``j`` and ``n - j`` (``j = 0``: ``O`` and the centroid)."""
    A = np.fft.fft(ring[1:], axis=0)
    keep = np.zeros(n, dtype=bool)
    keep[j % n] = keep[(n - j) % n] = True
    a = np.fft.ifft(np.where(keep[:, None], A, 0), axis=0).real
    centre = ring[0] if j == 0 else np.zeros(3)
    return np.vstack([centre[None, :], a])


def loop_chain(ring: np.ndarray, n: int, levels: int, frequency: int | None):
    """Single steps; per step the pair (before, after) in renormalised coordinates, and the centre in real ones."""
    offset, scale = np.zeros(3), 1.0
    current, steps, centres = ring.copy(), [], [ring[0].copy()]
    for _ in range(levels):
        out = loop_step(current, n)
        if frequency is not None:
            out = triangle_frequency_part(out, n, frequency) + (0 if frequency == 0 else np.tile(out[0], (n + 1, 1)))
        steps.append((current, out))
        centres.append(offset + scale * out[0])
        offset, scale, current = renormalise(out, offset, scale)
    return steps, centres
