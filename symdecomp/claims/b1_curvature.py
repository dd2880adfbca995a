"""Beyond the paper: curvature and shape at the extraordinary vertex (the toolkit's own claims, section B.1).

The paper ends: "In the future we plan to use the technique presented here to study more systematically
artifacts on subdivision surfaces." These claims do so for the curvature: the regime at each valence
(:mod:`symdecomp.verify.second_order_spectrum`: ``|mu|`` against ``lambda_1^2`` on the 2-ring matrix, certified,
exact on ties), against what the shape literature reports.

Sources, and what could be checked of them here: K. Karciauskas, J. Peters, U. Reif, *Shape
characterization of subdivision surfaces: case studies*, CAGD 21 (2004) 601-614, and J. Peters, U. Reif,
*Shape characterization of subdivision surfaces: basic principles*, CAGD 21 (2004) 585-599 (their
abstracts: the curvature behaviour follows from ``mu`` against ``lambda^2``, and for Catmull-Clark and
Loop "the limit shape is a function of the valence of the extraordinary point rather than the mesh
geometry"); M. Sabin, *Eigenanalysis and artifacts of subdivision curves and surfaces* (2002), the
paper's reference [17]. Their tables of valences could not be read here; the statements below give the
regimes by valence as those works describe them (flat spots at low valence for Catmull-Clark, divergence
from the hyperbolic part at high valence, Loop's vertex weight chosen so that the elliptic eigenvalue is
``lambda_1^2``), and each check computes them from the scheme's rules, so a different scheme or a
different statement changes the status.

What a statement about one scheme by name is about: "Curvature regime: Catmull-Clark" states the regimes of a
scheme on quad meshes and "Curvature regime: Loop" (and "Loop's vertex weight") those of one on triangle meshes. A
scheme on that lattice stands for the named one (its own rules are checked against the statement, as the paper's
claims about Catmull-Clark take the quad scheme given); a scheme on another lattice has nothing to put there, so the
check is given the lattice's reference scheme, and the verdict is the named scheme's. Each claim declares the lattices
it reads the scheme on (``reads_on=``) and the registry hands its check the scheme it reads, so a check reading one
lattice computes with the scheme it is given and the shape claim, reading two, with
:meth:`~symdecomp.claims.registry.Claim.schemes_read`: the fact is stated once, in the declaration. The registry
asks what a check needs (``requires=``) of each scheme it reads (:meth:`~symdecomp.claims.registry.Claim.unmet`): a
triangle file with free parameters gets Catmull-Clark's verdict for Catmull-Clark's regimes, as every triangle file
does, and "not applicable" for Loop's.
:meth:`~symdecomp.claims.registry.Claim.reads_instead` is the one test both routes ask, so a scheme of the zoo on the
other lattice (sqrt(3), the modified butterfly) gets the reference scheme's verdict as a 1-ring scheme does. The
regimes compare mu with lambda_1^2, a real number only for a real lambda_1, hence mirror-symmetric rules
(:data:`~symdecomp.claims.applicability.MIRROR_SYMMETRIC`: a rotating characteristic map has no tangent plane, so no
curvature or shape to speak of).
"""

from __future__ import annotations

import re

import sympy as sp

from symdecomp.algebra.trig_identity import reduced
from symdecomp.analysis.curvature_regime import CurvatureRegime
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.claims.applicability import MIRROR_SYMMETRIC, NO_FREE_PARAMETERS
from symdecomp.claims.notation import eq, gt, lambda_1, lt
from symdecomp.claims.registry import CheckResult, LazySteps, Scope, Status, Step, Text, Verbatim, claim, get_claim
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, QUAD, TRIANGLE
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify.artifacts import artifact_indicators
from symdecomp.verify.second_order_spectrum import CurvatureResult, dominant_part, second_order_eigenstructure

#: The valences of the tables (about a second per scheme; ``symdecomp artifacts`` does more).
VALENCES = (3, 64)

#: As printed: the multiplicity of ``mu = lambda_1^2`` at the regular valence (the three quadratic terms).
REGULAR_MULTIPLICITY = 3

B, Z, U = CurvatureRegime.BOUNDED, CurvatureRegime.ZERO, CurvatureRegime.UNBOUNDED

#: As printed (the statements below): ``(first n, last n or None, regime, the kind of mu or None)``.
CATMULL_CLARK = ((3, 3, Z, "elliptic"), (4, 4, B, None), (5, None, U, "hyperbolic"))
LOOP = ((3, 3, U, "regular rules (every frequency)"), (4, 5, B, "elliptic"), (6, 6, B, None), (7, None, U, "hyperbolic"))

