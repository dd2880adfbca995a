"""The toolkit's predictions for Loop's scheme checked against OpenSubdiv's Loop (an outside oracle).

The Loop counterpart of :mod:`symdecomp.verify.oracle`. For a valence ``n`` OpenSubdiv's Loop
refinement (:mod:`symdecomp.verify.opensubdiv.loop`) is compared with what the toolkit derives
from the rules of :func:`~symdecomp.schemes.loop.loop`:

======================  ===========================================  ======================
prediction              toolkit side                                 expected agreement
======================  ===========================================  ======================
one-step matrix         ``ring_subdivision_matrix`` (exact), read    double precision
                        column by column from OpenSubdiv
spectrum                ``ring_spectrum`` (with multiplicities) vs   double precision
                        the eigenvalues of OpenSubdiv's matrix
limit mask              ``ring_masks`` position mask vs              double precision
                        OpenSubdiv's ``Limit``
tangent plane           ``ring_masks`` tangent masks span            double precision
                        OpenSubdiv's two limit tangents
limit position          ``O_k -> l . ring_0``                        error ~ mu^k, mu the
                                                                     value after 1 at j = 0
shrink rate, freq. j    the dominant eigenvalue of frequency ``j``   exact when frequency
                        (``j = 0``: the one after 1)                 ``j`` has one value
======================  ===========================================  ======================

The shrink rates are measured as for Catmull-Clark: a random 1-ring ``(O, a_0..a_{n-1})`` is
pushed through single OpenSubdiv steps, each fed the 1-ring the previous one returned
(renormalised by a translation and a power of two), and the part in frequencies ``j`` and
``n - j`` is followed alone (projected back after every step). Loop's 1-ring has one value
per frequency ``j != 0`` (``3/8 + cos(2 pi j/n)/4``) and one after 1 at ``j = 0``
(``5/8 - n beta(n)``), so each rate is the ratio of one step exactly, to rounding.
"""

from __future__ import annotations

import math
import random

import numpy as np

from symdecomp.analysis.masks import ring_masks
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.schemes.loop import loop
from symdecomp.schemes.mesh import triangle_ring_mesh
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.validate import check_int, check_levels, check_valence
from symdecomp.verify.oracle import MAX_LEVELS, Prediction, ValenceComparison, _exact, _limit

__all__ = ["compare_loop_with_opensubdiv"]


def _loop_step(ring: np.ndarray, n: int) -> np.ndarray:
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


def _frequency_part(ring: np.ndarray, n: int, j: int) -> np.ndarray:
    """The part of a real 1-ring in the frequencies ``j`` and ``n - j`` (``j = 0``: ``O`` and the centroid)."""
    A = np.fft.fft(ring[1:], axis=0)
    keep = np.zeros(n, dtype=bool)
    keep[j % n] = keep[(n - j) % n] = True
    a = np.fft.ifft(np.where(keep[:, None], A, 0), axis=0).real
    centre = ring[0] if j == 0 else np.zeros(3)
    return np.vstack([centre[None, :], a])


def _chain(ring: np.ndarray, n: int, levels: int, frequency: int | None):
    """Single steps; per step the pair (before, after) in renormalised coordinates, and the centre in real ones."""
    offset, scale = np.zeros(3), 1.0
    current, steps, centres = ring.copy(), [], [ring[0].copy()]
    for _ in range(levels):
        out = _loop_step(current, n)
        if frequency is not None:
            out = _frequency_part(out, n, frequency) + (0 if frequency == 0 else np.tile(out[0], (n + 1, 1)))
        steps.append((current, out))
        centres.append(offset + scale * out[0])
        shift = out[0].copy()
        moved = out - shift
        size = float(np.max(np.abs(moved)))
        power = 2.0 ** (-math.floor(math.log2(size))) if size > 0 else 1.0
        offset, scale, current = offset + scale * shift, scale / power, moved * power
    return steps, centres


