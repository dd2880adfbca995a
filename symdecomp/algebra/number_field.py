"""Exact left eigenspaces of a rational matrix at an algebraic eigenvalue, in ``Q(lambda) = Q[x]/(p)``.

An eigenvalue of a rational matrix ``S`` is a root of an irreducible rational factor ``p`` of its
characteristic polynomial. Its left eigenvectors have entries in the field ``Q(lambda)``, each
written as a rational polynomial in ``lambda`` of degree ``< deg p`` (:class:`FieldElement`).
They are found by rational linear algebra only: with ``X`` the matrix of multiplication by
``x`` modulo ``p`` (the companion matrix), the coefficient matrix ``W`` (row ``i`` = the
coefficients of ``w_i``) of a left eigenvector satisfies the linear system ``S^T W = W X^T``,
whose rational null space (FLINT ``rref``) spans the eigenspace over ``Q``. The basis returned
is reduced over the field: each vector has a 1 at its own pivot and 0 at the others' pivots,
pivots taken in a given column order, so the result does not depend on elimination choices.

>>> import flint
>>> S = flint.fmpq_mat([[0, 1], [1, 1]])          # the eigenvalues (1 +- sqrt 5)/2
>>> p = flint.fmpq_poly([-1, -1, 1])              # x^2 - x - 1
>>> (w,) = left_eigenspace(S, p)
>>> [str(x) for x in w]
['1', 'x']
>>> to_sympy_vector(w, p, 1)                      # at the root (1 + sqrt 5)/2, the larger one
[1, 1/2 + sqrt(5)/2]
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq, to_sympy
from symdecomp.algebra.small_eigen import nullspace
from symdecomp.errors import InvalidInputError

__all__ = ["FieldElement", "left_eigenspace", "to_sympy_vector", "root_expression", "element_ball", "reduced_basis",
           "quadratic_element", "quadratic_expression"]


@dataclass(frozen=True)
class FieldElement:
    """An element of ``Q[x]/(p)``: a rational polynomial of degree ``< deg p``, reduced."""

    #: The reduced polynomial.
    poly: flint.fmpq_poly
    #: The modulus, irreducible over ``Q``.
    modulus: flint.fmpq_poly

    def __mul__(self, other: FieldElement) -> FieldElement:
        return FieldElement((self.poly * other.poly) % self.modulus, self.modulus)

    def __add__(self, other: FieldElement) -> FieldElement:
        return FieldElement(self.poly + other.poly, self.modulus)

    def __sub__(self, other: FieldElement) -> FieldElement:
        return FieldElement(self.poly - other.poly, self.modulus)

    def __bool__(self) -> bool:
        return not self.poly.is_zero()

    def inverse(self) -> FieldElement:
        """``1/self`` by the extended Euclidean algorithm (``p`` irreducible: every nonzero element is a unit)."""
        g, s, _ = self.poly.xgcd(self.modulus)
        if g.degree() != 0:
            raise ZeroDivisionError("not invertible modulo the given polynomial (zero, or the modulus is reducible)")
        return FieldElement((s / g[0]) % self.modulus, self.modulus)

    def __str__(self) -> str:
        return str(self.poly)


def _companion_system(S: flint.fmpq_mat, p: flint.fmpq_poly) -> list[list]:
    """The rational matrix of ``W -> S^T W - W X^T`` on ``vec(W)`` (index ``i*d + t``)."""
    m, d = S.nrows(), p.degree()
    lead = p[d]
    # X e_t = e_{t+1} (t < d-1), X e_{d-1} = -sum_t (p_t/lead) e_t: column s of X
    X = [[flint.fmpq(0)] * d for _ in range(d)]
    for s in range(d - 1):
        X[s + 1][s] = flint.fmpq(1)
    for t in range(d):
        X[t][d - 1] = -p[t] / lead
    rows = []
    for j in range(m):
        for t in range(d):
            row = [flint.fmpq(0)] * (m * d)
            for i in range(m):
                if S[i, j] != 0:
                    row[i * d + t] += S[i, j]
            for s in range(d):
                if X[t][s] != 0:
                    row[j * d + s] -= X[t][s]
            rows.append(row)
    return rows


def reduced_basis(vectors: list[list[FieldElement]], order: Sequence[int]) -> list[list[FieldElement]]:
    """A field basis of the span of ``vectors`` in reduced echelon form, pivots in ``order``."""
    basis: list[list[FieldElement]] = []
    pivots: list[int] = []
    for v in vectors:
        v = list(v)
        for b, c in zip(basis, pivots):
            if v[c]:
                f = v[c]
                v = [x - f * y for x, y in zip(v, b)]
        c = next((c for c in order if v[c]), None)
        if c is None:
            continue
        inv = v[c].inverse()
        v = [x * inv for x in v]
        for i, b in enumerate(basis):
            if b[c]:
                f = b[c]
                basis[i] = [x - f * y for x, y in zip(b, v)]
        basis.append(v)
        pivots.append(c)
    return [b for _, b in sorted(zip([list(order).index(c) for c in pivots], basis), key=lambda t: t[0])]


def left_eigenspace(S: flint.fmpq_mat, p: flint.fmpq_poly, order: Sequence[int] | None = None) -> list[list[FieldElement]]:
    """A basis over ``Q(lambda)`` of ``{w : w S = lambda w}``, ``lambda`` a root of the irreducible ``p``.

    Every root of ``p`` gives the same vectors (as polynomials in ``lambda``): evaluate them at the root
    wanted. ``order``: the column order in which pivots are taken (default ``0, 1, ...``); each basis
    vector has weight 1 at its pivot. An empty list when no root of ``p`` is an eigenvalue.
    """
    if S.nrows() != S.ncols():
        raise InvalidInputError(f"left_eigenspace: the matrix must be square, got {S.nrows()}x{S.ncols()}")
    if p.degree() < 1 or len(p.factor()[1]) != 1 or p.factor()[1][0][1] != 1:
        raise InvalidInputError(f"left_eigenspace: p must be irreducible over Q, got {p}")
    m, d = S.nrows(), p.degree()
    order = list(range(m)) if order is None else list(order)
    if sorted(order) != list(range(m)):
        raise InvalidInputError(f"left_eigenspace: order must be a permutation of 0..{m - 1}")
    solutions = nullspace([[x for x in row] for row in _companion_system(S, p)])
    vectors = [[FieldElement(flint.fmpq_poly([to_fmpq(v[i * d + t]) for t in range(d)]), p) for i in range(m)] for v in solutions]
    return reduced_basis(vectors, order)


def _roots(p: flint.fmpq_poly) -> list:
    """The roots of ``p`` as sympy numbers, in sympy's order (real ascending, then complex): closed forms up to degree 2."""
    x = sp.Symbol("x")
    poly = sp.Poly([to_sympy(c) for c in reversed(p.coeffs())], x)
    if poly.degree() <= 2:
        return sorted(sp.roots(poly, x, multiple=True), key=sp.default_sort_key) if poly.degree() == 1 else _quadratic(poly)
    return [sp.CRootOf(poly, i) for i in range(poly.degree())]


