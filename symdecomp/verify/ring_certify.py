"""Certified check of a K-ring spectrum for any scheme: the full matrix against the frequency factors.

The claim is that the spectrum of the full ``K``-ring matrix ``S`` (built by exact refinement,
:func:`~symdecomp.schemes.rings.ring_subdivision_matrix`, no block structure) is, with
multiplicities, the union of the spectra of ``E_0`` and of ``E(omega_n^k)``, ``k = 1..n-1``
(:func:`symdecomp.analysis.frequency.ring_blocks`), whose factored characteristic polynomials give the
closed forms and isolated roots of :func:`symdecomp.analysis.spectrum.ring_spectrum`. It is the identity

    chi_S(lambda) = det(lambda I - E_0) prod_{k=1}^{n-1} det(lambda I - E(omega^k)),

proved exactly, as in :mod:`symdecomp.verify.certify`: ``chi_S`` by FLINT from the matrix; for a
rational ``lambda_0`` the product over the roots of unity is a resultant,
``prod_k Q(omega^k) = Res(1 + omega + ... + omega^{n-1}, Q)`` with ``Q = omega^m det(lambda_0 I - E(omega))``
(sign ``(-1)^{m(n-1)}``); both sides are monic of degree ``size``, so equality at ``size``
points ``lambda_0 = 0, 1, ...`` is equality.

*Algebraic centre weights* (Loop's ``cos(2 pi/n)``). Only row 0 holds them, and both sides are
affine in them (a determinant is linear in a row; ``E_0``'s first row is linear in them too).
So the identity is proved for the weights as free symbols, at ``1 + (number of weights)``
affinely independent rational points (0 and each unit vector): it then holds for the actual
weights, whatever they are. No floating point is involved.

*Multiplicities.* With rational weights the squarefree part of ``chi_S`` gives the number of
distinct eigenvalues; the Arb balls of the spectrum must fall into as many clusters. With
algebraic weights, ``chi_S = det(lambda I - E_0) R(lambda)`` with ``R`` (the other frequencies)
rational: the distinct roots of ``R`` come from its squarefree part, and each root of ``E_0``
in ``Q(zeta_2n)`` is tested exactly for being a root of ``R`` (or of another root of ``E_0``).
The ``O(n)`` structural certificate (:func:`structural_certificate`) has no ``chi_S``; it
certifies multiplicities from the frequency factors instead (:func:`cluster_multiplicities`).
The product identity itself is computed in one place,
:func:`~symdecomp.analysis.charpoly.product_identity` (also behind ``charpoly``).

>>> from symdecomp.schemes.loop import loop
>>> c = certify_ring(loop(), 7, 1)
>>> c.status.value, c.distinct, c.multiplicities, c.multiplicities_certified
('agree', 5, (1, 2, 2, 1, 2), True)
"""

from __future__ import annotations

from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.algebra.numbers import to_fmpq, to_fraction, to_sympy
from symdecomp.analysis.charpoly import frequency_factors, product_identity
from symdecomp.analysis.frequency import RingBlocks, ring_blocks
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.rings import CENTRE_WEIGHTS, ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_limit, check_valence
from symdecomp.verify.certify import Certificate
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["certify_ring", "structural_certificate"]


