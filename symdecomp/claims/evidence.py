"""Computed evidence for the Section 5.1 claims: values at a valence, start points of components, certified
comparisons and iterations of the 1-ring (kept apart from the claims so that each module stays short)."""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.analysis.components import initial_vector_condition
from symdecomp.analysis.spectrum import recursion_eigenvalues
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import cos_jtheta as COS
from symdecomp.symbols import n, omega
from symdecomp.symbols import sin_jtheta as SIN

__all__ = ["at_valence", "number", "representative", "start_points", "dominant_vs_frequency_zero", "filtering_evidence",
           "complex_elliptic_pair"]

C = COS


def at_valence(expr, valence: int, j: int = 1):
    """``expr`` (in c = cos(j pi/n), s = sin(j pi/n), omega = omega_n^j) at a valence and frequency, exactly."""
    angle = sp.pi * sp.Rational(j, valence)
    return expr.subs({C: sp.cos(angle), SIN: sp.sin(angle), omega: sp.exp(2 * sp.I * angle), n: valence})


def number(expr, digits: int = 12):
    """A computed number, shown to ``digits`` digits (for reading; the verdicts are exact)."""
    return sp.N(expr, digits)


def representative(order: int, k: int = 1) -> tuple[int, int]:
    """The smallest valence ``n >= 3`` and the component ``j`` with ``omega_2n^j = exp(2 pi i k/order)``."""
    step = order // 2 if order % 2 == 0 else order
    valence = step * -(-3 // step)
    return valence, 2 * valence * k // order


def start_points(scheme: Scheme):
    """Every class of frequencies where a component starts on one eigenvector: one (n, j) per root of unity."""
    cond = initial_vector_condition(scheme)
    if cond.orders is None:
        return cond, None
    points = []
    for m in cond.orders:
        if m < 3:
            continue
        for k in range(1, m):
            if sp.gcd(k, m) == 1:
                points.append(cond.point(*representative(m, k)))
    return cond, points


def frequency_zero_others(scheme: Scheme) -> list:
    """The eigenvalues of the Eq. 43 block other than one eigenvalue 1, with multiplicity: a second 1 (1 not
    simple) stays in the list, where it is larger than every tangent-plane eigenvalue."""
    values = list(recursion_eigenvalues(scheme))
    if 1 in values:
        values.remove(1)
    return values


def dominant_vs_frequency_zero(scheme: Scheme, last: int) -> tuple[bool, int]:
    """Certify in interval arithmetic (Arb) that the derived dominant eigenvalue of M_1 exceeds the two
    derived eigenvalues of the Eq. 43 block other than 1, for n = 3..last.

    Returns ``(True, last)``, or ``(False, n)`` at the first ``n`` where it is certainly not larger;
    raises ``ArithmeticError`` where the balls overlap (undecided at this precision)."""
    from symdecomp.algebra.compile import compile_expression

    dominant = compile_expression(tangent_eigenvalues(scheme).dominant, (C,), engine="arb")
    block = [compile_expression(e, (n,), engine="arb") for e in frequency_zero_others(scheme)]
    with flint.ctx.workprec(128):
        for m in range(3, last + 1):
            lam1 = abs(dominant(flint.acb(flint.arb.cos_pi_fmpq(flint.fmpq(1, m)))))
            for f in block:
                mu = abs(f(flint.acb(m)))  # comparisons of balls are rigorous: true only when certain
                if lam1 > mu:
                    continue
                if lam1 <= mu:
                    return False, m
                raise ArithmeticError(f"n = {m}: lambda_1 and an Eq. 43 eigenvalue not separated at 128 bits")
    return True, last


def filtering_evidence(scheme: Scheme, valence: int):
    """``|1-ring after k steps| / lambda_1^k`` for the component j = n + 1 alone, k = 10, 20, 40 (60 digits)."""
    import mpmath

    from symdecomp.schemes.ring import OneRing, subdivide

    with mpmath.workdps(60):
        j = valence + 1
        pts = [mpmath.expjpi(mpmath.mpf(j * m) / valence) for m in range(2 * valence)]
        ring = OneRing.from_points((0, 0, 0), [(p.real, p.imag, 0) for p in pts[0::2]], [(p.real, p.imag, 0) for p in pts[1::2]])
        lam1 = mpmath.mpf(sp.N(at_valence(tangent_eigenvalues(scheme).dominant, valence), 70))
        ratios, current = [], ring
        for k in range(1, 41):
            current = subdivide(scheme, current)
            if k in (10, 20, 40):
                norm = mpmath.sqrt(mpmath.fsum(x**2 for p in current.a + current.b for x in p))
                ratios.append(sp.Float(mpmath.nstr(norm / lam1**k, 15), 15))
    return ratios


def larger_other_root(ev):
    """``(n, k, mu, lambda_1)`` at the first valence ``n <= 12`` where an eigenvalue ``mu`` of ``M_k`` is larger in modulus
    than ``lambda_1`` by more than ``1e-20`` (40 digits), or ``None``."""
    for m in range(3, 13):
        lam1 = sp.N(at_valence(ev.dominant, m), 40)
        for k in range(1, m):
            for root in (ev.dominant, ev.subdominant):
                mu = sp.N(root.subs(C, sp.cos(k * sp.pi / m)), 40)
                if abs(mu) > abs(lam1) + sp.Float("1e-20", 40):
                    return m, k, sp.N(mu, 12), sp.N(lam1, 12)
    return None


def other_root_result(ev, steps):
    """Prop. 5.1 when the trace of M_j is not positive on [-1, 1]: a larger other root at a small valence, or undecided."""
    from symdecomp.claims.notation import M as Mk
    from symdecomp.claims.notation import eq, lambda_1
    from symdecomp.claims.registry import CheckResult, Status, Text

    found = larger_other_root(ev)
    if found is not None:
        m, k, value, lam1 = found
        return CheckResult(
            Status.REFUTED,
            Text("the other eigenvalue of ", Mk(k), " is larger in modulus than ", lambda_1, " at ", eq(n, m)),
            counterexample=Text(eq(n, m), ", ", eq(sp.Symbol("k"), k), ": ", Mk(k), " has the eigenvalue ", value, ", ",
                                lambda_1, " = ", lam1),
            steps=steps,
        )
    return CheckResult(
        Status.UNDECIDED,
        Text("the trace of ", Mk("j"), " (", ev.trace, ") is not positive for every ", C, " in [-1, 1], so the other "
             "root of ", Mk("j"), " may exceed ", lambda_1, " in modulus; no valence n = 3..12 shows it"),
        steps=steps,
    )


def frequency_zero_refutation(ev, block, upto: int, steps):
    """Prop. 5.1 refuted at ``upto``: an eigenvalue of the Eq. 43 block (``block``) is at least ``lambda_1`` there."""
    from symdecomp.claims.notation import eq, lambda_1
    from symdecomp.claims.registry import CheckResult, Status, Text

    lam1 = number(at_valence(ev.dominant, upto))
    mus = [number(e.subs(n, upto)) for e in block]
    return CheckResult(
        Status.REFUTED,
        Text("at ", eq(n, upto), " an eigenvalue of the Eq. 43 block is at least ", lambda_1, " (certified in interval arithmetic)"),
        counterexample=Text(eq(n, upto), ": ", eq(lambda_1, lam1), ", the Eq. 43 eigenvalues other than 1 are ", sp.Matrix(mus).T),
        steps=steps,
    )


def complex_elliptic_pair(scheme: Scheme, lo: int, hi: int) -> tuple[int | None, bool]:
    """The first valence ``n >= lo`` where the Eq. 43 eigenvalues besides 1 are not two distinct reals (a complex pair
    or a double root: no real elliptic eigenvalue of its own), and whether the search covered every ``n >= lo``.

    Their quadratic's discriminant is a function of ``n``: when it is rational in ``n``, its sign is decided for every
    ``n >= lo`` (:func:`~symdecomp.algebra.valence_signs.positive_from`, Sturm sequences) and only the valences below its
    last real root are tried; otherwise the valences ``lo..hi`` are tried one by one (exact signs)."""
    from symdecomp.algebra.algebraic_sign import exact_sign
    from symdecomp.algebra.valence_signs import positive_from
    from symdecomp.analysis.frequency import recursion_matrix
    from symdecomp.errors import InvalidInputError

    x = sp.Symbol("x")
    chi = sp.Matrix(recursion_matrix(scheme, n)).charpoly(x).as_expr()
    quadratic = sp.quo(sp.Poly(sp.together(chi), x), sp.Poly(x - 1, x)).as_expr()
    disc = sp.cancel(sp.discriminant(quadratic, x))
    if disc.free_symbols - {n}:  # free parameters: no sign at a valence (the remark's own check handles them)
        return None, False
    try:
        if positive_from(disc, n, lo):
            return None, True
        numerator = sp.Poly(sp.numer(sp.together(disc)), n)
        roots = [r for r in numerator.real_roots() if r >= lo]
        last, every = (int(sp.ceiling(max(roots))) + 1 if roots else lo), True
    except InvalidInputError:  # cos(2 pi/n) in a weight: not rational in n
        last, every = hi, False
    for k in range(lo, max(lo, last) + 1):
        if exact_sign(disc.subs(n, k)) <= 0:
            return k, every
    return None, every
