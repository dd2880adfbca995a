"""The figure of ``symdecomp c1 --plot``: the characteristic map at a few of the tested vertices, and the certified
bounds of its Jacobian and of the spectral gap at every one of them.

The panels are drawn from the results the command prints (each vertex's
:meth:`~symdecomp.verify.c1.C1Result.as_json`): the verdicts in the titles and the bounds are those
of the text. The maps themselves are the ring of :func:`~symdecomp.output.plotting.characteristic.ring_curves`
at an interior vertex and :func:`~symdecomp.output.plotting.boundary.sector_characteristic_map` at a
boundary, corner, crease or dart vertex.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable

import numpy as np

from symdecomp.errors import SymdecompError
from symdecomp.output.plotting._mpl import new_figure
from symdecomp.output.plotting.boundary import sector_characteristic_map, sector_map_panel
from symdecomp.output.plotting.characteristic import ring_curves
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.stencils import StencilScheme

__all__ = ["MAX_MAPS", "VERDICT_COLOURS", "shown", "c1_figure"]

#: The characteristic maps drawn at most (the first, the last and ones between); the bounds are drawn for every vertex.
MAX_MAPS = 3

#: The colour of each verdict.
VERDICT_COLOURS = {"c1": "C2", "not-c1": "C3", "undecided": "C1"}


def shown(count: int, limit: int = MAX_MAPS) -> list[int]:
    """Indices of at most ``limit`` of ``count`` items, evenly spread, the first and the last among them.

    >>> shown(10), shown(2), shown(1)
    ([0, 4, 9], [0, 1], [0])
    """
    if count <= limit:
        return list(range(count))
    return sorted({round(i * (count - 1) / (limit - 1)) for i in range(limit)})


def _ring_panel(ax, scheme: Scheme, row: dict) -> None:
    _curves_panel(ax, ring_curves(scheme, row["n"], samples=5))


def _curves_panel(ax, curves: dict) -> None:
    """A ring's curves (:func:`~symdecomp.output.plotting.characteristic.ring_curves`' keys): lines, inner boundary, rays."""
    for z in curves["lines"]:
        ax.plot(z.real, z.imag, color="0.6", lw=0.5)
    for z in curves["inner"]:
        ax.plot(z.real, z.imag, color="C0", lw=1.8)
    for z in curves["rays"]:
        ax.plot(z.real, z.imag, color="C3", lw=1.2, ls="--")
    ax.plot([0], [0], "k+")
    ax.set_aspect("equal")
    ax.set_xlabel("x (Re of the eigenvector)")
    ax.set_ylabel("y (Im)")


def _map_panel(ax, scheme: Scheme | StencilScheme, row: dict, vertex, maps: Callable[[int], dict] | None = None) -> None:
    """The characteristic map of one tested vertex, titled with its verdict; a line saying why where there is none."""
    name = row.get("vertex") or f"n = {row['n']}"
    title = f"{name}: {row['verdict']}"
    ax.set_title(title, fontsize=9, color=VERDICT_COLOURS.get(row["verdict"], "k"))
    # the spectral conditions held: an interior vertex's row names the subdominant frequency, a sharp one its lambda
    if maps is None and row.get("frequency" if vertex is None else "lambda") is None:
        _note(ax, row["reason"])
        return
    try:
        if maps is not None:  # the map's own curves (a scheme of the zoo): what they are goes under the panel
            curves = maps(row["n"])
            _curves_panel(ax, curves)
            ax.set_xlabel(f"x (Re of the eigenvector)\n{textwrap.fill(curves['drawn'], 40)}", fontsize=8)
        elif vertex is None:
            _ring_panel(ax, scheme, row)  # type: ignore[arg-type]  # maps is given for a scheme of the zoo
        else:
            sector_map_panel(ax, sector_characteristic_map(scheme, vertex))  # type: ignore[arg-type]  # as above
    except SymdecompError as exc:  # the spectral conditions fail: there is no map to draw
        ax.clear()
        ax.set_title(title, fontsize=9, color=VERDICT_COLOURS.get(row["verdict"], "k"))
        _note(ax, str(exc))


def _note(ax, why: str) -> None:
    """In place of a map: why there is none."""
    ax.text(0.5, 0.5, "no characteristic map:\n" + textwrap.fill(why[:200], 40), ha="center", va="center",
            transform=ax.transAxes, fontsize=7)
    ax.set_axis_off()


def _bounds_panel(ax, rows: list[dict], labels: list[str]) -> None:
    """The certified lower bound of |J| and the spectral gap at each vertex, coloured by verdict."""
    x = np.arange(len(rows))
    for key, marker, name in (("jacobian_lower_bound", "o", "|J| >= (certified)"), ("gap", "s", "spectral gap >=")):
        points = [(i, r[key], VERDICT_COLOURS.get(r["verdict"], "k")) for i, r in zip(x, rows) if r.get(key)]
        if points:
            ax.scatter([p[0] for p in points], [p[1] for p in points], c=[p[2] for p in points], marker=marker, s=18,
                       label=name)
            ax.plot([p[0] for p in points], [p[1] for p in points], color="0.7", lw=0.6, zorder=0)
    if ax.has_data():
        ax.set_yscale("log")
        ax.legend(fontsize=8)
    else:  # e.g. a scheme of the zoo whose test has no route: say so rather than leave an empty frame
        ax.text(0.5, 0.5, "no certified bounds: the test gave none (see each valence's reason)", ha="center", va="center",
                transform=ax.transAxes, fontsize=8)
    step = max(1, len(rows) // 16)
    ax.set_xticks(x[::step], [labels[i] for i in x[::step]], fontsize=8, rotation=30 if len(labels[0]) > 4 else 0)
    ax.set_ylabel("certified lower bound")
    ax.grid(alpha=0.3)


def c1_figure(scheme: Scheme | StencilScheme, rows: list[dict], vertices: list | None = None, *,
              maps: Callable[[int], dict] | None = None):
    """The figure of ``c1 --plot``: at most :data:`MAX_MAPS` characteristic maps over the bounds at every vertex.

    ``rows``: each tested vertex's ``as_json()``, in order; ``vertices``: the boundary, corner, crease or dart
    vertices (:class:`~symdecomp.schemes.sector.SharpVertex`) the rows are about, or ``None`` for interior valences.
    ``maps(n)``: the curves of the map at ``n`` with the key ``"drawn"`` saying what they are, for a scheme of the
    zoo (:func:`~symdecomp.output.plotting.zoo_maps.zoo_map_curves`), drawn whatever the verdict's route; a
    :class:`~symdecomp.errors.SymdecompError` it raises is the line in place of the map.
    """
    picked = shown(len(rows))
    fig = new_figure(3.7 * max(len(picked), 2), 7.2)
    grid = fig.add_gridspec(2, len(picked), height_ratios=(3, 2))
    for column, i in enumerate(picked):
        _map_panel(fig.add_subplot(grid[0, column]), scheme, rows[i], None if vertices is None else vertices[i], maps)
    labels = [r.get("vertex") or str(r["n"]) for r in rows]
    _bounds_panel(fig.add_subplot(grid[1, :]), rows, labels)
    if maps is not None:
        fig.suptitle(f"{scheme.name}: C1 of a scheme of the zoo; the characteristic map (the hole's boundary blue),\nand "
                     "the certified bounds where its test gives them", fontsize=10)
        return fig
    what = "Reif's test" if vertices is None else "Zorin's conditions"
    fig.suptitle(f"{scheme.name}: {what}; the characteristic map (inner ring boundary blue,\nsector boundaries or sharp "
                 "edges), and its certified bounds", fontsize=10)  # two lines: one runs past a one-map figure
    return fig
