"""Beyond Section 5.1: the tangent-plane conditions are necessary; Reif's sufficient test certifies C1.

The paper's Section 5.1 shows the tangent-plane structure of the spectrum (the frequency-1
eigenvalue dominates), which is necessary for a tangent plane at the extraordinary vertex.
Whether Catmull-Clark surfaces are C1 there is answered by Reif's sufficient test, certified by
:mod:`symdecomp.verify.c1`; this claim records its verdicts as a table, the same table for
Loop's scheme (quartic box-spline ring, on triangles), and that the vertex weights
``alpha = beta = 0`` break it at ``n = 3``. Where the argument for every ``n`` closes for both
(:mod:`symdecomp.verify.c1_every_n`: the spectral conditions in ``t = cos(2 pi/n)``, the table's
valences, and the characteristic map by :mod:`symdecomp.verify.c1_uniform`) the claim is proved,
with a step per scheme; otherwise it is verified for the table's range.
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


def _table(scheme: Scheme, results: dict | None = None):
    """``(rows, None)`` with one row per valence, or ``(None, CheckResult)`` at the first valence that is not C1; each
    valence's :class:`~symdecomp.verify.c1.C1Result` goes into ``results``."""
    lo, hi = max(VALENCES[0], scheme.minimum_valence()), VALENCES[1]
    rows = []
    for n in range(lo, hi + 1):
        r = c1_test(scheme, n)
        if results is not None:
            results[n] = r
        if r.verdict is C1Verdict.NOT_C1:
            what = Verbatim(f"{scheme.name}, n = {n}: {r.reason}")
            return None, CheckResult(Status.REFUTED, what, counterexample=what)
        if r.verdict is not C1Verdict.C1:  # undecided: the test could not settle it, which is no finding about the scheme
            return None, CheckResult(Status.UNDECIDED, Verbatim(f"{scheme.name}, n = {n}: {r.reason}"))
        lam = r.spectral.subdominant.value.real
        rows.append([n, sp.Float(float(lam.mid()), 6), _down(r.spectral.gap), _down(r.jacobian_lower_bound), r.winding_number])
    return rows, None


_HEADER = [sp.Symbol("n"), sp.Symbol("lambda"), sp.Symbol("gap"), sp.Symbol("|J|_min"), sp.Symbol("winding")]


def _every_n(scheme: Scheme, results: dict, who: str) -> Step | None:
    """The proof for every ``n`` (:func:`~symdecomp.verify.c1_every_n.c1_every_n`, the table's valences reused) as one
    step with the polynomial of the subdominant eigenvalue, or ``None`` where it is not proved. ``who`` names the scheme in
    the step (never a file's own name: the text is LaTeX)."""
    from symdecomp.analysis.characteristic_uniform import uniform_nets
    from symdecomp.claims.notation import lambda_1
    from symdecomp.verify.c1_every_n import c1_every_n

    lo, hi = min(results), max(results)
    r = c1_every_n(scheme, hi, certify=lambda k: results[k] if k in results else c1_test(scheme, k))
    if r.status != "proved" or r.uniform is None:
        return None
    u, nets = r.uniform, uniform_nets(scheme)
    symbols = {sp.Symbol("L"): lambda_1, sp.Symbol("t"): sp.Symbol("t")}
    polynomial = sp.Eq(nets.quadratic.as_expr().subs(symbols), 0)
    return Step(
        rf"{who}, for every $n \ge {lo}$ (exact, in $t = \cos(2\pi/n)$): the spectral conditions of Reif's test "
        r"(Sturm sequences on the trace and discriminant of $M(t)$; the eigenvalues of $E_0$ besides 1 below "
        r"$\lambda_1$ by Proposition 5.1's tail bound, or equal to $\lambda_1^2$), Reif's test at "
        rf"$n = {lo}, \dots, {hi}$, and for every $n \ge {u.first}$ the characteristic map: its control nets are "
        r"polynomials in $t$ and $\lambda_1$ (the dominant root below), stretched by $1/\sin(2\pi/n)$ across the ray of "
        rf"$a_0$ so that they converge as $n$ grows; the {u.coefficients} Bezier coefficients of the Jacobian and control "
        rf"points of the inner boundary have the signs of a regular map that winds once, for every "
        rf"$t \in [{sp.latex(u.t_low)}, 1]$ (Sturm sequences; symdecomp.verify.c1_uniform)", polynomial)



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
    mine: dict = {}
    rows, failed = _table(scheme, mine)
    if failed:
        return failed
    companion = next(lat for lat in LATTICES.values() if lat != scheme.lattice).reference()
    theirs: dict = {}
    other, failed = _table(companion, theirs)
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
    proofs = [_every_n(s, results, who) for s, results, who in ((scheme, mine, "This scheme"), (companion, theirs, companion.name))]
    if all(p is not None for p in proofs):
        return CheckResult(
            Status.PROVED,
            Text("C1 proved for every n >= ", lo, " for ", Verbatim(scheme.name), f" and {companion.name}: the spectral "
                 "conditions and a regular, injective characteristic map by exact signs of polynomials in t = cos(2 pi/n) "
                 f"(Sturm sequences), Reif's test certified for n = {lo}..{hi} (symdecomp c1 --every-n prints the steps)"),
            steps=steps + tuple(p for p in proofs if p is not None),
        )
    return CheckResult(
        Status.VERIFIED,
        Text(f"Reif's test certified for n = {lo}..{hi} for ", Verbatim(scheme.name), f" and {companion.name} in rigorous interval "
             "arithmetic (Arb balls; exact in the cyclotomic field at frequency 0); symdecomp c1 extends the range"),
        steps=steps,
        valences=(lo, hi),
    )
