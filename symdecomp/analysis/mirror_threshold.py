"""The sector's spectrum for every ``k``: the sine blocks as polynomials in ``c = cos(theta)``, exact characteristic
polynomials by resultants, and where the first sine eigenvalue passes the boundary curve's (issue 20, item 2).

A sine block's entries (:func:`symdecomp.analysis.mirror.sine_block`) are polynomials in ``c = cos(theta)`` on the
diagonal and multiples of ``h = cos(theta/2)`` off it, so its trace and determinant are polynomials in ``c``
(``h^2 = (1 + c)/2``). The frequencies of a sector of ``k`` faces are the roots ``cos(pi j/k)``, ``j = 1..k-1``, of the
Chebyshev polynomial ``U_(k-1)``, so the product of the blocks' characteristic polynomials is the resultant
``Res_c(U_(k-1)(c), det(x I - M(c)))`` up to a constant: an exact rational polynomial (:func:`sine_part`), compared
with the assembled matrix's characteristic polynomial in FLINT (:func:`charpoly_check`).

The boundary curve's eigenvalue is the crease block's on ``a_0 - a_k``: ``1 - crease_edge`` (1/2). Whether the first
sine block's largest eigenvalue exceeds it at ``c_k = cos(pi/k)`` depends on the signs of ``g(c) = det(M - lambda I)``
and ``t(c) = tr M - 2 lambda``; ``c_k`` increases with ``k``, so beyond the last real root of ``g t`` below 1 the answer
is the same for every ``k`` (:func:`first_exceeding`).
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.algebraic_sign import exact_sign
from symdecomp.analysis.mirror import (
    THETA,
    THETA_K,
    crease_block,
    mirror_stencils,
    sector_decomposition,
    sector_matrix,
    sine_block,
    vertex_layout,
    vertex_of,
)
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import check_scheme
from symdecomp.schemes.sector import sharp_subdivision_matrix

__all__ = ["C", "CK", "X", "in_cos", "block_polynomials", "sine_part", "sine_part_in_cos",
           "charpoly_check", "Threshold", "first_exceeding", "boundary_eigenvalue",
           "crease_eigenvectors"]

#: ``c = cos(theta)``, the variable of the sine blocks' polynomials.
C = sp.Symbol("c", real=True)
#: The variable of characteristic polynomials.
X = sp.Symbol("x")
_H = sp.Symbol("h", positive=True)


def boundary_eigenvalue(scheme, rules=None) -> sp.Expr:
    """The boundary curve's eigenvalue: the crease block's on ``O = 0, a_0 = 1, a_k = -1``, i.e. ``1 - crease_edge``."""
    Cb = crease_block(check_scheme(scheme), 2, rules=rules)
    v = sp.Matrix([0, 1, -1])
    return sp.simplify((Cb * v)[1] / v[1])


def in_cos(expr) -> sp.Expr:
    """``expr`` (in ``cos(theta)``, ``cos(theta/2)``) as a polynomial in :data:`C`, ``cos(theta/2)^2 = (1 + c)/2``."""
    out = sp.expand(sp.sympify(expr, strict=True).subs({sp.cos(THETA / 2): _H, sp.cos(THETA): C}))
    out = sp.expand(out.subs(_H**2, (1 + C) / 2))
    if out.has(THETA) or out.has(THETA_K):
        raise NotApplicableError(f"a sine block entry {expr} is not a polynomial in cos(theta)")
    return out


def block_polynomials(scheme, rules=None, *, first: bool = True) -> tuple[sp.Expr, sp.Expr]:
    """``(trace, det)`` of ``M(theta)`` as polynomials in :data:`C` (the determinant is the entry on triangles).

    ``first``: the sector angle ``theta_k`` of the sharp rules is ``theta`` (the block ``j = 1``); else the rules must
    not depend on it.
    """
    M = sine_block(scheme, rules)
    M = M.subs(THETA_K, THETA) if first else M
    if M.shape == (1, 1):
        return in_cos(M[0, 0]), in_cos(M[0, 0])
    off = in_cos(M[0, 1] * M[1, 0])
    return in_cos(M.trace()), sp.expand(in_cos(M[0, 0]) * in_cos(M[1, 1]) - off)


def _charpoly_in_c(scheme, rules=None) -> sp.Poly:
    tr, det = block_polynomials(scheme, rules, first=False)
    quad = check_scheme(scheme).face_rule is not None
    return sp.Poly(X**2 - tr * X + det if quad else X - tr, X, C)


def _frequencies(k: int, dart: bool) -> sp.Poly:
    """The polynomial in ``c`` whose roots are a sector's frequencies: ``cos(pi j/k)`` (``cos(2 pi j/k)`` at a dart)."""
    U = sp.Poly(sp.chebyshevu(k - 1, C), C)
    if dart:
        U = sp.gcd(U, sp.Poly(sp.chebyshevt(k, C) - 1, C))
        U = sp.Poly(sp.quo(U, sp.gcd(U, sp.Poly((C - 1) * (C + 1), C))), C)
    return U.monic() if U.degree() > 0 else sp.Poly(1, C)


