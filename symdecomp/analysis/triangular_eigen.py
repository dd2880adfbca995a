"""Exact eigenvalues of a block-triangular one-step matrix, part by part (over ``Q`` or ``Q(cos(pi/k))``): the
crease block and each sector of a boundary, crease, corner or dart vertex.

At a boundary, crease or corner vertex the rules of the crease points (the vertex and its
neighbours on the sharp edges) read crease points only, and the rules of a sector's points read
that sector and the crease points only. So the one-step matrix ``S`` (in any order) is block
lower-triangular with the *crease block* ``C`` and one block ``Y_s`` per sector on its diagonal, and
``chi_S = chi_C prod_s chi_{Y_s}``. Nothing here assumes it: the crease points are *found* as the
smallest set of points that contains the vertex and its sharp-edge neighbours and the support of its own rows
(:func:`matrix_parts`), and the sectors as the connected pieces of the rest. A dart or a
semi-sharp crease (the vertex reads its whole ring) has one part, the whole matrix.

Each eigenvalue is a root of an irreducible rational factor of its part's characteristic
polynomial (FLINT), kept exactly: the factor, the root's index in sympy's order, a closed form
(degree <= 2) or a ``CRootOf``, and a certified Arb ball. Equal eigenvalues of two parts are the
same root of the same factor, so equality is exact. Rational matrices here; rules whose weights
hold cos(pi/k) give entries in Q(cos(pi/k)), whose eigenvalues are found as the same objects (roots of
irreducible rational factors of the norm of the characteristic polynomial, below).

>>> import flint
>>> S = flint.fmpq_mat([[flint.fmpq(3, 4), flint.fmpq(1, 8), flint.fmpq(1, 8), 0],
...                     [flint.fmpq(1, 2), flint.fmpq(1, 2), 0, 0], [flint.fmpq(1, 2), 0, flint.fmpq(1, 2), 0],
...                     [flint.fmpq(1, 4), flint.fmpq(1, 4), flint.fmpq(1, 4), flint.fmpq(1, 4)]])
>>> [p.indices for p in matrix_parts(S, (0, 1, 2))]
[(0, 1, 2), (3,)]
>>> [(str(e.exact), e.multiplicity, e.part) for e in part_eigenvalues(S, matrix_parts(S, (0, 1, 2)))]
[('1', 1, 'crease'), ('1/2', 1, 'crease'), ('1/4', 1, 'crease'), ('1/4', 1, 'sector 1')]

**Rules with** ``cos(theta_k)`` **weights** (Biermann-Levin-Zorin's), exactly over ``Q(cos(pi/k))``.
BLZ's near-edge rule has the weight ``w = 3/8 - cos(theta_k)/4`` (Catmull-Clark) on the edge's other end, so the
one-step matrix of a boundary or corner vertex with ``k`` faces (or a crease with ``k`` faces on both sides) has
entries ``p + q w`` in the real cyclotomic field ``K = Q(cos(pi/k))``. :func:`sharp_matrix` returns the rational
matrix when it is rational (``k <= 3``), else the :class:`~symdecomp.algebra.cos_field.FieldMatrix` over ``K``;
:func:`sharp_values` its eigenvalues part by part, the same
:class:`~symdecomp.analysis.eigenvalue.Eigenvalue` objects as for rational rules
(:func:`root_eigenvalue`): each is a root of an
irreducible rational factor of the norm of the part's characteristic polynomial (its minimal polynomial over
``Q``), picked out and counted exactly (:func:`~symdecomp.algebra.cos_field.field_roots`).

Out of reach (:class:`~symdecomp.errors.NotApplicableError`): a crease whose two sides have different face counts
``k1 != k2`` with both ``cos(pi/k_i)`` irrational (entries in ``Q(cos(pi/k1), cos(pi/k2))``), and corners given an
angle.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import flint
import sympy as sp

from symdecomp.algebra.cos_field import FieldMatrix, field_charpoly, field_roots, norm_charpoly
from symdecomp.algebra.number_field import root_expression
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.errors import NotApplicableError, PrecisionError

__all__ = ["MatrixPart", "root_eigenvalue", "matrix_parts", "part_eigenvalues", "submatrix", "by_modulus",
           "merge", "separated", "ball_at",
           "near_weight", "sharp_matrix", "sharp_values", "field_part_eigenvalues"]


@dataclass(frozen=True)
class MatrixPart:
    """A diagonal block of the block-triangular one-step matrix."""

    #: ``"crease"``, ``"sector 1"``, ``"sector 2"``, ... or ``"whole"`` (no block structure).
    label: str
    #: Its rows (= columns) in the matrix, ascending.
    indices: tuple[int, ...]


def root_eigenvalue(factor: flint.fmpq_poly, index: int, exact: sp.Expr, ball, multiplicity: int, part: str) -> Eigenvalue:
    """One distinct eigenvalue of a part (or of the matrix, after :func:`merge`): the root ``index`` (sympy's order:
    real ascending, then complex) of the monic irreducible rational ``factor``, exactly (a closed form for degree <= 2,
    else a ``CRootOf``) and as a certified ball, with its multiplicity and the part(s) it comes from. Its key (equal
    keys, equal eigenvalues, and conversely) is the factor's coefficients and the root's index."""
    key = (tuple(int(c) for c in factor.numer().coeffs()), index)
    return Eigenvalue(ball, "", multiplicity, exact=exact, factor=factor, index=index, part=part, key=key)


def submatrix(S: flint.fmpq_mat, indices: Sequence[int]) -> flint.fmpq_mat:
    """The principal submatrix of ``S`` on ``indices``."""
    return flint.fmpq_mat([[S[i, j] for j in indices] for i in indices])


def _support(S: flint.fmpq_mat, i: int) -> set[int]:
    return {j for j in range(S.ncols()) if S[i, j]}


def matrix_parts(S: flint.fmpq_mat, seeds: Sequence[int] = (0,)) -> tuple[MatrixPart, ...]:
    """The crease block (the closure of ``seeds``, the vertex and its sharp-edge neighbours, under row supports) and
    the sectors, or the whole matrix when that closure is everything (a dart, a semi-sharp crease)."""
    m = S.nrows()
    crease, todo = set(seeds), list(seeds)
    while todo:
        for j in _support(S, todo.pop()) - crease:
            crease.add(j)
            todo.append(j)
    if len(crease) == m and crease != set(seeds):
        return (MatrixPart("whole", tuple(range(m))),)
    rest = set(range(m)) - crease
    parts = [MatrixPart("crease", tuple(sorted(crease)))]
    links = {i: (_support(S, i) & rest) for i in rest}
    for i in rest:
        for j in links[i]:
            links[j].add(i)
    seen: set[int] = set()
    for start in sorted(rest):
        if start in seen:
            continue
        piece, todo = {start}, [start]
        while todo:
            for j in links[todo.pop()] - piece:
                piece.add(j)
                todo.append(j)
        seen |= piece
        parts.append(MatrixPart(f"sector {len(parts)}", tuple(sorted(piece))))
    return tuple(parts)


def _balls(p: flint.fmpq_poly, prec: int) -> list:
    with flint.ctx.workprec(prec):
        return [r for r, _ in p.numer().complex_roots()]


def _factor_roots(p: flint.fmpq_poly, prec: int) -> list[tuple[int, sp.Expr, object]]:
    """``(index, exact, ball)`` for each root of the irreducible ``p``, the ball matched to the exact value."""
    balls = _balls(p, prec)
    out = []
    for index in range(p.degree()):
        exact = root_expression(p, index)
        ball = _in_interval(exact, balls) if isinstance(exact, sp.CRootOf) else None
        if ball is None:  # a closed form (degree <= 2), or sympy's interval meets several balls
            approx = complex(sp.N(exact, 30))
            ball = min(balls, key=lambda b: abs(complex(float(b.real.mid()), float(b.imag.mid())) - approx))
        out.append((index, exact, ball))
    return out


def _in_interval(root: sp.CRootOf, balls: list):
    """The one ball that meets sympy's isolating interval of ``root`` (which holds that root and no other), or ``None``.

    The interval is what sympy already computed to number the roots; refining it to 30 digits, as evaluating the root
    does, costs minutes at degree 30 or more (the roots of a dart's factors), matching by the interval does not.
    """
    iv = root._get_interval()
    if isinstance(iv, sp.polys.rootisolation.RealInterval):
        box = ((iv.a, iv.b), (0, 0))
    else:
        box = ((iv.ax, iv.bx), (iv.ay, iv.by))
    (x0, x1), (y0, y1) = ((flint.arb(flint.fmpq(int(sp.Rational(v).p), int(sp.Rational(v).q))) for v in pair) for pair in box)
    hits = [b for b in balls if not (b.real < x0 or b.real > x1 or b.imag < y0 or b.imag > y1)]
    return hits[0] if len(hits) == 1 else None


def part_eigenvalues(S: flint.fmpq_mat, parts: Sequence[MatrixPart], *, prec: int = 256) -> list[Eigenvalue]:
    """Every distinct eigenvalue of each part, exactly, with its multiplicity in that part (parts in order)."""
    out = []
    for part in parts:
        chi = submatrix(S, part.indices).charpoly()
        _, factors = chi.factor()
        items = []
        for f, e in factors:
            f = f / f.leading_coefficient()
            for index, exact, ball in _factor_roots(f, prec):
                items.append(root_eigenvalue(f, index, exact, ball, e, part.label))
        out += sorted(items, key=lambda v: (-float(abs(v.ball).mid()), -float(v.ball.real.mid())))
    return out


def merge(values: Sequence[Eigenvalue]) -> list[Eigenvalue]:
    """The eigenvalues of several parts as those of their matrix: equal values joined, multiplicities added."""
    joined: dict[tuple, Eigenvalue] = {}
    for v in values:
        old = joined.get(v.key)
        if old is None:
            joined[v.key] = v
        else:
            parts = old.part if v.part in old.part.split(", ") else f"{old.part}, {v.part}"
            joined[v.key] = replace(old, multiplicity=old.multiplicity + v.multiplicity, part=parts)
    return by_modulus(list(joined.values()))


def by_modulus(values: Sequence[Eigenvalue]) -> list[Eigenvalue]:
    """``values`` sorted by decreasing modulus (then real part), by their balls' midpoints.

    The order is a presentation: where it matters (is this value strictly larger in modulus than
    that one?) :func:`separated` certifies it.
    """
    return sorted(values, key=lambda v: (-float(abs(v.ball).mid()), -float(v.ball.real.mid()), v.key))


def separated(a: Eigenvalue, b: Eigenvalue, *, max_prec: int = 4096) -> bool:
    """Whether ``|a| > |b|`` is certified (Arb, raising the precision of the roots up to ``max_prec`` bits)."""
    if a.key == b.key:
        return False
    prec = 256
    while True:
        ra = ball_at(a, prec)
        rb = ball_at(b, prec)
        if abs(ra) > abs(rb):
            return True
        if abs(ra) < abs(rb) or prec >= max_prec:
            return False
        prec *= 2


def ball_at(v: Eigenvalue, prec: int):
    """The eigenvalue's ball at ``prec`` bits (its own ball when that is at least as precise)."""
    if prec <= 256:
        return v.ball
    balls = _balls(v.factor, prec)
    for b in balls:
        if b.overlaps(v.ball):
            return b
    raise PrecisionError(f"the root {v.exact} was not found again at {prec} bits")  # pragma: no cover - isolating balls


def near_weight(scheme, vertex, k: int):
    """The near-edge rule's weight on the edge's other end in a sector of ``k`` faces, when it is irrational (else ``None``).

    BLZ's ``theta_k = pi/k``, or ``angle/k`` at a corner given its angle (:mod:`symdecomp.schemes.tagged_refinement`).
    """
    rules = scheme.sharp
    if rules is None or rules.near_edge_centre is None:
        return None
    theta = (vertex.angle if getattr(vertex, "angle", None) is not None else sp.pi) / k
    weight = rules.near_edge(theta, k)[1]
    return None if weight.is_Rational else weight


def sharp_matrix(scheme, vertex, *, level: int = 0):
    """The vertex's 1-ring matrix: a FLINT rational matrix, or a :class:`FieldMatrix` over ``Q(cos(pi/k))``."""
    from symdecomp.schemes.sector import exact_sharp_matrix, sharp_subdivision_matrix

    try:
        return exact_sharp_matrix(scheme, vertex, level=level)
    except NotApplicableError as refused:
        irrational = sorted(k for k in set(vertex.sectors) if near_weight(scheme, vertex, k) is not None)
        weights = {near_weight(scheme, vertex, k) for k in irrational}
        if not weights:  # irrational for another reason (Loop's cos(2 pi/n) at a dart): out of this route's reach
            raise
        if len(weights) != 1:
            fields = ", ".join(f"cos(pi/{k})" for k in irrational)
            raise NotApplicableError(f"scheme {scheme.name!r}: the sharp matrix's entries lie in Q({fields}) (sectors of "
                                     f"{' and '.join(map(str, irrational))} faces), beyond one field Q(cos(pi/k))") from None
        S = sharp_subdivision_matrix(scheme, vertex, level=level)
        try:
            return FieldMatrix.from_sympy(S.tolist(), weights.pop())
        except NotApplicableError as exc:
            raise NotApplicableError(f"{str(refused).split('; use ')[0]}, and {exc}") from None


def field_part_eigenvalues(M: FieldMatrix, parts, *, prec: int = 256) -> list[Eigenvalue]:
    """:func:`~symdecomp.analysis.triangular_eigen.part_eigenvalues` for a matrix over ``Q(w)``: each eigenvalue a root of
    an irreducible rational factor of the norm, with its exact multiplicity in the part at ``w``'s real value."""
    out = []
    for part in parts:
        P = M.submatrix(part.indices)
        chi = field_charpoly(P)
        items = []
        for f, _ in norm_charpoly(P).factor()[1]:
            f = f / f.leading_coefficient()
            found = field_roots(chi, f, P, prec=prec)
            if not found:
                continue
            named = _factor_roots(f, prec)
            for _, ball, mult in found:
                index, exact, own = next(t for t in named if t[2].overlaps(ball))
                items.append(root_eigenvalue(f, index, exact, own, mult, part.label))
        out += sorted(items, key=lambda v: (-float(abs(v.ball).mid()), -float(v.ball.real.mid())))
    return out


def sharp_values(scheme, vertex, *, level: int = 0, prec: int = 256):
    """``(S, parts, eigenvalues by part)`` of the vertex at ``level``, over ``Q`` or ``Q(cos(pi/k))``."""
    S = sharp_matrix(scheme, vertex, level=level)
    parts = matrix_parts(S, vertex.crease_points())
    if isinstance(S, flint.fmpq_mat):
        return S, parts, part_eigenvalues(S, parts, prec=prec)
    return S, parts, field_part_eigenvalues(S, parts, prec=prec)
