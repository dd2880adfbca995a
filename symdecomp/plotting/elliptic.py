"""Figures for Sections 5.2-5.3: the ellipses ``E_a``, ``E_b`` (Fig. 7), hyperbolic rings (Fig. 8), defects.

The geometry comes from :mod:`symdecomp.evolution` (rings iterated by the exact subdivision
matrix); the closed forms from the scheme's derived matrices.
"""

from __future__ import annotations

from typing import Iterable, Sequence

import numpy as np

from ..evolution import EllipticProfile, split_ring
from ._mpl import new_figure
from .polygons import _few_ticks, draw_polygon_3d, set_equal_3d

__all__ = ["ellipses_figure", "nested_rings_figure", "defect_figure", "tuned_weights_figure"]


def _paraboloid(ax, kappa: float, radius: float, color: str = "C2") -> None:
    r = np.linspace(0, radius, 20)
    t = np.linspace(0, 2 * np.pi, 48)
    R, T = np.meshgrid(r, t)
    ax.plot_surface(R * np.cos(T), R * np.sin(T), kappa * R**2, color=color, alpha=0.15, linewidth=0)


def ellipses_figure(profile: EllipticProfile, steps: Iterable[int] = range(1, 6), *, title: str = ""):
    """Fig. 7: the ellipses ``E_a``, ``E_b`` after several steps, each relative to that step's ``O``.

    Left (3-D): for each step ``k`` in ``steps``, ``E_a`` and ``E_b`` translated so that ``O_k`` is at
    the origin, with the paraboloid of revolution ``z = kappa r^2`` through the last ``E_a``
    (``kappa = d_a / scale^2``, :class:`symdecomp.evolution.EllipticProfile`). With nice elliptic
    properties every ellipse lies on it. Right: ``kappa_a`` and ``kappa_b`` at every step; nice
    elliptic properties make both curves flat (subdominant eigenvalue of Eq. 43 = ``lambda_1^2``)
    and equal (Eq. 44 = the squared scale ratio of Eq. 39).
    """
    steps = [k for k in steps if 0 <= k < len(profile.rings)]
    if not steps:
        raise ValueError(f"no step to show: the profile has steps 0..{len(profile.rings) - 1}")
    fig = new_figure(12, 5.2)
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    for index, k in enumerate(steps):
        O, _, _ = split_ring(profile.rings[k])
        for ellipse, color, name in ((profile.ellipses_a[k], "C0", "$E_a$"), (profile.ellipses_b[k], "C3", "$E_b$")):
            p = ellipse.points() - O
            ax.plot(p[:, 0], p[:, 1], p[:, 2], color=color, lw=1.2, label=name if index == 0 else None)
    ax.scatter([0], [0], [0], color="black", s=20, label="$O_k$ (each step's O, at the origin)")
    last = steps[-1]
    kappa = float(profile.kappa_a[last])
    radius = max(profile.ellipses_b[k].semi_axes()[0] for k in steps)
    _paraboloid(ax, kappa, radius)
    ax.plot([], [], color="C2", alpha=0.5, lw=6, label=f"paraboloid through $E_a$ of step {last}")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("height above $O_k$")
    ax.set_title(f"$E_a$, $E_b$ at steps {steps[0]}..{steps[-1]}, relative to $O_k$")
    ax.legend(fontsize=7, loc="upper left")
    ax.view_init(elev=14, azim=-60)
    _few_ticks(ax)

    right = fig.add_subplot(1, 2, 2)
    k = np.arange(len(profile.rings))
    right.plot(k[1:], profile.kappa_a[1:], marker="o", color="C0", label=r"$\kappa_a = d_a / \mathrm{scale}(E_a)^2$")
    right.plot(k[1:], profile.kappa_b[1:], marker="s", color="C3", label=r"$\kappa_b = d_b / \mathrm{scale}(E_b)^2$")
    both = np.abs(np.concatenate([profile.kappa_a[1:], profile.kappa_b[1:]]))
    logarithmic = both.min() > 0 and both.max() / both.min() > 3
    if logarithmic:
        right.set_yscale("log")
    right.set_xlabel("subdivision step k")
    right.set_ylabel(r"$\kappa$" + (" (log scale)" if logarithmic else ""))
    right.set_title("Nice elliptic properties: both flat and equal")
    right.legend(fontsize=8)
    right.grid(alpha=0.3, which="both")
    fig.suptitle(title or "The ellipses $E_a$, $E_b$ over several steps (Fig. 7)")
    return fig


