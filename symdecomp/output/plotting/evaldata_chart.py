"""The figure of ``symdecomp evaldata --plot``: the eigenvalues of the written data, one line per rank.

At each valence ``n`` (or each ``K`` of a sharp vertex) the distinct eigenvalues the file holds are ordered by
modulus, largest first (:func:`eigenvalue_ranks`: 1, then ``lambda_1``, then ``mu``, ...), and the ``r``-th of each is
joined across the valences into one line: how each rank of the spectrum moves with ``n``. A complex eigenvalue is
drawn by its modulus (the axis says so when there is one). The values are the ones the command wrote
(:mod:`symdecomp.cli.evaldata_plot` gathers them); nothing here computes a spectrum.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from symdecomp.output.plotting._mpl import label_axes, new_figure

__all__ = ["RANKS", "eigenvalue_ranks", "evaldata_figure"]

#: Ranks drawn (the largest distinct eigenvalues by modulus).
RANKS = 6


def eigenvalue_ranks(values: Sequence[complex]) -> list[complex]:
    """The distinct values, by modulus, largest first (ties: the larger real part, then imaginary part, first).

    >>> eigenvalue_ranks([0.25, 1.0, 0.5, 0.25, -0.5, 1.0])
    [1.0, 0.5, -0.5, 0.25]
    """
    distinct = list(dict.fromkeys(values))
    return sorted(distinct, key=lambda z: (-abs(z), -complex(z).real, -complex(z).imag))


def _name(rank: int) -> str:
    return ("1st", "2nd", "3rd")[rank] if rank < 3 else f"{rank + 1}th"


def evaldata_figure(columns: Mapping[int, Sequence[complex] | None], xlabel: str, title: str) -> Any:
    """One line per rank (:data:`RANKS` of them): the ``r``-th largest distinct eigenvalue at each ``x`` of ``columns``
    (``None``: no eigenvalues written there, left out)."""
    ranked = {x: eigenvalue_ranks(v) for x, v in columns.items() if v is not None}
    complex_values = any(complex(z).imag != 0 for v in ranked.values() for z in v)
    fig = new_figure(7.0, 4.5)
    ax = fig.subplots()
    for r in range(RANKS):
        xs = [x for x in ranked if len(ranked[x]) > r]
        if xs:
            ys = [abs(ranked[x][r]) if complex_values else complex(ranked[x][r]).real for x in xs]
            ax.plot(xs, ys, "o-", ms=3, lw=1, label=f"{_name(r)} largest")
    missing = [x for x, v in columns.items() if v is None]
    note = f"\n(no decomposition written at {', '.join(map(str, missing))}: not drawn there)" if missing else ""
    label_axes(ax, xlabel, "|eigenvalue|" if complex_values else "eigenvalue", title + note, loc="best")
    ax.title.set_fontsize(10)
    from matplotlib.ticker import MaxNLocator

    ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # valences and face counts
    return fig
