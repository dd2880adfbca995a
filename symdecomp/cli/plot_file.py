"""``--plot FILE``: the option of the commands that draw what they print or write (``c1``, ``spectrum``,
``artifacts``, ``check``, ``masks``, ``charpoly``, ``refine``, ``design``, ``oracle``, ``evaldata``).

The format is the file's extension: ``.png``, ``.svg`` or ``.pdf``, written with the same bytes every
run (:func:`symdecomp.output.plotting._mpl.figure_bytes`: fixed metadata, no dates, a fixed SVG
hash salt, matplotlib's Agg renderer). Everything that can be refused is refused before the work
starts (:func:`check_plot`): an unknown extension and an unwritable path are bad input (exit code
2), a missing matplotlib is a missing optional component (exit code 3, saying how to get it). The
figure is made from the same results the command prints and written whole
(:func:`symdecomp.cli.files.write_output_file`), never left half written.
"""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

from symdecomp.cli.common import Once
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.errors import InvalidInputError, UnavailableError

__all__ = ["PLOT_FORMATS", "PlotTarget", "add_plot_option", "check_plot", "write_plot"]

#: The extensions ``--plot`` takes (``symdecomp.output.plotting._mpl.FORMATS``, named here so that ``--help`` stays cheap).
PLOT_FORMATS = ("png", "svg", "pdf")


class PlotTarget(NamedTuple):
    """Where ``--plot`` writes: the checked path and the format from its extension."""

    path: Path
    fmt: str


def add_plot_option(parser, what: str) -> None:
    """``--plot FILE.png|FILE.svg|FILE.pdf``: draw ``what`` into FILE."""
    parser.add_argument("--plot", action=Once, metavar="FILE.png|FILE.svg|FILE.pdf",
                        help=f"also draw {what} into FILE, the format by its extension (png, svg or pdf; the same bytes "
                        "every run); needs matplotlib (pip install 'symdecomp[report]')")


def check_plot(args) -> PlotTarget | None:
    """The target of ``--plot`` (``None`` if not given), refused at once: an unknown extension or an unwritable path
    (:class:`~symdecomp.errors.InvalidInputError`), or no matplotlib (:class:`~symdecomp.errors.UnavailableError`)."""
    text = getattr(args, "plot", None)
    if text is None:
        return None
    fmt = text.rsplit(".", 1)[-1].lower() if "." in Path(text).name else ""
    if fmt not in PLOT_FORMATS:
        raise InvalidInputError(f"--plot {text}: the file name must end in .png, .svg or .pdf (the format of the figure)")
    path = check_output_file(text, "--plot")
    from symdecomp.output.plotting._mpl import require_matplotlib

    try:
        require_matplotlib()
    except ImportError:
        raise UnavailableError("--plot needs matplotlib; install it with  pip install 'symdecomp[report]'") from None
    return PlotTarget(path, fmt)


def write_plot(target: PlotTarget | None, draw) -> None:
    """Write the figure ``draw()`` returns to ``target`` (nothing if ``None``), whole, as its format's bytes."""
    if target is None:
        return
    from symdecomp.output.plotting._mpl import figure_bytes

    write_output_file(target.path, figure_bytes(draw(), target.fmt), "--plot")
