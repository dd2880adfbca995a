"""The patch next to an extraordinary vertex and its subdivision matrices (Stam): quads and triangles.

The lattice (:attr:`~symdecomp.schemes.lattice.Lattice.patch_matrices`) says which patch a
scheme has; either way the result is one :class:`PatchMatrices`, assembled by :func:`_assemble`.

**Quads**: the (2N+8) x (2N+8) matrix. Stam's exact evaluation of Catmull-Clark surfaces
reads the patch ``(O, e_2, f_1, e_1)`` next to a vertex of valence ``N`` from ``K = 2N + 8`` control points, in the order fixed by the data
file's format note: ``O``, then ``e_0, f_0, ..., e_{N-1}, f_{N-1}`` (edge and face neighbours of
``O``), then seven regular points beyond the patch. Points are placed on the ``(u, v)`` lattice
of the patch (``u`` along ``O -> e_2``, ``v`` along ``O -> e_1``), which is a chart of the three
sectors around the patch.

The matrices are not typed in: they are read off one exact refinement of a valence-``N`` ring
mesh by the scheme's mesh rules (:func:`~symdecomp.schemes.refinement.refinement_matrix`), which also
asserts that the new points depend on the ``K`` old ones only.

**Triangles**: the (N+6) x (N+6) matrix (Stam 1998). Stam's exact evaluation of Loop surfaces
reads the triangle ``(O, a_0, a_1)`` next to a vertex of valence ``N`` from ``K = N + 6`` control points. Points sit on the ``(u, v)`` lattice of the
patch (the triangle is ``(0, 0), (1, 0), (0, 1)``: ``u`` along ``O -> a_0``, ``v`` along
``O -> a_1``; lattice edges along ``(1, 0)``, ``(0, 1)`` and ``(1, -1)``), a chart of the three
sectors ``N - 1, 0, 1`` around the patch. The order (this toolkit's, stated in the data file):

* ``0``: ``O``; ``1 .. N``: its neighbours ``a_0 .. a_{N-1}`` counter-clockwise
  (``a_0 = (1, 0)``, ``a_1 = (0, 1)``, ``a_2 = (-1, 1)``, ``a_{N-1} = (1, -1)``);
* ``N + 1 .. N + 5``: the regular points beyond the patch, :data:`TRIANGLE_OUTER_POINTS`;
* rows ``K .. K + 5`` of the extended matrix: :data:`TRIANGLE_EXTRA_POINTS`, the further points that
  the three regular sub-triangles of the refined patch need.

After one refinement the patch splits into four triangles; the three away from ``O`` are
regular, each the box-spline patch (:mod:`symdecomp.schemes.box_spline`) of 12 refined points.
Sub-patch ``k`` maps its local ``(s, t)`` to the refined lattice point ``c_k + sigma_k (s, t)``
and takes its point ``l`` at ``c_k + sigma_k BOX_POINTS[l]`` (:data:`TRIANGLE_SUBPATCHES`):
``k = 0`` next to ``a_0`` (``c = (1, 0)``, ``sigma = 1``), ``k = 1`` the middle one, upside
down (``c = (1, 1)``, ``sigma = -1``), ``k = 2`` next to ``a_1`` (``c = (0, 1)``, ``sigma = 1``).

The matrices are read off the exact 3-ring matrix of the scheme
(:func:`~symdecomp.schemes.rings.ring_subdivision_matrix`, one refinement of a valence-``N``
ring mesh by the mesh rules), which also checks that the new points depend on the ``K`` old
ones only.

On either lattice, past :data:`REFERENCE_VALENCE` only the 1-ring's rows are refined at ``N``; the
rows of the points beyond it are the reference valence's, moved on the lattice (:func:`_transplanted`:
those points see only regular vertices, the same neighbourhood at every valence). The centre's weights stay exact:
Fractions, or elements of ``Q(zeta_2N)`` (:class:`~symdecomp.algebra.cyclotomic.Cyclotomic`) when irrational (Loop's ``cos(2 pi/N)``).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> p = patch_matrices(catmull_clark(), 3)
>>> p.size, p.extended.nrows(), p.matrix[0, 0]
(14, 23, 5/12)
>>> from symdecomp.schemes.loop import loop
>>> p = patch_matrices(loop(), 6)
>>> p.size, len(p.sparse), p.sparse[0][0], p.sparse[1][0]
(12, 18, Fraction(5, 8), Fraction(3, 8))
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, CyclotomicFunction, cyclotomic_value, to_acb
from symdecomp.algebra.numbers import to_fmpq, to_fraction
from symdecomp.errors import InvalidInputError, InvalidSchemeError, SymdecompError
from symdecomp.schemes.box_spline import BOX_POINTS
from symdecomp.schemes.lattice import QUAD, TRIANGLE, Lattice
from symdecomp.schemes.mesh import ring_mesh, ring_mesh_labels
from symdecomp.schemes.refinement import refinement_matrix
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.validate import cached, check_limit, check_valence

__all__ = [
    "OUTER_POINTS", "EXTRA_POINTS", "SUBPATCH_CORNERS", "PatchMatrices", "patch_matrices", "lattice_index", "patch_mesh",
    "TRIANGLE_OUTER_POINTS", "TRIANGLE_EXTRA_POINTS", "TRIANGLE_SUBPATCHES",
    "triangle_lattice_label", "triangle_patch_matrices", "triangle_patch_rows", "centre_weights", "position_mask",
]

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
    raise InvalidInputError(f"lattice point {point} is not a control point of the patch")


@dataclass(frozen=True)
class PatchMatrices:
    """The patch's subdivision matrices at valence ``n`` (exact).

    Quad meshes (Catmull-Clark): ``K = 2n + 8`` control points, the 1-ring first (``2n + 1``),
    sub-patches of 16 B-spline points. Triangle meshes (Loop): ``K = n + 6``, the 1-ring ``n + 1``,
    sub-patches of 12 box-spline points. Either way the matrix is block lower triangular: the 1-ring block,
    then the regular points beyond it.
    """

    n: int
    #: For k = 0, 1, 2, the rows of ``extended`` holding the control points of sub-patch k
    #: (quads: point ``l = a + 4 b`` at lattice ``corner + (a - 1, b - 1)``; triangles: point ``l``
    #: at ``corner + sigma BOX_POINTS[l]``, :data:`TRIANGLE_SUBPATCHES`).
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

    @functools.cached_property
    def extended(self) -> flint.fmpq_mat | None:
        """``(K + extra) x K``: :attr:`matrix` followed by the further points the sub-patches need (Stam's A-bar);
        ``None`` when the centre's weights are irrational (e.g. Loop's ``cos(2 pi/n)``: see :attr:`sparse`).
        Made from :attr:`sparse` when first read (the eigen-data file reads only the sparse rows)."""
        if not all(isinstance(w, Fraction) for row in self.sparse for w in row.values()):
            return None
        extended = flint.fmpq_mat(len(self.sparse), self.size)
        for i, row in enumerate(self.sparse):
            for j, w in row.items():
                extended[i, j] = to_fmpq(w)
        return extended

    @functools.cached_property
    def matrix(self) -> flint.fmpq_mat | None:
        """``K x K``: the control points after one refinement, in the same order (``None`` as :attr:`extended`)."""
        extended = self.extended
        if extended is None:
            return None
        return flint.fmpq_mat([[extended[i, j] for j in range(self.size)] for i in range(self.size)])

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


@cached(256, scheme=check_scheme, n=check_valence)
def patch_matrices(scheme: Scheme, n: int) -> PatchMatrices:
    """The patch matrices of ``scheme`` at valence ``n`` from one exact refinement: ``2n + 8`` points
    on quad meshes (:func:`quad_patch_matrices`), ``n + 6`` on triangle meshes (:func:`triangle_patch_matrices`)."""
    return scheme.lattice.patch_matrices(scheme, check_limit(check_valence(n), "patch_matrices(n)", "valence n"))


def quad_patch_matrices(scheme: Scheme, n: int) -> PatchMatrices:
    """Stam's ``(2n + 8)``-point patch matrices of a quad scheme at valence ``n`` (exact): from
    :data:`REFERENCE_VALENCE` on, its rows beyond the 1-ring are the reference valence's (:func:`_transplanted`)."""
    n = check_valence(n)
    return _transplanted(scheme, n, QUAD, _quad_subpatch_rows, rational=True) or _quad_by_refinement(scheme, n)


