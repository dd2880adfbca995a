"""The patch next to an extraordinary vertex and its (2N+8) x (2N+8) subdivision matrix (Stam).

Stam's exact evaluation of Catmull-Clark surfaces reads the patch ``(O, e_2, f_1, e_1)`` next
to a vertex of valence ``N`` from ``K = 2N + 8`` control points, in the order fixed by the data
file's format note: ``O``, then ``e_0, f_0, ..., e_{N-1}, f_{N-1}`` (edge and face neighbours of
``O``), then seven regular points beyond the patch. Points are placed on the ``(u, v)`` lattice
of the patch (``u`` along ``O -> e_2``, ``v`` along ``O -> e_1``), which is a chart of the three
sectors around the patch.

The matrices are not typed in: they are read off one exact refinement of a valence-``N`` ring
mesh by the scheme's mesh rules (:func:`~symdecomp.schemes.mesh.refinement_matrix`), which also
asserts that the new points depend on the ``K`` old ones only.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> p = patch_matrices(catmull_clark(), 3)
>>> p.size, p.extended.nrows(), p.matrix[0, 0]
(14, 23, 5/12)
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import flint

from symdecomp.algebra.cyclotomic import to_acb
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.lattice import QUAD, Lattice
from symdecomp.schemes.mesh import refinement_matrix, ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import check_valence

__all__ = ["OUTER_POINTS", "EXTRA_POINTS", "SUBPATCH_CORNERS", "PatchMatrices", "patch_matrices", "lattice_index", "patch_mesh"]

#: The seven control points beyond the patch, (u, v) lattice coordinates, in file order.
OUTER_POINTS = ((2, 2), (2, 1), (2, 0), (2, -1), (1, 2), (0, 2), (-1, 2))
#: The nine further points one refinement needs for the three regular sub-patches (rows K..K+8).
EXTRA_POINTS = ((3, -1), (3, 0), (3, 1), (3, 2), (3, 3), (2, 3), (1, 3), (0, 3), (-1, 3))
#: Lower-left corner of sub-patch k = 0, 1, 2 on the lattice of the refined mesh.
SUBPATCH_CORNERS = ((1, 0), (1, 1), (0, 1))


def lattice_index(n: int, point: tuple[int, int]) -> int:
    """Row of the lattice point ``(u, v)`` among the ``2N + 17`` points of :attr:`PatchMatrices.extended`."""
    near = {(0, 0): 0, (-1, 0): 1, (-1, 1): 2, (0, 1): 3, (1, 1): 4, (1, 0): 5, (1, -1): 6, (0, -1): 1 + 2 * (3 % n)}
    if point in near:
        return near[point]
    if point in OUTER_POINTS:
        return 2 * n + 1 + OUTER_POINTS.index(point)
    if point in EXTRA_POINTS:
        return 2 * n + 8 + EXTRA_POINTS.index(point)
    raise KeyError(f"lattice point {point} is not a control point of the patch")


@dataclass(frozen=True)
class PatchMatrices:
    """The patch's subdivision matrices at valence ``n`` (exact).

    Quad meshes (Catmull-Clark): ``K = 2n + 8`` control points, the 1-ring first (``2n + 1``),
    sub-patches of 16 B-spline points. Triangle meshes (Loop,
    :mod:`symdecomp.schemes.triangle_patch`): ``K = n + 6``, the 1-ring ``n + 1``, sub-patches
    of 12 box-spline points. Either way the matrix is block lower triangular: the 1-ring block,
    then the regular points beyond it.
    """

    n: int
    #: ``K x K``: the control points after one refinement, in the same order (``None`` when the
    #: centre's weights are irrational, e.g. Loop's ``cos(2 pi/n)``: see :attr:`sparse`).
    matrix: flint.fmpq_mat | None
    #: ``(K + extra) x K``: ``matrix`` followed by the further points the sub-patches need (Stam's A-bar).
    extended: flint.fmpq_mat | None
    #: For k = 0, 1, 2, the rows of ``extended`` holding the control points of sub-patch k
    #: (quads: point ``l = a + 4 b`` at lattice ``corner + (a - 1, b - 1)``; triangles: see
    #: :mod:`symdecomp.schemes.triangle_patch`).
    subpatches: tuple[tuple[int, ...], ...]
    #: The rows of ``extended`` as sparse ``{column: weight}`` dicts: ``Fraction``, except in
    #: row 0 where an irrational centre weight is an exact element of a cyclotomic field.
    sparse: tuple[dict, ...]
    #: ``K``, the number of control points.
    size: int = 0
    #: Rows (and columns) ``0..ring_size - 1`` are the 1-ring: ``O`` and its neighbours.
    ring_size: int = 0
    #: The lattice (:data:`~symdecomp.schemes.lattice.QUAD` or :data:`~symdecomp.schemes.lattice.TRIANGLE`).
    lattice: Lattice = QUAD

    @property
    def mesh(self) -> str:
        """The lattice's name, as files and reports spell it."""
        return self.lattice.name

    def float_extended(self):
        """``extended`` as a float64 numpy array (irrational centre weights rounded)."""
        import numpy as np

        out = np.zeros((len(self.sparse), self.size))
        for i, row in enumerate(self.sparse):
            for j, w in row.items():
                out[i, j] = float(w) if isinstance(w, Fraction) else float(to_acb(w).real.mid())
        return out


