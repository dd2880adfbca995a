"""The certificate of a StencilScheme's spectrum at valence ``n``: the blocks' eigenvalues against the full matrix's.

Two routes, as :func:`symdecomp.verify.certify.certify_ring` has for 1-ring schemes:

* ``charpoly`` (every entry of the matrix rational): the characteristic polynomial ``chi_S`` of the full
  matrix in FLINT rationals, its roots isolated with their exact multiplicities (``fmpz_poly.complex_roots``:
  squarefree factorisation, certified balls); each root must lie in exactly one of the engine's eigenvalue
  balls, and the multiplicities must add up. A root outside every ball refutes the blocks; a root in two
  balls leaves the certificate undecided.
* ``structural-form`` (valences beyond :data:`~symdecomp.analysis.zoo_structure.READ_AT` + 3): the blocks read once
  (:mod:`symdecomp.analysis.zoo_structure`) in Arb, ``O(n)`` per valence, without the explicit matrix
  (:mod:`symdecomp.verify.zoo_structural`).
* ``structural`` (entries in ``Q(cos 2 pi/N)``): the full matrix is, entry by entry and exactly, the
  block-circulant matrix of its blocks (:func:`~symdecomp.analysis.zoo_blocks.zoo_blocks` checks every entry
  by exact zero tests), so its spectrum is that of ``B_0`` and ``B(zeta^k)`` (the Fourier transform
  block-diagonalises it); their characteristic polynomials are factored exactly and the roots enclosed by
  certified Arb balls. The multiplicities are certified when the balls of distinct values are disjoint.

>>> from symdecomp.analysis.zoo_matrix import zoo_matrix
>>> import sympy as sp
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

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.ring_spectrum import RingSpectrum
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks, structural_applies
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import check_digits, check_valence
from symdecomp.verify.certify import Certificate
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["certify_zoo"]


def _hull(e: Eigenvalue) -> flint.acb:
    """The ball holding every root of the value's cluster."""
    assert isinstance(e.hull, flint.acb)
    return e.hull


def _disjoint(spectrum: RingSpectrum) -> bool:
    hulls = [_hull(e) for e in spectrum.eigenvalues]
    return all(not a.overlaps(b) for i, a in enumerate(hulls) for b in hulls[i + 1:])


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
        roots: list[tuple[flint.acb, int]] = integral.complex_roots()  # type: ignore[assignment]  # (ball, multiplicity) pairs
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
    certified = _disjoint(spectrum)
    note = "multiplicities certified" if certified else "multiplicities not certified (balls of distinct values overlap)"
    method = "S is block circulant (exact, entry by entry); blocks factored exactly, roots in Arb"
    message = f"n = {n}{steps}: proved: {method}; {len(values)} distinct eigenvalues, {note}"
    return Certificate(n=n, scheme=scheme.name, status=CrossCheckStatus.AGREE, message=message, method=method,
                       distinct=len(values), multiplicities=multiplicities, values=values, multiplicities_certified=certified,
                       height_bits=0, route="structural")
