"""The tuning region: the free vertex weights at one valence coloured by curvature regime (issue 21, item 5).

**How a cell is coloured (two parameters).** Every condition of
:mod:`symdecomp.analysis.tuning_region` is the sign of a form affine in the weights, so on a
rectangular cell it takes its extremes at the corners. The corners are exact rationals; each
form's coefficients are Arb balls (:func:`~symdecomp.algebra.algebraic_sign.real_ball`), so its
value at a corner is a rigorous ball. A form is *decided* on a cell when the four corner balls
are all ``> 0`` or all ``< 0``; a cell gets a regime's colour only when the decided forms fix the
regime for every point of the cell. The other cells meet a boundary line (or are too close to one
for the balls) and are drawn in the boundary colour: no cell's colour rests on a float. With
``m = lambda_1^2`` not the case, the set ``mu = lambda_1^2`` is a polygon's boundary, so it appears
as boundary cells around the ``mu < lambda_1^2`` region. **One parameter**: the exact intervals of
:func:`~symdecomp.analysis.tuning_region.interval_region`, drawn as bars (their ends are algebraic;
the drawing places them at their midpoints). The placed points are markers.

:func:`figure_bytes` writes a figure without time stamps or version strings, so the same region
gives the same bytes.
"""

from __future__ import annotations

import io
from fractions import Fraction

import flint
import numpy as np
import sympy as sp

from symdecomp.algebra.algebraic_sign import real_ball
from symdecomp.analysis.curvature_regime import CurvatureRegime
from symdecomp.analysis.tuning_region import TuningRegion, interval_region
from symdecomp.output.plotting._mpl import new_figure

__all__ = ["COLOURS", "cell_regimes", "tuning_region_figure", "figure_bytes"]

#: The colour of each regime, and of the cells that meet a boundary (key ``None``).
COLOURS = {CurvatureRegime.NOT_APPLICABLE: "#d9d9d9", CurvatureRegime.ZERO: "#4575b4", CurvatureRegime.BOUNDED: "#1a9850",
           CurvatureRegime.UNBOUNDED: "#d73027",
           None: "#000000"}
_CODES = [CurvatureRegime.NOT_APPLICABLE, CurvatureRegime.ZERO, CurvatureRegime.BOUNDED, CurvatureRegime.UNBOUNDED, None]


def _cell_signs(form: sp.Expr, params, xs, ys) -> np.ndarray:
    """``+1``/``-1`` where the form is decided on a cell (all four corners), ``0`` elsewhere."""
    x, y = params
    with flint.ctx.workprec(128):
        c0, cx, cy = (real_ball(sp.expand(form).coeff(v, 1) if v is not None else sp.expand(form).subs({x: 0, y: 0}), 128)
                      for v in (None, x, y))
        bx = [cx * flint.arb(flint.fmpq(v.numerator, v.denominator)) for v in xs]
        by = [c0 + cy * flint.arb(flint.fmpq(v.numerator, v.denominator)) for v in ys]
        pos = np.array([[b + a > 0 for a in bx] for b in by])
        neg = np.array([[b + a < 0 for a in bx] for b in by])
    allpos = pos[:-1, :-1] & pos[1:, :-1] & pos[:-1, 1:] & pos[1:, 1:]
    allneg = neg[:-1, :-1] & neg[1:, :-1] & neg[:-1, 1:] & neg[1:, 1:]
    return allpos.astype(int) - allneg.astype(int)


def cell_regimes(region: TuningRegion, xs: list[Fraction], ys: list[Fraction]) -> np.ndarray:
    """Codes (indices into ``[NOT_APPLICABLE (not C1), ZERO, BOUNDED, UNBOUNDED, boundary]``) of the cells between exact grid lines."""
    params = region.parameters
    c1 = [_cell_signs(f.expr, params, xs, ys) for f in region.c1_forms]
    sq = [_cell_signs(f.expr, params, xs, ys) for f in region.square_forms]
    out = np.full(c1[0].shape, 4)
    outside = np.any([s < 0 for s in c1], axis=0) | (not region.independent_c1)
    inside = np.all([s > 0 for s in c1], axis=0) & region.independent_c1
    out[outside] = 0
    some_neg = np.any([s < 0 for s in sq], axis=0)
    all_pos = np.all([s > 0 for s in sq], axis=0)
    if region.fixed_vs_square > 0:
        out[inside] = 3
    else:
        out[inside & some_neg] = 3
        out[inside & all_pos] = 1 if region.fixed_vs_square < 0 else 2
    return out


def _grid(lo: Fraction, hi: Fraction, cells: int) -> list[Fraction]:
    return [lo + (hi - lo) * k / cells for k in range(cells + 1)]


