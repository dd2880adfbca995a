"""The numeric cross-check with certified enclosures: Arb (python-flint ``acb_mat``) instead of ``mpmath.eig``.

Same question as :mod:`symdecomp.verify.numeric` (do the closed forms agree with the full
matrix's eigenvalues to ``dps`` digits, with multiplicities?), answered with balls that are
proved to hold the eigenvalues, so that no answer rests on a guess of convergence:

1. the full matrix ``A`` (from the rules, no block structure) as Arb balls at ``prec`` bits;
   approximate eigenvectors ``R`` by Arb's QR iteration (``acb_mat.eig(algorithm="approx")``);
2. ``B = R^-1 A R`` in ball arithmetic, with ``R`` the exact matrix of midpoints and ``R^-1``
   a certified enclosure of its inverse: ``B`` holds a matrix similar to ``A``;
3. Gershgorin's theorem for ``B``: every eigenvalue lies in a disc (centre ``B_ii``, radius
   the row's off-diagonal sum, both bounded rigorously), and a union of ``m`` discs disjoint
   from the others holds exactly ``m`` eigenvalues (a *cluster*);
4. the closed forms (Arb balls) are matched with the clusters: each must hold as many closed
   forms as eigenvalues, and every eigenvalue of a cluster must be within ``10^-dps`` (relative
   to ``max(1, |value|)``) of each closed form in it. A closed form outside every disc, or a
   cluster with more (certainly inside) or fewer (possibly inside) closed forms than
   eigenvalues, refutes the closed forms: ``disagree``, certified. Discs that do not separate
   leave the question open at this precision: the precision rises (as in numeric mode) up to
   ``max_dps`` digits, after which the answer is ``undecided`` (a failure), never a pass.

A defective eigenvalue (a Jordan block) has one eigenvector: QR returns it for each copy, ``R``
is nearly singular and the discs do not separate at any precision, so the answer is
``undecided`` (``--solver mpmath`` matches such a cluster by its mean). Arb's own certified
routines (``acb_mat.eig`` with ``multiple=True``) refuse exactly repeated eigenvalues in
python-flint 0.9 (``diag(1, 1, 2)`` fails to isolate) and solve one system per cluster, which is
why the certificate is the Gershgorin step above.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> r = arb_numeric_check(catmull_clark(), 4, dps=20)
>>> r.status.value, r.solver, [m.eigenvalue.multiplicity for m in r.matches]
('agree', 'flint', [1, 2, 3, 2, 1])
"""

from __future__ import annotations

from collections.abc import Mapping

import flint
import mpmath

from symdecomp.algebra.clusters import overlap_groups
from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.spectrum import format_value
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.full_matrix import parameter_values, sparse_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.validate import MAX_DPS, check_memory, check_precision, check_valence
from symdecomp.verify.numeric import EigenvalueMatch, NumericCheck, _frequencies, _next_precision
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["gershgorin_clusters", "arb_numeric_check"]

_BITS_PER_DIGIT = 3.3219280948873626


def _bits(digits: int) -> int:
    return int(digits * _BITS_PER_DIGIT) + 8


