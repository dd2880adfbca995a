"""The figure of ``symdecomp check --plot``: how far the closed forms and the full matrix agree, valence by valence.

Numeric mode: the digits to which the eigenvalues agree (``-log10`` of the largest deviation and of
the largest spread of the enclosures) against the digits asked for (``--dps``). Certified mode: the
distinct eigenvalues proved and the size of the exact characteristic polynomial's coefficients (bits;
0 on the structural route, which needs none). Each valence (each sector of ``K`` faces at a sharp
vertex) is coloured by its status. The numbers are the rows the command prints
(:meth:`~symdecomp.verify.result.CrossCheckResult.as_json`).
"""

from __future__ import annotations

import math

from symdecomp.output.plotting._mpl import new_figure

__all__ = ["STATUS_COLOURS", "agreeing_digits", "check_figure"]

#: The colour of each status of a check.
STATUS_COLOURS = {"agree": "C2", "disagree": "C3", "undecided": "C1"}


def agreeing_digits(text: str | None) -> float | None:
    """``-log10`` of a deviation printed as text (``"3.45e-57"``: 56.46...); None for none, inf for an exact 0.

    >>> round(agreeing_digits("1e-20"), 6), agreeing_digits("0"), agreeing_digits(None)
    (20.0, inf, None)
    """
    if text is None:
        return None
    value = float(text)
    return math.inf if value == 0 else -math.log10(value)


def _label(row: dict) -> str:
    return row.get("vertex") or str(row["n"])


def check_figure(scheme: str, rows: list[dict]):
    """The figure of the rows of ``check`` (numeric or certified, interior valences or sharp vertices), in order."""
    fig = new_figure(7.5, 4.5)
    ax = fig.subplots()
    x = list(range(len(rows)))
    colours = [STATUS_COLOURS.get(r["status"], "0.5") for r in rows]
    numeric = rows[0]["mode"] == "numeric"
    if numeric:
        for key, marker, name in (("max_deviation", "o", "-log10 largest deviation"), ("max_spread", "s", "-log10 largest spread")):
            digits = [agreeing_digits(r.get(key)) for r in rows]
            shown = [(i, d, c) for i, d, c in zip(x, digits, colours) if d is not None and math.isfinite(d)]
            ax.scatter([s[0] for s in shown], [s[1] for s in shown], c=[s[2] for s in shown], marker=marker, s=20, label=name)
        ax.plot(x, [r["dps"] for r in rows], color="0.4", lw=0.8, ls="--", label="digits asked for (--dps)")
        ax.set_ylabel("digits of agreement")
        what = "numeric check"
    else:
        ax.bar(x, [r["distinct"] for r in rows], color=colours, alpha=0.7, label="distinct eigenvalues proved")
        twin = ax.twinx()
        twin.plot(x, [r.get("height_bits") or 0 for r in rows], "k.-", lw=0.8, label="chi_S coefficient bits")
        twin.set_ylabel("bits of the characteristic polynomial's coefficients")
        twin.legend(fontsize=8, loc="upper right")
        ax.set_ylabel("distinct eigenvalues")
        what = "certified check (" + ", ".join(dict.fromkeys(str(r.get("route")) for r in rows)) + ")"
    for status, colour in STATUS_COLOURS.items():
        ax.scatter([], [], color=colour, label=status)
    step = max(1, len(rows) // 16)
    ax.set_xticks(x[::step], [_label(rows[i]) for i in x[::step]], fontsize=8, rotation=30 if "vertex" in rows[0] else 0)
    ax.set_xlabel("sharp vertex" if "vertex" in rows[0] else "valence n")
    ax.legend(fontsize=8, loc="best")
    ax.grid(alpha=0.3)
    ax.set_title(f"{scheme}: closed forms against the full matrix, {what}", fontsize=10)
    return fig
