"""The toolkit's numbers for Catmull-Clark at one valence that the oracle checks against OpenSubdiv.

Derived from the scheme's rules, then evaluated (:func:`toolkit_predictions`): the exact one-step matrix, the limit
mask, the dominant and subdominant eigenvalues of every ``M_j`` (Eq. 34), the Eq. 43 matrix's eigenvalues after 1 and
the ratio of Eq. 44 on the subdominant one's eigenvector (:func:`elliptic_eigenvector`), the ratio of Eq. 39. The
comparisons are :mod:`symdecomp.verify.oracle`.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp

from symdecomp.algebra.numbers import to_fraction
from symdecomp.analysis.elliptic import recursion_eigenvector
from symdecomp.analysis.masks import limit_masks_at
from symdecomp.analysis.spectrum import recursion_eigenvalues
from symdecomp.analysis.tangent import invariant_ratio_at, tangent_eigenvalues
from symdecomp.errors import InternalError
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import n as N
from symdecomp.validate import cached, check_valence

__all__ = ["ToolkitPredictions", "toolkit_predictions", "elliptic_eigenvector"]


def elliptic_eigenvector(scheme, n: int) -> tuple[sp.Expr, tuple[sp.Expr, sp.Expr, sp.Expr]]:
    """``(mu_2, (u_O, u_a, u_b))``: the subdominant eigenvalue of the Eq. 43 matrix at ``n`` and its eigenvector.

    ``mu_2`` is the larger of the two eigenvalues other than 1 (closed form from
    :func:`symdecomp.analysis.spectrum.recursion_eigenvalues`); the eigenvector is
    :func:`symdecomp.analysis.elliptic.recursion_eigenvector`, scaled so that ``u_a - u_O = 1``.

    >>> mu, (uo, ua, ub) = elliptic_eigenvector(catmull_clark(), 4)
    >>> mu, (ub - uo) / (ua - uo)
    (1/4, 2)
    """
    n = check_valence(n)
    _, m2, m3 = (sp.radsimp(sp.simplify(e.subs(N, n))) for e in recursion_eigenvalues(scheme))
    mu = m2 if sp.N(abs(m2)) >= sp.N(abs(m3)) else m3
    u = recursion_eigenvector(scheme, mu, n)
    scale = sp.simplify(u[1] - u[0])
    if scale == 0:
        raise InternalError(f"the Eq. 43 eigenvector for {mu} at n = {n} has u_a = u_O; Eq. 44's ratio is undefined")
    return mu, tuple(sp.radsimp(sp.simplify(x / scale)) for x in u)


@dataclass(frozen=True)
class ToolkitPredictions:
    """The toolkit's numbers for Catmull-Clark at one valence (derived, then evaluated)."""

    #: The valence.
    n: int
    #: The exact subdivision matrix with Fraction entries (rows ``O, a_0.., b_0..``).
    matrix: tuple[tuple[Fraction, ...], ...]
    #: The limit mask: left eigenvector of eigenvalue 1, weights summing to 1 (Fractions).
    limit_mask: tuple[Fraction, ...]
    #: ``j -> (lambda_dom, lambda_sub)`` of ``M_j`` for ``j = 1..n-1`` (floats, by magnitude).
    tangent: dict
    #: Eigenvalues of the Eq. 43 matrix other than 1, larger first.
    mu: tuple[float, float]
    #: ``(u_b - u_O)/(u_a - u_O)`` on the ``mu_2`` eigenvector (Eq. 44).
    elliptic_ratio: float
    #: ``B^1/A^1`` on the dominant eigenvector of ``M_1`` (Eq. 39).
    eq39_ratio: complex


def _f(expr, dps=30) -> float:
    with mpmath.workdps(dps):
        return float(sp.N(expr, dps))


@cached(n=check_valence)
def toolkit_predictions(n: int) -> ToolkitPredictions:
    """Derive the predictions for standard Catmull-Clark at valence ``n``."""
    n = check_valence(n)
    cc = catmull_clark()
    S = subdivision_matrix(cc, n)
    size = 2 * n + 1
    mask = limit_masks_at(cc, n).position
    ev = tangent_eigenvalues(cc)
    tangent = {}
    for j in range(1, n):
        d, s = ev.at(n, j)
        d, s = _f(d), _f(s)
        tangent[j] = (d, s) if abs(d) >= abs(s) else (s, d)
    mu, (uo, ua, ub) = elliptic_eigenvector(cc, n)
    others = sorted((_f(e.subs(N, n)) for e in recursion_eigenvalues(cc)[1:]), key=abs, reverse=True)
    r39 = complex(sp.N(invariant_ratio_at(cc, n, 1), 30))
    return ToolkitPredictions(
        n,
        tuple(tuple(to_fraction(S[i, k]) for k in range(size)) for i in range(size)),
        tuple(to_fraction(x) for x in mask),
        tangent,
        (others[0], others[1]),
        _f((ub - uo) / (ua - uo)),
        r39,
    )
