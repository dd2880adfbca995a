"""Per-frequency matrices derived from a scheme's rules (Eq. 25-33 and Eq. 43).

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
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp

from symdecomp.algebra.circulant import mode_eigenvalue_derivation, root_of_unity
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
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
