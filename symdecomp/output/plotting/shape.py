"""Figures of the shape at an extraordinary vertex: second-order height fields over the characteristic map, and the shape chart.

The numbers come from :mod:`symdecomp.verify.shape` (Bezier nets of sector 0's sub-patches as Arb
balls; the figures use their midpoints) and the rotational symmetry: the characteristic map of
sector ``s`` is sector 0's times ``omega^s``; the elliptic height is the same in every sector, the
hyperbolic one on sector ``s`` is ``cos(theta_s) h_2c + sin(theta_s) h_2s`` with
``theta_s = t - 4 pi s / n``. The sign of ``L N - M^2`` is sampled from the nets the certificate
bounds; its zero line (where the Gaussian curvature changes sign) is drawn in black.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> ring = height_field_samples(catmull_clark(), 4, "elliptic", samples=3)
>>> d = ring["h"] - 4 * (ring["x"] ** 2 + ring["y"] ** 2)   # regular: h = |2 chi|^2 + constant (level-1 scale)
>>> bool(d.max() - d.min() < 1e-12), bool((ring["k"] > 0).all())
(True, True)
"""

from __future__ import annotations

import textwrap
from math import comb

import flint
import numpy as np

from symdecomp.algebra.triangle_bezier import bezier_value
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.output.plotting._mpl import new_figure
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import check_int, check_valence
from symdecomp.verify.curvature import combine, curvature_gram, patch_algebra
from symdecomp.verify.shape import ShapeChart, classify_shape, height_fields

__all__ = ["height_field_samples", "height_field_figure", "shape_chart_figure", "KIND_COLOURS"]

#: The colour of each verdict in the figures.
KIND_COLOURS = {"elliptic": "#3b75af", "hyperbolic": "#c03d3e", "hybrid": "#e3a33b", "undecided": "#b0b0b0"}


def _floats(net) -> np.ndarray:
    return np.array([[float(c.mid()) for c in row] for row in net]) if isinstance(net[0], list) else np.array([float(c.mid()) for c in net])


