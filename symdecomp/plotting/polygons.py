"""Figures for Sections 2 and 4: regular n-gons (Fig. 3), decompositions, the 1-ring (Fig. 2).

>>> vertex_labels(np.array([1, -1, 1, -1]))
{0: '0,2', 1: '1,3'}
"""

from __future__ import annotations

from typing import Iterable

import numpy as np

from ..circulant import fourier_matrix
from ..errors import check_valence
from ._mpl import new_figure

__all__ = ["regular_polygons_figure", "vertex_labels", "draw_polygon_2d", "draw_polygon_3d", "draw_one_ring_3d", "set_equal_3d"]


def vertex_labels(points: np.ndarray, *, decimals: int = 9) -> dict[int, str]:
    """Group the indices of coinciding vertices: ``{first index: "i,k,..."}``.

    Regular n-gons ``v_k`` with ``gcd(k, n) > 1`` pass through the same point several times;
    their vertices are labelled together.
    """
    seen: dict[tuple, list[int]] = {}
    for i, p in enumerate(np.atleast_1d(points)):
        key = tuple(np.round(np.atleast_1d(np.asarray(p, dtype=complex)).view(float), decimals) + 0.0)
        seen.setdefault(key, []).append(i)
    return {idx[0]: ",".join(map(str, idx)) for idx in seen.values()}


def draw_polygon_2d(ax, points, *, color="C0", label=None, numbered=True, **kwargs) -> None:
    """Draw a planar polygon given as complex numbers: closed edge path, vertices, vertex numbers."""
    z = np.asarray(points, dtype=complex)
    closed = np.append(z, z[0])
    ax.plot(closed.real, closed.imag, color=color, label=label, **kwargs)
    ax.scatter(z.real, z.imag, color=color, s=18, zorder=3)
    ax.scatter([z[0].real], [z[0].imag], color=color, s=60, marker="o", facecolors="none", zorder=3)
    if numbered:
        for i, text in vertex_labels(z).items():
            direction = z[i] / abs(z[i]) if abs(z[i]) > 1e-12 else 1
            pos = z[i] + 0.16 * direction
            ax.annotate(text, (pos.real, pos.imag), ha="center", va="center", fontsize=8)


def draw_polygon_3d(ax, points, *, color="C0", label=None, closed=True, **kwargs) -> None:
    """Draw a polygon in R^3 (an ``(m, 3)`` array): closed edge path and vertices."""
    p = np.asarray(points, dtype=float)
    path = np.vstack([p, p[:1]]) if closed else p
    ax.plot(path[:, 0], path[:, 1], path[:, 2], color=color, label=label, **kwargs)
    ax.scatter(p[:, 0], p[:, 1], p[:, 2], color=color, s=12)


def regular_polygons_figure(valences: Iterable[int] = (5, 6)):
    """Fig. 3: the rows ``v_0..v_{n-1}`` of the Fourier matrix ``F_n`` (Eq. 2, 4) as planar n-gons.

    One row of panels per valence. Vertex ``m`` of ``v_k`` is ``omega_n^(k m)``; the numbers
    give the order of the vertices (the circled one is vertex 0), so that the convex ``v_1``,
    the star polygons and the degenerate ``v_0`` (all vertices at 1) can be told apart.
    """
    valences = [check_valence(v, minimum=1) for v in valences]
    cols = max(valences)
    fig = new_figure(2.1 * cols, 2.4 * len(valences))
    axes = np.atleast_2d(fig.subplots(len(valences), cols, squeeze=False))
    circle = np.exp(2j * np.pi * np.linspace(0, 1, 200))
    for row, n in zip(axes, valences):
        F = np.array(fourier_matrix(n).evalf(20), dtype=complex)
        for k, ax in enumerate(row):
            if k >= n:
                ax.set_axis_off()
                continue
            ax.plot(circle.real, circle.imag, color="0.85", lw=0.8)
            draw_polygon_2d(ax, F[k], color=f"C{k}")
            ax.set_title(rf"$\vec v_{{{k}}}$, n = {n}", fontsize=10)
            ax.set_aspect("equal")
            ax.set_xlim(-1.35, 1.35)
            ax.set_ylim(-1.35, 1.35)
            ax.set_xlabel("Re", fontsize=8)
            ax.set_ylabel("Im", fontsize=8)
            ax.tick_params(labelsize=7)
    fig.suptitle(r"The regular planar n-gons: rows of $F_n$ (Eq. 2, Fig. 3)")
    return fig


def draw_one_ring_3d(ax, center, a, b, *, color="0.55", a_color="C0", b_color="C3", label_prefix="", lw=0.8) -> None:
    """Draw a 1-ring in R^3: the quads ``(O, a_i, b_i, a_{i+1})`` and the n-gons ``A`` (a's) and ``B`` (b's).

    ``center`` is a point, ``a`` and ``b`` are ``(n, 3)`` arrays.
    """
    O = np.asarray(center, dtype=float)
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    n = len(a)
    for i in range(n):
        path = np.array([O, a[i], b[i], a[(i + 1) % n]])
        ax.plot(path[:, 0], path[:, 1], path[:, 2], color=color, lw=lw)
    draw_polygon_3d(ax, a, color=a_color, ls="--", lw=1.2, label=f"{label_prefix}A (the $a_i$)")
    draw_polygon_3d(ax, b, color=b_color, ls=":", lw=1.5, label=f"{label_prefix}B (the $b_i$)")
    ax.scatter([O[0]], [O[1]], [O[2]], color="black", s=25)


def set_equal_3d(ax, points) -> None:
    """Give a 3-D axes equal scales on x, y, z around the given points (an ``(m, 3)`` array)."""
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    centre = (p.max(axis=0) + p.min(axis=0)) / 2
    radius = max(float(np.max(p.max(axis=0) - p.min(axis=0))) / 2, 1e-12)
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - radius, c + radius)
    ax.set_box_aspect((1, 1, 1))
