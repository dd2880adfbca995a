"""The distinct eigenvalues of a certified spectrum and their multiplicities, proved; or a closed form refuted.

Every certificate (:mod:`symdecomp.verify.certify`, :mod:`symdecomp.verify.structural`) proves first that
a set of eigenvalues is the spectrum with multiplicities; this module proves on top which of them are
equal, whatever the neighbourhood:

* from an exact characteristic polynomial ``chi_S``: its squarefree part gives the number of distinct
  eigenvalues, and Arb balls of the claimed values fall into as many disjoint clusters
  (:func:`separate_or_refute`, doubling the precision); a factorization over ``Q`` gives them outright
  (:func:`factored_values`); with algebraic centre weights ``chi_S = det(lambda I - E_0) R(lambda)``
  is split and each root of ``E_0`` tested exactly against ``R`` (:func:`distinct_count`);
* without ``chi_S`` (the O(n) routes): from the frequency factors, their clusters disjoint and the roots
  in each equal by an exact argument (:func:`cluster_multiplicities`).

Where the claimed values are not the spectrum, a rigorous reason names one (:func:`refute`): its Arb
enclosure ``v`` makes every squarefree factor of ``chi_S`` a ball that excludes 0, or more values lie in
an isolating ball of a root than that root's multiplicity.
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.clusters import overlap_groups
from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.algebra.numbers import to_fmpq, to_fraction
from symdecomp.analysis.charpoly import frequency_factors
from symdecomp.analysis.eigenvalue import ClosedFormLabel
from symdecomp.analysis.frequency import RingBlocks
from symdecomp.analysis.spectrum import acb_text, format_value
from symdecomp.schemes.rings import CENTRE_WEIGHTS
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA

__all__ = ["separate_or_refute", "refute", "value_text", "describe_labels", "factored_values", "distinct_count",
           "cluster_multiplicities", "squarefree_degree", "largest_first",
           "disjoint"]

def separate_or_refute(cf, n, subs, chi, squarefree, identity, digits, max_prec):
    """``(balls, clusters, prec, refutation)``: the closed forms as Arb balls, doubling the precision.

    When the identity holds, until the balls fall into as many clusters as ``chi_S`` has
    distinct roots; otherwise until one closed form is rigorously refuted. Either way at most
    up to ``max_prec`` bits.
    """
    labels = cf.eigenvalue_labels(n)
    prec, refutation = 128, None
    while True:
        balls = cf.values(n, subs, engine="arb", prec=prec)
        clusters = _clusters(balls)
        if identity:
            done = len(clusters) == sum(f.degree() for f, _ in squarefree)
        else:
            with flint.ctx.workprec(prec):
                refutation = refute(chi, squarefree, balls, labels, n, digits)
            done = refutation is not None
        if done or prec >= max_prec:
            return balls, clusters, prec, refutation
        prec *= 2


def _mid_abs(z):
    return float(abs(z.mid()).mid())


def _mid_re(z):
    return float(z.real.mid())


def largest_first(clusters: list[list[int]], balls) -> list[list[int]]:
    """The clusters of ``balls`` (lists of indices) by decreasing modulus, then real part, of their first ball."""
    return sorted(clusters, key=lambda cl: (-_mid_abs(balls[cl[0]]), -_mid_re(balls[cl[0]])))


def value_text(ball, digits):
    import mpmath

    with mpmath.workdps(digits + 5):
        re = mpmath.mpf(ball.real.mid().str(digits + 5, radius=False))
        im = mpmath.mpf(0) if ball.imag.contains(0) else mpmath.mpf(ball.imag.mid().str(digits + 5, radius=False))
        value = re if im == 0 else mpmath.mpc(re, im)
        return format_value(value, digits)


def _clusters(balls) -> list[list[int]]:
    """Connected components of the overlap graph of the balls (equal values always overlap)."""
    return overlap_groups(balls, lambda a, b: a.overlaps(b), key=lambda b: float(b.real.lower()),
                          beyond=lambda a, b: b.real.lower() > a.real.upper())


def describe_labels(labels: list[ClosedFormLabel]) -> str:
    kinds = sorted({lab.label for lab in labels})
    ks = sorted({lab.frequency for lab in labels})
    return f"{'; '.join(kinds)}; k = {', '.join(map(str, ks))}"


def _nearest(squarefree, v) -> str:
    """``"; the nearest eigenvalue is ... at distance ..."``, from a rigorous root isolation."""
    product = flint.fmpz_poly(1)
    for f, _ in squarefree:
        product *= f
    roots = [r for r, _ in product.complex_roots()]
    if not roots:
        return ""
    best = min(roots, key=lambda r: float(abs(r - v).mid()))
    distance = abs(best - v)
    return f"; the nearest eigenvalue is {value_text(best, 25)}, at distance {distance.mid().str(3, radius=False)}"


def refute(chi, squarefree, balls, labels, n, digits) -> str | None:
    """A rigorous reason why the closed forms are not the spectrum, or ``None`` (at ``flint.ctx.prec``)."""
    polys = [flint.acb_poly([flint.acb(c) for c in f.coeffs()]) for f, _ in squarefree]
    # (a) a closed-form value at which every squarefree factor of chi_S is certainly nonzero
    # is not an eigenvalue
    for i, v in enumerate(balls):
        if all(not p(v).contains(0) for p in polys):
            return (
                f"n = {n}: closed-form eigenvalue {value_text(v, digits)} ({describe_labels([labels[i]])}) is not an eigenvalue of "
                f"the full matrix: chi_S(v) != 0 (certified){_nearest(squarefree, v)}"
            )
    # (b) more closed-form values in an isolating ball of a root than its multiplicity. The
    # roots of the squarefree part are isolated together, so each ball holds exactly one
    # eigenvalue; a closed-form value inside it is that eigenvalue or no eigenvalue at all.
    product = flint.fmpz_poly(1)
    for f, _ in squarefree:
        product *= f
    if product.degree() < 1:
        return None
    roots = [ball for ball, _ in product.complex_roots()]
    mids = [flint.acb(r.mid()) for r in roots]
    radii = [r.rad() for r in roots]
    for i, ball in enumerate(roots):
        owners = [e for (f, e), p in zip(squarefree, polys) if p(ball).contains(0)]
        if len(owners) != 1:
            continue
        # a square around the root that meets no other isolating ball holds no other eigenvalue
        separation = min(
            ((abs(mids[i] - mids[j]) - 2 * radii[j]).lower() for j in range(len(roots)) if j != i),
            default=flint.arb(1),
        )
        half_side = flint.arb(separation.mid() / 2)
        if not half_side > 2 * radii[i]:
            continue
        square = flint.acb(flint.arb(ball.real.mid(), half_side), flint.arb(ball.imag.mid(), half_side))
        inside = [k for k, v in enumerate(balls) if square.contains(v)]
        if len(inside) > owners[0]:
            return (
                f"n = {n}: {len(inside)} closed-form eigenvalues lie at the eigenvalue {value_text(ball, digits)} "
                f"({describe_labels([labels[k] for k in inside])}), whose multiplicity in the full matrix is {owners[0]} (certified)"
            )
    return None


def factored_values(chi: flint.fmpq_poly, digits: int) -> tuple[int, tuple[int, ...], tuple[str, ...]]:
    """``(distinct, multiplicities, texts)`` from the exact factorization of ``chi``, largest modulus first."""
    _, factors = chi.factor()
    roots = []
    with flint.ctx.workprec(4 * digits + 64):
        for f, e in factors:
            roots += [(r, e) for r, _ in f.numer().complex_roots()]
    roots.sort(key=lambda t: (-float(abs(t[0]).mid()), -float(t[0].real.mid())))
    return len(roots), tuple(e for _, e in roots), tuple(acb_text(r, digits) for r, _ in roots)


def squarefree_degree(p: flint.fmpq_poly) -> int:
    return sum(f.degree() for f, _ in p.numer().factor_squarefree()[1])


def distinct_count(scheme, blocks, n, chis, free, fixed) -> int | None:
    """The number of distinct eigenvalues, exactly, or ``None`` if it cannot be decided."""
    if not free:
        return squarefree_degree(chis[0])
    # chi_S = det(l - E_0) R(l): R from the weight-free frequencies, exactly over Q
    weights = {**fixed, **{s: sp.Integer(0) for s in free}}
    E0 = blocks.frequency_zero_matrix(n, symbolic_weights=True).xreplace(weights)
    f0 = sp.Poly((LAM * sp.eye(E0.shape[0]) - E0).det(method="berkowitz"), LAM)
    R, rem = divmod(chis[0], flint.fmpq_poly([to_fmpq(c) for c in reversed(f0.all_coeffs())]))
    if rem != 0:  # pragma: no cover - the identity was proved above
        return None
    field = CyclotomicField(2 * n)
    roots = []
    v = scheme.vertex_rule
    actual = {CENTRE_WEIGHTS[1]: v.each_a, CENTRE_WEIGHTS[2]: v.each_b}
    for f in frequency_factors(blocks).zero:
        if f.roots is None:
            return None
        for r in f.roots:
            try:
                value = cyclotomic_value(sp.sympify(r, strict=True).xreplace(actual), {N: n}, field=field)
            except ValueError:
                return None
            roots += [value] * f.exponent
    new = []
    for r in roots:
        if any((r - x).poly == 0 for x in new):
            continue
        acc = field(0)
        for c in reversed(R.coeffs()):
            acc = acc * r + field(to_fraction(c))
        if acc.poly != 0:
            new.append(r)
    return squarefree_degree(R) + len(new)


def cluster_multiplicities(scheme: Scheme, blocks: RingBlocks, spectrum) -> str | None:
    """Prove that the Arb clusters of ``spectrum`` are its distinct eigenvalues with their multiplicities.

    Returns ``None`` when proved, else the reason it could not be. Two parts:

    * *distinct*: the hulls of any two clusters are disjoint balls (checked in Arb), so values
      in different clusters differ;
    * *equal*: the roots inside each cluster are equal, by one of two exact arguments:
      (a) they are one root of one factor at a frequency ``k`` (repeated by the factor's
      exponent), or of a factor written in ``c_k = cos(2 pi k/n)`` at ``k`` and ``n - k``, where
      the factor is the same polynomial (one root from each: the other root at ``n - k`` equal
      to it lies in this cluster since clusters are disjoint); (b) every root has a closed form
      that is exact in ``Q(zeta_2n)`` there, and they are equal in that field.
    """
    n = spectrum.n
    entries = spectrum.eigenvalues
    if any(not e.members for e in entries):
        return "the spectrum does not list its clusters' roots"
    if not disjoint([e.value for e in entries]):
        return "two clusters of Arb balls overlap"
    ff = frequency_factors(blocks)
    field = None
    for e in entries:
        roots = sorted(set(e.members))
        if _same_root_by_symmetry(roots, ff, n):
            continue
        field = field or CyclotomicField(2 * n)
        values = [_root_value(scheme, ff, n, member, field) for member in roots]
        if any(v is None for v in values):
            return f"equality of the roots near {e.text} is not decidable exactly (no closed form in Q(zeta_{2 * n}))"
        if any((v - values[0]).poly != 0 for v in values[1:]):
            return f"the roots clustered near {e.text} are not all equal (exact)"
    return None


def _same_root_by_symmetry(roots, ff, n: int) -> bool:
    """Argument (a) of :func:`cluster_multiplicities` for distinct ``(k, factor, root)`` triples."""
    ks, factors = {k for k, _, _ in roots}, {i for _, i, _ in roots}
    if len(factors) != 1 or len(roots) != len(ks):  # one factor, one root per frequency
        return False
    if len(ks) == 1:
        return True
    k = min(ks)
    (i,) = factors
    return k != 0 and ks == {k, n - k} and not ff.other[i].poly.has(OMEGA)


def _root_value(scheme: Scheme, ff, n: int, member, field):
    """The exact value of root ``j`` of factor ``i`` at frequency ``k`` in ``Q(zeta_2n)``, or ``None``."""
    from symdecomp.analysis.factor_roots import centre_values, exact_root

    k, i, j = member
    f = (ff.zero if k == 0 else ff.other)[i]
    if f.roots is None:
        return None
    exact_w, _ = centre_values(scheme, n)
    try:
        return cyclotomic_value(exact_root(f.roots[j], k, n, exact_w), field=field)
    except ValueError:
        return None


def disjoint(balls) -> bool:
    """Whether the (complex) balls are pairwise disjoint; candidates by a sweep on the real parts, decided in Arb."""
    spans = sorted(((float(b.real.mid()) - float(b.real.rad()), float(b.real.mid()) + float(b.real.rad()), b) for b in balls),
                   key=lambda t: t[0])
    margin = 1e-9
    for a, (_, hi, b) in enumerate(spans):
        for lo2, _, b2 in spans[a + 1:]:
            if lo2 > hi + margin * max(1.0, abs(hi)):
                break
            if b.overlaps(b2):
                return False
    return True
