"""The Loop patch next to an extraordinary vertex and its (N+6) x (N+6) subdivision matrix (Stam 1998).

Stam's exact evaluation of Loop surfaces reads the triangle ``(O, a_0, a_1)`` next to a vertex
of valence ``N`` from ``K = N + 6`` control points. Points sit on the ``(u, v)`` lattice of the
patch (the triangle is ``(0, 0), (1, 0), (0, 1)``: ``u`` along ``O -> a_0``, ``v`` along
``O -> a_1``; lattice edges along ``(1, 0)``, ``(0, 1)`` and ``(1, -1)``), a chart of the three
sectors ``N - 1, 0, 1`` around the patch. The order (this toolkit's, stated in the data file):

* ``0``: ``O``; ``1 .. N``: its neighbours ``a_0 .. a_{N-1}`` counter-clockwise
  (``a_0 = (1, 0)``, ``a_1 = (0, 1)``, ``a_2 = (-1, 1)``, ``a_{N-1} = (1, -1)``);
* ``N + 1 .. N + 5``: the regular points beyond the patch, :data:`OUTER_POINTS`;
* rows ``K .. K + 5`` of the extended matrix: :data:`EXTRA_POINTS`, the further points that
  the three regular sub-triangles of the refined patch need.

After one refinement the patch splits into four triangles; the three away from ``O`` are
regular, each the box-spline patch (:mod:`symdecomp.schemes.box_spline`) of 12 refined points.
Sub-patch ``k`` maps its local ``(s, t)`` to the refined lattice point ``c_k + sigma_k (s, t)``
and takes its point ``l`` at ``c_k + sigma_k BOX_POINTS[l]`` (:data:`SUBPATCHES`):
``k = 0`` next to ``a_0`` (``c = (1, 0)``, ``sigma = 1``), ``k = 1`` the middle one, upside
down (``c = (1, 1)``, ``sigma = -1``), ``k = 2`` next to ``a_1`` (``c = (0, 1)``, ``sigma = 1``).

The matrices are read off the exact 3-ring matrix of the scheme
(:func:`~symdecomp.schemes.rings.ring_subdivision_matrix`, one refinement of a valence-``N``
ring mesh by the mesh rules), which also checks that the new points depend on the ``K`` old
ones only. The centre's weights stay exact: Fractions, or elements of ``Q(zeta_2N)``
(:class:`~symdecomp.algebra.cyclotomic.Cyclotomic`) when irrational (Loop's ``cos(2 pi/N)``).

>>> from symdecomp.schemes.loop import loop
>>> p = triangle_patch_matrices(loop(), 6)
>>> p.size, len(p.sparse), p.sparse[0][0], p.sparse[1][0]
(12, 18, Fraction(5, 8), Fraction(3, 8))
"""

from __future__ import annotations

from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, cyclotomic_value
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.box_spline import BOX_POINTS
from symdecomp.schemes.lattice import TRIANGLE
from symdecomp.schemes.patch import PatchMatrices
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = [
    "OUTER_POINTS", "EXTRA_POINTS", "SUBPATCHES",
    "triangle_lattice_label", "triangle_patch_matrices", "triangle_patch_rows", "centre_weights", "position_mask",
]

#: The five control points beyond the patch (lattice points), in file order.
OUTER_POINTS = ((2, -1), (2, 0), (1, 1), (0, 2), (-1, 2))
#: The six further refined points the three regular sub-triangles need (rows K..K+5).
EXTRA_POINTS = ((3, -1), (3, 0), (2, 1), (1, 2), (-1, 3), (0, 3))
#: ``(corner, sigma)`` of sub-patch k = 0, 1, 2 on the refined lattice.
SUBPATCHES = (((1, 0), 1), ((1, 1), -1), ((0, 1), 1))


def triangle_lattice_label(n: int, point: tuple[int, int]) -> tuple[int, int, int]:
    """The ring-mesh label ``(s, u, v)`` (:func:`~symdecomp.schemes.trimesh.triangle_ring_labels`) of a lattice point."""
    x, y = point
    if x >= 0 and y >= 0:
        s, a, b = 0, x, y
    elif x <= 0 and y >= -x:
        s, a, b = 1, x + y, -x
    elif y <= 0 and x >= -y:
        s, a, b = n - 1, -y, x + y
    else:
        raise KeyError(f"lattice point {point} is outside the three sectors around the patch")
    if a == 0 and b == 0:
        return (0, 0, 0)
    return ((s + 1) % n, b, 0) if a == 0 else (s % n, a, b)