def _quadratic(poly: sp.Poly) -> list:
    a, b, c = poly.all_coeffs()
    disc = b * b - 4 * a * c
    r = sp.sqrt(disc)
    lo, hi = (-b - r) / (2 * a), (-b + r) / (2 * a)
    if disc > 0 and a < 0:
        lo, hi = hi, lo
    return [sp.radsimp(lo), sp.radsimp(hi)]


def root_expression(p: flint.fmpq_poly, index: int) -> sp.Expr:
    """Root number ``index`` of ``p`` (sympy's order: real ascending, then complex) as an exact sympy number."""
    return _roots(p)[index]


def to_sympy_vector(vector: Sequence[FieldElement], p: flint.fmpq_poly, index: int) -> list:
    """The vector at the root number ``index`` of ``p`` (see :func:`root_expression`), exact sympy entries."""
    root = root_expression(p, index)
    x = sp.Symbol("x")
    out = []
    for e in vector:
        value = sp.Poly([to_sympy(c) for c in reversed(e.poly.coeffs())] or [0], x).as_expr().subs(x, root)
        out.append(sp.radsimp(sp.expand(value)) if p.degree() <= 2 else value)
    return out


def element_ball(e: FieldElement, root) -> flint.acb:
    """The element at a root given as an Arb ball (``flint.acb``), by Horner's rule."""
    acc = flint.acb(0)
    for c in reversed(e.poly.coeffs()):
        acc = acc * root + flint.acb(c)
    return acc


def quadratic_element(value) -> tuple[FieldElement, sp.Expr] | None:
    """A number ``a + b sqrt(d)`` (``a``, ``b`` rational, ``sqrt(d)`` one square root of an integer ``d > 1``, as sympy
    writes it) as an element of ``Q(sqrt d) = Q[x]/(x^2 - d)``, with that square root (``x`` stands for it); a rational
    as an element of ``Q[x]/(x)`` with the root ``0``. ``None`` for any other number.

    Arithmetic in the field is exact and costs a few FLINT operations, where sympy's ``simplify`` of the same
    quotients of radicals costs milliseconds each.

    >>> e, root = quadratic_element(sp.Rational(1, 3) + sp.sqrt(24) / 12)
    >>> str(e.poly), str(e.modulus), root
    ('1/6*x + 1/3', 'x^2 + (-6)', sqrt(6))
    >>> quadratic_expression(e * e.inverse(), root)
    1
    """
    value = sp.sympify(value, strict=True)
    if value.is_Rational:
        return FieldElement(flint.fmpq_poly([to_fmpq(value)]), flint.fmpq_poly([0, 1])), sp.Integer(0)
    roots = {p for p in value.atoms(sp.Pow) if p.exp == sp.S.Half and p.base.is_Integer and p.base > 1}
    if len(roots) != 1 or value.free_symbols:
        return None
    root = roots.pop()
    try:
        poly = sp.Poly(value, root, domain=sp.QQ)
    except (sp.PolynomialError, sp.CoercionFailed):
        return None
    if poly.degree() > 1:
        return None
    modulus = flint.fmpq_poly([-int(root.base), 0, 1])
    return FieldElement(flint.fmpq_poly([to_fmpq(c) for c in reversed(poly.all_coeffs())]) % modulus, modulus), root


def quadratic_expression(e: FieldElement, root: sp.Expr) -> sp.Expr:
    """The element ``e`` of :func:`quadratic_element`'s field as the sympy number ``a + b*root``."""
    coeffs = e.poly.coeffs()
    return sum((to_sympy(c) * root**i for i, c in enumerate(coeffs)), sp.Integer(0))
