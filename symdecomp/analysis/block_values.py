"""The spectrum of a boundary, crease or corner vertex from the blocks of its mirror decomposition, O(k) per vertex.

The one-step matrix of a vertex with infinitely sharp edges is block lower-triangular ``[[C, 0], [X, T]]``
(:mod:`symdecomp.analysis.mirror`): the crease block ``C`` (``O`` and its sharp-edge neighbours, 3 x 3) and, per
sector of ``k`` faces, the sine blocks ``M(pi j/k)``, ``j = 1..k-1`` (2 x 2 on quads, 1 x 1 on triangles), and on
quads the last mode ``h_0`` (``j = k``). That the sine polylines are invariant is an identity in ``theta`` and the
index (:func:`~symdecomp.analysis.mirror.sine_identity`, checked here once per scheme), so it holds for every ``k``;
the blocks' sizes add up to the matrix's. So the spectrum is:

* the crease block's eigenvalues, exactly (FLINT's characteristic polynomial, factored over ``Q``);
* each sine block's two roots of ``x^2 - t(c) x + d(c)``, with ``t, d`` the block's trace and determinant as
  polynomials in ``c = cos(pi j/k)`` and (BLZ's rules) ``c_k = cos(pi/k)``
  (:func:`~symdecomp.analysis.mirror_threshold.block_polynomials`): an exact closed form, and a certified Arb ball;
* the last mode's ``h_0``.

Multiplicities are exact: blocks with the same ``theta`` and rules are the same block; values whose balls overlap
are decided equal or not exactly in ``K = Q(cos(pi/k))`` (a rational or a root of one block is a root of another's
quadratic, with the right sign of the square root), and values not decided so are separated by raising Arb's
precision, else refused (:class:`~symdecomp.errors.NotApplicableError`, the dense route then decides). Work: O(k)
block evaluations, no matrix of the vertex. The dense route (:func:`~symdecomp.analysis.spectrum.sharp_spectrum`
with ``route="dense"``) is the independent cross-check.

Out of reach here (refused, so the dense route is used): darts (their symmetric part is not a small block), semi-sharp
edges, corners given an angle, and rules that read ``theta_k`` other than through ``cos(theta_k)``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace
from fractions import Fraction

import flint
import sympy as sp

from symdecomp import symbols
from symdecomp.algebra.number_field import FieldElement
from symdecomp.analysis.eigenvalue import Eigenvalue, MirrorBlock
from symdecomp.analysis.mirror import THETA_K, crease_block, mirror_stencils, sine_block, sine_identity, vertex_layout
from symdecomp.analysis.mirror_threshold import CK, C, in_cos
from symdecomp.analysis.triangular_eigen import MatrixPart, ball_at, part_eigenvalues
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import check_scheme

__all__ = ["structural_values", "layout", "block_values", "MAX_PREC"]

#: Most bits Arb is given to separate two values that are not decided equal exactly.
MAX_PREC = 4096
_X = sp.Symbol("x")


@functools.lru_cache(maxsize=32)
def checked_polynomials(scheme) -> tuple[sp.Expr, sp.Expr, bool]:
    """``(trace, det, quad)`` of the sine block in ``C`` and ``CK``, after checking the sine identity for every ``k``."""
    residual, _ = sine_identity(scheme)
    if any(sp.simplify(r) != 0 for r in residual):
        raise NotApplicableError(f"scheme {scheme.name!r}: the sine polylines are not invariant (residual {list(residual)})")
    tr, det = _with_ck(scheme)
    return tr, det, scheme.face_rule is not None


def _with_ck(scheme) -> tuple[sp.Expr, sp.Expr]:
    """The block's trace and determinant with ``cos(theta_k)`` as :data:`CK` (BLZ's rules)."""
    M = sine_block(scheme).subs(sp.cos(THETA_K), CK)
    if M.has(THETA_K):
        raise NotApplicableError(f"scheme {scheme.name!r}: the rules read the sector angle other than through cos(theta_k)")
    if M.shape == (1, 1):
        return in_cos(M[0, 0]), in_cos(M[0, 0])
    return in_cos(M.trace()), sp.expand(in_cos(M[0, 0]) * in_cos(M[1, 1]) - in_cos(M[0, 1] * M[1, 0]))


class _Field:
    """``K = Q(cos(pi/k))``: elements are rational polynomials in ``x = cos(pi/k)`` modulo its minimal polynomial."""

    def __init__(self, k: int):
        self.k = k

    @functools.cached_property
    def modulus(self) -> flint.fmpq_poly:
        """The minimal polynomial of ``cos(pi/k)`` (computed when an element is first needed: most blocks need none)."""
        p = flint.fmpz_poly.cos_minpoly(2 * self.k)  # of 2 cos(2 pi/(2k))
        q = flint.fmpq_poly([c * 2**i for i, c in enumerate(p.coeffs())])
        return q / q[q.degree()]

    def element(self, poly: flint.fmpq_poly) -> FieldElement:
        return FieldElement(poly % self.modulus, self.modulus)

    def rational(self, q) -> FieldElement:
        return self.element(flint.fmpq_poly([flint.fmpq(q.numerator, q.denominator)]))

    def cos_multiple(self, m: int) -> FieldElement:
        """``cos(m pi/k) = T_m(cos(pi/k))``."""
        return self.element(flint.fmpq_poly(flint.fmpz_poly.chebyshev_t(m)))

    def ball(self, e: FieldElement, prec: int):
        with flint.ctx.workprec(prec):
            x = flint.arb.cos_pi_fmpq(flint.fmpq(1, self.k))
            acc = flint.arb(0)
            for c in reversed(e.poly.coeffs()):
                acc = acc * x + flint.arb(c)
            return acc


@functools.lru_cache(maxsize=64)
def _symbolic_terms(expr: sp.Expr) -> tuple[tuple[int, int, sp.Expr], ...] | None:
    """``expr`` as ``(a, b, coefficient)`` terms of ``c^a c_k^b``, coefficients possibly in ``k`` (``None``: not a polynomial)."""
    try:
        poly = sp.Poly(sp.expand(expr), C, CK)
    except sp.PolynomialError:
        return None
    return tuple((a, b, coeff) for (a, b), coeff in poly.terms())


def poly_terms(expr: sp.Expr, k: int) -> tuple[tuple[int, int, Fraction], ...]:
    """``expr`` at ``k`` faces as ``(a, b, coefficient)`` terms of ``c^a c_k^b``, rational coefficients, or refused.

    The polynomial is read once per expression (sympy), its coefficients evaluated at each ``k``."""
    expr = sp.sympify(expr, strict=True)
    terms = _symbolic_terms(expr)
    if terms is None:
        raise NotApplicableError(f"a sine block's trace or determinant {expr.xreplace({symbols.sector_faces: sp.Integer(k)})} "
                                 "is not a polynomial in cos(theta), cos(theta_k)")
    out = []
    for a, b, coeff in terms:
        coeff = sp.expand(coeff.xreplace({symbols.sector_faces: sp.Integer(k)})) if coeff.free_symbols else coeff
        if coeff == 0:
            continue
        if not coeff.is_Rational:
            raise NotApplicableError(f"a sine block's coefficient {coeff} is not rational")
        out.append((a, b, Fraction(int(coeff.p), int(coeff.q))))
    return tuple(out)


def eval_arb(terms, c, ck):
    acc = flint.arb(0)
    for a, b, q in terms:
        acc += flint.arb(flint.fmpq(q.numerator, q.denominator)) * c**a * ck**b
    return acc


def _eval_field(terms, field: _Field, c: FieldElement, ck: FieldElement) -> FieldElement:
    acc = field.rational(Fraction(0))
    for a, b, q in terms:
        term = field.rational(q)
        for _ in range(a):
            term = term * c
        for _ in range(b):
            term = term * ck
        acc = acc + term
    return acc


@dataclass
class _Block:
    """One sine block ``M(pi j/k)`` of a sector: its trace and determinant, numerically and (on demand) exactly in K."""

    k: int
    j: int
    terms: tuple  # (trace terms, det terms)
    quad: bool
    field: _Field

    def arb(self, prec: int) -> tuple:
        with flint.ctx.workprec(prec):
            c, ck = flint.arb.cos_pi_fmpq(flint.fmpq(self.j, self.k)), flint.arb.cos_pi_fmpq(flint.fmpq(1, self.k))
            return eval_arb(self.terms[0], c, ck), eval_arb(self.terms[1], c, ck)

    @functools.cached_property
    def exact(self) -> tuple[FieldElement, FieldElement]:
        f = self.field
        c, ck = f.cos_multiple(self.j), f.cos_multiple(1)
        return _eval_field(self.terms[0], f, c, ck), _eval_field(self.terms[1], f, c, ck)

    def root(self, sign: int, prec: int):
        """``(t + sign sqrt(t^2 - 4 d))/2`` (principal root), or ``t`` on a 1 x 1 block, as a ball."""
        t, d = self.arb(prec)
        with flint.ctx.workprec(prec):
            if not self.quad:
                return flint.acb(t)
            return (flint.acb(t) + sign * flint.acb(t * t - 4 * d).sqrt()) / 2

    def is_root(self, sign: int, e: FieldElement) -> bool:
        """Whether ``e`` in K is this block's root of that sign (0: its only root), exactly."""
        t, d = self.exact
        if not self.quad:
            return not (t - e)
        if e * e - t * e + d:
            return False
        diff = e - (t - e)  # e minus the other root
        if not diff or sign == 0:
            return True
        return _sign(self.field, diff) == sign


