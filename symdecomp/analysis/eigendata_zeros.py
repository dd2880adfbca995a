"""The zeros of the eigen-data's sub-patch tables that a mirror symmetry makes exact, proved in rationals.

An entry ``(k, i, l)`` of a sub-patch table is the linear functional ``r`` of sub-patch ``k``'s point ``l``
(its row of the extended patch matrix; ``lam e_idx`` for a control point) applied to the eigenvector
``v_i = [u; W D]`` that extends the 1-ring eigenvector ``u`` (``D_r = (g_r . u)/(lam - nu_r)``,
``g = W^-1 S11``; :mod:`symdecomp.analysis.eigendata`). Grouping the regular block's eigenvalues,

    ``r . v_i = (r_ring + sum_nu h_nu/(lam - nu)) . u``,  ``h_nu = sum_{r: nu_r = nu} (r_outer W)_r g_r``,

a rational vector on the 1-ring for each distinct ``nu`` (the sum over an eigenspace does not depend on its
basis). If ``r_ring`` and every ``h_nu`` are symmetric under the mirror of the 1-ring about an axis (``s ->
2a - s`` in half steps around ``O``), and ``u`` is antisymmetric about it, the entry is exactly 0 for every
``lam``: no 1200-bit ball is needed to show that it rounds to 0.0 (a ball around 0 does so only inside
``(-2^-1075, 2^-1075)``). ``u`` is a wave of frequency ``j`` (:class:`~symdecomp.analysis.fourier_patterns.PatternForm`),
``cos(pi (2 j s + shift)/(2n))`` times a scalar per kind of point, antisymmetric about ``a`` exactly when
``2 j a + shift - n`` is a multiple of ``2n`` (integers: decided exactly). Loop's sine columns vanish so on
the points of the patch's edge ``O a_0``.
"""

from __future__ import annotations

from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.schemes.patch import PatchMatrices

__all__ = ["mirror_zeros", "lower_mirror_zeros"]


def _functional(p: PatchMatrices, idx: int) -> tuple[dict, dict]:
    """``(r_ring, r_outer)``: the row of point ``idx`` of the extended matrix split at the 1-ring (a control point's
    own unit row: its table entry is ``lam`` times the eigenvector's entry)."""
    k0, size = p.ring_size, p.size
    row = {idx: Fraction(1)} if idx < size else p.sparse[idx]
    return {c: x for c, x in row.items() if c < k0}, {c - k0: x for c, x in row.items() if c >= k0}


def _vectors(p: PatchMatrices, idx: int, nus, w: list[list[flint.fmpq]], g_rows) -> list[dict]:
    """``[r_ring, h_nu, ...]``: the rational vectors on the 1-ring that must all be symmetric (zeros left out);
    ``w``: the regular block's eigenvectors ``W``, rows of ``fmpq``; ``g_rows``' weights ``fmpq`` too (FLINT's
    rationals: several times faster than ``Fraction`` here; within one vector all entries are of one type, so
    the symmetry's comparisons are exact)."""
    ring, outer = _functional(p, idx)
    h: dict = {}
    for r, nu in enumerate(nus):
        c = sum((to_fmpq(x) * w[q][r] for q, x in outer.items()), flint.fmpq(0))
        if c:
            acc = h.setdefault(nu, {})
            for col, x in g_rows[r].items():
                acc[col] = acc.get(col, 0) + c * x
    return [ring] + [{c: x for c, x in v.items() if x} for v in h.values()]


def _points_at(steps: list[int]) -> dict[int, int]:
    """``{half step: point}`` of the 1-ring's points (``O``, at step -1, left out)."""
    return {s: c for c, s in enumerate(steps) if s >= 0}