def gershgorin_clusters(entries: dict, size: int, prec: int) -> list[tuple[list, int]] | None:
    """Certified clusters of the eigenvalues of the exact matrix ``entries`` (``{(row, col): fmpq-like}``).

    Returns ``[(discs, m)]``: ``discs`` a list of ``(centre: acb, radius: arb)`` whose union holds
    exactly ``m = len(discs)`` eigenvalues, the unions pairwise disjoint; ``None`` when the
    approximate eigenvectors cannot be inverted at ``prec`` bits (try a higher precision).
    """
    check_memory(8 * size * size * (2 * prec // 8 + 64), f"the {size} x {size} Arb eigenvalue enclosure at {prec} bits")
    with flint.ctx.workprec(prec):
        A = flint.acb_mat(size, size)
        for (r, c), x in entries.items():
            A[r, c] = flint.acb(flint.arb(flint.fmpq(int(x.p), int(x.q))))
        try:
            _, R = A.eig(algorithm="approx", right=True)
            R = flint.acb_mat([[flint.acb(R[i, j].mid()) for j in range(size)] for i in range(size)])
            B = R.inv() * (A * R)
        except (ValueError, ZeroDivisionError):  # QR did not converge, or R is singular at this precision
            return None
        discs = []
        for i in range(size):
            radius = B[i, i].rad() + sum((abs(B[i, j]) for j in range(size) if j != i), flint.arb(0))
            discs.append((flint.acb(B[i, i].mid()), flint.arb(radius.upper())))
    return [([discs[i] for i in group], len(group)) for group in overlap_groups(discs, _may_overlap)]


def _may_overlap(a, b) -> bool:
    """Whether two discs ``(centre, radius)`` may overlap (only certainly disjoint discs are apart)."""
    return not abs(a[0] - b[0]) > a[1] + b[1]


def _in_disc(v, disc) -> tuple[bool, bool]:
    """``(certainly inside, possibly inside)`` for the ball ``v`` and the disc ``(centre, radius)``."""
    centre, radius = disc
    distance = abs(v - centre)
    return bool(distance + v.rad() < radius), not bool(distance > radius + v.rad())


def _match_clusters(clusters, balls, labels, dps: int, n: int):
    """``(status, message, matches)`` at one precision; status ``None`` means: not decided here."""
    tol = flint.arb(10) ** (-dps)
    possibly = [[j for j, (discs, _) in enumerate(clusters) if any(_in_disc(v, d)[1] for d in discs)] for v in balls]
    certainly = [[j for j, (discs, _) in enumerate(clusters) if any(_in_disc(v, d)[0] for d in discs)] for v in balls]
    for i, where in enumerate(possibly):
        if not where:
            return CrossCheckStatus.DISAGREE, (f"n = {n}: closed-form eigenvalue {_text(balls[i], dps)} ({_name(labels[i])}) "
                                               "is not an eigenvalue of the full matrix: outside every Gershgorin disc "
                                               "(certified)"), None
    matches, decided = [], True
    for j, (discs, m) in enumerate(clusters):
        inside = [i for i in range(len(balls)) if j in certainly[i]]
        near = [i for i in range(len(balls)) if j in possibly[i]]
        if len(inside) > m or len(near) < m:
            which = inside if len(inside) > m else near
            where = _text(discs[0][0], dps)
            return CrossCheckStatus.DISAGREE, (f"n = {n}: {len(which)} closed-form eigenvalue(s) lie at the full matrix's "
                                               f"cluster of {m} eigenvalue(s) near {where}"
                                               f"{' (' + _name(labels[which[0]]) + ')' if which else ''} (certified)"), None
        if len(inside) != m or any(len(possibly[i]) != 1 for i in near):
            decided = False
            continue
        deviation = max(abs(balls[i] - c).upper() + r for i in inside for c, r in discs)
        if not deviation < tol * max(flint.arb(1), abs(balls[inside[0]]).upper()):
            decided = False
        matches.append((inside, m, deviation))
    return (CrossCheckStatus.AGREE if decided else None), "", matches


def _name(label) -> str:
    return f"{label.label}; k = {label.frequency}"


def _text(ball, digits: int) -> str:
    with mpmath.workdps(digits + 5):
        return format_value(_mp(ball, digits + 5), digits)


def _mp(ball, digits: int):
    re = mpmath.mpf(ball.real.mid().str(digits, radius=False))
    im = mpmath.mpf(0) if ball.imag.contains(0) else mpmath.mpf(ball.imag.mid().str(digits, radius=False))
    return re if im == 0 else mpmath.mpc(re, im)


def arb_numeric_check(scheme: Scheme, n: int, *, dps: int = 50, parameters: Mapping | None = None,
                      closed_forms: ClosedForms | None = None, max_dps: int | None = None) -> NumericCheck:
    """Match certified enclosures of the full valence-``n`` matrix's eigenvalues with the closed forms.

    Arguments as for :func:`~symdecomp.verify.numeric.numeric_check` (``max_dps``: the highest
    working precision, digits, default ``4 * dps + 40``).
    """
    n, dps = check_valence(n), check_precision(dps)
    max_dps = check_precision(max_dps, "max_dps", maximum=4 * MAX_DPS + 40) if max_dps is not None else 4 * dps + 40
    if max_dps < dps + 10:
        raise InvalidInputError(f"max_dps = {max_dps} leaves no room above dps = {dps} (need at least dps + 10)")
    subs = parameter_values(scheme, parameters)
    cf = closed_forms or derived_closed_forms(scheme)
    labels = cf.eigenvalue_labels(n)
    entries = sparse_subdivision_matrix(scheme, n, parameters)
    balls = cf.values(n, subs, engine="arb", prec=_bits(max_dps + 30))
    precisions: list[int] = []
    work, status, message, found = dps + 10, None, "", []
    while work <= max_dps and status is None:
        precisions.append(work)
        clusters = gershgorin_clusters(entries, 2 * n + 1, _bits(work))
        if clusters is not None:
            status, message, found = _match_clusters(clusters, balls, labels, dps, n)
        work = _next_precision(work)
    return _result(scheme, n, dps, precisions, status, message, found or [], balls, labels)


def _eigenvalue(ball, dps: int, labels: tuple) -> Eigenvalue:
    """The closed-form eigenvalue in ``ball``, with the closed forms whose enclosures lie in its cluster."""
    return Eigenvalue(_mp(ball, dps + 10), _text(ball, dps), len(labels), frequencies=_frequencies(labels), labels=labels)


def _result(scheme, n, dps, precisions, status, message, found, balls, labels) -> NumericCheck:
    with mpmath.workdps(dps + 10):
        matches = tuple(
            EigenvalueMatch(_eigenvalue(balls[inside[0]], dps, tuple(labels[i] for i in inside)), matched=m,
                            deviation=mpmath.mpf(deviation.mid().str(5, radius=False)),
                            spread=mpmath.mpf(deviation.mid().str(5, radius=False)))
            for inside, m, deviation in found
        )
        matches = tuple(sorted(matches, key=lambda m: (-abs(m.eigenvalue.value), -mpmath.re(m.eigenvalue.value), -mpmath.im(m.eigenvalue.value))))
        worst = max((m.deviation for m in matches), default=mpmath.inf)
    if status is None:
        status = CrossCheckStatus.UNDECIDED
        message = (f"n = {n}: the Arb enclosures of the full matrix's eigenvalues did not separate to {dps} digits by "
                   f"{precisions[-1]} digits of working precision (a defective eigenvalue never separates: --solver mpmath "
                   "matches it by its mean); no verdict")
    elif status is CrossCheckStatus.AGREE:
        message = (f"n = {n}: {sum(m.eigenvalue.multiplicity for m in matches)} eigenvalues ({len(matches)} distinct) agree to {dps} "
                   f"digits, certified (Arb enclosures); largest deviation below {mpmath.nstr(worst, 3)}")
    return NumericCheck(n=n, scheme=scheme.name, dps=dps, precisions=tuple(precisions), status=status, max_deviation=worst,
                        max_spread=max((m.spread for m in matches), default=mpmath.inf), matches=matches, message=message,
                        solver="flint")