def _box(region: TuningRegion, points) -> tuple[Fraction, Fraction, Fraction, Fraction]:
    """A rational box around the C1 triangle's corners and the placed points (floats only choose the view)."""
    forms = [f.expr for f in region.c1_forms]
    corners = []
    for i in range(len(forms)):
        for j in range(i + 1, len(forms)):
            sol = sp.solve([forms[i], forms[j]], region.parameters, dict=True)
            if sol and all(v in sol[0] for v in region.parameters):
                corners.append([float(sp.N(sol[0][v], 20)) for v in region.parameters])
    corners += [[float(sp.N(v, 20)) for v in p] for _, p in points]
    if not corners:
        corners = [[0.0, 0.0]]
    arr = np.array(corners)
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    pad = np.maximum((hi - lo) * 0.12, 0.01)
    lo, hi = lo - pad, hi + pad
    q = [Fraction(float(v)).limit_denominator(4096) for v in (lo[0], hi[0], lo[1], hi[1])]
    return q[0], q[1], q[2], q[3]


def _legend_handles(ax):
    from matplotlib.patches import Patch

    labels = {None: "cell meets a boundary"}
    return [Patch(color=COLOURS[k], label=labels.get(k, str(k))) for k in _CODES]


def _plane(ax, region: TuningRegion, points, cells: int) -> None:
    from matplotlib.colors import ListedColormap

    x0, x1, y0, y1 = _box(region, points)
    codes = cell_regimes(region, _grid(x0, x1, cells), _grid(y0, y1, cells))
    cmap = ListedColormap([COLOURS[k] for k in _CODES])
    ax.imshow(codes, origin="lower", extent=(float(x0), float(x1), float(y0), float(y1)), cmap=cmap, vmin=-0.5, vmax=4.5,
              aspect="auto", interpolation="nearest")
    handles = _legend_handles(ax)
    for k, (label, p) in enumerate(points):
        handles += ax.plot([float(sp.N(p[0], 20))], [float(sp.N(p[1], 20))], marker="oxs+^"[k % 5], color="white",
                           markeredgecolor="black", linestyle="none", label=f"{label}: {region.classify(p)}")
    ax.set_xlabel(str(region.parameters[0]))
    ax.set_ylabel(str(region.parameters[1]))
    ax.legend(handles=handles, fontsize=7, loc="upper right")


def _line(ax, region: TuningRegion, points) -> None:
    pieces = interval_region(region)
    ends = [float(sp.N(e, 20)) for i in pieces for e in (i.lo, i.hi) if e is not None]
    ends += [float(sp.N(p[0], 20)) for _, p in points]
    lo, hi = (min(ends), max(ends)) if ends else (-1.0, 1.0)
    pad = max((hi - lo) * 0.15, 0.01)
    lo, hi = lo - pad, hi + pad
    for piece in pieces:
        a = lo if piece.lo is None else float(sp.N(piece.lo, 20))
        b = hi if piece.hi is None else float(sp.N(piece.hi, 20))
        if a == b:
            ax.plot([a], [0], marker="|", markersize=30, color=COLOURS[piece.regime])
        else:
            ax.plot([a, b], [0, 0], linewidth=14, solid_capstyle="butt", color=COLOURS[piece.regime])
    handles = _legend_handles(ax)[:4]
    for k, (label, p) in enumerate(points):
        handles += ax.plot([float(sp.N(p[0], 20))], [0], marker="oxs+^"[k % 5], color="white", markeredgecolor="black",
                           linestyle="none", label=f"{label}: {region.classify(p)}")
    ax.set_xlim(lo, hi)
    ax.set_yticks([])
    ax.set_xlabel(str(region.parameters[0]))
    ax.legend(handles=handles, fontsize=7, loc="upper right")


def tuning_region_figure(regions: list[TuningRegion], points: dict[int, list], *, cells: int = 120):
    """One panel per region (valence): the parameter plane (two parameters) or line (one), with the placed points."""
    fig = new_figure(6.0 * len(regions), 5.0 if len(regions[0].parameters) == 2 else 2.6)
    axes = fig.subplots(1, len(regions), squeeze=False)[0]
    for ax, region in zip(axes, regions):
        if len(region.parameters) == 2:
            _plane(ax, region, points.get(region.n, []), cells)
        else:
            _line(ax, region, points.get(region.n, []))
        ax.set_title(f"{region.scheme}, n = {region.n} (C1 test: {region.witness_verdict})", fontsize=9)
    return fig


def figure_bytes(fig, fmt: str) -> bytes:
    """The figure as ``png`` or ``pdf`` bytes, without time stamps or software versions (deterministic)."""
    buffer = io.BytesIO()
    metadata = {"Software": None} if fmt == "png" else {"Creator": None, "Producer": None, "CreationDate": None}
    fig.savefig(buffer, format=fmt, metadata=metadata, dpi=100)
    return buffer.getvalue()
