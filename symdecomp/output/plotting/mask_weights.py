"""The figure of ``symdecomp masks N --plot``: each mask's weights on the points of the neighbourhood.

Every point sits where it sits in the regular picture of the neighbourhood: the centre ``O`` at the
origin, the point ``(s, u, v)`` of sector ``s`` (:meth:`~symdecomp.schemes.lattice.Lattice.ring_labels`:
``a_s = (s, 1, 0)``, ``b_s = (s, 1, 1)``) at ``u d_s + v d_(s+1)`` with ``d_s`` the unit vector at the
angle ``2 pi s/n``: the lattice coordinates of a sector laid on the fan of ``n`` equal angles. At a sharp vertex the
fan's rays are those of its sectors (:func:`sector_rays`: each sector's faces share its angle, pi between a crease's
sharp edges, pi for a boundary, pi/2 for a corner) and the point ``(s, u, v)`` sits at ``u d_s + v d_(s+1)`` on them
(:func:`fan_position`). A scheme of the zoo's neighbourhood (:func:`neighbourhood_places`) puts a vertex-centred
point where its label puts it in the regular picture, and a face-centred one (a dual scheme: the centre n-gon's
corners and the rings around it) at the centroid of the primal face it stands for. Each
weight is drawn by colour (a diverging map, symmetric about 0) and by marker area (its modulus), and
written beside its point (its decimal to four digits and, where given and short, its exact value; the
point's name too in a small neighbourhood; no text past :data:`LABELLED_POINTS` points), one panel per
mask. The weights are the ones the command prints (:class:`MaskPanel`, built by :mod:`symdecomp.cli.masks_cmd`
from the same results); nothing here computes a mask.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from symdecomp.output.plotting._mpl import new_figure

__all__ = ["MaskPoint", "MaskPanel", "point_position", "fan_position", "sector_rays", "neighbourhood_places",
           "mask_figure"]

#: Past this many points per panel the weights are shown by colour and size only (their text would overlap).
LABELLED_POINTS = 48
#: Past this many points per panel a weight's text goes without the point's name.
NAMED_POINTS = 21


@dataclass(frozen=True)
class MaskPoint:
    """One weight of a mask, on one point of the neighbourhood."""

    #: The point's name as the command prints it (``O``, ``a_2``, ``(1,1)_3``).
    name: str
    #: The point's label ``(sector, u, v)``; the centre is ``(0, 0, 0)``.
    label: tuple[int, int, int]
    #: The weight as the command prints it (a decimal string).
    text: str
    #: Its exact value, when the command has it and it is short (``None`` otherwise).
    exact: str | None = None
    #: Where it is drawn, when not at ``label`` on the interior fan (:func:`fan_position`, :func:`neighbourhood_places`).
    place: tuple[float, float] | None = None

    @property
    def weight(self) -> float:
        """The weight as a float (the printed decimal, rounded)."""
        return float(self.text)


@dataclass(frozen=True)
class MaskPanel:
    """One mask: its title and its weights."""

    #: What the mask is (``position``, ``tangent 1``, ...).
    title: str
    #: The weights, the centre first.
    points: tuple[MaskPoint, ...]


def point_position(label: tuple[int, int, int], n: int) -> tuple[float, float]:
    """Where the point ``(s, u, v)`` sits in the regular picture of a valence-``n`` fan: ``u d_s + v d_(s+1)``.

    >>> [tuple(round(c, 12) + 0.0 for c in point_position(p, 4)) for p in [(0, 0, 0), (0, 1, 0), (1, 1, 1), (3, 2, 1)]]
    [(0.0, 0.0), (1.0, 0.0), (-1.0, 1.0), (1.0, -2.0)]
    """
    s, u, v = label
    a, b = 2 * math.pi * s / n, 2 * math.pi * (s + 1) / n
    return u * math.cos(a) + v * math.cos(b), u * math.sin(a) + v * math.sin(b)


def fan_position(label: tuple[int, int, int], rays: Sequence[float]) -> tuple[float, float]:
    """Where the point ``(s, u, v)`` sits on a fan whose ray ``i`` is at the angle ``rays[i]``: ``u d_s + v d_(s+1)``
    (a closed fan's last sector ends on its first ray).

    >>> [tuple(round(c, 12) + 0.0 for c in fan_position(p, sector_rays((2,), closed=False))) for p in [(0, 1, 0), (1, 1, 1)]]
    [(1.0, 0.0), (-1.0, 1.0)]
    """
    s, u, v = label
    a, b = rays[s % len(rays)], rays[(s + 1) % len(rays)]
    return u * math.cos(a) + v * math.cos(b), u * math.sin(a) + v * math.sin(b)


def sector_rays(sectors: Sequence[int], closed: bool, span: float | None = None) -> list[float]:
    """The angles of a sharp vertex's rays ``(O, a_i)``: the faces of a sector share its angle, ``span`` (default pi:
    a boundary's half plane, a crease's two sides) on an open fan; a closed fan's sectors share the full turn.

    >>> [round(a / math.pi, 6) for a in sector_rays((1, 2), closed=True)], [round(a / math.pi, 6) for a in sector_rays((2,), False)]
    ([0.0, 1.0, 1.5], [0.0, 0.5, 1.0])
    """
    each = 2 * math.pi / len(sectors) if closed else (math.pi if span is None else span)
    rays, start = [], 0.0
    for k in sectors:
        rays += [start + each * i / k for i in range(k)]
        start += each
    return rays if closed else rays + [start]


def neighbourhood_places(nb: Any) -> dict[int, tuple[float, float]]:
    """Where each point of a :class:`~symdecomp.schemes.neighbourhood.Neighbourhood` sits in the regular picture, by its
    vertex id: its ring label's place (:func:`point_position`) around a centre vertex; around a centre face (the dual of
    the primal ring mesh one ring deeper), the centroid of the primal face it stands for."""
    if nb.centred == "vertex":
        labels = nb.lattice.ring_labels(nb.n, nb.depth)
        return {v: point_position(labels[v], nb.n) for v in nb.order}
    primal = nb.lattice.ring_mesh(nb.n, nb.depth + 1)
    corners = nb.lattice.ring_labels(nb.n, nb.depth + 1)
    places = {}
    for v in nb.order:
        xy = [point_position(corners[c], nb.n) for c in primal.faces[v]]
        places[v] = (sum(x for x, _ in xy) / len(xy), sum(y for _, y in xy) / len(xy))
    return places


def _note(point: MaskPoint) -> str:
    short = f"{point.weight:.4g}"
    return f"{short}\n= {point.exact}" if point.exact is not None and point.exact != short else short


def _panel(ax: Any, panel: MaskPanel, rays: Sequence[float], fig: Any) -> None:
    xy = [p.place if p.place is not None else fan_position(p.label, rays) for p in panel.points]
    weights = [p.weight for p in panel.points]
    top = max((abs(w) for w in weights), default=0.0) or 1.0
    reach = max(1.0, max(math.hypot(x, y) for x, y in xy))
    for angle in rays:  # the fan's rays, for orientation
        ax.plot([0.0, reach * math.cos(angle)], [0.0, reach * math.sin(angle)], color="0.8", lw=0.6, zorder=0)
    dots = ax.scatter([q[0] for q in xy], [q[1] for q in xy], c=weights, cmap="coolwarm", vmin=-top, vmax=top,
                      s=[12 + 220 * abs(w) / top for w in weights], edgecolors="0.3", linewidths=0.5, zorder=2)
    if len(panel.points) <= LABELLED_POINTS:
        named = len(panel.points) <= NAMED_POINTS
        for p, (x, y) in zip(panel.points, xy):
            text = f"{p.name}: {_note(p)}" if named else _note(p)
            ax.annotate(text, (x, y), xytext=(4, 4), textcoords="offset points", fontsize=6)
    fig.colorbar(dots, ax=ax, shrink=0.7, label="weight")
    ax.set_aspect("equal")
    ax.margins(0.25)
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(panel.title, fontsize=9)


def mask_figure(panels: list[MaskPanel], n: int, title: str, rays: Sequence[float] | None = None) -> Any:
    """One panel per mask, its weights on the points of the valence-``n`` neighbourhood (:func:`point_position`), or
    of the fan whose rays are at the angles ``rays`` (:func:`fan_position`; a point's ``place`` wins over both)."""
    fan = list(rays) if rays is not None else [2 * math.pi * s / n for s in range(n)]
    fig = new_figure(4.2 * len(panels), 4.6)
    for ax, panel in zip(fig.subplots(1, len(panels), squeeze=False)[0], panels):
        _panel(ax, panel, fan, fig)
    fig.suptitle(title, fontsize=10)
    return fig
