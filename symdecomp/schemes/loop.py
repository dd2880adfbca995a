"""Loop's scheme on triangle meshes, as a :class:`~symdecomp.schemes.scheme.Scheme` (1-ring rules).

Around a vertex ``O`` of valence ``n`` with neighbours ``a_0..a_{n-1}`` (faces ``(O, a_i, a_{i+1})``):

* edge rule, for the new ``a_i`` (the edge point of ``(O, a_i)``): ``3/8`` on each end and ``1/8``
  on each of the two opposite vertices ``a_{i-1}``, ``a_{i+1}``;
* vertex rule, for the new ``O``: ``beta(n)`` on each neighbour and ``1 - n beta(n)`` on ``O``.

Loop's own weight is ``beta(n) = (5/8 - (3/8 + cos(2 pi/n)/4)^2)/n`` (:func:`loop`); Warren's
simpler choice is ``3/(8n)`` for ``n > 3`` and ``3/16`` for ``n = 3`` (:func:`loop_warren`). The
cosine stays exact: at a concrete valence it is an algebraic number (sympy keeps ``cos(2 pi/7)``
unevaluated; :mod:`symdecomp.algebra.cyclotomic` computes with it exactly).

>>> loop().vertex_rule.each_a.subs(N, 6)
1/16
>>> loop_warren().vertex_rule.each_a.subs(N, 3), loop_warren().vertex_rule.each_a.subs(N, 8)
(3/16, 3/64)
"""

from __future__ import annotations

import functools

import sympy as sp

from symdecomp.schemes.lattice import TRIANGLE
from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule
from symdecomp.symbols import n as N

__all__ = ["loop_beta", "warren_beta", "loop", "loop_warren", "triangle_scheme"]

R = sp.Rational


def loop_beta() -> sp.Expr:
    """Loop's vertex weight ``(5/8 - (3/8 + cos(2 pi/n)/4)^2)/n``."""
    return (R(5, 8) - (R(3, 8) + sp.cos(2 * sp.pi / N) / 4) ** 2) / N


def warren_beta() -> sp.Expr:
    """Warren's vertex weight: ``3/16`` at ``n = 3``, ``3/(8n)`` otherwise."""
    return sp.Piecewise((R(3, 16), sp.Eq(N, 3)), (R(3, 8) / N, True))


def triangle_scheme(name: str, beta, *, edge_end=None, edge_side=None) -> Scheme:
    """A Loop-type scheme: vertex weight ``beta`` (an expression in ``n``), edge weights ``edge_end``, ``edge_side``.

    The edge weights default to Loop's ``3/8`` and ``1/8``; the edge rule must be affine:
    ``2 edge_end + 2 edge_side = 1``.
    """
    edge_end = R(3, 8) if edge_end is None else edge_end
    edge_side = R(1, 8) if edge_side is None else edge_side
    edge = Stencil.from_weights(edge_end, {0: edge_end, -1: edge_side, 1: edge_side}, {}, name="edge rule")
    vertex = VertexRule.affine(beta, 0, name="vertex rule")
    return Scheme(name, edge, None, vertex, lattice=TRIANGLE)


def loop() -> Scheme:
    """Loop's scheme with Loop's original vertex weight (built and validated once: a scheme is immutable)."""
    return _loop()


@functools.lru_cache(maxsize=1)
def _loop() -> Scheme:
    return triangle_scheme("loop", loop_beta())


def loop_warren() -> Scheme:
    """Loop's scheme with Warren's vertex weight ``3/(8n)`` (``3/16`` at ``n = 3``)."""
    return triangle_scheme("loop-warren", warren_beta())