def _sign(field: _Field, e: FieldElement) -> int:
    """The sign of a nonzero element of K at ``cos(pi/k)`` (Arb, precision raised until the ball excludes 0)."""
    prec = 128
    while prec <= MAX_PREC:
        b = field.ball(e, prec)
        if b > 0 or b < 0:
            return 1 if b > 0 else -1
        prec *= 2
    raise NotApplicableError(f"the sign of an element of Q(cos(pi/{field.k})) was not decided at {MAX_PREC} bits")


@dataclass(frozen=True)
class _Witness:
    """What decides exactly whether an eigenvalue of one block equals another's, and gives its ball at any precision:
    a rational value, a sine block's root of that sign, or an eigenvalue of the crease block (kept as the
    :attr:`~symdecomp.analysis.eigenvalue.Eigenvalue.witness` of its value while equal values are joined)."""

    rational: Fraction | None = None
    block: _Block | None = None
    sign: int = 0
    crease: Eigenvalue | None = None  # an eigenvalue of the crease block

    def ball(self, prec: int):
        if self.rational is not None:
            with flint.ctx.workprec(prec):
                return flint.acb(flint.fmpq(self.rational.numerator, self.rational.denominator))
        if self.crease is not None:
            return ball_at(self.crease, prec)
        assert self.block is not None  # one of the three is set
        return self.block.root(self.sign, prec)


