"""The characteristic polynomial of the K-ring matrix in product form, for any scheme.

``det(x I - S) = det(x I - E_0) prod_{k=1}^{n-1} det(x I - E(omega_n^k))`` with both factors
written as products of the irreducible factors of :func:`~symdecomp.analysis.ring_spectrum.frequency_factors`.
At a valence the polynomial is the full matrix's (FLINT), written through the centre weights
(it is affine in them: only row 0 holds them), and compared with the product exactly, at
``size`` rational points for each corner of the centre weights: the identity behind
:func:`~symdecomp.verify.ring_certify.certify_ring`.

>>> from symdecomp.schemes.loop import loop_warren
>>> d = ring_charpoly(loop_warren(), 3)
>>> d["polynomial"], d["matches_matrix"]
('lambda**4 - 25*lambda**3/16 + 21*lambda**2/32 - 25*lambda/256 + 1/256', True)
"""

from __future__ import annotations

from functools import lru_cache

import flint
import sympy as sp

from symdecomp.analysis.ring_blocks import RingBlocks, ring_blocks
from symdecomp.analysis.ring_spectrum import frequency_factors
from symdecomp.schemes.full_matrix import entries_characteristic_polynomial
from symdecomp.schemes.rings import CENTRE_WEIGHTS, ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_valence

__all__ = ["ring_charpoly", "product_form", "frequency_product_values"]


def _power(f, e):
    return f"({f})" if e == 1 else f"({f})^{e}"


def product_form(scheme: Scheme, rings: int = 1) -> tuple[list[str], list[str], str]:
    """``(E_0 factors, E(omega) factors, the product formula)`` as text."""
    ff = frequency_factors(ring_blocks(scheme, rings))
    zero = [_power(f.poly, f.exponent) for f in ff.zero]
    other = [_power(f.poly, f.exponent) for f in ff.other]
    formula = "det(x I - E_0) * prod_{k=1}^{n-1} det(x I - E(omega_n^k)), c_k = cos(2 pi k/n)"
    return zero, other, formula


def _fmpq(x) -> flint.fmpq:
    x = sp.Rational(x)
    return flint.fmpq(int(x.p), int(x.q))


@lru_cache(maxsize=32)
def _laurent_charpoly(blocks: RingBlocks) -> tuple[int, tuple[flint.fmpq_poly, ...]]:
    """``(m, (Q_0, Q_1, ...))`` with ``omega^m det(lambda I - E(omega)) = sum_i lambda^i Q_i(omega)``."""
    K = blocks.class_count
    det = sp.expand((LAM * sp.eye(K) - blocks.frequency_matrix()).det(method="berkowitz"))
    terms = sp.Poly(sp.expand(det * OMEGA ** (4 * K * 8)), LAM, OMEGA).terms()
    low = min(b for (_, b), _ in terms)
    m = 4 * K * 8 - low
    degree = max(a for (a, _), _ in terms)
    polys = [dict() for _ in range(degree + 1)]
    for (a, b), c in terms:
        polys[a][b - low] = _fmpq(c)
    return m, tuple(flint.fmpq_poly([p.get(j, 0) for j in range(max(p, default=0) + 1)]) for p in polys)


def frequency_product_values(blocks: RingBlocks, n: int, weights: dict, points) -> list:
    """``det(l I - E_0) prod_{k=1}^{n-1} det(l I - E(omega^k))`` exactly at each rational ``l``.

    ``weights``: rational values for every symbol of :data:`CENTRE_WEIGHTS`.
    """
    m, Q = _laurent_charpoly(blocks)
    E0 = blocks.frequency_zero_matrix(n, symbolic_weights=True).xreplace(weights)
    f0 = sp.Poly((LAM * sp.eye(E0.shape[0]) - E0).det(method="berkowitz"), LAM)
    zero = flint.fmpq_poly([_fmpq(c) for c in reversed(f0.all_coeffs())])
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


def ring_charpoly(scheme: Scheme, n: int, rings: int = 1) -> dict:
    """JSON-ready: the product form, the polynomial at ``n`` (exact coefficients) and whether they agree."""
    n = check_valence(n)
    blocks = ring_blocks(scheme, rings)
    S = ring_subdivision_matrix(scheme, n, rings)
    free = sorted(S.weights, key=str)
    v = scheme.vertex_rule
    rule = dict(zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)))
    fixed = {s: sp.sympify(w).subs(N, n) for s, w in rule.items() if s not in free}
    corners = [{s: 0 for s in free}] + [{s: int(s == t) for s in free} for t in free]
    polys, matches = [], True
    for point in corners:
        chi = entries_characteristic_polynomial(S.entries(point), S.size)
        values = frequency_product_values(blocks, n, {**fixed, **{s: sp.Integer(x) for s, x in point.items()}}, range(S.size))
        matches &= all(chi(flint.fmpq(x)) == values[x] for x in range(S.size))
        polys.append([sp.Rational(int(c.p), int(c.q)) for c in chi.coeffs()])
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