def sine_part(scheme, k: int, rules=None, *, dart: bool = False) -> sp.Poly:
    """The product of the characteristic polynomials of a sector's sine blocks (and its face mode), exactly in ``Q[x]``.

    ``Res_c(F(c), det(x I - M(c)))`` with ``F`` monic with the frequencies as roots (:func:`_frequencies`), times
    ``x - h_0`` for the face mode on quads.
    """
    scheme = check_scheme(scheme)
    F = _frequencies(k, dart)
    p = _charpoly_in_c(scheme, rules)
    out = sp.Poly(sp.resultant(F.as_expr(), p.as_expr(), C), X) if F.degree() > 0 else sp.Poly(1, X)
    out = out.monic() if out.degree() > 0 else sp.Poly(1, X)
    if scheme.face_rule is not None and (not dart or k % 2 == 0):
        out *= sp.Poly(X - scheme.face_rule.b[0][1] if scheme.face_rule.b else X, X)
    return out


#: ``cos(theta_k)`` in the sine blocks of rules that read the sector angle (BLZ's).
CK = sp.Symbol("c_k", real=True)


def sine_part_in_cos(scheme, k: int, rules=None, *, dart: bool = False) -> sp.Poly:
    """:func:`sine_part` for rules whose weights hold ``cos(theta_k)``: exactly in ``Q[x, c_k]`` (:data:`CK`), the
    product over the frequencies ``cos(pi j/k)`` taken as the resultant in ``c`` with ``theta_k`` left symbolic."""
    from symdecomp import symbols

    scheme = check_scheme(scheme)
    M = sine_block(scheme, rules).subs({sp.cos(THETA_K): CK, symbols.sector_faces: k})
    if M.has(THETA_K):
        raise NotApplicableError("a sine block reads the sector angle other than through cos(theta_k)")
    if M.shape == (1, 1):
        p = sp.Poly(X - in_cos(M[0, 0]), X, C, CK)
    else:
        det = sp.expand(in_cos(M[0, 0]) * in_cos(M[1, 1]) - in_cos(M[0, 1] * M[1, 0]))
        p = sp.Poly(X**2 - in_cos(M.trace()) * X + det, X, C, CK)
    F = _frequencies(k, dart)
    out = sp.Poly(sp.resultant(F.as_expr(), p.as_expr(), C), X, CK) if F.degree() > 0 else sp.Poly(1, X, CK)
    lead = out.coeff_monomial(X ** out.degree(X)) if out.degree(X) > 0 else 1
    out = sp.Poly(out.as_expr() / lead, X, CK)
    if scheme.face_rule is not None and (not dart or k % 2 == 0):
        out *= sp.Poly(X - scheme.face_rule.b[0][1] if scheme.face_rule.b else X, X, CK)
    return out


