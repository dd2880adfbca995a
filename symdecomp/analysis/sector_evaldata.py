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

Evaluation at ``(u, v) != (0, 0)`` (:func:`evaluate`): the level ``n >= 2`` with ``2 < 2^n max(u, v) <= 4``,
``(x, y) = 2^n (u, v)``, the cell ``(a, b) = (min(floor x, 3), min(floor y, 3))`` and local ``(x - a, y - b)``,
then ``point = b(x - a, y - b) . cells[s][c] . A^(n-2) C`` with the bicubic B-spline basis ``b``. At ``(0, 0)``:
``limit . C``. Triangles (Loop's box spline) are not handled here (the lattice's fact is missing).

>>> from fractions import Fraction
>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> d = sector_evaldata(catmull_clark(), SharpVertex.crease(2, 3, "quad"))
>>> d.size, d.exact, d.modified, len(d.cells), len(d.cells[0])
(31, True, (), 5, 12)
>>> evaluate(d, 4, Fraction(1, 3), Fraction(1, 5), [[Fraction(1)]] * d.size)["point"]
[1]
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
from symdecomp.errors import EvaluationError, InternalError, InvalidInputError, NotApplicableError
from symdecomp.schemes.lattice import BICUBIC
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix
from symdecomp.schemes.sector_patch import ORIGIN, check_spline_sharp_rules, sector_point
from symdecomp.validate import cached, check_type

__all__ = ["CELLS", "PREC", "SectorEvalData", "PrimaryBlock", "sector_evaldata", "evaluate", "global_point", "regular_row", "real_ball"]

#: The cells ``(a, b)`` (lower-left corners, level-``n`` lattice) of a face's wide ring: ``2 <= max(a, b) <= 3``.
CELLS = tuple((a, b) for b in range(4) for a in range(4) if max(a, b) >= 2)
#: Bits of the Arb balls when the rules' weights are irrational.
PREC = 256


@dataclass(frozen=True)
class PrimaryBlock:
    """One block of the eigen-decomposition over ``Q``: the generalized eigenspace of a factor ``q^e``."""

    #: ``q``: integer coefficients, constant term first (irreducible over ``Q``).
    factor: tuple[int, ...]
    #: ``e``: its multiplicity in the characteristic polynomial.
    multiplicity: int
    #: Independent eigenvectors per root (``e`` when the block is diagonalizable).
    eigenvectors: int
    #: ``W_i``: ``K x (deg q * e)``, a basis of ``ker q(A)^e`` (columns).
    basis: flint.fmpq_mat
    #: ``B_i``: ``A`` on that basis, ``A W_i = W_i B_i``.
    block: flint.fmpq_mat
    #: The rows of ``W^-1`` that give this block's coordinates of ``C``.
    left: flint.fmpq_mat
    #: The roots of ``q`` as complex Arb balls (sorted by modulus, largest first).
    values: tuple


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


def _numbers(rows: list[dict], ncols: int, exact: bool):
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


def _limit(matrix, exact: bool) -> tuple:
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


def _nullspace(m: flint.fmpq_mat) -> flint.fmpq_mat:
    """A basis of ``ker m`` (columns), from the reduced row echelon form."""
    r, rank = m.rref()
    cols = m.ncols()
    pivots = [next(j for j in range(cols) if r[i, j] != 0) for i in range(rank)]
    free = [j for j in range(cols) if j not in pivots]
    out = flint.fmpq_mat(cols, len(free))
    for c, j in enumerate(free):
        out[j, c] = 1
        for i, p in enumerate(pivots):
            out[p, c] = -r[i, j]
    return out


def _poly_at(q, a: flint.fmpq_mat) -> flint.fmpq_mat:
    size = a.nrows()
    value = flint.fmpq_mat(size, size)
    for c in reversed(q.coeffs()):  # Horner
        value = value * a
        for i in range(size):
            value[i, i] += c
    return value


def _roots(q) -> tuple:
    roots = q.numer().complex_roots()
    return tuple(sorted((z for z, _ in roots), key=lambda z: -abs(z).mid()))


