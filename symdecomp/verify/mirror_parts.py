"""The spectrum and eigenvectors of a sharp sector's 2-ring matrix, certified (Arb), split by the sector's mirror.

A sector of ``k`` faces between two sharp rays (the one sector of a boundary or corner vertex, or one side
of an infinitely sharp crease) is cut out of the exact subdivision matrix of its vertex
(:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`, the whole-mesh model) as
:class:`SectorMatrices`: the rows and columns of the sector's own points, which must not read any point
of another sector (exactly: the sharp rays decouple the sectors, else the test does not apply).

**Mirror blocks.** The sector has no rotational symmetry, but when the rules are symmetric the mirror ``(s, u,
v) -> (k - 1 - s, v, u)`` (rays ``s -> k - s``) commutes with the matrix (checked exactly, entry by entry).
Then the matrix is the direct sum of its even and odd parts (vectors with ``x[P p] = x[p]`` and ``x[P p] =
-x[p]``), and each part is block lower triangular: the new 1-ring reads only the old 1-ring (checked exactly),
the outer points hold only the regular and crease rules. The spectrum is the union of the four blocks'
spectra: rational blocks exactly (FLINT's characteristic polynomial and its certified complex roots with their
exact multiplicities), blocks with weights in one ``cos(t)`` (BLZ's ``cos(theta_k)``) from their
characteristic polynomial in ``x`` and ``c = cos(t)``, factored over the rationals (exact multiplicities, each
factor's roots certified by Arb), other blocks by Arb's certified eigenvalue clusters
(``acb_mat.eig(multiple=True)``: a cluster of ``m`` equal balls holds ``m`` eigenvalues). An eigenvalue simple
in its part has one eigenvector there, which is computed rigorously (a null vector of the 1-ring block by a
certified solve, lifted to the outer points), so two subdominant eigenvalues of *different* parts need not be
separated from each other (equal or not, the eigenspace is spanned by the two vectors), only from the rest.

**Real and simple.** An eigenvalue's ball that holds one eigenvalue (counted with multiplicity) and whose
complex conjugate meets no other eigenvalue's ball is real: the conjugate of that eigenvalue is an
eigenvalue of the real matrix in the conjugate ball, hence the same one.

**Which part holds an eigenvector, from the blocks alone** (:func:`block_parts`, for the blocks' route that has no
characteristic polynomial, :mod:`.c1_mirror_blocks`): a sine block ``j`` has the mode ``sin(pi j s/k)`` on the rays ``s``,
and the mirror ``s -> k - s`` multiplies it by ``(-1)^(j + 1)``: even for ``j`` odd, odd for ``j`` even; an eigenvalue
``q`` (rational) of the crease block has an odd eigenvector when ``(C - q) (0, 1, -1) = 0`` exactly and ``C - q`` has
rank 2, an even one when ``C - q`` has rank 2 and the odd vector is not in its kernel. An eigenvalue the blocks count once
in the whole matrix is simple in its part; a double one (BLZ's ``1/2``: the crease block's, odd, and sine block 1's,
even) has one eigenvector in each part.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cos_field import affine_in
from symdecomp.algebra.null_vector import null_vector
from symdecomp.algebra.numbers import to_sympy
from symdecomp.analysis.triangular_eigen import near_weight
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.lattice import Lattice
from symdecomp.schemes.sector import SharpVertex, sharp_matrix_rows

__all__ = ["NEAR", "SectorMatrices", "sector_matrices", "mirror_label", "Eigenpart", "sector_eigenvalues", "sector_eigenvector", "sector_parts",
           "ball_matrix", "block_parts"]


#: The near-edge rule's weight on the edge's other end, as a symbol where its value is irrational.
NEAR = sp.Symbol("w_near")


@dataclass(frozen=True)
class SectorMatrices:
    """One sector's part of its vertex's exact subdivision matrix, in the sector's own labels."""

    #: Faces of the sector.
    k: int
    lattice: Lattice
    #: Labels ``(s, u, v)`` of the 2-ring (faces ``0..k-1``, last ray ``(k, u, 0)``), in matrix order.
    labels: tuple
    #: The exact 2-ring matrix (sympy, sparse).
    matrix: sp.ImmutableSparseMatrix
    #: Labels of the level-1 3-ring, in row order of :attr:`refine` (the 2-ring first).
    fine_labels: tuple
    #: The exact map from the level-0 2-ring to the level-1 3-ring (rows of the 3-ring matrix).
    refine: sp.ImmutableSparseMatrix
    #: ``O`` is a corner (interpolated).
    corner: bool
    #: The value of :data:`NEAR` in :attr:`matrix` and :attr:`refine` (``None``: they are exact numbers).
    weight: sp.Expr | None = None