def certify_ring(scheme: Scheme, n: int, rings: int = 1, *, blocks: RingBlocks | None = None, digits: int = 20,
                 method: str = "charpoly") -> Certificate:
    """Prove (or refute, exactly) that the frequency factors give the spectrum of the full ``rings``-ring matrix.

    ``blocks``: the block form under test (default: the derived one; tests pass a wrong one).
    ``method``: ``"charpoly"`` (the identity above, dense FLINT characteristic polynomials) or
    ``"structure"`` (:func:`structural_certificate`: ``O(n)``, for large valences).
    """
    n, digits = check_limit(check_valence(n), "certify_ring(n)", "valence n"), check_digits(digits)
    if method not in ("charpoly", "structure"):
        raise InvalidInputError(f"method must be 'charpoly' or 'structure', got {method!r}")
    blocks = blocks or ring_blocks(scheme, rings)
    if method == "structure":
        return structural_certificate(scheme, n, rings, blocks=blocks, digits=digits)
    identity = product_identity(scheme, n, rings, blocks=blocks)
    S, free, fixed, chis, failure = identity.matrix, list(identity.free), identity.fixed, identity.chis, identity.failure
    size = S.size
    spectrum = ring_spectrum(scheme, n, rings, digits=digits, exact=False, jordan=False)
    multiplicities = tuple(e.multiplicity for e in spectrum.eigenvalues)
    texts = tuple(e.text for e in spectrum.eigenvalues)
    height = max(int(c.p).bit_length() for c in chis[0].coeffs())
    if failure is not None:
        point, bad, left, right = failure
        where = f" with centre weights {point}" if free else ""
        message = (f"n = {n}: refuted: chi_S({bad}) = {left} but the frequency factors give {right}{where} "
                   "(exact): the frequency matrices are not the spectrum of the full matrix")
        return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.DISAGREE, message=message,
                           method="chi_S != product of frequency factors", distinct=0, multiplicities=multiplicities,
                           values=texts, multiplicities_certified=False, height_bits=height)
    count = 1 + len(free)
    method = f"chi_S = prod(frequency factors) at {size} points"
    if free:
        method += f", for {count} values of the centre weights {', '.join(map(str, free))} (affine in them)"
    distinct = _distinct(scheme, blocks, n, chis, free, fixed)
    certified = distinct is not None and distinct == len(spectrum.eigenvalues)
    note = "multiplicities certified" if certified else "multiplicities not certified (distinct values not separated or not decidable)"
    message = f"n = {n}: proved: {method}; {len(spectrum.eigenvalues)} distinct eigenvalues, {note}"
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.AGREE, message=message, method=method,
                       distinct=distinct if distinct is not None else len(spectrum.eigenvalues), multiplicities=multiplicities,
                       values=texts, multiplicities_certified=certified, height_bits=height)


def _squarefree_degree(p: flint.fmpq_poly) -> int:
    return sum(f.degree() for f, _ in p.numer().factor_squarefree()[1])


def _distinct(scheme, blocks, n, chis, free, fixed) -> int | None:
    """The number of distinct eigenvalues, exactly, or ``None`` if it cannot be decided."""
    if not free:
        return _squarefree_degree(chis[0])
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
    return _squarefree_degree(R) + len(new)