def _quad_by_refinement(scheme: Scheme, n: int) -> PatchMatrices:
    """:func:`quad_patch_matrices` read off one exact refinement of the 2-ring mesh at valence ``n``."""
    mesh, vid, columns = patch_mesh(n)
    o, a, b = mesh.one_ring(0, start=columns[1])
    rows = [o]
    for i in range(n):
        rows += [frozenset((o, a[i])), frozenset((o, a[i], b[i], a[(i + 1) % n]))]
    rows += [_refined_element(vid, p) for p in OUTER_POINTS + EXTRA_POINTS]
    entries = refinement_matrix(mesh, scheme, columns, rows)
    irrational = next((w for row in entries for w in row.values() if not isinstance(w, Fraction)), None)
    if irrational is not None:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: weight {irrational} at valence {n} is not rational")
    return _assemble(n, entries, _quad_subpatch_rows(n), 2 * n + 8, QUAD)


def _assemble(n: int, sparse: list[dict], subpatches, size: int, lat: Lattice) -> PatchMatrices:
    """The patch matrices from the sparse rows of the extended matrix (the ``size`` control points first).

    The FLINT matrices are made when first read, and exist when every weight is a Fraction (not when the
    centre's weights are irrational: then :attr:`PatchMatrices.sparse` holds them exactly).
    """
    return PatchMatrices(n, subpatches, tuple(sparse), size, lat.one_ring_size(n), lat)