def mirror_label(label: tuple, k: int) -> tuple:
    """The mirror image of a sector label: ray ``s`` to ray ``k - s``, face ``s`` to face ``k - 1 - s`` with ``u, v`` exchanged."""
    s, u, v = label
    if u == 0 and v == 0:
        return label
    return (k - s, u, 0) if v == 0 else (k - 1 - s, v, u)


def _extract(scheme, vertex: SharpVertex, sector: int) -> tuple:
    """``(refine, coarse labels, fine labels)`` of one sector, from the vertex's exact 3-ring rows under ``scheme``.

    ``refine`` is sparse (``{(row, column): exact weight}``): the rows are read as the refinement gives them, so the work
    is the number of entries read, not the square of the ring's size.
    """
    k, start = vertex.sectors[sector], sum(vertex.sectors[:sector])
    local = SharpVertex.boundary(k, vertex.lattice)
    full = sharp_matrix_rows(scheme, vertex, rings=3)
    index = {lab: i for i, lab in enumerate(vertex.ring_labels(3))}

    def glob(label):
        s, u, v = label
        if u == 0 and v == 0:
            return index[label]
        s = s + start
        return index[(s % vertex.faces if vertex.closed else s, u, v)]

    fine, coarse = local.ring_labels(3), local.ring_labels(2)
    column = {glob(lab): c for c, lab in enumerate(coarse)}
    entries = {}
    for r, lab in enumerate(fine):
        for c, w in full[glob(lab)].items():
            w = to_sympy(w)
            if w == 0:
                continue
            if c not in column:
                raise NotApplicableError(
                    f"sector {sector} of the vertex is not separated from the rest: the new point {lab} reads points outside "
                    "the sector's 2-ring (the sector test needs infinitely sharp edges between the sectors)")
            entries[(r, column[c])] = w
    return entries, coarse, fine


def _affine(e: sp.Expr, weight: sp.Expr) -> sp.Expr | None:
    """``p + q NEAR`` if the number ``e`` is ``p + q weight`` with rationals ``p, q`` (:func:`~symdecomp.algebra.cos_field.affine_in`)."""
    pq = affine_in(e, weight)
    return None if pq is None else pq[0] + pq[1] * NEAR


def _in_near(entries: dict, weight: sp.Expr) -> dict | None:
    """The entries with ``weight`` written as :data:`NEAR` (each distinct value converted once), or ``None`` if one is not
    affine in it."""
    if not all(v.is_Rational for v in sp.expand(weight).as_coefficients_dict().values()):
        return None  # pragma: no cover - a weight sympy does not expand into rational multiples of radicals
    converted = {e: _affine(e, weight) for e in set(entries.values())}
    if any(e is None for e in converted.values()):
        return None
    return {rc: converted[e] for rc, e in entries.items()}


def sector_matrices(scheme, vertex: SharpVertex, sector: int = 0) -> SectorMatrices:
    """The matrices of sector ``sector`` of ``vertex`` (see the module docstring), as sparse sympy matrices.

    Where the sector's near-edge weight ``w`` is irrational (BLZ's ``3/8 - cos(pi/k)/4``) and every entry is
    ``p + q w`` with rational ``p, q`` (the refinement is linear in the rules' weights, and the near-edge rule's two
    weights have a rational sum), the matrices are given in the symbol :data:`NEAR`, with :attr:`SectorMatrices.weight`.
    """
    k = vertex.sectors[sector]
    weight = near_weight(scheme, vertex, k)
    entries, coarse, fine = _extract(scheme, vertex, sector)
    if weight is not None:
        affine = _in_near(entries, weight)
        if affine is None:
            weight = None
        else:
            entries = affine
    refine = sp.ImmutableSparseMatrix(len(fine), len(coarse), entries)
    return SectorMatrices(k, vertex.lattice, coarse, refine[: len(coarse), :], fine, refine, vertex.corner, weight)