def _chart(n: int, ids: dict):
    """Lattice point of the coarse mesh -> ring-mesh vertex id (three sectors around the patch)."""

    def vid(u: int, v: int) -> int:
        if u >= 0 and v >= 0:
            s, a, b = 1, v, u
        elif u <= 0 and v >= 0:
            s, a, b = 0, -u, v
        elif u >= 0 and v <= 0:
            s, a, b = 2, u, -v
        else:
            raise KeyError((u, v))
        if a == 0 and b == 0:
            return 0
        if a == 0:
            s, a, b = s + 1, b, 0
        return ids[(s % n, a, b)]

    return vid


def _refined_element(vid, point: tuple[int, int]):
    """The coarse element whose refined point sits at the fine lattice point ``point``."""
    u, v = point
    us = (u // 2,) if u % 2 == 0 else (u // 2, u // 2 + 1)
    vs = (v // 2,) if v % 2 == 0 else (v // 2, v // 2 + 1)
    return frozenset(vid(a, b) for a in us for b in vs)


def patch_mesh(n: int, values=None):
    """``(mesh, vid, columns)``: the 2-ring mesh of valence ``n``, lattice point -> vertex id, and the
    ids of the ``2n + 8`` control points in the patch order. ``values(s, u, v)`` as in
    :func:`~symdecomp.schemes.mesh.ring_mesh`."""
    n = check_valence(n)
    mesh = ring_mesh(n, 2, values)
    ids = {lab: i for i, lab in enumerate(ring_mesh_labels(n, 2))}
    vid = _chart(n, ids)
    o, a, b = mesh.one_ring(0, start=ids[(0, 1, 0)])
    columns = [o] + [x for i in range(n) for x in (a[i], b[i])] + [vid(*p) for p in OUTER_POINTS]
    return mesh, vid, columns


@lru_cache(maxsize=256)
def patch_matrices(scheme: Scheme, n: int) -> PatchMatrices:
    """The patch matrices of ``scheme`` at valence ``n`` from one exact refinement: ``2n + 8`` points
    on quad meshes, ``n + 6`` on triangle meshes (:func:`~symdecomp.schemes.triangle_patch.triangle_patch_matrices`)."""
    return scheme.lattice.patch_matrices(scheme, check_valence(n))


def quad_patch_matrices(scheme: Scheme, n: int) -> PatchMatrices:
    """Stam's ``(2n + 8)``-point patch matrices of a quad scheme at valence ``n`` (exact)."""
    n = check_valence(n)
    mesh, vid, columns = patch_mesh(n)
    o, a, b = mesh.one_ring(0, start=columns[1])
    rows = [o]
    for i in range(n):
        rows += [frozenset((o, a[i])), frozenset((o, a[i], b[i], a[(i + 1) % n]))]
    rows += [_refined_element(vid, p) for p in OUTER_POINTS + EXTRA_POINTS]
    entries = refinement_matrix(mesh, scheme, columns, rows)
    k = 2 * n + 8
    extended, matrix = flint.fmpq_mat(len(rows), k), flint.fmpq_mat(k, k)
    for i, row in enumerate(entries):
        for j, w in row.items():
            if not isinstance(w, Fraction):
                raise InvalidSchemeError(f"scheme {scheme.name!r}: weight {w} at valence {n} is not rational")
            extended[i, j] = flint.fmpq(w.numerator, w.denominator)
            if i < k:
                matrix[i, j] = extended[i, j]
    subpatches = tuple(
        tuple(lattice_index(n, (cu + a_ - 1, cv + b_ - 1)) for b_ in range(4) for a_ in range(4)) for cu, cv in SUBPATCH_CORNERS
    )
    return PatchMatrices(n, matrix, extended, subpatches, tuple(entries), k, QUAD.one_ring_size(n), QUAD)
