"""Section 4 (1-ring decomposition for Catmull-Clark): Eq. 11-24, Propositions 4.1-4.3."""

from __future__ import annotations

import sympy as sp

from symdecomp.analysis.frequency import per_frequency_matrix, recursion_matrix
from symdecomp.analysis.tuning import with_free_vertex_rule
from symdecomp.claims.applicability import FACE_NEIGHBOURS
from symdecomp.claims.notation import A, B, eq, ne, omega_2n, omega_n, tup
from symdecomp.claims.registry import CheckResult, Scope, Status, Step, Text, Verbatim, claim, is_zero
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.shift_stencil import ShiftStencil, composed_stages, identity_b, then_b
from symdecomp.symbols import alpha, beta, n, omega

R = sp.Rational
I_ROW = sp.Symbol("i", integer=True)
J = sp.Symbol("j", integer=True)
Z = sp.Symbol("z")


# The staged rules as printed (Eq. 17-21).
EQ17 = ShiftStencil(sp.Integer(0), R(3, 4) + R(1, 8) * (1 / omega + omega), sp.Integer(0))
EQ18 = ShiftStencil(sp.Integer(0), R(8, 10), R(1, 10) * (1 / omega + 1))
EQ19 = ShiftStencil(R(3, 8), R(5, 8), sp.Integer(0))
EQ20 = ShiftStencil(sp.Integer(0), R(1, 3) * (1 + omega), R(1, 3))
EQ21 = ShiftStencil(R(1, 4), sp.Integer(0), R(3, 4))


def PRINTED_COMPONENT_VERTEX(j, k, size):
    """Vertex ``k`` of the component ``v_j`` of the 1-ring 2n-gon as printed (Eq. 11, the rows of ``F_2n``)."""
    return sp.exp(2 * sp.pi * sp.I * j * k / size)


