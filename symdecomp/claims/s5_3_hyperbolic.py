"""Section 5.3, hyperbolic properties: the j = 2 components, the paper's construction, the basis function."""

from __future__ import annotations

import sympy as sp

from symdecomp.analysis.elliptic import elliptic_component, tangent_lambda
from symdecomp.analysis.hyperbolic import hyperbolic_defect, hyperbolic_equality, hyperbolic_lambda, iterate_hyperbolic_ring
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.claims import CheckResult, Status, Step, Text, claim
from symdecomp.claims.notation import A, M, eq, ge, gt, j, lambda_1, lambda_2, listed, lt, ne, tup
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import cos_jtheta
from symdecomp.symbols import n as N

_VALENCES = (3, 12)
Sym = sp.Symbol


@claim(
    "Section 5.3: smaller eigenvalues",
    section="5.3",
    title="Hyperbolic components have smaller eigenvalues",
    statement=r"The eigenvalues of $A^2, A^{2n-2}, B^2, B^{2n-2}$ are smaller than those related to tangent plane "
    r"continuity.",
)
def _smaller() -> CheckResult:
    cc = catmull_clark()
    dominant = tangent_eigenvalues(cc).dominant
    t = sp.Symbol("t", positive=True)  # t = |c|
    slope = sp.factor(sp.diff(dominant.subs(sp.Abs(cos_jtheta), t).subs(cos_jtheta**2, t**2), t))
    c = sp.Symbol("c", positive=True)  # cos(pi/n); cos(2 pi/n) = 2c^2 - 1
    below = sp.factor(2 * c**2 - 1 - c)  # cos(2pi/n) < cos(pi/n)  <=> (2c+1)(c-1) < 0
    above = sp.factor(-(2 * c**2 - 1) - c)  # -cos(2pi/n) < cos(pi/n) <=> (2c-1)(c+1) > 0, false at c = 1/2 (n = 3)
    # On c in (1/2, 1) (n >= 4) both polynomials keep one sign: no root inside, negative at c = 3/4.
    for poly in (below, above):
        inside = [r for r in sp.Poly(poly, c).real_roots() if sp.Rational(1, 2) < r < 1]
        if inside or not poly.subs(c, sp.Rational(3, 4)) < 0:
            return CheckResult(Status.ERROR, Text("sign analysis failed for ", poly))
    if not sp.simplify(slope).is_positive:
        return CheckResult(Status.ERROR, Text("could not show ", gt(slope, 0)))
    lam1_3 = tangent_lambda(cc, 1).subs(N, 3)
    lam2_3 = hyperbolic_lambda(cc).subs(N, 3)
    equal_at_3 = sp.simplify(lam1_3 - lam2_3) == 0
    if not equal_at_3:
        return CheckResult(Status.ERROR, Text("expected ", eq(lambda_2, lambda_1), " at ", eq(N, 3)))
    cos_n = sp.cos(sp.pi / N)
    return CheckResult(
        Status.CORRECTED,
        Text(
            "the dominant eigenvalue of ", M("j"), " increases with ", eq(t, sp.Abs(sp.cos(j * sp.pi / N))), " (",
            eq(sp.Derivative(Sym("lambda"), t), slope), ", positive), and ", lt(sp.Abs(sp.cos(2 * sp.pi / N)), cos_n),
            " iff ", ge(N, 4), "; at ", eq(N, 3), ", ", eq(j, 2), " is the conjugate frequency of ", eq(j, 1), " (",
            eq(sp.cos(2 * sp.pi / 3, evaluate=False), -sp.cos(sp.pi / 3, evaluate=False)), ") and ",
            eq(lambda_2, lambda_1),
        ),
        correction=Text(
            "for ", ge(N, 4), " the ", eq(j, 2), " eigenvalues are strictly smaller than ", lambda_1, " (both of them: ",
            eq(sp.Function("det")(M("j")), tangent_eigenvalues(cc).determinant), ", positive, so the other one is "
            "smaller still); at ", eq(N, 3), " the components ", A(2), ", ", A(4),
            " are tangent-plane components with eigenvalue ", lambda_1,
        ),
        counterexample=Text(eq(N, 3), ": ", eq(lambda_2, lambda_1), " = ", sp.N(lam1_3, 15)),
        steps=(
            Step("$d\\lambda/d|c|$ of the dominant eigenvalue of $M_j$", slope),
            Step("$\\cos(2\\pi/n) - \\cos(\\pi/n)$ in $c = \\cos(\\pi/n)$", below),
            Step("$-\\cos(2\\pi/n) - \\cos(\\pi/n)$", above),
        ),
    )


