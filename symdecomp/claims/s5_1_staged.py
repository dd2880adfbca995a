"""Section 5.1 (Tangent plane properties), the staged rules in the frequency domain: Eq. 25-30 (the circulants of the
staged rules Eq. 17, 18, 20 and their eigenvalues) and Eq. 31-32 (the substitutions on ``A^j``, ``B^j`` they compose to).

The printed circulants are module attributes (tests/claims/test_mutations.py); the rest of Section 5.1 is in
:mod:`symdecomp.claims.s5_1_tangent`.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.circulant import mode_eigenvalue_derivation
from symdecomp.analysis.frequency import per_frequency_matrix
from symdecomp.claims.applicability import FACE_NEIGHBOURS
from symdecomp.claims.registry import CheckResult, Status, Step, Text, claim, is_zero
from symdecomp.claims.s4_one_ring import EQ17, EQ18, EQ19, EQ20, EQ21
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.shift_stencil import composed_stages
from symdecomp.symbols import n, omega

R = sp.Rational
S = sp.Symbol


#: The circulants of Eq. 25-30 as printed, as offsets (``c_{n-1}`` is offset -1).
PRINTED_CIRCULANTS = {
    "alpha": {0: R(3, 4), 1: R(1, 8), -1: R(1, 8)},
    "beta": {0: R(1, 2), -1: R(1, 2)},
    "gamma": {0: R(1, 2), 1: R(1, 2)},
}


@claim(
    "Eq. 25-30",
    section="5.1",
    reads_scheme=False,
    title="The three circulants of the staged rules",
    statement="The steps Eq. 17, 18, 20 involve $C_\\alpha = circ(3/4, 1/8, 0, \\dots, 0, 1/8)$, "
    "$C_\\beta = circ(1/2, 0, \\dots, 0, 1/2)$, $C_\\gamma = circ(1/2, 1/2, 0, \\dots, 0)$, with eigenvalues "
    "$\\lambda^\\alpha_j, \\lambda^\\beta_j, \\lambda^\\gamma_j$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq25_30(scheme: Scheme) -> CheckResult:
    printed = PRINTED_CIRCULANTS
    eig = {k: mode_eigenvalue_derivation(v)[1] for k, v in printed.items()}
    # the steps: Eq. 17 acts on the a's by C_alpha; Eq. 18 reads (b_{i-1} + b_i)/10 = (1/5) C_beta B; Eq. 20 reads
    # (a_i + a_{i+1})/3 = (2/3) C_gamma A.
    checks = [
        sp.expand(EQ17.a - eig["alpha"]),
        sp.expand(EQ18.b - R(1, 5) * eig["beta"]),
        sp.expand(EQ20.a - R(2, 3) * eig["gamma"]),
    ]
    ok = all(c == 0 for c in checks)
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        Text(
            "with circ's convention (entry ", S("c_s-r"), "), ", S("C_alpha"), " is Eq. 17, ", S("C_beta"), " (",
            S("c_0"), " = ", S("c_n-1"), " = ", R(1, 2), ") reads ", S("b_i"), " and ", S("b_i-1"), " as in Eq. 18, ",
            S("C_gamma"), " reads ", S("a_i"), " and ", S("a_i+1"), " as in Eq. 20; their eigenvalues from Prop. 2.1, for every ", n,
        ),
        counterexample=None if ok else Text("the differences ", sp.Tuple(*checks)),
        steps=tuple(Step(f"$\\lambda^\\{k}_j$ (Prop. 2.1, $\\omega = \\omega_n^j$):", v) for k, v in eig.items()),
    )


@claim(
    "Eq. 31-32",
    section="5.1",
    title="The substitutions on $A^j$ and $B^j$",
    statement="$A^j \\rightarrow \\frac58(\\frac45\\lambda^\\alpha_j A^j + \\frac15\\lambda^\\beta_j B^j)$ and "
    "$B^j \\rightarrow \\frac34(\\frac23\\lambda^\\gamma_j A^j + \\frac13 B^j)$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq31_32(scheme: Scheme) -> CheckResult:
    la = R(3, 4) + (omega + 1 / omega) / 8
    lb = (1 + 1 / omega) / 2
    lg = (1 + omega) / 2
    printed = sp.Matrix([[R(5, 8) * R(4, 5) * la, R(5, 8) * R(1, 5) * lb], [R(3, 4) * R(2, 3) * lg, R(3, 4) * R(1, 3)]])
    # the same from composing the staged rules Eq. 17-19 and Eq. 20-21 (O drops out for omega != 1)
    a, b = composed_stages((EQ17, EQ18, EQ19), (EQ20, EQ21))
    staged = sp.Matrix([[a.a, a.b], [b.a, b.b]])
    derived = per_frequency_matrix(scheme)
    ok = is_zero(printed - staged) and is_zero(staged - derived)
    return CheckResult(
        Status.PROVED if ok else Status.REFUTED,
        "the printed combinations equal the staged rules composed, and the matrix derived from Eq. 14-15, for every n"
        if ok else "the printed combinations are not the matrix derived from this scheme's rules",
        counterexample=None if ok else Text("printed minus derived: ", (printed - derived).applyfunc(sp.expand)),
        steps=(Step("Eq. 31-32 as a matrix on $(A^j, B^j)$:", printed), Step("Derived from the scheme's rules:", derived)),
    )
