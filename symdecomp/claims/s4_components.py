"""Section 4: Eq. 22 and Eq. 23, the staged rule Eq. 18 split by linearity into the components of Eq. 11.

Identities for every ``n``: a symbolic row ``i``, symbolic sums over the components ``j = 0..2n-1``, and
Laurent polynomials in the shift. The printed coefficients are module attributes (tests/claims/test_mutations.py).
The statements are steps of the paper's derivation from the printed Eq. 18 and do not involve the scheme.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.circulant import generating_polynomial, mode_eigenvalue_derivation
from symdecomp.claims.applicability import FACE_NEIGHBOURS
from symdecomp.claims.notation import n
from symdecomp.claims.registry import CheckResult, Status, Step, Text, claim
from symdecomp.claims.s4_one_ring import EQ18
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import omega

R = sp.Rational
I_, J_ = sp.symbols("i j", integer=True)
A_, B_ = sp.IndexedBase("a"), sp.IndexedBase("b")

#: Eq. 22 as printed: a_i -> 8/10 a_i + 1/10 (b_{i-1} + b_i), on the sums over the components (offsets of b).
PRINTED_EQ22 = (R(8, 10), {-1: R(1, 10), 0: R(1, 10)})
#: Eq. 23 as printed: a_i^j -> 8/10 a_i^j + 1/10 (b_{i-1}^j + b_i^j).
PRINTED_EQ23 = (R(8, 10), {-1: R(1, 10), 0: R(1, 10)})


def _rhs(printed, point) -> sp.Expr:
    """The right-hand side of a printed substitution at row ``i``; ``point(name, offset)`` is the point."""
    on_a, on_b = printed
    return on_a * point(A_, 0) + sp.Add(*[w * point(B_, k) for k, w in on_b.items()])


@claim(
    "Eq. 22",
    section="4",
    reads_scheme=False,
    title="Eq. 18 on the sums of the components",
    statement="Eq. 18 can be written $\\sum_j a_i^j \\rightarrow \\frac{8}{10}\\sum_j a_i^j + \\frac{1}{10}"
    "(\\sum_j b_{i-1}^j + \\sum_j b_i^j)$, $j = 0, \\dots, 2n-1$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq22(scheme: Scheme) -> CheckResult:
    on_a, on_b = PRINTED_EQ22
    difference = (sp.expand(on_a - EQ18.a), sp.expand(generating_polynomial(on_b) - EQ18.b), EQ18.o)
    steps = (
        Step("Eq. 22 on $a_i = \\sum_j a_i^j$ (Eq. 11), as shift polynomials, minus Eq. 18 (on the $a$'s, the $b$'s, $O$):",
             sp.Matrix(difference)),
    )
    if any(d != 0 for d in difference):
        return CheckResult(Status.REFUTED, Text("Eq. 22 is not Eq. 18 on the sums of the components"),
                           counterexample=Text("the differences on the a's, the b's and O: ", sp.Tuple(*difference)), steps=steps)
    return CheckResult(
        Status.PROVED,
        Text("with ", sp.Eq(A_[I_], sp.Sum(A_[I_, J_], (J_, 0, 2 * n - 1))), " (Eq. 11), Eq. 22 has the weights of Eq. 18: ",
             on_a, " on ", A_[I_], ", ", EQ18.b, " on the b's (shift polynomial), none on O, for every ", n),
        steps=steps,
    )


@claim(
    "Eq. 23",
    section="4",
    reads_scheme=False,
    title="Eq. 18 split into the components",
    statement="Eq. 22 decomposes into $a_i^j \\rightarrow \\frac{8}{10} a_i^j + \\frac{1}{10}(b_{i-1}^j + b_i^j)$, "
    "$i = 0, \\dots, n-1$, $j = 0, \\dots, 2n-1$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq23(scheme: Scheme) -> CheckResult:
    per_component = _rhs(PRINTED_EQ23, lambda base, k: base[I_ + k, J_])
    summed = sp.Sum(per_component, (J_, 0, 2 * n - 1)).expand()
    on_sums = _rhs(PRINTED_EQ22, lambda base, k: sp.Sum(base[I_ + k, J_], (J_, 0, 2 * n - 1))).expand()
    linear = sp.simplify(summed - on_sums)
    # a component: a_i^j = X w^i, b_i^j = Y w^i (omega = omega_n^j); the result stays one, row i divided by w^i free of i
    i = sp.Symbol("i", integer=True)
    X, Y = sp.symbols("X Y")
    on_a, on_b = PRINTED_EQ23
    _, eig_b = mode_eigenvalue_derivation(on_b)
    image = sp.expand(on_a * X + Y * eig_b)
    steps = (
        Step("The sum over $j$ of Eq. 23, minus Eq. 22:", linear, summed),
        Step("Eq. 23 on a component $a_i^j = X\\omega^i$, $b_i^j = Y\\omega^i$, divided by $\\omega^i$:", image),
    )
    if linear != 0 or image.has(i):
        what = Text("the sum over the components differs from Eq. 22 by ", linear) if linear != 0 else Text(
            "the image of a component depends on the row: ", image)
        return CheckResult(Status.REFUTED, Text("Eq. 23 does not decompose Eq. 22"), counterexample=what, steps=steps)
    return CheckResult(
        Status.PROVED,
        Text("summed over the components Eq. 23 is Eq. 22 (linearity, for every ", n, "), and it maps the component j to "
             "itself: amplitude ", image, " with ", sp.Eq(omega, sp.Symbol("omega_n") ** J_), ", "
             "free of the row ", i),
        steps=steps,
    )
