"""The figure of ``symdecomp charpoly N --plot``: the roots of the printed polynomial in the complex plane.

The roots are the certified balls of :func:`symdecomp.analysis.polynomial_roots.polynomial_roots`, found from the
exact polynomial the command prints (never from a matrix); each distinct root is drawn at its ball's midpoint, its
multiplicity as the marker's area (and written beside it when above 1). The unit circle and the circle of radius
``lambda_1`` (:attr:`~symdecomp.analysis.polynomial_roots.PolynomialRoots.lambda_1`: the largest modulus left once
the root 1 is taken away once) are drawn.
"""

from __future__ import annotations

import math
from typing import Any

from symdecomp.output.plotting._mpl import new_figure

__all__ = ["root_points", "roots_figure"]


def root_points(roots: Any) -> list[tuple[complex, int]]:
    """``(midpoint, multiplicity)`` of each distinct root of a ``PolynomialRoots``: the points the figure draws."""
    return [(complex(float(z.real.mid()), float(z.imag.mid())), m) for z, m in roots.roots]


def _circle(ax: Any, radius: float, **style: Any) -> None:
    t = [2 * math.pi * k / 360 for k in range(361)]
    ax.plot([radius * math.cos(a) for a in t], [radius * math.sin(a) for a in t], **style)


def roots_figure(roots: Any, title: str) -> Any:
    """The roots of a ``PolynomialRoots`` in the complex plane (marker area: multiplicity), ``|z| = 1`` and
    ``|z| = lambda_1``."""
    fig = new_figure(6.0, 6.0)
    ax = fig.subplots()
    _circle(ax, 1.0, color="0.5", lw=0.8, label="|z| = 1")
    if roots.lambda_1 is not None:
        r = float(roots.lambda_1)
        _circle(ax, r, color="C2", lw=0.8, ls="--", label=f"|z| = lambda_1 = {r:.6g}")
    ax.axhline(0.0, color="0.8", lw=0.5)
    ax.axvline(0.0, color="0.8", lw=0.5)
    points = root_points(roots)
    ax.scatter([z.real for z, _ in points], [z.imag for z, _ in points], s=[18 * m for _, m in points], color="C0",
               zorder=3, label=f"{roots.degree} roots, {len(points)} distinct (area: multiplicity)")
    for z, m in points:
        if m > 1:
            ax.annotate(f"x{m}", (z.real, z.imag), xytext=(4, 4), textcoords="offset points", fontsize=7)
    ax.set_aspect("equal")
    ax.set_xlabel("Re")
    ax.set_ylabel("Im")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    return fig
