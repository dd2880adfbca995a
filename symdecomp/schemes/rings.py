"""The subdivision matrix of the K-ring neighbourhood of a vertex, by exact refinement of a mesh.

For a valence-``n`` vertex ``O`` the ``K``-ring neighbourhood is the vertex and the ``K``
rings of vertices around it: ``1 + n K (K + 1)`` points on a quad mesh (Catmull-Clark 2-ring:
``6n + 1``), ``1 + n K (K + 1)/2`` on a triangle mesh (Loop 2-ring: ``3n + 1``). The matrix is
*not* assembled from 1-ring stencils: a ring mesh with ``K`` rings around ``O`` (every other
vertex regular) is refined once by the scheme's mesh rules (face, edge and vertex points of
the whole mesh: :func:`~symdecomp.schemes.refinement.refine`,
:func:`~symdecomp.schemes.refinement.refine_triangles`), with the unit vector ``e_j`` as the value
of old vertex ``j``; the value of a new point is then its row of the matrix. Points are
ordered by :meth:`~symdecomp.schemes.lattice.Lattice.ring_labels` (ring by ring, sector by sector), and the new point with label
``(s, u, v)`` is the one at lattice position ``(u/2, v/2)`` of the old mesh (a vertex point if
``u, v`` are even, an edge point if one is odd, a face point (quads) if both are).

The centre's vertex rule is the only rule evaluated at valence ``n``; when its weights are
not rational there (Loop's ``cos(2 pi/n)``) the matrix keeps them as the symbols
:data:`CENTRE_WEIGHTS` in row 0 (every other entry is rational: the other vertices are
regular), and :meth:`RingMatrix.weight_values` gives their exact values.

>>> from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
>>> S = ring_subdivision_matrix(catmull_clark(), 5, 2)
>>> order = S.block_order()
>>> S.size, S.classes(), S.exact_matrix().extract(order[:11], order[:11]) == subdivision_matrix(catmull_clark(), 5)
(31, ((1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (2, 2)), True)
"""

from __future__ import annotations

import functools
import numbers
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp

from symdecomp.algebra.numbers import to_fraction, to_sympy
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.lattice import Lattice
from symdecomp.schemes.scheme import Scheme, check_scheme, subdivision_entries
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = ["CENTRE_WEIGHTS", "EDGE_WEIGHTS", "MAX_RINGS", "SparseRow", "RingMatrix", "check_rings", "ring_subdivision_matrix"]

#: The deepest neighbourhood supported.
MAX_RINGS = 3
#: Symbols for the centre's vertex-rule weights ``(on O, each edge neighbour, each face neighbour)``.
CENTRE_WEIGHTS = (sp.Symbol("w_O"), sp.Symbol("w_a"), sp.Symbol("w_b"))
#: Symbols for the edge rule's weights at the centre's valence (:attr:`~symdecomp.schemes.refinement.MeshRules.oriented`:
#: on O, on a_i, on each side corner next to O, next to a_i; triangles: the first three), kept symbolic with
#: the centre's when the edge rule depends on ``n`` (the edges at the centre read it at ``n``; the model).
EDGE_WEIGHTS = (sp.Symbol("e_O"), sp.Symbol("e_a"), sp.Symbol("e_near"), sp.Symbol("e_far"))


class SparseRow:
    """A sparse vector ``{index: coefficient}``: the value carried through refinement."""

    __slots__ = ("entries",)

    def __init__(self, entries: Mapping):
        self.entries = dict(entries)

    def __rmul__(self, w):
        return SparseRow({k: w * x for k, x in self.entries.items()})

    def __add__(self, other: SparseRow) -> SparseRow:
        out = dict(self.entries)
        for k, x in other.entries.items():
            out[k] = out[k] + x if k in out else x
        return SparseRow(out)


def check_rings(rings) -> int:
    if isinstance(rings, bool) or not isinstance(rings, numbers.Integral) or not 1 <= rings <= MAX_RINGS:
        raise InvalidSchemeError(f"rings must be an integer from 1 to {MAX_RINGS}, got {rings!r}")
    return int(rings)


