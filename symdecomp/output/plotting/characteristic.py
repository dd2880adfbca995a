"""The characteristic map of Reif's test: the ring's image, sector by sector (issue: certified C1).

The numbers come from :mod:`symdecomp.verify.c1` (the Bezier nets of sector 0's three bicubic
sub-patches, or Loop's three quartic triangular ones, as Arb balls; the figure uses their
midpoints) and the rotational symmetry: the ring of sector ``s`` is that of sector 0 times
``omega^(j s)``.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> curves = ring_curves(catmull_clark(), 4, samples=3)
>>> [round(abs(complex(curves["inner"][0][0])), 6)]   # a_0 at level 1: lambda = 1/2
[0.5]
>>> from symdecomp.schemes.loop import loop
>>> [round(abs(complex(ring_curves(loop(), 6, samples=3)["inner"][0][0])), 6)]   # Loop, regular: lambda = 1/2
[0.5]
"""

from __future__ import annotations

import numpy as np

from symdecomp.algebra.triangle_bezier import bezier_value
from symdecomp.output.plotting._mpl import new_figure
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import check_valence
from symdecomp.verify.c1 import c1_test, characteristic_nets
from symdecomp.verify.result import C1Verdict

__all__ = ["ring_curves", "bicubic_points", "characteristic_map_figure"]


def _bernstein(degree: int, t: np.ndarray) -> np.ndarray:
    from math import comb

    return np.array([comb(degree, i) * t**i * (1 - t) ** (degree - i) for i in range(degree + 1)])


def bicubic_points(z: np.ndarray, s: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Complex points of the bicubic Bezier patch with the 4 x 4 complex control points ``z`` on the grid ``s x t`` (rows: s)."""
    return _bernstein(3, s).T @ z @ _bernstein(3, t)


def _patch(net_x, net_y, s: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Complex points of a bicubic Bezier patch (nets of Arb balls) on the grid ``s x t`` (rows: s)."""
    z = np.array([[complex(float(x.mid()), float(y.mid())) for x, y in zip(rx, ry)] for rx, ry in zip(net_x, net_y)])
    return bicubic_points(z, s, t)


def _triangle(net_x, net_y, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Complex points of a quartic triangular Bezier patch at the parameters ``(u, v)``."""
    z = [complex(float(x.mid()), float(y.mid())) for x, y in zip(net_x, net_y)]
    return bezier_value(z, 4, u, v)


def _triangle_curves(nets, rotation: complex, n: int, t: np.ndarray, grid: np.ndarray) -> dict:
    """:func:`ring_curves` for Loop's sub-patches: lines of constant u, v and w = 1 - u - v in each triangle."""
    lines, inner, rays = [], [], []
    for sector in range(n):
        r = rotation**sector
        for p, (x, y) in enumerate(nets):
            for g in grid[:-1]:
                s = (1 - g) * t
                lines += [r * _triangle(x, y, g + 0 * s, s), r * _triangle(x, y, s, g + 0 * s), r * _triangle(x, y, s, 1 - g - s)]
            if p == 1:  # the middle triangle: its edge u = 0 runs from the level-1 point (1, 0) to (0, 1)
                inner.append(r * _triangle(x, y, 0 * t, t))
            if p == 0:  # the first triangle: its edge v = 0 runs from (1, 0) to (2, 0), on the edge ray
                rays.append(r * _triangle(x, y, t, 0 * t))
    return {"lines": lines, "inner": inner, "rays": rays}


def ring_curves(scheme: Scheme, n: int, *, samples: int = 9) -> dict:
    """Iso-parameter lines of the ring (all sectors), its inner boundary, and the sector boundaries, as complex arrays."""
    n = check_valence(n)
    nets, vec = characteristic_nets(scheme, n)
    rotation = np.exp(2j * np.pi * vec.j / n)
    t = np.linspace(0.0, 1.0, 4 * samples + 1)
    grid = np.linspace(0.0, 1.0, samples)
    return scheme.lattice.select(_CURVES, "the characteristic map's curves")(nets, rotation, n, t, grid)


def _quad_curves(nets, rotation: complex, n: int, t: np.ndarray, grid: np.ndarray) -> dict:
    lines, inner, rays = [], [], []
    for sector in range(n):
        r = rotation**sector
        for p, (x, y) in enumerate(nets):
            for g in grid:
                lines.append(r * _patch(x, y, np.array([g]), t)[0])
                lines.append(r * _patch(x, y, t, np.array([g]))[:, 0])
            if p == 0:  # face (1, 0): its edge u = 1 is the inner boundary, v = 0 the sector boundary
                inner.append(r * _patch(x, y, np.array([0.0]), t)[0])
                rays.append(r * _patch(x, y, t, np.array([0.0]))[:, 0])
            if p == 2:  # face (0, 1): its edge v = 1 is the inner boundary
                inner.append(r * _patch(x, y, t, np.array([0.0]))[:, 0])
    return {"lines": lines, "inner": inner, "rays": rays}


#: The ring's curves from the sub-patch nets of :func:`~symdecomp.verify.c1.characteristic_nets`, per lattice.
_CURVES = {BICUBIC: _quad_curves, BOX_SPLINE: _triangle_curves}


def characteristic_map_figure(scheme: Scheme, valences=(3, 5, 16), *, samples: int = 7):
    """One panel per valence: the ring's image, its inner boundary (thick) and the sector boundaries (dashed).

    Each panel's title carries the certified verdict of :func:`~symdecomp.verify.c1.c1_test`.
    """
    valences = [check_valence(n) for n in valences]
    fig = new_figure(3.6 * len(valences), 3.8)
    axes = fig.subplots(1, len(valences), squeeze=False)[0]
    for ax, n in zip(axes, valences):
        result = c1_test(scheme, n)
        if result.spectral.status is not C1Verdict.C1:
            ax.set_title(f"n = {n}: {result.verdict}")
            ax.text(0.5, 0.5, "no characteristic map:\n" + result.reason[:60], ha="center", va="center", transform=ax.transAxes, fontsize=7)
            ax.set_xlabel("x")
            ax.set_ylabel("y")
            continue
        curves = ring_curves(scheme, n, samples=samples)
        for z in curves["lines"]:
            ax.plot(z.real, z.imag, color="0.6", lw=0.5)
        for z in curves["inner"]:
            ax.plot(z.real, z.imag, color="C0", lw=1.8)
        for z in curves["rays"]:
            ax.plot(z.real, z.imag, color="C3", lw=1.2, ls="--")
        ax.plot([0], [0], "k+")
        ax.set_aspect("equal")
        ax.set_title(f"n = {n}: {result.verdict} (winding {result.winding_number})", fontsize=9)
        ax.set_xlabel("x (Re of the eigenvector)")
        ax.set_ylabel("y (Im)")
    fig.suptitle(f"Characteristic map of {scheme.name}: the ring at level 1, sector boundaries dashed")
    return fig
