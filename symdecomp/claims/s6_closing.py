"""Section 6, its closing paragraph: tuning without multiplicities, the 1-ring suffices, larger neighbourhoods.

The paragraph after the tuning discussion makes three statements, registered separately:

* the tuning property (alpha, beta change only the eigenvalues of ``E_0``) holds whatever the
  algebraic or geometric multiplicities are;
* the 1-ring is sufficient for the computation of all the continuous derivatives at the vertex;
* "increasing the range might only increase the rank deficiency of the subdivision matrix by
  introducing null columns".

The last two are checked on the K-ring matrices built by exact refinement of a mesh
(:mod:`symdecomp.schemes.rings`, block form :func:`symdecomp.analysis.frequency.ring_blocks`), for every
valence through the banded circulant-block form: with the rings ordered from the centre out, the
matrix is block lower-triangular (the rows of the inner rings do not read the outer ones), so its
characteristic polynomial is that of the inner part times that of the outer block, and a left
eigenvector whose eigenvalue is not one of the outer block's vanishes on the outer rings.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.components import ZETA, root_of_unity_orders
from symdecomp.analysis.frequency import ring_blocks
from symdecomp.claims.applicability import FACE_NEIGHBOURS, NO_FREE_PARAMETERS
from symdecomp.claims.notation import eq, lambda_1, listed, ne, tup
from symdecomp.claims.registry import CheckResult, Scope, Status, Step, Text, claim
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, subdivision_matrix
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA

X = sp.Symbol("x")


_det = sp.Function("det")


def _named(name: str) -> sp.Symbol:
    """A matrix by name (products keep their order)."""
    return sp.Symbol(name, commutative=False)

#: The neighbourhood the paragraph calls sufficient: "a one ring neighborhood".
PRINTED_SUFFICIENT_RINGS = 1
#: The eigenvalues the paragraph says a larger range adds: only those of null columns, 0.
PRINTED_ADDED_EIGENVALUES = frozenset({0})


def _split(scheme: Scheme, rings: int, inner_rings: int) -> tuple:
    """The K-ring block form and the indices of its vertex classes inside and outside ``inner_rings`` rings."""
    blocks = ring_blocks(scheme, rings)
    inside = set(ring_blocks(scheme, inner_rings).classes) if inner_rings >= 1 else set()
    inner = [i for i, c in enumerate(blocks.classes) if c in inside]
    outer = [i for i, c in enumerate(blocks.classes) if c not in inside]
    return blocks, inner, outer


def _triangular(blocks, inner, outer) -> bool:
    """The rows of the centre and of the inner classes read no outer class (every n, every frequency)."""
    E = blocks.frequency_matrix()
    return all(E[p, q] == 0 for p in inner for q in outer) and all(blocks.centre_row[q] == 0 for q in outer)


def _outer_charpoly(blocks, outer) -> sp.Expr:
    """``det(xI - Y(omega))``, ``Y`` the outer classes' block (the centre is an inner vertex)."""
    Y = blocks.frequency_matrix().extract(outer, outer)
    return sp.factor(sp.cancel((X * sp.eye(len(outer)) - Y).det()))


def _null_classes(blocks, outer) -> list:
    """Outer classes whose columns are zero in the whole matrix (no new point reads them)."""
    E = blocks.frequency_matrix()
    return [blocks.classes[q] for q in outer if all(E[p, q] == 0 for p in range(blocks.class_count)) and blocks.centre_row[q] == 0]


def _subdominant_condition(scheme: Scheme) -> sp.Expr:
    """``det(xI - E_1(omega))`` of the 1-ring: its roots at ``omega = omega_n`` are the frequency-1 eigenvalues
    (``lambda_1`` the dominant one)."""
    E1 = ring_blocks(scheme, 1).frequency_matrix()
    return sp.cancel((X * sp.eye(E1.rows) - E1).det())