@dataclass(frozen=True)
class RingMatrix:
    """The exact subdivision matrix of a ``K``-ring neighbourhood, as sparse rows."""

    scheme: str
    lattice: Lattice
    n: int
    rings: int
    #: Labels ``(s, u, v)`` of rows and columns (:meth:`~symdecomp.schemes.lattice.Lattice.ring_labels`).
    labels: tuple[tuple[int, int, int], ...]
    #: Row ``i``: ``{column: weight}``; weights are ``Fraction`` or linear in :data:`CENTRE_WEIGHTS` (row 0).
    rows: tuple[Mapping[int, object], ...]
    #: Symbol of :data:`CENTRE_WEIGHTS` -> the vertex rule's weight, an expression in ``n``
    #: (only the symbols left in row 0; :meth:`weight_values` evaluates them).
    weights: Mapping[sp.Symbol, sp.Expr] = field(default_factory=dict)

    @property
    def size(self) -> int:
        return len(self.labels)

    @property
    def mesh(self) -> str:
        """The lattice's name, as reports spell it."""
        return self.lattice.name

    def weight_values(self) -> dict:
        """Symbol -> exact value of the centre weight at this ``n`` (sympy)."""
        return {s: sp.sympify(w, strict=True).subs(N, self.n) for s, w in self.weights.items()}

    def classes(self) -> tuple[tuple[int, int], ...]:
        """The vertex classes ``(u, v)`` of a sector (the labels of sector 0), in label order."""
        return tuple((u, v) for s, u, v in self.labels[1:] if s == 0)

    def block_order(self) -> tuple[int, ...]:
        """A permutation of the rows: the centre, then class by class, each over the sectors ``0..n-1``.

        In this order the matrix is bordered with ``n x n`` circulant blocks (Section 6).
        """
        index = {lab: i for i, lab in enumerate(self.labels)}
        return (0,) + tuple(index[(s, u, v)] for u, v in self.classes() for s in range(self.n))

    def entries(self, weights: Mapping | None = None) -> dict:
        """``{(row, column): Fraction}`` with the centre weights set to the rational ``weights``."""
        subs = {k: sp.Rational(v) for k, v in (weights or {}).items()}
        out = {}
        for r, row in enumerate(self.rows):
            for c, x in row.items():
                if not isinstance(x, Fraction):
                    x = sp.sympify(x, strict=True).xreplace(subs)
                    if not x.is_Rational:
                        raise InvalidSchemeError(f"entry ({r}, {c}) = {x} is not rational; give values for {sorted(map(str, self.weights))}")
                    x = to_fraction(x)
                if x:
                    out[(r, c)] = x
        return out

    def exact_matrix(self) -> sp.ImmutableMatrix:
        """The matrix as sympy, the centre weights replaced by their exact values."""
        values = self.weight_values()
        M = sp.zeros(self.size, self.size)
        for r, row in enumerate(self.rows):
            for c, x in row.items():
                M[r, c] = to_sympy(x) if isinstance(x, Fraction) else sp.sympify(x, strict=True).xreplace(values)
        return sp.ImmutableMatrix(M)


def _exact_weights(scheme: Scheme, valence: int) -> tuple:
    v = scheme.vertex_rule
    out = tuple(sp.sympify(w, strict=True).subs(N, valence) for w in (v.center, v.each_a, v.each_b))
    return out


def ring_subdivision_matrix(scheme: Scheme, n: int, rings: int = 1, *, symbolic_centre: bool = False) -> RingMatrix:
    """The ``rings``-ring subdivision matrix of ``scheme`` at valence ``n``, by one exact refinement.

    ``symbolic_centre``: keep the centre's vertex-rule weights as :data:`CENTRE_WEIGHTS` even
    when they are rational (used to read the block structure for symbolic ``n``; needs ``n``
    other than the regular valence).
    """
    check_scheme(scheme)
    n, rings = check_valence(n), check_rings(rings)
    if scheme.parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters {[str(p) for p in scheme.parameters]}; substitute values first")
    lat = scheme.lattice
    regular = lat.regular_valence
    count = len(lat.vertex_order(1))  # the vertex rule's weights: on O, each a_i (and each b_i)
    if symbolic_centre and n == regular:
        raise InvalidSchemeError(f"symbolic centre weights need n != {regular}")
    used: dict = {}

    def weights_at(valence: int):
        exact = _exact_weights(scheme, valence)
        if valence == n and (symbolic_centre or not all(w.is_Rational for w in exact)):
            v = scheme.vertex_rule
            for s, w in zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)):
                used[s] = w
            return CENTRE_WEIGHTS[:count]
        if not all(w.is_Rational for w in exact):
            raise InvalidSchemeError(
                f"scheme {scheme.name!r}: the vertex rule at valence {valence} is not rational ({exact}); "
                "the ring matrices need rational weights at the regular valence"
            )
        return exact[:count]

    labels = lat.ring_labels(n, rings)
    rules, mesh_rules_error = _whole_mesh_rules(scheme)
    if mesh_rules_error is not None:
        if rings > 1:
            raise InvalidSchemeError(
                f"{mesh_rules_error}; the {rings}-ring matrix needs the scheme's rules on the whole mesh "
                "(its 1-ring, --rings 1, is analysed from the stencils)"
            )
        row0 = weights_at(n)
        rows = _stencil_rows(scheme, n, labels, row0, symbolic=symbolic_centre)
        weights = {s: w for s, w in used.items() if any(sp.sympify(x, strict=True).has(s) for x in rows[0].values())}
        return RingMatrix(scheme.name, lat, n, rings, labels, tuple(rows), weights)
    unit = lambda s, u, v: (SparseRow({_index(labels, n, s, u, v): Fraction(1)}),)  # noqa: E731
    mesh = lat.ring_mesh(n, rings, unit)
    edges = _symbolic_edges(rules, n, used) if symbolic_centre and rules.depends_on_valence else None
    step = lat.refine(mesh, rules, vertex_weights=weights_at, edge_weights=edges)
    face_of = {frozenset(f): fi for fi, f in enumerate(mesh.faces)}
    rows = []
    for s, u, v in labels:
        point = _new_point(step, lat, labels, n, s, u, v, face_of)
        row = step.mesh.values[point][0].entries
        rows.append({c: x for c, x in sorted(row.items()) if x != 0})
    weights = {s: w for s, w in used.items()
               if any(sp.sympify(x, strict=True).has(s) for row in (rows if s in EDGE_WEIGHTS else rows[:1]) for x in row.values())}
    return RingMatrix(scheme.name, lat, n, rings, labels, tuple(rows), weights)


