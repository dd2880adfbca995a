"""The ``O(n)`` certificate of the 1-ring closed forms: no characteristic polynomial of the full matrix.

For one valence ``n`` the claim is the one of :mod:`symdecomp.verify.certify`: the closed-form
eigenvalues (:mod:`symdecomp.analysis.closed_forms`) are the spectrum of the full
``(2n+1) x (2n+1)`` matrix, with multiplicities. The proof:

1. *The matrix is the block matrix* (:func:`structural_certificate`):
   the full 1-ring matrix, built from the rules without the block structure, equals entry by
   entry the bordered circulant-block matrix of ``E_0`` and ``E(omega)``. Its spectrum is then
   that of ``E_0`` and of ``E(omega^k)``, ``k = 1..n-1``, with multiplicities (Prop. 6.2 and
   Remark 6.1, proved for every ``n``).
2. *The closed forms are the frequency factors.* With ``e_1 = v_+ + v_-`` and ``e_2 = v_+ v_-``
   as Laurent polynomials in ``omega`` (step 1 of :mod:`~symdecomp.verify.certify`,
   :func:`~symdecomp.verify.symmetric_functions.symmetric_functions`), ``e_1 - tr E(omega)`` and
   ``e_2 - det E(omega)`` vanish at every ``omega^k``, ``k = 1..n-1``: exactly when, folded
   modulo ``omega^n - 1``, their ``n`` coefficients are all equal (a multiple of
   ``1 + omega + ... + omega^{n-1}``). Either orientation, ``omega`` or ``1/omega``, will do: the
   set of the ``omega^k`` is closed under inversion. And ``F_0 = det(lambda I - E_0)``: three
   rational coefficients at ``n``. Then both sides are the same product of factors.
3. *Otherwise* the multisets are compared exactly: the closed forms' characteristic polynomial
   (resultants, :func:`~symdecomp.verify.symmetric_functions.closed_form_characteristic_value`) against the
   product of the frequency factors (:func:`~symdecomp.analysis.charpoly.frequency_product_values`)
   at ``2n+1`` rational points. Equal: proved (the closed forms pair up across frequencies);
   different: refuted, exactly.

Distinct values and multiplicities come from the frequency factors
(:func:`~symdecomp.verify.multiplicities.cluster_multiplicities`). The route applies where the block
form is read for every ``n`` and the closed forms' symmetric functions reduce:
:func:`structural_obstacle` says why not otherwise (edge or face rules in ``n``, free parameters,
the block form not banded), and ``check --certify`` then takes the dense route and says so. Closed
forms whose symmetric functions do not reduce (steps 2 and 3 cannot be formed) are refuted, where
they are wrong, from the certified roots of the frequency factors (:func:`_refute_by_balls`), or
left undecided (a failure), as on the dense route.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> c = certify_structural(catmull_clark(), 1000)
>>> c.status.value, c.route, c.distinct, c.multiplicities_certified
('agree', 'structural', 1002, True)
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.algebra.numbers import to_fmpq, to_fraction, to_sympy
from symdecomp.analysis.charpoly import frequency_product_values
from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.analysis.frequency import RingBlocks, ring_blocks
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.errors import NotApplicableError, SymdecompError
from symdecomp.schemes.rings import CENTRE_WEIGHTS, ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_digits, check_valence
from symdecomp.verify.certify import Certificate
from symdecomp.verify.multiplicities import cluster_multiplicities, describe_labels, value_text
from symdecomp.verify.result import CrossCheckStatus
from symdecomp.verify.symmetric_functions import SymmetricFunctions, closed_form_characteristic_value, symmetric_functions

__all__ = ["structural_obstacle", "certify_structural", "structural_certificate", "STRUCTURAL_BYTES_PER_VALENCE"]

#: Memory of the structural route per valence and per ring squared (measured: 6 kB on the 1-ring, 84 kB on
#: the 3-ring at n = 2000; the refined matrix's sparse rows
#: as Python dictionaries of fractions, and one certified ball per eigenvalue): an estimate.
STRUCTURAL_BYTES_PER_VALENCE = 10_000


def structural_obstacle(scheme: Scheme) -> str | None:
    """Why the structural certificate does not apply to ``scheme``'s 1-ring (``None`` when it does)."""
    if scheme.parameters:
        return f"the scheme has free parameters ({', '.join(map(str, scheme.parameters))})"
    try:
        blocks = ring_blocks(scheme, 1)
    except SymdecompError as exc:
        return str(exc)
    if blocks.frequency_matrix().has(N):  # the model reads an edge rule in n at the centre's valence
        return "the edge rule depends on the valence n, so its circulant blocks change with n (the certificate reads them once)"
    return None


