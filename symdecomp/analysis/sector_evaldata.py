"""Evaluation data at crease, boundary and corner vertices, standard and Biermann-Levin-Zorin rules (Stam's method).

A vertex ``O`` with infinitely sharp edges (:class:`~symdecomp.schemes.sector.SharpVertex`: a crease, two sectors
of a closed fan; a boundary or corner, one open sector) on quads has one patch per face ``s``, parameters
``(u, v)`` in ``[0, 1]^2`` (``u`` along the ray ``O -> a_s``, ``v`` along ``O -> a_{s+1}``). Its control points
``C`` are the closed 2-ring (``K`` points, :meth:`~symdecomp.schemes.sector.SharpVertex.ring_labels` order).
The data (:func:`sector_evaldata`), exact rationals (FLINT ``fmpq``) when the rules are rational there, else
Arb balls that contain the exact values (BLZ's ``cos(pi/k)`` weights, ``k >= 4``):

* ``matrix``: ``A``, the ``K x K`` one-step matrix of the 2-ring (the tagged mesh refined with the scheme's rules,
  :func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`), and ``refine3``, the level-1 3-ring from the 2-ring;
* **which patches are splines**: every row of the 3-ring matrix at lattice distance 2 and 3 must be the regular
  rule (the tensor cubic B-spline's, through the phantom points of :mod:`symdecomp.schemes.sector_patch` across
  the sharp rays), else the data are refused; the rows at distance 1 that are not (``modified``: BLZ's near-edge
  points ``(s, 1, 0)``) make the level-``n`` cells that touch ``O``'s 1-ring non-splines: a cell
  ``[a, a+1] x [b, b+1]`` of the level-``n`` lattice is the spline of its 16 points when ``max(a, b) >= 2``
  (its refinement never reads a point at distance 1), and, with ``modified`` empty, for every cell;
* ``cells[s][c]``: the picking matrices of the twelve cells ``CELLS[c]`` (``2 <= max(a, b) <= 3``) of face ``s``,
  the ``16 x K`` map from the 2-ring at level ``n - 2`` to the cell's B-spline net at level ``n`` (net point
  ``(a - 1 + i, b - 1 + j)`` at row ``i + 4 j``): level-``n`` points up to distance 3 are ``refine3 A``, those
  at distance 4 and 5 the regular rule on the level-``(n - 1)`` 3-ring (``refine3``). These cells are splines
  for BLZ's rules too, so one table serves both (Stam's sub-patches at distance 1 to 2 are not, under BLZ);
* ``limit``: the limit position mask (left eigenvector of ``A`` for 1, summing to 1);
* ``decomposition`` (exact data): the eigen-decomposition of ``A`` over ``Q``, ``A W = W B``, one block of ``B``
  per irreducible factor ``q^e`` of the characteristic polynomial (the generalized eigenspace ``ker q(A)^e``;
  its roots as Arb balls in ``values``), so that ``A^m C = sum_i W_i B_i^m (W^-1 C)_i`` (Stam's expansion; a
  block is a Jordan block or a real block of conjugate roots when ``A`` is not diagonalizable over ``Q``). With
  balls there is no decomposition (``None``): the powers of ``A`` are taken.

Evaluation from the data: :mod:`symdecomp.analysis.sector_evaluation`; the eigen-decomposition over ``Q``:
:mod:`symdecomp.algebra.primary_decomposition`.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> d = sector_evaldata(catmull_clark(), SharpVertex.crease(2, 3, "quad"))
>>> d.size, d.exact, d.modified, len(d.cells), len(d.cells[0])
(31, True, (), 5, 12)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from itertools import accumulate

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.primary_decomposition import PrimaryBlock, decomposition
from symdecomp.errors import InternalError, InvalidInputError, NotApplicableError
from symdecomp.schemes.lattice import BICUBIC
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix
from symdecomp.schemes.sector_patch import ORIGIN, check_spline_sharp_rules, sector_point
from symdecomp.validate import cached, check_type

__all__ = ["CELLS", "PREC", "SectorEvalData", "sector_evaldata", "global_point", "regular_row", "real_ball", "matrix_numbers",
           "limit_mask"]

#: The cells ``(a, b)`` (lower-left corners, level-``n`` lattice) of a face's wide ring: ``2 <= max(a, b) <= 3``.
CELLS = tuple((a, b) for b in range(4) for a in range(4) if max(a, b) >= 2)
#: Bits of the Arb balls when the rules' weights are irrational.
PREC = 256


@dataclass(frozen=True)
class SectorEvalData:
    """The data that evaluate the patches of a crease, boundary or corner vertex (module docstring)."""

    #: The scheme's name.
    scheme: str
    #: The vertex (infinitely sharp edges).
    vertex: SharpVertex
    #: ``True``: exact rationals (``fmpq_mat``); ``False``: Arb balls (``arb_mat``) containing the exact values.
    exact: bool
    #: ``A``, ``K x K``.
    matrix: object
    #: The level-1 3-ring from the level-0 2-ring (its first ``K`` rows are ``A``); ``None`` when read from a file.
    refine3: object
    #: ``cells[s][c]``: the ``16 x K`` picking matrix of cell :data:`CELLS` ``[c]`` of face ``s``.
    cells: tuple
    #: The limit position mask (``K`` numbers summing to 1).
    limit: tuple
    #: Labels at distance 1 whose refinement rule is not the regular one (BLZ's near-edge points).
    modified: tuple
    #: The eigen-decomposition over ``Q`` (exact data), else ``None``.
    decomposition: tuple[PrimaryBlock, ...] | None
    #: ``phi[s][c][i]``: ``cells[s][c] W_i``, Stam's eigenbasis functions' nets (exact data), else ``None``.
    phi: tuple | None = None

    @property
    def size(self) -> int:
        return self.matrix.nrows()

    @property
    def faces(self) -> int:
        return self.vertex.faces

    @property
    def kind(self) -> str:
        if self.vertex.closed:
            return "crease"
        return "corner" if self.vertex.corner else "boundary"

    @property
    def inner_splines(self) -> bool:
        """Whether the cells at distance 1 to 2 (Stam's sub-patches) are splines too (no modified rule)."""
        return not self.modified


def _check_vertex(vertex) -> SharpVertex:
    vertex = check_type(vertex, SharpVertex, "vertex", hint="SharpVertex.crease(k1, k2, lattice), .boundary(k, lattice), ...")
    crease = vertex.closed and len(vertex.sectors) == 2
    if vertex.sharpness != math.inf or not (crease or (not vertex.closed and len(vertex.sectors) == 1)):
        raise NotApplicableError(f"{vertex!r}: sector evaluation data are for infinitely sharp creases (two sectors), "
                                 "boundary and corner vertices (one open sector)")
    return vertex


def _sector_of(vertex: SharpVertex, face: int) -> tuple[int, int]:
    """``(start, k)``: the first face and the faces of the sector that holds ``face``."""
    for start, k in zip(accumulate((0, *vertex.sectors)), vertex.sectors):
        if start <= face < start + k:
            return start, k
    raise InternalError(f"face {face} is not in a sector of {vertex!r}")


def global_point(vertex: SharpVertex, face: int, x: int, y: int) -> tuple:
    """The lattice point ``(x, y)`` of ``face``'s chart as ``((weight, label), ...)`` of the vertex's labels.

    Phantom points across the sector's sharp rays are :func:`~symdecomp.schemes.sector_patch.sector_point`'s.
    """
    start, k = _sector_of(vertex, face)
    out = []
    for w, (s, u, v) in sector_point(vertex.lattice, k, face - start, x, y):
        if (s, u, v) == ORIGIN:
            out.append((w, ORIGIN))
            continue
        g = start + s
        out.append((w, (g % vertex.faces if vertex.closed else g, u, v)))
    return tuple(out)


def _chart(vertex: SharpVertex, label) -> tuple[int, int, int]:
    s, u, v = label
    return (vertex.faces - 1, 0, u) if not vertex.closed and s == vertex.faces else (s, u, v)


def _spline_weights(x: int) -> dict:
    """The cubic B-spline's refinement weights of level-1 index ``x`` on the level-0 indices."""
    i, odd = divmod(x, 2)
    if odd:
        return {i: Fraction(1, 2), i + 1: Fraction(1, 2)}
    return {i - 1: Fraction(1, 8), i: Fraction(3, 4), i + 1: Fraction(1, 8)}


def regular_row(vertex: SharpVertex, label) -> dict:
    """``{coarse label: weight}``: the regular rule (tensor cubic B-spline, phantoms across sharp rays) for ``label``."""
    vertex.lattice.handled("the regular refinement rule of a sector", BICUBIC)
    face, X, Y = _chart(vertex, label)
    row: dict = {}
    for x, wx in _spline_weights(X).items():
        for y, wy in _spline_weights(Y).items():
            for w, lab in global_point(vertex, face, x, y):
                row[lab] = row.get(lab, 0) + w * wx * wy
    return {lab: w for lab, w in row.items() if w != 0}


def _sparse_sympy(scheme: Scheme, vertex: SharpVertex) -> list[dict]:
    m = sharp_subdivision_matrix(scheme, vertex, rings=3)
    rows: list[dict] = [{} for _ in range(m.rows)]
    for (i, j), w in m.todok().items():
        if w != 0:
            rows[i][j] = w
    return rows


def _spline_check(vertex: SharpVertex, rows: list[dict], labels: tuple) -> tuple:
    """The modified labels at distance 1; a row at distance 2 or 3 that is not the regular rule is refused."""
    index = {lab: i for i, lab in enumerate(labels)}
    modified = []
    for i, lab in enumerate(labels):
        if lab == ORIGIN:
            continue
        want = {index[c]: sp.Rational(w.numerator, w.denominator) for c, w in regular_row(vertex, lab).items()}
        if all(sp.expand(rows[i].get(c, 0) - want.get(c, 0)) == 0 for c in set(rows[i]) | set(want)):
            continue
        if vertex.lattice.ring_of(lab[1], lab[2]) >= 2:
            raise NotApplicableError(f"the refinement rule of the point {lab} is not the cubic B-spline's: the regular part "
                                     "of the sector is not a spline, so there are no evaluation data")
        modified.append(lab)
    return tuple(modified)


def real_ball(w: sp.Expr) -> flint.arb:
    """The real weight ``w`` (an exact expression such as ``3/8 - cos(pi/5)/4``) as an Arb ball containing it."""
    z = compile_expression(w, (), "arb")()
    if isinstance(z, flint.acb):
        if not z.imag.contains(0):
            raise InternalError(f"the weight {w} is not real")
        z = z.real
    return z


def matrix_numbers(rows: list[dict], ncols: int, exact: bool):
    """The sparse sympy ``rows`` as an ``fmpq_mat`` (exact) or an ``arb_mat`` (at the precision in force)."""
    out = (flint.fmpq_mat if exact else flint.arb_mat)(len(rows), ncols)
    for i, row in enumerate(rows):
        for j, w in row.items():
            if j >= ncols:
                raise InternalError(f"refined point {i} depends on a point outside the 2-ring")
            out[i, j] = to_fmpq(w) if exact else real_ball(w)
    return out


def _picking(vertex: SharpVertex, refine3, near, index3: dict, face: int, cell: tuple[int, int], exact: bool):
    """The ``16 x K`` picking matrix of ``cell`` of ``face`` (module docstring): ``Near . refine3 A + Far . refine3``."""
    a, b = cell
    size3 = refine3.nrows()
    first, second = flint.fmpq_mat(16, size3), flint.fmpq_mat(16, size3)
    for j in range(4):
        for i in range(4):
            for w, lab in global_point(vertex, face, a - 1 + i, b - 1 + j):
                if vertex.lattice.ring_of(lab[1], lab[2]) <= 3:
                    first[i + 4 * j, index3[lab]] += to_fmpq(w)
                    continue
                for c, wc in regular_row(vertex, lab).items():
                    second[i + 4 * j, index3[c]] += to_fmpq(w * wc)
    if not exact:
        first, second = flint.arb_mat(first), flint.arb_mat(second)
    return first * near + second * refine3


def limit_mask(matrix, exact: bool) -> tuple:
    """The left eigenvector of ``A`` for 1 summing to 1: the bordered system ``[[A^T - I, 1], [1^T, 0]]`` solved."""
    size = matrix.nrows()
    kind = flint.fmpq_mat if exact else flint.arb_mat
    bordered, rhs = kind(size + 1, size + 1), kind(size + 1, 1)
    for i in range(size):
        for j in range(size):
            bordered[i, j] = matrix[j, i] - (1 if i == j else 0)
        bordered[i, size] = bordered[size, i] = 1
    rhs[size, 0] = 1
    try:
        solution = bordered.solve(rhs)
    except (ZeroDivisionError, ValueError):
        raise NotApplicableError("the eigenvalue 1 of the 2-ring matrix is not simple (or not certified so): no limit "
                                 "position mask") from None
    return tuple(solution[i, 0] for i in range(size))


def _check_scheme_rules(scheme: Scheme, vertex: SharpVertex) -> None:
    if vertex.lattice is not scheme.lattice:
        raise InvalidInputError(f"scheme {scheme.name!r} lives on {scheme.lattice} meshes, the vertex on {vertex.lattice}")
    vertex.lattice.handled("sector evaluation data (the bicubic B-spline's cells)", BICUBIC)
    check_spline_sharp_rules(scheme.sharp, f"scheme {scheme.name!r}")


@cached(64, scheme=check_scheme, vertex=_check_vertex)
def sector_evaldata(scheme: Scheme, vertex: SharpVertex) -> SectorEvalData:
    """The evaluation data of the crease, boundary or corner ``vertex`` under ``scheme`` (module docstring)."""
    scheme, vertex = check_scheme(scheme), _check_vertex(vertex)
    _check_scheme_rules(scheme, vertex)
    labels3, size = vertex.ring_labels(3), len(vertex.ring_labels(2))
    rows = _sparse_sympy(scheme, vertex)[:len(labels3)]
    modified = _spline_check(vertex, rows, labels3)
    exact = all(w.is_Rational for row in rows for w in row.values())
    index3 = {lab: i for i, lab in enumerate(labels3)}
    with flint.ctx.workprec(PREC):
        refine3 = matrix_numbers(rows, size, exact)
        matrix = matrix_numbers(rows[:size], size, exact)
        near = refine3 * matrix
        cells = tuple(tuple(_picking(vertex, refine3, near, index3, s, cell, exact) for cell in CELLS)
                      for s in range(vertex.faces))
        limit = limit_mask(matrix, exact)
    blocks = decomposition(matrix) if exact else None
    phi = None if blocks is None else tuple(tuple(tuple(p * b.basis for b in blocks) for p in face) for face in cells)
    return SectorEvalData(scheme.name, vertex, exact, matrix, refine3, cells, limit, modified, blocks, phi)


