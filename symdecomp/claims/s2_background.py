"""Section 2 (Background): Eq. 1, Eq. 2-6 and Proposition 2.1."""

from __future__ import annotations

import random

import sympy as sp

from symdecomp.algebra.circulant import circ, generating_polynomial, mode_eigenvalue_derivation
from symdecomp.algebra.polygons import decompose
from symdecomp.claims.notation import eq, ge, j, listed, lt, n, ne, omega_n
from symdecomp.claims.registry import CheckResult, LazySteps, Status, Step, Text, claim
from symdecomp.schemes.scheme import Scheme

W = sp.Symbol("w")
M = sp.Symbol("m", integer=True)
PHI = sp.Symbol("phi", real=True)


def _random_polygon(n: int, seed: int) -> sp.Matrix:
    rng = random.Random(seed)
    return sp.Matrix([[sp.Rational(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(3)] for _ in range(n)])


def PRINTED_VERTEX(j, m, n):
    """Entry ``(j, m)`` of ``F_n`` as printed (Eq. 2-3): ``omega_n^(j m)``."""
    return sp.exp(2 * sp.pi * sp.I * j * m / n)


def PRINTED_ORDER(n):
    """The order of the root of unity in ``F_n`` as printed (Eq. 3): ``omega_n^n = 1``."""
    return n

#: The sign in the real pair ``R cos(phi) -+ I sin(phi)`` of Eq. 6 (``-`` as printed).
PRINTED_PAIR_SIGN = -1


def _special_polygons(size: int) -> dict[str, sp.Matrix]:
    """Exact n-gons of the kinds Eq. 1 allows: collapsed, degenerate, self-intersecting."""
    collapsed = sp.Matrix([[sp.Rational(1, 2), -3, 2]] * size)
    repeated = sp.Matrix([[0, 0, 0] if m < 2 else [m, m * m % 5, 1] for m in range(size)])  # two vertices coincide
    collinear = sp.Matrix([[m % 3, 2 * (m % 3), 3 * (m % 3)] for m in range(size)])  # on a line, back and forth
    crossing = sp.Matrix([[m % 2, (m // 2) % 2, sp.Rational(m, size)] for m in range(size)])  # edges that cross
    return {"collapsed": collapsed, "repeated vertex": repeated, "collinear": collinear, "self-intersecting": crossing}


def _first_not_rebuilt(last: int):
    """The first ``(n, kind, P)`` of :func:`_special_polygons` not rebuilt exactly from its decomposition (a collapsed
    polygon must have no component but ``j = 0``), or ``None``."""
    for size in range(3, last + 1):
        for kind, P in _special_polygons(size).items():
            dec = decompose(P)
            exact = dec.reconstruct() == P
            if kind == "collapsed":
                exact &= all(all(z == 0 for z in zs) for zs in dec.amplitudes[1:])
            if not exact:
                return size, kind, P
    return None


def _singular_basis(last: int):
    """The first ``(n, m, m')`` with equal nodes ``x_m = x_m'`` of the printed rows (columns ``m, m'`` of ``F_n``)."""
    for size in range(3, last + 1):
        nodes = [PRINTED_VERTEX(1, m, size) for m in range(size)]
        for m in range(size):
            for m2 in range(m + 1, size):
                if sp.simplify(nodes[m2] / nodes[m]) == 1:
                    return size, m, m2, nodes[m]
    return None


def _not_a_basis() -> CheckResult:
    """Eq. 1's verdict when the printed rows are not shown to be a basis for every n: refuted at the first valence
    whose rows share two nodes (:func:`_singular_basis`), undecided if none up to 12 does."""
    from symdecomp.symbols import n

    x_m = sp.Symbol("x_m")
    found = _singular_basis(12)
    if found is None:
        return CheckResult(Status.UNDECIDED, Text("the rows are not shown to be a basis for every ", n,
                                                  ", and they are for n = 3..12"))
    size, m, m2, value = found
    gon = tuple(1 if k == m else 0 for k in range(size))
    return CheckResult(
        Status.REFUTED,
        Text("the rows ", sp.Symbol("v_j"), " of ", sp.Symbol("F_n"), " as printed are not a basis of ", sp.Symbol("C^n"),
             " for every ", n, ": not every n-tuple decomposes"),
        counterexample=Text(eq(n, size), ": vertices ", m, " and ", m2, " of every row are equal (", eq(x_m, value),
                            " for both), so every combination of the rows has ", eq(sp.Symbol(f"p_{m}"), sp.Symbol(f"p_{m2}")),
                            ", and the degenerate polygon ", sp.Tuple(*gon), " has no decomposition"),
    )


@claim(
    "Eq. 1",
    section="2",
    reads_scheme=False,
    title="An $n$-gon is any $n$-tuple of points",
    statement="An $n$-gon is an $n$-tuple $P = (p_0, \\dots, p_{n-1})$ of points of $\\mathbf{R}^3$, with no restriction on "
    "their positions: it may intersect itself, degenerate, or collapse to a single point (and the decomposition of "
    "Section 2 applies to it).",
)
def _eq1(scheme: Scheme) -> CheckResult:
    from symdecomp.symbols import n

    d = sp.Symbol("d", integer=True, positive=True)
    e = sp.Symbol("e", integer=True, positive=True)  # n = d + e: 0 < d < n
    node = lambda m: PRINTED_VERTEX(1, m, n)  # noqa: E731
    vandermonde = sp.simplify(sp.powsimp(PRINTED_VERTEX(j, M, n) / node(M) ** j, force=True)) == 1
    ones = sp.simplify(PRINTED_VERTEX(0, M, n)) == 1
    ratio = sp.powsimp(node(M + d) / node(M), force=True)
    turn = sp.simplify(ratio.args[0] / (2 * sp.pi * sp.I)) if isinstance(ratio, sp.exp) else None
    distinct = turn is not None and not turn.has(M) and all(
        sp.simplify(x.subs(n, d + e)).is_positive for x in (turn, 1 - turn)
    )
    x_m = sp.Symbol("x_m")
    if not (vandermonde and ones and distinct):
        return _not_a_basis()
    last, kinds = 12, tuple(_special_polygons(3))
    if (failed := _first_not_rebuilt(last)) is not None:
        size, kind, P = failed
        return CheckResult(Status.REFUTED, Text("a ", kind, " polygon is not rebuilt exactly"),
                           counterexample=Text(eq(n, size), ", the ", kind, " polygon ", P.T))
    return CheckResult(
        Status.PROVED,
        Text(
            "entry ", M, " of the row ", sp.Symbol("v_j"), " of ", sp.Symbol("F_n"), " is ", x_m**j, " with the node ",
            eq(x_m, node(M)), ": a Vandermonde matrix; two nodes differ by the turn ", turn, " with ", ge(d, 1), " and ",
            lt(d, n), ", never an integer, so the nodes are distinct and ", sp.Symbol("F_n"), " is invertible for every ",
            n, ": every n-tuple has one decomposition, whatever its vertices; a collapsed polygon is ", sp.Symbol("p v_0"),
            " (", eq(sp.Symbol("v_0"), sp.Tuple(1, sp.Symbol("..."), 1)), "); exact decompositions of "
            + ", ".join(kinds) + " polygons rebuilt exactly for n = 3..",
            last, ", the collapsed ones with ", eq(sp.Symbol("z_j"), 0), " for every ", ne(j, 0),
        ),
        steps=LazySteps(lambda: (  # the displayed forms are simplified again: only when the steps are read
            Step("Row $j$ over the $j$-th power of the node $x_m$ of column $m$ (Vandermonde):",
                 sp.powsimp(PRINTED_VERTEX(j, M, n) / node(M) ** j, force=True)),
            Step("Ratio of the nodes of columns $m + d$ and $m$, $0 < d < n$:", sp.simplify(ratio)),
            Step("Its turn, free of $m$, strictly between 0 and 1:", turn),
        )),
    )


@claim(
    "Eq. 2-4",
    section="2",
    reads_scheme=False,
    title="The rows of $F_n$ are regular planar polygons",
    statement="The rows $v_0, \\dots, v_{n-1}$ of $F_n$ (Eq. 2), $\\omega_n = e^{2\\pi i/n}$ (Eq. 3), are regular planar $n$-gons.",
)
def _eq2_4(scheme: Scheme) -> CheckResult:
    from symdecomp.symbols import j, n

    vertex = PRINTED_VERTEX(j, M, n)
    step = sp.simplify(vertex.subs(M, M + 1) / vertex)
    modulus = sp.simplify(sp.Abs(vertex))
    ok = not step.has(M) and modulus == 1
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        Text(
            "vertex ", M, " of ", sp.Symbol("v_j"), " is ", vertex, " = ", omega_n ** (j * M), ": all on the unit circle "
            "(modulus ", modulus, "), each obtained from the previous by the same rotation ", step, " = ", omega_n**j,
            ", for every ", n, " and ", j, " (", sp.Symbol("v_0"), " is a point; ", sp.Symbol("v_n/2"),
            " for even ", n, " is a segment traversed back and forth)",
        ),
        counterexample=None if ok else Text("ratio ", step, ", modulus ", modulus),
        steps=(
            Step("Vertex $m$ of $v_j$:", vertex),
            Step("Ratio of consecutive vertices, free of $m$:", step),
            Step("Modulus:", modulus),
        ),
    )


@claim(
    "Eq. 5",
    section="2",
    reads_scheme=False,
    title="Decomposition into planar regular polygons",
    statement="Every $n$-gon $P$ in $\\mathbf{R}^3$ is $P = z_0 v_0 + \\dots + z_{n-1} v_{n-1}$ with the rows "
    "$v_j$ of $F_n$ (Eq. 4) a basis of $\\mathbf{C}^n$.",
)
def _eq5(scheme: Scheme) -> CheckResult:
    from symdecomp.symbols import n

    geometric = sp.summation(W**M, (M, 0, n - 1))
    general = geometric.args[-1][0] if isinstance(geometric, sp.Piecewise) else geometric
    reduced = sp.simplify(general.subs(W ** PRINTED_ORDER(n), 1))
    if reduced != 0:
        return CheckResult(
            Status.REFUTED, Text("the sum of ", W**M, " does not vanish: ", reduced), counterexample=Text(reduced)
        )
    last = 12
    F_n = sp.Symbol("F_n", commutative=False)
    for size in range(3, last + 1):
        P = _random_polygon(size, seed=size)
        if decompose(P).reconstruct() != P:
            return CheckResult(
                Status.REFUTED, Text("reconstruction failed at ", eq(n, size)), counterexample=Text(eq(n, size), ": ", P)
            )
    return CheckResult(
        Status.PROVED,
        Text(
            eq(F_n * sp.adjoint(F_n), n * sp.Symbol("I", commutative=False)), " for every ", n,
            " (geometric sum with ", eq(W**n, 1), ", ", ne(W, 1), "), so the ", sp.Symbol("v_j"), " are a basis; "
            "exact reconstruction of random rational polygons checked for ", n, f" from 3 to {last}",
        ),
        steps=(
            Step("Entry $(k, l)$ of $F_n \\overline{F_n}^T$ is a geometric sum in $w = \\omega_n^{k-l}$:", geometric, sp.Sum(W**M, (M, 0, n - 1))),
            Step("For $k \\ne l$, $w \\ne 1$ and $w^n = 1$, so it vanishes:", reduced, general),
            Step("Hence $F_n^{-1} = \\overline{F_n}^T / n$ and $z_j = \\frac{1}{n}\\sum_m p_m \\omega_n^{-jm}$.", None),
        ),
    )


@claim(
    "Eq. 6",
    section="2",
    reads_scheme=False,
    title="Coplanar pairs",
    statement="The decomposition of Eq. 5 can be chosen so that the pairs $\\{z_j v_j, z_{n-j} v_{n-j}\\}$, "
    "$j = 1, \\dots, \\lfloor (n-1)/2 \\rfloor$, are coplanar.",
)
def _eq6(scheme: Scheme) -> CheckResult:
    r, s = sp.symbols("r s")
    pair = sp.Symbol("R") * sp.cos(PHI) + PRINTED_PAIR_SIGN * sp.Symbol("I") * sp.sin(PHI)
    two_regular = sp.exp(sp.I * PHI) * (r + sp.I * s) / 2 + sp.exp(-sp.I * PHI) * (r - sp.I * s) / 2
    identity = sp.simplify(sp.expand((two_regular - (r * sp.cos(PHI) + PRINTED_PAIR_SIGN * s * sp.sin(PHI))).rewrite(sp.cos)))
    if identity != 0:
        return CheckResult(Status.REFUTED, "identity fails", counterexample=Text("the difference ", identity))
    import mpmath

    worst = mpmath.mpf(0)
    with mpmath.workdps(50):
        for size in range(3, 11):
            P = mpmath.matrix([[mpmath.mpf(x) for x in row] for row in _random_polygon(size, seed=100 + size).tolist()])
            d = decompose(P)
            for j in range(1, (size - 1) // 2 + 1):
                first, second = d.planar_pair(j)
                Q = d.pair_polygon(j)
                for m_, (p, q) in enumerate(zip(first.vertices(), second.vertices())):
                    worst = max(worst, max(abs(p[k] + q[k] - Q[m_, k]) for k in range(3)))
        ok = worst < mpmath.mpf(10) ** -45
    if not ok:
        return CheckResult(
            Status.REFUTED,
            Text("pair reconstruction off by ", sp.Float(worst, 15)),
            counterexample=Text("a vertex of a random polygon rebuilt from its pairs off by ", sp.Float(worst, 15)),
        )
    R_, I_ = sp.Symbol("R"), sp.Symbol("I")
    return CheckResult(
        Status.PROVED,
        Text(
            "the real pair ", pair, " lies in ", sp.Function("span")(R_, I_), " and equals the regular polygons of "
            "amplitudes ", listed(((r + sp.I * s) / 2, (r - sp.I * s) / 2)), " in one orthonormal frame of that plane "
            "(identity in ", PHI, "); random polygons of ", n, " = 3 to 10 vertices rebuilt from the pairs to 45 digits "
            "(max deviation ", sp.Float(worst, 3), ")",
        ),
        steps=(
            Step("The pair $z_j v_j + z_{n-j} v_{n-j}$ of a real polygon, with $R = 2\\,\\mathrm{Re}\\,z_j$, $I = 2\\,\\mathrm{Im}\\,z_j$:", pair),
            Step("In an orthonormal frame of $\\mathrm{span}(R, I)$, with $r, s$ the complex coordinates of $R, I$:", two_regular),
            Step("minus $r\\cos\\varphi - s\\sin\\varphi$ simplifies to", identity),
        ),
    )


def PRINTED_EIGENVALUE(coeffs):
    """Prop. 2.1 as printed: the eigenvalue on ``v_k`` is ``p(omega_n^k)``, ``p(z) = sum_l c_l z^l``."""
    return generating_polynomial(coeffs)


@claim(
    "Proposition 2.1",
    section="2",
    reads_scheme=False,
    title="Eigenvectors and eigenvalues of circulants",
    statement="The eigenvectors of any $n \\times n$ circulant $C$ are the rows of $F_n$; the eigenvalue on $v_k$ "
    "is $p(\\omega_n^k)$ with $p(z) = c_0 + c_1 z + \\dots + c_{n-1} z^{n-1}$ (Eq. 8, 9).",
)
def _prop21(scheme: Scheme) -> CheckResult:
    from symdecomp.symbols import omega

    coeffs = {k: sp.Symbol(f"c_{{{k}}}") for k in range(-2, 3)}
    row, eig = mode_eigenvalue_derivation(coeffs)
    expected = PRINTED_EIGENVALUE(coeffs)
    if sp.expand(eig - expected) != 0 or eig.has(sp.Symbol("i", integer=True)):
        return CheckResult(Status.REFUTED, "eigenvalue depends on the row", counterexample=Text("the eigenvalue ", eig))
    last = 10
    i_, p_ = sp.Symbol("i"), sp.Function("p")
    C_, v_ = sp.Symbol("C", commutative=False), sp.Symbol("v", commutative=False)
    for size in range(3, last + 1):
        cs = sp.symbols(f"c0:{size}")
        C = circ(cs)
        v = sp.Matrix([omega**m for m in range(size)])
        p = sum(cs[k] * omega**k for k in range(size))
        residual = (C * v - p * v).applyfunc(lambda e: sp.rem(sp.expand(e), omega**size - 1, omega))  # noqa: B023 (applied at once)
        if any(x != 0 for x in residual):
            return CheckResult(
                Status.REFUTED, Text("fails at ", eq(n, size)), counterexample=Text(eq(n, size), ": residual ", residual)
            )
    return CheckResult(
        Status.PROVED,
        Text(
            "row ", i_, " of ", C_ * sp.Symbol("v_j", commutative=False), " is ", omega_n ** (i_ * j) * p_(omega_n**j),
            " at a symbolic row ", i_, " (any ", n, " larger than the band width, symbolic ", sp.Symbol("c_k"),
            f"); general symbolic circulants of order 3 to {last}: ",
            eq(C_ * v_ - p_(W) * v_, 0), " modulo ", W**n - 1,
        ),
        steps=(
            Step("Row $i$ of $C v_j$ for a circulant with diagonals $-2..2$, $\\omega = \\omega_n^j$:", row),
            Step("Divided by $\\omega^i$ it is free of $i$: the generating polynomial (Eq. 9)", eig, sp.Symbol("p(omega)")),
        ),
    )
