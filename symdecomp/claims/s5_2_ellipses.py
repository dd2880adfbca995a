"""Section 5.2, elliptic properties: the ellipse of the component ``A^1 + A^{2n-1}`` of the quad 1-ring's 2n-gon (Eq. 40,
its axes; Eq. 41, initially the same ellipse for the a- and the b-part). The rest of Section 5.2 is in
:mod:`symdecomp.claims.s5_2_elliptic`; the printed formulas are module attributes (tests/claims/test_mutations.py).
"""

from __future__ import annotations

import random

import sympy as sp

from symdecomp.analysis.ellipses import ellipse_axes
from symdecomp.claims import CheckResult, Status, Step, Text, claim, is_zero
from symdecomp.claims.applicability import FACE_NEIGHBOURS
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N

S = sp.Symbol


def PRINTED_AXES(w1: sp.Expr, w2: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """The axes of Eq. 40 as printed: ``l_1 = |w_1| + |w_(2n-1)|``, ``l_2 = ||w_1| - |w_(2n-1)||``."""
    return abs(w1) + abs(w2), abs(abs(w1) - abs(w2))


@claim(
    "Eq. 40",
    section="5.2",
    reads_scheme=False,
    title="Axes of the ellipse $E_a$",
    statement=r"$A^1 + A^{2n-1}$ is inscribed on an ellipse with axes "
    r"$l_1 = |w_1| + |w_{2n-1}|$, $l_2 = \bigl||w_1| - |w_{2n-1}|\bigr|$.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq40(scheme: Scheme) -> CheckResult:
    # The polygon is L(v_1) with L(zeta) = w1 zeta + w2 conj(zeta), a real-linear map of the plane;
    # it lies on L(unit circle), whose semi-axes are the singular values of L.
    p1, q1, p2, q2 = sp.symbols("p1 q1 p2 q2", real=True)
    # Real 2x2 matrix of L: zeta = x + i y -> (w1 + w2) x + i (w1 - w2) y.
    w1, w2 = p1 + sp.I * q1, p2 + sp.I * q2
    col_x = [sp.re(w1 + w2), sp.im(w1 + w2)]
    col_y = [sp.re(sp.I * (w1 - w2)), sp.im(sp.I * (w1 - w2))]
    L = sp.Matrix([[col_x[0], col_y[0]], [col_x[1], col_y[1]]])
    G = L.T * L
    l1, l2 = PRINTED_AXES(w1, w2)
    # sigma_1^2 + sigma_2^2 = tr G and sigma_1 sigma_2 = |det L|: the printed axes must have the same invariants.
    sum_sq = sp.simplify(sp.expand(G.trace() - (l1**2 + l2**2)))
    prod_sq = sp.simplify(sp.expand(L.det() ** 2 - (l1 * l2) ** 2))
    if not (is_zero(sum_sq) and is_zero(prod_sq)):
        return CheckResult(
            Status.REFUTED,
            "the singular values differ from the printed axes",
            counterexample=Text("invariants off by ", sum_sq, " and ", prod_sq),
        )
    # Cross-check on random rational 1-rings: Eq. 40 from the decomposition vs the singular values of [U W].
    rng = random.Random(5)
    worst = 0
    for n in (3, 4, 5, 6):
        ring = sp.Matrix(2 * n + 1, 3, lambda r, c: sp.Rational(rng.randint(-9, 9), rng.randint(1, 4)))
        e = ellipse_axes(ring, 1, digits=40)
        for a, b in zip(e.semi_axes, e.singular_values):
            worst = max(worst, abs(sp.N(a - b, 40)))
    if worst > sp.Float("1e-35"):
        return CheckResult(Status.ERROR, Text("decomposition and singular values disagree by ", worst))
    w_1, w_2, t = S("w_1"), S("w_2"), S("t", real=True)
    return CheckResult(
        Status.PROVED,
        Text(
            "the semi-axes of ", w_1 * sp.exp(sp.I * t) + w_2 * sp.exp(-sp.I * t), " are ", abs(w_1), " + ", abs(w_2),
            " and ", abs(abs(w_1) - abs(w_2)), " (singular-value invariants match identically); ", S("l_1"), ", ",
            S("l_2"), " are semi-axes (half-axes) for the unit-circumradius ", S("v_1"),
            "; random rings of valence 3 to 6 agree to 35 digits",
        ),
        steps=(
            Step("Real matrix of $\\zeta \\mapsto w_1\\zeta + w_2\\bar\\zeta$", L),
            Step("$\\operatorname{tr}(L^TL) - 2(|w_1|^2+|w_2|^2)$", sum_sq),
            Step("$\\det(L)^2 - (|w_1|^2-|w_2|^2)^2$", prod_sq),
        ),
    )


#: The factor taking the a-part ``z_1`` of the component to its b-part as printed (Eq. 24 at ``j = 1``).
PRINTED_B_FACTOR = sp.exp(sp.pi * sp.I / N)


@claim(
    "Eq. 41",
    section="5.2",
    reads_scheme=False,
    title="Initially $E_a = E_b$",
    statement=r"$A^1 = w_1 \vec{v_1}$, $A^{2n-1} = w_{2n-1}\vec{v_{n-1}}$; initially $E_a = E_b$, the ellipse of the "
    r"2n-gonal regular convex component of Eq. 11.",
    requires=(FACE_NEIGHBOURS,),
)
def _eq41(scheme: Scheme) -> CheckResult:
    # z_1 = p + i q (p, q in R^3). A-pair: U = 2p, W = -2q; B-pair: z_1 times the printed factor (Eq. 24).
    p = sp.Matrix(sp.symbols("p0:3", real=True))
    q = sp.Matrix(sp.symbols("q0:3", real=True))
    factor = sp.expand_complex(PRINTED_B_FACTOR.subs(N, S("n", positive=True, integer=True)))
    # the factor's real and imaginary parts as symbols c, s bound by c^2 + s^2 = |factor|^2 (simplified: a small
    # expression): each entry of G_b - G_a is reduced modulo that polynomial (a Groebner basis by itself), exact in
    # Q[p, q, c, s] where simplify's trigonometry on the entries took a second
    c, s = sp.symbols("c s", real=True)
    modulus = sp.simplify(sp.re(factor) ** 2 + sp.im(factor) ** 2)
    zb_re = p * c - q * s
    zb_im = p * s + q * c
    gram_a = 4 * (p * p.T + q * q.T)
    gram_b = 4 * (zb_re * zb_re.T + zb_im * zb_im.T)
    diff = (gram_b - gram_a).applyfunc(lambda e: sp.reduced(sp.expand(e), [s**2 + c**2 - modulus], s, c)[1])
    if not is_zero(diff):
        return CheckResult(Status.REFUTED, Text(S("E_b"), " differs from ", S("E_a")), counterexample=Text(diff))
    U, W, t = S("U"), S("W"), S("t")
    return CheckResult(
        Status.PROVED,
        Text(
            "an ellipse ", U * sp.cos(t) + W * sp.sin(t), " is fixed by its matrix ", U * S("U^T") + W * S("W^T"),
            "; for the b-part (", S("z_1"), " times ", PRINTED_B_FACTOR, ", a rotation) it is identical for every ring and ", N,
        ),
        steps=(Step("$G_b - G_a$ (zero)", diff),),
    )