def ball_matrix(rows, weight=None) -> flint.acb_mat:
    """An exact sympy matrix (list of rows) as an Arb matrix at the working precision (each distinct entry compiled once).

    ``weight``: the value of :data:`NEAR` where the entries are affine in it (``None``: no symbol).
    """
    cache: dict = {}
    value = None if weight is None else compile_expression(weight, (), "arb")()

    def ball(e):
        if e not in cache:
            e2 = sp.sympify(e, strict=True)
            if e2.free_symbols - {NEAR} or (e2.has(NEAR) and value is None):
                raise InvalidSchemeError(f"the sector matrix has the symbolic entry {e2}; give the scheme's parameters values")
            cache[e] = compile_expression(e2, (NEAR,), "arb")(value)
        return cache[e]

    return flint.acb_mat([[ball(e) for e in row] for row in rows])


@dataclass(frozen=True)
class Eigenpart:
    """One invariant part of the sector matrix: its basis (how a part vector expands) and its 1-ring/outer split."""

    #: ``"even"``, ``"odd"`` or ``"all"`` (no mirror symmetry).
    name: str
    #: ``basis[i] = ((index, sign), ...)``: the matrix indices (and signs) of part coordinate ``i``.
    basis: tuple
    #: The part's matrix in its coordinates (exact sympy rows).
    rows: tuple
    #: Number of leading coordinates that belong to the 1-ring (0: no triangular split).
    inner: int


def sector_parts(sm: SectorMatrices) -> list[Eigenpart]:
    """The sector matrix's invariant parts: even and odd under the mirror when it commutes with the matrix (exactly), else
    one part ``"all"``; each split into its 1-ring block and the rest where the new 1-ring reads only the old one."""
    return _parts(sm)


def _parts(sm: SectorMatrices) -> list[Eigenpart]:
    labels, k = sm.labels, sm.k
    entries = {ij: e for ij, e in sm.matrix.todok().items() if e != 0}
    row_of: dict = {}
    for (i, j), e in entries.items():
        row_of.setdefault(i, {})[j] = e
    index = {lab: i for i, lab in enumerate(labels)}
    mirror = [index[mirror_label(lab, k)] for lab in labels]
    zero = sp.Integer(0)
    symmetric = all(entries.get((mirror[i], mirror[j]), zero) == e or sp.simplify(entries.get((mirror[i], mirror[j]), zero) - e) == 0
                    for (i, j), e in entries.items())
    ring1 = [i for i, lab in enumerate(labels) if sm.lattice.ring_of(lab[1], lab[2]) <= 1]
    if not symmetric:
        bases = {"all": [((i, 1),) for i in range(len(labels))]}
    else:
        reps = [i for i in range(len(labels)) if i <= mirror[i]]
        bases = {"even": [((i, 1),) if i == mirror[i] else ((i, 1), (mirror[i], 1)) for i in reps],
                 "odd": [((i, 1), (mirror[i], -1)) for i in reps if i != mirror[i]]}
    out = []
    for name, basis in bases.items():
        basis.sort(key=lambda b: (b[0][0] not in ring1, b[0][0]))
        inner = sum(1 for b in basis if b[0][0] in ring1)
        rows = _part_rows(row_of, basis)
        if any(rows[r][c] != 0 for r in range(inner) for c in range(inner, len(basis))):
            inner = 0  # pragma: no cover - the new 1-ring reads only the old one for every rule set
        out.append(Eigenpart(name, tuple(tuple(b) for b in basis), rows, inner))
    return [p for p in out if p.basis]


