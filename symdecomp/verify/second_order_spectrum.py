"""The second-order eigenstructure at an extraordinary vertex and the curvature regime, certified, for any scheme.

**Which matrix.** The eigenvalues counted are those of the 2-ring subdivision matrix whose eigenvectors
generate the characteristic map and the rings of patches around the vertex
(:mod:`symdecomp.analysis.characteristic`; ``(6n + 1)`` square on quads, ``(3n + 1)`` on triangles), the
matrix of Reif's test (:mod:`symdecomp.verify.c1_spectrum`, whose certified per-frequency enclosures
are reused here). Every ring of patches is a fixed linear function of those 2-ring points, so every
eigenvalue of that matrix counts, at every frequency: the roots of the 1-ring blocks (``M_j``; at
``j = 0`` the Eq. 43 matrix without its eigenvalue 1) and those of the outer blocks, which hold only
the regular rules and have the same exact rational eigenvalues at every frequency of every valence
(Catmull-Clark ``1/8, 1/16, 1/32, 1/64``, Loop ``1/8, 1/16``; ``n`` copies each).

**The test** (:mod:`symdecomp.analysis.curvature_regime` for what the regimes mean):

1. Reif's spectral conditions must hold (:func:`~symdecomp.verify.c1_spectrum.spectral_conditions`:
   ``lambda_1`` real, double, strictly dominant after 1); otherwise the regime is *not applicable* and
   the reason says why (the second-order terms are measured against ``lambda_1^2`` only then).
2. Every other eigenvalue ``e`` is compared with ``lambda_1^2`` in Arb. When the balls of ``|e|`` and
   ``lambda_1^2`` overlap, the tie is decided exactly in the cyclotomic field ``Q(e^{2 pi i/2n})``
   (:mod:`symdecomp.algebra.cyclotomic`): the squares of the roots of ``lambda_1``'s block are the roots of
   ``x^2 - (c_1^2 - 2 c_2) x + c_2^2`` (``x - c_1^2`` for a ``1 x 1`` block), and ``e = +-lambda_1^2``
   exactly when that polynomial and ``e``'s block's (at ``-x`` for the minus sign) share the root that
   only ``lambda_1^2`` and ``e`` are near (the shared-root test of the C1 spectrum). A tie with a non-real
   eigenvalue is not decided exactly: it stays undecided (after a retry at higher precision).
3. The regime follows from the signs of ``|e| - lambda_1^2`` alone (:func:`~symdecomp.analysis.curvature_regime.curvature_regime`):
   unbounded if one is positive, zero if all are negative, bounded if the largest are exact ties. ``mu``
   is the largest modulus after ``1`` and ``lambda_1``; when several eigenvalues (different frequencies,
   a complex pair) are not separated from it in modulus they are all reported.

Schemes outside the test: regular rules other than Catmull-Clark's or Loop's, free parameters, or
weights outside the cyclotomic field raise :class:`~symdecomp.errors.NotApplicableError` (one line).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import flint

from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.analysis.characteristic import check_applicable, outer_charpoly
from symdecomp.analysis.curvature_regime import REGIME_TEXT, CurvatureRegime, curvature_regime, frequency_kind
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached, check_limit, check_valence
from symdecomp.verify.c1_spectrum import (
    ball_text,
    exact_charpoly,
    exact_entry,
    frequency_zero_eigenvalues,
    other_frequency_eigenvalues,
    shared_root,
    sibling_values,
    spectral_conditions,
)
from symdecomp.verify.result import C1Verdict

__all__ = ["SquareComparison", "CurvatureResult", "second_order_eigenstructure", "dominant_frequency", "dominant_part"]

#: Working precisions (bits): the second is tried only when the first leaves the regime undecided.
PRECISIONS = (128, 512)


@dataclass(frozen=True)
class SquareComparison:
    """How an eigenvalue after ``1`` and ``lambda_1`` compares with ``lambda_1^2`` in modulus (the eigenvalue itself is an
    :class:`~symdecomp.analysis.eigenvalue.Eigenvalue`: a root of one frequency block, those of several frequencies with
    equal moduli kept apart, since which frequencies give ``mu`` is the regime's cause)."""

    #: The sign of ``|value| - lambda_1^2`` (``None``: not decided).
    sign: int | None
    #: ``sign == 0`` was shown exactly (in the cyclotomic field).
    exact: bool = False


@dataclass(frozen=True)
class CurvatureResult:
    """The second-order eigenstructure at one valence and the curvature regime it implies."""

    n: int
    regime: CurvatureRegime
    #: One line: which eigenvalue decides, and how.
    reason: str
    #: ``lambda_1`` (``None`` when the spectral conditions fail).
    lambda1: flint.acb | None = None
    #: The frequency of ``lambda_1`` (1 for the schemes in use).
    lambda1_frequency: int | None = None
    #: The eigenvalues of largest modulus after ``1`` and ``lambda_1`` (several when they are not separated).
    mu: tuple[Eigenvalue, ...] = ()
    #: Every eigenvalue after ``1`` and ``lambda_1``, largest modulus first: Arb balls, the block's frequency first in
    #: ``frequencies`` (none for the outer blocks, the same at every frequency), copies in the full matrix.
    eigenvalues: tuple[Eigenvalue, ...] = ()
    #: Each eigenvalue's comparison with ``lambda_1^2``, in the order of ``eigenvalues``.
    comparisons: tuple[SquareComparison, ...] = ()

    def compared(self, e: Eigenvalue) -> SquareComparison:
        """The comparison of ``e`` (one of ``eigenvalues``, or of ``mu``) with ``lambda_1^2``."""
        return next(c for x, c in zip(self.eigenvalues, self.comparisons) if x is e)

    def kind(self, e: Eigenvalue) -> str:
        """The paper's name of ``e``'s frequency: elliptic (0), tangent (1), hyperbolic (2), ..."""
        return frequency_kind(e.frequency, self.n)

    def eigenvalue_json(self, e: Eigenvalue) -> dict:
        c = self.compared(e)
        return {"value": ball_text(e.value, 10), "frequency": e.frequency, "multiplicity": e.multiplicity,
                "kind": self.kind(e), "comparison": c.sign, "exact": c.exact, "complex": e.conjugate}

    @property
    def cause(self) -> str:
        """The part of the surface that decides the regime: the kinds (frequencies) of ``mu``."""
        return ", ".join(dict.fromkeys(self.kind(e) for e in self.mu))

    @property
    def mu_multiplicity(self) -> int:
        return sum(e.multiplicity for e in self.mu)

    def as_json(self) -> dict:
        lam = self.lambda1
        return {
            "n": self.n, "regime": self.regime.value, "reason": self.reason, "cause": self.cause,
            "lambda1": None if lam is None else ball_text(lam, 10),
            "lambda1_squared": None if lam is None else ball_text(abs(lam) ** 2, 10),
            "mu": [self.eigenvalue_json(e) for e in self.mu], "mu_multiplicity": self.mu_multiplicity,
            "eigenvalues": [self.eigenvalue_json(e) for e in self.eigenvalues[:8]],
        }


def _outer_eigenvalues(scheme: Scheme, n: int) -> list[tuple[flint.acb, flint.fmpq | None, int]]:
    """``(ball, exact rational or None, multiplicity)`` for the outer blocks' eigenvalues (the same at every frequency)."""
    coeffs = outer_charpoly(scheme.lattice)
    _, factors = flint.fmpq_poly(list(reversed(coeffs))).factor()
    out = []
    for poly, exponent in factors:
        if poly.degree() == 1:
            root = -poly[0] / poly[1]
            out.append((flint.acb(root), root, n * exponent))
        else:  # pragma: no cover - the regular rules in use have rational outer eigenvalues
            out += [(r, None, n * exponent * m) for r, m in poly.complex_roots()]
    return out


def _square_poly(p: tuple) -> tuple:
    """The monic polynomial whose roots are the squares of the roots of ``x^k + p_1 x^(k-1) + ..`` (``k = 1, 2``)."""
    if len(p) == 1:
        return (-(p[0] * p[0]),)
    return (-(p[0] * p[0] - 2 * p[1]), p[1] * p[1])


def _exact_square_tie(square: tuple | None, others: list, lam_sq: flint.acb, q: tuple | None,
                      value: flint.acb, siblings: list) -> bool:
    """Whether ``value`` (a root of ``q``) is exactly ``+-lambda_1^2`` (a root of ``square``; ``others``: its other roots)."""
    if square is None or q is None:
        return False
    for sign in (1, -1):
        qs = tuple(c * sign ** (i + 1) for i, c in enumerate(q))
        v = value * sign
        if not v.overlaps(lam_sq):
            continue
        shared = shared_root(square, qs)
        if shared is None:
            continue
        if shared == "all":
            if all(not v.overlaps(x) for x in others):
                return True
        elif shared.overlaps(lam_sq) and all(not shared.overlaps(x) for x in others + [s * sign for s in siblings]):
            return True
    return False


def _double_root_tie(scheme: Scheme, n: int, j: int, square: tuple | None) -> tuple[bool, bool]:
    """For a double root ``r = -c_1/2`` of ``M_j`` (``j != 0``): ``(r^2 = lambda_1^4 exactly, M_j - r I != 0)``.

    ``|r| = lambda_1^2`` iff ``r`` or ``-r`` is a root of ``square``; the root has a Jordan block iff
    ``M_j`` is not ``r I`` (exact entries in the cyclotomic field).
    """
    p = exact_charpoly(scheme, n, j)
    if square is None or p is None:
        return False, False
    r = -p[0] / 2
    value = lambda x: sum((c * x ** (len(square) - 1 - i) for i, c in enumerate(square)), x ** len(square))  # noqa: E731
    if value(r) != 0 and value(-r) != 0:
        return False, False
    M = [[exact_entry(x, n, j) for x in row] for row in one_ring_matrices(scheme)[0].tolist()]
    return True, any((M[a][b] - (r if a == b else 0)) != 0 for a in range(len(M)) for b in range(len(M)))


def _compare(modulus: flint.arb, lam_sq: flint.arb) -> int | None:
    if modulus < lam_sq:
        return -1
    return 1 if modulus > lam_sq else None


def _eigenvalues(scheme: Scheme, n: int, dom) -> list[tuple[Eigenvalue, SquareComparison]]:
    """Every eigenvalue after 1 and ``lambda_1`` (``dom``), compared with ``lambda_1^2`` (exactly on a tie)."""
    inner = frequency_zero_eigenvalues(scheme, n)[0] + other_frequency_eigenvalues(scheme, n, outer=False)[0]
    lam_sq = dom.value * dom.value
    exact_lam = exact_charpoly(scheme, n, dom.frequency)
    square = None if exact_lam is None else _square_poly(exact_lam)
    others = [s * s for s in sibling_values(inner, dom)]
    out = []
    for e in inner:
        if e.frequency == dom.frequency and e.index == dom.index:
            continue
        comparison, exact = _compare(abs(e.value), abs(lam_sq)), False
        defective = e.defective
        if comparison is None and e.double:
            exact, defective = _double_root_tie(scheme, n, e.frequency, square)
            comparison = 0 if exact else None
        elif comparison is None and not e.conjugate:
            q = exact_charpoly(scheme, n, e.frequency)
            exact = _exact_square_tie(square, others, lam_sq, q, e.value, sibling_values(inner, e))
            comparison = 0 if exact else None
        out.append((replace(e, text=ball_text(e.value, 10), jordan=(2,) if defective else None), SquareComparison(comparison, exact)))
    field = CyclotomicField(2 * n)
    for ball, rational, multiplicity in _outer_eigenvalues(scheme, n):
        comparison, exact = _compare(abs(ball), abs(lam_sq)), False
        if comparison is None and rational is not None:
            exact = _exact_square_tie(square, others, lam_sq, (field(-rational),), ball, [])
            comparison = 0 if exact else None
        out.append((Eigenvalue(ball, ball_text(ball, 10), multiplicity), SquareComparison(comparison, exact)))
    return sorted(out, key=lambda e: -abs(e[0].value).mid())


def _mu_text(mu: list[tuple[Eigenvalue, SquareComparison]], n: int) -> str:
    """``mu`` in words: its value(s), frequencies, multiplicity; complex, negative, or not separated."""
    parts = []
    for e, _ in mu:
        where = "the outer blocks" if e.frequency is None else f"frequency {e.frequency} ({frequency_kind(e.frequency, n)})"
        note = ", complex" if e.conjugate else (", negative" if e.value.real < 0 else "")
        parts.append(f"{ball_text(e.value)} at {where}, multiplicity {e.multiplicity}{note}")
    joined = "; ".join(parts)
    if len(mu) > 1 and not all(c.exact for _, c in mu):
        return f"mu not separated in modulus among: {joined}"
    return f"mu = {joined}" if len(mu) == 1 else f"mu at several frequencies (exactly equal moduli): {joined}"


def _decide(n: int, dom, eigen: list[tuple[Eigenvalue, SquareComparison]]) -> CurvatureResult:
    top = eigen[0]
    mu = [(e, c) for e, c in eigen if not abs(e.value) < abs(top[0].value)]
    signs = [c.sign for _, c in eigen]
    if 1 in signs:
        comparison = 1
    elif None in signs:
        comparison = None
    else:
        comparison = 0 if 0 in signs else -1
    defective = any(e.defective and c.sign == 0 for e, c in eigen)
    regime = curvature_regime(comparison, defective=defective)
    lam_sq = ball_text(abs(dom.value) ** 2)
    if comparison is None:
        open_ = next(e for e, c in eigen if c.sign is None)
        why = f"|{ball_text(open_.value)}| (frequency {open_.frequency}) is not separated from lambda_1^2 = {lam_sq}"
    else:
        rel = {1: ">", 0: "=", -1: "<"}[comparison]
        how = " (exactly)" if comparison == 0 else ""
        why = f"{_mu_text(mu, n)}; |mu| {rel} lambda_1^2 = {lam_sq}{how}"
        if comparison == 1 and top[1].sign != 1:  # pragma: no cover - the largest modulus decides first
            why += " (another eigenvalue exceeds lambda_1^2)"
    if defective:
        why += "; mu has a Jordan block"
    return CurvatureResult(n, regime, f"{REGIME_TEXT[regime]}: {why}", dom.value, dom.frequency, tuple(e for e, _ in mu),
                           tuple(e for e, _ in eigen), tuple(c for _, c in eigen))


@cached(maxsize=512, n=check_valence)
def _structure(scheme: Scheme, n: int, prec: int) -> CurvatureResult:
    with flint.ctx.workprec(prec):
        spectral = spectral_conditions(scheme, n)
        if spectral.status is not C1Verdict.C1:
            regime = CurvatureRegime.UNDECIDED if spectral.status is C1Verdict.UNDECIDED else CurvatureRegime.NOT_APPLICABLE
            return CurvatureResult(n, regime, f"Reif's spectral conditions do not hold ({spectral.reason}), so there is no "
                                   "lambda_1 to compare mu with")
        return _decide(n, spectral.subdominant, _eigenvalues(scheme, n, spectral.subdominant))


def second_order_eigenstructure(scheme: Scheme, n: int) -> CurvatureResult:
    """The eigenvalues after 1 and ``lambda_1`` at valence ``n``, ``mu`` and the curvature regime, certified.

    See the module docstring (which matrix, the exact tie). Raises
    :class:`~symdecomp.errors.NotApplicableError` for schemes outside the test.

    >>> from symdecomp.schemes.loop import loop
    >>> r = second_order_eigenstructure(loop(), 5)
    >>> r.regime.value, r.cause, r.compared(r.mu[0]).exact
    ('bounded', 'elliptic', True)
    """
    n = check_scheme(scheme).fitting_valence(check_limit(check_valence(n), "second_order_eigenstructure(n)", "valence n"))
    check_applicable(scheme)
    for prec in PRECISIONS:
        result = _structure(scheme, n, prec)
        if result.regime is not CurvatureRegime.UNDECIDED:
            break
    return result


def dominant_frequency(elliptic: flint.arb | flint.acb | None, hyperbolic: flint.arb | flint.acb | None) -> int | None:
    """Which second-order part dominates on fine rings: ``0`` if ``|mu_0| > |mu_2|``, ``2`` if ``|mu_2| > |mu_0|``.

    ``elliptic``, ``hyperbolic``: balls around the largest eigenvalue of frequency 0 and of frequency 2 after ``lambda_1``;
    on ring ``m`` the parts scale like ``mu_0^m`` and ``mu_2^m``. ``None`` when one is missing or the balls are not
    separated in modulus (equal moduli are never separated). The one comparison behind :func:`dominant_part` (the
    ``artifacts`` table and claims) and :attr:`symdecomp.verify.shape.ShapeResult.dominant` (the shape chart).
    """
    if elliptic is None or hyperbolic is None:
        return None
    a, b = abs(elliptic), abs(hyperbolic)
    return 0 if a > b else 2 if b > a else None


def dominant_part(curvature: CurvatureResult) -> int | None:
    """The frequency, 0 or 2, of the larger of the two parts' largest eigenvalues (``None``: equal or not separated).

    At ``n = 3`` frequency 2 is frequency 1, the tangent plane's (its block holds ``lambda_1``): ``None``. (The shape
    chart, :func:`symdecomp.verify.shape.shape_chart`, does use the other root of that block as its hyperbolic height at
    ``n = 3``, so its ``dominant`` may be 0 or 2 there; both compare with :func:`dominant_frequency`.)
    """
    tops = {j: max((abs(e.value) for e in curvature.eigenvalues if e.frequency == j), key=lambda x: x.mid(), default=None)
            for j in (0, 2)}
    if curvature.n == 3:  # at n = 3 frequency 2 is the tangent plane's
        return None
    return dominant_frequency(tops[0], tops[2])
