"""Section 2 (Background): the circulant of Eq. 7 and its eigenvalues, Eq. 8 and Eq. 9, for every ``n``.

Each check is an identity in symbolic integers (valence ``n``, row ``r``, column ``s``, frequency ``k``,
index ``l``) that sympy reduces: the printed formulas are module attributes, so a changed formula changes
the verdict (tests/claims/test_mutations.py). None of these statements involves the scheme.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.claims.notation import eq, n
from symdecomp.claims.registry import CheckResult, Status, Step, Text, claim
from symdecomp.schemes.scheme import Scheme

ROW, COL, FREQ, IDX = sp.symbols("r s k l", integer=True)
CIRC = sp.IndexedBase("c")
Z = sp.Symbol("z")


def PRINTED_INDEX(r, s, n):
    """Eq. 7 as printed: entry ``(r, s)`` of ``circ(c_0, ..., c_{n-1})`` is ``c_{(s - r) mod n}``."""
    return sp.Mod(s - r, n)


def PRINTED_EIGENVALUE_TERM(l, k, n):
    """Eq. 8 as printed: term ``l`` of ``lambda_k`` is ``c_l exp(i 2 pi l k / n)`` (without ``c_l``)."""
    return sp.exp(sp.I * 2 * sp.pi * l * k / n)


def PRINTED_POLYNOMIAL_TERM(l, z):
    """Eq. 9 as printed: term ``l`` of ``p(z)`` is ``c_l z^l`` (without ``c_l``)."""
    return z**l


def _reduce(expr: sp.Expr) -> sp.Expr:
    """Simplify with ``Mod`` written through ``floor`` (``exp(2 pi i m) = 1`` for an integer ``m``)."""
    return sp.simplify(sp.expand(sp.simplify(expr.rewrite(sp.floor))))


def _omega_n() -> sp.Expr:
    return sp.exp(2 * sp.pi * sp.I / n)


@claim(
    "Eq. 7",
    section="2",
    reads_scheme=False,
    title="The circulant matrix",
    statement="$circ(c_0, \\dots, c_{n-1})$ has first row $(c_0, c_1, \\dots, c_{n-1})$, each row the previous one "
    "shifted right by one, last row $(c_1, c_2, \\dots, c_0)$.",
)
def _eq7(scheme: Scheme) -> CheckResult:
    shift = _reduce(PRINTED_INDEX(ROW + 1, COL + 1, n) - PRINTED_INDEX(ROW, COL, n))
    corners = {
        "first row, first column": (PRINTED_INDEX(0, 0, n), 0),
        "first row, last column": (PRINTED_INDEX(0, n - 1, n), n - 1),
        "last row, first column": (PRINTED_INDEX(n - 1, 0, n), 1),
        "last row, last column": (PRINTED_INDEX(n - 1, n - 1, n), 0),
        "second row, first column": (PRINTED_INDEX(1, 0, n), n - 1),
    }
    # n >= 3: Mod(1, n) is 1; sympy keeps it symbolic, so evaluate Mod of a constant below n explicitly.
    values = {key: _reduce(got.subs(sp.Mod(1, n), 1)) for key, (got, _) in corners.items()}
    wrong = [key for key, (_, want) in corners.items() if sp.simplify(values[key] - want) != 0]
    steps = (
        Step("Index of entry $(r+1, s+1)$ minus that of $(r, s)$, reduced for every $n$:", shift),
        *(Step(f"Index of the {key} entry:", values[key]) for key in corners),
    )
    if shift != 0 or wrong:
        what = Text("the shifted index differs by ", shift) if shift != 0 else Text("the ", wrong[0], " entry is ", CIRC[values[wrong[0]]])
        return CheckResult(Status.REFUTED, Text("the printed index ", PRINTED_INDEX(ROW, COL, n), " does not give the printed matrix"),
                           counterexample=what, steps=steps)
    return CheckResult(
        Status.PROVED,
        Text(
            "entry ", CIRC[PRINTED_INDEX(ROW, COL, n)], ": the index is unchanged when ", ROW, " and ", COL, " both increase by 1",
            " (so each row is the previous one shifted right), and the first row is ", CIRC[0], "..", CIRC[n - 1],
            ", the last row starts ", CIRC[1], " and ends ", CIRC[0], ", for every ", n,
        ),
        steps=steps,
    )


@claim(
    "Eq. 8",
    section="2",
    reads_scheme=False,
    title="The eigenvalues of a circulant",
    statement="The eigenvalue of $circ(c_0, \\dots, c_{n-1})$ on $v_k$ is $\\lambda_k = \\sum_{j=0}^{n-1} c_j e^{i 2\\pi jk/n}$.",
)
def _eq8(scheme: Scheme) -> CheckResult:
    index = PRINTED_INDEX(ROW, COL, n)
    # row r of C v_k is sum_s c_{index(r, s)} omega^{ks}; reindex by l = index(r, s), a bijection of Z/n (inverse s = l + r)
    inverse = _reduce(sp.Mod(index + ROW, n) - sp.Mod(COL, n))
    # term by term, omega^{ks} must be omega^{kr} times the printed term at l = index(r, s)
    w = _omega_n()
    ratio = _reduce(w ** (FREQ * COL) / (w ** (FREQ * ROW) * PRINTED_EIGENVALUE_TERM(index, FREQ, n)))
    steps = (
        Step("Row $r$ of $C v_k$, $l = (s - r) \\bmod n$ (Eq. 7):", sp.Sum(CIRC[index] * w ** (FREQ * COL), (COL, 0, n - 1))),
        Step("$l \\mapsto (l + r) \\bmod n$ inverts the reindexing (difference from $s \\bmod n$):", inverse),
        Step("$\\omega_n^{ks}$ divided by $\\omega_n^{kr}$ times the printed term at $l$:", ratio),
    )
    if inverse != 0 or ratio != 1:
        return CheckResult(
            Status.REFUTED,
            Text("row ", ROW, " of ", sp.Symbol("C v_k"), " is not ", w ** (FREQ * ROW), " times the printed sum"),
            counterexample=Text("the term of ", CIRC[IDX], " is off by the factor ", ratio, " (difference of the reindexing ", inverse, ")"),
            steps=steps,
        )
    return CheckResult(
        Status.PROVED,
        Text(
            "with ", eq(IDX, index), " (a bijection of the residues mod ", n, "), row ", ROW, " of ", sp.Symbol("C v_k"), " is ",
            w ** (FREQ * ROW), " times ", sp.Sum(CIRC[IDX] * PRINTED_EIGENVALUE_TERM(IDX, FREQ, n), (IDX, 0, n - 1)),
            ": the factor between the terms reduces to ", ratio, " (", sp.Symbol("exp(2 pi i m)"), " = 1 for an integer m), "
            "for every ", n, ", ", FREQ, " and ", ROW,
        ),
        steps=steps,
    )


@claim(
    "Eq. 9",
    section="2",
    reads_scheme=False,
    title="The generating polynomial",
    statement="$\\lambda_k$ of Eq. 8 is $p(\\omega_n^k)$ with $p(z) = c_0 + c_1 z + \\dots + c_{n-1} z^{n-1}$.",
)
def _eq9(scheme: Scheme) -> CheckResult:
    w = _omega_n()
    term = PRINTED_POLYNOMIAL_TERM(IDX, Z)
    difference = _reduce(sp.powsimp(term.subs(Z, w**FREQ), force=True) - PRINTED_EIGENVALUE_TERM(IDX, FREQ, n))
    steps = (
        Step("Term $l$ of $p(z)$ (without $c_l$):", term),
        Step("At $z = \\omega_n^k$, minus term $l$ of Eq. 8:", difference),
    )
    if difference != 0:
        return CheckResult(
            Status.REFUTED,
            Text("the polynomial at ", w**FREQ, " is not the sum of Eq. 8"),
            counterexample=Text("term ", IDX, " differs by ", difference),
            steps=steps,
        )
    return CheckResult(
        Status.PROVED,
        Text("term by term ", eq(term.subs(Z, sp.Symbol("omega_n") ** FREQ), PRINTED_EIGENVALUE_TERM(IDX, FREQ, n)),
             ", so ", eq(sp.Symbol("lambda_k"), sp.Function("p")(sp.Symbol("omega_n") ** FREQ)), " for every ", n, " and ", FREQ),
        steps=steps,
    )