@lru_cache(maxsize=32)
def _trace_and_determinant(blocks: RingBlocks) -> tuple[dict, dict]:
    """``tr E(omega)`` and ``det E(omega)`` as ``{power of omega: rational}``."""
    E = blocks.frequency_matrix()

    def laurent(expr):
        out: dict = {}
        for term in sp.Add.make_args(sp.expand(expr)):
            coeff, power = term.as_coeff_exponent(OMEGA)
            out[int(power)] = out.get(int(power), 0) + to_fmpq(coeff)
        return out

    return laurent(E.trace()), laurent(E.det(method="berkowitz"))


def _vanishes_at_roots_of_unity(diff: dict, n: int) -> bool:
    """Whether the Laurent polynomial ``diff`` vanishes at every ``omega_n^k``, ``k = 1..n-1`` (exactly)."""
    folded = [flint.fmpq(0)] * n
    for p, c in diff.items():
        folded[p % n] += c
    return all(c == folded[0] for c in folded)


def _frequency_identity(sym: SymmetricFunctions, blocks: RingBlocks, n: int) -> bool | None:
    """Step 2: whether the closed forms are the frequency factors factor by factor; ``None`` if undecidable at ``n``."""
    at = {N: n}
    trace = {p: sym.rational_at(c, at) for p, c in sym.trace.items()}
    det = {p: sym.rational_at(c, at) for p, c in sym.determinant.items()}
    if None in trace.values() or None in det.values():
        return None
    tr_E, det_E = _trace_and_determinant(blocks)

    def minus(a, b, sign):
        out = dict(a)
        for p, c in b.items():
            out[sign * p] = out.get(sign * p, 0) - c
        return out

    other = any(_vanishes_at_roots_of_unity(minus(trace, tr_E, s), n) and _vanishes_at_roots_of_unity(minus(det, det_E, s), n)
                for s in (1, -1))
    return _zero_identity(sym, blocks, n) if other else False


def _zero_identity(sym: SymmetricFunctions, blocks: RingBlocks, n: int) -> bool | None:
    """``F_0 = det(lambda I - E_0)`` at ``n``, exactly: rational, or in ``Q(zeta_2n)`` for algebraic centre weights."""
    E0 = blocks.frequency_zero_matrix(n)
    f0 = sp.Poly((LAM * sp.eye(E0.shape[0]) - E0).det(method="berkowitz"), LAM).all_coeffs()
    e1, e2, e3 = (e.subs(N, n) for e in sym.frequency_zero)
    field = None
    for got, want in zip(f0, (1, -e1, e2, -e3)):
        difference = sp.expand(got - want)
        if difference.is_Rational:
            if difference != 0:
                return False
            continue
        field = field or CyclotomicField(2 * n)
        try:
            if cyclotomic_value(difference, field=field).poly != 0:
                return False
        except ValueError:
            return None
    return len(f0) == 4


def _multiset_identity(sym: SymmetricFunctions, blocks: RingBlocks, scheme: Scheme, n: int):
    """Step 3: ``None`` if the closed forms' polynomial is the frequency product, else ``(lambda, C, P)``;
    ``"inexact"`` when the centre weights or the closed forms' symmetric functions are not rational at ``n``
    (no exact products to compare)."""
    v = scheme.vertex_rule
    weights = {s: sp.sympify(w, strict=True).subs(N, n) for s, w in zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b))}
    if not all(w.is_Rational for w in weights.values()) or closed_form_characteristic_value(sym, n, {}, []) is None:
        return "inexact"
    for x in range(2 * n + 1):  # one point at a time: a refutation usually stops at the first
        (c,) = closed_form_characteristic_value(sym, n, {}, [x])
        (p,) = frequency_product_values(blocks, n, weights, [x])
        if c != p:
            return x, c, p
    return None