def _item(key: tuple, multiplicity: int, names: list, exact: str, rational: Fraction | None = None, **work) -> Eigenvalue:
    """One eigenvalue of one block (no ball yet), with its witness."""
    return Eigenvalue(None, "", multiplicity, exact=exact, blocks=tuple(names), key=key, witness=_Witness(rational, **work))


def _decide(x: Eigenvalue, y: Eigenvalue) -> bool | None:
    """Whether two values are equal, exactly; ``None`` where this route cannot tell (then Arb separates them)."""
    a, b = x.witness, y.witness
    if a.rational is not None and b.rational is not None:
        return a.rational == b.rational
    if a.block is None:
        a, b = b, a
    if a.block is None or (b.block is None and b.rational is None):
        return None
    if b.rational is not None:
        return a.block.is_root(a.sign, a.block.field.rational(b.rational))
    if a.block.k != b.block.k:
        return None
    (t1, d1), (t2, d2) = a.block.exact, b.block.exact
    if not b.block.quad:
        return a.block.is_root(a.sign, t2)
    if not a.block.quad:
        return b.block.is_root(b.sign, t1)
    if not (t1 - t2):
        return not (d1 - d2) and a.sign == b.sign
    x0 = (d1 - d2) * (t1 - t2).inverse()
    return a.block.is_root(a.sign, x0) and b.block.is_root(b.sign, x0)


