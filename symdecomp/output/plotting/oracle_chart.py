"""The figure of ``symdecomp oracle --plot``: the toolkit's predictions against OpenSubdiv, level by level.

One panel per ``"limit"`` prediction (limit position, the shrink rate of each frequency, the ratios of Eq. 39 and 44):
its disagreement at each level compared, on a log axis, one line per valence, beside a dashed reference line of the
predicted rate (``rate^level`` from the first level drawn: the slope the disagreement should follow until it meets
rounding). One last panel the ``"exact"`` rows (the one-step matrix, 1-ring locality, the limit mask, ...): each
valence's disagreement in units of double precision's epsilon (``2^-52``), on a symmetric-log axis so that an exact 0
is drawn at 0, with the tolerance of an exact row
(:data:`~symdecomp.verify.comparisons.EXACT_TOLERANCE`) as a line. The numbers are the comparisons the command
printed (:class:`~symdecomp.verify.comparisons.ValenceComparison`, its per-level ``errors``); nothing here runs
OpenSubdiv or recomputes a prediction.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from typing import Any

from symdecomp.output.plotting._mpl import label_axes, new_figure
from symdecomp.verify.comparisons import EXACT_TOLERANCE, ValenceComparison, error_levels

__all__ = ["EPSILON", "oracle_figure"]

#: Double precision's machine epsilon, ``2^-52``: the unit of the exact rows' panel.
EPSILON = sys.float_info.epsilon

#: Panels per row of the figure.
COLUMNS = 3


def _limit_panel(ax: Any, name: str, results: Sequence[ValenceComparison]) -> None:
    for i, r in enumerate(results):
        for p in r.predictions:
            if p.name != name or p.kind != "limit" or not p.errors or p.rate is None:
                continue
            x = error_levels(p.errors, r.levels)  # the levels --json gives as "per_level"
            colour = f"C{i % 10}"
            ax.plot(x, list(p.errors), "o-", color=colour, ms=3, lw=1, label=f"n = {r.n}")
            ax.plot(x, [p.errors[0] * p.rate ** (k - x[0]) for k in x], "--", color=colour, lw=0.8,
                    label=f"rate {p.rate:.4f}")
    ax.set_yscale("log")
    label_axes(ax, "level", "largest disagreement", name, ncol=2)


def _exact_panel(ax: Any, results: Sequence[ValenceComparison]) -> None:
    names = list(dict.fromkeys(p.name for r in results for p in r.predictions if p.kind == "exact"))
    width = 0.8 / max(1, len(names))
    for j, name in enumerate(names):
        rows = [(r.n, p.disagreement) for r in results for p in r.predictions if p.name == name and p.kind == "exact"]
        ax.bar([n - 0.4 + width * (j + 0.5) for n, _ in rows], [d / EPSILON for _, d in rows], width, color=f"C{j % 10}",
               label=name)
    ax.axhline(EXACT_TOLERANCE / EPSILON, color="C3", ls="--", lw=0.8, label=f"tolerance {EXACT_TOLERANCE:.0e}")
    ax.set_yscale("symlog", linthresh=1.0)
    ax.set_xticks([r.n for r in results])
    label_axes(ax, "valence n", "disagreement / epsilon (2^-52)", "exact rows, against double precision")


def oracle_figure(results: Sequence[ValenceComparison], title: str) -> Any:
    """A panel per limit prediction (disagreement against level and the predicted rate), then the exact rows' panel."""
    limits = list(dict.fromkeys(p.name for r in results for p in r.predictions if p.kind == "limit" and p.errors))
    panels = len(limits) + 1
    rows = math.ceil(panels / COLUMNS)
    fig = new_figure(4.3 * min(panels, COLUMNS), 3.6 * rows)
    axes = fig.subplots(rows, min(panels, COLUMNS), squeeze=False).ravel()
    for ax, name in zip(axes, limits):
        _limit_panel(ax, name, results)
    _exact_panel(axes[len(limits)], results)
    for ax in axes[panels:]:
        ax.set_visible(False)
    fig.suptitle(title, fontsize=10)
    return fig
