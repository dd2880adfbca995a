"""Figures of a mesh's extraordinary vertex: its 1-ring and its main components (``symdecomp inspect --figures``).

:func:`vertex_figure` draws, for one :class:`~symdecomp.analysis.inspection.VertexInspection`, two panels:

* the 1-ring seen from the normal, in the limit tangent plane (first axis along ``t_1``), with ``O``, the
  limit point and the tangent-plane (n-gon frequency 1) and hyperbolic (frequency 2) components of Eq. 11,
  each drawn around ``O``;
* the heights along the normal of the 1-ring's points, in polygon order (``a_0, b_0, a_1, ..`` on quads),
  with the elliptic (frequency 0: the planes of ``A^0`` and ``B^0``) and hyperbolic parts.

:func:`colored_mesh_figure` draws a whole mesh with a colour per vertex (each face the mean of its corners'
colours, at most :data:`MAX_DRAWN_FACES` faces: a larger mesh is drawn from an even sample of its faces), as
``symdecomp inspect --plot`` colours it.

:func:`png_bytes` renders a figure as PNG bytes without metadata that changes from run to run.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np

from symdecomp.algebra.polygons import decompose
from symdecomp.output.plotting._mpl import label_axes, new_figure

__all__ = ["vertex_figure", "colored_mesh_figure", "png_bytes", "equal_axes", "even_sample", "shaded_colors"]


def _ring_polygon(points: np.ndarray, n: int) -> np.ndarray:
    """The 1-ring polygon (Eq. 10 on quads: ``a_0, b_0, a_1, ..``) relative to ``O``, from the rows ``O, a.., b..``."""
    a, b = points[1 : n + 1], points[n + 1 :]
    return (np.stack([a, b], axis=1).reshape(-1, 3) if len(b) else a) - points[0]


def _frequency_part(polygon: np.ndarray, n: int, k: int) -> np.ndarray:
    """The sum of the components of the polygon whose n-gon frequency is ``k`` or ``n - k``."""
    d = decompose(polygon)
    N = len(polygon)
    representatives = sorted({min(j, N - j) for j in range(N) if j % n in (k % n, (n - k) % n)})
    return sum((d.pair_polygon(j) for j in representatives), np.zeros_like(polygon))


def vertex_figure(report, points):
    """The figure of one inspected vertex; ``points`` are the 1-ring's coordinates in the order of ``report.ring``."""
    points = np.asarray(points, dtype=float)
    n = report.valence
    polygon = _ring_polygon(points, n)
    normal = np.array(report.normal if report.normal is not None else (0.0, 0.0, 1.0))
    e1 = np.array(report.tangents[0]) - (np.array(report.tangents[0]) @ normal) * normal
    e1 = e1 / np.linalg.norm(e1) if np.linalg.norm(e1) > 0 else np.array([1.0, 0.0, 0.0])
    e2 = np.cross(normal, e1)
    fig = new_figure(10, 4.6)
    left, right = fig.subplots(1, 2)
    flat = lambda p: (p @ e1, p @ e2)  # noqa: E731
    closed = np.vstack([polygon, polygon[:1]])
    left.plot(*flat(closed), "-o", color="0.3", ms=3, label="1-ring")
    tangent = _frequency_part(polygon, n, 1)
    left.plot(*flat(np.vstack([tangent, tangent[:1]])), "-", color="C0", label="tangent plane (k = 1)")
    if report.hyperbolic_size is not None:
        hyper = _frequency_part(polygon, n, 2)
        left.plot(*flat(np.vstack([hyper, hyper[:1]])), "-", color="C3", label="hyperbolic (k = 2)")
    limit = np.array(report.limit) - points[0]
    left.plot([0], [0], "ks", ms=5, label="O")
    left.plot(*flat(limit), "C2*", ms=10, label="limit point")
    left.set_aspect("equal")
    label_axes(left, "along t_1", "along n x t_1", f"vertex {report.vertex}, valence {n}: in the tangent plane", loc="best")
    index = np.arange(len(polygon))
    right.plot(index, polygon @ normal, "-o", color="0.3", ms=3, label="height of the 1-ring")
    elliptic = _frequency_part(polygon, n, 0)
    right.plot(index, elliptic @ normal, "--", color="C1", label="elliptic (k = 0)")
    if report.hyperbolic_size is not None:
        right.plot(index, hyper @ normal, "-", color="C3", label="hyperbolic (k = 2)")
    right.axhline(0, color="k", lw=0.5)
    label_axes(right, "point of the 1-ring polygon", "height along the normal", "off the tangent plane through O", loc="best")
    return fig


#: Most faces :func:`colored_mesh_figure` draws (an even sample of a larger mesh's faces).
MAX_DRAWN_FACES = 20000


def even_sample(count: int, limit: int) -> int:
    """The step of an even sample of at most ``limit`` of ``count`` faces (every step-th face; 1: all of them).

    >>> even_sample(100, 100), even_sample(101, 100), even_sample(10 ** 6, 20000)
    (1, 2, 50)
    """
    return max(1, -(-count // limit))


def equal_axes(ax: Any, points: np.ndarray) -> None:
    """A 3-D axes around ``points`` with the same scale on the three axes (a cube), without axes drawn."""
    low, high = points.min(axis=0), points.max(axis=0)
    centre, half = (low + high) / 2, float((high - low).max()) / 2 or 1.0
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()


#: The direction the shading of :func:`shaded_colors` is lit from (a fixed light: the same picture every run).
LIGHT = np.array([1.0, -1.0, 2.0]) / np.sqrt(6.0)


def shaded_colors(polygons: list[np.ndarray], base: tuple[float, float, float]) -> np.ndarray:
    """An RGB colour per face: ``base`` darkened by the angle between the face's normal (Newell's) and :data:`LIGHT`,
    either side of the face lit alike (``0.35`` of ``base`` facing away, all of it facing the light)."""
    normals = np.array([np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0) for p in polygons]).reshape(-1, 3)
    lengths = np.linalg.norm(normals, axis=1)
    cosine = np.abs(normals @ LIGHT) / np.where(lengths > 0, lengths, 1.0)
    return np.outer(0.35 + 0.65 * cosine, np.asarray(base))


def colored_mesh_figure(points, faces, colors, title: str):
    """The mesh seen from a fixed direction, each face coloured by the mean of its vertices' ``colors`` (uint8 RGB)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    points = np.asarray(points, dtype=float)
    colors = np.asarray(colors, dtype=float) / 255
    step = even_sample(len(faces), MAX_DRAWN_FACES)
    chosen = faces[::step]
    polygons = [points[list(f)] for f in chosen]
    face_colors = [colors[list(f)].mean(axis=0) for f in chosen]
    fig = new_figure(7, 6)
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=face_colors, edgecolors=(0, 0, 0, 0.15), linewidths=0.2))
    equal_axes(ax, points)
    ax.set_title(title + ("" if step == 1 else f" (every {step}th face drawn)"))
    return fig


def png_bytes(fig, dpi: int = 100) -> bytes:
    """The figure as PNG bytes, the same on every run (no software or date entries)."""
    out = io.BytesIO()
    fig.savefig(out, format="png", dpi=dpi, metadata={"Software": None})
    return out.getvalue()