def _symmetric_axes(vectors: list[dict], steps: list[int], period: int, at: dict[int, int]) -> set[int]:
    """The axes ``a`` (half steps, ``0..period - 1``) about which every vector is symmetric (``O`` is on every axis);
    ``at``: :func:`_points_at` of ``steps``."""
    support = sorted({c for v in vectors for c in v if c != 0})
    if not support:  # the entry reads the eigenvector at O only, where a wave is 0: any axis will do
        return {0}
    s0 = steps[support[0]]
    candidates = {((s0 + steps[c]) // 2 + half) % period for c in support if (s0 + steps[c]) % 2 == 0 for half in (0, period // 2)}
    axes = set()
    for a in sorted(candidates):
        mirror = {c: at.get((2 * a - steps[c]) % period) for c in support}
        if all(m is not None and v.get(m, 0) == x for v in vectors for c, x in v.items() if c != 0 for m in [mirror[c]]):
            axes.add(a)
    return axes


def mirror_zeros(p: PatchMatrices, cols: list, nus, wmat, g_rows) -> list[tuple[int, int, int]]:
    """The entries ``(k, i, l)`` of the sub-patch tables that are exactly 0 by a mirror symmetry (module docstring).

    ``cols``: the 1-ring eigenvectors (their right patterns' waves are read); ``nus``, ``wmat``: the regular
    block's eigenvalues and eigenvectors; ``g_rows``: ``W^-1 S11``, exact. Columns that are not waves are left out.
    """
    waves = [(i, col.right_form.wave) for i, col in enumerate(cols) if col.right_form is not None and col.right_form.wave is not None]
    if not waves:
        return []
    first = cols[waves[0][0]].right_form
    same = lambda a, b: a is b or np.array_equal(a, b)  # noqa: E731 - the layouts are shared arrays: identity first
    if any(not same(cols[i].right_form.coef, first.coef) or not same(w[2], first.wave[2]) for i, w in waves):
        return []  # one layout of points for every wave, else nothing is claimed
    steps, coef = first.wave[2].tolist(), first.coef.tolist()
    period = 2 * p.n  # half steps around O
    w = [[to_fmpq(wmat[q, r]) for r in range(wmat.ncols())] for q in range(wmat.nrows())]
    g_rows = [{c: to_fmpq(x) for c, x in g.items()} for g in g_rows]
    columns = np.array([i for i, _ in waves], dtype=np.int64)
    js, shifts = (np.array([wave[m] for _, wave in waves], dtype=np.int64) for m in (0, 1))
    at = _points_at(steps)  # once per valence: made per point it was a third of this function's time
    kinds_kept: dict[int, bool] = {}
    vanishing: dict[int, list[int]] = {}  # point -> the wave columns that vanish on it (points shared by sub-patches)
    out = []
    for k, sub in enumerate(p.subpatches):
        for l, idx in enumerate(sub):
            if idx not in vanishing:
                axes = _symmetric_axes(_vectors(p, idx, nus, w, g_rows), steps, period, at)
                for a in axes - kinds_kept.keys():  # each axis's test once per valence
                    kinds_kept[a] = _same_kinds(coef, steps, a, period, at)
                axes = {a for a in axes if kinds_kept[a]}
                odd = np.zeros(len(waves), dtype=bool)  # the waves antisymmetric about one of the axes
                for a in axes:
                    odd |= (2 * js * a + shifts - p.n) % period == 0
                vanishing[idx] = columns[odd].tolist()
            out += [(k, i, l) for i in vanishing[idx]]
    return out


def _same_kinds(coef: list, steps: list, a: int, period: int, at: dict[int, int]) -> bool:
    """Whether the mirror about ``a`` maps every point of the 1-ring to one with the same scalar (the same kind);
    ``at``: :func:`_points_at` of ``steps``."""
    return all((2 * a - s) % period in at and coef[at[(2 * a - s) % period]] == coef[c] for c, s in enumerate(steps) if s >= 0)


def lower_mirror_zeros(p: PatchMatrices, cols: list, g_rows) -> list[tuple[int, int]]:
    """The entries ``(i, j)`` of ``V^-1``'s lower-left block that are exactly 0 by a mirror symmetry.

    Row ``r`` of the block is ``-g_r`` times the resolvent ``(S - nu_r)^-1`` on the eigenspaces of ``S`` whose
    eigenvalue is not ``nu_r`` (``g = W^-1 S11``). ``S`` commutes with every mirror of the 1-ring (its rules are
    rotation invariant and mirror symmetric, checked when its columns are made), and so do those spectral
    projections; if ``g_r`` is antisymmetric about an axis, so is the row, and its entries on the axis (``O``
    and the points the axis passes through) are 0. The axes are read off the waves' layout as in :func:`mirror_zeros`.
    """
    waves = [col.right_form for col in cols if col.right_form is not None and col.right_form.wave is not None]
    if not waves:
        return []
    steps = waves[0].wave[2].tolist()
    period, k0 = 2 * p.n, p.ring_size
    at = _points_at(steps)
    out = []
    for r, g in enumerate(g_rows):
        if g.get(0, 0) or not g:
            continue
        support = sorted(g)
        s0 = steps[support[0]]
        candidates = {((s0 + steps[c]) // 2 + half) % period for c in support if (s0 + steps[c]) % 2 == 0 for half in (0, period // 2)}
        on_axes: set[int] = set()
        for a in candidates:
            if all(at.get((2 * a - steps[c]) % period) is not None and g.get(at[(2 * a - steps[c]) % period], 0) == -x for c, x in g.items()):
                on_axes.update([0] + [at[s] for s in (a % period, (a + p.n) % period) if s in at])  # O is on every axis
        out += [(k0 + r, j) for j in sorted(on_axes)]
    return out