def _flint_poly(poly: sp.Poly) -> flint.fmpq_poly:
    return flint.fmpq_poly([flint.fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q)) for c in reversed(poly.all_coeffs())])


def charpoly_check(scheme, vertex, rules=None, matrix=None) -> tuple[bool, flint.fmpq_poly, flint.fmpq_poly]:
    """Compare the characteristic polynomial of the 1-ring matrix (``matrix``; default: by exact refinement,
    :func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`, or assembled from ``rules`` when given) with the
    product of the blocks': the crease block's (or a dart's cosine part's) times :func:`sine_part` of each sector.

    Exact, in FLINT rationals; returns ``(equal, of the matrix, of the blocks)``. Rational rules only.
    """
    scheme = check_scheme(scheme)
    lay = vertex_layout(scheme, vertex)
    mirror_stencils(scheme)  # the blocks need the mirror: refuse, naming the weight, before refining
    if matrix is None:  # the matrix by refinement of the tagged mesh, which knows nothing of the blocks
        P = sharp_subdivision_matrix(scheme, vertex_of(scheme, vertex)) if rules is None else sector_matrix(scheme, vertex, rules)
    else:
        P = matrix
    if any(not sp.sympify(e, strict=True).is_Rational for e in P):
        raise NotApplicableError("the matrix has irrational entries: FLINT's rational characteristic polynomial does not apply")
    full = flint.fmpq_mat([[flint.fmpq(int(e.p), int(e.q)) for e in row] for row in P.tolist()]).charpoly()
    dart = len(lay.sharp) == 1
    if dart:
        head = sp.Poly(sector_decomposition(scheme, vertex, rules).cosine.charpoly(X).as_expr(), X)
    else:
        idx = [0] + [lay.a(m) for m in lay.sharp]
        head = sp.Poly(P.extract(idx, idx).charpoly(X).as_expr(), X)
    blocks = _flint_poly(head)
    for k in lay.sectors:
        blocks *= _flint_poly(sine_part(scheme, k, rules, dart=dart))
    return full == blocks, full, blocks


@dataclass(frozen=True)
class Threshold:
    """Where the first sine eigenvalue passes the boundary curve's ``value``, for every ``k`` (:func:`first_exceeding`)."""

    value: sp.Expr
    #: ``g(c)`` and ``t(c)`` (see the module docstring).
    g: sp.Expr
    t: sp.Expr
    #: ``{k: ">", "=", "<"}`` for ``k = 2..last``: the largest eigenvalue of ``M(pi/k)`` against ``value``.
    table: dict
    #: The relation for every ``k > last`` (one sign beyond the last root of ``g t`` below 1).
    beyond: str
    #: The first ``k`` from which the relation is ``>`` for every larger ``k`` (``None`` if never).
    first: int | None
    #: True when ``g`` is identically 0: ``value`` is an eigenvalue of ``M(pi/k)`` for every ``k``.
    identically: bool


def _relation(g_sign: int, t_sign: int, quad: bool) -> str:
    if not quad:
        return {1: ">", 0: "=", -1: "<"}[g_sign]
    if g_sign < 0 or (t_sign > 0):
        return ">"
    return "=" if g_sign == 0 else "<"


def _last_root(poly: sp.Expr) -> sp.Rational:
    """A rational bound at or above every real root of ``poly`` below 1 (-1 if none)."""
    p = sp.Poly(poly, C)
    while p.degree() > 0 and p.eval(1) == 0:
        p = sp.Poly(sp.quo(p, sp.Poly(C - 1, C)), C)
    bounds = [sp.Rational(-1)]
    for (lo, hi), _ in (p.intervals() if p.degree() > 0 else []):
        while hi >= 1 > lo:
            (lo, hi), = [iv for iv, _ in p.intervals(inf=lo, sup=hi, eps=(hi - lo) / 4)][:1]
        if hi < 1:
            bounds.append(sp.Rational(hi))
    return max(bounds)