def _part_rows(row_of: dict, basis: list) -> tuple:
    """The part's matrix: row ``bi`` reads ``sum(S[bi_0, j] sign_j)`` over each coordinate ``bj``'s indices ``j`` (only the
    matrix's non-zero entries are visited; an index outside the basis is one the part's vectors vanish on)."""
    coord = {j: (c, sgn) for c, bj in enumerate(basis) for j, sgn in bj}
    out = []
    for bi in basis:
        acc: dict = {}
        for j, e in row_of.get(bi[0][0], {}).items():
            if j in coord:
                c, sgn = coord[j]
                acc[c] = acc.get(c, 0) + e * sgn
        out.append(tuple(sp.expand(acc[c]) if c in acc else sp.Integer(0) for c in range(len(basis))))
    return tuple(out)


def _block_values(rows, weight=None) -> list[flint.acb]:
    """The eigenvalues of an exact square block, with multiplicity (see the module docstring)."""
    if not rows:
        return []
    if all(sp.sympify(e, strict=True).is_Rational for row in rows for e in row):
        m = flint.fmpq_mat([[flint.fmpq(int(sp.Rational(e).p), int(sp.Rational(e).q)) for e in row] for row in rows])
        out = []
        for factor, mult in m.charpoly().factor()[1]:
            out += [r for r, m2 in factor.complex_roots() for _ in range(m2 * mult)]
        return out
    if weight is not None and all(sp.sympify(e, strict=True).free_symbols <= {NEAR} for row in rows for e in row):
        return _algebraic_values(rows, NEAR, weight)
    entries = [sp.sympify(e, strict=True) for row in rows for e in row]
    atoms = set().union(*(e.atoms(sp.cos, sp.sin) for e in entries))
    if len(atoms) == 1:  # a user's weight in one cos(theta_k) that sympy left as it is
        (atom,) = atoms
        c = sp.Dummy("c")
        M = sp.Matrix(rows).xreplace({atom: c})
        if all(e.is_polynomial(c) for e in M):
            return _algebraic_values(M.tolist(), c, atom)
    return list(ball_matrix(rows).eig(multiple=True))


def _roots(poly: flint.acb_poly, bits: int) -> list[flint.acb]:
    """Arb's certified roots of a squarefree ball polynomial, refined to about ``2^-bits`` (``ValueError`` if not isolated)."""
    if poly.degree() < 1:
        return []
    for scale in (1, 2, 4, 8):
        try:
            return poly.roots(tol=flint.arb(2) ** -bits, maxprec=scale * 4 * flint.ctx.prec)
        except ValueError:
            continue
    raise ValueError(f"the roots of a degree-{poly.degree()} factor are not isolated")


def _algebraic_values(rows, symbol: sp.Symbol, value: sp.Expr) -> list[flint.acb]:
    """Eigenvalues of a block polynomial in ``symbol``, at ``symbol = value``, with multiplicity.

    The characteristic polynomial is exact in ``x`` and ``symbol``, factored over the rationals; each factor's roots are
    Arb's certified roots of its coefficients at ``value`` (a factor repeated ``m`` times gives its roots ``m`` times).
    """
    x = sp.Symbol("x")
    out = []
    factors = sp.factor_list(sp.Matrix(rows).charpoly(x).as_expr(), x, symbol)[1]
    bits = flint.ctx.prec
    with flint.ctx.workprec(4 * bits):  # the coefficients are polynomials in the value: cancellation
        ball = compile_expression(value, (), "arb")()
        for factor, mult in factors:
            coeffs = sp.Poly(factor, x).all_coeffs()[::-1]
            poly = flint.acb_poly([compile_expression(a, (symbol,), "arb")(ball) for a in coeffs])
            out += [r for r in _roots(poly, bits) for _ in range(mult)]
    return [+r for r in out]  # rounded to the working precision