# ---------------------------------------------------------------------------------------------
# triangles


#: The five control points beyond the patch (lattice points), in file order.
TRIANGLE_OUTER_POINTS = ((2, -1), (2, 0), (1, 1), (0, 2), (-1, 2))
#: The six further refined points the three regular sub-triangles need (rows K..K+5).
TRIANGLE_EXTRA_POINTS = ((3, -1), (3, 0), (2, 1), (1, 2), (-1, 3), (0, 3))
#: ``(corner, sigma)`` of sub-patch k = 0, 1, 2 on the refined lattice.
TRIANGLE_SUBPATCHES = (((1, 0), 1), ((1, 1), -1), ((0, 1), 1))


def triangle_lattice_label(n: int, point: tuple[int, int]) -> tuple[int, int, int]:
    """The ring-mesh label ``(s, u, v)`` (:meth:`~symdecomp.schemes.lattice.Lattice.ring_labels`) of a lattice point."""
    x, y = point
    if x >= 0 and y >= 0:
        s, a, b = 0, x, y
    elif x <= 0 and y >= -x:
        s, a, b = 1, x + y, -x
    elif y <= 0 and x >= -y:
        s, a, b = n - 1, -y, x + y
    else:
        raise InvalidInputError(f"lattice point {point} is outside the three sectors around the patch")
    if a == 0 and b == 0:
        return (0, 0, 0)
    return ((s + 1) % n, b, 0) if a == 0 else (s % n, a, b)


def triangle_patch_rows(n: int) -> tuple[tuple[int, int, int], ...]:
    """The labels of the ``n + 6`` control points and then of the 6 extra refined points, in row order."""
    n = check_valence(n)
    beyond = tuple(triangle_lattice_label(n, p) for p in TRIANGLE_OUTER_POINTS + TRIANGLE_EXTRA_POINTS)
    return ((0, 0, 0),) + tuple((i, 1, 0) for i in range(n)) + beyond


def _triangle_subpatch_rows(n: int, labels) -> tuple[tuple[int, ...], ...]:
    index = {lab: i for i, lab in enumerate(labels)}
    out = []
    for (cu, cv), sigma in TRIANGLE_SUBPATCHES:
        out.append(tuple(index[triangle_lattice_label(n, (cu + sigma * bu, cv + sigma * bv))] for bu, bv in BOX_POINTS))
    return tuple(out)


@functools.lru_cache(maxsize=256)
def _weight_function(expr: sp.Expr) -> CyclotomicFunction | None:
    """A centre weight read once as a function of the valence (None where it is not of that kind: then
    :func:`~symdecomp.algebra.cyclotomic.cyclotomic_value` says why, at the valence)."""
    try:
        return CyclotomicFunction(expr, N)
    except ValueError:
        return None