def _left_support(scheme: Scheme, valence: int, rings: int, value, inner_rings: int) -> tuple:
    """Exact left eigenvectors of the ``rings``-ring matrix for ``value``: ``(count, label)`` with ``label`` the
    first vertex outside ``inner_rings`` rings where one of them is nonzero (``None``: they vanish there)."""
    S = ring_subdivision_matrix(scheme, valence, rings)
    inside = set(ring_subdivision_matrix(scheme, valence, inner_rings).labels) if inner_rings >= 1 else {(0, 0, 0)}
    left = (S.exact_matrix().T - value * sp.eye(S.size)).nullspace(simplify=True)
    for vector in left:
        for label, entry in zip(S.labels, vector):
            if label not in inside and sp.simplify(entry) != 0:
                return len(left), label
    return len(left), None


def _rational_valences(scheme: Scheme, count: int) -> list[int]:
    """The first ``count`` valences from 3 on where the vertex rule's weights are rational (exact matrices stay
    rational there; Loop's ``cos(2 pi/n)`` is rational at n = 3, 4, 6)."""
    v = scheme.vertex_rule
    out = [k for k in range(3, 13) if all(sp.sympify(w, strict=True).subs(N, k).is_Rational for w in (v.center, v.each_a, v.each_b))]
    return out[:count]


def _lambda1_at(scheme: Scheme, valence: int):
    """``lambda_1`` at a valence: the exact root of the frequency-1 polynomial of largest modulus."""
    condition = sp.expand(_subdominant_condition(scheme).subs({OMEGA: sp.exp(2 * sp.pi * sp.I / valence), N: valence}))
    roots = [sp.radsimp(sp.simplify(sp.expand_complex(r))) for r in sp.roots(sp.Poly(condition, X))]
    return max(roots, key=lambda r: abs(complex(sp.N(r, 30))))


def _regular_lambda1(scheme: Scheme):
    """``(valence, lambda_1)`` at the regular valence, where the frequency-1 eigenvalues are simplest."""
    valence = scheme.lattice.regular_valence
    return valence, _lambda1_at(scheme, valence)


def _outer_block_proof(scheme: Scheme, rings: int, inner_rings: int) -> tuple[bool, bool, list]:
    """For every n: is the ``rings``-ring matrix block lower-triangular with the classes outside ``inner_rings``
    last, and is its outer block's spectrum free of 1 and of ``lambda_1``? ``(triangular, clear, steps)``."""
    condition = _subdominant_condition(scheme)
    blocks, inner, outer = _split(scheme, rings, inner_rings)
    p_outer = _outer_charpoly(blocks, outer)
    constant = not p_outer.has(OMEGA)
    # lambda_1(n) is a root of condition(x, omega_n): it is an eigenvalue of the outer block only where the
    # resultant vanishes at a root of unity of order n >= 3
    outer_poly, frequency_one = sp.numer(sp.together(p_outer)), sp.numer(sp.together(condition))
    shared = sp.gcd(outer_poly, frequency_one) if constant else sp.Integer(1)
    if shared.has(X) and not shared.has(OMEGA) and sp.Poly(shared, X).monoms() == [(sp.Poly(shared, X).degree(),)]:
        # a root 0 shared for every omega (M(omega) singular): lambda_1, the root of largest modulus, is not it when the
        # frequency-1 polynomial keeps a nonzero root; the resultant then compares the other roots
        frequency_one = sp.cancel(frequency_one / shared)
    resultant = sp.resultant(outer_poly, frequency_one, X) if constant and frequency_one.has(X) else None
    # an edge rule in n puts n into the resultant: the roots of unity alone no longer decide it (the range decides)
    orders = root_of_unity_orders(sp.expand(resultant).subs(OMEGA, ZETA)) if resultant is not None and not resultant.has(N) else None
    # at a valence where the resultant vanishes, another root of the frequency-1 polynomial may be the outer
    # eigenvalue: look at lambda_1 itself there, exactly
    exceptions = [m for m in orders or () if m >= 3]
    clear = constant and sp.simplify(p_outer.subs(X, 1)) != 0 and orders is not None and all(
        sp.simplify(p_outer.subs(X, _lambda1_at(scheme, m))) != 0 for m in exceptions
    )
    steps = [Step(f"{rings}-ring: $\\det(xI - Y(\\omega))$ of the classes outside the {inner_rings}-ring", p_outer),
             Step(f"{rings}-ring: resultant in $x$ with $\\det(xI - E_1(\\omega))$ of the 1-ring (a root at $\\omega_n$ means "
                  "that an eigenvalue of frequency 1 at valence $n$ is an outer one)", sp.factor(resultant) if resultant is not None else None)]
    return _triangular(blocks, inner, outer), clear, steps