def triangle_patch_rows(n: int) -> tuple[tuple[int, int, int], ...]:
    """The labels of the ``n + 6`` control points and then of the 6 extra refined points, in row order."""
    n = check_valence(n)
    return ((0, 0, 0),) + tuple((i, 1, 0) for i in range(n)) + tuple(triangle_lattice_label(n, p) for p in OUTER_POINTS + EXTRA_POINTS)


def _subpatch_rows(n: int, labels) -> tuple[tuple[int, ...], ...]:
    index = {lab: i for i, lab in enumerate(labels)}
    out = []
    for (cu, cv), sigma in SUBPATCHES:
        out.append(tuple(index[triangle_lattice_label(n, (cu + sigma * bu, cv + sigma * bv))] for bu, bv in BOX_POINTS))
    return tuple(out)


def _exact_weight(expr: sp.Expr, n: int):
    """A centre weight at valence ``n``: a Fraction, or an element of a cyclotomic field (exact)."""
    try:
        x = cyclotomic_value(expr, {N: n}, field=CyclotomicField(2 * n))
    except ValueError as exc:
        raise InvalidSchemeError(f"the centre weight {expr} at valence {n} is not in a cyclotomic field: {exc}") from None
    if x.poly.degree() <= 0:
        c = x.poly[0] if x.poly.degree() == 0 else flint.fmpq(0)
        return Fraction(int(c.p), int(c.q))
    return x


def centre_weights(scheme: Scheme, n: int) -> tuple:
    """``(on O, on each neighbour)`` of the vertex rule at valence ``n``, exact (Fraction or ``Q(zeta_2n)``)."""
    v = scheme.vertex_rule
    return tuple(_exact_weight(sp.sympify(w, strict=True), check_valence(n)) for w in (v.center, v.each_a))


def position_mask(scheme: Scheme, n: int) -> tuple:
    """The limit position mask ``(on O, on each neighbour)`` of a valence-``n`` vertex, exact.

    The left eigenvector for 1 of the 1-ring matrix is rotation invariant, so it solves the
    frequency-0 block ``[[w_O, n w_a], [e_O, 1 - e_O]]`` (``e_O``: the edge rule's weight on
    ``O``): ``l_O = e_O/(e_O + 1 - w_O)``, each neighbour ``(1 - l_O)/n``.
    """
    w_o, _ = centre_weights(scheme, n)
    e_o = Fraction(sp.Rational(scheme.edge_rule.center).p, sp.Rational(scheme.edge_rule.center).q)
    one = w_o.field(1) if isinstance(w_o, Cyclotomic) else Fraction(1)
    l_o = (one * e_o) / (one * e_o + one - w_o)
    return l_o, (one - l_o) / n


def triangle_patch_matrices(scheme: Scheme, n: int) -> PatchMatrices:
    """The ``(n + 6)``-point patch matrices of a triangle scheme at valence ``n`` (exact)."""
    n = check_valence(n)
    ring = ring_subdivision_matrix(scheme, n, 3)
    index = {lab: i for i, lab in enumerate(ring.labels)}
    labels = triangle_patch_rows(n)
    size = n + 6
    column = {index[lab]: c for c, lab in enumerate(labels[:size])}
    exprs = {sym: sp.sympify(w, strict=True) for sym, w in ring.weights.items()}
    sparse = []
    for lab in labels:
        row = {}
        for c, w in ring.rows[index[lab]].items():
            if c not in column:
                raise InvalidSchemeError(f"scheme {scheme.name!r}: the refined patch point {lab} depends on a point beyond the {size} control points")
            if not isinstance(w, Fraction):
                w = _exact_weight(sp.sympify(w, strict=True).xreplace(exprs), n)
            row[column[c]] = w
        sparse.append(row)
    rational = all(isinstance(w, Fraction) for w in sparse[0].values())
    matrix = extended = None
    if rational:
        extended = flint.fmpq_mat(len(sparse), size)
        for i, row in enumerate(sparse):
            for j, w in row.items():
                extended[i, j] = flint.fmpq(w.numerator, w.denominator)
        matrix = flint.fmpq_mat([[extended[i, j] for j in range(size)] for i in range(size)])
    return PatchMatrices(n, matrix, extended, _subpatch_rows(n, labels), tuple(sparse), size, TRIANGLE.one_ring_size(n), TRIANGLE)
