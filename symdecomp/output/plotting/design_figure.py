"""The control net ``symdecomp design --plot`` draws: the 2-ring it wrote, its centre, and the limit frame it reports.

:func:`design_figure` takes the net the command writes (its doubles), the centre vertex and its 1-ring, and the
achieved values the command prints (limit position, unit normal, tangents), and draws in 3-D from the fixed view
:data:`~symdecomp.output.plotting.refine_figure.VIEW`: the faces of the net that have a corner in the 1-ring (the
2-ring; for a redesign, the part of the mesh around the vertex) as a light shaded net, the centre ``O``, the 1-ring's
points, the limit point, and from it the normal and the two tangent directions, each as a segment of length
:data:`ARROW` times the largest side of the box around the drawn net; the points and segments are drawn over the
faces. Nothing is recomputed: what is drawn is what the command reports (the tangents are drawn as directions; their
lengths depend on the masks' scale).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from symdecomp.output.plotting._mpl import new_figure
from symdecomp.output.plotting.meshes import equal_axes, shaded_colors
from symdecomp.output.plotting.refine_figure import VIEW

__all__ = ["ARROW", "design_figure"]

#: The length of the drawn normal and tangents, in the largest side of the box around the drawn net.
ARROW = 0.3

#: The colour of the net's faces, before shading.
FACE_COLOUR = (0.85, 0.85, 0.8)


def _segment(ax: Any, start: np.ndarray, direction: Sequence[float], length: float, **style: Any) -> None:
    """A segment from ``start`` along the unit vector of ``direction``, ``length`` long, ending in a dot."""
    d = np.asarray(direction, dtype=float)
    if not np.linalg.norm(d):
        return  # a zero tangent has no direction to draw
    end = start + length * d / np.linalg.norm(d)
    ax.plot(*np.stack([start, end]).T, lw=2, zorder=3, **style)
    ax.plot(*end.reshape(3, 1), "o", ms=3, zorder=3, color=style.get("color"))


def design_figure(points: Any, faces: Sequence[Sequence[int]], ring: Sequence[int], position: Sequence[float],
                  normal: Sequence[float] | None, tangents: Sequence[Sequence[float]], title: str) -> Any:
    """The net (``points``, ``faces``) around ``O = ring[0]`` with the limit point, normal and tangent directions."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    points = np.asarray(points, dtype=float).reshape(-1, 3)
    around = set(ring)
    polygons = [points[list(f)] for f in faces if around.intersection(f)]
    corners = np.vstack(polygons)
    centre, one_ring = points[ring[0]], points[list(ring[1:])]
    length = ARROW * float((corners.max(axis=0) - corners.min(axis=0)).max())
    fig = new_figure(7, 6)
    ax = fig.add_subplot(projection="3d", computed_zorder=False)  # the frame over the faces, whatever the depth
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=shaded_colors(polygons, FACE_COLOUR), alpha=0.5,
                                         edgecolors=(0.3, 0.3, 0.3, 0.8), linewidths=0.6, zorder=1))
    ax.plot(*one_ring.T, "o", ms=4, color="0.3", zorder=2, label="1-ring")
    ax.plot(*centre.reshape(3, 1), "ks", ms=6, zorder=2, label="O (centre vertex)")
    limit = np.asarray(position, dtype=float)
    ax.plot(*limit.reshape(3, 1), "*", ms=12, color="C2", zorder=4, label="limit point")
    if normal is not None:
        _segment(ax, limit, normal, length, color="C3", label="limit normal")
    for k, (tangent, colour) in enumerate(zip(tangents, ("C0", "C1")), 1):
        _segment(ax, limit, tangent, length, color=colour, label=f"tangent t{k} (direction)")
    equal_axes(ax, np.vstack([corners, limit]))
    ax.view_init(*VIEW)
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title(title + ("" if normal is not None else "\n(no normal: the tangents are parallel)"), fontsize=10)
    return fig
