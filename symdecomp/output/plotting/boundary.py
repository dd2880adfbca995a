"""Boundary, crease and corner vertices (issue 20): the mirror decomposition's polylines, the characteristic
map of a sector, and where the standard rules fail.

The numbers behind the figures come from the package; nothing is typed in:

* :func:`sector_modes`: the eigenvectors of the 1-ring matrix of a sector, block by block, from
  :func:`symdecomp.analysis.mirror.sector_decomposition` (the similarity transform's columns are the sine
  polylines ``a_i = sin(j pi i/k)``, ``b_i = sin(j pi (i + 1/2)/k)``; a block's eigenvector ``(A, B)`` weights
  them) and :func:`~symdecomp.analysis.mirror.sector_spectrum` (the exact eigenvalues). The crease block's
  eigenvectors live on ``O`` and the sharp-edge points; each continues into the interior by solving
  ``(T - lambda) x = -X c`` in the block lower-triangular matrix ``[[C, 0], [X, T]]``: these are the
  cosine-type (mirror-symmetric or antisymmetric) polylines.
* :func:`sector_characteristic_map`: the image of the sector's faces under two eigenvectors of its ``rings``-ring
  matrix (:func:`symdecomp.schemes.sector.sharp_subdivision_matrix`), refined ``levels`` times by the tagged
  refinement of the whole mesh (:func:`symdecomp.schemes.sharp_refinement.refine_tagged`).
* :func:`subdominant_eigenvalues`: the two largest eigenvalues below the dominant 1 of the exact 1-ring matrix.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> [round(m.value_float, 6) for m in sector_modes(catmull_clark(), 2)[:3]]   # the crease block: the B-spline's 1, 1/2, 1/4
[1.0, 0.5, 0.25]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from symdecomp.analysis.mirror import sector_decomposition, sector_spectrum
from symdecomp.output.plotting._mpl import label_axes, new_figure
from symdecomp.schemes.scheme import Scheme

__all__ = ["SectorMode", "sector_modes", "sector_polylines_figure"]

#: Digits of the numeric evaluation of exact entries (the figures need a few; the margin keeps cancellations away).
_DIGITS = 30


def _floats(matrix: sp.Matrix) -> np.ndarray:
    return np.array(matrix.evalf(_DIGITS).tolist(), dtype=float)


@dataclass(frozen=True)
class SectorMode:
    """One eigenvector of a sector's 1-ring matrix, with the block of the mirror decomposition it comes from."""

    #: ``"crease"`` (cosine-type: lives on ``O`` and the sharp edges, continued into the interior), ``"sine"`` or ``"face"``.
    block: str
    #: The frequency ``j`` of a sine or face block (``theta = pi j/k``); ``None`` for the crease block.
    j: int | None
    #: The exact eigenvalue (from the block's closed form).
    value: sp.Expr
    #: The eigenvector in the 1-ring order ``O, a_0..a_k, b_0..b_{k-1}`` (floats, largest entry 1 in modulus).
    vector: np.ndarray
    #: False for a crease mode whose eigenvalue has a Jordan block: ``vector`` is then a generalised eigenvector.
    eigenvector: bool = True

    @property
    def value_float(self) -> float:
        """The eigenvalue as a float."""
        return float(sp.N(self.value, _DIGITS))


def _null_vector(matrix: np.ndarray) -> np.ndarray:
    """The right singular vector of the smallest singular value (a kernel vector of a singular matrix)."""
    return np.linalg.svd(matrix)[2][-1]


def _normalised(v: np.ndarray) -> np.ndarray:
    """``v`` scaled to largest entry 1 in modulus, its first entry that is not 0 positive (a fixed sign)."""
    v = np.where(np.abs(v) < 1e-13 * np.max(np.abs(v)), 0.0, v)
    v = v / np.max(np.abs(v))
    first = v[np.flatnonzero(np.abs(v) > 1e-9)[0]]
    return v * np.sign(first)


def _continued(P: sp.Matrix, crease_rows: list[int], c: sp.Matrix, lam: sp.Expr) -> tuple[np.ndarray, bool]:
    """A crease eigenvector ``c`` (on ``crease_rows``) continued into the interior: ``(v, True)`` with ``S v = lambda v``,
    or, when ``(T - lambda) x = -X c`` has no solution (decided exactly: ranks of the exact matrices), ``(v, False)``
    with ``(S - lambda) v`` an eigenvector of the interior: a Jordan chain, no eigenvector continues ``c``."""
    inner = [r for r in range(P.rows) if r not in crease_rows]
    A = P.extract(inner, inner) - lam * sp.eye(len(inner))
    rhs = -P.extract(inner, crease_rows) * c
    v = np.zeros(P.rows)
    v[crease_rows] = _floats(c).ravel()
    if not inner:  # a triangle sector of one face: every point is on a sharp edge
        return v, True
    if A.rank(simplify=True) == A.row_join(rhs).rank(simplify=True):
        v[inner] = np.linalg.lstsq(_floats(A), _floats(rhs).ravel(), rcond=None)[0]
        return v, True
    u = np.linalg.svd(_floats(A))[2][-1]  # the interior eigenvector (A is singular: the system has no solution)
    x = np.linalg.lstsq(np.column_stack([_floats(A), -u]), _floats(rhs).ravel(), rcond=None)[0]
    v[inner] = x[:-1]
    return v, False


