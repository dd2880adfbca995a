"""Certified check of a boundary, crease, corner or dart vertex: the mirror decomposition against the full matrix.

The claim is that the blocks of the mirror decomposition (:func:`~symdecomp.analysis.mirror.sector_decomposition`:
the crease block ``C``, or at a dart the symmetric part, and the sine blocks ``M(theta_j)`` of each sector)
give the spectrum of the one-step matrix ``S`` of the vertex's 1-ring, with multiplicities. ``S`` is built by
exact refinement of the tagged mesh (:func:`~symdecomp.schemes.sector.exact_sharp_matrix`), without the block
structure. The claim is the identity

    chi_S(lambda) = det(lambda I - C) prod_blocks det(lambda I - M(theta_j)),

proved as the interior's (:mod:`symdecomp.verify.certify`): ``chi_S`` exactly by FLINT; the right-hand side at a
rational ``lambda_0`` exactly, each sine block's entries (cosines of rational multiples of ``pi``) in the
cyclotomic field ``Q(zeta_N)`` (:mod:`symdecomp.algebra.cyclotomic`), the product over the blocks a rational
number there. Both sides are monic of degree ``size`` (the blocks' sizes are checked to add up to it), so
equality at ``size`` points ``lambda_0 = 0, 1, ...`` is equality of polynomials. No floating point is involved.

The distinct eigenvalues and their multiplicities are then exact too: ``chi_S`` is factored over ``Q``, and the
roots of distinct irreducible factors are distinct (each root of a factor with exponent ``e`` has multiplicity
``e``). The decimal values are certified Arb balls of those roots.

Scope: rational rules (the standard ones and a scheme file's rational ``[sharp]`` weights). Rules whose weights
hold ``cos(theta_k)`` (Biermann-Levin-Zorin's) give an irrational ``S``; the certificate says so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.algebra.numbers import to_fmpq, to_fraction
from symdecomp.analysis.ring_spectrum import acb_text
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_digits
from symdecomp.verify.certify import Certificate
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["SharpCertificate", "certify_sharp", "describe_vertex"]


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


def _rational_matrix(M: sp.Matrix) -> flint.fmpq_mat:
    return flint.fmpq_mat([[to_fmpq(x) for x in row] for row in M.tolist()])


def _field_of(entries) -> CyclotomicField:
    order = 1
    for expr, at in entries:
        for row in expr:
            for x in row:
                n = cyclotomic_value(x, at).field.N
                order = order * n // math.gcd(order, n)
    return CyclotomicField(order)


def _sine_entries(scheme: Scheme, vertex, decomposition) -> list:
    """Each sine or face block as ``(entries, values)``: the symbolic ``M(theta)`` of :func:`~symdecomp.analysis.mirror.sine_block`
    with ``theta`` (and the sector angle ``theta_k``) to substitute, so that cosines stay cosines of rational multiples of pi."""
    from symdecomp.analysis.mirror import THETA, THETA_K, sine_block

    dart = decomposition.crease is None
    M = sine_block(scheme, modified=not dart)
    angle = vertex.angle if (vertex.corner and vertex.angle is not None) else sp.pi
    out = []
    for blk in decomposition.blocks:
        if blk.kind == "face":
            out.append(([[sp.sympify(blk.matrix[0, 0], strict=True)]], {}))
            continue
        k = vertex.sectors[blk.sector]
        out.append(([[x for x in row] for row in M.tolist()], {THETA: blk.theta, THETA_K: angle / k}))
    return out


def _block_product(entries, field: CyclotomicField, lam: flint.fmpq):
    """``prod det(lam I - M)`` over the blocks, in ``field``; a rational ``fmpq``, or ``None`` if it is not rational."""
    acc = field(1)
    for rows, at in entries:
        M = [[cyclotomic_value(x, at, field=field) for x in row] for row in rows]
        L = field(to_fraction(lam))
        if len(M) == 1:
            acc = acc * (L - M[0][0])
        else:
            acc = acc * ((L - M[0][0]) * (L - M[1][1]) - M[0][1] * M[1][0])
    coeffs = acc.poly.coeffs()
    if acc.poly.degree() > 0:
        return None
    return coeffs[0] if coeffs else flint.fmpq(0)


def _distinct_values(chi: flint.fmpq_poly, digits: int) -> tuple[int, tuple[int, ...], tuple[str, ...]]:
    """``(distinct, multiplicities, texts)`` from the exact factorization of ``chi``, largest modulus first."""
    _, factors = chi.factor()
    roots = []
    with flint.ctx.workprec(4 * digits + 64):
        for f, e in factors:
            roots += [(r, e) for r, _ in f.numer().complex_roots()]
    roots.sort(key=lambda t: (-float(abs(t[0]).mid()), -float(t[0].real.mid())))
    return len(roots), tuple(e for _, e in roots), tuple(acb_text(r, digits) for r, _ in roots)


def certify_sharp(scheme: Scheme, vertex, *, digits: int = 20) -> SharpCertificate:
    """Prove (or refute, exactly) that the mirror decomposition's blocks are the spectrum of the vertex's matrix.

    ``vertex``: a :class:`~symdecomp.schemes.sector.SharpVertex` with infinitely sharp edges (the mirror
    decomposition's scope). Raises :class:`~symdecomp.errors.NotApplicableError` for irrational rules.
    """
    from symdecomp.analysis.mirror import sector_decomposition
    from symdecomp.schemes.sector import exact_sharp_matrix

    scheme, digits = check_scheme(scheme), check_digits(digits)
    S = exact_sharp_matrix(scheme, vertex)
    size = S.nrows()
    chi = S.charpoly()
    d = sector_decomposition(scheme, vertex)
    head = d.crease if d.crease is not None else d.cosine
    if any(not sp.sympify(x).is_Rational for x in head):
        raise NotApplicableError(f"{describe_vertex(vertex)}: the crease block is not rational; the certificate needs rational rules")
    chi_head = _rational_matrix(head).charpoly()
    entries = _sine_entries(scheme, vertex, d)
    field = _field_of(entries)
    distinct, multiplicities, texts = _distinct_values(chi, digits)
    height = max(int(c.p).bit_length() for c in chi.coeffs())
    common = dict(n=vertex.sectors[0], scheme=scheme.name, distinct=distinct, multiplicities=multiplicities, values=texts,
                  height_bits=height, route="mirror", vertex=describe_vertex(vertex))
    count = head.shape[0] + sum(len(rows) for rows, _ in entries)
    if count != size:
        return SharpCertificate(status=CrossCheckStatus.DISAGREE, method="block sizes != matrix size", multiplicities_certified=False,
                                message=f"{describe_vertex(vertex)}: refuted: the blocks have {count} eigenvalues, the matrix {size}",
                                **common)
    for x in range(size):
        lam = flint.fmpq(x)
        right = _block_product(entries, field, lam)
        right = None if right is None else chi_head(lam) * right
        if right != chi(lam):
            got = "not rational" if right is None else str(right)
            return SharpCertificate(status=CrossCheckStatus.DISAGREE, method="chi_S != product of the blocks' polynomials",
                                    multiplicities_certified=False,
                                    message=f"{describe_vertex(vertex)}: refuted: chi_S({x}) = {chi(lam)}, the blocks give {got} (exact)",
                                    **common)
    method = f"chi_S = det(l - {'C' if d.crease is not None else 'cosine part'}) prod det(l - M(theta_j)) at {size} points"
    message = f"{describe_vertex(vertex)}: proved: {method}; {distinct} distinct eigenvalues, multiplicities exact (chi_S factored over Q)"
    return SharpCertificate(status=CrossCheckStatus.AGREE, method=method, multiplicities_certified=True, message=message, **common)
