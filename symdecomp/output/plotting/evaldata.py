"""Figures for exact evaluation near an extraordinary vertex (Stam's method, notebook 6).

The surfaces are evaluated by :class:`~symdecomp.analysis.evaluation.PatchEvaluator` from the
certified float64 data; the control net is a valence-``n`` ring mesh laid out regularly in the
plane and lifted onto a quadric, so the curvature shown is the scheme's, not the data's.

>>> len(demo_control_points(5, sector=0))
18
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import lru_cache

import numpy as np

from symdecomp.analysis.eigendata import certified_eigendata
from symdecomp.analysis.evaluation import PatchEvaluator, curvatures
from symdecomp.output.plotting._mpl import new_figure
from symdecomp.schemes.patch import patch_mesh
from symdecomp.schemes.scheme import Scheme
from symdecomp.verify.patch_eval import baseline_error, numpy_baseline

__all__ = ["demo_control_points", "surface_samples", "patch_surface_figure", "curvature_profile_figure", "baseline_error_figure"]


@lru_cache(maxsize=32)
def _evaluator(scheme: Scheme, n: int) -> PatchEvaluator:
    return PatchEvaluator.from_rounded(scheme, certified_eigendata(scheme, n)[1])


def demo_control_points(n: int, sector: int = 0, lift=(0.5, 0.2, 0.3)) -> np.ndarray:
    """The patch's ``2n + 8`` control points for the patch in ``sector`` of a lifted regular ring mesh.

    Vertex ``(s, u, v)`` of the ring mesh sits at ``u r_s + v r_{s+1}`` (``r_s`` the unit vector at
    angle ``2 pi s/n``) with height ``a x^2 + b y^2 + c x y``, ``(a, b, c) = lift``.
    """
    a, b, c = lift

    def place(s, u, v):
        s = s + sector - 1
        x = u * math.cos(2 * math.pi * s / n) + v * math.cos(2 * math.pi * (s + 1) / n)
        y = u * math.sin(2 * math.pi * s / n) + v * math.sin(2 * math.pi * (s + 1) / n)
        return (x, y, a * x * x + b * y * y + c * x * y)

    mesh, _, columns = patch_mesh(n, place)
    return np.array([mesh.values[k] for k in columns], dtype=float)


def surface_samples(scheme: Scheme, n: int, resolution: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """``(points, gaussian)`` of all ``n`` patches around the vertex, on a grid refined towards it."""
    ev = _evaluator(scheme, n)
    t = np.concatenate([[1e-4], np.geomspace(1e-3, 1.0, resolution)])
    u, v = np.meshgrid(t, t, indexing="ij")
    points, gauss = [], []
    for sector in range(n):
        out = ev.evaluate(demo_control_points(n, sector), u, v)
        points.append(out["point"])
        gauss.append(curvatures(out)[0])
    return np.array(points), np.array(gauss)


def patch_surface_figure(scheme: Scheme, valences: Sequence[int] = (3, 5, 80), resolution: int = 16):
    """The surface around vertices of the given valences, coloured by Gaussian curvature."""
    from matplotlib import cm, colors

    fig = new_figure(4.2 * len(valences), 4.2)
    for k, n in enumerate(valences):
        points, gauss = surface_samples(scheme, n, resolution)
        ax = fig.add_subplot(1, len(valences), k + 1, projection="3d")
        lo, hi = np.nanpercentile(gauss, [5, 95])  # the extremes at the vertex would wash out the rest
        norm = colors.Normalize(vmin=float(lo), vmax=float(hi), clip=True)
        for p, g in zip(points, gauss):
            ax.plot_surface(p[..., 0], p[..., 1], p[..., 2], facecolors=cm.viridis(norm(g)), linewidth=0, shade=False)
        ax.set_title(f"valence {n}")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
        fig.colorbar(cm.ScalarMappable(norm=norm, cmap="viridis"), ax=ax, shrink=0.6, label="Gaussian curvature (5-95%)")
    return fig


def curvature_profile_figure(scheme: Scheme, valences: Sequence[int] = (3, 5, 80)):
    """Gaussian curvature along the patch diagonal ``u = v = t`` as ``t -> 0`` (log scale in ``t``)."""
    fig = new_figure(6.5, 4.0)
    ax = fig.add_subplot(1, 1, 1)
    t = np.geomspace(1e-6, 1.0, 200)
    for n in valences:
        ev = _evaluator(scheme, n)
        gauss = curvatures(ev.evaluate(demo_control_points(n), t, t))[0]
        ax.plot(t, gauss, label=f"valence {n}")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=0.1)
    ax.set_xlabel("t  (u = v = t)")
    ax.set_ylabel("Gaussian curvature")
    ax.set_title("Curvature approaching the extraordinary vertex")
    ax.legend()
    return fig


def baseline_error_figure(scheme: Scheme, valences: Sequence[int]):
    """Largest error of the numpy ``eig`` baseline against the certified data, per valence."""
    errors = []
    for n in valences:
        certified = _evaluator(scheme, n)
        errors.append(baseline_error(certified, numpy_baseline(scheme, n)[1], seed=n))
    fig = new_figure(6.5, 4.0)
    ax = fig.add_subplot(1, 1, 1)
    ax.semilogy(list(valences), errors, "o-")
    ax.axhline(np.finfo(float).eps, color="grey", linestyle=":", label="float64 epsilon")
    ax.set_xlabel("valence N")
    ax.set_ylabel("largest error of evaluated points")
    ax.set_title("numpy eig baseline against the certified data")
    ax.legend()
    return fig
