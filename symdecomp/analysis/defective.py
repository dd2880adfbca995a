"""Vertex-rule weights for which the Eq. 43 block is defective (has a Jordan block).

With free vertex weights ``alpha, beta`` the characteristic polynomial of the ``3 x 3``
matrix of Eq. 43 is ``(lambda - 1) q(lambda)`` (the scheme is affine), and the coefficients
of ``q`` are affine in ``alpha, beta`` (they enter only through the first row). So for any
exact ``mu`` the weights that make ``q = (lambda - mu)^2`` (the discriminant of ``q``
vanishes, with double root ``mu``) solve a linear system, and are exact rationals for a
rational ``mu``. For Catmull-Clark's edge and face rules the double root is always
defective: rows 2 and 3 of ``A - mu I`` are never proportional, so ``rank(A - mu I) = 2``.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.symbols import alpha, beta
>>> w = jordan_vertex_weights(catmull_clark(alpha, beta), 5, sp.Rational(3, 8))
>>> w[alpha], w[beta]
(-1/8, 1/8)
>>> jordan_block_size(catmull_clark(alpha, beta).substitute(w), 5, sp.Rational(3, 8))
2
"""

from __future__ import annotations

import sympy as sp

from symdecomp.analysis.frequency import recursion_matrix
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.expressions import exact_value
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import lam as LAM
from symdecomp.validate import check_limit, check_valence

__all__ = ["jordan_vertex_weights", "jordan_block_size"]


def _check_quad(scheme: Scheme, function: str) -> None:
    """Eq. 43 is the paper's 3 x 3 block of a quad scheme (``O``, ``a``, ``b``); a triangle scheme has no face points."""
    if scheme.face_rule is None:
        raise NotApplicableError(f"{function}: scheme {scheme.name!r} is a {scheme.lattice}-mesh scheme; the Eq. 43 "
                                 "recursion matrix (O, a_i, b_i) is defined for quad schemes, whose rings have face points")


def jordan_vertex_weights(scheme: Scheme, n: int, eigenvalue) -> dict:
    """Exact values of the scheme's two free parameters making ``eigenvalue`` a double root of Eq. 43.

    Raises :class:`~symdecomp.errors.InvalidSchemeError` if the scheme does not have exactly
    two free parameters or the linear system has no unique solution.
    """
    _check_quad(check_scheme(scheme), "jordan_vertex_weights")
    n = check_limit(check_valence(n), "jordan_vertex_weights(n)", "valence n")
    mu = exact_value(eigenvalue, argument="eigenvalue")
    params = tuple(scheme.parameters)
    if len(params) != 2:
        raise NotApplicableError(
            f"scheme {scheme.name!r} has free parameters {[str(p) for p in params]}; need exactly two (e.g. alpha, beta)"
        )
    A = recursion_matrix(scheme, n)
    charpoly = sp.Poly(sp.expand((LAM * sp.eye(3) - A).det()), LAM)
    target = sp.Poly(sp.expand((LAM - 1) * (LAM - mu) ** 2), LAM)
    equations = [sp.expand(a - b) for a, b in zip(charpoly.all_coeffs(), target.all_coeffs())]
    solution = sp.solve(equations, params, dict=True)
    if len(solution) != 1 or set(solution[0]) != set(params):
        raise InvalidSchemeError(f"no unique vertex weights give a double eigenvalue {mu} of Eq. 43 at n = {n}")
    return {p: sp.simplify(solution[0][p]) for p in params}


def jordan_block_size(scheme: Scheme, n: int, eigenvalue) -> int:
    """Size of the largest Jordan block of ``eigenvalue`` in the Eq. 43 matrix (exact ranks).

    ``0`` if it is not an eigenvalue.
    """
    _check_quad(check_scheme(scheme), "jordan_block_size")
    A = sp.Matrix(recursion_matrix(scheme, check_limit(check_valence(n), "jordan_block_size(n)", "valence n")))
    mu = exact_value(eigenvalue, argument="eigenvalue")
    B = A - mu * sp.eye(3)
    ranks = [3] + [(B**k).rank() for k in range(1, 4)]
    if ranks[1] == 3:
        return 0
    # the number of blocks of size >= k is rank(B^(k-1)) - rank(B^k)
    return max(k for k in range(1, 4) if ranks[k - 1] - ranks[k] > 0)
