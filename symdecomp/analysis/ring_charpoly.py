"""The characteristic polynomial of the K-ring matrix in product form, for any scheme.

``det(x I - S) = det(x I - E_0) prod_{k=1}^{n-1} det(x I - E(omega_n^k))`` with both factors
written as products of the irreducible factors of :func:`~symdecomp.analysis.ring_spectrum.frequency_factors`.
At a valence the polynomial is the full matrix's (FLINT), written through the centre weights
(it is affine in them: only row 0 holds them), and compared with the product exactly, at
``size`` rational points for each corner of the centre weights: the identity behind
:func:`~symdecomp.verify.certify.certify_ring`.

>>> from symdecomp.schemes.loop import loop_warren
>>> d = ring_charpoly(loop_warren(), 3)
>>> d["polynomial"], d["matches_matrix"]
('lambda**4 - 25*lambda**3/16 + 21*lambda**2/32 - 25*lambda/256 + 1/256', True)
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.ring_blocks import RingBlocks, ring_blocks
from symdecomp.analysis.ring_spectrum import frequency_factors
from symdecomp.schemes.full_matrix import entries_characteristic_polynomial
from symdecomp.schemes.rings import CENTRE_WEIGHTS, RingMatrix, ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_valence

__all__ = ["ring_charpoly", "product_form", "frequency_product_values", "ProductIdentity", "product_identity"]


def _power(f, e):
    return f"({f})" if e == 1 else f"({f})^{e}"


def product_form(scheme: Scheme, rings: int = 1) -> tuple[list[str], list[str], str]:
    """``(E_0 factors, E(omega) factors, the product formula)`` as text."""
    ff = frequency_factors(ring_blocks(scheme, rings))
    zero = [_power(f.poly, f.exponent) for f in ff.zero]
    other = [_power(f.poly, f.exponent) for f in ff.other]
    formula = "det(x I - E_0) * prod_{k=1}^{n-1} det(x I - E(omega_n^k)), c_k = cos(2 pi k/n)"
    return zero, other, formula


@lru_cache(maxsize=32)
def _laurent_charpoly(blocks: RingBlocks, n: int | None = None) -> tuple[int, tuple[flint.fmpq_poly, ...]]:
    """``(m, (Q_0, Q_1, ...))`` with ``omega^m det(lambda I - E(omega)) = sum_i lambda^i Q_i(omega)``; ``n``: the valence,
    for blocks that depend on it (an edge rule in ``n``), else ``None``."""
    K = blocks.class_count
    E = blocks.frequency_matrix() if n is None else blocks.frequency_matrix().subs(N, n)
    det = sp.expand((LAM * sp.eye(K) - E).det(method="berkowitz"))
    terms = sp.Poly(sp.expand(det * OMEGA ** (4 * K * 8)), LAM, OMEGA).terms()
    low = min(b for (_, b), _ in terms)
    m = 4 * K * 8 - low
    degree = max(a for (a, _), _ in terms)
    polys = [dict() for _ in range(degree + 1)]
    for (a, b), c in terms:
        polys[a][b - low] = to_fmpq(c)
    return m, tuple(flint.fmpq_poly([p.get(j, 0) for j in range(max(p, default=0) + 1)]) for p in polys)


def frequency_product_values(blocks: RingBlocks, n: int, weights: dict, points) -> list:
    """``det(l I - E_0) prod_{k=1}^{n-1} det(l I - E(omega^k))`` exactly at each rational ``l``.

    ``weights``: rational values for every symbol of :data:`CENTRE_WEIGHTS`.
    """
    m, Q = _laurent_charpoly(blocks, n if blocks.frequency_matrix().has(N) else None)
    E0 = blocks.frequency_zero_matrix(n, symbolic_weights=True).xreplace(weights)
    f0 = sp.Poly((LAM * sp.eye(E0.shape[0]) - E0).det(method="berkowitz"), LAM)
    zero = flint.fmpq_poly([to_fmpq(c) for c in reversed(f0.all_coeffs())])
    cyclotomic = flint.fmpq_poly([1] * n)
    sign = -1 if (m * (n - 1)) % 2 else 1
    out = []
    for lam in points:
        lam = flint.fmpq(lam)
        G, power = flint.fmpq_poly(0), flint.fmpq(1)
        for q in Q:
            G += q * power
            power *= lam
        out.append(zero(lam) * cyclotomic.resultant(G) * sign)
    return out


@dataclass(frozen=True)
class ProductIdentity:
    """``chi_S = det(l I - E_0) prod_k det(l I - E(omega^k))`` tested exactly at one valence.

    The one home of the comparison behind ``charpoly`` and ``check --certify``: ``chi_S`` of
    the refined matrix (FLINT, no block structure) against the product of the frequency
    factors (resultants, :func:`frequency_product_values`) at ``size`` rational points, for
    each corner of the centre weights that are not rational (both sides are affine in them).
    """

    #: The refined matrix.
    matrix: RingMatrix
    #: The centre-weight symbols kept free (algebraic weights), sorted by name.
    free: tuple
    #: The other centre weights: symbol -> exact rational value at ``n``.
    fixed: dict
    #: The corners: ``{symbol: 0 or 1}`` for the free symbols (one corner, ``{}``, if none).
    corners: tuple
    #: ``chi_S`` at each corner (``flint.fmpq_poly``).
    chis: tuple
    #: ``None`` if the identity holds, else ``(corner, l, chi_S(l), product at l)`` of the first failure.
    failure: tuple | None


def product_identity(scheme: Scheme, n: int, rings: int = 1, *, blocks: RingBlocks | None = None) -> ProductIdentity:
    """Test the product identity at valence ``n`` exactly (``blocks``: the block form under test)."""
    n = check_valence(n)
    blocks = blocks or ring_blocks(scheme, rings)
    S = ring_subdivision_matrix(scheme, n, rings)
    free = tuple(sorted(S.weights, key=str))
    v = scheme.vertex_rule
    rule = dict(zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)))
    fixed = {s: sp.sympify(w, strict=True).subs(N, n) for s, w in rule.items() if s not in free}
    corners = tuple([{s: 0 for s in free}] + [{s: int(s == t) for s in free} for t in free])
    chis, failure = [], None
    for point in corners:
        chi = entries_characteristic_polynomial(S.entries(point), S.size)
        chis.append(chi)
        if failure is None:
            values = frequency_product_values(blocks, n, {**fixed, **{s: sp.Integer(x) for s, x in point.items()}}, range(S.size))
            bad = next((x for x in range(S.size) if chi(flint.fmpq(x)) != values[x]), None)
            if bad is not None:
                failure = (point, bad, chi(flint.fmpq(bad)), values[bad])
    return ProductIdentity(S, free, fixed, corners, tuple(chis), failure)


def ring_charpoly(scheme: Scheme, n: int, rings: int = 1) -> dict:
    """JSON-ready: the product form, the polynomial at ``n`` (exact coefficients) and whether they agree."""
    identity = product_identity(scheme, n, rings)
    S, free, corners, matches = identity.matrix, identity.free, identity.corners, identity.failure is None
    polys = [[sp.Rational(int(c.p), int(c.q)) for c in chi.coeffs()] for chi in identity.chis]
    actual = S.weight_values()
    coeffs = [sp.expand(p0 + sum((actual[s] * (p[i] - p0) for s, p in zip(free, polys[1:])), sp.Integer(0))) for i, p0 in enumerate(polys[0])]
    polynomial = sp.Add(*[c * LAM**i for i, c in enumerate(coeffs)])
    zero, other, formula = product_form(scheme, rings)
    return {
        "n": n, "scheme": scheme.name, "rings": rings, "size": S.size,
        "product_form": formula, "frequency_zero_factors": zero, "frequency_factors": other,
        "centre_weights": {str(s): str(w) for s, w in actual.items()},
        "polynomial": str(polynomial), "coefficients": [str(c) for c in reversed(coeffs)],
        "matches_matrix": bool(matches),
        "method": f"chi_S = product at {S.size} points" + (f" for {len(corners)} values of the centre weights" if free else ""),
    }
