"""Evaluation data at an extraordinary face of a dual quad scheme whose regular part is the biquadratic B-spline (Stam's method).

Doo and Sabin's scheme (and a user's variant with other weights in the ``n``-gon) refines an ``n``-sided face
``F`` into a smaller ``n``-gon; every other face near it is a quad, and there the rule is the biquadratic B-spline's
(computed, not assumed: below). Around ``F`` there are ``n`` sectors; sector ``s`` is the quadrant of ``F``'s
corner ``P_s``, with chart coordinates in which the lattice points are half-integers, ``P_s = (1/2, 1/2)``,
``P_(s-1) = (1/2, -1/2)``, ``P_(s+1) = (-1/2, 1/2)`` (counter-clockwise), and parameters ``(u, v)`` in ``[0, 1]^2``
(``(0, 0)`` the limit point of ``F``; the edge ``v = 0`` of sector ``s`` is the edge ``u = 0`` of sector ``s - 1``).

The control points ``C`` are the zoo engine's neighbourhood of depth 2 (:func:`~symdecomp.analysis.zoo_matrix.zoo_matrix`:
``F`` and two rings of faces, ``K = 9n`` points in its orbit order) and the data (:func:`dual_evaldata`) are

* ``matrix``: ``A``, the exact ``K x K`` one-step matrix on that neighbourhood (the explicit mesh refined by the
  scheme's rules), exact rationals (FLINT ``fmpq``) when the rules are rational at ``n`` (Doo-Sabin: ``n = 3, 4, 6``),
  else Arb balls containing the exact values (``cos(2 pi j/n)``);
* **which patches are splines**: every row of ``A`` of a new point in a quad face (every face but ``F``) of the
  chart of every sector must be the biquadratic B-spline's corner rule (``3/4, 1/4`` in each direction: the tensor
  product of Chaikin's weights), else the data are refused; then at level ``m >= 1`` the vertex at
  ``(a + 1/2, b + 1/2)`` (level-``m`` units) with ``max(a, b) = 1`` has four quads and its patch, over the cell
  ``[a, a + 1] x [b, b + 1]``, is the biquadratic B-spline of its ``3 x 3`` points (their refinement never reads
  ``F``'s points again): the three cells :data:`CELLS` cover ``1 < 2^m max(u, v) <= 2``, and their scaled copies
  cover the sector;
* ``patches[s][c]``: the ``9 x K`` picking matrix of cell :data:`CELLS` ``[c]`` of sector ``s`` (grid point
  ``(a - 1/2 + i, b - 1/2 + j)`` at row ``i + 3 j``) from the level-``m`` neighbourhood ``A^m C``;
* ``limit``: the limit position mask (the left eigenvector of ``A`` for 1, summing to 1);
* ``decomposition`` (exact data): the eigen-decomposition of ``A`` over ``Q``
  (:func:`~symdecomp.algebra.primary_decomposition.decomposition`: one block per irreducible factor ``q^e`` of the
  characteristic polynomial, so Jordan blocks are handled: Doo-Sabin's ``A`` is not diagonalizable at ``n = 6``,
  where its ``n``-gon's eigenvalue ``1/4`` meets the regular part's; the engine's exact ranks by frequency,
  :mod:`symdecomp.analysis.zoo_jordan`, find Jordan blocks of ``1/4`` at ``n = 6, 7`` and none at ``n = 5``); with
  balls, ``None`` and the powers of ``A``, which need no eigenvector basis.

Evaluation: :mod:`symdecomp.analysis.dual_evaluation`; the certificate against exact refinement:
:mod:`symdecomp.verify.dual_evaldata`. Which families apply: :func:`spline_reason`.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> d = dual_evaldata(load_zoo("doo-sabin"), 4)
>>> d.size, d.exact, len(d.patches), len(d.patches[0]), [str(x) for x in d.limit[:4]]
(36, True, 4, 3, ['1/4', '1/4', '1/4', '1/4'])
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.primary_decomposition import PrimaryBlock, decomposition
from symdecomp.analysis.sector_evaldata import PREC, limit_mask, matrix_numbers
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.errors import InternalError, InvalidSchemeError, NotApplicableError
from symdecomp.schemes.halfedge import HalfedgeMesh
from symdecomp.schemes.lattice import BICUBIC, lattice
from symdecomp.schemes.neighbourhood import Neighbourhood
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import cached, check_type, check_valence

__all__ = ["CELLS", "DEPTH", "DualEvalData", "dual_evaldata", "sector_chart", "mesh_chart", "chart_index", "spline_reason"]

#: The cells ``(a, b)`` (lower-left corners, level-``m`` units) of a sector's ring: ``max(a, b) = 1``.
CELLS = ((1, 0), (1, 1), (0, 1))
#: The ring depth of the control points: ``F`` and two rings of faces (the ring patches' ``3 x 3`` points).
DEPTH = 2
#: Chaikin's weights: the quadratic B-spline's two-scale relation (nearer coarse point, farther one).
_CHAIKIN = (Fraction(3, 4), Fraction(1, 4))


@dataclass(frozen=True)
class DualEvalData:
    """The data that evaluate the ``n`` sectors around an extraordinary face (module docstring)."""

    #: The scheme's name.
    scheme: str
    #: The number of sides of the extraordinary face.
    n: int
    #: ``True``: exact rationals (``fmpq_mat``); ``False``: Arb balls (``arb_mat``) containing the exact values.
    exact: bool
    #: ``A``, ``K x K`` (``K = 9n``).
    matrix: object
    #: ``patches[s][c]``: the ``9 x K`` picking matrix of cell :data:`CELLS` ``[c]`` of sector ``s``.
    patches: tuple
    #: The limit position mask (``K`` numbers summing to 1).
    limit: tuple
    #: The eigen-decomposition over ``Q`` (exact data), else ``None``.
    decomposition: tuple[PrimaryBlock, ...] | None
    #: ``phi[s][c][i]``: ``patches[s][c] W_i`` (exact data), else ``None``.
    phi: tuple | None = None

    @property
    def size(self) -> int:
        return int(self.matrix.nrows())


def _in_window(x: int, y: int, reach: int) -> bool:
    """Doubled coordinates ``(2x, 2y)`` of sector 0's chart: ``x, y >= -1/2``, not both negative, within ``reach``."""
    return x >= -1 and y >= -1 and (x > 0 or y > 0) and max(x, y) <= reach


