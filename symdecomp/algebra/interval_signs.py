"""The sign of a rational polynomial on a closed interval, exactly, in FLINT (Sturm sequences over ``Q``).

A statement "for every valence" often ends as the sign of a polynomial with rational coefficients on an interval
(:func:`~symdecomp.algebra.valence_signs.sign_on_interval` in ``t = cos(2 pi/n)``; the Jacobian's Bezier coefficients
of :mod:`symdecomp.verify.c1_uniform`). The arithmetic is FLINT's ``fmpq_poly``, exact and fast:

* :func:`count_roots`: the distinct real roots in ``[low, high]``: the squarefree part ``p/gcd(p, p')``, with the roots
  at the endpoints divided out, has ``V(low) - V(high)`` roots strictly inside (Sturm's theorem: ``V`` counts the sign
  changes of its Sturm sequence at a point);
* :func:`positive_on`: positive (``strict``) or nonnegative on ``[low, high]``, decided as
  :func:`~symdecomp.algebra.valence_signs.sign_on_interval` states it: positive means no root in the interval and
  positive at ``low``; nonnegative means no root of odd multiplicity strictly inside (the product of the odd-multiplicity
  factors, by Yun's squarefree factorisation, has none) and positive at the first of the points
  ``low + (high - low) k/(d + 2)``, ``k = 1..d + 1`` (``d`` the degree) that is no root; the zero polynomial is
  nonnegative, not positive.

>>> import flint
>>> p = flint.fmpq_poly([-1, 0, 2])  # 2 t^2 - 1: roots -+ 1/sqrt(2)
>>> count_roots(p, 0, 1), count_roots(p, -1, 1), count_roots(p * p, -1, 1), count_roots(p, 1, 2)
(1, 2, 2, 0)
>>> positive_on(p, 1, 2), positive_on(p, 0, 1), positive_on(p * p, -1, 1, strict=False), positive_on(p * p, -1, 1)
(True, False, True, False)
"""

from __future__ import annotations

import flint

from symdecomp.algebra.numbers import to_fmpq

__all__ = ["count_roots", "positive_on", "odd_multiplicity_part", "squarefree_part"]


def squarefree_part(p: flint.fmpq_poly) -> flint.fmpq_poly:
    """``p/gcd(p, p')``: the same roots, each simple."""
    g = p.gcd(p.derivative())
    return p if g.degree() < 1 else divmod(p, g)[0]


def odd_multiplicity_part(p: flint.fmpq_poly) -> flint.fmpq_poly:
    """The product of the squarefree factors of ``p`` of odd multiplicity (Yun's algorithm): the roots where ``p``
    changes sign."""
    if p.degree() < 1:
        return flint.fmpq_poly([1])
    g = p.gcd(p.derivative())
    b, c = divmod(p, g)[0], divmod(p.derivative(), g)[0]
    d = c - b.derivative()
    out, multiplicity = flint.fmpq_poly([1]), 1
    while b.degree() >= 1:
        a = b.gcd(d)
        if multiplicity % 2:
            out *= a
        b, c = divmod(b, a)[0], divmod(d, a)[0]
        d = c - b.derivative()
        multiplicity += 1
    return out


def _variations(sequence: list[flint.fmpq_poly], x: flint.fmpq) -> int:
    values = [q(x) for q in sequence]
    signs = [v > 0 for v in values if v != 0]
    return sum(1 for u, v in zip(signs, signs[1:]) if u != v)


def _sturm(p: flint.fmpq_poly) -> list[flint.fmpq_poly]:
    sequence = [p, p.derivative()]
    while sequence[-1].degree() >= 1:
        rest = -(sequence[-2] % sequence[-1])
        if rest.is_zero():
            break
        sequence.append(rest)
    return sequence


def count_roots(p: flint.fmpq_poly, low: object, high: object) -> int:
    """The number of distinct real roots of ``p`` (not the zero polynomial) in the closed interval ``[low, high]``."""
    low, high = to_fmpq(low), to_fmpq(high)
    if p.is_zero():
        raise ValueError("the zero polynomial has every number as a root")
    q = squarefree_part(p)
    at_ends = 0
    for end in (low, high) if low != high else (low,):
        if q.degree() >= 1 and q(end) == 0:
            q, at_ends = divmod(q, flint.fmpq_poly([-end, 1]))[0], at_ends + 1
    if q.degree() < 1 or low >= high:
        return at_ends
    sequence = _sturm(q)
    return at_ends + _variations(sequence, low) - _variations(sequence, high)


def positive_on(p: flint.fmpq_poly, low: object, high: object, *, strict: bool = True) -> bool:
    """Whether ``p`` is positive (``strict``) or nonnegative on ``[low, high]`` (module docstring), exactly."""
    low, high = to_fmpq(low), to_fmpq(high)
    if p.is_zero():
        return not strict
    if strict:
        return p(low) > 0 and count_roots(p, low, high) == 0
    odd = odd_multiplicity_part(p)
    if odd.degree() >= 1 and count_roots(odd, low, high) - (odd(low) == 0) - (odd(high) == 0) > 0:
        return False
    if low == high:
        return p(low) >= 0
    degree = p.degree()
    points = (low + (high - low) * flint.fmpq(k, degree + 2) for k in range(1, degree + 2))
    return bool(p(next(x for x in points if p(x) != 0)) > 0)
