"""Lazy access to matplotlib, so that the rest of symdecomp works without it.

Every plotting function builds a :class:`matplotlib.figure.Figure` directly (no pyplot, no
global figure state) and returns it; Jupyter displays a returned figure, a script saves it
with ``fig.savefig(...)``.
"""

from __future__ import annotations

import importlib

__all__ = ["new_figure", "label_axes", "require_matplotlib"]


def require_matplotlib():
    """Import matplotlib, or raise an ImportError that says how to get it."""
    try:
        return importlib.import_module("matplotlib")
    except ImportError as exc:  # pragma: no cover - exercised only without matplotlib
        raise ImportError(
            "symdecomp.output.plotting needs matplotlib; install it with  pip install 'symdecomp[notebooks]'"
        ) from exc


def new_figure(width: float, height: float):
    """A new, free-standing Figure of the given size in inches."""
    require_matplotlib()
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


def label_axes(ax, xlabel: str, ylabel: str, title: str, **legend) -> None:
    """The house style of a panel: axis labels, a title, a small legend (``legend``: more options) and a light grid."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=8, **legend)
    ax.grid(alpha=0.3)