def _symbolic_edges(rules, n: int, used: dict):
    """``valence -> edge weights``: :data:`EDGE_WEIGHTS` at the centre's valence ``n`` (recorded in ``used``), the rule's
    numbers at every other valence."""
    def at(valence: int):
        if valence == n:
            used.update(zip(EDGE_WEIGHTS, rules.oriented))
            return EDGE_WEIGHTS[:len(rules.oriented)]
        return rules.edge_weights(valence)
    return at


@functools.lru_cache(maxsize=64)
def _whole_mesh_rules(scheme: Scheme) -> tuple[object, str | None]:
    """``(rules, None)``: the scheme's 1-ring stencils read as rules of the whole mesh, or ``(None, why not)``.

    Read once per scheme: the reading checks identities of the weights (sympy), and every ring matrix of a
    scheme, at every valence and depth, needs the same answer.
    """
    try:
        return scheme.lattice.mesh_rules(scheme), None
    except InvalidSchemeError as exc:
        return None, str(exc)


def _stencil_rows(scheme: Scheme, n: int, labels, centre_weights, *, symbolic: bool = False) -> list[dict]:
    """The 1-ring matrix assembled from the stencils (for rules that are not rules of a mesh).

    Row 0 takes ``centre_weights`` (``(w_O, w_a[, w_b])``: symbols or exact values); the other
    rows must be rational at this valence, or (``symbolic``, to read the blocks for every ``n``) are kept as the
    stencils' expressions in ``n``.
    """
    index = {lab: i for i, lab in enumerate(labels)}
    # 1-ring order (O, a_0..a_{n-1}, b_0..b_{n-1}) -> label index
    where = [index[lab] for lab in scheme.lattice.one_ring_labels(n)]
    rows: list[dict] = [dict() for _ in labels]
    at = (lambda w: sp.sympify(w, strict=True)) if symbolic else (lambda w: sp.sympify(w, strict=True).subs(N, n))
    for (r, c), x in subdivision_entries(scheme, n, at).items():
        if r == 0:
            continue
        if symbolic and x.has(N):
            rows[where[r]][where[c]] = x
            continue
        if not x.is_Rational:
            raise InvalidSchemeError(f"scheme {scheme.name!r}: a weight of its edge or face rule at n = {n} is not rational ({x})")
        rows[where[r]][where[c]] = to_fraction(x)
    w_o, *each = (to_fraction(w) if getattr(w, "is_Rational", False) else w for w in centre_weights)
    rows[0][0] = w_o
    for k, w in enumerate(each):  # on each a_i, then on each b_i
        for i in range(n):
            rows[0][where[1 + k * n + i]] = w
    return [{c: x for c, x in sorted(row.items()) if x != 0} for row in rows]


_INDEX_CACHE: dict = {}


def _index(labels, n, s, u, v) -> int:
    key = id(labels)
    if key not in _INDEX_CACHE or _INDEX_CACHE[key][0] is not labels:
        _INDEX_CACHE.clear()
        _INDEX_CACHE[key] = (labels, {lab: i for i, lab in enumerate(labels)})
    return _INDEX_CACHE[key][1][_normal(n, s, u, v)]


def _normal(n, s, u, v):
    if u == 0 and v == 0:
        return (0, 0, 0)
    return ((s + 1) % n, v, 0) if u == 0 else (s % n, u, v)


def _new_point(step, lat: Lattice, labels, n: int, s: int, u: int, v: int, face_of=None) -> int:
    """The id, in the refined mesh, of the new point with label ``(s, u, v)``."""
    return lat.refined_point(step, lambda a, b: _index(labels, n, s, a, b), u, v, face_of)
