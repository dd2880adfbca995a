"""Reif's spectral conditions for C1, certified per frequency in Arb (with exact steps where they decide).

The conditions (Reif 1995; Peters and Reif 2008) on the 2-ring subdivision matrix whose
eigenvectors generate the characteristic map (:mod:`symdecomp.analysis.characteristic`;
``(6n + 1)`` square on quads, ``(3n + 1)`` on triangles):

1. 1 is an eigenvalue, simple;
2. the next largest eigenvalue in modulus, ``lambda``, is real, of algebraic and geometric
   multiplicity 2, and strictly larger in modulus than every other eigenvalue.

The matrix is block-circulant, so its spectrum is the union over frequencies ``j`` of the
spectra of ``B_j``; each ``B_j`` is block lower triangular, so that is the union of the spectra
of the 1-ring blocks (:func:`~symdecomp.analysis.frequency.one_ring_matrices`: at ``j = 0`` the
Eq. 43 matrix, ``3 x 3`` on quads and ``2 x 2`` on triangles; otherwise ``M_j``, ``2 x 2`` or
``1 x 1``) and of the outer blocks ``S_j`` (the regular rules). The eigenvalues of ``M_j`` (and
those of ``M_{n-j} = conj(M_j)``) are enclosed from its characteristic polynomial. ``S_j`` holds
only the regular rules, and its characteristic polynomial is the same at every frequency of every
valence (:func:`~symdecomp.analysis.characteristic.outer_charpoly`, expanded once in symbolic
``omega``): its exact roots (Catmull-Clark ``1/8 .. 1/64``, Loop ``1/8, 1/16``) are the outer
eigenvalues everywhere, so a valence costs ``n / 2`` blocks of size 2 or 1 (linear in ``n``).
Were it not the same, each ``S_j`` would be bounded by ``||S_j^k||_inf^{1/k}`` (``k = 1, 2, 4``;
the tests keep that route as a check); the reported gap still uses those bounds where one may be
the largest other modulus (small ``n``). If ``lambda`` is a simple root of
``M_j`` for some ``0 < j < n/2`` and strictly dominates everything else, it has algebraic and
geometric multiplicity 2 (one eigenvector at ``j``, one at ``n - j``: the *conjugate-frequency
copy*, the same eigenvalue, which is why it is never compared with itself). ``lambda`` is real
when ``M_j``'s characteristic polynomial is real (exactly: Laurent polynomials in ``omega``
symmetric under ``omega -> 1/omega``) and, for ``2 x 2`` blocks, the discriminant is positive.

**Exact steps**, in the cyclotomic field ``Q(e^{2 pi i / 2n})``
(:mod:`symdecomp.algebra.cyclotomic`, which also holds Loop's ``cos(2 pi / n)`` weights):

* at ``j = 0`` the characteristic polynomial is ``(x - 1) q(x)``; a double root of ``q`` is
  found exactly, and its Jordan block by exact ranks when it is rational;
* a ``2 x 2`` block ``M_j`` (``j != 0``) whose discriminant ball holds 0 is tested for a double
  root exactly; a double root has multiplicity 4 with its conjugate-frequency copy (2 at
  ``j = n/2``), so as ``lambda`` it fails condition 2;
* two eigenvalues whose moduli cannot be separated by the balls (a *tie*) are compared exactly:
  the blocks' characteristic polynomials (for ``-lambda``: the other one at ``-x``) share a
  root, and the shared root is ``lambda`` when its ball misses the blocks' other roots. The
  same value at another frequency makes ``lambda``'s multiplicity larger than 2; ``-lambda``
  anywhere (another frequency, or the other root of ``lambda``'s block) means ``lambda`` is not
  strictly dominant. Both fail condition 2, and no precision would have separated them. A tie
  with a non-real eigenvalue of the same modulus is not decided exactly and stays
  ``undecided``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic, exact_entry, to_acb
from symdecomp.analysis.characteristic import (
    check_applicable,
    frequency_block,
    frequency_blocks,
    outer_bounds,
    outer_radius,
    outer_row_sum,
    ring_layout,
)
from symdecomp.analysis.defective import jordan_block_size
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify.result import C1Verdict

__all__ = ["block_root", "SpectralResult", "spectral_conditions", "ball_text", "float_down", "round_down", "real_at", "quadratic_roots",
           "exact_entry", "exact_charpoly", "frequency_zero_eigenvalues", "other_frequency_eigenvalues", "shared_root", "sibling_values"]

_X = sp.Symbol("x")


def ball_text(ball, digits: int = 6) -> str:
    """A ball as a short decimal (real part if the imaginary part may be 0)."""
    if isinstance(ball, flint.acb):
        if ball.imag.contains(0):
            ball = ball.real
        else:
            return f"{ball.real.str(digits, radius=False)} {'+' if ball.imag > 0 else '-'} {abs(ball.imag).str(digits, radius=False)}i"
    return ball.str(digits, radius=False)


def float_down(x: flint.arb) -> float:
    """A float ``<=`` every point of the ball ``x`` (its lower end, rounded down, not to nearest)."""
    value = float(x.lower())
    return value if flint.arb(value) <= x.lower() else math.nextafter(value, -math.inf)


def round_down(x: float, digits: int = 4) -> float:
    """``x > 0`` rounded *down* to ``digits`` significant digits, so that a lower bound stays one when printed.

    >>> round_down(0.27999076), round_down(0.25)
    (0.2799, 0.25)
    """
    scale = 10 ** (digits - 1 - math.floor(math.log10(x)))
    return math.floor(x * scale) / scale


def block_root(value: flint.acb, frequency: int, multiplicity: int, n: int | None = None, *, index: int = 0,
               conjugate: bool = False, defective: bool = False, double: bool = False) -> Eigenvalue:
    """A root of the frequency block ``j`` (a ball), the one eigenvalue type: ``multiplicity`` counts its copies in the full
    matrix (frequencies ``j`` and ``n - j``, both in ``frequencies`` when ``n`` is given and they differ); ``index``: 0 the
    larger root of the block in modulus; ``defective``: a Jordan block of size 2. The test reasons block by block, and
    roots of different blocks that tie are what it must examine."""
    frequencies = (frequency,) if n is None or 2 * frequency % n == 0 else (frequency, n - frequency)
    return Eigenvalue(value, "", multiplicity, frequencies=frequencies, index=index,
                      jordan=(2,) if defective else None, conjugate=conjugate, double=double)


@dataclass(frozen=True)
class SpectralResult:
    """The outcome of the spectral test at one valence."""

    n: int
    #: ``C1`` (the spectral conditions hold), ``NOT_C1`` or ``UNDECIDED``.
    status: C1Verdict
    reason: str
    #: The subdominant eigenvalue (``None`` if not determined).
    subdominant: Eigenvalue | None = None
    #: Lower bound of ``|lambda| - max |other eigenvalue|`` (``None`` unless ``status`` is ``C1``).
    gap: float | None = None
    #: Upper bound of the largest modulus of the other eigenvalues.
    second: float | None = None
    #: Whether 1 is a simple eigenvalue of the frequency-0 block (else nothing else was tested).
    one_simple: bool = True


@lru_cache(maxsize=32)
def _symbolic_charpoly(scheme: Scheme) -> tuple[sp.Expr, ...]:
    """The coefficients ``(c_1, .., c_k)`` of ``det(x - M(omega)) = x^k + c_1 x^(k-1) + ..`` (Laurent in omega, in n)."""
    M = one_ring_matrices(scheme)[0]
    if M.shape == (1, 1):
        return (sp.expand(-M[0, 0]),)
    return (sp.expand(-M.trace()), sp.expand(M.det()))


@lru_cache(maxsize=32)
def _asymmetry(scheme: Scheme) -> tuple[sp.Expr, ...]:
    """``c_i(omega) - c_i(1/omega)`` for the coefficients of :func:`_symbolic_charpoly`, expanded once per scheme."""
    return tuple(sp.expand(e - e.subs(OMEGA, 1 / OMEGA)) for e in _symbolic_charpoly(scheme))


def real_at(scheme: Scheme, n: int) -> bool:
    """Whether ``M_j``'s characteristic polynomial is real for every ``j`` (symmetric Laurent polynomials in omega)."""
    return all(e == 0 or sp.expand(e.subs(N, n)) == 0 for e in _asymmetry(scheme))


