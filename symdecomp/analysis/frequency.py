"""Per-frequency matrices derived from a scheme's rules (Eq. 25-33 and Eq. 43): the blocks of the cyclic symmetry of an
interior vertex, of its 1-ring and of its K-ring.

A subdivision step maps the 1-ring ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` linearly. Writing the
``a``'s and ``b``'s as sums of regular n-gons ``v_j`` (Eq. 12-13: ``A^j = X v_j``,
``B^j = Y v_j``), the rules act on each frequency separately:

* for ``omega = omega_n^j != 1`` the amplitudes ``(X, Y)`` move by the ``2 x 2`` matrix
  ``M_j`` (Eq. 33), whose entries are the eigenvalues (Prop. 2.1) of the four circulant
  blocks ``C_1..C_4`` of the subdivision matrix on ``v_j``;
* at ``j = 0`` the centre ``O`` joins in, and the positions of ``O``, of the centroid of the
  ``a``'s and of the centroid of the ``b``'s move by the ``3 x 3`` matrix of Eq. 43.

Everything here is derived by applying the rules of a :class:`~symdecomp.schemes.scheme.Scheme` to
a Fourier mode at a symbolic row ``i``; nothing is typed in from the paper.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> per_frequency_matrix(catmull_clark()).tolist()
[[omega/16 + 3/8 + 1/(16*omega), 1/16 + 1/(16*omega)], [omega/4 + 1/4, 1/4]]

**The** ``K``**-ring of any scheme** (:func:`ring_blocks`), for symbolic valence and frequency.
By rotational symmetry the ``K``-ring matrix of :mod:`symdecomp.schemes.rings`, with its rows
in :meth:`~symdecomp.schemes.rings.RingMatrix.block_order`, is bordered by the centre and has
``K' x K'`` circulant blocks of order ``n`` (``K'`` vertex classes per sector):

    S = [[w_O, w^T (x) 1^T], [c (x) 1, (C_pq)]].

Each block is banded (its stencils reach a fixed number of sectors), so it is given by a few
offsets independent of ``n``. As in Prop. 6.2 and Remark 6.1 the spectrum splits into

* frequency ``k = 0``: the ``(K'+1) x (K'+1)`` matrix ``E_0 = [[w_O, n w^T], [c, C(1)]]``;
* frequency ``k = 1..n-1``: the ``K' x K'`` matrix ``E(omega) = (sum_l c^pq_l omega^l)`` at
  ``omega = omega_n^k``, ``C(omega)`` the matrix of block symbols.

The blocks are *read off* the matrix built by exact refinement at one valence ``n_0`` (with the
centre weights kept as symbols) and checked against the refinement at ``n_0 + 1`` and
``n_0 + 2``: the blocks must reproduce those matrices entry by entry, or an error says so.

>>> from symdecomp.schemes.loop import loop
>>> b = ring_blocks(loop(), 1)
>>> b.frequency_matrix()
Matrix([[omega/8 + 3/8 + 1/(8*omega)]])
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp

from symdecomp.algebra.circulant import mode_eigenvalue_derivation, root_of_unity
from symdecomp.algebra.numbers import to_sympy
from symdecomp.errors import InvalidSchemeError, NotApplicableError, SymdecompError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice
from symdecomp.schemes.rings import CENTRE_WEIGHTS, EDGE_WEIGHTS, RingMatrix, check_rings, ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_frequency, check_valence

__all__ = [
    "CirculantBlocks",
    "circulant_blocks",
    "per_frequency_matrix",
    "per_frequency_matrix_at",
    "recursion_matrix",
    "one_ring_matrices",
    "laurent_to_cos",
    "valences_at_roots",
    "RingBlocks",
    "ring_blocks",
    "read_blocks",
]


@dataclass(frozen=True)
class CirculantBlocks:
    """The four circulant blocks of the subdivision matrix (Section 6), for symbolic ``n``.

    Each block is given by its offsets ``{k: c_k}`` and its eigenvalue on ``v_j`` as a
    Laurent polynomial in ``omega = omega_n^j`` (Prop. 2.1).
    """

    #: ``C_1``: weights of the old ``a``'s in the new ``a``'s.
    aa: dict
    #: ``C_2``: weights of the old ``b``'s in the new ``a``'s.
    ab: dict
    #: ``C_3``: weights of the old ``a``'s in the new ``b``'s.
    ba: dict
    #: ``C_4``: weights of the old ``b``'s in the new ``b``'s.
    bb: dict

    def __hash__(self):
        return hash(tuple(tuple(sorted(d.items())) for d in (self.aa, self.ab, self.ba, self.bb)))

    def eigenvalue(self, block: str) -> sp.Expr:
        """The eigenvalue of one block on ``v_j``, derived by applying it to the mode at row ``i``."""
        return mode_eigenvalue_derivation(getattr(self, block))[1]


def circulant_blocks(scheme: Scheme) -> CirculantBlocks:
    """The circulant blocks ``C_1..C_4`` of ``scheme`` read off its edge and face rules."""
    if check_scheme(scheme).face_rule is None:
        raise NotApplicableError(f"scheme {scheme.name!r} has no face rule: the four circulant blocks are the quad 1-ring's "
                                 "(one_ring_matrices covers every mesh)")
    return CirculantBlocks(
        dict(scheme.edge_rule.a), dict(scheme.edge_rule.b), dict(scheme.face_rule.a), dict(scheme.face_rule.b)
    )


@cached(scheme=check_scheme)
def per_frequency_matrix(scheme: Scheme) -> sp.ImmutableMatrix:
    """``M_j`` of Eq. 33 as a matrix of Laurent polynomials in ``omega = omega_n^j``.

    It acts on the column of amplitudes ``(X, Y)`` of ``(A^j, B^j)``; valid for every
    frequency with ``omega != 1`` (at ``omega = 1`` the centre ``O`` also contributes, see
    :func:`recursion_matrix`).
    """
    blocks = circulant_blocks(scheme)
    return sp.ImmutableMatrix(
        [[blocks.eigenvalue("aa"), blocks.eigenvalue("ab")], [blocks.eigenvalue("ba"), blocks.eigenvalue("bb")]]
    )


def per_frequency_matrix_at(scheme: Scheme, n: int, j: int) -> sp.ImmutableMatrix:
    """``M_j`` at a concrete valence and frequency ``0 <= j < 2n`` (exact, with ``omega_n^j``).

    Weights of the edge and face rules that depend on ``n`` are evaluated at this ``n`` too.
    """
    n = check_valence(n)
    j = check_frequency(j, n)
    w = root_of_unity(n, j)
    return sp.ImmutableMatrix(per_frequency_matrix(scheme).subs({OMEGA: w, N: n}).applyfunc(sp.expand))


def _valence_or_symbol(n):
    return n if n is N else check_valence(n)


@cached(scheme=check_scheme, n=_valence_or_symbol)
def recursion_matrix(scheme: Scheme, n=N) -> sp.ImmutableMatrix:
    """The ``3 x 3`` recursion matrix of Eq. 43, derived from the rules.

    It acts on the column ``(O, abar, bbar)``: the central vertex, the centroid of the
    ``a``'s (the centre of ``A^0``) and the centroid of the ``b``'s. Row 1 is the vertex rule
    with ``sum_i a_i = n*abar``; rows 2 and 3 are the edge and face rules applied to
    constant polygons (their ``a``- and ``b``-weights summed). Symbolic in ``n`` by default.
    """
    v = scheme.vertex_rule
    rows = [[v.center, N * v.each_a, N * v.each_b]]
    for rule in (scheme.edge_rule, scheme.face_rule):
        rows.append([rule.center, sum((w for _, w in rule.a), sp.Integer(0)), sum((w for _, w in rule.b), sp.Integer(0))])
    matrix = sp.Matrix(rows).applyfunc(lambda e: sp.expand(e.subs(N, n)))
    return sp.ImmutableMatrix(matrix)


@cached(scheme=check_scheme)
def one_ring_matrices(scheme: Scheme) -> tuple[sp.ImmutableMatrix, sp.ImmutableMatrix]:
    """``(M(omega), E_0)``: the 1-ring blocks for ``omega != 1`` and at frequency 0, on either mesh.

    On a quad mesh they are :func:`per_frequency_matrix` (``2 x 2``, on ``(a, b)``) and
    :func:`recursion_matrix` (``3 x 3``, on ``(O, abar, bbar)``). On a triangle mesh the 1-ring
    is ``(O, a_i)`` only: ``M(omega)`` is the ``1 x 1`` symbol of the edge rule's ``a``-weights and
    ``E_0`` the ``2 x 2`` matrix on ``(O, abar)`` (vertex rule, edge rule on a constant polygon).
    Both are symbolic in ``n`` (and ``omega``).

    >>> from symdecomp.schemes.loop import loop
    >>> M, E0 = one_ring_matrices(loop())
    >>> M, E0.shape
    (Matrix([[omega/8 + 3/8 + 1/(8*omega)]]), (2, 2))
    """
    if scheme.lattice.handled("1-ring frequency matrices", BICUBIC, BOX_SPLINE) == BICUBIC:
        return per_frequency_matrix(scheme), recursion_matrix(scheme)
    edge, v = scheme.edge_rule, scheme.vertex_rule
    M = sp.ImmutableMatrix([[sp.expand(sum((w * OMEGA**k for k, w in edge.a), sp.Integer(0)))]])
    E0 = sp.ImmutableMatrix([[v.center, N * v.each_a], [edge.center, sum((w for _, w in edge.a), sp.Integer(0))]])
    return M, E0.applyfunc(sp.expand)


def _laurent_terms(expr: sp.Expr) -> dict[int, sp.Expr]:
    expr = sp.expand(expr)
    terms: dict[int, sp.Expr] = {}
    for term in sp.Add.make_args(expr):
        coeff, power = sp.Integer(1), 0
        for factor in sp.Mul.make_args(term):
            base, exp = factor.as_base_exp()
            if base == OMEGA:
                if not exp.is_integer:
                    raise InvalidSchemeError(f"{expr} is not a Laurent polynomial in omega",
                                             parts=(expr, " is not a Laurent polynomial in ", OMEGA))
                power += int(exp)
            else:
                coeff *= factor
        terms[power] = terms.get(power, sp.Integer(0)) + coeff
    return terms


def laurent_to_cos(expr: sp.Expr) -> sp.Expr:
    """Rewrite a Laurent polynomial in ``omega = exp(2 i j theta)`` in ``c = cos(j theta)``.

    ``omega^k -> (c + i s)^(2k)`` with ``s = sin(j theta)``, then ``s^2 -> 1 - c^2``. For a
    symmetric polynomial (``p(omega) = p(1/omega)``) the result is a polynomial in :data:`symdecomp.symbols.cos_jtheta`
    alone; otherwise a term in :data:`symdecomp.symbols.sin_jtheta` remains.

    >>> laurent_to_cos(OMEGA + 1/OMEGA)
    4*c**2 - 2
    """
    total = sp.Integer(0)
    for k, coeff in _laurent_terms(expr).items():
        base = cos_jtheta + sp.I * sin_jtheta if k >= 0 else cos_jtheta - sp.I * sin_jtheta
        total += coeff * sp.expand(base ** (2 * abs(k)))
    poly = sp.Poly(sp.expand(total), sin_jtheta)
    reduced = sp.rem(poly, sp.Poly(sin_jtheta**2 - (1 - cos_jtheta**2), sin_jtheta))
    return sp.expand(reduced.as_expr())


def valences_at_roots(polynomial: sp.Expr, c: sp.Symbol, vanishes) -> tuple[tuple[sp.Expr, ...], tuple[int, ...]]:
    """The real roots of ``polynomial`` in ``c = cos(pi/n)`` that can be valences, and the valences.

    A valence ``n >= 3`` has ``c = cos(pi/n)`` in ``[1/2, 1)``, so only the real roots there
    are candidates (returned as exact algebraic numbers, each once). For each, the valence
    ``k`` nearest to ``pi/acos(c)`` is a candidate if it matches to 40 digits; it is kept
    only if ``vanishes(k)``, an exact test at that valence (the numeric match only selects
    which valence to test, it proves nothing).

    >>> from symdecomp.symbols import cos_theta as c
    >>> valences_at_roots(2 * c**2 - 1, c, lambda k: True)
    ((sqrt(2)/2,), (4,))
    """
    roots, valences = [], []
    for root in sp.Poly(polynomial, c).real_roots():
        if not sp.Rational(1, 2) <= root < 1 or root in roots:
            continue
        roots.append(root)
        with mpmath.workdps(50):
            m = mpmath.pi / mpmath.acos(mpmath.mpf(sp.N(root, 60)))
            k = int(mpmath.nint(m))
            close = abs(m - k) < mpmath.mpf(10) ** -40
        if close and vanishes(k):
            valences.append(k)
    return tuple(roots), tuple(sorted(set(valences)))


@dataclass(frozen=True)
class RingBlocks:
    """The bordered circulant-block form of the ``K``-ring matrix, for every valence."""

    scheme: str
    lattice: Lattice
    rings: int
    #: The vertex classes ``(u, v)`` of a sector.
    classes: tuple[tuple[int, int], ...]
    #: ``w_O``: the weight of the centre in the new centre, in terms of :data:`CENTRE_WEIGHTS`.
    centre: sp.Expr
    #: ``w_q``: the weight of each vertex of class ``q`` in the new centre (same symbols).
    centre_row: tuple[sp.Expr, ...]
    #: ``c_p``: the weight of the centre in each new vertex of class ``p``.
    centre_column: tuple[sp.Expr, ...]
    #: ``offsets[p][q]``: ``{l: c_l}``, the block ``C_pq`` is ``sum_l c_l P^l`` (``P`` the cyclic shift).
    offsets: tuple[tuple[tuple[tuple[int, sp.Expr], ...], ...], ...]
    #: The scheme's centre weights: :data:`CENTRE_WEIGHTS` symbol -> expression in ``n``.
    weights: tuple[tuple[sp.Symbol, sp.Expr], ...]

    @property
    def class_count(self) -> int:
        return len(self.classes)

    def frequency_matrix(self, omega=OMEGA) -> sp.ImmutableMatrix:
        """``E(omega)``: the ``K' x K'`` matrix of block symbols (frequencies ``k != 0``)."""
        K, omega = self.class_count, sp.sympify(omega, strict=True)
        return sp.ImmutableMatrix(K, K, lambda p, q: sp.Add(*[c * omega**l for l, c in self.offsets[p][q]]))

    def frequency_zero_matrix(self, n=N, *, symbolic_weights: bool = False) -> sp.ImmutableMatrix:
        """``E_0 = [[w_O, n w^T], [c, C(1)]]``; the centre weights as symbols or as the scheme's (in ``n``)."""
        C1 = self.frequency_matrix(1).subs(N, n)
        subs = {} if symbolic_weights else {s: w.subs(N, n) for s, w in self.weights}
        top = [self.centre.xreplace(subs)] + [n * w.xreplace(subs) for w in self.centre_row]
        rows = [top] + [[sp.sympify(self.centre_column[p], strict=True).subs(N, n)] + list(C1.row(p)) for p in range(self.class_count)]
        return sp.ImmutableMatrix(rows)

    def full_matrix(self, n: int, weights: dict | None = None) -> sp.ImmutableMatrix:
        """The concrete matrix in block order, rebuilt from the blocks (to compare with a refinement)."""
        K = self.class_count
        subs = weights if weights is not None else {s: w.subs(N, n) for s, w in self.weights}
        M = sp.zeros(1 + K * n, 1 + K * n)
        M[0, 0] = self.centre.xreplace(subs)
        for q in range(K):
            for s in range(n):
                M[0, 1 + q * n + s] = self.centre_row[q].xreplace(subs)
        for p in range(K):
            for s in range(n):
                M[1 + p * n + s, 0] = sp.sympify(self.centre_column[p], strict=True).subs(N, n)
                for q in range(K):
                    for l, c in self.offsets[p][q]:
                        M[1 + p * n + s, 1 + q * n + (s + l) % n] += sp.sympify(c, strict=True).subs(N, n)
        return sp.ImmutableMatrix(M)

    def entries(self, n: int, weights: dict | None = None) -> dict[tuple[int, int], sp.Expr]:
        """The nonzero entries of :meth:`full_matrix` (the same sums, entry by entry), without the dense matrix."""
        K = self.class_count
        subs = weights if weights is not None else {s: w.subs(N, n) for s, w in self.weights}
        at_n: dict[sp.Expr, sp.Expr] = {}

        def value(x) -> sp.Expr:
            x = sp.sympify(x, strict=True)
            if x not in at_n:
                at_n[x] = x.subs(N, n)
            return at_n[x]

        M: dict[tuple[int, int], sp.Expr] = {(0, 0): value(self.centre.xreplace(subs))}
        for q in range(K):
            for s in range(n):
                M[0, 1 + q * n + s] = value(self.centre_row[q].xreplace(subs))
        for p in range(K):
            for s in range(n):
                M[1 + p * n + s, 0] = value(self.centre_column[p])
                for q in range(K):
                    for l, c in self.offsets[p][q]:
                        key = (1 + p * n + s, 1 + q * n + (s + l) % n)
                        M[key] = M.get(key, sp.Integer(0)) + value(c)
        return {key: x for key, x in M.items() if x != 0}