@claim(
    "Section 5.3: quadratic speed",
    section="5.3",
    title="Hyperbolic components must shrink with quadratic speed",
    statement=r"Similarly to the elliptic case, the hyperbolic components have to shrink with quadratic speed compared "
    r"to the tangent plane ($\lambda_2 = \lambda_1^2$).",
)
def _quadratic() -> CheckResult:
    cc = catmull_clark()
    eq_ = hyperbolic_equality(cc)
    defect = hyperbolic_defect(cc)
    d5 = sp.N(defect.subs(N, 5), 30)
    d3 = sp.N(defect.subs(N, 3), 30)
    if eq_.valences != (4,) or not (d5 > 0 and d3 > 0):
        return CheckResult(Status.ERROR, f"unexpected: {eq_.valences}, {d3}, {d5}")
    cos_n = sp.cos(sp.pi / N)
    (root,) = [cos_n.subs(N, v) for v in eq_.valences]
    return CheckResult(
        Status.PROVED,
        Text(
            "for Catmull-Clark ", eq(lambda_2, lambda_1**2), " only at ", eq(N, eq_.valences[0]), ": the resultant ",
            eq_.polynomial, " has the single root ", eq(cos_n, root), " in ", sp.Interval.Ropen(sp.Rational(1, 2), 1),
            "; ", lambda_2 - lambda_1**2, " is continuous in ", cos_jtheta, " and positive at ", eq(N, 3), " (", sp.N(d3, 6),
            ") and ", eq(N, 5), " (", sp.N(d5, 6), "), hence positive for every ", ne(N, 4),
            ": the hyperbolic part shrinks slower than quadratically (the requirement fails for ", ne(N, 4), ")",
        ),
        steps=(Step("$\\lambda_2 - \\lambda_1^2$", defect), Step("Resultant in $c = \\cos(\\pi/n)$", eq_.polynomial)),
    )


@claim(
    "Section 5.3: construction",
    section="5.3",
    title="A 1-ring with only hyperbolic components",
    statement=r"Place $O$ on the plane of $A^1, A^{2n-1}, B^1, B^{2n-1}$ (the elliptic component becomes zero) and add "
    r"a combination of $\vec{v_2}, \vec{v_{2n-2}}$ on a plane perpendicular to the 1-ring.",
)
def _construction() -> CheckResult:
    cc = catmull_clark()
    lo, hi = 3, 8
    for n in range(lo, hi + 1):
        it = iterate_hyperbolic_ring(cc, n, steps=3, digits=15)
        if not (it.matches_prediction and it.elliptic_component_zero):
            return CheckResult(
                Status.REFUTED,
                f"n = {n}: exact iteration differs from the per-frequency prediction",
                counterexample=Text(eq(N, n), ", hyperbolic_ring, 3 steps"),
            )
    return CheckResult(
        Status.VERIFIED,
        Text(
            "hyperbolic_ring(n) iterated 3 steps with the exact subdivision matrix in ", sp.Function("Q")(Sym("zeta_4n")),
            " equals the prediction (tangent part by ", M(1) ** Sym("k"), ", heights by ", M(2) ** Sym("k"),
            ") exactly; O and the centroids of the a's and b's stay at height 0",
        ),
        valences=(lo, hi),
    )


@claim(
    "Section 5.3: basis function",
    section="5.3",
    title="The coarse mesh of the basis function is only elliptic near O",
    statement=r"The coarse mesh of the basis function has only elliptic component near $O$: its 1-ring is planar, so "
    r"the components perpendicular to the tangent plane are zero.",
)
def _basis() -> CheckResult:
    cc = catmull_clark()
    lo, hi = _VALENCES
    for n in range(lo, hi + 1):
        S = subdivision_matrix(cc, n)
        h = sp.Matrix([1] + [0] * (2 * n))
        for _ in range(3):
            h = S * h
            if len(set(h[1 : n + 1])) != 1 or len(set(h[n + 1 :])) != 1:
                return CheckResult(
                    Status.REFUTED,
                    Text(eq(N, n), ": heights leave the frequency-0 subspace"),
                    counterexample=Text(eq(N, n), ": heights ", tup(*h)),
                )
    comps = [elliptic_component(cc, n, (1, 0, 0)) for n in (3, 4, 5)]
    if any(c == 0 for c in comps):
        return CheckResult(
            Status.REFUTED,
            "the basis function has no elliptic component",
            counterexample=Text("elliptic components at n = 3, 4, 5: ", listed(comps)),
        )
    return CheckResult(
        Status.VERIFIED,
        Text(
            "heights ", tup(1, 0, Sym("..."), 0), " stay constant on the a's and on the b's under the exact matrix (3 steps): "
            "no ", ne(j, 0), " component off the plane; the input ", tup(1, 0, 0), " of Eq. 43 has a nonzero elliptic "
            "component (", N, " = 3, 4, 5: ", listed(c if c.is_Rational else sp.N(c, 6) for c in comps), ")",
        ),
        valences=(lo, hi),
    )