def quadratic_roots(t: flint.acb, d: flint.acb) -> tuple[flint.acb, flint.acb]:
    """The roots of ``x^2 - t x + d``, larger modulus first (midpoints; a double root gets two equal balls)."""
    disc = t * t - 4 * d
    if disc.real.contains(0) and disc.imag.contains(0):
        # near a double root: |sqrt(disc)| <= sqrt(|disc|), a far tighter ball than Arb's branch-cut-safe sqrt
        r = abs(disc).upper().sqrt().upper()
        root = flint.acb(flint.arb(0, r), flint.arb(0, r))
    elif disc.real < 0:
        root = flint.acb(0, 1) * (-disc).sqrt()  # away from the branch cut of sqrt: either root of disc will do
    else:
        root = disc.sqrt()
    a, b = (t + root) / 2, (t - root) / 2
    return (a, b) if abs(a).mid() >= abs(b).mid() else (b, a)


def _rational(x: Cyclotomic) -> sp.Rational | None:
    """``x`` as a rational, if it is one."""
    if x.poly.degree() > 0:
        return None
    c = x.poly.coeffs()[0] if x.poly.degree() == 0 else flint.fmpq(0)
    return sp.Rational(int(c.p), int(c.q))


def _charpoly(M: list[list[Cyclotomic]]) -> list[Cyclotomic]:
    """``[c_1, .., c_k]`` with ``det(x - M) = x^k + c_1 x^(k-1) + ..`` for ``k = 1, 2, 3`` (exact)."""
    k = len(M)
    if k == 1:
        return [-M[0][0]]
    minor = lambda a, b: M[a][a] * M[b][b] - M[a][b] * M[b][a]  # noqa: E731
    if k == 2:
        return [-(M[0][0] + M[1][1]), minor(0, 1)]
    det = (M[0][0] * minor(1, 2) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
           + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
    return [-(M[0][0] + M[1][1] + M[2][2]), minor(0, 1) + minor(0, 2) + minor(1, 2), -det]


def _frequency_zero_quotient(scheme: Scheme, n: int) -> tuple[list, list | None]:
    """``(p, q)``: the characteristic polynomial of the frequency-0 1-ring block (Eq. 43 on quads) and ``p / (x - 1)``.

    Coefficient lists as in :func:`_charpoly`, exact in ``Q(zeta_2n)``; ``q`` is ``None`` if 1 is not a root.
    """
    E0 = one_ring_matrices(scheme)[1]
    entries = [[exact_entry(x, n) for x in row] for row in E0.tolist()]
    if any(x is None for row in entries for x in row):
        raise NotApplicableError(
            f"scheme {scheme.name!r}: the C1 test needs rational weights at each valence (or rational in cos(2 pi k/n)); "
            f"at n = {n} the frequency-0 block is {sp.Matrix(E0).subs(N, n).tolist()}"
        )
    p = _charpoly(entries)
    q = [p[0] + 1]  # synthetic division by x - 1
    for c in p[1:-1]:
        q.append(c + q[-1])
    return p, (q if p[-1] + q[-1] == 0 else None)


def _ball(x: Cyclotomic) -> flint.acb:
    return to_acb(x, flint.ctx.prec)


def frequency_zero_eigenvalues(scheme: Scheme, n: int) -> tuple[list[Eigenvalue], str | None]:
    """The non-unit eigenvalues of the frequency-0 block (exact where it matters); a failure reason if 1 is not simple."""
    p, q = _frequency_zero_quotient(scheme, n)
    if q is None:
        return [], "1 is not an eigenvalue of the frequency-0 block (the rules are not affine)"
    if sum(q[1:], q[0] + 1) == 0:
        return [], "the eigenvalue 1 is not simple: it is a double root of the frequency-0 block (Eq. 43)"
    if len(q) == 1:
        return [block_root(-_ball(q[0]), 0, 1)], None
    b, c = q
    disc = b * b - 4 * c
    if disc == 0:
        mu = _rational(-b / 2)
        defective = mu is not None and jordan_block_size(scheme, n, mu) == 2  # Jordan blocks: rational roots only
        return [block_root(_ball(-b / 2), 0, 2, defective=defective)], None
    r1, r2 = quadratic_roots(-_ball(b), _ball(c))
    real = _rational(disc)
    pair = real is not None and real < 0  # a rational negative discriminant: conjugate roots
    if not pair and disc == disc.conjugate():  # real: conjugate roots iff negative
        pair = bool(_ball(disc).real < 0)
    return [block_root(r1, 0, 1, index=0, conjugate=pair), block_root(r2, 0, 1, index=1, conjugate=pair)], None


def other_frequency_eigenvalues(scheme: Scheme, n: int, *, outer: bool = True) -> tuple[list[Eigenvalue], list[tuple[int | None, flint.arb]]]:
    """The eigenvalues of ``M_j`` (``0 < j <= n/2``) and the bounds of the outer blocks ``S_j`` (none with ``outer=False``).

    The outer bound is one entry ``(None, radius)`` for every frequency when the outer block has the
    same eigenvalues at every frequency (:func:`~symdecomp.analysis.characteristic.outer_radius`), so
    only the 1-ring rows of each ``B_j`` are built; otherwise ``(j, ||S_j^k||^{1/k})`` for
    ``0 <= j <= n/2`` (:func:`~symdecomp.analysis.characteristic.outer_bounds`).
    """
    k1 = ring_layout(scheme.lattice).one_ring
    eigen = []
    real, blocks = real_at(scheme, n), frequency_blocks(scheme, n)
    for j in range(1, n // 2 + 1):
        B = blocks(j, k1)
        mult = 1 if 2 * j == n else 2
        if k1 == 1:
            eigen.append(block_root(B[0, 0], j, mult, n))
            continue
        t, d = B[0, 0] + B[1, 1], B[0, 0] * B[1, 1] - B[0, 1] * B[1, 0]
        disc = t * t - 4 * d
        if disc.real.contains(0) and disc.imag.contains(0) and _exact_discriminant_zero(scheme, n, j):
            eigen.append(block_root(t / 2, j, 2 * mult, n, double=True))  # exactly t/2, twice
            continue
        r1, r2 = quadratic_roots(t, d)
        pair = real and disc.real < 0  # real trace and determinant: the roots are conjugate
        eigen += [block_root(r1, j, mult, n, index=0, conjugate=pair), block_root(r2, j, mult, n, index=1, conjugate=pair)]
    if not outer:
        return eigen, []
    radius = outer_radius(scheme.lattice)
    return eigen, (outer_bounds(scheme, n) if radius is None else [(None, radius)])


def _gap_bounds(scheme: Scheme, n: int, outer: list, others: list[Eigenvalue]) -> list[flint.arb]:
    """The outer bounds the reported gap is measured against: the per-frequency norm bounds, as the gap has always been.

    With the exact outer eigenvalues (``(None, radius)``) the norm bounds are computed only where
    one of them may exceed every other 1-ring eigenvalue: not when an eigenvalue lies above
    :func:`~symdecomp.analysis.characteristic.outer_row_sum`, which bounds them all (large ``n``).
    """
    if not outer or any(j is not None for j, _ in outer):
        return [b for _, b in outer]
    top = max((abs(e.value).lower() for e in others), key=float, default=None)
    if top is not None and top > outer_row_sum(scheme.lattice) * (1 + flint.arb(2) ** -30):
        return []
    return [b for _, b in outer_bounds(scheme, n)]


def exact_charpoly(scheme: Scheme, n: int, j: int) -> tuple[Cyclotomic, ...] | None:
    """``(c_1, .., c_k)``: the block of frequency ``j`` has ``det(x - M_j) = x^k + c_1 x^(k-1) + ..``, exactly.

    The ``c_i`` lie in the cyclotomic field ``Q(zeta_2n)`` (exact: an element is 0 iff its
    reduced polynomial is). At ``j = 0`` the block is the quotient of the frequency-0 polynomial
    by ``x - 1``. ``None`` when a coefficient is not in the field.
    """
    if j == 0:
        q = _frequency_zero_quotient(scheme, n)[1]
        return None if q is None else tuple(q)
    out = tuple(exact_entry(e, n, j) for e in _symbolic_charpoly(scheme))
    return None if any(c is None for c in out) else out


def _exact_discriminant_zero(scheme: Scheme, n: int, j: int) -> bool:
    """Whether ``M_j`` (``2 x 2``) has a double root, exactly: ``c_1^2 - 4 c_2 = 0``."""
    p = exact_charpoly(scheme, n, j)
    return p is not None and len(p) == 2 and p[0] * p[0] - 4 * p[1] == 0


def shared_root(p1: tuple, p2: tuple):
    """A root common to the monic polynomials with coefficients ``p1``, ``p2`` (degree 1 or 2, exact).

    ``'all'`` if they are the same polynomial, a ball around the one shared root, or ``None`` if
    they share none. For different polynomials of degree <= 2 a shared root is a root of their
    difference (degree <= 1 after the leading terms cancel), tested exactly in the other one.
    """
    if len(p1) > len(p2):
        p1, p2 = p2, p1
    if len(p1) == len(p2) and all(a == b for a, b in zip(p1, p2)):
        return "all"
    if len(p1) == 1:  # x + c: the root -c
        root = -p1[0]
    else:  # (x^2 + a1 x + b1) - (x^2 + a2 x + b2) = (a1 - a2) x + (b1 - b2)
        if p1[0] == p2[0]:
            return None  # equal linear terms, different constants: no common root
        root = -(p1[1] - p2[1]) / (p1[0] - p2[0])
    value = root ** len(p2) + sum((c * root ** (len(p2) - 1 - i) for i, c in enumerate(p2)), root.field(0))
    return _ball(root) if value == 0 else None


def sibling_values(eigen: list[Eigenvalue], e: Eigenvalue) -> list[flint.acb]:
    return [x.value for x in eigen if x.frequency == e.frequency and x.index != e.index and not x.double]


def _exact_tie(scheme: Scheme, n: int, eigen: list[Eigenvalue], dom: Eigenvalue, e: Eigenvalue) -> str | None:
    """``'equal'`` if ``e`` is exactly ``dom``'s value, ``'opposite'`` if it is exactly ``-dom``, ``None`` if not shown.

    Exact in ``Q(e^{2 pi i / n})``: the blocks' characteristic polynomials (for ``-dom`` the one of
    ``e``'s block at ``-x``) share a root; the shared root is ``dom`` when its ball misses the
    blocks' other roots.
    """
    p, q = exact_charpoly(scheme, n, dom.frequency), exact_charpoly(scheme, n, e.frequency)
    if p is None or q is None:
        return None
    for kind, sign in (("equal", 1), ("opposite", -1)):
        qs = tuple(c * sign ** (i + 1) for i, c in enumerate(q))  # the roots of q times sign
        value = e.value * sign
        if not value.overlaps(dom.value):
            continue
        shared = shared_root(p, qs)
        if shared is None:
            continue
        others = sibling_values(eigen, dom) + [x * sign for x in sibling_values(eigen, e)]
        if shared == "all":
            if all(not x.overlaps(dom.value) for x in others):
                return kind
        elif shared.overlaps(dom.value) and all(not x.overlaps(shared) for x in others):
            return kind
    return None


def _ties(scheme: Scheme, n: int, eigen: list[Eigenvalue], dom: Eigenvalue, top: flint.arb):
    """The other eigenvalues whose modulus is not certainly below ``|dom|``, split by :func:`_exact_tie`."""
    # the conjugate of a non-real root of the same block has the same modulus: compare the pair as one
    others = [e for e in eigen if e is not dom and not (dom.conjugate and e.conjugate and e.frequency == dom.frequency)]
    close = [e for e in others if not abs(e.value) < top]
    kinds = {id(e): _exact_tie(scheme, n, eigen, dom, e) for e in close}
    split = {kind: [e for e in close if kinds[id(e)] == kind] for kind in ("equal", "opposite", None)}
    return [e for e in others if e not in close], split


def spectral_conditions(scheme: Scheme, n: int, *, one_ring: bool = False) -> SpectralResult:
    """Reif's spectral conditions at valence ``n``, certified (see the module docstring).

    ``one_ring``: the conditions on the 1-ring matrix alone (the blocks ``M_j`` and the frequency-0 block, no
    regular outer blocks), for any scheme: whether the frequency-1 eigenvalue is the subdominant eigenvalue of
    the 1-ring, which is what the limit and tangent masks need.
    """
    n = check_scheme(scheme).fitting_valence(n)  # the stencils fit, and every weight is defined and real at n
    if not one_ring:
        check_applicable(scheme)
    eigen, failure = frequency_zero_eigenvalues(scheme, n)
    if failure:
        return SpectralResult(n, C1Verdict.NOT_C1, failure, one_simple=False)
    more, outer = other_frequency_eigenvalues(scheme, n, outer=not one_ring)
    eigen += more
    dom = max(eigen, key=lambda e: abs(e.value).mid())
    top = abs(dom.value)
    others, ties = _ties(scheme, n, eigen, dom, top)
    for e in ties[None]:
        return SpectralResult(
            n, C1Verdict.UNDECIDED, f"the eigenvalues {ball_text(dom.value)} (frequency {dom.frequency}) and "
            f"{ball_text(e.value)} (frequency {e.frequency}) are not separated in modulus at this precision",
        )
    for j, bound in outer:
        if not bound < top:
            return _outer_failure(j, bound, top, n)
    if not top < 1:
        return SpectralResult(
            # Arb's ``>=`` holds only when every point of the ball is >= 1 (an exact -1 at frequency 0 is)
            n, C1Verdict.NOT_C1 if top >= 1 else C1Verdict.UNDECIDED,
            f"the eigenvalue {ball_text(dom.value)} at frequency {dom.frequency} is not smaller than 1 in modulus", dom,
        )
    failure = _tie_failure(dom, ties, n)
    if failure:
        return SpectralResult(n, C1Verdict.NOT_C1, failure, dom)
    second = max([abs(e.value) for e in others] + _gap_bounds(scheme, n, outer, others), key=lambda x: x.upper())
    gap = float_down((top - second).lower())
    if dom.conjugate:
        return SpectralResult(
            n, C1Verdict.NOT_C1, f"the largest eigenvalues after 1 are the complex conjugate pair {ball_text(dom.value)} at "
            f"frequency {dom.frequency}: the subdominant eigenvalue is not real", dom, gap, float(second.upper()),
        )
    if dom.frequency == 0 or 2 * dom.frequencies[0] == n:
        return SpectralResult(n, C1Verdict.NOT_C1, _symmetric_failure(eigen, dom, n), dom, gap, float(second.upper()))
    return _real_subdominant(scheme, n, dom, gap, float(second.upper()))


def _outer_failure(j: int | None, bound: flint.arb, top: flint.arb, n: int) -> SpectralResult:
    """The verdict when an outer block's eigenvalues are not certainly below ``|lambda|`` (``j = None``: every frequency)."""
    if j is None and bound > top:  # exact outer eigenvalues, the same at all n frequencies: that modulus n times
        return SpectralResult(
            n, C1Verdict.NOT_C1, f"the regular rules' outer blocks have an eigenvalue of modulus {ball_text(bound)} at every "
            f"frequency (multiplicity at least {n}), above every 1-ring eigenvalue after 1 (|lambda| = {ball_text(top)}): "
            "the subdominant eigenvalue does not have multiplicity 2",
        )
    where = "every frequency" if j is None else f"frequency {j}"
    return SpectralResult(
        n, C1Verdict.UNDECIDED, f"the outer eigenvalues at {where} are bounded only by {ball_text(bound)}, "
        f"not below |lambda| = {ball_text(top)}",
    )


def _tie_failure(dom: Eigenvalue, ties: dict, n: int) -> str | None:
    """Why exact ties make ``lambda`` fail: multiplicity above 2, or a different eigenvalue of the same modulus."""
    lam = ball_text(dom.value)
    if ties["equal"]:
        where = ", ".join(str(e.frequency) for e in [dom, *ties["equal"]])
        total = dom.multiplicity + sum(e.multiplicity for e in ties["equal"])
        return (f"the largest eigenvalue after 1, {lam}, is exactly the same at frequencies {where}: "
                f"multiplicity {total}, not 2")
    if dom.double and 0 < 2 * dom.frequencies[0] < n:
        return (f"the largest eigenvalue after 1, {lam}, is a double root of the frequency-{dom.frequency} block "
                f"(discriminant exactly 0), so with its copy at the conjugate frequency it has multiplicity {dom.multiplicity}, not 2")
    if ties["opposite"]:
        e = ties["opposite"][0]
        return (f"the largest eigenvalue after 1, {lam} (frequency {dom.frequency}), is not strictly dominant: "
                f"{ball_text(e.value)} (frequency {e.frequency}) is exactly its negative, of the same modulus")
    return None


def _symmetric_failure(eigen: list[Eigenvalue], dom: Eigenvalue, n: int) -> str:
    """Why a dominant eigenvalue at frequency 0 or ``n/2`` fails (its eigenvectors are the same up to sign in every sector)."""
    tangent = max((e for e in eigen if e.frequency == 1), key=lambda e: abs(e.value).mid())
    if dom.defective:
        what = "has algebraic multiplicity 2 but geometric multiplicity 1 (a Jordan block)"
    elif dom.multiplicity != 2:
        what = f"has multiplicity {dom.multiplicity}, not 2"
    else:
        what = (f"has multiplicity 2, but its eigenvectors repeat every {1 if dom.frequency == 0 else 2} sectors, so "
                "their characteristic map is not injective")
    return (f"the largest eigenvalue after 1 is {ball_text(dom.value)} at frequency {dom.frequency}, which {what}; it "
            f"exceeds the frequency-1 (tangent-plane) eigenvalue {ball_text(tangent.value)}")


def _real_subdominant(scheme: Scheme, n: int, dom: Eigenvalue, gap: float, second: float) -> SpectralResult:
    """The verdict once ``dom`` (frequency ``0 < j < n/2``) is strictly dominant: C1 iff it is certainly real and simple."""
    if dom.value.imag.contains(0) and real_at(scheme, n):
        B = frequency_block(scheme, n, dom.frequency)
        real = True
        if ring_layout(scheme.lattice).one_ring == 2:  # a real quadratic: real roots iff the discriminant is positive
            t, d = B[0, 0] + B[1, 1], B[0, 0] * B[1, 1] - B[0, 1] * B[1, 0]
            real = (t * t - 4 * d).real > 0
        if real:
            return SpectralResult(n, C1Verdict.C1, f"lambda = {ball_text(dom.value)} at frequency {dom.frequency}, real, "
                                  f"multiplicity 2, gap >= {round_down(gap)}", dom, gap, second)
    if not dom.value.imag.contains(0):
        return SpectralResult(n, C1Verdict.NOT_C1, f"the subdominant eigenvalue {ball_text(dom.value)} at frequency {dom.frequency} is not real", dom)
    return SpectralResult(n, C1Verdict.UNDECIDED, f"could not show that the subdominant eigenvalue {ball_text(dom.value)} is real and simple", dom)
