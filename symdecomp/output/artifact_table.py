"""The artifact table's columns: one valence's JSON object (``ArtifactIndicators.as_json``) as text cells.

One source for the table ``symdecomp artifacts`` prints and the report's section "Curvature and shape"
(:mod:`symdecomp.output.report`): a new indicator is one more entry of :data:`COLUMNS`. Pure text, no
computation, so the command line imports it cheaply.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

__all__ = ["Column", "COLUMNS", "table", "number", "mu_value", "mu_frequency"]


class Column(NamedTuple):
    """One column of the table: its header and its cell, a function of one valence's JSON object."""

    header: str
    cell: Callable[[dict], str]


def number(text: str | None) -> str:
    """A decimal from the JSON (a ball's midpoint, 10 digits) shown to 6 significant digits."""
    return "-" if text is None else f"{float(text):.6g}"


def _mu(row: dict) -> dict | None:
    return row["curvature"]["mu"][0] if row["curvature"]["mu"] else None


def mu_frequency(row: dict) -> str:
    """The frequencies of the eigenvalues ``mu`` (``outer``: the regular rules' blocks), comma-separated."""
    freqs = [("outer" if e["frequency"] is None else str(e["frequency"])) for e in row["curvature"]["mu"]]
    return ",".join(freqs) or "-"


def mu_value(row: dict) -> str:
    """``mu`` to 6 digits, with ``?`` when eigenvalues of the same modulus are not separated."""
    mu = _mu(row)
    if mu is None:
        return "-"
    tied = len(row["curvature"]["mu"]) > 1 and not all(e["exact"] for e in row["curvature"]["mu"])
    return number(mu["value"]) + ("?" if tied else "")


#: The table's columns, in order.
COLUMNS: list[Column] = [
    Column("n", lambda r: str(r["n"])),
    Column("lambda_1", lambda r: number(r["curvature"]["lambda1"])),
    Column("lambda_1^2", lambda r: number(r["curvature"]["lambda1_squared"])),
    Column("mu", mu_value),
    Column("freq", mu_frequency),
    Column("mult", lambda r: str(r["curvature"]["mu_multiplicity"] or "-")),
    Column("regime", lambda r: r["curvature"]["regime"]),
    Column("cause", lambda r: r["curvature"]["cause"] or "-"),
    Column("density", lambda r: r["density"]),
    Column("negative weights", lambda r: r["negative_weights"]),
    Column("spacing", lambda r: number(r["ring_spacing_ratio"])),
    Column("shape", lambda r: r["shape"]["text"]),
]


def table(rows: list[dict], columns: list[Column] = COLUMNS) -> str:
    """The rows as a text table, one line per valence, columns padded to their widest cell."""
    cells = [[c.header for c in columns]] + [[c.cell(r) for c in columns] for r in rows]
    widths = [max(len(line[i]) for line in cells) for i in range(len(columns))]
    return "\n".join("  ".join(x.ljust(w) for x, w in zip(line, widths)).rstrip() for line in cells)
