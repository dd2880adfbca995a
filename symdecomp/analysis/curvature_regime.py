"""The curvature regime at an extraordinary vertex: what the comparison of ``mu`` with ``lambda_1^2`` means.

The definitions live here, once, so that every user (the certified computation
:mod:`symdecomp.verify.second_order_spectrum`, a tuning region in the vertex weights) decides the regime the same way.

Let ``1 > lambda_1`` be the dominant and subdominant eigenvalues of the subdivision matrix whose
eigenvectors generate the surface near the extraordinary vertex, and ``mu`` the largest eigenvalue
in modulus after them (the *subsubdominant* eigenvalue). After ``k`` subdivision steps the ring of
patches around the vertex is, up to an affine map, the characteristic map (scale ``lambda_1^k``)
plus a second-order part of size ``|mu|^k``; its principal curvatures behave like
``(|mu| / lambda_1^2)^k`` (Peters and Reif, *Shape characterization of subdivision surfaces: basic
principles*, CAGD 21 (2004) 585-599, Section 4; their book *Subdivision Surfaces*, Springer 2008,
Chapter 7). Hence, for a generic initial mesh:

* ``|mu| = lambda_1^2``: the curvature stays **bounded** (and is generically nonzero) -- unless ``mu``
  has a Jordan block, when it grows like ``k`` (unbounded, logarithmically in the distance);
* ``|mu| < lambda_1^2``: the curvature tends to **zero** at the vertex (a flat spot);
* ``|mu| > lambda_1^2``: the curvature is **unbounded** at the vertex.

The frequency of ``mu`` (Section 5 of the paper: frequency 0 is the *elliptic* part, frequency 2 the
*hyperbolic* part; frequency 1 the tangent plane) says which part of the surface causes it.
"""

from __future__ import annotations

import enum

from symdecomp.validate import check_int, check_valence

__all__ = ["CurvatureRegime", "curvature_regime", "frequency_kind", "REGIME_TEXT"]


class CurvatureRegime(str, enum.Enum):
    """The behaviour of the curvature at the extraordinary vertex (module docstring)."""

    #: ``|mu| = lambda_1^2`` and no Jordan block: bounded, generically nonzero.
    BOUNDED = "bounded"
    #: ``|mu| < lambda_1^2``: tends to zero (a flat spot).
    ZERO = "zero"
    #: ``|mu| > lambda_1^2`` (or ``=`` with a Jordan block): unbounded.
    UNBOUNDED = "unbounded"
    #: The comparison could not be decided (intervals overlap and no exact tie was shown).
    UNDECIDED = "undecided"
    #: The test does not apply (no real, double, dominant ``lambda_1``; rules the test does not know).
    NOT_APPLICABLE = "not applicable"

    def __str__(self) -> str:
        return self.value


#: One line per regime, for tables and claims.
REGIME_TEXT = {
    CurvatureRegime.BOUNDED: "curvature bounded, generically nonzero (|mu| = lambda_1^2)",
    CurvatureRegime.ZERO: "curvature tends to zero, a flat spot (|mu| < lambda_1^2)",
    CurvatureRegime.UNBOUNDED: "curvature unbounded (|mu| > lambda_1^2)",
    CurvatureRegime.UNDECIDED: "curvature regime undecided",
    CurvatureRegime.NOT_APPLICABLE: "curvature regime not applicable",
}


def curvature_regime(comparison: int | None, *, defective: bool = False) -> CurvatureRegime:
    """The regime from ``comparison``, the sign of ``|mu| - lambda_1^2`` (``-1``, ``0``, ``1``; ``None``: undecided).

    ``defective``: ``mu`` (of modulus ``lambda_1^2``) has a Jordan block, which makes a tie unbounded.

    >>> curvature_regime(0), curvature_regime(-1), curvature_regime(1), curvature_regime(0, defective=True)
    (<CurvatureRegime.BOUNDED: 'bounded'>, <CurvatureRegime.ZERO: 'zero'>, <CurvatureRegime.UNBOUNDED: 'unbounded'>, \
<CurvatureRegime.UNBOUNDED: 'unbounded'>)
    """
    if comparison is None:
        return CurvatureRegime.UNDECIDED
    comparison = check_int(comparison, "comparison (the sign of |mu| - lambda_1^2)", minimum=-1, maximum=1)
    if comparison > 0 or (comparison == 0 and defective):
        return CurvatureRegime.UNBOUNDED
    return CurvatureRegime.ZERO if comparison < 0 else CurvatureRegime.BOUNDED


def frequency_kind(frequency: int | None, n: int) -> str:
    """The paper's name of an eigenvalue's frequency ``j`` at valence ``n`` (``None``: the outer blocks, every frequency).

    >>> frequency_kind(0, 5), frequency_kind(4, 5), frequency_kind(3, 5), frequency_kind(3, 8), frequency_kind(None, 5)
    ('elliptic', 'tangent', 'hyperbolic', 'frequency 3', 'regular rules (every frequency)')
    """
    n = check_valence(n)
    if frequency is None:
        return "regular rules (every frequency)"
    frequency = check_int(frequency, "frequency", minimum=0)
    j = min(frequency % n, -frequency % n)
    return {0: "elliptic", 1: "tangent", 2: "hyperbolic"}.get(j, f"frequency {j}")