@claim(
    "1-ring suffices (after Eq. 51)",
    section="6",
    title="The 1-ring is sufficient for the continuous derivatives",
    statement=r"We restricted the range of our decomposition analysis to a one ring neighborhood. We showed that this "
    r"is sufficient for the computation of all the continuous derivatives.",
    requires=(NO_FREE_PARAMETERS,),
)
def _sufficient(scheme: Scheme) -> CheckResult:
    inner_rings = PRINTED_SUFFICIENT_RINGS
    proofs, steps = [], []
    for rings in (2, 3):
        triangular, clear, ring_steps = _outer_block_proof(scheme, rings, inner_rings)
        proofs.append((rings, triangular, clear))
        steps += ring_steps
    small = _rational_valences(scheme, 3)
    supports = [(v, rings, 1, _left_support(scheme, v, rings, 1, inner_rings)) for rings in (2,) for v in small]
    valence, lam1 = _regular_lambda1(scheme)
    supports += [(valence, rings, lam1, _left_support(scheme, valence, rings, lam1, inner_rings)) for rings in (2, 3)]
    leak = next((s for s in supports if s[3][1] is not None), None)
    if leak is not None:
        v, rings, value, (count, label) = leak
        return CheckResult(
            Status.REFUTED,
            Text("a left eigenvector of the ", rings, "-ring matrix for ", value, " is nonzero outside the ",
                 inner_rings, "-ring, so that neighbourhood does not determine the limit position and derivatives"),
            counterexample=Text(eq(N, v), ", the ", rings, "-ring matrix: a left eigenvector for the eigenvalue ", value,
                                " has a nonzero weight on the vertex ", tup(*label), ", outside the ", inner_rings, "-ring"),
            steps=tuple(steps),
        )
    if not all(t and c for _, t, c in proofs):
        return CheckResult(
            Status.VERIFIED,
            Text("the left eigenvectors of 1 (", N, " in ", sp.FiniteSet(*small), ") and of ", lambda_1, " (", eq(N, valence),
                 ") of the 2- and 3-ring matrices vanish outside the ", inner_rings, "-ring (exact); the proof for every ",
                 N, " does not go through for this scheme (block form not triangular, or the outer spectrum depends on the "
                 "frequency or meets 1 or ", lambda_1, ", or the rules depend on ", N, "); the scope is the valence where both "
                 "left eigenvectors were computed"),
            valences=(valence, valence),
            steps=tuple(steps),
        )
    return CheckResult(
        Status.PROVED,
        Text(
            "for every ", N, ": with the rings ordered from the centre out, the 2- and 3-ring matrices are block "
            "lower-triangular (no vertex of the 1-ring reads an outer vertex: the banded block form at symbolic ", OMEGA,
            "), and the outer block's eigenvalues are the same at every frequency and valence, never 1 and never ",
            lambda_1, " (the resultant with the 1-ring's frequency-1 polynomial vanishes at no primitive n-th root of unity, "
            "or only at valences where the outer eigenvalue it shares is not ", lambda_1,
            ", checked exactly); so the left eigenvectors of 1 and ", lambda_1,
            ", which give the limit position and the tangent plane, vanish outside the 1-ring. Exact left "
            "eigenvectors agree: of 1 at ", N, " in ", sp.FiniteSet(*small), " (2-ring), of ", eq(lambda_1, lam1), " at ", eq(N, valence),
            " (2- and 3-ring)",
        ),
        steps=tuple(steps),
    )