def _signed(l: int, n: int) -> int:
    l %= n
    return l - n if l > n // 2 else l


def read_blocks(S: RingMatrix, scheme: Scheme) -> RingBlocks:
    """Read the block form off a refinement matrix built with ``symbolic_centre=True``."""
    n, classes = S.n, S.classes()
    K = len(classes)
    order = S.block_order()
    position = {r: i for i, r in enumerate(order)}
    rows: list[dict[int, sp.Expr]] = [dict() for _ in order]
    for r, row in enumerate(S.rows):
        rows[position[r]] = {position[c]: to_sympy(x) for c, x in row.items()}

    def uniform(values, what):
        values = set(values)
        if len(values) != 1:
            raise SymdecompError(f"the {what} is not the same in every sector: the matrix is not rotationally symmetric")
        return values.pop()

    centre = rows[0].get(0, sp.Integer(0))
    centre_row = tuple(uniform([rows[0].get(1 + q * n + s, sp.Integer(0)) for s in range(n)], "centre row") for q in range(K))
    centre_column = tuple(uniform([rows[1 + p * n + s].get(0, sp.Integer(0)) for s in range(n)], "centre column") for p in range(K))
    offsets = []
    for p in range(K):
        block_row = []
        for q in range(K):
            first = {_signed(c - 1 - q * n, n): x for c, x in rows[1 + p * n].items() if c and (c - 1) // n == q}
            block_row.append(tuple(sorted(first.items())))
        offsets.append(tuple(block_row))
    edges = {s: sp.sympify(w, strict=True) for s, w in S.weights.items() if s in EDGE_WEIGHTS}
    if edges:  # the edge rule at the centre's valence, as an expression in n (the model)
        centre_column = tuple(sp.sympify(x, strict=True).xreplace(edges) for x in centre_column)
        offsets = [tuple(tuple((l, sp.sympify(c, strict=True).xreplace(edges)) for l, c in block) for block in row) for row in offsets]
    v = scheme.vertex_rule
    weights = tuple(zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)))
    return RingBlocks(scheme.name, scheme.lattice, S.rings, classes, centre, centre_row, centre_column, tuple(offsets), weights)


