"""Synthetic claims that exercise the LaTeX layout: long sums, wide matrices, awkward text."""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from symdecomp import catmull_clark, per_frequency_matrix, subdivision_matrix, tangent_eigenvalues
from symdecomp.claims import CheckResult, Claim, Status, Step, Text
from symdecomp.symbols import alpha, beta, n, omega

x, y = sp.symbols("x y")


def long_sum():
    """A sum far wider than a line (several hundred em when printed on one line)."""
    return sp.expand((x + y + omega + 1 / n + alpha) ** 5)


def long_product():
    """A product of long sums over a long denominator: breaks inside the factors."""
    return sp.Mul(sp.expand((x + y + omega + 2) ** 3), sp.expand((alpha + beta + n) ** 3), evaluate=False) / sp.expand((n + 3) ** 6)


@lru_cache(maxsize=1)
def stress_pairs() -> tuple[tuple[Claim, CheckResult], ...]:
    cc = catmull_clark()
    m_j = per_frequency_matrix(cc)
    tangent = tangent_eigenvalues(cc)
    wide = sp.Matrix(3, 3, lambda r, c: sp.expand((omega ** (r - c) + alpha + r) ** 2 / (r + c + 2)))
    cases = [
        (
            "Eq. 901", "2", "A long sum_with & special % characters # and $\\omega_n^j$ inline",
            "The sum $S = \\sum_{k} s_k$ is long; 100% of a_i & b_i are ~ counted ^ here {ok}.",
            CheckResult(
                Status.PROVED, "the identity vanishes (50% faster) & is_zero",
                steps=(
                    Step("A very long sum, broken across lines:", long_sum(), sp.Symbol("S")),
                    Step("A long product over a long denominator:", long_product(), sp.Symbol("P")),
                    Step("As an equation:", sp.Eq(sp.Symbol("T"), long_sum() - 3)),
                ),
            ),
        ),
        (
            "Eq. 902", "4", "Matrices of all sizes",
            "$M_j$ of Eq. 33 and the $9 \\times 9$ subdivision matrix at $n = 4$.",
            CheckResult(
                Status.VERIFIED, "exact arithmetic", valences=(3, 64),
                steps=(
                    Step("The per-frequency matrix:", m_j, sp.Symbol("M_j")),
                    Step("A 3x3 matrix with long entries:", wide, sp.Symbol("W")),
                    Step("The subdivision matrix at $n = 4$:", subdivision_matrix(cc, 4), sp.Symbol("S")),
                    Step("At $n = 12$ (25 columns):", subdivision_matrix(catmull_clark(alpha, beta), 12), sp.Symbol("S")),
                    Step("Mapping of eigenvalues:", {sp.Symbol("lambda_1"): tangent.dominant, sp.Symbol("lambda_2"): tangent.subdominant}),
                ),
            ),
        ),
        (
            "Proposition 5.9", "5.1", "Piecewise, Abs, sqrt and complex numbers",
            "Refuted claim with unicode ω ≤ 1 — ☃ and a long inline formula "
            "$" + sp.latex(sp.expand((x + y + 1) ** 4)) + "$ inside the text.",
            CheckResult(
                Status.REFUTED, Text("the defect is ", sp.sqrt(long_sum()) / (n + 3), ", not 0 (a long formula in a box)"),
                counterexample="at $n = 4$, $j = 2$ the ratio is $0/0$ (100% degenerate)",
                steps=(
                    Step("Piecewise:", sp.Piecewise((x**2, x > 0), (sp.Abs(x), True)), sp.Symbol("f")),
                    Step("Complex:", (1 + sp.I) / sp.sqrt(5) + sp.sqrt(2) * sp.I),
                    Step("A tuple:", tuple(sp.expand((x + k) ** 6) for k in range(1, 4))),
                    Step("Only words, no formula."),
                ),
            ),
        ),
        (
            "Eq. 950", "5.2", "Corrected claim\n\nwith a title over two paragraphs", "As printed: $1 - \\alpha - \\beta$.",
            CheckResult(
                Status.CORRECTED, "the row sums to $1 + (n-1)(\\alpha + \\beta)$",
                correction="the centre weight is $1 - n\\alpha - n\\beta$",
                steps=(Step("Characteristic polynomial:", tangent.characteristic_polynomial, sp.Symbol("p") ),),
            ),
        ),
        (
            "Eq. 960", "6", "Numeric, long words and awkward objects", "A numeric one.",
            CheckResult(
                Status.NUMERIC,
                "agrees with T=[[1,-1/2],[2,1/3],[4,5/7],[9,9/10],[11,12/13]] for n=3..16 via "
                "symdecomp.analysis.frequency.per_frequency_matrix_at_every_valence_and_frequency_index",
                digits=30,
                steps=(
                    Step("Eigenvalues with multiplicities:", sp.Matrix([[2, 1], [0, 2]]).eigenvals()),
                    Step("A long left-hand side and a wide matrix:", subdivision_matrix(cc, 10),
                         sp.Symbol("S") + sp.Symbol("T") * sp.Symbol("U") + sp.Symbol("V") ** 2 + sp.Symbol("W")),
                    Step("An inequality:", sp.Lt(long_sum(), sp.oo)),
                ),
            ),
        ),
        ("Remark 6.1 (b)", "6", "Same anchor as Remark 6.1 b", "Text.", CheckResult(Status.PROVED, "trivially")),
        ("Remark 6.1 b", "6", "Same anchor as Remark 6.1 (b)", "Text.", CheckResult(Status.PROVED, "trivially")),
        ("Remark 6.1", "6", "A check that crashed", "Text.", CheckResult(Status.ERROR, "check raised ZeroDivisionError: division by zero")),
    ]
    pairs = []
    for order, (label, section, title, statement, result) in enumerate(cases):
        c = Claim(label, section, title, statement, check=lambda r=result: r, order=order)
        pairs.append((c, result))
    return tuple(pairs)