def _ring_growth(scheme: Scheme, rings: int) -> dict:
    """What the ``rings``-th ring adds to the ``(rings - 1)``-ring matrix, for every n: the new classes' block
    polynomial, its roots, the null columns among them, and whether the block form is triangular."""
    blocks, inner, outer = _split(scheme, rings, rings - 1)
    p_new = _outer_charpoly(blocks, outer)
    roots = sp.roots(sp.Poly(sp.numer(sp.together(p_new)), X)) if not p_new.has(OMEGA) else None
    return {"triangular": _triangular(blocks, inner, outer), "polynomial": p_new, "roots": roots,
            "new": [blocks.classes[q] for q in outer], "null": _null_classes(blocks, outer)}


def _rank_and_null_columns(scheme: Scheme, valence: int, rings: int) -> tuple:
    """``(size, rank, null columns, characteristic polynomial)`` of the exact ``rings``-ring matrix at ``valence``
    (FLINT rationals)."""
    import flint

    S = ring_subdivision_matrix(scheme, valence, rings)
    entries = S.entries(S.weight_values())
    M = flint.fmpq_mat(S.size, S.size)
    for (r, c), x in entries.items():
        M[r, c] = flint.fmpq(x.numerator, x.denominator)
    null = S.size - len({c for (_, c) in entries})
    return S.size, M.rank(), null, M.charpoly()


def _factor_holds(counts: dict, growth: dict, rings: int, valence: int) -> bool:
    """``det(xI - S_K) = det(xI - S_(K-1)) p(x)^n`` at ``valence``, exactly (p the new ring's block polynomial)."""
    import flint

    poly = sp.Poly(sp.expand(growth[rings]["polynomial"]), X)
    p = flint.fmpq_poly([to_fmpq(c) for c in reversed(poly.all_coeffs())])
    return counts[rings][3] == counts[rings - 1][3] * p**valence


def _growth_text(rings: int, g: dict) -> Text:
    # by modulus, then real and imaginary part (outer eigenvalues may be complex: a vertex rule with complex regular roots)
    nonzero = sorted((r for r in g["roots"] if r != 0), key=lambda r: (-abs(complex(r)), -complex(r).real, -complex(r).imag))
    nulls = Text(len(g["null"]) * N, " null columns")
    if not nonzero:
        return Text("ring ", rings, " adds only the eigenvalue 0 (", len(g["new"]) * N, " times) and ", nulls)
    return Text("ring ", rings, " adds the eigenvalues ", listed(nonzero), " (", len(g["new"]) * N, " eigenvalues with the "
                "zeros, the roots of ", g["polynomial"], " at every frequency) and ", nulls)