def sector_chart(nb: Neighbourhood) -> dict[tuple[int, int], int]:
    """``(2x, 2y) -> vertex id`` of sector 0's chart of a face-centred quad neighbourhood (module docstring)."""
    return mesh_chart(nb.mesh, nb.start, 2 * nb.depth + 1)


def mesh_chart(mesh: HalfedgeMesh, start: int, reach: int) -> dict[tuple[int, int], int]:
    """``(2x, 2y) -> vertex id`` of the chart of the sector whose corner is ``start``'s origin, up to ``max(2x, 2y) <= reach``.

    ``start`` is a halfedge ``P_s -> P_(s+1)`` of the centre face. Walks the quads only (``next`` turns left by a
    right angle, ``twin`` reverses); the window (``x, y >= -1/2``, not both negative) holds no second copy of a point.
    """
    centre_face, n = mesh.face[start], len(mesh.around_face(start))
    at: dict[tuple[int, int], int] = {}
    where: dict[int, tuple[int, int]] = {}
    seen: set[int] = set()
    queue = deque([(start, (1, 1), (-1, 0))])
    while queue:
        h, p, d = queue.popleft()
        if h in seen or not _in_window(*p, reach):
            continue
        seen.add(h)
        v = mesh.origin[h]
        if at.setdefault(p, v) != v or where.setdefault(v, p) != p:
            raise InternalError(f"the chart of the {n}-gon's sector is not a quad lattice at {p}")
        q = (p[0] + 2 * d[0], p[1] + 2 * d[1])
        queue.append((mesh.twin[h], q, (-d[0], -d[1])))
        if mesh.face[h] is not None and mesh.face[h] != centre_face:
            queue.append((mesh.next[h], q, (-d[1], d[0])))
    missing = [(x, y) for x in range(-1, reach + 1, 2) for y in range(-1, reach + 1, 2)
               if _in_window(x, y, reach) and (x, y) not in at]
    if missing:
        raise InternalError(f"the chart of the {n}-gon's sector misses the point {missing[0]}")
    return at


def chart_index(nb: Neighbourhood, chart: dict, sector: int) -> dict[tuple[int, int], int]:
    """``(2x, 2y) -> row`` of sector ``sector``'s chart: the rotation by ``sector`` of sector 0's points."""
    row = nb.index()
    by_label = {nb.labels[v]: v for v in nb.labels}
    out = {}
    for p, v in chart.items():
        s, c = nb.labels[v]
        out[p] = row[by_label[((s + sector) % nb.n, c)]]
    return out


def _two_scale(x: int) -> tuple[tuple[int, Fraction], tuple[int, Fraction]]:
    """The level-1 point at ``x / 2`` (level-1 units) in one direction: its face's nearer and farther coarse points
    (doubled level-0 coordinates) with Chaikin's weights; the face is the level-0 cell around ``round(x / 4)``."""
    face = round(x / 4)
    side = 1 if 4 * face < x else -1
    return (2 * face + side, _CHAIKIN[0]), (2 * face - side, _CHAIKIN[1])


