"""Polynomials over a triangle in Bernstein-Bezier form: index order, values, derivatives, products.

A polynomial of total degree ``d`` over the triangle with corners ``(0, 0)``, ``(1, 0)``,
``(0, 1)`` of the ``(u, v)`` plane is ``sum c_{abc} B_{abc}(u, v)`` over ``a + b + c = d``, with
``B_{abc} = d!/(a! b! c!) w^a u^b v^c`` and ``w = 1 - u - v``. Coefficient ``c_{abc}`` sits at
the *domain point* ``(b/d, c/d)``. Coefficients are listed in :func:`bezier_indices` order:
by ``c`` (the power of ``v``), then by ``b``, i.e. domain points row by row from ``(0, 0)``.

Everything here is generic in the number type: the coefficients (and ``u``, ``v``) may be
``Fraction``, sympy, mpmath, FLINT ``arb`` balls or numpy arrays (vectorized over many points).

>>> from fractions import Fraction
>>> bezier_indices(2)
((2, 0, 0), (1, 1, 0), (0, 2, 0), (1, 0, 1), (0, 1, 1), (0, 0, 2))
>>> net = [Fraction(b, 2) for _, b, _ in bezier_indices(2)]   # the function u, degree-raised
>>> bezier_value(net, 2, Fraction(1, 3), Fraction(1, 5))
Fraction(1, 3)
"""

from __future__ import annotations

from functools import cache
from math import factorial

__all__ = ["bezier_indices", "multinomial", "bernstein", "bezier_value", "bezier_derivative", "bezier_product"]


@cache
def bezier_indices(degree: int) -> tuple[tuple[int, int, int], ...]:
    """The ``(a, b, c)`` (powers of ``w, u, v``) of degree ``degree``, in coefficient order."""
    return tuple((degree - b - c, b, c) for c in range(degree + 1) for b in range(degree + 1 - c))


def multinomial(index: tuple[int, int, int]) -> int:
    """``d!/(a! b! c!)`` for ``index = (a, b, c)``, ``d = a + b + c``."""
    a, b, c = index
    return factorial(a + b + c) // (factorial(a) * factorial(b) * factorial(c))


def bernstein(degree: int, u, v) -> list:
    """The Bernstein polynomials ``B_{abc}(u, v)`` of ``degree``, in :func:`bezier_indices` order."""
    w = 1 - u - v
    return [multinomial(i) * w ** i[0] * u ** i[1] * v ** i[2] for i in bezier_indices(degree)]


def bezier_value(net, degree: int, u, v):
    """``sum c_i B_i(u, v)`` for the coefficients ``net`` (a sequence in :func:`bezier_indices` order)."""
    basis = bernstein(degree, u, v)
    total = net[0] * basis[0]
    for c, b in zip(net[1:], basis[1:]):
        total = total + c * b
    return total


def bezier_derivative(net, degree: int, direction: str) -> list:
    """The net (degree ``degree - 1``) of ``d/du`` (``direction='u'``) or ``d/dv`` (``'v'``).

    ``d/du`` of ``sum c_{abc} B_{abc}`` is ``d sum (c_{a,b+1,c} - c_{a+1,b,c}) B_{abc}``
    (``w = 1 - u - v`` falls with ``u``); likewise for ``v``.
    """
    if direction not in ("u", "v") or degree < 1:
        raise ValueError(f"direction must be 'u' or 'v' and degree >= 1, got {direction!r}, {degree}")
    pos = {i: k for k, i in enumerate(bezier_indices(degree))}
    out = []
    for a, b, c in bezier_indices(degree - 1):
        up = (a, b + 1, c) if direction == "u" else (a, b, c + 1)
        out.append(degree * (net[pos[up]] - net[pos[(a + 1, b, c)]]))
    return out


def bezier_product(f, g, degree_f: int, degree_g: int) -> list:
    """The net (degree ``degree_f + degree_g``) of the product of two polynomials given by nets.

    ``h_k = sum f_i g_j C(i) C(j)/C(k)`` over ``i + j = k`` (componentwise), ``C`` the
    :func:`multinomial` coefficient; exact for exact inputs, a ball for balls.
    """
    out = []
    for terms, divisor in _product_table(degree_f, degree_g):
        a, b, w = terms[0]
        total = f[a] * g[b] * w
        for a, b, w in terms[1:]:
            total = total + f[a] * g[b] * w
        out.append(total / divisor)
    return out


@cache
def _product_table(degree_f: int, degree_g: int) -> tuple:
    """For each coefficient ``k`` of :func:`bezier_product`: ``(((i, j, C(i) C(j)), ...), C(k))`` (positions in the nets)."""
    pos = {i: k for k, i in enumerate(bezier_indices(degree_f + degree_g))}
    terms: list[list] = [[] for _ in pos]
    for a, i in enumerate(bezier_indices(degree_f)):
        for b, j in enumerate(bezier_indices(degree_g)):
            k = (i[0] + j[0], i[1] + j[1], i[2] + j[2])
            terms[pos[k]].append((a, b, multinomial(i) * multinomial(j)))
    return tuple((tuple(ts), multinomial(k)) for ts, k in zip(terms, bezier_indices(degree_f + degree_g)))
