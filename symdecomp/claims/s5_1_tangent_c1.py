"""Beyond Section 5.1: the tangent-plane conditions are necessary; Reif's sufficient test certifies C1.

The paper's Section 5.1 shows the tangent-plane structure of the spectrum (the frequency-1
eigenvalue dominates), which is necessary for a tangent plane at the extraordinary vertex.
Whether Catmull-Clark surfaces are C1 there is answered by Reif's sufficient test, certified by
:mod:`symdecomp.verify.c1`; this claim records its verdicts as a table, the same table for
Loop's scheme (quartic box-spline ring, on triangles), and that the vertex weights
``alpha = beta = 0`` break it at ``n = 3``.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.claims.applicability import NO_FREE_PARAMETERS
from symdecomp.claims.registry import CheckResult, Status, Step, Text, Verbatim, claim
from symdecomp.schemes.lattice import LATTICES
from symdecomp.schemes.scheme import Scheme, catmull_clark
from symdecomp.symbols import n as N
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_spectrum import round_down
from symdecomp.verify.result import C1Verdict

#: The valences of the table (a second; ``symdecomp c1`` does more).
VALENCES = (3, 16)


def _down(x: float) -> sp.Float:
    """A lower bound shown to 4 significant digits, rounded down."""
    return sp.Float(round_down(x), 4)


def _table(scheme: Scheme):
    """``(rows, None)`` with one row per valence, or ``(None, CheckResult)`` at the first valence that is not C1."""
    lo, hi = max(VALENCES[0], scheme.minimum_valence()), VALENCES[1]
    rows = []
    for n in range(lo, hi + 1):
        r = c1_test(scheme, n)
        if r.verdict is C1Verdict.NOT_C1:
            what = Verbatim(f"{scheme.name}, n = {n}: {r.reason}")
            return None, CheckResult(Status.REFUTED, what, counterexample=what)
        if r.verdict is not C1Verdict.C1:  # undecided: the test could not settle it, which is no finding about the scheme
            return None, CheckResult(Status.UNDECIDED, Verbatim(f"{scheme.name}, n = {n}: {r.reason}"))
        lam = r.spectral.subdominant.value.real
        rows.append([n, sp.Float(float(lam.mid()), 6), _down(r.spectral.gap), _down(r.jacobian_lower_bound), r.winding_number])
    return rows, None


_HEADER = [sp.Symbol("n"), sp.Symbol("lambda"), sp.Symbol("gap"), sp.Symbol("|J|_min"), sp.Symbol("winding")]



@claim(
    "C1 (Reif's test)",
    section="5.1",
    title="Catmull-Clark and Loop surfaces are $C^1$ at extraordinary vertices",
    statement=r"Beyond the paper: the tangent-plane conditions of Section 5.1 are necessary; Reif's sufficient "
    r"condition (1 simple, the subdominant eigenvalue $\lambda$ real, double, non-defective and strictly dominant, "
    r"and a regular, injective characteristic map) holds for Catmull-Clark, and for Loop's scheme, at every valence $n$.",
    requires=(NO_FREE_PARAMETERS,),
)
def _c1_reif(scheme: Scheme) -> CheckResult:
    rows, failed = _table(scheme)
    if failed:
        return failed
    companion = next(lat for lat in LATTICES.values() if lat != scheme.lattice).reference()
    other, failed = _table(companion)
    if failed:
        return failed
    lo, hi = rows[0][0], rows[-1][0]
    # alpha = beta = 0 at n = 3, Catmull-Clark's weights at the regular valence 4 (which every regular vertex uses)
    broken = c1_test(catmull_clark(sp.Rational(3, 32) * (N - 3), sp.Rational(1, 64) * (N - 3)), 3)
    steps = (
        Step("For each $n$: $\\lambda$, a lower bound of the gap $|\\lambda| - \\max|\\mu|$ over the other eigenvalues "
             "$\\mu$ of the 2-ring matrix, a lower bound of the Jacobian of the characteristic map (Bernstein-Bezier "
             f"coefficients of its {scheme.lattice.subpatches_text}, Arb), and the winding number of its inner boundary",
             sp.Matrix([_HEADER] + rows)),
        Step(f"The same for {companion.name}: {companion.lattice.subpatches_text}{companion.lattice.subpatches_where}",
             sp.Matrix([_HEADER] + other)),
        Step(f"With the vertex weights $\\alpha = \\beta = 0$ at $n = 3$ the test fails ({broken.verdict}): "
             + broken.reason.replace("lambda", "$\\lambda$")),
    )
    return CheckResult(
        Status.VERIFIED,
        Text(f"Reif's test certified for n = {lo}..{hi} for ", Verbatim(scheme.name), f" and {companion.name} in rigorous interval "
             "arithmetic (Arb balls; exact in the cyclotomic field at frequency 0); symdecomp c1 extends the range"),
        steps=steps,
        valences=(lo, hi),
    )
