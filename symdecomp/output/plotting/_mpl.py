"""Lazy access to matplotlib, so that the rest of symdecomp works without it.

Every plotting function builds a :class:`matplotlib.figure.Figure` directly (no pyplot, no
global figure state) and returns it; Jupyter displays a returned figure, a script saves it
with ``fig.savefig(...)``.
"""

from __future__ import annotations

import importlib

__all__ = ["FORMATS", "new_figure", "label_axes", "require_matplotlib", "figure_bytes"]


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


#: The metadata a saved figure carries, per format: no date, the same creator every time.
_METADATA = {
    "pdf": {"Creator": "symdecomp", "Producer": "symdecomp", "CreationDate": None},
    "svg": {"Creator": "symdecomp", "Date": None},
    "png": {"Software": "symdecomp"},
}

#: The formats :func:`figure_bytes` writes, by file extension.
FORMATS = tuple(_METADATA)


def figure_bytes(fig, fmt: str, *, dpi: int = 100) -> bytes:
    """``fig`` saved as ``fmt`` (``pdf``, ``svg`` or ``png``, at ``dpi``) with the same bytes every time: no dates,
    fixed metadata, SVG element ids from a fixed salt (matplotlib draws them from a random one), and the layout
    fixed at the first save (a constrained layout moves by rounding each time it runs)."""
    import io

    import matplotlib

    buffer = io.BytesIO()
    if fig.get_layout_engine() is not None:  # lay it out once and keep it: each further layout moves it a little
        fig.draw_without_rendering()
        fig.set_layout_engine("none")
    with matplotlib.rc_context({"svg.hashsalt": "symdecomp", "svg.fonttype": "path", "pdf.compression": 6}):
        fig.savefig(buffer, format=fmt, metadata=_METADATA[fmt], dpi=dpi)
    return buffer.getvalue()
