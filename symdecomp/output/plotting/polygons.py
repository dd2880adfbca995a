"""Figures for Sections 2 and 4: regular n-gons (Fig. 3), decompositions, the 1-ring (Fig. 2).

>>> vertex_labels(np.array([1, -1, 1, -1]))
{0: '0,2', 1: '1,3'}
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from symdecomp.algebra.circulant import fourier_matrix
from symdecomp.output.plotting._mpl import label_axes, new_figure
from symdecomp.validate import check_valence

__all__ = [
    "regular_polygons_figure",
    "vertex_labels",
    "draw_polygon_2d",
    "draw_polygon_3d",
    "draw_one_ring_3d",
    "set_equal_3d",
    "ring_split_figure",
    "decomposition_figure",
    "regular_components",
]


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


def _plane_patch(ax, points, color, alpha=0.12) -> None:
    """Shade the convex hull (in its own plane) of a planar polygon given as an ``(m, 3)`` array."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    p = np.asarray(points, dtype=float)
    centre = p.mean(axis=0)
    u = p[0] - centre
    normal = np.cross(u, p[1] - centre)
    if np.linalg.norm(normal) < 1e-12 or np.linalg.norm(u) < 1e-12:
        return
    v = np.cross(normal, u)
    angles = np.arctan2((p - centre) @ v / np.linalg.norm(v), (p - centre) @ u / np.linalg.norm(u))
    ax.add_collection3d(Poly3DCollection([p[np.argsort(angles)]], facecolor=color, alpha=alpha, edgecolor="none"))


def _few_ticks(ax, count: int = 4) -> None:
    from matplotlib.ticker import MaxNLocator

    for axis in (ax.xaxis, ax.yaxis, getattr(ax, "zaxis", None)):
        if axis is not None:
            axis.set_major_locator(MaxNLocator(count))
            axis.set_tick_params(labelsize=7)


def _ring_panel(ax, ring, title: str) -> None:
    """One 3-D panel of :func:`ring_split_figure`: the ring, its n-gons or 2n-gon, and their planes."""
    from symdecomp.analysis.evolution import split_ring
    from symdecomp.schemes.ring import interleaved_polygon

    O, a, b = split_ring(ring)
    n = len(a)
    planar = np.ptp(np.append(a[:, 2], b[:, 2])) < 1e-9 * max(1.0, float(np.abs(ring).max()))
    for i in range(n):
        spoke = np.array([O, a[i]])
        ax.plot(spoke[:, 0], spoke[:, 1], spoke[:, 2], color="0.7", lw=0.6)
    if planar:
        polygon = np.array(interleaved_polygon(a, b))
        draw_polygon_3d(ax, polygon, color="C2", lw=1.6, label=f"the {2 * n}-gon $(a_0, b_0, a_1, \\dots)$")
        _plane_patch(ax, polygon, "C2")
    else:
        draw_polygon_3d(ax, a, color="C0", lw=1.6, label="$A$ (the $a_i$)")
        draw_polygon_3d(ax, b, color="C3", lw=1.6, label="$B$ (the $b_i$)")
        _plane_patch(ax, a, "C0", alpha=0.18)
        _plane_patch(ax, b, "C3", alpha=0.18)
    ax.scatter([O[0]], [O[1]], [O[2]], color="black", s=30, label="O")
    centre = np.vstack([a, b]).mean(axis=0)
    ax.plot([O[0], centre[0]], [O[1], centre[1]], [O[2], centre[2]], color="0.3", lw=0.8, ls="-.")
    points = np.vstack([O, a, b])
    lo, hi = points.min(axis=0), points.max(axis=0)
    half = (hi[:2] - lo[:2]).max() / 2 * 1.05
    mid = (hi + lo) / 2
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(lo[2] - 0.05 * (hi[2] - lo[2] + 1e-9), hi[2] + 0.05 * (hi[2] - lo[2] + 1e-9))
    ax.set_box_aspect((1, 1, 0.7))
    _few_ticks(ax)
    ax.view_init(elev=12, azim=-60)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(title)
    ax.legend(fontsize=8, loc="upper left")


def ring_split_figure(rings, *, titles=None, suptitle: str = "A planar 2n-gon splits into two parallel n-gons (Fig. 2)"):
    """Fig. 2: a 1-ring before and after subdivision steps, in 3-D, with the planes of ``A`` and ``B``.

    ``rings`` are ``(2n+1, 3)`` arrays in the vertex order ``(O, a's, b's)``
    (:mod:`symdecomp.analysis.evolution`), e.g. ``subdivide_ring(scheme, ring, 1)``. The ``a``'s and the
    ``b``'s of each ring are drawn as the n-gons ``A`` and ``B`` with their planes shaded; a last
    panel shows the heights (z) of ``O``, of the ``a``'s and of the ``b``'s in each ring.
    """
    from symdecomp.analysis.evolution import split_ring

    rings = [np.asarray(r, dtype=float) for r in rings]
    if titles is None:
        titles = ["initial 1-ring"] + [f"after {k} step{'s' if k != 1 else ''}" for k in range(1, len(rings))]
    titles = list(titles)
    fig = new_figure(5.6 * len(rings) + 4.6, 5.0)
    for k, (ring, title) in enumerate(zip(rings, titles)):
        _ring_panel(fig.add_subplot(1, len(rings) + 1, k + 1, projection="3d"), ring, title)
    heights = fig.add_subplot(1, len(rings) + 1, len(rings) + 1)
    for k, ring in enumerate(rings):
        O, a, b = split_ring(ring)
        heights.scatter([k], [O[2]], color="black", marker="o", label="O" if k == 0 else None)
        heights.scatter(np.full(len(a), k - 0.08), a[:, 2], color="C0", marker="o", s=14, label="a's" if k == 0 else None)
        heights.scatter(np.full(len(b), k + 0.08), b[:, 2], color="C3", marker="s", s=14, label="b's" if k == 0 else None)
    heights.set_xticks(range(len(rings)), titles, fontsize=8)
    label_axes(heights, "ring", "height z", "Heights of O, the a's and the b's")
    fig.suptitle(suptitle)
    return fig