def _evaluate(net, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """A Bezier net (tensor or triangular, any degree) at the parameter points ``(u, v)``."""
    z = _floats(net)
    if z.ndim == 2:
        p, q = z.shape[0] - 1, z.shape[1] - 1
        bu = np.array([comb(p, i) * u**i * (1 - u) ** (p - i) for i in range(p + 1)])
        bv = np.array([comb(q, k) * v**k * (1 - v) ** (q - k) for k in range(q + 1)])
        return np.einsum("ik,ip,kp->p", z, bu, bv)
    degree = next(d for d in range(64) if (d + 1) * (d + 2) // 2 == len(z))
    return bezier_value(list(z), degree, u, v)


def _parameters(tensor: bool, samples: int) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, 1.0, samples)
    if tensor:
        u, v = np.meshgrid(t, t, indexing="ij")
        return u.ravel(), v.ravel()
    pts = [(a, b) for a in t for b in t if a + b <= 1 + 1e-12]
    return np.array([a for a, _ in pts]), np.array([b for _, b in pts])


def height_field_samples(scheme: Scheme, n: int, kind: str = "elliptic", *, angle=0, samples: int = 9) -> dict:
    """``{'x', 'y', 'h', 'k', ...}``: the ring of every sector, sampled: characteristic map, height, and ``L N - M^2``.

    The arrays run patch by patch (``patch_size`` points each, at the parameters ``u``, ``v`` of one patch).

    ``kind``: ``'elliptic'`` (frequency 0) or ``'hyperbolic'`` (frequency 2, at ``angle`` ``t`` in units of pi,
    a float for the figure). Raises :class:`~symdecomp.errors.NotApplicableError` where the field is not
    determined (see :func:`~symdecomp.verify.shape.height_fields`).
    """
    n = check_valence(n)
    samples = check_int(samples, "samples", minimum=2, maximum=64)
    if kind not in ("elliptic", "hyperbolic"):
        raise InvalidInputError(f"kind must be 'elliptic' or 'hyperbolic', got {kind!r}")
    fields = height_fields(scheme, n, elliptic=kind == "elliptic", hyperbolic=kind == "hyperbolic")
    alg = patch_algebra(scheme.lattice)
    u, v = _parameters(isinstance(fields.chi[0][0][0], list), samples)
    xs, ys, hs, ks = [], [], [], []
    for s in range(n):
        theta = np.pi * (float(angle) - 4 * s / n)
        weights = [1.0] if kind == "elliptic" else [np.cos(theta), np.sin(theta)]
        rotation = np.exp(2j * np.pi * s / n)
        for (X, Y), heights in zip(fields.chi, fields.heights):
            z = rotation * (_evaluate(X, u, v) + 1j * _evaluate(Y, u, v))
            xs.append(z.real)
            ys.append(z.imag)
            hs.append(sum(w * _evaluate(h, u, v) for w, h in zip(weights, heights)))
            gram, _ = curvature_gram(alg, X, Y, list(heights))
            ks.append(_evaluate(combine(gram, [flint.arb(w) for w in weights]), u, v))
    return {"x": np.concatenate(xs), "y": np.concatenate(ys), "h": np.concatenate(hs), "k": np.concatenate(ks), "patch_size": len(u),
            "u": u, "v": v}


def _panel(ax, scheme: Scheme, n: int, kind: str, samples: int) -> None:
    try:
        ring = height_field_samples(scheme, n, kind, samples=samples)
    except NotApplicableError as exc:
        ax.set_title(f"n = {n}: not determined", fontsize=9)
        ax.text(0.5, 0.5, textwrap.fill(str(exc), 42), ha="center", va="center", transform=ax.transAxes, fontsize=6)
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_xlabel("chi_1")
        ax.set_ylabel("chi_2")
        return
    verdict = classify_shape(scheme, n, elliptic=int(kind == "elliptic"), hyperbolic=int(kind == "hyperbolic"))
    from matplotlib.tri import Triangulation

    triangles = Triangulation(ring["u"], ring["v"]).triangles  # the patch's parameter domain is convex: no filled hole
    levels = np.linspace(ring["h"].min(), ring["h"].max(), 15)
    size = ring["patch_size"]
    for start in range(0, len(ring["x"]), size):
        part = slice(start, start + size)
        mesh = Triangulation(ring["x"][part], ring["y"][part], triangles)
        ax.tricontourf(mesh, ring["h"][part], levels=levels, cmap="viridis")
        k = ring["k"][part]
        if k.min() < 0 < k.max():
            ax.tricontour(mesh, k, levels=[0.0], colors="k", linewidths=1.2)
    ax.plot([0], [0], "w+")
    ax.set_aspect("equal")
    ax.set_title(f"n = {n}: {verdict.kind} (mu = {verdict.mu[0]:.4f})", fontsize=9, color=KIND_COLOURS[verdict.kind])
    ax.set_xlabel("chi_1")
    ax.set_ylabel("chi_2")


def height_field_figure(scheme: Scheme, valences=(3, 5, 8, 16), kind: str = "elliptic", *, samples: int = 9):
    """One panel per valence: the height field (colour) over the ring of the characteristic map, K = 0 in black.

    The title carries the certified verdict of :func:`~symdecomp.verify.shape.classify_shape` for the pure input.
    """
    valences = [check_valence(n) for n in valences]
    fig = new_figure(3.2 * len(valences), 3.5)
    axes = fig.subplots(1, len(valences), squeeze=False)[0]
    for ax, n in zip(axes, valences):
        _panel(ax, scheme, n, kind, samples)
    fig.suptitle(f"{scheme.name}: the {kind} second-order height field over the characteristic ring (level 1)")
    return fig


def shape_chart_figure(charts):
    """One panel per :class:`~symdecomp.verify.shape.ShapeChart`: the verdict for each mixture ``r`` (up) and angle ``t`` (across)."""
    charts = list(charts)
    if not charts or not all(isinstance(c, ShapeChart) for c in charts):
        raise InvalidInputError("charts must be a non-empty sequence of ShapeChart (symdecomp.verify.shape.shape_chart)")
    fig = new_figure(3.3 * len(charts) + 1.2, 3.9)
    axes = fig.subplots(1, len(charts), squeeze=False)[0]
    for ax, chart in zip(axes, charts):
        for i, row in enumerate(chart.results):
            for k, result in enumerate(row):
                ax.add_patch(_rectangle(k, i, KIND_COLOURS[result.kind]))
        ax.set_xlim(0, len(chart.angles))
        ax.set_ylim(0, len(chart.ratios))
        ax.set_xticks([k + 0.5 for k in range(len(chart.angles))], [str(t) for t in chart.angles], fontsize=7)
        ax.set_yticks([i + 0.5 for i in range(len(chart.ratios))], [str(r) for r in chart.ratios], fontsize=7)
        toward = {0: "r = 0 (elliptic)", 2: "r = 1 (hyperbolic)", None: "neither end"}[chart.dominant]
        ax.set_title(f"{chart.scheme}, n = {chart.n}: mu_0 = {chart.mu[0]:.4f}, mu_2 = {chart.mu[1]:.4f}\nrings move towards {toward}",
                     fontsize=8)
        ax.set_xlabel("angle t (units of pi)")
        ax.set_ylabel("r: h = (1 - r) h_0 + r h_2(t)")
    handles = [_rectangle(0, 0, colour) for colour in KIND_COLOURS.values()]
    fig.legend(handles, list(KIND_COLOURS), loc="outside right center", fontsize=8)
    fig.suptitle("Shape chart: the central surface's verdict for each mixture of the elliptic and hyperbolic inputs")
    return fig


def _rectangle(x: float, y: float, colour: str):
    from matplotlib.patches import Rectangle

    return Rectangle((x, y), 1, 1, facecolor=colour, edgecolor="white")
