"""Products and derivatives of Bernstein-Bezier polynomials with Arb coefficients, tensor and triangular.

A product of two polynomials in Bernstein form is a convolution of their *scaled* coefficients:
``sum f_i B^p_i * sum g_k B^q_k = sum h_a B^(p+q)_a`` with
``C(p+q, a) h_a = sum_(i+k=a) C(p, i) f_i C(q, k) g_k`` (one variable; a tensor net scales by
``C(p, i) C(q, k)`` in each direction, a triangular net by the multinomial ``d!/(a! b! c!)``,
:func:`~symdecomp.algebra.triangle_bezier.multinomial`). The two-dimensional convolution is done
as one product of univariate Arb polynomials by Kronecker substitution (``x^i y^k -> x^(i K + k)``
with ``K`` above the product's degree in ``y``), so FLINT's certified polynomial multiplication does
the work: every coefficient is a ball holding the exact one. The results agree with
:func:`~symdecomp.algebra.triangle_bezier.bezier_product` (a loop over all pairs, the definition).

Nets: tensor nets are lists of rows ``net[i][k]`` (``i`` the power of ``u``, ``k`` of ``v``),
degree ``(p, q)``; triangular nets are flat lists in
:func:`~symdecomp.algebra.triangle_bezier.bezier_indices` order, total degree ``d``.

>>> import flint
>>> u = [[flint.arb(0)], [flint.arb(1)]]          # the function u, degree (1, 0)
>>> [[c.mid() for c in row] for row in tensor_product(u, u, (1, 0), (1, 0))]   # u^2 in degree (2, 0)
[[0], [0], [1.00000000000000]]
"""

from __future__ import annotations

from math import comb

import flint

from symdecomp.algebra.triangle_bezier import bezier_indices, multinomial

__all__ = ["tensor_product", "tensor_derivative", "triangle_product", "net_sum", "net_scale"]


def _kronecker(scaled: dict[tuple[int, int], flint.arb], K: int) -> flint.arb_poly:
    coeffs = [flint.arb(0)] * (max(i * K + k for i, k in scaled) + 1)
    for (i, k), c in scaled.items():
        coeffs[i * K + k] = c
    return flint.arb_poly(coeffs)


def _convolve(f: dict, g: dict, K: int) -> dict:
    """``{(i, k): h}`` with ``h`` the 2-D convolution of ``f`` and ``g`` (both ``{(i, k): coefficient}``; ``k < K``)."""
    product = _kronecker(f, K) * _kronecker(g, K)
    coeffs = product.coeffs()
    return {(m // K, m % K): c for m, c in enumerate(coeffs)}


def tensor_product(f, g, degree_f: tuple[int, int], degree_g: tuple[int, int]) -> list[list[flint.arb]]:
    """The tensor Bernstein net (degree ``degree_f + degree_g``) of the product of two tensor nets."""
    (p1, q1), (p2, q2) = degree_f, degree_g
    P, Q = p1 + p2, q1 + q2
    sf = {(i, k): f[i][k] * (comb(p1, i) * comb(q1, k)) for i in range(p1 + 1) for k in range(q1 + 1)}
    sg = {(i, k): g[i][k] * (comb(p2, i) * comb(q2, k)) for i in range(p2 + 1) for k in range(q2 + 1)}
    h = _convolve(sf, sg, Q + 1)
    zero = flint.arb(0)
    return [[h.get((a, b), zero) / (comb(P, a) * comb(Q, b)) for b in range(Q + 1)] for a in range(P + 1)]


def tensor_derivative(net, degree: tuple[int, int], direction: str) -> list[list]:
    """The net of ``d/du`` (``direction='u'``, degree ``(p - 1, q)``) or ``d/dv`` of a tensor net of ``degree``."""
    p, q = degree
    if direction == "u":
        return [[p * (net[i + 1][k] - net[i][k]) for k in range(q + 1)] for i in range(p)]
    if direction == "v":
        return [[q * (net[i][k + 1] - net[i][k]) for k in range(q)] for i in range(p + 1)]
    raise ValueError(f"direction must be 'u' or 'v', got {direction!r}")


def triangle_product(f, g, degree_f: int, degree_g: int) -> list[flint.arb]:
    """The triangular net (degree ``degree_f + degree_g``) of the product of two triangular nets (Arb coefficients)."""
    K = degree_f + degree_g + 1
    sf = {(i[1], i[2]): x * multinomial(i) for x, i in zip(f, bezier_indices(degree_f))}
    sg = {(i[1], i[2]): x * multinomial(i) for x, i in zip(g, bezier_indices(degree_g))}
    h = _convolve(sf, sg, K)
    zero = flint.arb(0)
    return [h.get((b, c), zero) / multinomial((a, b, c)) for a, b, c in bezier_indices(degree_f + degree_g)]


def net_sum(*terms):
    """The coefficient-wise sum of nets of one shape (tensor: lists of rows; triangular: flat lists)."""
    first = terms[0]
    if first and isinstance(first[0], list):
        return [net_sum(*rows) for rows in zip(*terms)]
    return [sum(cs[1:], cs[0]) for cs in zip(*terms)]


def net_scale(net, factor):
    """``factor`` times a net (tensor or triangular)."""
    if net and isinstance(net[0], list):
        return [net_scale(row, factor) for row in net]
    return [c * factor for c in net]