_HEADER = [sp.Symbol("n"), sp.Symbol("lambda_1"), sp.Symbol("lambda_1") ** 2, sp.Abs(sp.Symbol("mu")), sp.Symbol("j_mu")]


def _number(ball) -> sp.Float:
    return sp.Float(float(abs(ball).mid()), 6)


def _row(r: CurvatureResult) -> list:
    freq = ",".join("outer" if e.frequency is None else str(e.frequency) for e in r.mu)
    return [r.n, _number(r.lambda1), _number(abs(r.lambda1) ** 2), _number(r.mu[0].value), sp.Symbol(freq)]


MU = sp.Symbol("mu")
_RELATION = {CurvatureRegime.BOUNDED: eq, CurvatureRegime.ZERO: lt, CurvatureRegime.UNBOUNDED: gt}


def _computed(r: CurvatureResult) -> Text:
    """The computed regime as a finding: the comparison of ``|mu|`` with ``lambda_1^2`` and the numbers (6 digits)."""
    relation = _RELATION.get(r.regime)
    compared = relation(sp.Abs(MU), lambda_1**2) if relation else Text("no comparison")
    return Text(f"computed: {r.regime.value} (", compared, ", with ", eq(sp.Abs(MU), _number(r.mu[0].value) if r.mu else sp.nan),
                " and ", eq(lambda_1**2, _number(abs(r.lambda1) ** 2)), f", mu at the {r.cause} part)")


def _expected(n: int, printed) -> tuple[CurvatureRegime, str | None]:
    return next((regime, kind) for lo, hi, regime, kind in printed if lo <= n and (hi is None or n <= hi))


def check_regimes(scheme: Scheme, printed, valences: tuple[int, int] = VALENCES) -> CheckResult:
    """Compare the certified regime at each valence with ``printed`` (``(lo, hi, regime, kind of mu)`` rows)."""
    lo, hi = max(valences[0], scheme.minimum_valence()), valences[1]
    rows = []
    for n in range(lo, hi + 1):
        r = second_order_eigenstructure(scheme, n)
        if r.regime in (CurvatureRegime.UNDECIDED, CurvatureRegime.NOT_APPLICABLE):
            return CheckResult(Status.UNDECIDED, Verbatim(f"{scheme.name}, n = {n}: {r.reason}"))
        regime, kind = _expected(n, printed)
        if r.regime is not regime or (kind is not None and r.cause != kind):
            what = Text(Verbatim(scheme.name), f", n = {n}: the statement says {regime.value}"
                        + (f" caused by the {kind} part" if kind else "") + "; ", _computed(r))
            return CheckResult(Status.REFUTED, what, counterexample=what,
                               steps=(Step("The regimes up to the counterexample", sp.Matrix([_HEADER] + rows + [_row(r)])),))
        if n <= 10:
            rows.append(_row(r))
    proof = _unbounded_for_every_n(scheme, printed, hi)
    steps = (Step(f"$\\lambda_1$, $\\lambda_1^2$, $|\\mu|$ and the frequency of $\\mu$ for $n = {lo}, \\dots, {min(hi, 10)}$ "
                  "(to 6 digits; the comparisons are certified, and exact where $|\\mu| = \\lambda_1^2$)",
                  sp.Matrix([_HEADER] + rows)),)
    agrees = Text("the certified regime agrees with the statement for ", Verbatim(scheme.name),
                  f" at every n = {lo}..{hi} (Arb balls; ties exact in Q(exp(2 pi i/2n)))")
    if proof is not None and proof[1]:  # the regime and its cause for every larger n: the statement is proved
        return CheckResult(Status.PROVED, Text(agrees, "; for every n beyond: ", *(_typeset(p) + "; " for p in proof[0]),
                                               "(the proofs' steps: symdecomp artifacts --every-n)"), steps=steps)
    tail = Text("; ", _typeset(proof[0][0]), " (the cause beyond ", hi, " is not shown)") if proof else Text("")
    return CheckResult(Status.VERIFIED, Text(agrees, tail), steps=steps, valences=(lo, hi))


def _typeset(step) -> Text:
    """A proof step's statement (its text up to the first colon) with ``lambda_1`` and ``lambda_1^2`` as formulas."""
    head = step.text.split(": ", 1)[0]
    return Text(*({"lambda_1^2": lambda_1**2, "lambda_1": lambda_1}.get(part, part) for part in re.split(r"(lambda_1\^2|lambda_1)", head)
                  if part))