def decomposition_figure(polygon, components, *, pairs=None, title: str = "An n-gon in R^3 decomposed into planar regular n-gons (Eq. 5-6)"):
    """A polygon in R^3, its components (regular planar n-gons), and their sum.

    ``polygon`` is an ``(n, 3)`` array; ``components[j]`` the ``(n, 3)`` vertices of the component
    ``z_j v_j`` of Eq. 5. ``pairs`` lists groups of indices drawn in one panel (by default
    ``{j, n-j}``, which Eq. 6 says are coplanar; their common plane is shaded). The last panel
    overlays the sum of the components on the polygon and states the largest deviation.
    """
    P = np.asarray(polygon, dtype=float)
    comps = [np.asarray(c, dtype=float) for c in components]
    n = len(P)
    if pairs is None:
        pairs = [[0]] + [[j, n - j] if j != n - j else [j] for j in range(1, n // 2 + 1)]
    panels = len(pairs) + 2
    cols = min(panels, 3)
    rows = -(-panels // cols)
    fig = new_figure(4.2 * cols, 4.0 * rows)
    everything = np.vstack([P] + comps)
    lo, hi = everything.min(axis=0), everything.max(axis=0)
    centre, half = (lo + hi) / 2, float((hi - lo).max()) / 2 * 1.05

    def frame(ax, label):
        for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
            setter(c - half, c + half)
        ax.set_box_aspect((1, 1, 1))
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
        ax.set_title(label, fontsize=10)
        _few_ticks(ax, 3)

    ax = fig.add_subplot(rows, cols, 1, projection="3d")
    draw_polygon_3d(ax, P, color="black", lw=1.5)
    ax.scatter(*P[0], color="black", s=50, facecolors="none")
    frame(ax, f"the polygon P (n = {n}; circle: vertex 0)")
    for k, group in enumerate(pairs):
        ax = fig.add_subplot(rows, cols, k + 2, projection="3d")
        for j in group:
            draw_polygon_3d(ax, comps[j], color=f"C{j % 10}", lw=1.4, label=f"$z_{{{j}}} v_{{{j}}}$")
            ax.scatter(*comps[j][0], color=f"C{j % 10}", s=40, facecolors="none")
        if len(group) > 1 or np.linalg.matrix_rank(comps[group[0]] - comps[group[0]].mean(axis=0), tol=1e-9) == 2:
            _plane_patch(ax, np.vstack([comps[j] for j in group]), "C7", alpha=0.15)
        frame(ax, ", ".join(f"$z_{{{j}}} v_{{{j}}}$" for j in group) + (" (coplanar pair)" if len(group) == 2 else ""))
        ax.legend(fontsize=7, loc="upper left")
    ax = fig.add_subplot(rows, cols, len(pairs) + 2, projection="3d")
    total = np.sum(comps, axis=0)
    draw_polygon_3d(ax, P, color="black", lw=2.5, alpha=0.35, label="P")
    draw_polygon_3d(ax, total, color="C3", lw=1.0, ls="--", label=r"$\sum_j z_j v_j$")
    frame(ax, f"sum of the components: max deviation {np.abs(total - P).max():.1e}")
    ax.legend(fontsize=7, loc="upper left")
    fig.suptitle(title)
    return fig


def regular_components(decomposition) -> list[np.ndarray]:
    """The ``n`` planar regular n-gons ``z_j v_j`` of a decomposition of an n-gon in R^3, as float arrays.

    ``decomposition`` is a :class:`symdecomp.algebra.polygons.PolygonDecomposition` of a polygon in R^3;
    component ``j`` is the regular polygon of frequency ``j`` of its coplanar pair
    (:meth:`~symdecomp.algebra.polygons.PolygonDecomposition.planar_pair`, Eq. 6). For ``j = 0`` (the
    centroid) and ``j = n/2`` (a segment) the pair is one degenerate polygon.
    """
    n = decomposition.n
    out = []
    for j in range(n):
        k = min(j, n - j)
        first, second = decomposition.planar_pair(k)
        component = first if j == k else second
        out.append(np.array(component.vertices(), dtype=float))
    return out
