"""Exact linear algebra over one real algebraic number field ``K = Q(w)``, e.g. ``w = cos(pi/k)``.

Biermann-Levin-Zorin's sharp rules carry a weight ``w`` in ``Q(cos(pi/k))`` (a real cyclotomic field), and every
entry of a subdivision matrix built from them is ``p + q w`` with rational ``p, q`` (:func:`affine_in`: the
refinement is linear in the rules' weights). Here an element of ``K`` is a :class:`~symdecomp.algebra.number_field.
FieldElement` modulo the minimal polynomial of ``w``, and a matrix over ``K`` is a :class:`FieldMatrix`. What is exact:

* the characteristic polynomial ``chi_S`` in ``K[x]`` (Hessenberg reduction over ``K``, :func:`field_charpoly`);
* its norm ``N = prod_sigma sigma(chi_S)`` in ``Q[x]``: the characteristic polynomial of the rational matrix of
  ``S`` acting on ``K^n = Q^(n d)`` (:func:`norm_charpoly`), factored over ``Q`` by FLINT;
* which roots of an irreducible factor ``f`` of ``N`` are eigenvalues of ``S`` (at the real embedding given by a
  ball of ``w``) and with which multiplicity: the gcds ``g_t = gcd(chi_S / (g_1 ... g_(t-1)), f)`` in ``K[x]`` hold the
  roots of ``f`` of multiplicity ``>= t``, and Arb decides which roots of ``f`` those are (a root is excluded when its
  ball keeps ``g_t`` away from 0; exactly ``deg g_t`` must remain, else the precision is raised);
* left eigenvectors at a *rational* eigenvalue, over ``K`` (:func:`rational_left_eigenspace`).

>>> import sympy as sp
>>> w = sp.sqrt(5)
>>> field_of(w)                                                 # K = Q(sqrt 5)
x^2 + (-5)
>>> M = FieldMatrix.from_sympy([[w, 1], [1, 0]], w)             # chi = x^2 - sqrt(5) x - 1, coefficients in w
>>> [str(c) for c in field_charpoly(M)]
['(-1)', '(-1)*x', '1']
>>> norm_charpoly(M)                                            # (x^2 - sqrt5 x - 1)(x^2 + sqrt5 x - 1)
x^4 + (-7)*x^2 + 1
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.number_field import FieldElement, element_ball
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.errors import NotApplicableError, PrecisionError

__all__ = ["affine_in", "field_of", "FieldMatrix", "field_charpoly", "norm_charpoly", "field_roots", "rational_left_eigenspace",
           "poly_mul", "specialize", "field_name"]


def affine_in(e, weight) -> tuple[sp.Rational, sp.Rational] | None:
    """``(p, q)`` with rationals ``p, q`` if the number ``e`` is ``p + q w`` (``w = weight``), else ``None``.

    Exact: ``e`` and ``w`` expanded into rational multiples of the same irrational terms (sympy's canonical radicals or
    cosines); ``q`` is the ratio of their coefficients, the same on every term.
    """
    terms = sp.expand(sp.sympify(e, strict=True)).as_coefficients_dict()
    weight_terms = sp.expand(weight).as_coefficients_dict()
    p = sp.Rational(terms.pop(sp.Integer(1), 0))
    if not terms:
        return p, sp.Integer(0)
    if set(terms) != set(weight_terms) - {sp.Integer(1)} or not all(v.is_Rational for v in terms.values()):
        return None
    ratios = {sp.Rational(terms[t]) / sp.Rational(weight_terms[t]) for t in terms}
    if len(ratios) != 1:
        return None
    q = ratios.pop()
    return p - q * sp.Rational(weight_terms.get(sp.Integer(1), 0)), q


def field_of(weight) -> flint.fmpq_poly:
    """The monic minimal polynomial over ``Q`` of the real algebraic number ``weight`` (exact, sympy)."""
    x = sp.Dummy("x")
    poly = sp.Poly(sp.minimal_polynomial(weight, x), x)
    coeffs = [to_fmpq(sp.Rational(c)) for c in reversed(poly.all_coeffs())]
    p = flint.fmpq_poly(coeffs)
    return p / p[p.degree()]


@dataclass(frozen=True)
class FieldMatrix:
    """A square matrix over ``K = Q[w]/(modulus)``, rows of :class:`FieldElement`, with a ball of the real ``w``."""

    rows: tuple[tuple[FieldElement, ...], ...]
    modulus: flint.fmpq_poly
    #: The sympy value of the generator ``w`` (its real embedding).
    weight: sp.Expr

    @classmethod
    def from_sympy(cls, rows: Sequence[Sequence], weight) -> FieldMatrix:
        """From exact sympy entries ``p + q weight``; :class:`~symdecomp.errors.NotApplicableError` for any other entry."""
        modulus = field_of(weight)
        out = []
        for r, row in enumerate(rows):
            line = []
            for c, e in enumerate(row):
                pq = affine_in(e, weight)
                if pq is None:
                    raise NotApplicableError(f"entry ({r}, {c}) = {e} is not p + q*({weight}) with rational p, q")
                line.append(FieldElement(flint.fmpq_poly([to_fmpq(pq[0]), to_fmpq(pq[1])]) % modulus, modulus))
            out.append(tuple(line))
        return cls(tuple(out), modulus, sp.sympify(weight, strict=True))

    def nrows(self) -> int:
        return len(self.rows)

    def ncols(self) -> int:
        return len(self.rows)

    def __getitem__(self, index: tuple[int, int]) -> FieldElement:
        return self.rows[index[0]][index[1]]

    def submatrix(self, indices: Sequence[int]) -> FieldMatrix:
        return FieldMatrix(tuple(tuple(self.rows[i][j] for j in indices) for i in indices), self.modulus, self.weight)

    def weight_ball(self, prec: int) -> flint.arb:
        with flint.ctx.workprec(prec):
            return compile_expression(self.weight, (), "arb")()


def _const(q, modulus) -> FieldElement:
    return FieldElement(flint.fmpq_poly([q]), modulus)


def _hessenberg(A: list[list[FieldElement]]) -> None:
    """``A`` (over a field) to upper Hessenberg form in place, by similarity."""
    n = len(A)
    for m in range(1, n - 1):
        i = next((i for i in range(m, n) if A[i][m - 1]), None)
        if i is None:
            continue
        if i != m:
            A[i], A[m] = A[m], A[i]
            for row in A:
                row[i], row[m] = row[m], row[i]
        inv = A[m][m - 1].inverse()
        for i in range(m + 1, n):
            u = A[i][m - 1] * inv
            if u:
                A[i] = [a - u * b for a, b in zip(A[i], A[m])]
                for row in A:
                    row[m] = row[m] + u * row[i]


def _poly_ops(modulus):
    zero = _const(0, modulus)

    def sub(a, b):
        size = max(len(a), len(b))
        a, b = a + [zero] * (size - len(a)), b + [zero] * (size - len(b))
        return [x - y for x, y in zip(a, b)]

    def scale(a, s):
        return [x * s for x in a]

    return zero, sub, scale


def field_charpoly(M: FieldMatrix) -> list[FieldElement]:
    """``det(x I - M)`` in ``K[x]``, coefficients from the constant term up (monic)."""
    A = [list(row) for row in M.rows]
    _hessenberg(A)
    zero, sub, scale = _poly_ops(M.modulus)
    one = _const(1, M.modulus)
    p = [[one]]
    for m in range(len(A)):
        nxt = sub([zero] + p[m], scale(p[m], A[m][m]))
        prod = one
        for i in range(m - 1, -1, -1):
            prod = prod * A[i + 1][i]
            if not prod:
                break
            nxt = sub(nxt, scale(p[i], prod * A[i][m]))
        p.append(nxt)
    return p[-1]


def norm_charpoly(M: FieldMatrix) -> flint.fmpq_poly:
    """``prod_sigma sigma(chi_M)`` in ``Q[x]``: the characteristic polynomial of ``M`` as a rational ``(n d) x (n d)`` matrix."""
    n, d = M.nrows(), M.modulus.degree()
    big = flint.fmpq_mat(n * d, n * d)
    x = flint.fmpq_poly([0, 1])
    for i in range(n):
        for j in range(n):
            a = M[i, j].poly
            if a.is_zero():
                continue
            for t in range(d):  # (w^t a) in the basis 1, w, .., w^(d-1): row t of the block
                image = (a * x**t) % M.modulus
                for s in range(d):
                    big[i * d + t, j * d + s] = image[s]
    return big.charpoly()


def _divmod(a: list, b: list, modulus) -> tuple[list, list]:
    """Division with remainder in ``K[x]`` (``b`` with a nonzero leading coefficient)."""
    zero = _const(0, modulus)
    a = list(a)
    inv = b[-1].inverse()
    q = [zero] * max(len(a) - len(b) + 1, 1)
    while len(a) >= len(b) and any(a):
        s = a[-1] * inv
        shift = len(a) - len(b)
        q[shift] = s
        for i, bi in enumerate(b):
            a[shift + i] = a[shift + i] - s * bi
        a.pop()
        while a and not a[-1]:
            a.pop()
    return q, a


def _gcd(a: list, b: list, modulus) -> list:
    while b and any(b):
        _, r = _divmod(a, b, modulus)
        a, b = b, r
    inv = a[-1].inverse()
    return [x * inv for x in a]


def _root_count(g: list, roots: list, w, prec: int) -> list[bool]:
    """Which of the ``roots`` (balls) are roots of ``g`` in ``K[x]`` at ``w``: ``None`` where Arb cannot decide."""
    out = []
    with flint.ctx.workprec(prec):
        coeffs = [element_ball(c, w) for c in g]
        for r in roots:
            value = flint.acb(0)
            for c in reversed(coeffs):
                value = value * r + c
            out.append(value.contains(0))
    return out


def field_roots(chi: list[FieldElement], f: flint.fmpq_poly, M: FieldMatrix, *, prec: int = 256,
                max_prec: int = 8192) -> list[tuple[int, object, int]]:
    """``(index, ball, multiplicity)`` of each root of the irreducible ``f`` that is a root of ``chi`` (module docstring).

    ``index``: the root's position among ``f``'s certified complex roots (FLINT's order at ``prec``)."""
    from symdecomp.algebra.number_field import FieldElement as _FE

    fK = [_FE(flint.fmpq_poly([c]), M.modulus) for c in f.coeffs()]
    layers, rest = [], chi
    while True:
        g = _gcd(list(rest), list(fK), M.modulus)
        if len(g) <= 1:
            break
        layers.append(g)
        rest, _ = _divmod(rest, g, M.modulus)
    while True:
        with flint.ctx.workprec(prec):
            roots = [r for r, _ in f.numer().complex_roots()]
        w = M.weight_ball(prec)
        counts = [0] * len(roots)
        decided = True
        for g in layers:
            hits = _root_count(g, roots, w, prec)
            decided &= sum(hits) == len(g) - 1
            counts = [c + h for c, h in zip(counts, hits)]
        if decided:
            return [(i, roots[i], c) for i, c in enumerate(counts) if c]
        if prec >= max_prec:
            raise PrecisionError(f"the roots of {f} that are eigenvalues were not separated at {prec} bits")
        prec *= 2


def rational_left_eigenspace(M: FieldMatrix, value, order: Sequence[int]) -> list[list[FieldElement]]:
    """A basis over ``K`` of ``{v : v M = value v}`` for a rational ``value``, reduced with pivots in ``order`` (weight 1)."""
    n, mod = M.nrows(), M.modulus
    lam = _const(to_fmpq(value), mod)
    # rows of (M - value I)^T: v (M - lam) = 0  <=>  (M - lam)^T v^T = 0
    A = [[M[j, i] - (lam if i == j else _const(0, mod)) for j in range(n)] for i in range(n)]
    pivots, r = [], 0
    cols = list(order)
    for c in cols:
        p = next((i for i in range(r, n) if A[i][c]), None)
        if p is None:
            continue
        A[r], A[p] = A[p], A[r]
        inv = A[r][c].inverse()
        A[r] = [a * inv for a in A[r]]
        for i in range(n):
            if i != r and A[i][c]:
                u = A[i][c]
                A[i] = [a - u * b for a, b in zip(A[i], A[r])]
        pivots.append(c)
        r += 1
    free = [c for c in cols if c not in pivots]
    basis = []
    for fc in free:
        v = [_const(0, mod)] * n
        v[fc] = _const(1, mod)
        for i, pc in enumerate(pivots):
            v[pc] = _const(0, mod) - A[i][fc]
        basis.append(v)
    return basis


def poly_mul(a: Sequence[FieldElement], b: Sequence[FieldElement]) -> list[FieldElement]:
    """The product of two polynomials in ``K[x]`` (coefficient lists, constant term first)."""
    if not a or not b:
        return []
    zero = FieldElement(flint.fmpq_poly([]), a[0].modulus)
    out = [zero] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] = out[i + j] + x * y
    return out