def _unbounded_for_every_n(scheme: Scheme, printed, hi: int):
    """``(steps, complete)``: the statement's last row, unbounded from some n on, proved for every n from a valence of the
    certified range (:mod:`symdecomp.verify.regime_every_n`), and whether its cause (the hyperbolic part) is proved too."""
    from symdecomp.verify.regime_every_n import hyperbolic_cause_from, unbounded_from

    first, last, regime, kind = printed[-1]
    if last is not None or regime is not U or first > hi or unbounded_from(scheme, first) is None:
        return None
    step = unbounded_from(scheme, first)
    cause = hyperbolic_cause_from(scheme, first) if kind == "hyperbolic" else None
    return ((step,) + ((cause,) if cause else ()), kind is None or cause is not None)


@claim(
    "Curvature regime: Catmull-Clark",
    section="B.1",
    title="Catmull-Clark: a flat spot at $n = 3$, unbounded curvature for $n \\ge 5$",
    statement=r"For Catmull-Clark surfaces the curvature at an extraordinary vertex tends to zero at $n = 3$ "
    r"($|\mu| < \lambda_1^2$, $\mu$ elliptic), is bounded at $n = 4$, and is unbounded for every $n \ge 5$, caused by "
    r"the hyperbolic (frequency 2) eigenvalue (Karciauskas, Peters, Reif, CAGD 21 (2004); Peters, Reif, CAGD 21 (2004)).",
    requires=(NO_FREE_PARAMETERS, MIRROR_SYMMETRIC),
    reads_on=(QUAD,),
)
def _catmull_clark(scheme: Scheme) -> CheckResult:
    return check_regimes(scheme, CATMULL_CLARK)


@claim(
    "Curvature regime: Loop",
    section="B.1",
    title="Loop: bounded curvature for $n = 4, 5, 6$ only",
    statement=r"For Loop surfaces the curvature at an extraordinary vertex is unbounded at $n = 3$ (the regular rules' "
    r"eigenvalue $1/8$ exceeds $\lambda_1^2 = 1/16$), bounded at $n = 4, 5$ (Loop's vertex weight puts the elliptic "
    r"eigenvalue at $\lambda_1^2$) and at $n = 6$, and unbounded for every $n \ge 7$, caused by the hyperbolic "
    r"eigenvalue (Karciauskas, Peters, Reif, CAGD 21 (2004)).",
    requires=(NO_FREE_PARAMETERS, MIRROR_SYMMETRIC),
    reads_on=(TRIANGLE,),
)
def _loop(scheme: Scheme) -> CheckResult:
    return check_regimes(scheme, LOOP)


@claim(
    "Loop's vertex weight",
    section="B.1",
    title="Loop's weight makes the elliptic eigenvalue exactly $\\lambda_1^2$",
    statement=r"Loop's vertex weight $\beta(n) = (5/8 - (3/8 + \cos(2\pi/n)/4)^2)/n$ makes the frequency-0 (elliptic) "
    r"eigenvalue equal to $\lambda_1^2$ at every valence (Loop 1987; Peters, Reif 2004).",
    requires=(MIRROR_SYMMETRIC,),
    reads_on=(TRIANGLE,),
)
def _loop_weight(scheme: Scheme) -> CheckResult:
    M, E0 = one_ring_matrices(scheme)
    elliptic = sp.expand(E0.trace() - 1)  # E_0 is 2 x 2 with the eigenvalue 1: the other one is its trace minus 1
    lam1 = M[0, 0].subs(OMEGA, sp.exp(2 * sp.pi * sp.I / N))
    defect = reduced(sp.expand((elliptic - lam1**2).rewrite(sp.cos)))
    steps = LazySteps(lambda: (Step("The elliptic eigenvalue (trace of $E_0$ minus 1)", elliptic),  # lambda_1 only displayed
                               Step("$\\lambda_1 = M(\\omega_n)$", sp.simplify(lam1.rewrite(sp.cos))),
                               Step("The elliptic eigenvalue minus $\\lambda_1^2$", defect)))
    if defect == 0:
        return CheckResult(Status.PROVED, Text("for ", Verbatim(scheme.name), ", the elliptic eigenvalue minus ", lambda_1**2,
                                               " simplifies to 0 for every n"), steps=steps)
    k = next((k for k in range(3, 65) if sp.simplify(defect.subs(N, k)) != 0), None)
    if k is None:
        return CheckResult(Status.UNDECIDED, Text("the difference ", defect, " does not simplify to 0 but vanishes for n = 3..64"),
                           steps=steps)
    at = sp.simplify(defect.subs(N, k))
    return CheckResult(Status.REFUTED, Text("for ", Verbatim(scheme.name), " the elliptic eigenvalue is not ", lambda_1**2),
                       counterexample=Text(f"n = {k}: the elliptic eigenvalue minus ", lambda_1**2, " is ", at), steps=steps)


