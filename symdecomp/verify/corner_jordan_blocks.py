"""The Jordan chain of ``1/2`` at a corner from the sector's blocks: the 1-ring block over the field, the rest rational.

The sector's 2-ring matrix is block lower triangular, ``S = [[T, 0], [X, U]]``: the new 1-ring reads only the old one
(``T``, the one-step matrix of the corner, whose near-edge rows hold BLZ's weight in ``Q(cos(pi/k))``), and the outer
points hold only the regular and crease rules (``X``, ``U``; checked to be rational, exactly). With ``h = 1/2`` and
``U - h I`` invertible (exactly: FLINT's rational solve), the map ``v -> (v, y(v))`` is an isomorphism from
``ker (T - h)^p`` onto ``ker (S - h)^p`` for ``p = 1, 2``, where the tail solves

    ``(U - h) y(v) = y((T - h) v) - X v``    (``y(0) = 0``; the recursion stops because ``(T - h)^2 v = 0``),

so that ``(S - h) (v, y(v)) = ((T - h) v, y((T - h) v))``: the chain ``A g = e`` on the 1-ring lifts to the chain on the
2-ring. Where the three ``1/2``'s sit: all in ``T`` (``U - h`` is invertible), two in its mirror-even part (the crease
block's even boundary tangent and sine block ``j = 1``, whose mode is even) and one in the odd part (the crease block's
odd tangent, a plain eigenvector); the chain's ``e`` is mirror-even (the tests check it exactly), so the Jordan block
joins the even tangent and the sine mode. So the dimensions, the chain and the eigenvectors come from the ``(2k + 2)``-point 1-ring block (quads;
``k + 2`` on triangles) and rational solves, not from the whole matrix. The kernels of ``T - h`` and ``(T - h)^2`` are
computed by sparse elimination along the sector (columns by ray, ``O`` last): the 1-ring block is banded apart from
``O``'s column, so the number of field operations grows about linearly in ``k``, where the dense kernels of
:mod:`.corner_jordan` take ``k^3`` of them; each operation costs more as the field's degree ``phi(2k)/2`` and the
coefficients grow, so the measured time still grows about like ``k^3`` (:data:`BLOCK_JORDAN_FACES`).
Every lifted vector is checked on the whole matrix, exactly (``A e = 0``,
``A^2 g = 0``, ``A g = e != 0``), so a wrong lift raises instead of answering.

>>> from symdecomp.schemes.files import load_scheme
>>> found = block_jordan_chain(load_scheme("catmull-clark-blz"), 20)
>>> len(found.eigen), len(found.general), found.on_rays(found.chain[1])
(2, 3, False)
"""

from __future__ import annotations

from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.number_field import FieldElement
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.verify.corner_jordan import HALF, JordanChain, Rows, constant, shifted_rows, square, times
from symdecomp.verify.mirror_parts import SectorMatrices, sector_matrices

__all__ = ["BLOCK_JORDAN_FACES", "block_jordan_chain", "sparse_kernel", "ring_split"]

#: The most faces whose Jordan chain the C1 test computes from the blocks. Measured (one process, ``c1 --corner --k k:k
#: --scheme catmull-clark-blz``, start-up included): 3 s at 48 faces, 5 s at 64, 30 s at 128; the field's degree grows
#: with ``k`` (``phi(2k)/2``), so the exact work grows about like ``k^3`` and ``--k 1:1000`` is out of reach.
BLOCK_JORDAN_FACES = 64


def ring_split(sm: SectorMatrices) -> tuple[list[int], list[int]]:
    """``(ring, outer)``: the matrix indices of the 1-ring (by ray, ``O`` last) and of the points past it."""
    ring = [i for i, lab in enumerate(sm.labels) if sm.lattice.ring_of(lab[1], lab[2]) <= 1]
    ring.sort(key=lambda i: (sm.labels[i] == ORIGIN, sm.labels[i]))
    inner = set(ring)
    return ring, [i for i in range(len(sm.labels)) if i not in inner]


def sparse_kernel(rows: Rows, order: list[int], mod: flint.fmpq_poly) -> list[dict[int, FieldElement]]:
    """A basis of ``{x : A x = 0}`` for sparse rows ``A`` (``{row: {column: entry}}``) over ``Q[w]/(mod)``, exact.

    Forward elimination taking the columns in ``order`` (each pivot row the sparsest one holding the column), then one
    back-substitution per free column; the vectors are sparse (``{column: entry}``)."""
    live = {i: {c: x for c, x in r.items() if x} for i, r in rows.items()}
    holding: dict[int, set[int]] = {}
    for i, r in live.items():
        for c in r:
            holding.setdefault(c, set()).add(i)
    pivots: list[tuple[int, dict[int, FieldElement], FieldElement]] = []
    free = []
    for c in order:
        candidates = holding.get(c, set())
        if not candidates:
            free.append(c)
            continue
        p = min(candidates, key=lambda i: (len(live[i]), i))
        prow = live.pop(p)
        for c2 in prow:
            holding[c2].discard(p)
        inv = prow[c].inverse()
        for i in list(candidates):
            row, u = live[i], live[i][c] * inv
            for c2, x in prow.items():
                y = row.get(c2, constant(0, mod)) - u * x
                if y:
                    row[c2] = y
                    holding.setdefault(c2, set()).add(i)
                else:
                    row.pop(c2, None)
                    holding[c2].discard(i)
        pivots.append((c, prow, inv))
    return [_back_substitute(pivots, f, mod) for f in free]