def _exact_weight(expr: sp.Expr, n: int):
    """A centre weight at valence ``n``: a Fraction, or an element of a cyclotomic field (exact); sympy reads each
    weight once (:func:`_weight_function`), not once per valence."""
    field, f = CyclotomicField(2 * n), _weight_function(expr)
    try:
        x = f(n, field) if f is not None else cyclotomic_value(expr, {N: n}, field=field)
    except ValueError as exc:
        raise InvalidSchemeError(f"the centre weight {expr} at valence {n} is not in a cyclotomic field: {exc}") from None
    if x.poly.degree() <= 0:
        c = x.poly[0] if x.poly.degree() == 0 else flint.fmpq(0)
        return to_fraction(c)
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
    """The ``(n + 6)``-point patch matrices of a triangle scheme at valence ``n`` (exact): from
    :data:`REFERENCE_VALENCE` on, its rows beyond the 1-ring are the reference valence's (:func:`_transplanted`)."""
    n = check_valence(n)
    subpatches = lambda m: _triangle_subpatch_rows(m, triangle_patch_rows(m))  # noqa: E731
    return _transplanted(scheme, n, TRIANGLE, subpatches, rational=False) or _triangle_by_refinement(scheme, n)


def _triangle_by_refinement(scheme: Scheme, n: int) -> PatchMatrices:
    """:func:`triangle_patch_matrices` read off the exact 3-ring matrix at valence ``n``."""
    ring = ring_subdivision_matrix(scheme, n, 3)
    labels = triangle_patch_rows(n)
    size = n + 6
    index = {lab: i for i, lab in enumerate(ring.labels)}
    column = {index[lab]: c for c, lab in enumerate(labels[:size])}
    rows = [ring.rows[index[lab]] for lab in labels]
    for lab, row in zip(labels, rows):
        if any(c not in column for c in row):
            raise InvalidSchemeError(f"scheme {scheme.name!r}: the refined patch point {lab} depends on a point beyond the {size} control points")
    sparse = _exact_rows(ring, rows, column, n)
    return _assemble(n, sparse, _triangle_subpatch_rows(n, labels), size, TRIANGLE)


def _exact_rows(ring, rows, column: dict, n: int) -> list[dict]:
    """``rows`` of the ring matrix ``ring`` on the patch's columns (``column``: ring index -> patch index), the
    centre's symbolic weights made exact at valence ``n`` (each distinct expression once, not once per row)."""
    exprs = {sym: sp.sympify(w, strict=True) for sym, w in ring.weights.items()}
    exact: dict = {}
    out = []
    for ring_row in rows:
        row = {}
        for c, w in ring_row.items():
            if not isinstance(w, Fraction):
                if w not in exact:
                    exact[w] = _exact_weight(sp.sympify(w, strict=True).xreplace(exprs), n)
                w = exact[w]
            row[column[c]] = w
        out.append(row)
    return out


# ---------------------------------------------------------------------------------------------
# every valence from the reference valence's rows


#: From this valence on, the patch's rows beyond the 1-ring are taken from this valence's refinement.
#: Those points are refined by the regular rules from points of the sectors ``n - 3 .. 3`` around the
#: patch (every vertex but ``O`` is regular), a neighbourhood of the lattice that is the same at every valence
#: where those sectors are distinct (``n >= 8``); only the 1-ring's rows read the centre's valence (its vertex rule, and an
#: edge rule that depends on it), and they are refined at ``n`` itself (:func:`_transplanted`).
REFERENCE_VALENCE = 8