@claim(
    "Curvature at the regular valence",
    section="B.1",
    title="At the regular valence the curvature is bounded: $\\mu = \\lambda_1^2$, three times",
    statement=r"At the regular valence the subdivision surface is the spline, which reproduces quadratic polynomials: "
    r"$\mu = \lambda_1^2$ exactly, with multiplicity 3 (the quadratic terms), and the curvature is bounded.",
    requires=(NO_FREE_PARAMETERS,),
)
def _regular(scheme: Scheme) -> CheckResult:
    return check_regular(scheme, REGULAR_MULTIPLICITY)


def check_regular(scheme: Scheme, multiplicity: int) -> CheckResult:
    """At the regular valence: ``mu = lambda_1^2`` exactly, with ``multiplicity`` copies (printed: 3), bounded curvature."""
    n = scheme.lattice.regular_valence
    r = second_order_eigenstructure(scheme, n)
    frequencies = sp.FiniteSet(*(e.frequency for e in r.mu))
    steps = (Step(f"The eigenvalues of largest modulus after 1 and $\\lambda_1$ at $n = {n}$, their frequencies", frequencies),)
    if r.regime is CurvatureRegime.BOUNDED and r.mu_multiplicity == multiplicity and all(r.compared(e).exact for e in r.mu):
        return CheckResult(Status.VERIFIED, Text(f"at n = {n}: ", eq(sp.Abs(MU), lambda_1**2), " exactly (",
                                                 eq(lambda_1**2, _number(abs(r.lambda1) ** 2)), "), at the frequencies ", frequencies,
                                                 f" with multiplicity {r.mu_multiplicity}: the curvature is bounded"),
                           steps=steps, valences=(n, n))
    if r.regime is CurvatureRegime.UNDECIDED:
        return CheckResult(Status.UNDECIDED, Verbatim(r.reason), steps=steps)
    what = Text(Verbatim(scheme.name), f" at n = {n}: ", _computed(r), f"; multiplicity {r.mu_multiplicity}, not {multiplicity}")
    return CheckResult(Status.REFUTED, what, counterexample=what, steps=steps)


#: As printed: ``(first n, last n or None, the dominant part's frequency or None for neither)``, per kind of regular patch.
DOMINANCE = {BICUBIC: ((3, 4, None), (5, None, 2)), BOX_SPLINE: ((3, 3, None), (4, 5, 0), (6, 6, None), (7, None, 2))}
#: Valences compared one by one where the last row is not proved for every n (far enough to meet a late change).
SHAPE_VALENCES = (3, 128)
_PART = {0: "the elliptic part", 2: "the hyperbolic part", None: "neither part"}


def _disagreement(scheme: Scheme, printed, lo: int, hi: int) -> CheckResult | None:
    """The first valence of ``lo..hi`` whose certified dominant part is not the printed one, as a refutation."""
    for n in range(lo, hi + 1):
        a = artifact_indicators(scheme, n) if n <= 8 else None
        dominant = a.shape[2] if a else dominant_part(second_order_eigenstructure(scheme, n))
        expected = next(d for first, last, d in printed if first <= n and (last is None or n <= last))
        if dominant != expected:
            what = Text(Verbatim(scheme.name), f", n = {n}: the statement says {_PART[expected]} dominates; computed: "
                        f"{_PART[dominant]} (certified, Arb balls)")
            # one valence's certified comparison, as the C1 test's and the regimes' counterexamples: a single case
            return CheckResult(Status.REFUTED, what, counterexample=what, scope=Scope.SINGLE_CASE)
    return None


