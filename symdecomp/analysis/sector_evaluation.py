"""Evaluation of a crease, boundary or corner vertex's patches from its data (:mod:`symdecomp.analysis.sector_evaldata`).

Evaluation at ``(u, v) != (0, 0)`` (:func:`evaluate`): the level ``n >= 2`` with ``2 < 2^n max(u, v) <= 4``,
``(x, y) = 2^n (u, v)``, the cell ``(a, b) = (min(floor x, 3), min(floor y, 3))`` and local ``(x - a, y - b)``,
then ``point = b(x - a, y - b) . cells[s][c] . A^(n-2) C`` with the bicubic B-spline basis ``b``. At ``(0, 0)``:
``limit . C``. Triangles (Loop's box spline) are not handled here (the lattice's fact is missing).

>>> from fractions import Fraction
>>> from symdecomp.analysis.sector_evaldata import sector_evaldata
>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> d = sector_evaldata(catmull_clark(), SharpVertex.crease(2, 3, "quad"))
>>> evaluate(d, 4, Fraction(1, 3), Fraction(1, 5), [[Fraction(1)]] * d.size)["point"]
[1]
"""

from __future__ import annotations

import math
from fractions import Fraction

import flint

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.regular_basis import bspline_basis
from symdecomp.analysis.sector_evaldata import CELLS, PREC, SectorEvalData
from symdecomp.errors import EvaluationError, InvalidInputError
from symdecomp.validate import check_type

__all__ = ["evaluate", "cell_net", "control_points_matrix", "limit_values", "matrix_times", "tensor_values"]


def _level(u, v, level) -> int:
    """The level ``n >= 2`` with ``2 < 2^n max(u, v) <= 4``; or the given one, where ``2 <= 2^n max(u, v) <= 4``."""
    m = max(u, v)
    if level is not None:
        if isinstance(level, bool) or not isinstance(level, int) or level < 2 or not 2 <= 2**level * m <= 4:
            raise EvaluationError(f"level must be an integer n >= 2 with 2 <= 2^n max(u, v) <= 4, got {level!r:.40}")
        return level
    n = 2
    while 2**n * m <= 2:
        n += 1
    return n


def control_points_matrix(data: SectorEvalData, points):
    rows = [list(p) for p in points] if hasattr(points, "__iter__") else None
    if not rows or len(rows) != data.size or len({len(p) for p in rows}) != 1 or not rows[0]:
        raise InvalidInputError(f"control points: need {data.size} points of one dimension d >= 1 (the closed 2-ring)")
    for p in rows:
        for x in p:
            if isinstance(x, bool) or not isinstance(x, (int, Fraction, flint.fmpq, flint.arb)):
                raise InvalidInputError(f"control points: coordinates must be exact rationals or Arb balls, got {x!r:.40}")
    ball = not data.exact or any(isinstance(x, flint.arb) for p in rows for x in p)
    kind = flint.arb_mat if ball else flint.fmpq_mat
    out = kind(len(rows), len(rows[0]))
    for i, p in enumerate(rows):
        for j, x in enumerate(p):
            out[i, j] = x if isinstance(x, flint.arb) else to_fmpq(x)
    return out, ball


def _check_parameters(data: SectorEvalData, face, u, v) -> tuple:
    if isinstance(face, bool) or not isinstance(face, int) or not 0 <= face < data.faces:
        raise InvalidInputError(f"face must be an integer from 0 to {data.faces - 1}, got {face!r:.40}")
    out = []
    for name, x in (("u", u), ("v", v)):
        if isinstance(x, bool) or not isinstance(x, (int, Fraction)) or not 0 <= x <= 1:
            raise EvaluationError(f"{name} must be an exact rational in [0, 1] (int or Fraction), got {x!r:.40}")
        out.append(Fraction(x))
    return tuple(out)


def matrix_times(a, b, ball: bool):
    if ball:
        a = a if isinstance(a, flint.arb_mat) else flint.arb_mat(a)
        b = b if isinstance(b, flint.arb_mat) else flint.arb_mat(b)
    return a * b


