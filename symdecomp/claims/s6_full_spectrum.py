"""The closed forms against the full subdivision matrix (the premise of Sections 5 and 6)."""

from __future__ import annotations

import sympy as sp

from symdecomp.analysis.closed_forms import derived_closed_forms
from symdecomp.claims.registry import CheckResult, Status, Step, Text, claim
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam
from symdecomp.verify.certify import certify, symmetric_functions

#: The valences proved by the claim's check (a second or two; ``symdecomp check`` does more).
VALENCES = (3, 48)


@claim(
    "Spectrum (Eq. 34, Eq. 43)",
    section="6",
    title="The closed forms are the spectrum of the full matrix",
    statement=r"For every valence $n$, the eigenvalues of the $(2n+1)\times(2n+1)$ Catmull-Clark subdivision "
    r"matrix $S$, with their multiplicities, are the three eigenvalues of the matrix of Eq. 43 and the two "
    r"eigenvalues of $M_k$ given by Eq. 34 for $k = 1, \dots, n-1$.",
)
def _full_spectrum(scheme: Scheme) -> CheckResult:
    cf = derived_closed_forms(scheme)
    sym = symmetric_functions(cf)
    omega = sp.Symbol("omega")
    steps = [
        Step("Sum of the two closed forms of $M_k$ (Eq. 34), as a Laurent polynomial in $\\omega = \\omega_n^k$",
             sum(c * omega**p for p, c in sym.trace.items()), sp.Symbol("lambda_+") + sp.Symbol("lambda_-")),
        Step("Their product", sum(c * omega**p for p, c in sym.determinant.items()),
             sp.Symbol("lambda_+") * sp.Symbol("lambda_-")),
        Step("Characteristic polynomial of the three closed forms of Eq. 43",
             lam**3 - sym.frequency_zero[0] * lam**2 + sym.frequency_zero[1] * lam - sym.frequency_zero[2],
             sp.Function("F_0")(lam)),
    ]
    lo, hi = max(VALENCES[0], scheme.minimum_valence()), VALENCES[1]
    for valence in range(lo, hi + 1):
        r = certify(scheme, valence, closed_forms=cf)
        if not r.ok:
            return CheckResult(Status.REFUTED if r.status.value == "disagree" else Status.ERROR,
                               r.message, steps=tuple(steps), counterexample=r.message)
    steps.append(Step(
        f"For each $n = {lo}, \\dots, {hi}$: $\\det(\\lambda I - S) = F_0(\\lambda) \\prod_{{k=1}}^{{n-1}} "
        "(\\lambda^2 - (\\lambda_+ + \\lambda_-)\\lambda + \\lambda_+\\lambda_-)$ exactly (FLINT, $S$ built from "
        "the rules; the product over $\\omega \\ne 1$ as a resultant), checked at $2n+1$ rational points; the "
        "multiplicities certified by Arb clusters against the squarefree part"))
    return CheckResult(
        Status.VERIFIED,
        Text(
            sp.Function("det")(lam * sp.Symbol("I", commutative=False) - sp.Symbol("S", commutative=False)),
            " equals the closed forms' characteristic polynomial, multiplicities certified "
            "(symdecomp check --certify extends the range)",
        ),
        steps=tuple(steps),
        valences=VALENCES,
    )

