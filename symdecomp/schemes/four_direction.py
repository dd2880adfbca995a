"""The regular part of a dual quad scheme as a piecewise quadratic on the four-direction mesh, derived from its corner rule.

A dual step on the regular quad lattice puts, for every face and each of its four corners, one new point: the
corner rule's weights ``w_0..w_3`` on the face's corners, ``w_k`` on the corner ``k`` steps on (counter-clockwise)
from the new point's own corner. With the old control points on ``Z^2`` and the new ones on ``Z^2/2 + (1/4, 1/4)``
(the new point of a corner lies half way from the corner to its face's centre) the limit of the control net
``c`` is ``sum_b c_b phi(x - b)``, where the basis function solves the refinement equation

    ``phi(x) = sum_a A_a phi(2 x - a - (1/2, 1/2))``,  ``A_a``: the weight the new point ``a`` puts on the old point 0.

**The space.** The four-direction (criss-cross) mesh: the unit cells centred on the integer points, each split by
both diagonals into four triangles; triangle ``k`` of a cell has the corners (centre, ``r_k``, ``r_(k+1)``), with
``r_0..r_3 = (1/2, -1/2), (1/2, 1/2), (-1/2, 1/2), (-1/2, -1/2)`` (``k = 0`` the side ``u = 1/2``, then the top,
the left, the bottom). A continuous piecewise quadratic on it is one number per domain point (the quadratic
Bernstein-Bezier coefficients; neighbours share the coefficients on their common edge), zero outside a box of
``(2 R + 1)^2`` cells.

**The derivation.** The refinement equation, imposed at every point of ``Z^2/8`` in the box (a superset of the
domain points of the finer mesh, on which both sides are piecewise quadratic), is a homogeneous linear system over
the rationals (FLINT). Its solutions are the compactly supported refinable functions in the space: the space holds
the scheme's regular part exactly when the null space is one line (then ``phi`` is normalised by the partition of
unity ``sum_b phi(-b) = 1``); no solution means the regular part is no continuous piecewise quadratic on this
mesh. Nothing is typed in: the mid-edge rule ``(2, 1, 0, 1)/4`` gives the four-direction (Zwart-Powell) box
spline (``1/2`` at its centre, ``1/8`` one step away, ``1/4`` at a cell's corner); Doo and Sabin's rule
``(9, 3, 1, 3)/16`` gives none, its biquadratic B-spline being of total degree 4 (its own route is
:mod:`symdecomp.verify.c1_dual`).

>>> from fractions import Fraction as F
>>> zp = four_direction_patch((F(1, 2), F(1, 4), F(0), F(1, 4)))
>>> zp.value((0, 0), (F(0), F(0))), zp.value((1, 0), (F(0), F(0))), zp.value((1, 1), (F(1, 2), F(1, 2)))
(Fraction(1, 2), Fraction(1, 8), Fraction(1, 4))
>>> zp.c1, zp.dependent_translates
(True, True)
>>> from symdecomp.errors import InvalidSchemeError
>>> try:
...     four_direction_patch((F(9, 16), F(3, 16), F(1, 16), F(3, 16)))
... except InvalidSchemeError as exc:
...     print(str(exc).split(": ")[1])
its regular part is no continuous piecewise quadratic on the four-direction mesh (the refinement equation has no solution there)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import Any

import flint

from symdecomp.algebra.numbers import to_fraction
from symdecomp.algebra.triangle_bezier import bernstein, bezier_derivative, bezier_indices, bezier_value
from symdecomp.errors import InvalidInputError, InvalidSchemeError, InvalidTypeError

__all__ = ["CORNERS", "OFFSETS", "FourDirectionPatch", "refinement_mask", "cell_triangle", "four_direction_patch"]

#: The cell's corners ``r_0..r_3`` relative to its centre, counter-clockwise; triangle ``k`` is (centre, r_k, r_(k+1)).
CORNERS = ((Fraction(1, 2), Fraction(-1, 2)), (Fraction(1, 2), Fraction(1, 2)), (Fraction(-1, 2), Fraction(1, 2)),
           (Fraction(-1, 2), Fraction(-1, 2)))
#: The control points of the cell centred at 0: the offsets ``b`` of the 3 x 3 grid, row by row.
OFFSETS = tuple((i, k) for i in (-1, 0, 1) for k in (-1, 0, 1))
#: Half the box's side, in cells: the support searched for the basis function.
_RADIUS = 2
#: A quad face's corners (lower left first, counter-clockwise) as steps from its lower-left corner.
_FACE = ((0, 0), (1, 0), (1, 1), (0, 1))

_Point = tuple[Fraction, Fraction]


@dataclass(frozen=True)
class FourDirectionPatch:
    """The regular patch over one cell of the four-direction mesh, in Bernstein-Bezier form."""

    #: The corner rule it was derived from (weights on corners ``0..3``).
    corner_weights: tuple[Fraction, ...]
    #: ``coefficients[k][b]``: the six quadratic coefficients (:func:`~symdecomp.algebra.triangle_bezier.bezier_indices`
    #: order, corners (centre, ``r_k``, ``r_(k+1)``)) of ``phi(x - b)`` on triangle ``k``, ``b`` in :data:`OFFSETS` order.
    coefficients: tuple[tuple[tuple[Fraction, ...], ...], ...]
    #: Whether the basis function is C1 (its gradient continuous across every edge; computed, not assumed): Reif's
    #: test needs a C1 regular part.
    c1: bool
    #: Whether the alternating net ``(-1)^(b_1 + b_2)`` gives the zero function: the translates are linearly dependent.
    dependent_translates: bool

    def value(self, offset: tuple[int, int], point: _Point) -> Fraction:
        """``phi(point - offset)`` for a point of the cell centred at 0 (exact)."""
        k, u, v = _locate(point)
        total = Fraction(0)
        for c, b in zip(self.coefficients[k][OFFSETS.index(offset)], bernstein(2, u, v)):
            total += c * b
        return total


def refinement_mask(corner_weights: Sequence[Fraction]) -> dict[tuple[int, int], Fraction]:
    """``a -> A_a``: the weight that the new point ``a`` (on ``Z^2``, position ``a/2 + (1/4, 1/4)``) puts on old point 0.

    The faces around the old point 0 have their lower-left corners at ``{-1, 0}^2``; in the face at ``(i, j)`` the
    new point of the corner ``(a', b')`` is ``a = (2 i + a', 2 j + b')``.
    """
    mask: dict[tuple[int, int], Fraction] = {}
    for i in (-1, 0):
        for j in (-1, 0):
            q = _FACE.index((-i, -j))  # the old point 0 is this corner of the face
            for own, (a, b) in enumerate(_FACE):
                key = (2 * i + a, 2 * j + b)
                mask[key] = mask.get(key, Fraction(0)) + Fraction(corner_weights[(q - own) % 4])
    return mask


def cell_triangle(d: tuple[Any, Any]) -> tuple[int, Any, Any]:
    """The triangle ``k`` of the cell centred at 0 holding ``d`` and its coordinates ``(u, v)``: ``d = u r_k + v r_(k+1)``
    (exact for rationals; floats give floats)."""
    return _locate(d)


def _locate(d: tuple[Any, Any]) -> tuple[int, Any, Any]:
    x, y = d
    k = 0 if x >= abs(y) else 1 if y >= abs(x) else 2 if -x >= abs(y) else 3
    (ax, ay), (bx, by) = CORNERS[k], CORNERS[(k + 1) % 4]
    det = ax * by - ay * bx
    return k, (x * by - y * bx) / det, (ax * y - ay * x) / det


def _domain_point(cell: tuple[int, int], k: int, index: tuple[int, int, int]) -> _Point:
    (ax, ay), (bx, by) = CORNERS[k], CORNERS[(k + 1) % 4]
    _, b, c = index
    return (cell[0] + (b * ax + c * bx) / 2, cell[1] + (b * ay + c * by) / 2)


def _unknowns() -> dict[_Point, int]:
    """The domain points strictly inside the box (those on its boundary are 0), numbered."""
    out: dict[_Point, int] = {}
    edge = Fraction(2 * _RADIUS + 1, 2)
    for p in range(-_RADIUS, _RADIUS + 1):
        for q in range(-_RADIUS, _RADIUS + 1):
            for k in range(4):
                for index in bezier_indices(2):
                    point = _domain_point((p, q), k, index)
                    if max(abs(point[0]), abs(point[1])) < edge:
                        out.setdefault(point, len(out))
    return out


def _form(z: _Point, unknowns: dict[_Point, int]) -> dict[int, Fraction]:
    """``phi(z)`` as a linear form in the unknowns (zero outside the box)."""
    cell = (_nearest(z[0]), _nearest(z[1]))
    if max(abs(cell[0]), abs(cell[1])) > _RADIUS:
        return {}
    k, u, v = _locate((z[0] - cell[0], z[1] - cell[1]))
    form: dict[int, Fraction] = {}
    for index, weight in zip(bezier_indices(2), bernstein(2, u, v)):
        unknown = unknowns.get(_domain_point(cell, k, index))
        if unknown is not None and weight:
            form[unknown] = form.get(unknown, Fraction(0)) + weight
    return form


def _nearest(t: Fraction) -> int:
    return int((t + Fraction(1, 2)) // 1)


def _null_space(rows: list[dict[int, Fraction]], size: int) -> list[list[Fraction]]:
    """A basis of the rational null space of the sparse rows (FLINT's exact elimination)."""
    matrix = flint.fmpq_mat(len(rows), size)
    for r, row in enumerate(rows):
        for c, value in row.items():
            matrix[r, c] = flint.fmpq(value.numerator, value.denominator)
    reduced, rank = matrix.rref()
    pivots = [next(c for c in range(size) if reduced[r, c] != 0) for r in range(rank)]
    basis = []
    for free in sorted(set(range(size)) - set(pivots)):
        vector = [Fraction(0)] * size
        vector[free] = Fraction(1)
        for r, c in enumerate(pivots):
            entry = reduced[r, free]
            vector[c] = -Fraction(int(entry.p), int(entry.q))
        basis.append(vector)
    return basis


def four_direction_patch(corner_weights: Sequence[Any]) -> FourDirectionPatch:
    """The regular patch of the dual quad scheme with this corner rule (exact rationals: ``Fraction``, ``int``, sympy's
    or FLINT's; module docstring), or :class:`~symdecomp.errors.InvalidSchemeError` when its regular part is no
    continuous piecewise quadratic here."""
    if isinstance(corner_weights, (str, bytes)) or not isinstance(corner_weights, Sequence):
        raise InvalidTypeError(f"corner_weights must be a sequence of 4 rationals, got {type(corner_weights).__name__}")
    try:
        weights = tuple(to_fraction(w) for w in corner_weights)
    except InvalidInputError as exc:
        raise InvalidTypeError(f"corner_weights must be exact rationals: {exc}") from None
    if len(weights) != 4:
        raise InvalidSchemeError(f"corner rule ({', '.join(map(str, weights))}): a quad face has 4 corners, "
                                 f"got {len(weights)} weights")
    return _derive(weights)


@cache  # keyed on a tuple of Fractions (normalised by four_direction_patch): the derivation is exact and takes seconds
def _derive(weights: tuple[Fraction, ...]) -> FourDirectionPatch:
    name = f"corner rule ({', '.join(map(str, weights))})"
    mask = refinement_mask(weights)
    unknowns = _unknowns()
    half, rows = Fraction(1, 2), []
    steps = range(-8 * _RADIUS - 4, 8 * _RADIUS + 5)
    for i in steps:
        for j in steps:
            y = (Fraction(i, 8), Fraction(j, 8))
            row = _form(y, unknowns)
            for (a, b), weight in mask.items():
                if weight:
                    for c, value in _form((2 * y[0] - a - half, 2 * y[1] - b - half), unknowns).items():
                        row[c] = row.get(c, Fraction(0)) - weight * value
            if any(row.values()):
                rows.append(row)
    basis = _null_space(rows, len(unknowns))
    if len(basis) != 1:
        what = "has no solution there" if not basis else f"has {len(basis)} independent solutions there"
        raise InvalidSchemeError(f"{name}: its regular part is no continuous piecewise quadratic on the four-direction "
                                 f"mesh (the refinement equation {what})")
    return _patch(weights, basis[0], unknowns)


def _patch(weights: tuple[Fraction, ...], vector: list[Fraction], unknowns: dict[_Point, int]) -> FourDirectionPatch:
    """The patch over the cell centred at 0 from the solved basis function, normalised by the partition of unity."""
    def phi(point: _Point) -> Fraction:
        unknown = unknowns.get(point)
        return Fraction(0) if unknown is None else vector[unknown]

    scale = sum((phi((Fraction(-i), Fraction(-k))) for i in range(-_RADIUS, _RADIUS + 1)
                 for k in range(-_RADIUS, _RADIUS + 1)), Fraction(0))
    if scale == 0:
        raise InvalidSchemeError(f"corner rule ({', '.join(map(str, weights))}): its refinable function sums to 0 over "
                                 "its translates (no partition of unity)")
    reach = [p for p in unknowns if vector[unknowns[p]] and max(abs(p[0]), abs(p[1])) > Fraction(3, 2)]
    if reach:
        raise InvalidSchemeError(f"corner rule ({', '.join(map(str, weights))}): its basis function reaches beyond the "
                                 "3 x 3 control points of a cell (a patch here has nine)")
    coefficients = tuple(
        tuple(tuple(phi(_domain_point((-b[0], -b[1]), k, index)) / scale for index in bezier_indices(2)) for b in OFFSETS)
        for k in range(4))
    dependent = all(sum((coefficients[k][m][i] * (1 - 2 * ((b[0] + b[1]) % 2)) for m, b in enumerate(OFFSETS)), Fraction(0)) == 0
                    for k in range(4) for i in range(6))
    return FourDirectionPatch(weights, coefficients, _is_c1(phi), dependent)


def _gradient(net: list[Fraction], k: int, u: Fraction, v: Fraction) -> tuple[Fraction, Fraction]:
    """The ``(x, y)`` gradient of triangle ``k``'s quadratic at its parameters ``(u, v)``."""
    du = bezier_value(bezier_derivative(net, 2, "u"), 1, u, v)
    dv = bezier_value(bezier_derivative(net, 2, "v"), 1, u, v)
    (ax, ay), (bx, by) = CORNERS[k], CORNERS[(k + 1) % 4]
    det = ax * by - ay * bx
    return (du * by - ay * dv) / det, (ax * dv - bx * du) / det


#: The edges of the mesh as pairs of (cell step, triangle, parameters) that meet: the diagonal through ``r_(k+1)``
#: between triangles ``k`` and ``k + 1`` of one cell, and the sides ``x = 1/2`` and ``y = 1/2`` with the next cell's.
_ONE, _ZERO = Fraction(1), Fraction(0)
_JOINS = tuple(
    [(((0, 0), k, (_ZERO, _ZERO)), ((0, 0), (k + 1) % 4, (_ZERO, _ZERO))) for k in range(4)]
    + [(((0, 0), k, (_ZERO, _ONE)), ((0, 0), (k + 1) % 4, (_ONE, _ZERO))) for k in range(4)]
    + [(((0, 0), 0, (_ONE, _ZERO)), ((1, 0), 2, (_ZERO, _ONE))), (((0, 0), 0, (_ZERO, _ONE)), ((1, 0), 2, (_ONE, _ZERO))),
       (((0, 0), 1, (_ONE, _ZERO)), ((0, 1), 3, (_ZERO, _ONE))), (((0, 0), 1, (_ZERO, _ONE)), ((0, 1), 3, (_ONE, _ZERO)))])


def _is_c1(phi: Callable[[_Point], Fraction]) -> bool:
    """Whether the piecewise quadratic ``phi`` has one gradient at both ends of every edge in the box (the gradient is
    linear on each triangle, so then it is continuous along the whole edge)."""
    def gradient(cell: tuple[int, int], k: int, at: tuple[Fraction, Fraction]) -> tuple[Fraction, Fraction]:
        return _gradient([phi(_domain_point(cell, k, index)) for index in bezier_indices(2)], k, *at)

    box = range(-_RADIUS - 1, _RADIUS + 1)
    return all(gradient((p + a[0][0], q + a[0][1]), a[1], a[2]) == gradient((p + b[0][0], q + b[0][1]), b[1], b[2])
               for p in box for q in box for a, b in _JOINS)
