"""C1 on the four-direction route when the subdominant eigenvalue has one pair of Jordan chains (Midedge at n = 3).

:func:`~symdecomp.verify.c1_four_direction_quotient.quotient_test` finds, at Midedge's triangle, that no control vector
gives the zero function and that ``lambda = 1/4`` has two eigenvectors at frequency 0 and, at each of frequencies 1
and 2, one Jordan block of size 2 and one of size 1. Reif's test needs no Jordan block; the condition used here is
derived below for this structure (largest blocks of size ``p >= 2`` at a positive rational ``lambda``, strictly dominant
after a simple 1, and those blocks exactly one pair of frequencies ``j, n - j``), the way
:mod:`symdecomp.verify.c1_corner_jordan` does it for BLZ's corners.

*What was read*: a search of stored public pages for Peters and Reif on Jordan blocks and generalized eigenvectors of
subdivision matrices found none of their text, only textbook pages on Jordan chains (e.g. *11.6 Jordan Form and
Eigenanalysis*, a course text: the chain ``N v_1 = 0, N v_2 = v_1``, ``N = A - lambda I``, the convention used
here); J. Peters and U. Reif, *Subdivision Surfaces* (Springer 2008), whose Sect. 5.3 the earlier undecided reason
named, was not read. The argument below is this module's own and is not claimed to be theirs.

**The expansion.** Let ``A = S - lambda I`` on the functions' quotient, ``g`` start a chain of length ``p`` in the
class of frequencies ``j, n - j`` and ``e = A^(p-1) g`` (the chain's eigenvector). Then
``S^m g = sum_k binomial(m, k) lambda^(m-k) A^k g``, whose largest term is ``binomial(m, p-1) lambda^(m-p+1) e``. The
class's chains give a real pair ``g_x, g_y`` (``g_y = R g_x - cos(2 pi/d) g_x``, ``R`` the rotation, ``d`` the class)
with eigenvectors ``e_x, e_y``, and on a net ``c_0 1 + c_x g_x + c_y g_y + (the other generalized eigenvectors of
lambda) + (eigenvalues below |lambda|)`` (``c`` in ``R^3``) the ring of patches at level ``m`` is

    ``F_m = c_0 + b_m (c_x f_(e_x) + c_y f_(e_y)) + O(m^(p-2) lambda^m)``, ``b_m = binomial(m, p-1) lambda^(m-p+1)``,

``f_v`` the ring's function of ``v``. For Midedge at ``n = 3``: ``p = 2``, ``b_m = 4 m 4^-m``, and the ``O(4^-m)``
terms are frequency 0's two eigenvectors, the chain starts and the size-1 blocks. The normal (cross product of the
partial derivatives) is

    ``N_m = b_m^2 (c_x x c_y) J(chi) + O(m^(2p-3) lambda^(2m))``, ``chi = (f_(e_x), f_(e_y))``,

(for ``p = 2``: ``16 m^2 4^-2m (c_x x c_y) J(chi) + O(m 4^-2m)``). ``chi`` is the map of two eigenvectors of ``lambda``,
so ``chi`` at level ``m + 1`` is ``lambda chi`` at level ``m``: a characteristic map, whose ring
:func:`~symdecomp.verify.c1_four_direction.certify_four_direction_ring` certifies (Jacobian sign, winding number). The
map is the one of the vectors multiplied by ``b_m`` (``e``, not ``g``); another ``e`` of the same pair changes ``chi``
by a rotation and scaling (``R`` acts on the pair as a rotation), so the sign of ``J`` does not depend on the choice.

* ``J(chi)`` has one strict sign and ``chi`` winds once (so it is injective, Reif's argument for a characteristic
  map): for every net with ``c_x x c_y != 0`` the normal converges to ``sign(J) (c_x x c_y)/|c_x x c_y|``, like
  ``1/m``. In the plane of ``c_x, c_y``, in those coordinates, the projection of ``F_m`` is ``b_m (chi + O(1/m))``
  (with its derivatives): its Jacobian is ``b_m^2 (J(chi) + O(1/m))``, one sign, and the outer boundary of the
  level-``M`` ring is a relative ``O(1/M)`` perturbation of ``chi``'s, a regular simple closed curve, so for ``M``
  large it is simple and winds once around ``c_0``; a map of one Jacobian sign from a disc whose boundary is a simple
  curve takes every point inside at most once (the degree counts the preimages, all of one sign), so the projection
  is injective near the centre. The height over the plane is ``O(lambda^m)`` while the plane's coordinates are
  ``b_m``-sized, so its gradient is ``O(1/m)``: the surface is the graph of a C1 function, *C1 for almost every control
  net* (every net with ``c_x x c_y != 0``), the normal converging only like ``1/m``.
* ``J(chi)`` changes sign: for every net with ``c_x x c_y != 0`` the leading term of ``N_m`` has both signs on every
  level's ring, so normals arbitrarily near the centre point to opposite sides: *not C1* (tangent plane continuity
  fails for almost every net).
* ``J(chi)`` of one sign but ``chi`` not shown to wind once, or the sign not decided: *undecided* (the consequence is
  not worked out here).

What both Jordan routes share is the reading above of a certified map's sign; the maps themselves differ (a sector
ending on two rays there, a closed ring of four-direction patches here), so each module certifies its own.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> from symdecomp.verify.c1_zoo import c1_zoo
>>> from symdecomp.verify.zoo_characteristic import engine_neighbourhood
>>> str(c1_zoo(load_zoo("midedge"), 3, neighbourhood=engine_neighbourhood).verdict)
'c1'
"""