def _overlapping(items: list[Eigenvalue], prec: int) -> list[tuple[int, int]]:
    balls = [it.witness.ball(prec) for it in items]
    order = sorted(range(len(items)), key=lambda i: float(balls[i].real.lower()))
    pairs = []
    for pos, i in enumerate(order):
        top = balls[i].real.upper()
        for j in order[pos + 1:]:
            if balls[j].real.lower() > top:
                break
            if balls[i].overlaps(balls[j]):
                pairs.append((min(i, j), max(i, j)))
    return pairs


def _separated(a: Eigenvalue, b: Eigenvalue, prec: int) -> bool:
    while prec < MAX_PREC:
        prec *= 2
        if not a.witness.ball(prec).overlaps(b.witness.ball(prec)):
            return True
    return False


def _fraction(q) -> Fraction:
    return Fraction(int(q.p), int(q.q))


def _crease_items(scheme, lay, prec: int) -> list[Eigenvalue]:
    """The crease block's eigenvalues, exactly (FLINT), as items (a new list: the caller adds the sectors' to it)."""
    return list(_crease_eigenvalues(scheme, len(lay.sharp), lay.corner, prec))


@functools.lru_cache(maxsize=32)
def _crease_eigenvalues(scheme, count: int, corner: bool, prec: int) -> tuple[Eigenvalue, ...]:
    """The crease block has no ``k`` (:func:`~symdecomp.analysis.mirror.crease_block`): its eigenvalues are derived once per
    scheme, kind of vertex and precision, not once per sector."""
    block = crease_block(scheme, count, corner=corner)
    if not all(sp.sympify(e, strict=True).is_Rational for e in block):
        raise NotApplicableError(f"scheme {scheme.name!r}: the crease block {block.tolist()} is not rational")
    S = flint.fmpq_mat([[flint.fmpq(int(e.p), int(e.q)) for e in row] for row in block.tolist()])
    out = []
    for v in part_eigenvalues(S, [MatrixPart("crease", tuple(range(S.nrows())))], prec=prec):
        rational = -_fraction(v.factor[0]) if v.factor.degree() == 1 else None
        key = ("q", rational) if rational is not None else ("crease", v.key)
        out.append(_item(key, v.multiplicity, [MirrorBlock("crease")], sp.sstr(v.exact), rational, crease=v))
    return tuple(out)


def _theta_text(j: int, k: int) -> str:
    q = Fraction(j, k)
    return f"cos({'' if q.numerator == 1 else f'{q.numerator}*'}pi/{q.denominator})" if q.denominator > 1 else f"cos({q.numerator}*pi)"


def _sector_items(scheme, s: int, k: int, polys: tuple, prec: int, fields: dict, js: range | None = None) -> list[Eigenvalue]:
    """The sine blocks ``j`` in ``js`` (default ``1..k-1``) of sector ``s`` (``k`` faces) and, on quads, its last mode,
    as items."""
    tr, det, quad = polys
    at = {symbols.sector_faces: sp.Integer(k)}
    terms = (poly_terms(tr, k), poly_terms(det, k))
    uses_k = any(b for part in terms for _, b, _ in part) or tr.has(symbols.sector_faces) or det.has(symbols.sector_faces)
    field = fields.setdefault(k, _Field(k))
    where = (f", c_k = cos(pi/{k})" if any(b for part in terms for _, b, _ in part) else "")
    t_text, d_text = sp.sstr(tr.xreplace(at)), sp.sstr(det.xreplace(at))
    out = []
    for j in range(1, k) if js is None else js:
        blk, names = _Block(k, j, terms, quad, field), [MirrorBlock("sine", s, j)]
        base, c = ("sine", Fraction(j, k), k if uses_k else None), f", c = {_theta_text(j, k)}{where}"
        if not quad:
            out.append(_item(base + (0,), 1, names, f"{t_text}{c}", block=blk))
            continue
        t, d = blk.arb(prec)
        with flint.ctx.workprec(prec):
            disc = t * t - 4 * d
        if disc.contains(0):
            te, de = blk.exact
            if not (te * te - de * field.rational(Fraction(4))):
                out.append(_item(base + (0,), 2, names * 2, f"t/2 with t = {t_text}{c}", block=blk))
                continue
        for sign in (1, -1):
            text = f"(t {'+' if sign > 0 else '-'} sqrt(t**2 - 4*d))/2 with t = {t_text}, d = {d_text}{c}"
            out.append(_item(base + (sign,), 1, list(names), text, block=blk, sign=sign))
    if quad:
        h0 = sp.sympify(mirror_stencils(scheme)[1]["b"].get(0, 0), strict=True)
        if not h0.is_Rational:
            raise NotApplicableError(f"scheme {scheme.name!r}: the face rule's own weight {h0} is not rational")
        out.append(_item(("q", Fraction(int(h0.p), int(h0.q))), 1, [MirrorBlock("face", s, k)], sp.sstr(h0),
                         Fraction(int(h0.p), int(h0.q))))
    return out