def certify_structural(scheme: Scheme, n: int, *, closed_forms: ClosedForms | None = None, digits: int = 20,
                       max_digits: int = 320) -> Certificate:
    """Prove (or refute) that the closed forms are the spectrum at valence ``n``, in ``O(n)`` steps.

    ``closed_forms``: the closed forms under test (default: the derived ones; tests pass a wrong
    one). ``max_digits``: the largest precision of the balls that refute closed forms whose
    symmetric functions do not reduce. Raises :class:`~symdecomp.errors.NotApplicableError`
    where :func:`structural_obstacle` objects.
    """
    n = check_valence(n)
    cf = closed_forms or derived_closed_forms(scheme)
    obstacle = structural_obstacle(scheme)
    if obstacle is not None:
        raise NotApplicableError(f"scheme {scheme.name!r}: the structural certificate does not apply: {obstacle}")
    blocks = ring_blocks(scheme, 1)
    base = structural_certificate(scheme, n, 1, blocks=blocks, digits=digits)
    if not base.ok:
        return base
    sym = symmetric_functions(cf)
    fields = dict(n=n, scheme=scheme.name, distinct=base.distinct, multiplicities=base.multiplicities, values=base.values,
                  height_bits=0, route="structural")
    by_factor = None if sym.reason else _frequency_identity(sym, blocks, n)
    if by_factor is None:
        why = f"identity not formed: {sym.reason}" if sym.reason else "symmetric functions not exact at this n"
        return _undecided_or_refuted(scheme, cf, n, why, digits, max_digits, fields)
    failure = None if by_factor else _multiset_identity(sym, blocks, scheme, n)
    if failure == "inexact":  # no exact products: the certified roots decide
        return _undecided_or_refuted(scheme, cf, n, "closed forms != frequency factors, factor by factor", digits,
                                     max_digits, fields)
    if failure is not None:
        x, c, p = failure
        return Certificate(status=CrossCheckStatus.DISAGREE, method="prod(closed-form factors) != prod(frequency factors)",
                           multiplicities_certified=False, message=(
                               f"n = {n}: {_first_wrong(cf, blocks, n)}refuted: the closed forms' characteristic polynomial "
                               f"is {c} at lambda = {x}, the full matrix's (the product of its frequency factors, proved "
                               f"equal to it) is {p} (exact)"), **fields)
    how = "closed forms = frequency factors, factor by factor" if by_factor else \
        f"prod(closed-form factors) = prod(frequency factors) at {2 * n + 1} points"
    method = f"{base.method}; {how}"
    note = "multiplicities certified" if base.multiplicities_certified else "multiplicities not certified"
    return Certificate(status=CrossCheckStatus.AGREE, method=method, multiplicities_certified=base.multiplicities_certified,
                       message=f"n = {n}: proved: {method}; {base.distinct} distinct eigenvalues, {note}", **fields)


def _undecided_or_refuted(scheme, cf, n, why, digits, max_digits, fields) -> Certificate:
    refutation = _refute_by_balls(scheme, cf, n, digits, max_digits)
    if refutation is not None:
        return Certificate(status=CrossCheckStatus.DISAGREE, method=why, multiplicities_certified=False,
                           message=refutation, **fields)
    return Certificate(status=CrossCheckStatus.UNDECIDED, method=why, multiplicities_certified=False,
                       message=f"n = {n}: not certified ({why}), and no closed-form eigenvalue could be refuted at "
                       f"{max_digits} digits", **fields)


