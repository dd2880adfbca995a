"""``evaldata --plot FILE``: the eigenvalues of the data being written, drawn per valence (or per ``K``).

The numbers are read from what the command writes, as it writes it, and only when ``--plot`` is given (without it
nothing is kept and nothing is decoded): Stam's file's eigenvalues from each valence's piece (the binary bytes, or the
JSON text, or the decimal entry at ``--digits D > 17``); a boundary or corner vertex's from the irreducible factors
over ``Q`` the file lists (their roots, in floating point); a crease's, and a dual scheme's faces', from the blocks
of the eigen-decomposition written (their roots' balls, at their midpoints). A file of Arb balls without a
decomposition has no eigenvalues to draw for that ``K``: the figure leaves it out and says so.
The figure is :mod:`symdecomp.output.plotting.evaldata_chart`; ``--plot`` is checked with ``--out`` before any work,
and the same file for both is refused.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from symdecomp.cli.plot_file import PlotTarget, check_plot, write_plot
from symdecomp.errors import InvalidInputError

__all__ = ["check_evaldata_plot", "EigenvaluesDrawn", "piece_values", "factor_roots", "block_values"]


def check_evaldata_plot(args: Any) -> PlotTarget | None:
    """``--plot``'s target, refused before any work (:func:`~symdecomp.cli.plot_file.check_plot`) and when it is ``--out``."""
    plot = check_plot(args)
    if plot is not None and plot.path.resolve() == Path(args.out).resolve():
        raise InvalidInputError(f"--plot {args.plot}: the same file as --out; the figure and the data need two files")
    return plot


def piece_values(piece: Any) -> list[complex]:
    """The eigenvalues of one valence of Stam's file as written: its binary piece (read by the file's own reader,
    :func:`~symdecomp.output.evaldata.read_binary_valence`), its JSON text, or its decimal entry (``"values"``)."""
    data = getattr(piece, "data", None)
    if isinstance(data, bytes):
        from symdecomp.output.evaldata import read_binary_valence  # only when drawing: --help loads no numpy

        return [complex(v) for v in read_binary_valence(int(piece.n), data)[0].values]
    text = getattr(piece, "text", None)
    entry = json.loads(text) if isinstance(text, str) else piece
    return [complex(float(v)) for v in entry["values"]]


def factor_roots(spectrum: Any) -> list[complex]:
    """The roots of the irreducible factors ``(coefficients, multiplicity, eigenvectors)`` written, constant term first."""
    import numpy as np

    roots: list[complex] = []
    for factor, _, _ in spectrum:
        roots += [complex(z) for z in np.roots([float(c) for c in reversed(factor)])] if len(factor) > 1 else []
    return roots


def block_values(decomposition: Any) -> list[complex] | None:
    """The roots of the eigen-decomposition's blocks, at their balls' midpoints (``None``: no decomposition)."""
    if decomposition is None:
        return None
    return [complex(float(z.real.mid()), float(z.imag.mid())) for b in decomposition for z in b.values]


class EigenvaluesDrawn:
    """The eigenvalues per valence (or ``K``) gathered for ``--plot`` while the data are written; inert without it."""

    def __init__(self, plot: PlotTarget | None) -> None:
        self.plot = plot
        self.columns: dict[int, list[complex] | None] = {}

    def add(self, x: int, values: Any, written: Any) -> None:
        """Keep ``values(written)`` (called only when drawing) as the eigenvalues at ``x``."""
        if self.plot is not None:
            self.columns[x] = values(written)

    def write(self, xlabel: str, title: str) -> None:
        """Draw what was gathered into the ``--plot`` target (nothing without one)."""
        from symdecomp.output.plotting.evaldata_chart import evaldata_figure

        write_plot(self.plot, lambda: evaldata_figure(self.columns, xlabel, title))