def _join(items: list[Eigenvalue], prec: int) -> list[Eigenvalue]:
    """Equal values joined (equal keys, then overlapping balls decided exactly or separated by Arb)."""
    merged: dict = {}
    for it in items:
        old = merged.get(it.key)
        merged[it.key] = it if old is None else replace(old, multiplicity=old.multiplicity + it.multiplicity,
                                                        blocks=old.blocks + it.blocks)
    items = list(merged.values())
    parent = list(range(len(items)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    undecided = []
    for i, j in _overlapping(items, prec):
        equal = _decide(items[i], items[j])
        if equal is None:
            undecided.append((i, j))
        elif equal:
            parent[root(i)] = root(j)
    for i, j in undecided:  # after the exact decisions: equal through a third value (a rational), or told apart by Arb
        if root(i) != root(j) and not _separated(items[i], items[j], prec):
            raise NotApplicableError(f"two eigenvalues ({items[i].exact}; {items[j].exact}) were neither decided equal "
                                     f"nor separated at {MAX_PREC} bits")
    groups: dict = {}
    for i, it in enumerate(items):
        groups.setdefault(root(i), []).append(it)
    out = []
    for group in groups.values():
        rep = min(group, key=lambda it: (it.witness.rational is None, it.witness.crease is None))
        names = tuple(n for it in group for n in it.blocks)
        out.append(replace(rep, value=rep.witness.ball(prec), multiplicity=sum(it.multiplicity for it in group), blocks=names,
                           witness=None))
    return out


def structural_values(scheme, vertex, *, prec: int = 256) -> tuple[list[Eigenvalue], int]:
    """``(distinct eigenvalues, matrix size)`` of a boundary, crease or corner vertex from its blocks (module docstring).

    Refuses (:class:`~symdecomp.errors.NotApplicableError`) what this route does not reach: darts, semi-sharp edges,
    corners given an angle, rules without a mirror decomposition, values it cannot tell apart.
    """
    scheme = check_scheme(scheme)
    lay = layout(scheme, vertex)
    values = block_values(scheme, lay, prec)
    if sum(v.multiplicity for v in values) != lay.size:  # pragma: no cover - the blocks' sizes add up by construction
        raise NotApplicableError(f"the blocks hold {sum(v.multiplicity for v in values)} eigenvalues, the matrix {lay.size}")
    return values, lay.size


def layout(scheme, vertex):
    """The vertex's layout (:func:`~symdecomp.analysis.mirror.vertex_layout`), or refused where this route does not reach."""
    lay = vertex_layout(scheme, vertex)
    if len(lay.sharp) == 1:
        raise NotApplicableError("a dart's symmetric part is not a small block; the structural route reads boundary, "
                                 "crease and corner vertices")
    if getattr(vertex, "angle", None) is not None:
        raise NotApplicableError("a corner given an angle: the structural route reads theta_k = pi/k")
    return lay


def block_values(scheme, lay, prec: int, head: int | None = None) -> list[Eigenvalue]:
    """The distinct eigenvalues of the crease block, the last modes and the sine blocks ``j <= head`` (default: every
    ``j``) of a :func:`layout`, joined exactly, largest modulus first."""
    polys = checked_polynomials(scheme)
    items, fields = _crease_items(scheme, lay, prec), {}
    for s, k in enumerate(lay.sectors):
        items += _sector_items(scheme, s, k, polys, prec, fields, None if head is None else range(1, min(k, head + 1)))
    values = _join(items, prec)
    values.sort(key=lambda v: (-float(abs(v.ball).mid()), -float(v.ball.real.mid())))
    return values
