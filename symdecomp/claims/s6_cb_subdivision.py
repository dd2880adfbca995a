"""Section 6 applied to the subdivision matrix: Eq. 51, the reduction S -> S', the tuning weights (after Eq. 51).

Split from :mod:`symdecomp.claims.s6_cb_matrices` (the CB-matrix algebra), which it follows in the paper."""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp

from symdecomp.algebra.quadratic_extension import NotInExtension, polynomial_in
from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial, verify_closed_form
from symdecomp.analysis.reduction import BorderedCBMatrix, add_columns_to_first, reduce_first_column, reduction_similarity, subdivision_block_form
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.analysis.tuning import with_free_vertex_rule
from symdecomp.claims.applicability import FACE_NEIGHBOURS, MIRROR_SYMMETRIC
from symdecomp.claims.cb_examples import _det, _nc
from symdecomp.claims.notation import eq, j, lambda_1, listed, ne, tup
from symdecomp.claims.registry import CheckResult, Scope, Status, Step, Text, claim, is_zero
from symdecomp.schemes.scheme import Scheme, subdivision_matrix
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import cos_jtheta as COS
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA


def _displayed_expression_agrees(free: Scheme, expression: sp.Expr, valences: Iterable[int]) -> str | None:
    """Expand the displayed closed form at each valence (vertex weights 0 and 1) exactly, in ``Q(lam)`` with its one
    square root, and compare it with the matrix; ``None`` when they agree, else where they differ. Raises
    :class:`~symdecomp.algebra.quadratic_extension.NotInExtension` for a form with more than one square root."""
    from symdecomp.schemes.full_matrix import characteristic_polynomial as matrix_characteristic_polynomial
    from symdecomp.symbols import lam

    for k in valences:
        for values in ({ALPHA: 0, BETA: 0}, {ALPHA: 1, BETA: 0}, {ALPHA: 0, BETA: 1}):
            subs = {N: k, **{p: v for p, v in values.items() if p in free.parameters}}
            if polynomial_in(expression.subs(subs), lam) != matrix_characteristic_polynomial(free, k, values):
                return f"n = {k}, alpha = {values[ALPHA]}, beta = {values[BETA]}"
    return None


def _against_the_matrix(free: Scheme, expression: sp.Expr, concrete: bool) -> CheckResult | None:
    """The finding when the closed form does not agree with the matrix (``concrete``: the evaluator's comparison for
    n = 3..16), or when its displayed ``expression`` could not be expanded; ``None`` when both agree."""
    try:
        displayed = _displayed_expression_agrees(free, expression, range(3, 7))
    except NotInExtension as unread:
        if concrete:
            return CheckResult(
                Status.UNDECIDED,
                f"the closed form equals the matrix's characteristic polynomial for n = 3..16, but the displayed "
                f"expression was not expanded: it is not rational in lambda and one square root ({unread})",
            )
        displayed = None
    if displayed is None and concrete:
        return None
    where = displayed if displayed is not None else "n = 3..16 (evaluator)"
    return CheckResult(
        Status.REFUTED,
        "the closed form does not equal the characteristic polynomial of the matrix",
        counterexample=Text("at ", where, " the displayed expression and det(xI - S) differ"),
    )


def _factored(cf, rho_p, rho_m) -> bool:
    """``q = (rho_+ + c_+ w)(rho_- + c_+ w)/(c_+ w)``; for ``c_+ = 0`` (``M(omega)`` triangular) ``q = c_0 + c_-/w`` with
    ``rho = c_0, 0``, whose product over the roots of unity is ``c_0^n - (-c_-)^n`` directly."""
    c_minus, c_zero, c_plus = cf.laurent_coefficients
    w = sp.Symbol("w")
    q = cf.frequency_factor.subs(OMEGA, w)
    if is_zero(c_plus):
        return is_zero(rho_p * rho_m) and is_zero(rho_p + rho_m - c_zero) and is_zero(sp.expand(c_zero + c_minus / w - q))
    return is_zero(sp.expand((rho_p + c_plus * w) * (rho_m + c_plus * w) / (c_plus * w)) - q)