def nested_rings_figure(rings: Sequence, *, title: str, highlight: np.ndarray | None = None, highlight_label: str = ""):
    """Fig. 8 (right) and the like: the 1-rings of successive steps drawn together, in 3-D.

    The 1-ring of step ``k`` covers a neighbourhood of ``O`` that shrinks with ``lambda_1^k``; drawn
    together, relative to the last ``O``, the quads trace the shape of the limit surface near
    ``O`` (a hyperbolic paraboloid when only hyperbolic components leave the tangent plane).
    ``highlight`` (an ``(m, 3)`` polygon, e.g. the eigencomponent ``A^2``) is drawn on the left.
    """
    fig = new_figure(12 if highlight is not None else 6.5, 5.4)
    panels = 2 if highlight is not None else 1
    if highlight is not None:
        left = fig.add_subplot(1, panels, 1, projection="3d")
        draw_polygon_3d(left, highlight, color="C1", lw=1.6, label=highlight_label)
        h = np.asarray(highlight, dtype=float)
        for p in h:
            left.plot([p[0], p[0]], [p[1], p[1]], [0, p[2]], color="0.6", lw=0.6)
        left.scatter([0], [0], [0], color="black", s=20, label="O")
        set_equal_3d(left, np.vstack([h, np.zeros((1, 3))]))
        left.set_xlabel("x")
        left.set_ylabel("y")
        left.set_zlabel("z")
        left.set_title(highlight_label or "component")
        left.legend(fontsize=8, loc="upper left")
        _few_ticks(left)
    ax = fig.add_subplot(1, panels, panels, projection="3d")
    origin = split_ring(rings[-1])[0]
    points = np.vstack([np.asarray(r, dtype=float) - origin for r in rings])
    # The vertices of all the rings, triangulated over the tangent plane (x, y): near O they
    # lie on the limit surface's graph, so the triangulation shows its shape.
    ax.plot_trisurf(points[:, 0], points[:, 1], points[:, 2], cmap="coolwarm", alpha=0.6, linewidth=0.1, edgecolor="0.5")
    for ring in rings:
        O, a, b = split_ring(np.asarray(ring, dtype=float) - origin)
        polygon = np.empty((2 * len(a), 3))
        polygon[0::2], polygon[1::2] = a, b
        draw_polygon_3d(ax, polygon, color="0.15", lw=0.8)
    ax.set_box_aspect((1, 1, 0.6))
    ax.scatter([0], [0], [0], color="black", s=20)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(f"The 1-rings ($2n$-gons) of {len(rings)} steps, and a surface through their vertices")
    ax.view_init(elev=22, azim=-50)
    _few_ticks(ax)
    fig.suptitle(title)
    return fig


def defect_figure(rows, *, title: str = "How far Catmull-Clark is from nice elliptic properties"):
    """The defect of each elliptic condition over ``n``, from rows of an elliptic defect table.

    ``rows`` have attributes ``n``, ``subdominant``, ``lambda1_squared``, ``eigenvalue_defect``,
    ``eq44_ratio``, ``scale_ratio_squared``, ``ratio_defect`` (numbers).
    """
    ns = [r.n for r in rows]
    fig = new_figure(12, 4.6)
    left, right = fig.subplots(1, 2)
    left.plot(ns, [float(r.subdominant) for r in rows], marker="o", ms=4, label=r"$\mu$, subdominant eigenvalue of Eq. 43")
    left.plot(ns, [float(r.lambda1_squared) for r in rows], marker="s", ms=4, label=r"$\lambda_1^2$ (Eq. 34)")
    left.plot(ns, [float(r.eigenvalue_defect) for r in rows], color="C3", ls="--", label=r"defect $\mu - \lambda_1^2$")
    left.axhline(0, color="0.6", lw=0.8)
    left.set_xlabel("valence n")
    left.set_ylabel("eigenvalue")
    left.set_title(r"Condition 1: $\mu = \lambda_1^2$")
    left.legend(fontsize=8)
    left.grid(alpha=0.3)
    right.plot(ns, [float(r.eq44_ratio) for r in rows], marker="o", ms=4, label=r"$d_b/d_a$ (Eq. 44)")
    right.plot(ns, [float(r.scale_ratio_squared) for r in rows], marker="s", ms=4, label=r"$|B^1/A^1|^2$ (Eq. 39 squared)")
    right.plot(ns, [float(r.ratio_defect) for r in rows], color="C3", ls="--", label="defect (difference)")
    right.axhline(0, color="0.6", lw=0.8)
    right.set_xlabel("valence n")
    right.set_ylabel("ratio")
    right.set_title("Condition 2: Eq. 44 = squared scale ratio")
    right.legend(fontsize=8)
    right.grid(alpha=0.3)
    fig.suptitle(title)
    return fig


def tuned_weights_figure(valences: Sequence[int], series: dict, *, standard: dict | None = None, title: str = "Tuned vertex-rule weights"):
    """Vertex-rule weights over ``n``: ``series`` maps a label to ``(alphas, betas)`` (``None`` where none exist).

    Weights are shown multiplied by ``n`` (the total weight ``n alpha`` of the ``a``'s, ``n beta`` of the
    ``b``'s), which stay of order 1 as ``n`` grows.
    """
    fig = new_figure(12, 4.6)
    left, right = fig.subplots(1, 2)
    ns = np.array(valences, dtype=float)
    for k, (label, (alphas, betas)) in enumerate(series.items()):
        a = np.array([np.nan if x is None else float(x) for x in alphas])
        b = np.array([np.nan if x is None else float(x) for x in betas])
        left.plot(ns, ns * a, marker="o", ms=4, color=f"C{k}", label=label)
        right.plot(ns, ns * b, marker="o", ms=4, color=f"C{k}", label=label)
    if standard is not None:
        left.plot(ns, ns * np.array([float(x) for x in standard["alpha"]]), color="0.3", ls=":", label="standard Catmull-Clark")
        right.plot(ns, ns * np.array([float(x) for x in standard["beta"]]), color="0.3", ls=":", label="standard Catmull-Clark")
    left.set_xlabel("valence n")
    left.set_ylabel(r"$n\,\alpha$ (total weight of the $a_i$)")
    left.set_title(r"$\alpha$")
    right.set_xlabel("valence n")
    right.set_ylabel(r"$n\,\beta$ (total weight of the $b_i$)")
    right.set_title(r"$\beta$")
    for ax in (left, right):
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle(title)
    return fig