@cached(32, scheme=check_scheme, rings=check_rings)
def ring_blocks(scheme: Scheme, rings: int = 1) -> RingBlocks:
    """The block form of ``scheme``'s ``rings``-ring matrix, read at one valence and checked at two more.

    The centre's vertex rule enters through :data:`CENTRE_WEIGHTS`. An edge rule that depends on ``n`` is read, as
    the model says (:class:`~symdecomp.schemes.scheme.Scheme`), at the centre's valence on the edges at the centre
    and at the regular valence elsewhere: its weights at the centre are kept as
    :data:`~symdecomp.schemes.rings.EDGE_WEIGHTS` while reading and then replaced by their expressions in ``n``, so
    the blocks are expressions in ``omega`` and ``n`` (in ``omega`` alone when the rules do not depend on ``n``).
    """
    n0 = 4 * rings + 7
    if n0 == scheme.lattice.regular_valence:  # pragma: no cover - 4K + 7 is odd
        n0 += 1
    blocks = read_blocks(ring_subdivision_matrix(scheme, n0, rings, symbolic_centre=True), scheme)
    for n in (n0 + 1, n0 + 2):
        S = ring_subdivision_matrix(scheme, n, rings, symbolic_centre=True)
        if _refined_entries(S) != blocks.entries(n, {s: s for s in CENTRE_WEIGHTS}):
            raise InvalidSchemeError(
                f"scheme {scheme.name!r}: the {rings}-ring matrix at n = {n} is not the banded block form read at n = {n0}"
            )
    return blocks


def _refined_entries(S: RingMatrix) -> dict[tuple[int, int], sp.Expr]:
    """The nonzero entries of ``S`` in block order, its edge weights at the centre and ``n`` set to ``S.n``: what
    :meth:`RingBlocks.entries` must give (sparse: the dense comparison cost a quarter of a second per valence)."""
    n, position = S.n, {r: i for i, r in enumerate(S.block_order())}
    edges = {s: sp.sympify(w, strict=True).subs(N, n) for s, w in S.weights.items() if s in EDGE_WEIGHTS}
    out = {}
    for r, row in enumerate(S.rows):
        for c, x in row.items():
            value = sp.sympify(to_sympy(x), strict=True).xreplace(edges).subs(N, n)
            if value != 0:
                out[position[r], position[c]] = value
    return out