@claim(
    "Larger neighbourhoods (after Eq. 51)",
    section="6",
    title="A larger range only adds null columns",
    statement=r"Increasing the range might only increase the rank deficiency of the subdivision matrix by introducing "
    r"null columns.",
    requires=(NO_FREE_PARAMETERS,),
)
def _larger(scheme: Scheme) -> CheckResult:
    growth = {rings: _ring_growth(scheme, rings) for rings in (2, 3)}
    valence = _rational_valences(scheme, 1)[0]
    counts = {rings: _rank_and_null_columns(scheme, valence, rings) for rings in (1, 2, 3)}
    steps = tuple(
        Step(f"ring {rings}: $\\det(xI - Y(\\omega))$ of its {len(g['new'])} new vertex classes (null columns: "
             f"{len(g['null'])} classes)", g["polynomial"])
        for rings, g in growth.items()
    ) + (Step(f"size, rank and null columns of the 1-, 2-, 3-ring matrices at $n = {valence}$",
              sp.Matrix([list(counts[r][:3]) for r in (1, 2, 3)])),)
    if not all(g["triangular"] and g["roots"] is not None for g in growth.values()):
        return CheckResult(Status.UNDECIDED, "the block form of a larger ring is not triangular or its new block depends on "
                           "the frequency; the added eigenvalues are not the same for every n", steps=steps)
    added = {rings: {r for r in g["roots"]} for rings, g in growth.items()}
    wrong = [(rings, sorted(added[rings] - PRINTED_ADDED_EIGENVALUES, key=abs, reverse=True)) for rings in (2, 3)]
    wrong = [(rings, values) for rings, values in wrong if values]
    # a column can be null only if no new point reads the vertex; the printed statement: every new column is null
    not_null = [(rings, len(g["new"]) - len(g["null"])) for rings, g in growth.items() if len(g["null"]) < len(g["new"])]
    description = [_growth_text(rings, g) for rings, g in growth.items()]
    if not wrong and not not_null:
        return CheckResult(Status.PROVED, Text("for every ", N, ": the matrix is block lower-triangular ring by ring; ",
                                               description[0], "; ", description[1]), steps=steps)
    rings, values = wrong[0] if wrong else (not_null[0][0], [])
    size, rank, null, _ = counts[rings]
    if not _factor_holds(counts, growth, rings, valence):
        return CheckResult(Status.ERROR, f"the {rings}-ring characteristic polynomial at n = {valence} is not the product form")
    previous = counts[rings - 1]
    return CheckResult(
        Status.CORRECTED,
        Text("for every ", N, " the matrix is block lower-triangular ring by ring, so the ", rings, "-ring matrix has the "
             "eigenvalues of the ", rings - 1, "-ring matrix and those of the new ring's block: ", description[0], "; ",
             description[1]),
        scope=Scope.EVERY_N,
        counterexample=Text(eq(N, valence), ": exactly, ", eq(_det(X * _named("I") - _named(f"S_{rings}")),
                                                         _det(X * _named("I") - _named(f"S_{rings - 1}")) * sp.Symbol("p(x)") ** valence),
                            " with ", eq(sp.Symbol("p(x)"), growth[rings]["polynomial"]), ": the ", rings, "-ring matrix has the "
                            "added eigenvalues ", listed(values), " (", valence, " times each), rank ", rank, " of ", size,
                            " (the ", rings - 1, "-ring: ", previous[1], " of ", previous[0], ") and ", null, " null columns"),
        correction=Text("Increasing the range adds the eigenvalues of each new ring's block, not only null columns: ",
                        description[0], "; ", description[1], ". The dominant eigenvalues and their left eigenvectors stay "
                        "those of the 1-ring (claim '1-ring suffices')."),
        steps=steps,
    )


def _defective_example(scheme: Scheme, valence: int):
    """Vertex weights where ``E_0`` has a double eigenvalue ``mu`` with one eigenvector (one weight 0, the other solved
    from the discriminant), and the subdivision matrix there: ``(weights, mu, S)``, or ``None``."""
    from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial
    from symdecomp.analysis.tuning import with_free_vertex_rule
    from symdecomp.symbols import alpha as ALPHA
    from symdecomp.symbols import beta as BETA

    free = with_free_vertex_rule(scheme)
    E0 = closed_form_characteristic_polynomial(free).zero_frequency_matrix.subs(N, valence)
    for fixed, solved in ((ALPHA, BETA), (BETA, ALPHA)):
        E1 = E0.subs(fixed, 0)
        for value in sorted(sp.solve(sp.expand(E1.trace() ** 2 - 4 * E1.det()), solved), key=sp.default_sort_key):
            if not value.is_Rational:
                continue  # rational weights keep the exact rank computation fast
            E = E1.subs(solved, value)
            mu = sp.radsimp(sp.simplify(E.trace() / 2))
            if (E - mu * sp.eye(E.rows)).applyfunc(sp.simplify).is_zero_matrix:
                continue  # a multiple of the identity: double, but not defective
            weights = {fixed: 0, solved: value}
            return weights, mu, sp.Matrix(subdivision_matrix(free, valence)).subs(weights)
    return None