from __future__ import annotations

from math import comb

from symdecomp.verify.c1_four_direction_quotient import QuotientOutcome
from symdecomp.verify.c1_spectrum import round_down
from symdecomp.verify.result import C1Verdict

__all__ = ["JORDAN_CHAIN_METHOD", "leading_scale", "jordan_chain_verdict"]

#: The method, as reported with the verdict of this route.
JORDAN_CHAIN_METHOD = ("the spectrum on the functions of the four-direction patch (exact), and for a subdominant eigenvalue "
                       "whose largest Jordan blocks are one pair of frequencies: the map of the chains' eigenvectors e "
                       "(the leading term m^(p-1) lambda^m of the rings), its Jacobian of one strict sign (Arb, bisection) "
                       "and winding once")


def leading_scale(value: object, length: int, m: int) -> object:
    """``b_m = binomial(m, p - 1) lambda^(m - p + 1)``, the factor of the chains' eigenvectors in ``S^m g`` (module
    docstring); ``value`` any exact number type, ``length`` the chain's ``p``."""
    return comb(m, length - 1) * value ** (m - length + 1)  # type: ignore[operator]


def jordan_chain_verdict(found: QuotientOutcome) -> tuple[C1Verdict, str] | None:
    """The verdict from the map of the chains' eigenvectors (module docstring), ``None`` when ``found`` has no such chain
    (``found.chain`` is set by :func:`~symdecomp.verify.c1_four_direction_quotient.quotient_test` only for the
    structure this route reads)."""
    ring, value = found.ring, found.spectrum.subdominant
    if found.chain is None or ring is None or value is None or found.chain_length < 2:
        return None
    p = found.chain_length
    growth = "m" if p == 2 else f"m^{p - 1}"
    normal = (f"the normal at level m is binomial(m, {p - 1})^2 ({value})^(2m - {2 * p - 2}) (c_x x c_y) J(chi) plus "
              f"terms smaller by 1/m, chi the map of the chains' eigenvectors e (what the rings grow on, as {growth} "
              f"({value})^m)")
    if ring.status == "changes":
        return C1Verdict.NOT_C1, (f"{normal}; J(chi) changes sign ({ring.where}), so for every net with c_x x c_y != 0 the "
                                  "normals near the centre point to opposite sides: not tangent plane continuous")
    if ring.status != "regular" or ring.winding_number is None:
        return C1Verdict.UNDECIDED, (f"{normal}; J(chi)'s sign is not certified at subdivision depth {ring.depth}, or the "
                                     "winding number is not: not shown C1 or not C1")
    if ring.winding_number != ring.jacobian_sign:
        return C1Verdict.UNDECIDED, (f"{normal}; chi is regular but winds {ring.winding_number} times (Jacobian sign "
                                     f"{ring.jacobian_sign}), a case whose consequence this route does not work out")
    bound = "" if ring.jacobian_lower_bound is None else f" (|J| >= {round_down(ring.jacobian_lower_bound)})"
    return C1Verdict.C1, (f"{normal}; chi is regular{bound} and winds once, so the normal converges to c_x x c_y like 1/m "
                          "and the projection onto that plane is injective near the centre: C1 for every net with "
                          "c_x x c_y != 0 (almost every control net)")
