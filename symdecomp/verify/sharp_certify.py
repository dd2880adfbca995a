"""Certified check of a boundary, crease, corner or dart vertex: the mirror decomposition against the full matrix.

The claim is that the blocks of the mirror decomposition (:mod:`symdecomp.analysis.mirror`: the crease block
``C``, or at a dart the symmetric part, and the sine blocks ``M(theta_j)`` of each sector) give the spectrum of
the one-step matrix ``S`` of the vertex's 1-ring, with multiplicities. ``S`` is built by exact refinement of the
tagged mesh (:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`), without the block structure. The
claim is the identity

    chi_S(lambda) = det(lambda I - C) prod_sectors prod_j det(lambda I - M(theta_j)),

proved exactly: the crease rows of ``S`` equal the decomposition's ``C`` entry by entry, and the two
polynomials are equal in ``Q[lambda]``: ``chi_S`` by FLINT from ``S``, the product over a sector's blocks as a
resultant with the Chebyshev polynomial whose roots are the frequencies ``cos(pi j/k)``
(:func:`symdecomp.analysis.mirror_threshold.charpoly_check`, the one home of that product).

The distinct eigenvalues and their multiplicities are then exact too: ``chi_S`` is factored over ``Q``, and the
roots of distinct irreducible factors are distinct (each root of a factor with exponent ``e`` has multiplicity
``e``). The decimal values are certified Arb balls of those roots.

Rules whose weights hold ``cos(theta_k)`` (Biermann-Levin-Zorin's) give ``S`` with entries in the real
cyclotomic field ``K = Q(cos(pi/k))`` (:mod:`symdecomp.analysis.triangular_eigen`); the same identity is then proved in
``K[lambda]`` (:func:`certify_sharp_field`): ``chi_S`` by Hessenberg reduction over ``K``, the sectors' products
as resultants in ``Q[lambda, cos(theta_k)]`` (:func:`~symdecomp.analysis.mirror_threshold.sine_part_in_cos`) at
``cos(theta_k) = cos(pi/k)`` in ``K``. The distinct eigenvalues and multiplicities are exact there too: roots of
the irreducible rational factors of the norm of ``chi_S``, each picked out and counted by gcds in ``K[lambda]``.

Scope: infinitely sharp edges (the decomposition's); out of reach (:class:`~symdecomp.errors.NotApplicableError`,
saying so): darts under such rules and creases whose two sides lie in different fields ``Q(cos(pi/k_i))``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.spectrum import acb_text
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_digits
from symdecomp.verify.certify import Certificate
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["SharpCertificate", "certify_sharp", "certify_sharp_field", "describe_vertex"]


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


def _distinct_values(chi: flint.fmpq_poly, digits: int) -> tuple[int, tuple[int, ...], tuple[str, ...]]:
    """``(distinct, multiplicities, texts)`` from the exact factorization of ``chi``, largest modulus first."""
    _, factors = chi.factor()
    roots = []
    with flint.ctx.workprec(4 * digits + 64):
        for f, e in factors:
            roots += [(r, e) for r, _ in f.numer().complex_roots()]
    roots.sort(key=lambda t: (-float(abs(t[0]).mid()), -float(t[0].real.mid())))
    return len(roots), tuple(e for _, e in roots), tuple(acb_text(r, digits) for r, _ in roots)


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
    distinct, multiplicities, texts = _distinct_values(chi, digits)
    common = dict(n=vertex.sectors[0], scheme=scheme.name, distinct=distinct, multiplicities=multiplicities, values=texts,
                  height_bits=max(int(c.p).bit_length() for c in chi.coeffs()), route="mirror", vertex=describe_vertex(vertex))
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
    from symdecomp.algebra.cos_field import FieldMatrix, field_charpoly, norm_charpoly
    from symdecomp.analysis.mirror import sector_decomposition, vertex_layout
    from symdecomp.analysis.sharp_spectrum import field_name
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
                  values=texts, height_bits=max(int(c).bit_length() for c in norm.numer().coeffs()), route="mirror", vertex=name)
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
