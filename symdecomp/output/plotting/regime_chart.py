"""The figure of ``symdecomp artifacts --plot``: the curvature regime over the valences.

Top: the subdominant eigenvalue ``lambda_1``, its square and the modulus of the next eigenvalue
``mu``; bottom: ``|mu| / lambda_1^2`` against 1, each valence coloured by its certified regime
(bounded at 1, zero below, unbounded above; Peters and Reif 2004). The numbers are each valence's
:meth:`~symdecomp.verify.artifacts.ArtifactIndicators.as_json`, the rows the command prints.
"""

from __future__ import annotations

from symdecomp.output.plotting._mpl import new_figure

__all__ = ["REGIME_COLOURS", "modulus", "regime_figure"]

#: The colour of each curvature regime (any other, e.g. not applicable: grey).
REGIME_COLOURS = {"bounded": "C0", "zero": "C2", "unbounded": "C3", "undecided": "C1"}


def modulus(text: str) -> float:
    """The modulus of an eigenvalue as the artifact rows print it (``ball_text``: ``"0.34"``, ``"0.06 - 0.09i"``).

    >>> modulus("0.3401073882"), modulus("0.3 - 0.4i"), modulus("-1.5e-2")
    (0.3401073882, 0.5, 0.015)
    """
    return abs(complex(text.replace(" ", "").replace("i", "j")))


def _values(row: dict) -> tuple[int, float, float, float] | None:
    """``(n, lambda_1, lambda_1^2, |mu|)`` of one valence's row, or None where it has no mu (not applicable)."""
    c = row["curvature"]
    if not c.get("mu") or c.get("lambda1") is None:
        return None
    mu = max(modulus(m["value"]) for m in c["mu"])
    return row["n"], float(c["lambda1"]), _square(c), mu


def _square(c: dict) -> float:
    """``lambda_1^2`` as a float: the row's decimal, or the square of ``lambda_1`` where the row prints it exact (a scheme
    of the zoo: ``3*sqrt(5)/32 + 7/32``)."""
    try:
        return float(c["lambda1_squared"])
    except ValueError:
        return float(c["lambda1"]) ** 2


def regime_figure(scheme: str, rows: list[dict]):
    """The regime chart of ``rows`` (``artifacts --json``'s rows, in order of n) for the scheme named ``scheme``."""
    fig = new_figure(7.5, 6.0)
    top, bottom = fig.subplots(2, 1, sharex=True)
    data = [v for v in map(_values, rows) if v is not None]
    colours = [REGIME_COLOURS.get(r["curvature"]["regime"], "0.5") for r in rows if _values(r) is not None]
    ns = [v[0] for v in data]
    top.plot(ns, [v[1] for v in data], "o-", ms=3, color="C7", label="lambda_1")
    top.plot(ns, [v[2] for v in data], "s-", ms=3, color="C0", label="lambda_1^2")
    top.scatter(ns, [v[3] for v in data], c=colours, marker="D", s=20, label="|mu| (colour: regime)", zorder=3)
    top.set_ylabel("eigenvalue")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    bottom.axhline(1.0, color="0.4", lw=0.8)
    bottom.scatter(ns, [v[3] / v[2] for v in data], c=colours, s=22)
    for regime, colour in REGIME_COLOURS.items():
        bottom.scatter([], [], color=colour, label=regime)
    bottom.set_ylabel("|mu| / lambda_1^2")
    bottom.set_xlabel("valence n")
    bottom.legend(fontsize=8, ncols=4)
    bottom.grid(alpha=0.3)
    fig.suptitle(f"{scheme}: curvature regime at the extraordinary vertex by valence\n|mu| / lambda_1^2 above 1: unbounded, "
                 "at 1: bounded, below 1: zero",
                 fontsize=10)
    return fig