def _transplanted(scheme: Scheme, n: int, lat: Lattice, subpatches, rational: bool) -> PatchMatrices | None:
    """The patch matrices at valence ``n > REFERENCE_VALENCE`` without refining the whole neighbourhood at ``n``.

    The 1-ring's rows come from the 1-ring matrix at ``n`` (:func:`~symdecomp.schemes.rings.ring_subdivision_matrix`,
    ``O(n)``); the rows beyond it are the reference valence's, each column moved to the same place on the
    lattice: the centre stays, a 1-ring point keeps its sector's offset ``d`` from sector 0 (``|d| <= 3``)
    and its place in the sector, a point beyond the 1-ring keeps its place in the list. None (refine at ``n``)
    below the reference valence, or where the reference's rows read more of the 1-ring or hold a weight that
    is not a rational (one that would depend on the centre). ``subpatches(n)``: the sub-patches' rows;
    ``rational``: whether the 1-ring's weights must be rational (else None, and the refinement says which is not).
    """
    if n <= REFERENCE_VALENCE:
        return None
    try:
        ref = patch_matrices(scheme, REFERENCE_VALENCE)
    except SymdecompError:  # the refinement at n says what is wrong, at n
        return None
    k0_ref, k0, per = ref.ring_size, lat.one_ring_size(n), (ref.ring_size - 1) // REFERENCE_VALENCE
    moved = {0: 0} | {c: c - k0_ref + k0 for c in range(k0_ref, ref.size)}
    for c in range(1, k0_ref):
        sector, place = divmod(c - 1, per)
        d = sector if sector <= REFERENCE_VALENCE // 2 else sector - REFERENCE_VALENCE
        if abs(d) < REFERENCE_VALENCE // 2:  # sectors on either side of the patch, told apart at every n >= 8
            moved[c] = 1 + per * (d % n) + place
    beyond = ref.sparse[k0_ref:]
    if any(c not in moved or not isinstance(w, Fraction) for row in beyond for c, w in row.items()):
        return None
    ring_rows = _moved_ring_rows(scheme, ref, n, per) if _ring_rules_fixed(scheme) else None
    if ring_rows is None:
        ring = ring_subdivision_matrix(scheme, n, 1)
        if len(ring.rows) != k0:
            return None
        ring_rows = _exact_rows(ring, ring.rows, {c: c for c in range(k0)}, n)
    if rational and any(not isinstance(w, Fraction) for row in ring_rows for w in row.values()):
        return None
    sparse = ring_rows + [{moved[c]: w for c, w in row.items()} for row in beyond]
    return _assemble(n, sparse, subpatches(n), ref.size - k0_ref + k0, lat)


@functools.lru_cache(maxsize=64)
def _ring_rules_fixed(scheme: Scheme) -> bool:
    """Whether the scheme's rules of the whole mesh read no valence on the 1-ring's edges (then only the centre's
    vertex rule depends on ``n``); False where its stencils are not rules of a mesh."""
    try:
        return not scheme.lattice.mesh_rules(scheme).depends_on_valence
    except InvalidSchemeError:
        return False


def _moved_ring_rows(scheme: Scheme, ref: PatchMatrices, n: int, per: int) -> list[dict] | None:
    """The 1-ring's rows at valence ``n`` when only the centre's vertex rule depends on ``n``: row 0 from the vertex
    rule at ``n`` (exact), the others the reference's sector-0 rows turned to each sector (their points are refined
    by rules that read no valence, from the centre and the sectors next to their own). None where a reference row
    reads a sector further away."""
    v = scheme.vertex_rule
    weights = [_exact_weight(sp.sympify(w, strict=True), n) for w in (v.center, v.each_a, v.each_b)[: 1 + per]]
    rows = [{0: weights[0]} | {1 + per * i + q: weights[1 + q] for i in range(n) for q in range(per)}]
    half = REFERENCE_VALENCE // 2
    offsets = []  # per kind of point: [(sector offset d, place, weight)], the centre as d = None
    for q in range(per):
        entries = []
        for c, w in ref.sparse[1 + q].items():
            sector, place = divmod(c - 1, per) if c else (0, 0)
            d = sector if sector <= half else sector - REFERENCE_VALENCE
            if c and abs(d) >= half:
                return None
            entries.append((None if c == 0 else d, place, w))
        offsets.append(entries)
    for t in range(n):
        for entries in offsets:
            rows.append({0 if d is None else 1 + per * ((d + t) % n) + place: w for d, place, w in entries})
    return rows


def _quad_subpatch_rows(n: int) -> tuple[tuple[int, ...], ...]:
    """The rows of the three quad sub-patches' 16 control points at valence ``n`` (:data:`SUBPATCH_CORNERS`)."""
    return tuple(
        tuple(lattice_index(n, (cu + a_ - 1, cv + b_ - 1)) for b_ in range(4) for a_ in range(4)) for cu, cv in SUBPATCH_CORNERS
    )