def _multiplicities_at(S: sp.Matrix, mu: sp.Expr) -> tuple[int, int]:
    """The algebraic and geometric multiplicities of ``mu`` in ``S``: in FLINT's rationals where both are rational (the
    characteristic polynomial divided by ``x - mu`` while it divides, the rank of ``S - mu I``), else by sympy."""
    import flint

    if not (sp.sympify(mu, strict=True).is_Rational and all(e.is_Rational for e in S)):
        algebraic = sp.roots(sp.Poly(sp.expand((X * sp.eye(S.rows) - S).det()), X)).get(mu, 0)
        return algebraic, S.rows - (S - mu * sp.eye(S.rows)).rank(simplify=True)
    F = flint.fmpq_mat([[to_fmpq(e) for e in row] for row in S.tolist()])
    m, linear, algebraic = to_fmpq(mu), flint.fmpq_poly([-to_fmpq(mu), 1]), 0
    poly = F.charpoly()
    while poly.degree() > 0 and poly(m) == 0:
        poly, algebraic = poly // linear, algebraic + 1
    return algebraic, S.rows - (F - m * flint.fmpq_mat(S.rows, S.rows, [1 if i == j else 0 for i in range(S.rows)
                                                                          for j in range(S.rows)])).rank()


@claim(
    "Tuning and multiplicities (after Eq. 51)",
    section="6",
    title="Tuning holds whatever the multiplicities",
    statement=r"Furthermore, this property holds regardless of any a priori knowledge of the underlying algebraic or "
    r"geometric multiplicity of the subdivision matrix.",
    requires=(FACE_NEIGHBOURS,),
)
def _multiplicities(scheme: Scheme) -> CheckResult:
    from symdecomp.analysis.charpoly import verify_closed_form
    from symdecomp.analysis.reduction import reduce_first_column, subdivision_block_form
    from symdecomp.analysis.tuning import with_free_vertex_rule
    from symdecomp.symbols import alpha as ALPHA
    from symdecomp.symbols import beta as BETA

    free = with_free_vertex_rule(scheme)
    E = reduce_first_column(subdivision_block_form(free)).lower_right.block_eigenvalue_matrix(zero_frequency=False)
    identity = all(verify_closed_form(free, k) for k in range(3, 9))
    if E.free_symbols & {ALPHA, BETA} or not identity:
        return CheckResult(
            Status.REFUTED,
            "the vertex weights enter a frequency other than 0, or det(xI - S) is not the product over the frequencies",
            counterexample=Text("for this scheme, ", _named("E_k"), " (", ne(sp.Symbol("k"), 0), ") is ", E,
                                " and the product form holds at n = 3..8: ", identity),
        )
    valence = 3
    example = _defective_example(scheme, valence)
    steps = [Step("$E_k$, $k \\ne 0$: free of $\\alpha, \\beta$", E)]
    shown = Text()
    if example is not None:
        weights, mu, Sm = example
        algebraic, geometric = _multiplicities_at(Sm, mu)
        if geometric < algebraic:
            steps.append(Step(f"$S$ at $n = {valence}$ and these weights: not diagonalizable", Sm))
            shown = Text("; at ", eq(N, valence), ", ", listed(eq(k, v) for k, v in sorted(weights.items(), key=str)), " the weights make ",
                         _named("E_0"), " a Jordan block for ", eq(sp.Symbol("mu"), mu), ", and ", _named("S"), " is not diagonalizable (",
                         mu, " has algebraic multiplicity ", algebraic, ", geometric ", geometric, "), while the other "
                         "eigenvalues are those of the frequencies ", ne(sp.Symbol("k"), 0), ", unchanged")
    return CheckResult(
        Status.PROVED,
        Text("the tuning property is an identity of characteristic polynomials, ",
             eq(sp.Function("det")(X * _named("I") - _named("S")), (X - 1) * sp.Function("det")(X * _named("I") - _named("E_0"))
                * sp.Product(sp.Function("det")(X * _named("I") - _named("E_k")), (sp.Symbol("k"), 1, N - 1))),
             " (Prop. 6.3 as corrected: a similarity, no eigenvectors used), with only ", _named("E_0"), " depending on ",
             sp.Symbol("alpha"), ", ", sp.Symbol("beta"), "; it holds for every ", N, " and, being polynomial in the "
             "weights, for all of them (exact at n = 3..8 with the weights free), whatever the multiplicities", shown),
        steps=tuple(steps),
    )