def decomposition(a: flint.fmpq_mat) -> tuple[PrimaryBlock, ...]:
    """The eigen-decomposition of ``A`` over ``Q`` (module docstring), blocks sorted by factor; exact."""
    size = a.nrows()
    _, factors = a.charpoly().factor()
    parts = []
    for q, e in sorted(factors, key=lambda f: (f[0].degree(), [int(c) for c in f[0].numer().coeffs()])):
        qa = _poly_at(q, a)
        power = qa
        for _ in range(e - 1):
            power = power * qa
        basis = _nullspace(power)
        if basis.ncols() != q.degree() * e:
            raise InternalError(f"the generalized eigenspace of {q} has dimension {basis.ncols()}, not {q.degree() * e}")
        eigenvectors = 1 if e == 1 else (size - qa.rref()[1]) // q.degree()
        parts.append((q, e, eigenvectors, basis))
    w = flint.fmpq_mat(size, size)
    col = 0
    for *_, basis in parts:
        for i in range(size):
            for j in range(basis.ncols()):
                w[i, col + j] = basis[i, j]
        col += basis.ncols()
    winv = w.inv()
    b_all = winv * a * w  # block diagonal: each generalized eigenspace is invariant (checked below)
    out, col = [], 0
    for q, e, g, basis in parts:
        d = basis.ncols()
        left = flint.fmpq_mat(d, size, [winv[col + i, j] for i in range(d) for j in range(size)])
        block = _columns(b_all, col, d)
        if basis * block != a * basis:
            raise InternalError(f"the generalized eigenspace of {q} is not invariant")
        out.append(PrimaryBlock(tuple(int(c) for c in q.numer().coeffs()), e, g, basis, block, left, _roots(q)))
        col += d
    return tuple(out)


def _columns(m: flint.fmpq_mat, col: int, d: int) -> flint.fmpq_mat:
    return flint.fmpq_mat(d, d, [m[col + i, col + j] for i in range(d) for j in range(d)])


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
        refine3 = _numbers(rows, size, exact)
        matrix = _numbers(rows[:size], size, exact)
        near = refine3 * matrix
        cells = tuple(tuple(_picking(vertex, refine3, near, index3, s, cell, exact) for cell in CELLS)
                      for s in range(vertex.faces))
        limit = _limit(matrix, exact)
    blocks = decomposition(matrix) if exact else None
    phi = None if blocks is None else tuple(tuple(tuple(p * b.basis for b in blocks) for p in face) for face in cells)
    return SectorEvalData(scheme.name, vertex, exact, matrix, refine3, cells, limit, modified, blocks, phi)


def _bspline(t, derivative: int) -> list:
    """The uniform cubic B-spline basis ``N_0..N_3`` (or a derivative) at ``t``, in the arithmetic of ``t``."""
    one = t * 0 + 1
    if derivative == 0:
        return [(one - t) ** 3 / 6, (3 * t**3 - 6 * t**2 + 4 * one) / 6, (-3 * t**3 + 3 * t**2 + 3 * t + one) / 6, t**3 / 6]
    return [-((one - t) ** 2) / 2, (9 * t**2 - 12 * t) / 6, (-9 * t**2 + 6 * t + 3 * one) / 6, t**2 / 2]


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


def _control_points(data: SectorEvalData, points):
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


def _times(a, b, ball: bool):
    if ball:
        a = a if isinstance(a, flint.arb_mat) else flint.arb_mat(a)
        b = b if isinstance(b, flint.arb_mat) else flint.arb_mat(b)
    return a * b


def _net(data: SectorEvalData, face: int, c: int, steps: int, control, ball: bool, route: str):
    """The level-``n`` B-spline net of cell ``c`` of ``face``: powers of ``A``, or the eigen-expansion."""
    if route == "powers" or data.decomposition is None:
        coarse = control
        for _ in range(steps):
            coarse = _times(data.matrix, coarse, ball)
        return _times(data.cells[face][c], coarse, ball)
    net = None
    for block, phi in zip(data.decomposition, data.phi[face][c]):
        coords = _times(block.left, control, ball)
        for _ in range(steps):  # B_i^m on this block's coordinates only
            coords = _times(block.block, coords, ball)
        term = _times(phi, coords, ball)
        net = term if net is None else net + term
    return net


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
        control, ball = _control_points(data, points)
        if u == 0 and v == 0:
            limit = flint.fmpq_mat(1, data.size, list(data.limit)) if data.exact else flint.arb_mat(1, data.size, list(data.limit))
            row = _times(limit, control, ball)
            return {"point": [row[0, j] for j in range(row.ncols())], "du": None, "dv": None, "level": None}
        n = _level(u, v, level)
        x, y = 2**n * u, 2**n * v
        a, b = min(math.floor(x), 3), min(math.floor(y), 3)
        net = _net(data, face, CELLS.index((a, b)), n - 2, control, ball, route)
        s, t = x - a, y - b
        if ball:
            s, t = flint.arb(s.numerator) / s.denominator, flint.arb(t.numerator) / t.denominator
        else:
            s, t = flint.fmpq(s.numerator, s.denominator), flint.fmpq(t.numerator, t.denominator)
        out: dict = {"level": n}
        for key, (ds, dt) in (("point", (0, 0)), ("du", (1, 0)), ("dv", (0, 1))):
            bs, bt = _bspline(s, ds), _bspline(t, dt)
            scale = 2 ** (n * (ds + dt))
            out[key] = [sum((bs[i] * bt[j] * net[i + 4 * j, k] for j in range(4) for i in range(4)), 0 * s) * scale
                        for k in range(net.ncols())]
        return out
