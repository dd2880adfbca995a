"""Claims about the eigenvalues of ``M_j`` for a scheme whose edge rule depends on ``n``: valence by valence.

Section 5's closed forms are written in ``c = cos(j pi/n)`` alone; an edge rule in ``n`` (the model of
:class:`~symdecomp.schemes.scheme.Scheme`: the edges at ``O`` read it at ``O``'s valence) puts ``n`` into
``M_j`` beside ``c``. A question at one valence substitutes ``n`` first: these checks take the certified
eigenvalues of every ``M_j`` and of the frequency-0 block at each valence of a range
(:mod:`symdecomp.verify.c1_spectrum`, Arb balls, exact at frequency 0) and compare them there. A comparison
that fails at one valence refutes the statement by that valence (scope ``single case``: a certified
comparison, as the C1 test's); one that holds at every valence of the range verifies it for the range.
"""

from __future__ import annotations

from symdecomp.claims.applicability import COSINE_ONLY
from symdecomp.claims.registry import CheckResult, Scope, Status, Text, Verbatim
from symdecomp.schemes.scheme import Scheme
from symdecomp.verify.c1_spectrum import ball_text, frequency_zero_eigenvalues, other_frequency_eigenvalues

__all__ = ["VALENCES", "depends_on_valence", "largest_at_frequency_one"]

#: The valences compared one by one.
VALENCES = (3, 40)


def depends_on_valence(scheme: Scheme) -> bool:
    """Whether ``M_j`` depends on ``n`` beside ``c`` (an edge or face rule in ``n``)."""
    return COSINE_ONLY.unmet(scheme) is not None


def _eigenvalues(scheme: Scheme, n: int, frequency_zero: bool) -> list:
    eigen, _ = other_frequency_eigenvalues(scheme, n, outer=False)
    if frequency_zero:
        zero, failure = frequency_zero_eigenvalues(scheme, n)
        if failure:
            raise ArithmeticError(failure)
        eigen += zero
    return eigen


def largest_at_frequency_one(scheme: Scheme, rivals: str, *, frequency_zero: bool, only: int | None = None) -> CheckResult:
    """Compare, at each valence of :data:`VALENCES`, the largest eigenvalue of ``M_1`` (``lambda_1``) with those of the
    other frequencies (``only``: that frequency alone; ``frequency_zero``: also the frequency-0 block's besides 1)."""
    lo, hi = max(VALENCES[0], scheme.minimum_valence()), VALENCES[1]
    for n in range(lo, hi + 1):
        try:
            eigen = _eigenvalues(scheme, n, frequency_zero)
        except ArithmeticError as exc:
            return CheckResult(Status.UNDECIDED, Verbatim(f"{scheme.name}, n = {n}: {exc}"))
        lam1 = max((e for e in eigen if e.frequency == 1), key=lambda e: abs(e.value).mid())
        for e in eigen:
            if e.frequency in (1, n - 1) or (only is not None and e.frequency != only):
                continue
            if abs(e.value) < abs(lam1.value):
                continue
            what = Text(Verbatim(scheme.name), f", n = {n}: the eigenvalue {ball_text(e.value)} at frequency {e.frequency} is "
                        + ("larger in modulus than" if abs(e.value) > abs(lam1.value) else "not separated from")
                        + f" lambda_1 = {ball_text(lam1.value)} (frequency 1; certified, Arb balls, n substituted first: the "
                        "edge rule depends on n)")
            if abs(e.value) > abs(lam1.value):
                return CheckResult(Status.REFUTED, what, counterexample=what, scope=Scope.SINGLE_CASE)
            return CheckResult(Status.UNDECIDED, what)
    return CheckResult(
        Status.VERIFIED,
        Text("the edge rule depends on n, so M_j is not a function of c = cos(j pi/n) alone: at each valence n = ",
             f"{lo}..{hi}, n substituted first, lambda_1 (frequency 1) is larger in modulus than every eigenvalue of ", rivals,
             " (certified, Arb balls; exact at frequency 0)"),
        valences=(lo, hi))