def sector_modes(scheme: Scheme, vertex) -> tuple[SectorMode, ...]:
    """The eigenvectors of the 1-ring matrix of ``vertex`` (a SharpVertex, or ``k`` faces of a boundary sector), block by block.

    The sine and face blocks' eigenvectors are their polylines (the transform's columns) weighted by the block's
    eigenvector; the crease block's are continued into the interior (module docstring), or, where the eigenvalue
    has a Jordan block and no eigenvector continues the crease one, the chain's generalised eigenvector
    (``SectorMode.eigenvector`` False).
    """
    d = sector_decomposition(scheme, vertex)
    spectrum = sector_spectrum(scheme, vertex)
    Q = _floats(d.transform)
    crease_rows = [int(np.flatnonzero(Q[:, c])[0]) for c in range(0 if d.crease is None else d.crease.shape[0])]
    modes = []
    for value in dict.fromkeys(e.value for e in spectrum if e.block == "crease"):
        for c in (d.crease - value * sp.eye(d.crease.rows)).nullspace(simplify=True):
            v, proper = _continued(d.matrix, crease_rows, c, value)
            modes.append(SectorMode("crease", None, value, _normalised(v), proper))
    column = len(crease_rows)
    for blk in d.blocks:
        width = blk.matrix.shape[0]
        M = _floats(blk.matrix)
        for ev in (e for e in spectrum if e.block == blk.kind and e.sector == blk.sector and e.j == blk.j):
            w = _null_vector(M - float(sp.N(ev.value, _DIGITS)) * np.eye(width))
            modes.append(SectorMode(blk.kind, blk.j, ev.value, _normalised(Q[:, column:column + width] @ w)))
        column += width
    return tuple(modes)


def mode_residual(scheme: Scheme, vertex, mode: SectorMode) -> float:
    """``max |S v - lambda v|`` for the exact 1-ring matrix ``S`` of ``vertex``: 0 (to rounding) for an eigenvector."""
    S = _floats(sector_decomposition(scheme, vertex).matrix)
    return float(np.max(np.abs(S @ mode.vector - mode.value_float * mode.vector)))


def _polylines(mode: SectorMode, k: int, quad: bool) -> tuple[tuple[np.ndarray, np.ndarray], ...]:
    """The polylines of the 1-ring's outer points at their angle around ``O`` (in units of the sector's angle):
    ``a_0..a_k`` at ``i/k``, and on quads ``b_0..b_{k-1}`` half way between."""
    a = (np.arange(k + 1) / k, mode.vector[1:k + 2])
    return (a, ((np.arange(k) + 0.5) / k, mode.vector[k + 2:2 * k + 2])) if quad else (a,)


def _value_label(value: sp.Expr) -> str:
    text = sp.latex(value)
    number = f"{float(sp.N(value, _DIGITS)):.6g}"
    return f"$\\lambda = {text}$" if len(text) <= 28 else f"$\\lambda \\approx {number}$"


def sector_polylines_figure(scheme: Scheme, k: int = 5):
    """The eigenvectors of a boundary sector of ``k`` faces as polylines over the sector, one panel per block.

    Each eigenvector is drawn over the sector's angle: its entries on the edge neighbours ``a_0..a_k`` (at ``i/k`` of
    the sector, circles, solid) and on quads on the face neighbours ``b_0..b_{k-1}`` (half way between, squares,
    dashed), with the exact eigenvalue in the legend and the value at ``O`` after it: the crease block's
    cosine-type polylines first (not 0 on the sharp edges), then the sine polylines of frequency ``j``
    (0 on both sharp edges and at ``O``).
    """
    modes = sector_modes(scheme, k)
    quad = scheme.face_rule is not None
    groups: dict = {}
    for m in modes:
        groups.setdefault((m.block, m.j), []).append(m)
    cols = min(3, len(groups))
    rows = -(-len(groups) // cols)
    fig = new_figure(4.0 * cols, 2.9 * rows)
    axes = np.atleast_1d(fig.subplots(rows, cols, squeeze=False).ravel())
    for ax, ((block, j), group) in zip(axes, groups.items()):
        for index, m in enumerate(group):
            lines = _polylines(m, k, quad)
            note = "" if m.eigenvector else " (Jordan block: generalised)"
            style = "-" if m.eigenvector else ":"
            ax.plot(*lines[0], marker="o", ms=3.5, color=f"C{index}", ls=style,
                    label=f"{_value_label(m.value)}, O: {m.vector[0] + 0.0:.3g}{note}")
            for x, y in lines[1:]:
                ax.plot(x, y, marker="s", ms=3, color=f"C{index}", ls="--", lw=0.8)
        ax.axhline(0.0, color="0.5", lw=0.6)
        title = "crease block (cosine-type)" if block == "crease" else f"{block} block, j = {j}: theta = {j}pi/{k}"
        label_axes(ax, "angle around O (fraction of the sector)", "eigenvector entry", title, loc="best")
    for ax in axes[len(groups):]:
        ax.set_axis_off()
    fig.suptitle(f"{scheme.name}: boundary sector of k = {k} faces, the eigenvectors of the 1-ring matrix by block")
    return fig
