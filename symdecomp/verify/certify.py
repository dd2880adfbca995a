"""Certified cross-check: a proof, at one neighbourhood, that a spectrum is the full matrix's.

One question, asked of every neighbourhood: an interior vertex of valence ``n`` with its 1-ring
(the closed forms, :func:`certify`), an interior vertex with its ``K``-ring under any scheme (the
frequency factors, :func:`certify_ring`), a boundary, crease, corner or dart vertex (the mirror
decomposition's blocks, :func:`certify_sharp`). Each proof is an exact polynomial identity
``chi_S = (the spectrum's characteristic polynomial)``, ``chi_S`` the characteristic polynomial of
the neighbourhood's matrix built without the block structure (by the rules, or by exact refinement)
and computed by FLINT; the distinct values and their multiplicities are certified on top
(:mod:`symdecomp.verify.multiplicities`). The ``O(n)`` route that compares the matrix with the block
matrix entry by entry instead is :mod:`symdecomp.verify.structural`.

*The 1-ring closed forms.* Let ``v_1..v_{2n+1}`` be the closed-form eigenvalues
(:mod:`symdecomp.analysis.closed_forms`) and ``C(lambda) = prod_i (lambda - v_i)``; the claim "the
closed forms are the eigenvalues, with multiplicities" is exactly ``chi_S = C``. Step 1, once per
scheme: the closed forms' symmetric functions as exact Laurent polynomials in ``omega``
(:mod:`symdecomp.verify.symmetric_functions`). Step 2, for each n:
``C = F_0 * prod_{k=1}^{n-1} (lambda^2 - e_1(omega^k) lambda + e_2(omega^k))``; for a rational
``lambda_0`` the product over the ``n-1`` roots of unity ``omega != 1`` is a resultant,
``prod_k G(omega^k) = Res(1 + omega + ... + omega^{n-1}, G)`` for
``G(omega) = omega^m (lambda_0^2 - e_1 lambda_0 + e_2)``, up to the sign ``(-1)^{(n-1)m}``: an exact
rational computed by FLINT. ``chi_S(lambda_0) = C(lambda_0)`` is checked at the ``2n+1`` points
``lambda_0 = 0, 1, ..., 2n``. Both sides are monic of degree ``2n+1``, so their difference has degree
at most ``2n`` and ``2n+1`` roots: it is zero. QED. Repeated eigenvalues (``n = 4``: ``1/4`` three
times), defective ones (a Jordan block of the Eq. 43 matrix) and ``k = n/2`` need no special care:
the identity is between polynomials, multiplicities included. When it fails (or the symmetric
functions do not reduce, so that it cannot be formed), the offending eigenvalue is named with a
rigorous reason; if none can be shown the result is ``undecided``, which is a failure.

*The K-ring, any scheme.* The spectrum of the full ``K``-ring matrix ``S``
(:func:`~symdecomp.schemes.rings.ring_subdivision_matrix`) is, with multiplicities, the union of the
spectra of ``E_0`` and of ``E(omega_n^k)``, ``k = 1..n-1`` (:func:`symdecomp.analysis.frequency.ring_blocks`),
whose factored characteristic polynomials give :func:`symdecomp.analysis.spectrum.ring_spectrum`:
``chi_S(lambda) = det(lambda I - E_0) prod_{k=1}^{n-1} det(lambda I - E(omega^k))``, both sides at
``size`` rational points, the product over the roots of unity a resultant as above
(:func:`~symdecomp.analysis.charpoly.product_identity`, the one home of that product, also
behind ``charpoly``). *Algebraic centre weights* (Loop's ``cos(2 pi/n)``): only row 0 holds them,
and both sides are affine in them, so the identity is proved for the weights as free symbols, at
``1 + (number of weights)`` affinely independent rational points: it then holds for the actual
weights. No floating point is involved.

*A boundary, crease, corner or dart vertex.* The blocks of the mirror decomposition
(:mod:`symdecomp.analysis.mirror`: the crease block ``C``, or at a dart the symmetric part, and the
sine blocks ``M(theta_j)`` of each sector) against the one-step matrix ``S`` of the vertex's 1-ring
by exact refinement of the tagged mesh (:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`):

    chi_S(lambda) = det(lambda I - C) prod_sectors prod_j det(lambda I - M(theta_j)),

proved exactly: the crease rows of ``S`` equal ``C`` entry by entry, and the two polynomials are
equal in ``Q[lambda]``, the product over a sector's blocks as a resultant with the Chebyshev
polynomial whose roots are the frequencies ``cos(pi j/k)``
(:func:`symdecomp.analysis.mirror_threshold.charpoly_check`). Rules whose weights hold
``cos(theta_k)`` (Biermann-Levin-Zorin's) give ``S`` over ``K = Q(cos(pi/k))``
(:mod:`symdecomp.analysis.triangular_eigen`); the same identity is then proved in ``K[lambda]``
(:func:`certify_sharp_field`). Scope: infinitely sharp edges (the decomposition's); out of reach
(:class:`~symdecomp.errors.NotApplicableError`, saying so): darts under such rules and creases whose
two sides lie in different fields ``Q(cos(pi/k_i))``.

*A StencilScheme of the zoo* (:func:`certify_zoo`; any neighbourhood the engine builds, a vertex or a dual face),
the blocks' eigenvalues (:func:`~symdecomp.analysis.zoo_blocks.zoo_blocks`, orbit labelling) against the full matrix's.
With every entry rational, ``chi_S`` in FLINT rationals has its roots isolated with their exact multiplicities
(``fmpz_poly.complex_roots``); each must lie in exactly one of the blocks' balls and the multiplicities must add up
(a root outside every ball refutes the blocks, a root in two leaves the certificate undecided). With entries in
``Q(cos 2 pi/N)``: the full matrix is, entry by entry and exactly, the block-circulant matrix of its blocks, so its
spectrum is theirs (factored exactly, roots in certified Arb balls; multiplicities certified when the balls of
distinct values are disjoint). Beyond :data:`~symdecomp.analysis.zoo_structure.READ_AT` + 3 the blocks are read once
in Arb, ``O(n)`` per valence (:mod:`symdecomp.verify.zoo_structural`).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> r = certify(catmull_clark(), 4)
>>> r.status.value, r.distinct, r.multiplicities
('agree', 5, (1, 2, 3, 2, 1))
>>> from symdecomp.schemes.loop import loop
>>> c = certify_ring(loop(), 7, 1)
>>> c.status.value, c.distinct, c.multiplicities, c.multiplicities_certified
('agree', 5, (1, 2, 2, 1, 2), True)
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, StencilScheme, J, M
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> ds = StencilScheme("doo-sabin", "quad", "dual", (KindRules("corner", (Rule((corner,)),)),))
>>> c = certify_zoo(ds, 4)
>>> c.status.value, c.route, c.multiplicities_certified
('agree', 'charpoly', True)
>>> certify_zoo(ds, 5).route
'structural'
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import ClassVar

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.charpoly import product_identity
from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.frequency import RingBlocks, ring_blocks
from symdecomp.analysis.spectrum import RingSpectrum, acb_text, ring_spectrum
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks, structural_applies
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.full_matrix import characteristic_polynomial, parameter_values
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import check_bits, check_digits, check_limit, check_valence
from symdecomp.verify.multiplicities import (
    disjoint,
    distinct_count,
    factored_values,
    largest_first,
    separate_or_refute,
    value_text,
)
from symdecomp.verify.result import CrossCheckResult, CrossCheckStatus
from symdecomp.verify.symmetric_functions import closed_form_identity, symmetric_functions

__all__ = ["Certificate", "certify", "certify_ring", "SharpCertificate", "certify_sharp", "certify_sharp_field",
           "describe_vertex", "certify_zoo"]


@dataclass(frozen=True)
class Certificate(CrossCheckResult):
    """The certified cross-check of one valence.

    Status ``agree`` (proved), ``disagree`` (refuted, rigorously) or ``undecided`` (neither: a failure).
    """

    #: How the verdict was reached, e.g. ``"chi_S = C at 2n+1 points"``.
    method: str
    #: Number of distinct eigenvalues (from the squarefree part of ``chi_S``).
    distinct: int
    #: Multiplicities of the distinct eigenvalues, largest modulus first (certified if ``multiplicities_certified``).
    multiplicities: tuple[int, ...]
    #: The distinct closed-form values, as decimal strings.
    values: tuple[str, ...]
    #: Whether the grouping into distinct values is proved (Arb clusters = squarefree degree).
    multiplicities_certified: bool
    #: Bits of the largest coefficient numerator of ``chi_S``.
    height_bits: int
    #: Which proof: ``"charpoly"`` (the dense characteristic polynomial of the full matrix) or
    #: ``"structural"`` (the full matrix is the block matrix, entry by entry; no ``chi_S``).
    route: str = "charpoly"

    mode: ClassVar[str] = "certified"

    def details(self) -> dict:
        return {
            "route": self.route,
            "method": self.method,
            "distinct": self.distinct,
            "multiplicities": list(self.multiplicities),
            "multiplicities_certified": self.multiplicities_certified,
            "height_bits": self.height_bits,
        }


def certify(
    scheme: Scheme,
    n: int,
    *,
    parameters: Mapping | None = None,
    closed_forms: ClosedForms | None = None,
    digits: int = 20,
    max_prec: int = 4096,
) -> Certificate:
    """Prove (or rigorously refute) that the closed forms are the spectrum at valence ``n``.

    ``closed_forms``: the closed forms under test (default: the derived ones; the tests pass
    a wrong one). ``digits``: significant digits of the printed values. ``max_prec``: the
    largest Arb precision (bits) tried when clustering or refuting.
    """
    check_scheme(scheme)
    n = check_valence(n)
    digits = check_digits(digits)
    max_prec = check_bits(max_prec, "max_prec", minimum=128)
    subs = parameter_values(scheme, parameters)
    cf = closed_forms or derived_closed_forms(scheme)
    chi = characteristic_polynomial(scheme, n, subs)
    height = max(int(c.p).bit_length() for c in chi.coeffs())
    squarefree = chi.numer().factor_squarefree()[1]  # [(f, e)]: chi ~ prod f^e, f squarefree, coprime
    distinct = sum(f.degree() for f, _ in squarefree)
    identity, method = closed_form_identity(chi, symmetric_functions(cf), n, subs)
    balls, clusters, prec, refutation = separate_or_refute(cf, n, subs, chi, squarefree, identity, digits, max_prec)
    order = largest_first(clusters, balls)
    # the printed values: a square root of a vanishing discriminant (a defective eigenvalue)
    # is only known to half the working precision, so they are recomputed with room to spare
    accurate = flint.arb(10) ** (-(digits + 5))
    if any(b.rad() >= accurate for b in balls):
        balls = cf.values(n, subs, engine="arb", prec=max(2 * prec, 8 * digits + 128))
    certified = identity and len(clusters) == distinct
    if identity:
        note = "multiplicities certified" if certified else "distinct values not separated at the precision limit"
        status, message = CrossCheckStatus.AGREE, f"n = {n}: proved: {method}; {distinct} distinct eigenvalues, {note}"
    elif refutation is not None:
        status, message = CrossCheckStatus.DISAGREE, refutation
    else:
        status = CrossCheckStatus.UNDECIDED
        message = f"n = {n}: not certified ({method}), and no closed-form eigenvalue could be refuted at {max_prec} bits"
    return Certificate(
        n=n,
        scheme=scheme.name,
        status=status,
        method=method,
        distinct=distinct,
        multiplicities=tuple(len(cl) for cl in order),
        values=tuple(value_text(balls[cl[0]], digits) for cl in order),
        multiplicities_certified=certified,
        height_bits=height,
        message=message,
    )


def certify_ring(scheme: Scheme, n: int, rings: int = 1, *, blocks: RingBlocks | None = None, digits: int = 20,
                 method: str = "charpoly") -> Certificate:
    """Prove (or refute, exactly) that the frequency factors give the spectrum of the full ``rings``-ring matrix.

    ``blocks``: the block form under test (default: the derived one; tests pass a wrong one).
    ``method``: ``"charpoly"`` (the identity above, dense FLINT characteristic polynomials) or
    ``"structure"`` (:func:`~symdecomp.verify.structural.structural_certificate`: ``O(n)``, for large valences).
    """
    n, digits = check_limit(check_valence(n), "certify_ring(n)", "valence n"), check_digits(digits)
    if method not in ("charpoly", "structure"):
        raise InvalidInputError(f"method must be 'charpoly' or 'structure', got {method!r}")
    blocks = blocks or ring_blocks(scheme, rings)
    if method == "structure":
        from symdecomp.verify.structural import structural_certificate  # the O(n) route builds on this module's type

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
    distinct = distinct_count(scheme, blocks, n, chis, free, fixed)
    certified = distinct is not None and distinct == len(spectrum.eigenvalues)
    note = "multiplicities certified" if certified else "multiplicities not certified (distinct values not separated or not decidable)"
    message = f"n = {n}: proved: {method}; {len(spectrum.eigenvalues)} distinct eigenvalues, {note}"
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.AGREE, message=message, method=method,
                       distinct=distinct if distinct is not None else len(spectrum.eigenvalues), multiplicities=multiplicities,
                       values=texts, multiplicities_certified=certified, height_bits=height)


def describe_vertex(vertex) -> str:
    """A short name of a sharp vertex: ``boundary k=5``, ``corner k=2``, ``crease 3+4``, ``dart n=5``; semi-sharp with ``s=``."""
    sectors = tuple(vertex.sectors)
    if not vertex.closed:
        kind = f"{'corner' if vertex.corner else 'boundary'} k={sectors[0]}" if len(sectors) == 1 else f"boundary {'+'.join(map(str, sectors))}"
    elif len(sectors) == 1:
        kind = f"dart n={sectors[0]}"
    else:
        kind = f"crease {'+'.join(map(str, sectors))}"
    if vertex.sharpness != math.inf and vertex.closed:
        kind += f", sharpness {vertex.sharpness}"
    return kind


@dataclass(frozen=True)
class SharpCertificate(Certificate):
    """The certified check of one sharp vertex; ``n`` is the sector's face count ``k`` (a dart's valence)."""

    #: The vertex, as :func:`describe_vertex` names it.
    vertex: str = ""

    def details(self) -> dict:
        return {"vertex": self.vertex, **super().details()}


def _is_dart(vertex) -> bool:
    return vertex.closed and len(vertex.sectors) == 1


def certify_sharp(scheme: Scheme, vertex, *, digits: int = 20) -> SharpCertificate:
    """Prove (or refute, exactly) that the mirror decomposition's blocks are the spectrum of the vertex's matrix.

    ``vertex``: a :class:`~symdecomp.schemes.sector.SharpVertex` with infinitely sharp edges (the mirror
    decomposition's scope). Raises :class:`~symdecomp.errors.NotApplicableError` for irrational rules.
    """
    from symdecomp.analysis.mirror import sector_decomposition, vertex_layout
    from symdecomp.analysis.mirror_threshold import charpoly_check
    from symdecomp.analysis.triangular_eigen import sharp_matrix
    from symdecomp.schemes.sector import sharp_subdivision_matrix

    scheme, digits = check_scheme(scheme), check_digits(digits)
    reads_angle = scheme.sharp is not None and scheme.sharp.near_edge_centre is not None and not _is_dart(vertex)
    if reads_angle or not isinstance(sharp_matrix(scheme, vertex), flint.fmpq_mat):
        return certify_sharp_field(scheme, vertex, digits=digits)
    S = sp.Matrix(sharp_subdivision_matrix(scheme, vertex))
    d = sector_decomposition(scheme, vertex)
    equal, chi, blocks = charpoly_check(scheme, vertex, matrix=S)
    distinct, multiplicities, texts = factored_values(chi, digits)
    common = dict(n=vertex.sectors[0], scheme=scheme.name, distinct=distinct, multiplicities=multiplicities, values=texts,
                  height_bits=max(int(c.p).bit_length() for c in chi.coeffs()), route="charpoly", vertex=describe_vertex(vertex))
    name = describe_vertex(vertex)
    if d.crease is not None:
        lay = vertex_layout(scheme, vertex)
        idx = [0] + [lay.a(m) for m in lay.sharp]
        rows = S.extract(idx, idx)
        if rows != d.crease:
            return SharpCertificate(status=CrossCheckStatus.DISAGREE, method="crease rows of S != the crease block C",
                                    multiplicities_certified=False, **common,
                                    message=f"{name}: refuted: the refined matrix's crease rows are {rows.tolist()}, the "
                                    f"decomposition's crease block is {d.crease.tolist()} (exact)")
    if not equal:
        return SharpCertificate(status=CrossCheckStatus.DISAGREE, method="chi_S != product of the blocks' polynomials",
                                multiplicities_certified=False, **common,
                                message=f"{name}: refuted: chi_S = {chi}, the blocks give {blocks} (exact)")
    head = "C" if d.crease is not None else "the symmetric part"
    method = f"crease rows = C; chi_S = det(l - {head}) prod_j det(l - M(theta_j)) in Q[l] (Chebyshev resultants)"
    if d.crease is None:
        method = f"chi_S = det(l - {head}) prod_j det(l - M(theta_j)) in Q[l] (Chebyshev resultants)"
    message = f"{name}: proved: {method}; {distinct} distinct eigenvalues, multiplicities exact (chi_S factored over Q)"
    return SharpCertificate(status=CrossCheckStatus.AGREE, method=method, multiplicities_certified=True, message=message, **common)


def _blocks_in_field(scheme, vertex, S, lay, dart: bool) -> list:
    """``det(l - C) prod_sectors prod_j det(l - M(theta_j))`` in ``K[l]``, ``K`` the field of ``S``'s entries."""
    from symdecomp.algebra.cos_field import affine_in, field_charpoly, poly_mul, specialize
    from symdecomp.algebra.number_field import FieldElement
    from symdecomp.analysis.mirror_threshold import sine_part_in_cos

    idx = [0] + [lay.a(m) for m in lay.sharp]
    blocks = field_charpoly(S.submatrix(idx))
    for k in lay.sectors:
        pq = affine_in(sp.cos(lay.angle / k), S.weight)
        if pq is None:
            raise NotApplicableError(f"cos({sp.sstr(lay.angle / k)}) is not in the field of the matrix's entries, "
                                     f"Q({sp.sstr(S.weight)}): sectors of different sizes are out of reach")
        ck = FieldElement(flint.fmpq_poly([to_fmpq(pq[0]), to_fmpq(pq[1])]) % S.modulus, S.modulus)
        blocks = poly_mul(blocks, specialize(sine_part_in_cos(scheme, k, dart=dart), ck))
    return blocks


def certify_sharp_field(scheme: Scheme, vertex, *, digits: int = 20) -> SharpCertificate:
    """:func:`certify_sharp` for rules with ``cos(theta_k)`` weights: the identity proved in ``Q(cos(pi/k))[lambda]``."""
    from symdecomp.algebra.cos_field import FieldMatrix, field_charpoly, field_name, norm_charpoly
    from symdecomp.analysis.mirror import sector_decomposition, vertex_layout
    from symdecomp.analysis.triangular_eigen import merge, sharp_values

    scheme, digits = check_scheme(scheme), check_digits(digits)
    S, _, values = sharp_values(scheme, vertex, prec=max(256, 4 * digits + 64))
    if isinstance(S, flint.fmpq_mat):  # cos(theta_k) rational at this k: the field is Q
        S = FieldMatrix.from_sympy([[S[i, j] for j in range(S.ncols())] for i in range(S.nrows())], sp.Integer(0))
    lay, name = vertex_layout(scheme, vertex), describe_vertex(vertex)
    if len(lay.sharp) == 1:
        raise NotApplicableError(f"{name}: a dart under rules with cos(theta_k) weights is out of reach of the certificate")
    field = field_name(S)
    values = merge(values)
    with flint.ctx.workprec(4 * digits + 64):
        texts = tuple(acb_text(v.ball, digits) for v in values)
    norm = norm_charpoly(S)
    common = dict(n=vertex.sectors[0], scheme=scheme.name, distinct=len(values), multiplicities=tuple(v.multiplicity for v in values),
                  values=texts, height_bits=max(int(c).bit_length() for c in norm.numer().coeffs()), route="charpoly", vertex=name)
    idx = [0] + [lay.a(m) for m in lay.sharp]
    crease = FieldMatrix.from_sympy(sector_decomposition(scheme, vertex).crease.tolist(), S.weight)
    if S.submatrix(idx).rows != crease.rows:
        return SharpCertificate(status=CrossCheckStatus.DISAGREE, method=f"crease rows of S != the crease block C (in {field})",
                                multiplicities_certified=False, **common,
                                message=f"{name}: refuted: the refined matrix's crease rows differ from the crease block (exact)")
    chi, blocks = field_charpoly(S), _blocks_in_field(scheme, vertex, S, lay, False)
    method = f"crease rows = C; chi_S = det(l - C) prod_j det(l - M(theta_j)) in {field}[l] (Chebyshev resultants)"
    if chi != blocks:
        return SharpCertificate(status=CrossCheckStatus.DISAGREE, method=f"chi_S != product of the blocks' polynomials in {field}[l]",
                                multiplicities_certified=False, **common,
                                message=f"{name}: refuted: chi_S differs from the blocks' product in {field}[l] (exact)")
    message = (f"{name}: proved: {method}; {len(values)} distinct eigenvalues, multiplicities exact (the norm of chi_S "
               "factored over Q, roots picked by gcds in the field)")
    return SharpCertificate(status=CrossCheckStatus.AGREE, method=method, multiplicities_certified=True, message=message, **common)


def _hull(e: Eigenvalue) -> flint.acb:
    """The ball holding every root of the value's cluster."""
    assert isinstance(e.hull, flint.acb)
    return e.hull


def _charpoly_verdict(S: sp.Matrix, spectrum: RingSpectrum, prec: int) -> tuple[CrossCheckStatus, str, bool, int]:
    """``(status, message, multiplicities certified, height bits)`` by the roots of the exact ``chi_S``."""
    size = S.shape[0]
    F = flint.fmpq_mat(size, size, [to_fmpq(x) for x in S])
    chi = F.charpoly()
    denominator = flint.fmpz(1)
    for c in chi.coeffs():
        denominator = denominator * c.q // denominator.gcd(c.q)
    integral = flint.fmpz_poly([int(c * denominator) for c in chi.coeffs()])
    height = max(int(c).bit_length() for c in integral.coeffs())
    with flint.ctx.workprec(prec):
        roots: list[tuple[flint.acb, int]] = integral.complex_roots()  # (ball, multiplicity) pairs
        counts = [0] * len(spectrum.eigenvalues)
        for ball, multiplicity in roots:
            hits = [i for i, e in enumerate(spectrum.eigenvalues) if _hull(e).overlaps(ball)]
            if not hits:
                return CrossCheckStatus.DISAGREE, f"the full matrix has the eigenvalue {ball.mid().str(10)} that no block gives", False, height
            if len(hits) > 1:
                return CrossCheckStatus.UNDECIDED, "an eigenvalue of the full matrix lies in two of the blocks' balls", False, height
            counts[hits[0]] += multiplicity
    expected = [e.multiplicity for e in spectrum.eigenvalues]
    if counts != expected:
        return CrossCheckStatus.DISAGREE, f"multiplicities {counts} of the full matrix against {expected} from the blocks", False, height
    return CrossCheckStatus.AGREE, "chi_S's roots (exact multiplicities) are the blocks' values", True, height


def certify_zoo(scheme: StencilScheme, n: int, depth: int | None = None, *, digits: int = 20) -> Certificate:
    """Prove (or refute) that the frequency blocks give the spectrum of ``scheme``'s full matrix at valence ``n``."""
    digits = check_digits(digits)
    if depth is None and structural_applies(scheme, check_valence(n)):
        from symdecomp.verify.zoo_structural import structural_zoo_certificate

        return structural_zoo_certificate(scheme, n, digits=digits)
    zm = zoo_matrix(scheme, n, depth)
    n = zm.n  # checked: an int
    blocks = zoo_blocks(zm)  # raises if the matrix is not block circulant (exact, entry by entry)
    spectrum = spectrum_of_blocks(blocks, digits=digits, exact=False, depth=zm.depth, mesh=scheme.lattice)
    multiplicities = tuple(e.multiplicity for e in spectrum.eigenvalues)
    values = tuple(e.text for e in spectrum.eigenvalues)
    S = sp.Matrix(zm.matrix)
    steps = f" over {scheme.steps} steps" if scheme.steps > 1 else ""
    if all(x.is_Rational for x in S):
        status, note, certified, height = _charpoly_verdict(S, spectrum, max(128, 4 * digits + 64))
        message = f"n = {n}{steps}: {'proved' if status == CrossCheckStatus.AGREE else status.value}: {note}"
        return Certificate(n=n, scheme=scheme.name, status=status, message=message, method="roots of chi_S in FLINT rationals",
                           distinct=len(values), multiplicities=multiplicities, values=values, multiplicities_certified=certified,
                           height_bits=height, route="charpoly")
    certified = disjoint([_hull(e) for e in spectrum.eigenvalues])
    note = "multiplicities certified" if certified else "multiplicities not certified (balls of distinct values overlap)"
    method = "S is block circulant (exact, entry by entry); blocks factored exactly, roots in Arb"
    message = f"n = {n}{steps}: proved: {method}; {len(values)} distinct eigenvalues, {note}"
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.AGREE, message=message, method=method,
                       distinct=len(values), multiplicities=multiplicities, values=values, multiplicities_certified=certified,
                       height_bits=0, route="structural")
