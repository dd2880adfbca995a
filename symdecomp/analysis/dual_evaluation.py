"""Evaluation of the sectors around an extraordinary face from their data (:mod:`symdecomp.analysis.dual_evaldata`).

At ``(u, v) != (0, 0)`` in sector ``s`` (:func:`evaluate`): the level ``m >= 1`` with ``1 < 2^m max(u, v) <= 2``,
``(x, y) = 2^m (u, v)``, the cell ``(a, b) = (min(floor x, 1), min(floor y, 1))`` and local ``(x - a, y - b)``, then
``point = b(x - a, y - b) . patches[s][c] . A^m C`` with the biquadratic B-spline basis ``b``
(:func:`quadratic_bspline_basis`; ``A^m C = sum_i W_i B_i^m (W^-1 C)_i`` by the decomposition, or the powers). At
``(0, 0)``: ``limit . C``.

>>> from fractions import Fraction
>>> from symdecomp.analysis.dual_evaldata import dual_evaldata
>>> from symdecomp.schemes.stencil_files import load_zoo
>>> d = dual_evaldata(load_zoo("doo-sabin"), 3)
>>> evaluate(d, 2, Fraction(1, 3), Fraction(1, 5), [[Fraction(1)]] * d.size)["point"]
[1]
>>> [str(x) for x in quadratic_bspline_basis(Fraction(1, 2))]
['1/8', '3/4', '1/8']
"""

from __future__ import annotations

import math
from fractions import Fraction

import flint

from symdecomp.analysis.dual_evaldata import CELLS, DualEvalData
from symdecomp.analysis.sector_evaldata import PREC
from symdecomp.analysis.sector_evaluation import cell_net, control_points_matrix, limit_values, tensor_values
from symdecomp.errors import EvaluationError, InvalidInputError
from symdecomp.validate import check_type

__all__ = ["evaluate", "quadratic_bspline_basis"]


def quadratic_bspline_basis(t, derivative: int = 0) -> list:
    """The uniform quadratic B-spline basis ``N_0, N_1, N_2`` (or its first derivative) at ``t`` in ``[0, 1]``."""
    one = t * 0 + 1
    if derivative == 0:
        return [(one - t) ** 2 / 2, (-2 * t * t + 2 * t + one) / 2, t * t / 2]
    return [t - one, one - 2 * t, t]


def _level(u, v, level) -> int:
    """The level ``m >= 1`` with ``1 < 2^m max(u, v) <= 2``; or the given one, where ``1 <= 2^m max(u, v) <= 2``."""
    top = max(u, v)
    if level is not None:
        if isinstance(level, bool) or not isinstance(level, int) or level < 1 or not 1 <= 2**level * top <= 2:
            raise EvaluationError(f"level must be an integer m >= 1 with 1 <= 2^m max(u, v) <= 2, got {level!r:.40}")
        return level
    m = 1
    while 2**m * top <= 1:
        m += 1
    return m


def _check_parameters(data: DualEvalData, sector, u, v) -> tuple:
    if isinstance(sector, bool) or not isinstance(sector, int) or not 0 <= sector < data.n:
        raise InvalidInputError(f"sector must be an integer from 0 to {data.n - 1}, got {sector!r:.40}")
    out = []
    for name, x in (("u", u), ("v", v)):
        if isinstance(x, bool) or not isinstance(x, (int, Fraction)) or not 0 <= x <= 1:
            raise EvaluationError(f"{name} must be an exact rational in [0, 1] (int or Fraction), got {x!r:.40}")
        out.append(Fraction(x))
    return tuple(out)


def evaluate(data: DualEvalData, sector: int, u, v, points, *, route: str = "eigen", level: int | None = None) -> dict:
    """``{"point", "du", "dv", "level"}`` of sector ``sector`` at ``(u, v)`` from the ``K`` control ``points``.

    ``u, v``: exact rationals; ``points``: rationals (exact results with exact data) or Arb balls. ``route``:
    ``"eigen"`` (the decomposition, when the data have one) or ``"powers"`` (``A^m``). At ``(0, 0)`` the point is the
    limit position and the derivatives are ``None``. ``level``: the other level whose ring holds ``(u, v)``
    (``2^m max(u, v) = 1``: the ring's inner edge), instead of the one chosen.
    """
    check_type(data, DualEvalData, "data")
    if route not in ("eigen", "powers"):
        raise InvalidInputError(f"route must be 'eigen' or 'powers', got {route!r:.40}")
    u, v = _check_parameters(data, sector, u, v)
    with flint.ctx.workprec(PREC):
        control, ball = control_points_matrix(data, points)
        if u == 0 and v == 0:
            return limit_values(data, control, ball)
        m = _level(u, v, level)
        x, y = 2**m * u, 2**m * v
        a, b = min(math.floor(x), 1), min(math.floor(y), 1)
        c = CELLS.index((a, b))
        net = cell_net(data, data.patches[sector][c], data.phi[sector][c] if data.phi else None, m, control, ball, route)
        return tensor_values(net, x - a, y - b, quadratic_bspline_basis, m, ball)