@claim(
    "Eq. 51",
    section="6",
    title="Characteristic polynomial of S in closed form",
    statement=r"The eigenvalues of $S$ are the roots of $\det(S-xI)$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq51(scheme: Scheme) -> CheckResult:
    free = with_free_vertex_rule(scheme)
    cf = closed_form_characteristic_polynomial(free)
    c_minus, c_zero, c_plus = cf.laurent_coefficients
    rho_p, rho_m = cf.rho
    factor_ok = _factored(cf, rho_p, rho_m)
    # prod_k c_+ w_k = c_+^n w^(n(n-1)/2), w = exp(2 pi i/n): the sign
    sign = sp.simplify(sp.exp(2 * sp.pi * sp.I / N * N * (N - 1) / 2))
    # with P = rho_+^n, Q = rho_-^n, A = (-c_+)^n, B = (-c_-)^n, and P Q = (c_+ c_-)^n = A B:
    P, Q, A, B = sp.symbols("P Q A B")
    numerator = sp.expand((P - A) * (Q - A)).subs(P * Q, A * B)
    combined = sp.expand(sp.powsimp(numerator / (sign * (-1) ** N * A)))  # c_+^n = (-1)^n A
    combine_ok = is_zero(combined - (P + Q - A - B))
    concrete = all(verify_closed_form(free, n) for n in range(3, 17)) and all(
        verify_closed_form(scheme, n) for n in range(3, 17)
    )
    if not (factor_ok and combine_ok and sign == (-1) ** (N - 1)):
        return CheckResult(Status.ERROR, "a step of the closed form failed")
    if (against_matrix := _against_the_matrix(free, cf.expression, concrete)) is not None:
        return against_matrix
    x_ = sp.Symbol("x")
    rho_p_, rho_m_, c_p_, c_m_ = sp.symbols("rho_+ rho_- c_+ c_-")
    return CheckResult(
        Status.PROVED,
        Text(
            eq(
                _det(x_ * _nc("I") - _nc("S")),
                (x_ - 1) * _det(x_ * _nc("I") - _nc("E_0"))
                * (rho_p_**N + rho_m_**N - (-c_p_) ** N - (-c_m_) ** N) / sp.Function("q")(x_, 1),
            ),
            ", derived for symbolic ", N, " and weights; exact (FLINT) against the matrix for ", N, " from 3 to 16 with ",
            ALPHA, ", ", BETA, " free and the scheme's own (tests: to 64, slow: to 128); the displayed expression itself "
            "expanded and compared for ", N, " from 3 to 6",
        ),
        steps=(
            Step("$q(x,\\omega)=\\det(xI-M(\\omega))$", cf.frequency_factor),
            Step("$(c_-, c_0, c_+)$", sp.Matrix([list(cf.laurent_coefficients)])),
            Step("$q=(\\rho_++c_+\\omega)(\\rho_-+c_+\\omega)/(c_+\\omega)$ with $\\rho_\\pm$ the roots of $\\rho^2-c_0\\rho+c_+c_-$", rho_p, sp.Symbol("rho_+")),
            Step("$\\prod_k(\\rho+c\\,\\omega_n^k)=\\rho^n-(-c)^n$ and $\\prod_k c_+\\omega_n^k=c_+^n\\cdot$", sign),
            Step("$\\prod_{k=0}^{n-1}q(x,\\omega_n^k)=(P-A)(Q-A)/(c_+^n\\,(-1)^{n-1})$ with $P,Q=\\rho_\\pm^n$, $A,B=(-c_\\pm)^n$", combined),
            Step("$\\det(xI-E_0)$", cf.zero_frequency_factor),
            Step("$\\det(xI-S)$ (the paper's $\\det(S-xI)$ is its negative: the size $2n+1$ is odd)", cf.expression),
        ),
    )


@claim(
    "S' (after Eq. 51)",
    section="6",
    title="The reduction S -> S'",
    statement=r"Adding all columns to the first and subtracting the first row from the others, the characteristic polynomial of $S$ equals that of $S'$ with lower-right block $\begin{pmatrix}C_1-A&C_2-B\\C_3-A&C_4-B\end{pmatrix}$, $a_{ij}=\alpha$, $b_{ij}=\beta$.",
    requires=(FACE_NEIGHBOURS,),
)
def _s_prime(scheme: Scheme) -> CheckResult:
    free = with_free_vertex_rule(scheme)
    red = reduce_first_column(subdivision_block_form(free))
    constants = sp.Matrix([[b.constant for b in row] for row in red.reduced.body.blocks])
    bands_same = all(
        red.reduced.body.blocks[p][q].offsets == red.original.body.blocks[p][q].offsets for p in range(2) for q in range(2)
    )
    form_ok = constants == sp.Matrix([[-ALPHA, -BETA], [-ALPHA, -BETA]]) and bands_same and red.reduced.column == (0, 0)
    first_row = (red.reduced.corner, red.reduced.row)
    # the text works on S - xI: after adding all columns the first column is (1 - x, ..., 1 - x)
    x = sp.Symbol("x")
    Sx = sp.Matrix(subdivision_matrix(free, 4)) - x * sp.eye(9)
    Q4, _ = reduction_similarity(9)
    column_ok = is_zero((Sx * sp.Matrix(Q4))[:, 0] - (1 - x) * sp.ones(9, 1))
    concrete_ok = column_ok
    for n in range(3, 9):
        S = sp.Matrix(subdivision_matrix(free, n))
        Q, Qinv = reduction_similarity(2 * n + 1)
        concrete_ok &= sp.Matrix(Q * Qinv) == sp.eye(2 * n + 1)
        concrete_ok &= is_zero(sp.Matrix(Qinv) * S * sp.Matrix(Q) - sp.Matrix(red.reduced.at(n)))
        concrete_ok &= is_zero(S - sp.Matrix(red.original.at(n)))
    # with Eq. 16 as printed (weight 1 - alpha - beta on O) the first row does not sum to 1
    printed_rule = subdivision_block_form(free)
    printed_form = BorderedCBMatrix(1 - ALPHA - BETA, printed_rule.row, printed_rule.column, printed_rule.body)
    printed_sums = add_columns_to_first(printed_form)
    printed_not_constant = sp.simplify(printed_sums.corner - printed_sums.column[0]) != 0
    if not (form_ok and concrete_ok and printed_not_constant):
        return CheckResult(Status.ERROR, "the derived S' does not have the stated form")
    Sn, Qn = _nc("S"), _nc("Q")
    blocks = [_nc(f"C_{k}") for k in range(1, 5)]
    return CheckResult(
        Status.PROVED,
        Text(
            "the two operations are the similarity ", Sn, " to ", Qn**-1 * Sn * Qn, "; derived on the block form for symbolic ",
            N, ", ", ALPHA, ", ", BETA, ": first column ", tup(*([red.reduced.corner, *red.reduced.column] + [sp.Symbol("...")])),
            ", first row ", tup(first_row[0], *first_row[1]), " (the weight on each ", sp.Symbol("a"), ", each ",
            sp.Symbol("b"), "), constant parts ", constants, " added to the circulant blocks ", listed(blocks),
            "; checked entry by entry against ", Qn**-1 * Sn * Qn, " for ", N, " from 3 to 8",
        ),
        steps=(
            Step("on $S-xI$ ($n=4$) the first column after adding all columns is $(1-x)(1,\\dots,1)^T$, as the text says"),
            Step("first column after adding all columns to it (row sums, symbolic $n$)", sp.Matrix([red.after_columns.corner, *red.after_columns.column])),
            Step("after subtracting the first row", sp.Matrix([red.reduced.corner, *red.reduced.column])),
            Step("first row of $S'$ (corner, weight on each $a$, each $b$)", sp.Matrix([[first_row[0], *first_row[1]]])),
            Step("constant parts added to the circulant blocks $C_1..C_4$", constants),
            Step("$S'$ at $n=3$", red.reduced.at(3)),
            Step("The reduction needs rows summing to 1 (the affine Eq. 16). With Eq. 16 as printed ($1-\\alpha-\\beta$ on $O$) the row sums after the column step are not all equal (first row, $a$-rows):", sp.Matrix([printed_sums.corner, printed_sums.column[0]])),
        ),
    )


@claim(
    "Tuning weights (after Eq. 51)",
    section="6",
    title="alpha, beta change only two eigenvalues",
    statement=r"From Prop. 6.3 and the form of $S'$, the fine tuning parameters $\alpha,\beta$ of Eq. 16 affect only two eigenvalues of the subdivision matrix.",
    requires=(FACE_NEIGHBOURS,),
)
def _two_eigenvalues(scheme: Scheme) -> CheckResult:
    free = with_free_vertex_rule(scheme)
    cf = closed_form_characteristic_polynomial(free)
    L = reduce_first_column(subdivision_block_form(free)).lower_right
    E = L.block_eigenvalue_matrix(zero_frequency=False)
    free_of_weights = not (E.free_symbols & {ALPHA, BETA})
    E0 = cf.zero_frequency_matrix
    dependence = sp.Matrix([[sp.diff(cf.zero_frequency_factor, ALPHA), sp.diff(cf.zero_frequency_factor, BETA)]])
    concrete_ok = all(verify_closed_form(free, n) for n in range(3, 13))
    if not (free_of_weights and concrete_ok and dependence != sp.zeros(1, 2)):
        return CheckResult(
            Status.REFUTED,
            "the vertex weights enter a frequency k != 0, or the closed form does not match the matrix",
            counterexample=Text("E_k for k != 0: ", E, "; derivatives of det(xI - E_0) in alpha, beta: ", dependence),
        )
    x_, k_, In, E_0 = sp.Symbol("x"), sp.Symbol("k"), _nc("I"), _nc("E_0")
    return CheckResult(
        Status.PROVED,
        Text(
            "for symbolic ", N, ", ", ALPHA, ", ", BETA, ": ",
            eq(
                _det(x_ * In - _nc("S")),
                (x_ - 1) * _det(x_ * In - E_0) * sp.Product(_det(x_ * In - sp.Function("M")(OMEGA**k_)), (k_, 1, N - 1)),
            ),
            " and only ", E_0, " contains ", ALPHA, ", ", BETA, "; exact for ", N, " from 3 to 12 with ", ALPHA, ", ", BETA,
            " free",
        ),
        steps=(
            Step("$E_k$ of the CB-block of $S'$ for $k\\ne0$ (free of $\\alpha,\\beta$)", E),
            Step("$E_0 = M(1)+nT$", E0),
            Step("$\\partial/\\partial\\alpha,\\ \\partial/\\partial\\beta$ of $\\det(xI-E_0)$", dependence),
        ),
    )


def _certainly_above(value: sp.Expr, bound: sp.Expr) -> bool:
    """``|value| > bound``, decided in Arb ball arithmetic (rigorous: true only when certain)."""
    import flint

    from symdecomp.algebra.compile import compile_expression

    with flint.ctx.workprec(128):
        left = abs(compile_expression(sp.sympify(value, strict=True), (), engine="arb")(()))
        right = compile_expression(sp.sympify(bound, strict=True), (), engine="arb")(())
        right = right.real if isinstance(right, flint.acb) else right
        return bool(left > right)


@claim(
    "Tangent plane unaffected (after Eq. 51)",
    section="6",
    title="Tuning does not interfere with tangent-plane properties",
    statement=r"Hence $\alpha,\beta$ affect only elliptic properties of Catmull-Clark without interfering with tangent plane or hyperbolic properties.",
    requires=(FACE_NEIGHBOURS, MIRROR_SYMMETRIC),  # an edge rule in n: lambda_1 is taken at each valence tried
)
def _no_interference(scheme: Scheme) -> CheckResult:
    # the two weight-dependent eigenvalues are those of E_0; look for vertex weights that lift one above lambda_1
    cf = closed_form_characteristic_polynomial(with_free_vertex_rule(scheme))
    lam1_expr = tangent_eigenvalues(scheme).dominant
    found = None
    for valence in (3, 4, 5):
        lam1 = lam1_expr.subs({COS: sp.cos(sp.pi / valence), N: valence})
        for weights in ((0, 0), (-1, 0), (0, -1)):
            E0 = cf.zero_frequency_matrix.subs({ALPHA: weights[0], BETA: weights[1], N: valence})
            moved = [e for e in sp.Matrix(E0).eigenvals() if _certainly_above(e, lam1)]
            if moved:
                found = (valence, weights, E0, moved[0], lam1)
                break
        if found:
            break
    if found is None:
        return CheckResult(
            Status.UNDECIDED,
            "the eigenvalues of the frequencies k != 0 do not depend on alpha, beta, and no vertex weights tried lift an "
            "E_0 eigenvalue above lambda_1",
        )
    valence, weights, E0, moved, lam1 = found
    k_, E_0 = sp.Symbol("k"), _nc("E_0")
    return CheckResult(
        Status.CORRECTED,
        Text(
            "the eigenvalues of frequencies ", ne(k_, 0), " (tangent-plane ", lambda_1, ", hyperbolic ", eq(j, 2),
            ") do not depend on ", ALPHA, ", ", BETA, " (proved), but the weights can push an eigenvalue of ", E_0,
            " above ", lambda_1, ", and then the tangent-plane pair is no longer subdominant",
        ),
        scope=Scope.EVERY_N,
        steps=(
            Step("$E_0$ at the weights of the counterexample", E0),
            Step("its larger eigenvalue", moved),
            Step("$\\lambda_1$ there (unchanged by $\\alpha,\\beta$)", sp.simplify(lam1)),
        ),
        counterexample=Text(
            eq(N, valence), ", ", eq(ALPHA, weights[0]), ", ", eq(BETA, weights[1]), ": ", E_0, " has the eigenvalue ", moved,
            ", larger in modulus than ", eq(lambda_1, sp.radsimp(sp.simplify(lam1))),
            " (certified in interval arithmetic), so the subdominant eigenvalue is no longer the tangent-plane one",
        ),
        correction=Text(
            ALPHA, ", ", BETA, " change only the two eigenvalues of ", eq(E_0, sp.Function("M")(1) + N * _nc("T")),
            "; tangent-plane and hyperbolic behaviour are unaffected provided both stay below ", lambda_1, " in modulus.",
        ),
    )