def _frequency_values(spectrum, n: int) -> dict[int, list[complex]]:
    """The distinct eigenvalues of each frequency ``j`` (1 left out at ``j = 0``), largest first."""
    out: dict[int, list[complex]] = {j: [] for j in range(n // 2 + 1)}
    for e in spectrum.eigenvalues:
        value = complex(float(e.value.real.mid()), float(e.value.imag.mid()))
        for j in e.frequencies:
            if j in out and not (j == 0 and abs(value - 1) < 1e-12):
                out[j].append(value)
    return {j: sorted(v, key=abs, reverse=True) for j, v in out.items()}


def compare_loop_with_opensubdiv(n: int, levels: int = 20, seed: int = 0) -> ValenceComparison:
    """Run the comparisons of this module at valence ``n`` (needs the OpenSubdiv bridge).

    Tolerances as in :func:`~symdecomp.verify.oracle.compare_with_opensubdiv`.
    """
    from symdecomp.verify.opensubdiv.loop import osd_loop_one_ring_matrix, osd_loop_position_mask, osd_loop_tangent_masks

    n = check_valence(n)
    levels = check_levels(levels, minimum=2, maximum=MAX_LEVELS, reason="double precision: beyond this the ring is below rounding")
    seed = check_int(seed, "seed", minimum=0, maximum=2**32 - 1)
    scheme = loop()
    exact = ring_subdivision_matrix(scheme, n, 1).exact_matrix()
    S = np.array([[float(exact[r, c]) for c in range(n + 1)] for r in range(n + 1)])
    osd = np.array(osd_loop_one_ring_matrix(n))
    rows = [_exact("one-step matrix", float(np.max(np.abs(osd - S))))]

    spectrum = ring_spectrum(scheme, n, 1, digits=20, exact=False, jordan=False)
    ours = sorted((complex(float(e.value.real.mid()), float(e.value.imag.mid())) for e in spectrum.eigenvalues
                   for _ in range(e.multiplicity)), key=lambda z: (z.real, z.imag))
    theirs = sorted(np.linalg.eigvals(osd), key=lambda z: (z.real, z.imag))
    rows.append(_exact("spectrum", max(abs(a - b) for a, b in zip(ours, theirs)) if len(ours) == len(theirs) else math.inf))

    masks = ring_masks(scheme, n, 1, digits=20)
    position = np.array([float(masks["position"]["O"])] + [float(x) for x in masks["position"]["a"]])
    rows.append(_exact("limit mask", float(np.max(np.abs(np.array(osd_loop_position_mask(n)) - position)))))
    tangents = np.array([[float(m["O"])] + [float(x) for x in m["a"]] for m in masks["tangents"]])
    osd_tangents = np.array(osd_loop_tangent_masks(n))
    C, *_ = np.linalg.lstsq(tangents.T, osd_tangents.T, rcond=None)
    spans = abs(np.linalg.det(C)) > 1e-8
    residual = float(np.abs(tangents.T @ C - osd_tangents.T).max() / max(1.0, np.abs(osd_tangents).max()))
    rows.append(_exact("tangent plane", residual if spans else math.inf))

    rng = random.Random(f"symdecomp-oracle-loop:{seed}:{n}")
    ring0 = np.array([[rng.uniform(-1.0, 1.0) for _ in range(3)] for _ in range(n + 1)])
    values = _frequency_values(spectrum, n)
    floor = 1e-13
    _, centres = _chain(ring0, n, levels, None)
    limit = position @ ring0
    # the centre sees frequency 0 only (the vertex rule weighs all a_i alike): it converges with its value after 1
    rate = abs(values[0][0])
    rows.append(_limit("limit position", None, None, [float(np.max(np.abs(c - limit))) for c in centres], rate, floor, levels))
    rows.extend(_shrink_rates(ring0, n, levels, values, floor))
    return ValenceComparison(n, levels, seed, tuple(rows))


def _shrink_rates(ring0: np.ndarray, n: int, levels: int, values: dict, floor: float) -> list[Prediction]:
    """``shrink rate j=..``: a generic linear functional of frequency ``j``'s part, step over step."""
    ell = np.array([complex(*x) for x in np.random.default_rng(12345).uniform(-1, 1, (3, 2))])
    rows = []
    for j in range(n // 2 + 1):
        steps, _ = _chain(_frequency_part(ring0, n, j), n, levels, j)
        seq = []
        for before, after in steps:
            if j == 0:
                z0, z1 = before[1:].mean(axis=0) - before[0], after[1:].mean(axis=0) - after[0]
            else:
                z0, z1 = np.fft.fft(before[1:], axis=0)[j], np.fft.fft(after[1:], axis=0)[j]
            seq.append(complex(np.dot(ell, z1) / np.dot(ell, z0)))
        dom = values[j][0]
        errors = [abs(x - dom) for x in seq]
        name = f"shrink rate j={j}"
        if len(values[j]) == 1:  # one value in this frequency: every step shrinks by it exactly
            rows.append(_exact(name, max(errors), predicted=abs(dom), observed=abs(seq[-1])))
        else:
            rows.append(_limit(name, abs(dom), abs(seq[-1]), errors, abs(values[j][1] / dom), floor, levels))
    return rows