def cell_net(data, picking, phi_cell, steps: int, control, ball: bool, route: str):
    """One cell's B-spline net after ``steps`` steps: ``picking . A^steps . C`` by powers of ``data.matrix``, or Stam's
    eigen-expansion ``sum_i phi_i B_i^steps (W^-1 C)_i`` over ``data.decomposition`` (``phi_cell``: the cell's
    ``picking W_i``). ``data``: any evaluation data with ``matrix`` and ``decomposition`` (sectors, dual faces)."""
    if route == "powers" or data.decomposition is None:
        coarse = control
        for _ in range(steps):
            coarse = matrix_times(data.matrix, coarse, ball)
        return matrix_times(picking, coarse, ball)
    net = None
    for block, phi in zip(data.decomposition, phi_cell):
        coords = matrix_times(block.left, control, ball)
        for _ in range(steps):  # B_i^m on this block's coordinates only
            coords = matrix_times(block.block, coords, ball)
        term = matrix_times(phi, coords, ball)
        net = term if net is None else net + term
    return net


def limit_values(data, control, ball: bool) -> dict:
    """``{"point", "du", "dv", "level"}`` at the extraordinary point: the limit mask ``data.limit`` applied to the
    control points, no derivatives."""
    kind = flint.fmpq_mat if data.exact else flint.arb_mat
    row = matrix_times(kind(1, data.size, list(data.limit)), control, ball)
    return {"point": [row[0, j] for j in range(row.ncols())], "du": None, "dv": None, "level": None}


def tensor_values(net, s: Fraction, t: Fraction, basis, level: int, ball: bool) -> dict:
    """``{"point", "du", "dv", "level"}`` of the tensor-product B-spline ``net`` (rows ``i + d j``, ``d`` the basis's
    length) at local ``(s, t)`` of a cell at ``level`` (derivatives scaled by ``2^level`` to the patch's parameters);
    ``basis(t, derivative)``: the uniform B-spline basis of the degree."""
    if ball:
        s, t = flint.arb(s.numerator) / s.denominator, flint.arb(t.numerator) / t.denominator
    else:
        s, t = flint.fmpq(s.numerator, s.denominator), flint.fmpq(t.numerator, t.denominator)
    out: dict = {"level": level}
    for key, (ds, dt) in (("point", (0, 0)), ("du", (1, 0)), ("dv", (0, 1))):
        bs, bt = basis(s, ds), basis(t, dt)  # exact numbers or balls
        d, scale = len(bs), 2 ** (level * (ds + dt))
        out[key] = [sum((bs[i] * bt[j] * net[i + d * j, k] for j in range(d) for i in range(d)), 0 * s) * scale
                    for k in range(net.ncols())]
    return out


def evaluate(data: SectorEvalData, face: int, u, v, points, *, route: str = "eigen", level: int | None = None) -> dict:
    """``{"point", "du", "dv", "level"}`` of patch ``face`` at ``(u, v)`` from the ``K`` control ``points``.

    ``u, v``: exact rationals; ``points``: rationals (exact results with exact data) or Arb balls. ``route``:
    ``"eigen"`` (the decomposition, when the data have one) or ``"powers"`` (``A^(n-2)``). At ``(0, 0)`` the point is
    the limit position and the derivatives are ``None``. ``level``: another level ``n`` whose wide ring holds
    ``(u, v)`` (``2^n max(u, v) = 2``: the inner edge of the ring), instead of the one chosen.
    """
    check_type(data, SectorEvalData, "data")
    if route not in ("eigen", "powers"):
        raise InvalidInputError(f"route must be 'eigen' or 'powers', got {route!r:.40}")
    u, v = _check_parameters(data, face, u, v)
    with flint.ctx.workprec(PREC):
        control, ball = control_points_matrix(data, points)
        if u == 0 and v == 0:
            return limit_values(data, control, ball)
        n = _level(u, v, level)
        x, y = 2**n * u, 2**n * v
        a, b = min(math.floor(x), 3), min(math.floor(y), 3)
        c = CELLS.index((a, b))
        net = cell_net(data, data.cells[face][c], data.phi[face][c] if data.phi else None, n - 2, control, ball, route)
        return tensor_values(net, x - a, y - b, bspline_basis, n, ball)
