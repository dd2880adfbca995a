"""The figure of ``symdecomp c1 --every-n --plot``: the proof's ``lambda_1(n)`` beside the valences certified one by one.

The proof for every ``n`` (:mod:`symdecomp.verify.c1_every_n`, :mod:`symdecomp.verify.c1_dual_every_n`) reads the
subdominant eigenvalue as a closed form in ``n`` (a primal scheme's frequency-1 block ``M(t)`` at ``t = cos(2 pi/n)``,
a dual scheme's ``n``-gon symbol at frequency 1). The upper panel draws that closed form as a curve over the valences
and, at each valence Reif's test certified, the test's own ``lambda_1`` and its bound on every other eigenvalue's modulus
(``lambda_1`` minus the certified gap): the dots sit on the curve, and the gap is what the spectral steps prove for every
``n``. The lower panel draws the certified lower bound of the characteristic map's Jacobian at each valence. The steps of
the argument and their status are the caption.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import sympy as sp

from symdecomp.output.plotting._mpl import new_figure
from symdecomp.symbols import n as N

if TYPE_CHECKING:
    from symdecomp.verify.c1_every_n import EveryNResult

__all__ = ["every_n_figure", "closed_form_points"]

#: The points at which the closed form is drawn between two valences.
SAMPLES = 160


def closed_form_points(lam: sp.Expr, first: int, last: int) -> tuple[list[float], list[float]]:
    """``(n, lambda_1(n))`` at :data:`SAMPLES` real ``n`` from ``first`` to ``last``, each value evaluated from the exact
    expression at 15 digits (sympy's ``evalf``: no code generated from it).

    >>> closed_form_points(sp.cos(2 * sp.pi / N) / 4 + sp.Rational(3, 8), 3, 4)[1][::SAMPLES - 1]
    [0.25, 0.375]
    """
    xs = [first + (last - first) * i / (SAMPLES - 1) for i in range(SAMPLES)]
    return xs, [float(lam.subs(N, sp.Float(x, 30)).evalf(15)) for x in xs]


def _caption(result: EveryNResult) -> str:
    lines = []
    for step in result.steps:
        first, last = step.valences
        where = f"n >= {first}" if last is None else f"n = {first}..{last}" if last > first else f"n = {first}"
        lines.append(f"[{step.status}] {step.name or 'step'}, {where}")
    return "; ".join(lines)


def every_n_figure(result: EveryNResult, rows: list[dict[str, Any]], lam: sp.Expr | None) -> Any:
    """The figure (module docstring). ``result``: the :class:`~symdecomp.verify.c1_every_n.EveryNResult`; ``rows``: the
    per-valence results' ``json`` (keys ``n``, ``verdict``, ``lambda``, ``gap``, ``jacobian_lower_bound``); ``lam``:
    ``lambda_1`` as a closed form in ``n``, or ``None`` where the proof has none (drawn without the curve)."""
    fig = new_figure(7.5, 6.0)
    top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=(3, 2))
    certified = [r for r in rows if r.get("lambda") is not None]
    last = max((r["n"] for r in rows), default=result.certified[1])
    if lam is not None:
        xs, ys = closed_form_points(lam, min(r["n"] for r in rows) if rows else 3, last)
        top.plot(xs, ys, color="C0", lw=1.2, label="lambda_1(n), the proof's closed form")
    top.scatter([r["n"] for r in certified], [r["lambda"] for r in certified], s=14, color="C1", zorder=3,
                label="lambda_1, Reif's test at n (certified)")
    bounded = [r for r in certified if r.get("gap") is not None]
    top.scatter([r["n"] for r in bounded], [r["lambda"] - r["gap"] for r in bounded], s=10, marker="v", color="C2",
                label="|other eigenvalues| <= (certified)")
    top.axhline(1.0, color="0.6", lw=0.6, ls=":")
    top.set_ylabel("eigenvalue (modulus)")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    jac = [r for r in rows if r.get("jacobian_lower_bound")]
    colours = {"c1": "C2", "not-c1": "C3"}
    bottom.scatter([r["n"] for r in jac], [r["jacobian_lower_bound"] for r in jac], s=12,
                   c=[colours.get(r["verdict"], "0.4") for r in jac])
    if jac:
        bottom.set_yscale("log")
    bottom.set_xlabel("valence n")
    bottom.set_ylabel("|J| >= (certified)")
    bottom.grid(alpha=0.3)
    fig.suptitle(f"{result.scheme}: C1 for every valence? {result.status}\n{_caption(result)}", fontsize=8, wrap=True)
    return fig