def _back_substitute(pivots: list[tuple[int, dict[int, FieldElement], FieldElement]], free: int, mod: flint.fmpq_poly) -> dict[int, FieldElement]:
    x = {free: constant(1, mod)}
    for c, row, inv in reversed(pivots):
        total = constant(0, mod)
        for j, a in row.items():
            if j != c and j in x:
                total = total + a * x[j]
        if total:
            x[c] = (constant(0, mod) - total) * inv
    return x


def _rational(e: FieldElement) -> Fraction:
    if e.poly.degree() > 0:
        raise NotApplicableError("a point past the 1-ring reads the near-edge weight: the outer block is not rational")
    c = e.poly[0]
    return Fraction(int(c.p), int(c.q))


class _Lift:
    """The tails ``y(v)`` of the module docstring: ``(U - h) y(v) = y((T - h) v) - X v``, solved in ``Q`` per coordinate."""

    def __init__(self, A: Rows, ring: list[int], outer: list[int], mod: flint.fmpq_poly) -> None:
        self.A, self.ring, self.outer, self.mod = A, ring, outer, mod
        pos = {j: c for c, j in enumerate(outer)}
        U = flint.fmpq_mat(len(outer), len(outer))
        for r, i in enumerate(outer):
            for j, x in A[i].items():
                if j in pos:
                    q = _rational(x)
                    U[r, pos[j]] = flint.fmpq(q.numerator, q.denominator)
        self.U = U

    def tail(self, v: dict[int, FieldElement]) -> dict[int, FieldElement]:
        """``y(v)`` for ``v`` on the 1-ring with ``(T - h)^2 v = 0`` (``ZeroDivisionError``: ``U - h`` is singular)."""
        image = {i: t for i in self.ring if (t := self._row(i, v))}
        ahead = self.tail(image) if image else {}
        rhs = [ahead.get(i, constant(0, self.mod)) - self._row(i, v) for i in self.outer]
        d = self.mod.degree()
        B = flint.fmpq_mat(len(self.outer), d)
        for r, x in enumerate(rhs):
            for c in range(d):
                B[r, c] = x.poly[c]
        Y = self.U.solve(B)
        out = {}
        for r, i in enumerate(self.outer):
            y = FieldElement(flint.fmpq_poly([Y[r, c] for c in range(d)]), self.mod)
            if y:
                out[i] = y
        return out

    def _row(self, i: int, v: dict[int, FieldElement]) -> FieldElement:
        total = constant(0, self.mod)
        for j, x in self.A[i].items():
            if j in v:
                total = total + x * v[j]
        return total


def _dense(v: dict[int, FieldElement], n: int, mod: flint.fmpq_poly) -> list[FieldElement]:
    zero = constant(0, mod)
    return [v.get(i, zero) for i in range(n)]


def block_jordan_chain(scheme: Scheme, k: int, angle: sp.Expr | None = None) -> JordanChain:
    """The eigenvalue ``1/2`` of a corner sector of ``k`` faces from the 1-ring block and rational lifts (module
    docstring), every vector checked exactly on the whole matrix; the same :class:`~.corner_jordan.JordanChain` as
    :func:`~.corner_jordan.jordan_chain`, up to the kernels' bases."""
    vertex = SharpVertex.corner(k, scheme.lattice, angle)  # type: ignore[operator]  # corner: a property and a constructor
    sm = sector_matrices(scheme, vertex)
    A, mod = shifted_rows(sm, HALF)
    ring, outer = ring_split(sm)
    inner = set(ring)
    if any(j not in inner for i in ring for j in A[i]):
        raise NotApplicableError("the new 1-ring reads a point past the old one: the sector matrix is not block triangular")
    T = {i: A[i] for i in ring}
    lift = _Lift(A, ring, outer, mod)
    n = len(sm.labels)
    kernels = sparse_kernel(T, ring, mod), sparse_kernel(square(T, mod), ring, mod)
    try:
        eigen, general = ([_dense({**v, **lift.tail(v)}, n, mod) for v in basis] for basis in kernels)
    except ZeroDivisionError as exc:
        raise NotApplicableError("1/2 is an eigenvalue of the outer block: the 1-ring block does not hold its chain") from exc
    if any(any(times(A, x, mod)) for x in eigen) or any(any(times(A, times(A, g, mod), mod)) for g in general):
        raise NotApplicableError("a lifted vector of the 1-ring block's kernel is not in the whole matrix's kernel")
    chain = next(((g, e) for g, e in ((g, times(A, g, mod)) for g in general) if any(e)), None)
    return JordanChain(sm, mod, eigen, general, chain)