def _expected_row(index: dict, x: int, y: int) -> dict[int, Fraction] | None:
    """The biquadratic corner rule of the level-1 point ``(x, y)`` (doubled level-1 units), or ``None`` in ``F``."""
    if (round(x / 4), round(y / 4)) == (0, 0):
        return None
    row: dict[int, Fraction] = {}
    for cx, wx in _two_scale(x):
        for cy, wy in _two_scale(y):
            if (cx, cy) not in index:
                return None
            row[index[(cx, cy)]] = wx * wy
    return row


def _is_zero(x: sp.Expr) -> bool:
    return bool(x == 0) if x.is_Number else sp.simplify(x) == 0


def _spline_check(name: str, matrix: sp.ImmutableMatrix, index: dict) -> None:
    """Every new point of a quad face in a sector's chart (``index``) takes the biquadratic rule; else refused."""
    for (x, y), r in sorted(index.items()):
        want = _expected_row(index, x, y)
        if want is None:
            continue
        got = {c: matrix[r, c] for c in range(matrix.cols) if matrix[r, c] != 0}
        if set(got) - set(want) or not all(_is_zero(got.get(c, 0) - sp.Rational(w.numerator, w.denominator))
                                           for c, w in want.items()):
            raise NotApplicableError(f"scheme {name!r}: the new point at ({x}/4, {y}/4) of a quad face is not the biquadratic "
                                     "B-spline's corner rule (3/4, 1/4 in each direction): its regular part is not that "
                                     "spline, so there are no evaluation data")


def spline_reason(scheme: StencilScheme) -> str | None:
    """``None`` when ``scheme``'s regular part is the biquadratic B-spline (the data apply), else why not, in one line."""
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    if scheme.interpolatory:
        return (f"scheme {scheme.name!r} is interpolatory: its regular part is not a spline, so Stam's method has no patch "
                "to evaluate")
    if scheme.topology != "dual" or scheme.steps != 1:
        return (f"scheme {scheme.name!r} takes {scheme.topology} steps on the {scheme.lattice} lattice: evaluation data of "
                "the zoo are for dual quad schemes whose regular part is the biquadratic B-spline (Doo-Sabin's)")
    try:
        dual_evaldata(scheme, 4)
    except InvalidSchemeError as exc:  # not the biquadratic rule, a lattice without that fact, no invariant neighbourhood
        return str(exc)
    return None


@cached(32, scheme=lambda s: check_type(s, StencilScheme, "scheme", hint="a StencilScheme"), n=check_valence)
def dual_evaldata(scheme: StencilScheme, n: int) -> DualEvalData:
    """The evaluation data of the ``n``-gon of the dual quad ``scheme`` (module docstring)."""
    if scheme.interpolatory or scheme.topology != "dual" or scheme.steps != 1:
        raise NotApplicableError(f"scheme {scheme.name!r}: evaluation data of the zoo are for dual quad schemes (one "
                                 f"step), not {scheme.topology} steps")
    lattice(scheme.lattice).handled("evaluation data of a dual scheme (the lattice's dual a quad lattice: biquadratic cells)",
                                    BICUBIC)
    zm = zoo_matrix(scheme, n, DEPTH)
    nb, a = zm.neighbourhood, zm.matrix
    chart = sector_chart(nb)
    indices = [chart_index(nb, chart, s) for s in range(n)]
    for index in indices:  # every sector: the rules are read at each point, not assumed to turn with the mesh
        _spline_check(scheme.name, a, index)
    rows = [{c: a[r, c] for c in range(a.cols) if a[r, c] != 0} for r in range(a.rows)]
    exact = all(w.is_Rational for row in rows for w in row.values())
    with flint.ctx.workprec(PREC):
        matrix = matrix_numbers(rows, a.cols, exact)
        patches = tuple(tuple(_picking(index, cell, a.cols, exact) for cell in CELLS) for index in indices)
        limit = limit_mask(matrix, exact)
    blocks = decomposition(matrix) if exact else None
    phi = None if blocks is None else tuple(tuple(tuple(p * b.basis for b in blocks) for p in face) for face in patches)
    return DualEvalData(scheme.name, n, exact, matrix, patches, limit, blocks, phi)


def _picking(index: dict, cell: tuple[int, int], size: int, exact: bool):
    """The ``9 x K`` selection of cell ``cell``'s ``3 x 3`` grid (row ``i + 3 j``) from the neighbourhood."""
    a, b = cell
    out = (flint.fmpq_mat if exact else flint.arb_mat)(9, size)
    for j in range(3):
        for i in range(3):
            out[i + 3 * j, index[(2 * a - 1 + 2 * i, 2 * b - 1 + 2 * j)]] = 1
    return out