def sector_eigenvalues(sm: SectorMatrices) -> list[tuple[flint.acb, Eigenpart, bool]]:
    """Every eigenvalue of the sector's 2-ring matrix with its part and whether it is the part's 1-ring block's."""
    out = []
    for part in _parts(sm):
        m = part.inner or len(part.basis)
        top = [row[:m] for row in part.rows[:m]]
        rest = [row[m:] for row in part.rows[m:]]
        out += [(x, part, True) for x in _block_values(top, sm.weight)]
        out += [(x, part, False) for x in _block_values(rest, sm.weight)]
    return out


def sector_eigenvector(sm: SectorMatrices, part: Eigenpart, value: flint.acb, in_ring: bool) -> list | None:
    """The eigenvector (2-ring, matrix order) of a simple eigenvalue ``value`` of ``part`` (``None`` if not certified).

    ``in_ring``: the eigenvalue is the 1-ring block's (the outer part is then solved from it); an eigenvalue
    of the outer block has an eigenvector that vanishes on the 1-ring.
    """
    A = ball_matrix(part.rows, sm.weight)
    size, m = len(part.basis), part.inner or len(part.basis)
    if in_ring:
        inner = flint.acb_mat([[A[r, c] - (value if r == c else 0) for c in range(m)] for r in range(m)])
        head = null_vector(inner)
        if head is None:
            return None
        if size > m:
            B = flint.acb_mat([[(value if r == c else 0) - A[r, c] for c in range(m, size)] for r in range(m, size)])
            rhs = flint.acb_mat([[sum((A[r, c] * head[c] for c in range(m)), flint.acb(0))] for r in range(m, size)])
            try:
                tail = B.solve(rhs)
            except ZeroDivisionError:
                return None
            head += [tail[i, 0] for i in range(size - m)]
    else:
        outer = flint.acb_mat([[A[r, c] - (value if r == c else 0) for c in range(m, size)] for r in range(m, size)])
        tail = null_vector(outer)
        if tail is None:
            return None
        head = [flint.acb(0)] * m + tail
    vec = [flint.acb(0)] * len(sm.labels)
    for coord, terms in zip(head, part.basis):
        for i, sign in terms:
            vec[i] = coord * sign
    return vec


def _crease_parity(crease: sp.Matrix, value) -> str | None:
    """The mirror part (``"even"``, ``"odd"``) of the crease block's eigenvector for ``value`` (``None``: not decided)."""
    if value.key[0] != "q":
        return None
    return _rational_parity(sp.ImmutableMatrix(crease), value.key[1])


@functools.lru_cache(maxsize=64)
def _rational_parity(crease: sp.ImmutableMatrix, value: Fraction) -> str | None:
    """:func:`_crease_parity` at a rational ``value``, decided once per crease block and value (every sector asks)."""
    q = sp.Rational(value.numerator, value.denominator)
    shifted = crease - q * sp.eye(crease.rows)
    if shifted.rank() != crease.rows - 1:
        return None
    odd = sp.Matrix([0, 1, -1])  # O and its two sharp neighbours: the mirror exchanges the neighbours
    return "odd" if shifted * odd == sp.zeros(3, 1) else "even"


def _parity(crease: sp.Matrix, value, block) -> str | None:
    if block.block == "crease":
        return _crease_parity(crease, value)
    if block.block == "sine":
        return "even" if block.j % 2 == 1 else "odd"
    return None


def block_parts(crease: sp.Matrix, picks: list) -> list[str] | None:
    """The mirror part of each subdominant eigenvector (module docstring), ``picks`` holding ``(ball, Eigenvalue, _)``
    (:class:`~symdecomp.analysis.eigenvalue.Eigenvalue` with its mirror blocks), ``crease`` the crease block.

    ``None`` where the blocks do not name one part per eigenvector (a value of several blocks of one part, a face mode).
    """
    first, second = picks[0][1], picks[1][1]
    if first is second:
        if first.multiplicity != 2 or len(first.blocks) != 2:
            return None
        names = [_parity(crease, first, b) for b in first.blocks]
        return names if None not in names and names[0] != names[1] else None
    if any(v.multiplicity != 1 or len(v.blocks) != 1 for v in (first, second)):
        return None
    names = [_parity(crease, v, v.blocks[0]) for v in (first, second)]
    return None if None in names else names