def check_dominance(scheme: Scheme, printed, valences: tuple[int, int] = SHAPE_VALENCES) -> CheckResult:
    """Compare which second-order part dominates on fine rings (frequency 0 or 2, or neither) with ``printed``: one
    valence at a time before the last row's first n, and the last row (the hyperbolic part from ``first`` on) for every
    n (:func:`~symdecomp.verify.dominance_every_n.hyperbolic_dominates_from`); where that is open, valence by valence to
    ``valences[1]``, so that a dominance that changes late is refuted at the first valence where it changes."""
    from symdecomp.verify.dominance_every_n import hyperbolic_dominates_from

    lo, hi = max(valences[0], scheme.minimum_valence()), valences[1]
    first, last, part = printed[-1]
    refuted = _disagreement(scheme, printed, lo, min(first - 1, hi))
    if refuted is not None:
        return refuted
    proof = hyperbolic_dominates_from(scheme, max(first, lo)) if last is None and part == 2 else None
    shapes = sp.Matrix([[sp.Integer(n), sp.Symbol(artifact_indicators(scheme, n).shape[0])] for n in range(max(lo, 4), 9)])
    steps = (Step("The certified shape of the central surface for elliptic input (the frequency-0 height), n = 4..8: where "
                  "the hyperbolic part dominates, this is not the shape the rings tend to", shapes),)
    if proof is not None and proof.status == "proved":
        below = f"at each n = {lo}..{first - 1} (certified, Arb balls) and " if first > lo else ""
        return CheckResult(Status.PROVED, Text("the part that dominates on fine rings agrees with the statement for ",
                                               Verbatim(scheme.name), f" {below}", _typeset(proof),
                                               " (decided exactly for every such n, any valences before the exact signs "
                                               "start certified one by one: the last step)"),
                           steps=steps + _argument(first, proof.text))
    refuted = _disagreement(scheme, printed, max(lo, first), hi)
    if refuted is not None:
        return refuted
    why = "; not proved for every n (why: the last step)" if proof is not None else ""
    steps += _argument(first, proof.text) if proof is not None else ()
    return CheckResult(
        Status.VERIFIED,
        Text("the part that dominates on fine rings agrees with the statement for ", Verbatim(scheme.name),
             f" at every n = {lo}..{hi} (the largest frequency-0 and frequency-2 eigenvalues after ", lambda_1,
             ", certified)", why),
        steps=steps, valences=(lo, hi))


def _argument(first: int, text: str) -> tuple[Step, ...]:
    """The argument for every ``n >= first`` as computed (:mod:`symdecomp.verify.dominance_every_n`), in its own words."""
    return (Step(f"For every $n \\ge {first}$, the argument as computed by symdecomp.verify.dominance_every_n "
                 "(formulas in sympy's notation):"), Step(Verbatim(text)))


#: The shape claim's label: its check reads the schemes the registry says it reads (:meth:`Claim.schemes_read`).
SHAPE = "Shape: the valence decides"


@claim(
    SHAPE,
    section="B.1",
    title="Convex input does not stay convex: for $n \\ge 5$ (Catmull-Clark) and $n \\ge 7$ (Loop)",
    statement=r"For generic input the shape near an extraordinary vertex is decided by the valence, not by the mesh: "
    r"the hyperbolic (frequency 2) eigenvalue exceeds the elliptic (frequency 0) one for Catmull-Clark at every "
    r"$n \ge 5$ and for Loop at every $n \ge 7$, so the hyperbolic part dominates on fine rings even for convex input; "
    r"for Loop at $n = 4, 5$ the elliptic part dominates, and the two tie at the regular valence (Karciauskas, Peters, "
    r"Reif, CAGD 21 (2004)).",
    requires=(NO_FREE_PARAMETERS, MIRROR_SYMMETRIC),
    reads_on=(QUAD, TRIANGLE),
)
def _shape(scheme: Scheme) -> CheckResult:
    results = []
    for read in get_claim(SHAPE).schemes_read(scheme):  # one per lattice of reads_on, in its order
        result = check_dominance(read, read.lattice.select(DOMINANCE, "the printed dominance"))
        if result.status not in (Status.VERIFIED, Status.PROVED):
            return result
        results.append(result)
    evidence = Text(*(part for i, r in enumerate(results) for part in (("; and ", r.evidence) if i else (r.evidence,))))
    steps = tuple(step for r in results for step in r.steps)
    if all(r.status is Status.PROVED for r in results):
        return CheckResult(Status.PROVED, evidence, steps=steps)
    ranges = [r.valences for r in results if r.valences is not None]
    return CheckResult(Status.VERIFIED, evidence, steps=steps,
                       valences=(min(lo for lo, _ in ranges), max(hi for _, hi in ranges)))