def first_exceeding(scheme, rules=None) -> Threshold:
    """Compare the largest eigenvalue of the first sine block ``M(pi/k)`` with the boundary curve's, for every ``k >= 2``."""
    scheme = check_scheme(scheme)
    quad = scheme.face_rule is not None
    lam = boundary_eigenvalue(scheme, rules)
    tr, det = block_polynomials(scheme, rules)
    g = sp.expand(det - lam * tr + lam**2) if quad else sp.expand(tr - lam)
    t = sp.expand(tr - 2 * lam)
    if g == 0:
        return Threshold(lam, g, t, {}, "=", None, True)
    bound = _last_root(g * t if quad and t != 0 else g)
    sample = (bound + 1) / 2
    beyond = _relation(exact_sign(g.subs(C, sample)), exact_sign(t.subs(C, sample)), quad)
    table, k = {}, 2
    while True:
        ck = sp.cos(sp.pi / k)
        table[k] = _relation(exact_sign(g.subs(C, ck)), exact_sign(t.subs(C, ck)), quad)
        if exact_sign(ck - bound) > 0:
            break
        k += 1
    first = None
    if beyond == ">":
        first = k
        while first - 1 in table and table[first - 1] == ">":
            first -= 1
    return Threshold(lam, g, t, table, beyond, first, False)


def _mirror_permutation(lay) -> list[int]:
    """The mirror ``a_i <-> a_(k-i)``, ``b_i <-> b_(k-1-i)`` of an open fan of one sector, as a permutation of the 1-ring."""
    k = lay.faces
    perm = [0] + [lay.a(k - i) for i in range(k + 1)]
    return perm + ([lay.b(k - 1 - i) for i in range(k)] if lay.quad else [])


def crease_eigenvectors(scheme, vertex, rules=None) -> tuple[tuple[sp.Expr, sp.Matrix | None, int | None], ...]:
    """The eigenvectors of the crease block's eigenvalues, continued into the sector: ``(lambda, vector, parity)``.

    For an eigenvector ``c`` of ``C`` the interior part solves ``(lambda - T) y = X c`` exactly; ``vector`` is ``None``
    when ``lambda`` is also an eigenvalue of ``T`` (the continuation is not unique, or there is a Jordan block).
    ``parity`` is ``+1`` (mirror symmetric: the cosine-type polylines), ``-1`` (antisymmetric) or ``None``, for a
    boundary or corner vertex (one open sector); ``None`` elsewhere.
    """
    scheme = check_scheme(scheme)
    lay = vertex_layout(scheme, vertex)
    if len(lay.sharp) < 2:
        raise NotApplicableError("vertex: a dart has no crease block; its symmetric part is sector_decomposition(...).cosine")
    P = sector_matrix(scheme, vertex, rules)
    head = [0] + [lay.a(m) for m in lay.sharp]
    tail = [i for i in range(lay.size) if i not in head]
    Cb, X_, T = P.extract(head, head), P.extract(tail, head), P.extract(tail, tail)
    perm = _mirror_permutation(lay) if not lay.closed and len(lay.sectors) == 1 else None
    out = []
    for lam, _, vectors in Cb.eigenvects():
        for c in vectors:
            A = lam * sp.eye(len(tail)) - T
            if A.det() == 0:
                out.append((lam, None, None))
                continue
            y = A.LUsolve(X_ * c)
            v = sp.zeros(lay.size, 1)
            for r, i in enumerate(head):
                v[i] = c[r]
            for r, i in enumerate(tail):
                v[i] = sp.simplify(y[r])
            parity = None
            if perm is not None:
                mirrored = sp.Matrix([v[perm[i]] for i in range(lay.size)])
                parity = 1 if mirrored == v else (-1 if mirrored == -v else None)
            out.append((lam, v, parity))
    return tuple(out)
