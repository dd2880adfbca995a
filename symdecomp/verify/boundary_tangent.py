"""Condition 2 of the sector test: the tangent of each boundary curve lies in the tangent plane of the subdominant pair.

The points on a sector's sharp rays form an invariant curve (the crease rules, a cubic B-spline: eigenvalues ``1, 1/2,
1/4, 1/8``, :func:`curve_eigenvalues`, read exactly from the sector's 2-ring matrix), whose tangent eigenvalue ``1/2``
occurs once per boundary curve (one at a boundary or crease, two at a corner). An eigenvector whose eigenvalue is not an
eigenvalue of the curve block vanishes on the curve; so if the subdominant eigenvalues miss a tangent, the tangent plane
cannot hold that boundary curve: not C1 (:func:`tangent_condition`; how the standard rules fail at boundary vertices and
corners with many faces, :mod:`.c1_sector_matrix`). The dense test and the blocks' route (:mod:`.c1_mirror_blocks`) decide it
alike, from the same eigenvalues.
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.errors import NotApplicableError
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.verify.c1_spectrum import ball_text
from symdecomp.verify.result import C1Verdict

__all__ = ["curve_eigenvalues", "tangent_condition"]


def curve_eigenvalues(sm) -> tuple[list[sp.Rational] | None, str | None]:
    """The exact eigenvalues of the boundary curve block, or a reason why its structure is not the one the test uses."""
    labels = [lab for lab in sm.labels if lab == ORIGIN or (lab[2] == 0 and lab[0] in (0, sm.k))]
    index = {lab: i for i, lab in enumerate(sm.labels)}
    ids = [index[lab] for lab in labels]
    S = sm.matrix
    if any(S[i, j] != 0 for i in ids for j in range(S.cols) if j not in ids):
        return None, "the boundary points do not form an invariant curve (their new points read inside points)"
    C = sp.Matrix([[S[i, j] for j in ids] for i in ids])
    if not all(e.is_Rational for e in C):
        return None, "the boundary curve's rules are not rational"
    kernel = (C - sp.eye(len(ids)) / 2).nullspace()
    pos = {lab: t for t, lab in enumerate(labels)}
    for vec in kernel:
        if vec[pos[ORIGIN]] != 0 or any(vec[pos[(r, 2, 0)]] != 2 * vec[pos[(r, 1, 0)]] for r in (0, sm.k)):
            return None, "an eigenvector of the boundary curve for 1/2 is not linear along the sharp rays"
    roots = [sp.Rational(r) for r in sp.roots(C.charpoly().as_expr(), multiple=True) if r.is_Rational]
    if len(roots) != len(ids):
        return None, "the boundary curve's eigenvalues are not rational"
    return sorted(roots, reverse=True), None


def _contains(ball: flint.acb, q: sp.Rational) -> bool:
    """Whether ``q`` may be the eigenvalue in ``ball`` (if not, it certainly is not)."""
    return ball.contains(flint.acb(flint.fmpq(int(q.p), int(q.q))))


def tangent_condition(roots, problem: str | None, picks) -> tuple[C1Verdict, str] | None:
    """Condition 2 (module docstring): ``None`` if the boundary curves' tangents may be among the subdominant eigenvectors
    (``picks``: ``(value, part, in_ring)``), else the verdict and why not; from the boundary curve's eigenvalues ``roots``
    (:func:`curve_eigenvalues`, or the ``problem`` why they are not read)."""
    if problem:
        raise NotApplicableError(f"the sector test does not apply: {problem}")
    half = sp.Rational(1, 2)
    curves = roots.count(half)
    for value, _, _ in picks:
        others = [q for q in set(roots) if q != half and _contains(value, q)]
        if others:
            return C1Verdict.UNDECIDED, f"lambda = {ball_text(value)} may be the boundary curve's eigenvalue {others[0]}"
    maybe = sum(1 for value, _, _ in picks if _contains(value, half))
    if maybe >= curves:
        return None
    lam = ", ".join(ball_text(v) for v, _, _ in picks)
    what = ("the tangent of the boundary curve (eigenvalue 1/2 of the crease rules) is" if curves == 1 else
            f"the tangents of the {curves} boundary curves (eigenvalue 1/2 of the crease rules, {curves} times) are")
    return C1Verdict.NOT_C1, (f"{what} not in the tangent plane: of the subdominant eigenvalues {lam}, {maybe} may be 1/2, "
                              "the others are not eigenvalues of the boundary curves, so their eigenvectors vanish there"
                              + (" and the characteristic map collapses the sharp rays to O" if maybe == 0 else ""))