@claim(
    "Eq. 10-11",
    section="4",
    reads_scheme=False,
    title="The 1-ring as a $2n$-gon and its decomposition",
    statement="The 1-ring is the $2n$-gon $P = (a_0, b_0, \\dots, a_{n-1}, b_{n-1})$ (Eq. 10), a sum of $2n$ regular "
    "planar $2n$-gons $z_j v_j$ (Eq. 11).",
    requires=(FACE_NEIGHBOURS,),
)
def _eq10_11(scheme: Scheme) -> CheckResult:
    import random

    from symdecomp.schemes.ring import OneRing, one_ring_decomposition

    # The printed components (Eq. 11): vertex k of v_j is omega_2n^(j k); each must be a regular planar 2n-gon.
    k = sp.Symbol("k", integer=True)
    vertex = PRINTED_COMPONENT_VERTEX(J, k, 2 * n)
    step = sp.simplify(vertex.subs(k, k + 1) / vertex)
    closes, modulus = sp.simplify(step ** (2 * n)), sp.simplify(sp.Abs(vertex))
    if step.has(k) or closes != 1 or modulus != 1:
        return CheckResult(
            Status.REFUTED,
            Text("the printed components are not regular 2n-gons: vertex ", k, " of ", sp.Symbol("v_j"), " is ", vertex),
            counterexample=Text("ratio of consecutive vertices ", step, ", its 2n-th power ", closes, ", modulus ", modulus),
        )
    last = 8
    for size in range(3, last + 1):
        rng = random.Random(size)
        pt = lambda: [sp.Rational(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(3)]  # noqa: E731, B023 (called in this iteration)
        ring = OneRing.from_points(pt(), [pt() for _ in range(size)], [pt() for _ in range(size)])
        d = one_ring_decomposition(ring)
        if d.polygon.reconstruct() != sp.Matrix(ring.polygon()):
            return CheckResult(
                Status.REFUTED,
                Text("reconstruction fails at ", eq(n, size)),
                counterexample=Text(eq(n, size), ": the 1-ring ", sp.Matrix(ring.polygon())),
            )
    return CheckResult(
        Status.PROVED,
        Text(
            "Eq. 11 is Eq. 5 for the 2n-gon (proved for every size); random rational 1-rings rebuilt exactly from their ",
            2 * n, " components for ", n, f" from 3 to {last}",
        ),
    )


def PRINTED_RING_POSITION(vertex: str, i):
    """The place of ``a_i`` and ``b_i`` in the 2n-gon ``P = (a_0, b_0, ..., a_(n-1), b_(n-1))`` as printed (Eq. 10)."""
    return 2 * i if vertex == "a" else 2 * i + 1


@claim(
    "Eq. 12-13",
    section="4",
    reads_scheme=False,
    title="$A^j$ and $B^j$ are regular $n$-gons",
    statement="If $z_j v_j = (a_0^j, b_0^j, \\dots, a_{n-1}^j, b_{n-1}^j)$ is a component of Eq. 11, then "
    "$A^j = (a_i^j)$ and $B^j = (b_i^j)$ are planar regular $n$-gons.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq12_13(scheme: Scheme) -> CheckResult:
    # Vertex k of the 2n-gon z_j v_j is z_j omega_2n^(j k) (Eq. 11); a_i^j and b_i^j sit where Eq. 10 puts them.
    found, failures = [], []
    for name in ("a", "b"):
        vertex = Z * sp.exp(2 * sp.pi * sp.I * J * PRINTED_RING_POSITION(name, I_ROW) / (2 * n))
        step = sp.simplify(vertex.subs(I_ROW, I_ROW + 1) / vertex)
        closes = sp.simplify(step**n)  # a regular n-gon: the same rotation each step, back after n steps
        found.append(Step(f"${name}_i^j$ and the ratio of consecutive vertices, its $n$-th power:", sp.Tuple(vertex, step, closes)))
        if step.has(I_ROW) or closes != 1 or sp.simplify(sp.Abs(step)) != 1:
            failures.append(Text(name, " vertices ", vertex, ": ratio ", step, ", its n-th power ", closes))
    ok = not failures
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        Text(
            "vertex ", 2 * I_ROW, " of ", sp.Symbol("v_j"), " (2n-gon) is ", eq(omega_2n ** (2 * I_ROW * J), omega_n ** (I_ROW * J)),
            ": ", eq(A(J), sp.Symbol("z_j") * sp.Symbol("v_j mod n", commutative=False)), ", a regular n-gon (the same rotation ",
            omega_n**J, " from vertex to vertex, closing after n), likewise ", B(J), " from vertex ", 2 * I_ROW + 1, ", for every ",
            n, " and ", J,
        ) if ok else "the printed positions do not give regular n-gons",
        counterexample=None if ok else failures[0],
        steps=tuple(found),
    )


@claim(
    "Eq. 14-15",
    section="4",
    title="Catmull-Clark on the 1-ring",
    statement="$a_i \\rightarrow \\frac38(a_i + O) + \\frac1{16}(a_{i-1} + b_{i-1} + b_i + a_{i+1})$ and "
    "$b_i \\rightarrow \\frac14(a_i + b_i + a_{i+1} + O)$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq14_15(scheme: Scheme) -> CheckResult:
    # Catmull-Clark's face point of the face (O, a_i, b_i, a_{i+1}) and edge point of the edge (O, a_i): the mean of
    # the edge's ends and of the face points of its two faces (i-1 and i).
    face_i = ShiftStencil(R(1, 4), R(1, 4) * (1 + omega), R(1, 4))
    edge_i = ShiftStencil(
        R(1, 4) + R(1, 4) * (face_i.o + face_i.o),
        R(1, 4) + R(1, 4) * sp.expand(face_i.a + face_i.a / omega),
        R(1, 4) * sp.expand(face_i.b + face_i.b / omega),
    )
    cc = scheme
    printed_a = ShiftStencil(R(3, 8), R(3, 8) + (1 / omega + omega) / 16, (1 / omega + 1) / 16)
    printed_b = ShiftStencil(R(1, 4), (1 + omega) / 4, R(1, 4))
    pairs = (
        ("Catmull-Clark's edge point", edge_i, printed_a),
        ("Catmull-Clark's face point", face_i, printed_b),
        ("this scheme's edge rule", ShiftStencil.of(cc.edge_rule), printed_a),
        ("this scheme's face rule", ShiftStencil.of(cc.face_rule), printed_b),
    )
    wrong = [(name, x.as_matrix(), y.as_matrix()) for name, x, y in pairs if not is_zero(x.as_matrix() - y.as_matrix())]
    ok = not wrong
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        "Catmull-Clark's face point (mean of the face) and edge point (mean of the edge's ends and its two face points), "
        "composed as shift-operator polynomials for every n, give the printed rules"
        + (", which are the package's scheme data" if ok else "; this scheme's rules differ from them"),
        counterexample=None if ok else Text(wrong[0][0], " as ", _SHIFT_FORM, " is ", wrong[0][1], ", the printed rule ", wrong[0][2]),
        steps=(
            Step("Face point of $(O, a_i, b_i, a_{i+1})$ as $(w_O, A(\\omega), B(\\omega))$:", face_i.as_matrix()),
            Step("Edge point of $(O, a_i)$:", edge_i.as_matrix()),
        ),
    )


#: A rule as shift-operator polynomials: the weight on O and the polynomials on the a's and b's.
_SHIFT_FORM = sp.Tuple(sp.Symbol("w_O"), sp.Function("A")(sp.Symbol("omega")), sp.Function("B")(sp.Symbol("omega")))

#: The weight of O in Eq. 16 as printed.
PRINTED_VERTEX_CENTER = 1 - alpha - beta


def _unaffine_example(printed_sum, scheme: Scheme) -> dict:
    """The first valence and vertex weights at which the printed weights do not sum to one: the scheme's own
    weights at n = 3, 4, ..., else those of its lattice's reference scheme (Catmull-Clark), whose alpha + beta
    never vanishes."""
    for rules in (scheme.vertex_rule, scheme.lattice.reference().vertex_rule):
        for valence in range(3, 13):
            example = {n: valence, alpha: rules.each_a.subs(n, valence), beta: rules.each_b.subs(n, valence)}
            if sp.expand(printed_sum.subs(example)) != 0:
                return example
    raise ValueError("no valence in 3..12 where the printed vertex weights fail to sum to one")


@claim(
    "Eq. 16",
    section="4",
    title="Vertex rule",
    statement="$O \\rightarrow (1-\\alpha-\\beta) O + \\alpha \\sum_i a_i + \\beta \\sum_i b_i$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq16(scheme: Scheme) -> CheckResult:
    printed_sum = sp.factor(sp.expand(PRINTED_VERTEX_CENTER + n * alpha + n * beta - 1))
    corrected_center = 1 - n * alpha - n * beta
    corrected_sum = sp.expand(corrected_center + n * alpha + n * beta)
    standard = scheme.vertex_rule  # the scheme's own weights, whatever its name
    std_center = sp.expand(corrected_center.subs({alpha: standard.each_a, beta: standard.each_b}))
    if printed_sum == 0:
        return CheckResult(Status.PROVED, "the printed rule is affine")
    example = _unaffine_example(printed_sum, scheme)
    O, i = sp.Symbol("O"), sp.Symbol("i")
    return CheckResult(
        Status.CORRECTED,
        Text(
            "as printed the weights sum to ", 1 + sp.UnevaluatedExpr(printed_sum), ", so the rule is not affine (not "
            "translation invariant) unless ", eq(alpha + beta, 0), "; with weight ", corrected_center, " on O it is, and "
            "the vertex rule of the scheme ", Verbatim(repr(scheme.name)), " (", eq(alpha, standard.each_a), ", ",
            eq(beta, standard.each_b), ") gives O the weight ", std_center,
        ),
        scope=Scope.EVERY_N,
        counterexample=Text(
            eq(n, example[n]), " with the weights ", eq(alpha, example[alpha]), ", ", eq(beta, example[beta]),
            ": the printed weights sum to ", sp.expand((PRINTED_VERTEX_CENTER + n * alpha + n * beta).subs(example)),
        ),
        correction=Text(
            O, " becomes ", corrected_center * O + alpha * sp.Sum(sp.Symbol("a_i"), (i, 0, n - 1)) + beta * sp.Sum(sp.Symbol("b_i"), (i, 0, n - 1)),
        ),
        steps=(
            Step("Sum of the printed weights minus one:", printed_sum),
            Step("Sum of the corrected weights:", corrected_sum),
            Step("The vertex weights $(\\alpha, \\beta)$ of the scheme's vertex rule:", sp.Tuple(standard.each_a, standard.each_b)),
            Step("The corrected weight of $O$ at them:", std_center),
        ),
    )


@claim(
    "Eq. 17-21",
    section="4",
    title="Staged Catmull-Clark rules",
    statement="Eq. 14 decomposes into the steps Eq. 17, 18, 19 and Eq. 15 into Eq. 20, 21.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq17_21(scheme: Scheme) -> CheckResult:
    cc = scheme
    edge, face = ShiftStencil.of(cc.edge_rule), ShiftStencil.of(cc.face_rule)
    a, b = composed_stages((EQ17, EQ18, EQ19), (EQ20, EQ21))
    da = (a.as_matrix() - edge.as_matrix()).applyfunc(sp.expand)
    db = (b.as_matrix() - face.as_matrix()).applyfunc(sp.expand)
    # Reading Eq. 20 with the a's already moved by Eq. 17-19 gives a different rule:
    sequential = then_b(identity_b(), ShiftStencil(EQ20.o + EQ20.a.subs(omega, 1) * a.o, sp.expand(EQ20.a * a.a), sp.expand(EQ20.a * a.b + EQ20.b)))
    sequential = then_b(sequential, EQ21)
    differs = not is_zero(sequential.as_matrix() - face.as_matrix())
    if not (is_zero(da) and is_zero(db)):
        return CheckResult(
            Status.REFUTED,
            "the staged rules do not compose to this scheme's rules",
            counterexample=Text("composed minus the scheme's edge rule: ", da, "; face rule: ", db),
        )
    return CheckResult(
        Status.PROVED,
        "as shift-operator polynomials (valid for every n): Eq. 17 -> 18 -> 19 gives Eq. 14 and Eq. 20 -> 21 gives "
        "Eq. 15, when the b-steps read the a's of the same level (not the a's moved by Eq. 17-19"
        + (", which would give a different rule)" if differs else ")"),
        steps=(
            Step("Each rule as $(w_O, A(\\omega), B(\\omega))$, $\\omega$ the index shift; Eq. 17, 18, 19 composed:", a.as_matrix()),
            Step("Eq. 14 from the scheme's edge rule:", edge.as_matrix()),
            Step("Eq. 20, 21 composed:", b.as_matrix()),
            Step("Eq. 15 from the scheme's face rule:", face.as_matrix()),
            Step("Eq. 20 applied to the moved a's would instead give", sequential.as_matrix()),
        ),
    )


@claim(
    "Proposition 4.1",
    section="4",
    title="$A^j$, $B^j$ stay planar on parallel planes",
    statement="$A^j$ and $B^j$ remain planar polygons on parallel planes throughout the subdivision process, "
    "$j = 0, \\dots, 2n-1$.",
    requires=(FACE_NEIGHBOURS,),
)
def _prop41(scheme: Scheme) -> CheckResult:
    cc = with_free_vertex_rule(scheme)
    X, Y = sp.symbols("X Y")
    rows = []
    for rule in (cc.edge_rule, cc.face_rule):
        # the rule at a symbolic row i on the mode a_m = X omega^m, b_m = Y omega^m, O = 0
        value = sum((w * X * omega ** (I_ROW + k) for k, w in rule.a), sp.Integer(0)) + sum(
            (w * Y * omega ** (I_ROW + k) for k, w in rule.b), sp.Integer(0)
        )
        rows.append(sp.expand(sp.powsimp(sp.expand(value / omega**I_ROW))))
    # The same on the components as printed (Eq. 10-13): a_m^j and b_m^j read off vertex PRINTED_RING_POSITION of
    # z_j v_j (Eq. 11), X and Y their amplitudes; the new a_i, b_i over the old must not depend on the row i.
    def printed_vertex(name, m):
        return PRINTED_COMPONENT_VERTEX(J, PRINTED_RING_POSITION(name, m), 2 * n)

    amplitude = {"a": X, "b": Y * printed_vertex("a", 0) / printed_vertex("b", 0)}
    printed_rows = []
    for name, rule in (("a", cc.edge_rule), ("b", cc.face_rule)):
        value = sum((w * amplitude["a"] * printed_vertex("a", I_ROW + k) for k, w in rule.a), sp.Integer(0)) + sum(
            (w * amplitude["b"] * printed_vertex("b", I_ROW + k) for k, w in rule.b), sp.Integer(0)
        )
        printed_rows.append(sp.simplify(sp.powsimp(sp.expand(value / printed_vertex(name, I_ROW)))))
    free_of_row = not any(r.has(I_ROW) for r in rows + printed_rows)
    matches = is_zero(sp.Matrix(rows) - per_frequency_matrix(cc) * sp.Matrix([X, Y]))
    ok = free_of_row and matches
    v_k, z_ = sp.Symbol("v_k", commutative=False), sp.Symbol("z")
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        Text(
            "for every ", n, " and every frequency with ", ne(omega, 1), " the rules map ", tup(X * v_k, Y * v_k), " to ",
            tup(sp.Symbol("X'") * v_k, sp.Symbol("Y'") * v_k), " with ", tup(sp.Symbol("X'"), sp.Symbol("Y'")), " = ",
            sp.Symbol("M_k"), " ", tup(X, Y), " (symbolic row ", I_ROW, "): ", A(J), " and ", B(J),
            " stay complex multiples of the same ", z_ * v_k, ", so they lie in planes parallel to ",
            sp.Function("span")(sp.re(z_), sp.im(z_)), "; the centres move along the line of Proposition 4.3",
        ),
        counterexample=None if ok else Text(
            "the new vertices over the old: ", sp.Tuple(*rows), ", on the printed components ", sp.Tuple(*printed_rows)
        ),
        steps=(
            Step("New $a_i$ and $b_i$ on the mode, divided by $\\omega^i$ ($O = 0$):", sp.Matrix(rows)),
            Step("which is $M_j (X, Y)^T$ (Eq. 33).", per_frequency_matrix(cc) * sp.Matrix([X, Y])),
        ),
    )


@claim(
    "Proposition 4.2",
    section="4",
    title="$A^j$ and $A^{2n-j}$ stay coplanar",
    statement="$A^j$ and $A^{2n-j}$ remain coplanar throughout the subdivision process.",
    requires=(FACE_NEIGHBOURS,),
)
def _prop42(scheme: Scheme) -> CheckResult:
    cc = with_free_vertex_rule(scheme)
    M = per_frequency_matrix(cc)
    weights_real = all(
        w.is_real is not False for rule in (cc.edge_rule, cc.face_rule) for _, w in rule.a + rule.b
    )
    # On |omega| = 1, conj(omega) = 1/omega; with real weights conj(M(omega)) = M(conj(omega)).
    u = sp.Symbol("u", real=True)
    on_circle = {omega: sp.exp(sp.I * u)}
    conj_M = M.subs(on_circle).applyfunc(sp.conjugate)
    M_inverse = M.subs(omega, 1 / omega).subs(on_circle)
    diff = (conj_M - M_inverse).applyfunc(lambda e: sp.simplify(e.rewrite(sp.cos)))
    ok = weights_real and is_zero(diff)
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        Text(
            "with real weights ", eq(sp.Symbol("M_n-k"), sp.conjugate(sp.Symbol("M_k"))), " for every ", n,
            "; a real 1-ring has ", eq(sp.Symbol("z_2n-j"), sp.conjugate(sp.Symbol("z_j"))), ", so ", A("2n-j"),
            " stays the conjugate of ", A(J), " and their sum stays a real planar polygon (the coplanar pair of Eq. 6)",
        ),
        counterexample=None if ok else Text("the difference ", diff),
        steps=(Step("$\\overline{M_j(\\omega)} - M_j(1/\\omega)$ on $|\\omega| = 1$:", diff),),
    )


@claim(
    "Proposition 4.3",
    section="4",
    title="$O$ and the centres of $A^j$, $B^j$ stay collinear",
    statement="The vertex $O$ and the centres of the polygons $A^j, B^j$ remain collinear throughout the subdivision process.",
    requires=(FACE_NEIGHBOURS,),
)
def _prop43(scheme: Scheme) -> CheckResult:
    cc = with_free_vertex_rule(scheme)
    E = recursion_matrix(cc)
    sums = sp.Matrix([sp.simplify(sum(E.row(r))) for r in range(3)])
    affine = all(s == 1 for s in sums)
    printed = sp.Matrix([[1 - alpha - beta, n * alpha, n * beta]])
    printed_sum = sp.factor(sum(printed) - 1)
    return CheckResult(
        Status.PROVED if affine else Status.REFUTED,
        Text(
            "the rows of the recursion for (O, centre of A, centre of B) (Eq. 43, derived) sum to 1 for every ", n, ", ",
            alpha, ", ", beta, ": new points are affine combinations of collinear points, so they stay on the line "
            "through O and the common initial centre. This needs the affine vertex rule: with Eq. 16 as printed the "
            "first row sums to ", 1 + sp.UnevaluatedExpr(printed_sum),
        ),
        counterexample=None if affine else Text("the row sums ", tup(*sums)),
        steps=(Step("The recursion matrix (Eq. 43, derived from the rules):", E), Step("Its row sums:", sums)),
    )


#: Eq. 24 as printed: ``B^j / A^j = omega_2n^j``.
PRINTED_B_OVER_A = sp.exp(sp.pi * sp.I * J / n)


@claim(
    "Eq. 24",
    section="4",
    reads_scheme=False,
    title="$B^j = \\omega_{2n}^j A^j$",
    statement="$B^j = \\omega_{2n}^j A^j$, $j = 1, \\dots, n-1$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq24(scheme: Scheme) -> CheckResult:
    b_ij = Z * sp.exp(2 * sp.pi * sp.I * J * (2 * I_ROW + 1) / (2 * n))
    a_ij = Z * sp.exp(2 * sp.pi * sp.I * J * (2 * I_ROW) / (2 * n))
    ratio = sp.simplify(b_ij / a_ij)
    expected = PRINTED_B_OVER_A
    ok = sp.simplify(ratio - expected) == 0
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        Text(
            sp.Symbol("b_i^j") / sp.Symbol("a_i^j"), " = ", omega_2n ** (J * (2 * I_ROW + 1) - 2 * I_ROW * J),
            " = ", omega_2n**J, " (derived: ", ratio, ") for every ", I_ROW,
            "; it holds for every ", J, " from 0 to ", 2 * n - 1, ", not only from 1 to ", n - 1,
        ),
        counterexample=None if ok else Text("b_i^j / a_i^j = ", ratio, ", not ", expected),
        steps=(Step("$b_i^j / a_i^j$:", ratio),),
    )