def specialize(poly: sp.Poly, value: FieldElement) -> list[FieldElement]:
    """A rational polynomial in ``(x, d)`` as a polynomial in ``K[x]`` at ``d = value`` (coefficients from ``x^0`` up)."""
    x, d = poly.gens
    mod = value.modulus
    out = [FieldElement(flint.fmpq_poly([]), mod) for _ in range(poly.degree(x) + 1)]
    for (i, j), c in poly.terms():
        term = FieldElement(flint.fmpq_poly([to_fmpq(sp.Rational(c))]), mod)
        for _ in range(j):
            term = term * value
        out[i] = out[i] + term
    return out


def field_name(S) -> str:
    """``"Q"`` for a rational matrix, else its entries' field, e.g. ``"Q(cos(pi/5))"`` (``"Q(w), w = ..."`` otherwise)."""
    if isinstance(S, flint.fmpq_mat) or S.modulus.degree() == 1:
        return "Q"
    atoms = S.weight.atoms(sp.cos)
    if len(atoms) == 1:
        return f"Q({sp.sstr(atoms.pop())})"
    k = _cos_index(S)
    return f"Q(cos(pi/{k}))" if k else f"Q({sp.sstr(S.weight)})"


def _cos_index(S) -> int | None:
    """The ``k`` with ``Q(w) = Q(cos(pi/k))``: ``cos(pi/k)`` has ``w``'s degree and is a rational affine function of it."""
    d = S.modulus.degree()
    for k in range(2, 4 * d + 8):
        c = sp.cos(sp.pi / k)
        pq = affine_in(c, S.weight)
        if pq is not None and pq[1] != 0:
            return k
    return None