def structural_certificate(scheme: Scheme, n: int, rings: int = 1, *, blocks: RingBlocks | None = None, digits: int = 20) -> Certificate:
    """An ``O(n)`` proof: the full refined matrix *is* the bordered circulant-block matrix of ``blocks``.

    Every entry of the matrix built by refinement (no block structure) is compared exactly
    with the entry the block form predicts (in block order; the centre weights as exact values
    or, when algebraic, as the same symbols). Equal matrices have equal spectra, and the
    spectrum of a bordered CB-matrix is that of ``E_0`` and of ``E(omega^k)`` with multiplicities
    (Prop. 6.2 and Remark 6.1, proved for every ``n`` in ``symdecomp claims --section 6``: the
    vectors ``e_0``, ``e_p (x) v_k`` form a basis in which the matrix is block diagonal). So the
    frequency factors are the spectrum. Multiplicities are those of the Arb clusters, certified
    by :func:`cluster_multiplicities` where its exact arguments apply (else the certificate says
    why not).
    """
    n, digits = check_valence(n), check_digits(digits)
    blocks = blocks or ring_blocks(scheme, rings)
    S = ring_subdivision_matrix(scheme, n, rings)
    v = scheme.vertex_rule
    rule = dict(zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)))
    fixed = {s: sp.sympify(w, strict=True).subs(N, n) for s, w in rule.items() if s not in S.weights}
    order = S.block_order()
    K = blocks.class_count
    mismatch, cache = None, {}
    for i, r in enumerate(order):
        expected = _expected_row(blocks, n, K, i, fixed, cache)
        got = {_POS(order, c): x for c, x in S.rows[r].items()}
        keys = set(expected) | set(got)
        bad = [c for c in keys if not _same(got.get(c, 0), expected.get(c, 0))]
        if bad:
            mismatch = (i, bad[0], got.get(bad[0], 0), expected.get(bad[0], 0))
            break
    spectrum = ring_spectrum(scheme, n, rings, digits=digits, exact=False, jordan=False)
    multiplicities = tuple(e.multiplicity for e in spectrum.eigenvalues)
    texts = tuple(e.text for e in spectrum.eigenvalues)
    if mismatch is not None:
        i, c, got, want = mismatch
        message = (f"n = {n}: refuted: entry ({i}, {c}) of the refined matrix (block order) is {got}, the block form "
                   f"gives {want} (exact)")
        return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.DISAGREE, message=message,
                           method="refined matrix != block form", distinct=0, multiplicities=multiplicities, values=texts,
                           multiplicities_certified=False, height_bits=0, route="structural")
    method = f"refined matrix = bordered CB-matrix of E_0, E(omega), entry by entry ({sum(len(r) for r in S.rows)} entries); Remark 6.1"
    why_not = cluster_multiplicities(scheme, blocks, spectrum)
    note = "multiplicities certified" if why_not is None else f"multiplicities not certified ({why_not})"
    message = f"n = {n}: proved: {method}; {len(spectrum.eigenvalues)} distinct values, {note}"
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.AGREE, message=message, method=method,
                       distinct=len(spectrum.eigenvalues), multiplicities=multiplicities, values=texts,
                       multiplicities_certified=why_not is None, height_bits=0, route="structural")


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
    if not _disjoint([e.value for e in entries]):
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
    from symdecomp.analysis.spectrum import centre_values, exact_root

    k, i, j = member
    f = (ff.zero if k == 0 else ff.other)[i]
    if f.roots is None:
        return None
    exact_w, _ = centre_values(scheme, n)
    try:
        return cyclotomic_value(exact_root(f.roots[j], k, n, exact_w), field=field)
    except ValueError:
        return None


def _disjoint(balls) -> bool:
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


_POS_CACHE: dict = {}


def _POS(order, c):
    key = id(order)
    if key not in _POS_CACHE or _POS_CACHE[key][0] is not order:
        _POS_CACHE.clear()
        _POS_CACHE[key] = (order, {r: i for i, r in enumerate(order)})
    return _POS_CACHE[key][1][c]


def _same(a, b) -> bool:
    """Exact equality of two entries (``Fraction`` or sympy, linear in the centre-weight symbols)."""
    if isinstance(a, (int, Fraction)) and isinstance(b, (int, Fraction)):
        return a == b
    return sp.expand(to_sympy(a) - to_sympy(b)) == 0


def _exact(x, fixed: dict):
    """A block entry with the fixed centre weights substituted: ``Fraction`` when rational, else sympy."""
    x = sp.expand(sp.sympify(x, strict=True).xreplace(fixed))
    return to_fraction(x) if x.is_Rational else x


def _expected_row(blocks: RingBlocks, n: int, K: int, i: int, fixed: dict, cache: dict) -> dict:
    """Row ``i`` (block order) of the bordered CB-matrix: ``{column: entry}``, centre weights as given."""
    if "centre" not in cache:
        fixed = {**fixed, N: sp.Integer(n)}  # an edge rule in n: the blocks at this valence
        cache["centre"] = _exact(blocks.centre, fixed)
        cache["row"] = [_exact(w, fixed) for w in blocks.centre_row]
        cache["column"] = [_exact(c, fixed) for c in blocks.centre_column]
        cache["offsets"] = [[[(l, _exact(c, fixed)) for l, c in blocks.offsets[p][q]] for q in range(K)] for p in range(K)]
    out: dict = {}

    def add(c, x):
        out[c] = out[c] + x if c in out else x

    if i == 0:
        add(0, cache["centre"])
        for q in range(K):
            for s in range(n):
                add(1 + q * n + s, cache["row"][q])
    else:
        p, s = divmod(i - 1, n)
        add(0, cache["column"][p])
        for q in range(K):
            for l, c in cache["offsets"][p][q]:
                add(1 + q * n + (s + l) % n, c)
    return {c: x for c, x in out.items() if x != 0}
