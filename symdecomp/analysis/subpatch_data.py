"""Stam's sub-patch data of a boundary or corner vertex, exact: the 2-ring's matrix, the sub-patches' rows, the limit.

A boundary vertex ``O`` with ``k`` faces (:meth:`~symdecomp.schemes.sector.SharpVertex.boundary`, or
tagged as a corner, :meth:`~symdecomp.schemes.sector.SharpVertex.corner`) has ``k`` patches, one per
face ``s = 0..k-1`` of its open fan, each with parameters ``(u, v)``: ``u`` along the ray ``O -> a_s``,
``v`` along ``O -> a_{s+1}`` (quads: ``[0, 1]^2``; triangles: ``u, v >= 0``, ``u + v <= 1``). Their
control net is the closed 2-ring of the vertex (``K`` points in
:meth:`~symdecomp.schemes.sector.SharpVertex.ring_labels` order), and the data that evaluate them are
*exact rationals*:

* ``matrix``: the ``K x K`` one-step subdivision matrix ``A`` of the 2-ring
  (:func:`~symdecomp.schemes.sector.exact_sharp_matrix`, the whole mesh refined with the sharp rules);
* ``patches[s][j]``: the control points of the regular sub-patch ``j`` of face ``s`` after one
  refinement, as rows over the ``K`` coarse points: rows of the 3-ring matrix (the refined points at
  fine lattice distance 3 depend on the coarse 2-ring only, which is checked), with the phantom points
  beyond a sharp ray resolved by :func:`~symdecomp.schemes.sector_patch.sector_point` (the one home of
  the boundary patches: reflection on quads, mirror on triangles, derived there to reproduce the sharp
  rules). Sub-patches and their point order are the interior patch's
  (:data:`~symdecomp.schemes.patch.SUBPATCH_CORNERS`, :data:`~symdecomp.schemes.patch.TRIANGLE_SUBPATCHES`);
* ``limit``: the limit position mask, the exact left eigenvector of ``A`` for the eigenvalue 1
  (required simple), normalised to sum 1;
* ``spectrum``: the exact eigenstructure of ``A``: its characteristic polynomial factored over Q, each
  irreducible factor with its multiplicity and the number of independent eigenvectors per root (the
  rank of ``q(A)``); ``A`` is diagonalisable exactly when the two agree for every factor
  (:attr:`SharpPatchData.diagonalizable`). It is not: Catmull-Clark boundary ``k = 3..8`` (``1/4`` at odd
  ``k``, ``1/2`` at ``k = 4, 8``), corners at even ``k`` (``1/2``), Loop boundary ``k = 6`` and corners
  ``k = 3, 6`` (``1/2``) have Jordan blocks.

The patches are evaluated from these data by matrix powers, not eigenvectors (``A`` need not be diagonalisable):
:func:`symdecomp.analysis.evaluation.evaluate`.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> d = sharp_patch_data(catmull_clark(), SharpVertex.boundary(3, "quad"))
>>> d.size, len(d.patches), d.limit[0]
(21, 3, Fraction(2, 3))
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import flint

from symdecomp.algebra.numbers import to_fraction
from symdecomp.algebra.small_eigen import nullspace
from symdecomp.errors import InternalError, NotApplicableError
from symdecomp.schemes.box_spline import BOX_POINTS, regular_patch
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice
from symdecomp.schemes.patch import SUBPATCH_CORNERS, TRIANGLE_SUBPATCHES
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, exact_sharp_matrix
from symdecomp.schemes.sector_patch import check_spline_sharp_rules, sector_point
from symdecomp.validate import cached, check_type

__all__ = ["SharpPatchData", "sharp_patch_data", "subpatch_points", "limit_mask", "exact_spectrum"]

#: A sparse row over the 2-ring's points: ``{column: weight}``.
Row = dict[int, Fraction]


@dataclass(frozen=True)
class SharpPatchData:
    """The exact data that evaluate the ``k`` patches of a boundary or corner vertex (module docstring;
    :func:`symdecomp.analysis.evaluation.evaluate` evaluates them)."""

    #: The scheme's name (files and reports).
    scheme: str
    #: The vertex: an open fan of one sector (``SharpVertex.boundary`` or ``.corner``).
    vertex: SharpVertex
    #: ``K x K`` rows of ``A`` as sparse ``{column: Fraction}``.
    matrix: tuple[Row, ...]
    #: ``patches[s][j]``: the rows (sparse ``{column: Fraction}``) of sub-patch ``j`` of face ``s``.
    patches: tuple[tuple[tuple[Row, ...], ...], ...]
    #: The limit position mask (``K`` Fractions, summing to 1).
    limit: tuple[Fraction, ...]
    #: ``(factor, multiplicity, eigenvectors)``: the characteristic polynomial's irreducible factors over Q
    #: (integer coefficients, constant term first), their multiplicities and eigenvectors per root.
    spectrum: tuple[tuple[tuple[int, ...], int, int], ...] = ()

    @property
    def diagonalizable(self) -> bool:
        """Whether ``A`` has an eigenvector basis (every factor's eigenvectors equal its multiplicity)."""
        return all(e == g for _, e, g in self.spectrum)

    @property
    def lattice(self) -> Lattice:
        return self.vertex.lattice

    @property
    def size(self) -> int:
        """``K``: the points of the closed 2-ring."""
        return len(self.matrix)

    @property
    def faces(self) -> int:
        return self.vertex.faces

    @property
    def kind(self) -> str:
        return "corner" if self.vertex.corner else "boundary"


def subpatch_points(lat: Lattice, j: int) -> tuple[tuple[int, int], ...]:
    """The refined lattice points ``(x, y)`` of the control points of sub-patch ``j`` (the interior patch's order)."""
    if lat.handled("the sub-patches' control points", BICUBIC, BOX_SPLINE) == BICUBIC:
        cu, cv = SUBPATCH_CORNERS[j]
        return tuple((cu + a - 1, cv + b - 1) for b in range(4) for a in range(4))
    (cu, cv), sigma = TRIANGLE_SUBPATCHES[j]
    return tuple((cu + sigma * bu, cv + sigma * bv) for bu, bv in BOX_POINTS)


def _check_vertex(given: object) -> SharpVertex:
    vertex: SharpVertex = check_type(given, SharpVertex, "vertex", hint="SharpVertex.boundary(k, lattice) or .corner(k, lattice)")
    if vertex.closed or len(vertex.sectors) != 1 or vertex.sharpness != float("inf"):
        raise NotApplicableError(f"{vertex!r}: evaluation data are for boundary and corner vertices (one open sector)")
    return vertex


def _fmpq_rows(m: flint.fmpq_mat, columns: int) -> list[Row]:
    rows: list[Row] = []
    for i in range(m.nrows()):
        row = {c: to_fraction(m[i, c]) for c in range(m.ncols()) if m[i, c] != 0}
        if any(c >= columns for c in row):
            raise InternalError(f"refined point {i} depends on a point outside the 2-ring")
        rows.append(row)
    return rows


def limit_mask(rows: Sequence[Row], size: int) -> tuple[Fraction, ...]:
    """The exact left eigenvector for 1 of the matrix with sparse ``rows``, summing to 1 (1 must be simple)."""
    shifted = [[Fraction(0)] * size for _ in range(size)]
    for i, row in enumerate(rows):
        for c, w in row.items():
            shifted[c][i] = w  # the transpose
    for i in range(size):
        shifted[i][i] -= 1
    null = nullspace(shifted)
    if len(null) != 1:
        raise NotApplicableError(f"the eigenvalue 1 of the 2-ring matrix has {len(null)} left eigenvectors; the limit "
                                 "position mask needs it simple")
    vec = null[0]
    total = sum(vec)
    return tuple(x / total for x in vec)


@cached(64, scheme=check_scheme, vertex=_check_vertex)
def sharp_patch_data(scheme: Scheme, vertex: SharpVertex) -> SharpPatchData:
    """The exact evaluation data of the boundary or corner ``vertex`` under ``scheme`` (module docstring)."""
    scheme, vertex = check_scheme(scheme), _check_vertex(vertex)
    check_spline_sharp_rules(scheme.sharp, f"scheme {scheme.name!r}")
    if scheme.sharp.near_edge_centre is not None or scheme.sharp.near_edge_end is not None:
        # the modified rule acts on the edges at O on every level, inside the sub-patches' nets: no spline there
        raise NotApplicableError(f"scheme {scheme.name!r}: its modified rules for smooth edges at a sharp vertex make the "
                                 "patches next to the vertex non-splines; evaluation data need the standard edge rule")
    box_spline = scheme.lattice.handled('the regular patch', BICUBIC, BOX_SPLINE) == BOX_SPLINE
    if box_spline and regular_patch(scheme).coefficients != regular_patch().coefficients:
        raise NotApplicableError(f"scheme {scheme.name!r}: its regular patch is not Loop's box spline")
    labels2 = vertex.ring_labels(2)
    size = len(labels2)
    rows3 = _fmpq_rows(exact_sharp_matrix(scheme, vertex, rings=3), size)
    index3 = {lab: i for i, lab in enumerate(vertex.ring_labels(3))}
    matrix = tuple(rows3[:size])
    patches = []
    for s in range(vertex.faces):
        face = []
        for j in range(3):
            sub = []
            for x, y in subpatch_points(vertex.lattice, j):
                row: Row = {}
                for w, lab in sector_point(vertex.lattice, vertex.faces, s, x, y):
                    for c, a in rows3[index3[lab]].items():
                        row[c] = row.get(c, 0) + w * a
                sub.append({c: a for c, a in row.items() if a != 0})
            face.append(tuple(sub))
        patches.append(tuple(face))
    return SharpPatchData(scheme.name, vertex, matrix, tuple(patches), limit_mask(matrix, size), exact_spectrum(matrix, size))


def exact_spectrum(rows: Sequence[Row], size: int) -> tuple[tuple[tuple[int, ...], int, int], ...]:
    """The factored characteristic polynomial of the matrix with sparse ``rows``, with eigenvectors per root (exact).

    A factor ``q`` of multiplicity ``e > 1`` has ``(size - rank q(A)) / deg q`` eigenvectors per root;
    ``e = 1``: one. Factors sorted by degree, then coefficients (deterministic files).
    """
    a = flint.fmpq_mat(size, size)
    for i, row in enumerate(rows):
        for c, w in row.items():
            a[i, c] = flint.fmpq(w.numerator, w.denominator)
    _, factors = a.charpoly().factor()
    eye = flint.fmpq_mat(size, size, [int(i == j) for i in range(size) for j in range(size)])
    out = []
    for q, e in factors:
        coeffs = tuple(int(c) for c in q.numer().coeffs())
        if e == 1:
            out.append((coeffs, 1, 1))
            continue
        value = flint.fmpq_mat(size, size)
        for coefficient in reversed(q.coeffs()):  # Horner: q(A)
            value = value * a + eye * coefficient
        _, rank = value.rref()
        out.append((coeffs, e, (size - rank) // q.degree()))
    return tuple(sorted(out, key=lambda f: (len(f[0]), f[0], f[1])))