def _refute_by_balls(scheme: Scheme, cf: ClosedForms, n: int, digits: int, max_digits: int) -> str | None:
    """A rigorous reason why the closed forms are not the spectrum, from the frequency factors' certified roots.

    The full matrix's spectrum is the frequency factors' (step 1), enclosed in the balls of
    :func:`~symdecomp.analysis.spectrum.ring_spectrum`: (a) a closed-form value outside
    cluster's ball is no eigenvalue; (b) a cluster's ball apart from the others holds exactly as
    many eigenvalues as the cluster's multiplicity: holding more closed-form values than that, or
    overlapping fewer, refutes them. The precision doubles up to ``max_digits``.
    """
    labels = cf.eigenvalue_labels(n)
    d = digits
    while True:
        hulls = [(e, e.hull) for e in ring_spectrum(scheme, n, 1, digits=d, exact=False, jordan=False).eigenvalues]
        balls = cf.values(n, {}, engine="arb", prec=max(256, 8 * d + 64))
        for label, v in zip(labels, balls):
            if not any(h.overlaps(v) for _, h in hulls):
                return (f"n = {n}: closed-form eigenvalue {value_text(v, digits)} ({describe_labels([label])}) is not an eigenvalue of "
                        "the full matrix: it lies outside the certified balls of the frequency factors' roots")
        for e, h in hulls:  # a hull apart from the others holds exactly e.multiplicity eigenvalues
            if any(h.overlaps(other) for f, other in hulls if f is not e):
                continue
            inside = [i for i, v in enumerate(balls) if h.contains(v)]
            near = [i for i, v in enumerate(balls) if h.overlaps(v)]
            if len(inside) > e.multiplicity or len(near) < e.multiplicity:
                which = inside if len(inside) > e.multiplicity else near
                return (f"n = {n}: {len(which)} closed-form eigenvalues lie at the eigenvalue {e.text}"
                        f"{' (' + describe_labels([labels[i] for i in which]) + ')' if which else ''}, whose multiplicity in the "
                        f"full matrix is {e.multiplicity} (certified)")
        if d >= max_digits:
            return None
        d = min(2 * d, max_digits)


def _first_wrong(cf: ClosedForms, blocks: RingBlocks, n: int, prec: int = 256) -> str:
    """Name a closed-form eigenvalue that is a root of neither orientation of its frequency's factor (Arb)."""
    labels = cf.eigenvalue_labels(n)
    balls = cf.values(n, {}, engine="arb", prec=prec)
    K = blocks.class_count
    E0 = blocks.frequency_zero_matrix(n)
    with flint.ctx.workprec(prec):
        zero = flint.acb_mat([[flint.acb(to_fmpq(x)) for x in E0.row(i)] for i in range(K + 1)])
        for label, v in zip(labels, balls):
            k = label.frequency
            if k == 0:
                mats = [zero]
            else:
                mats = []
                for sign in (1, -1):
                    w = flint.acb(flint.fmpq(2 * sign * k, n)).exp_pi_i()
                    mats.append(flint.acb_mat([[sum((flint.acb(to_fmpq(c)) * w**l for l, c in blocks.offsets[p][q]), flint.acb(0))
                                                for q in range(K)] for p in range(K)]))
            if all(not (M - v * flint.acb_mat(M.nrows(), M.ncols(), [int(i == j) for i in range(M.nrows()) for j in range(M.ncols())]))
                   .det().contains(0) for M in mats):
                return f"closed-form eigenvalue {value_text(v, 20)} ({describe_labels([label])}) is not a root of its frequency's factor; "
    return ""


def structural_certificate(scheme: Scheme, n: int, rings: int = 1, *, blocks: RingBlocks | None = None, digits: int = 20) -> Certificate:
    """An ``O(n)`` proof: the full refined matrix *is* the bordered circulant-block matrix of ``blocks``.

    Every entry of the matrix built by refinement (no block structure) is compared exactly
    with the entry the block form predicts (in block order; the centre weights as exact values
    or, when algebraic, as the same symbols). Equal matrices have equal spectra, and the
    spectrum of a bordered CB-matrix is that of ``E_0`` and of ``E(omega^k)`` with multiplicities
    (Prop. 6.2 and Remark 6.1, proved for every ``n`` in ``symdecomp claims --section 6``: the
    vectors ``e_0``, ``e_p (x) v_k`` form a basis in which the matrix is block diagonal). So the
    frequency factors are the spectrum. Multiplicities are those of the Arb clusters, certified
    by :func:`~symdecomp.verify.multiplicities.cluster_multiplicities` where its exact arguments apply (else the certificate says
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
