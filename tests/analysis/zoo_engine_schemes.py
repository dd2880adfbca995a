"""Schemes written as StencilSchemes for the engine's tests (the shipped families are files; these are built in Python).

Catmull-Clark and Loop are today's ``catmull_clark()`` and ``loop()`` written as stencils, so that the
engine's spectrum can be compared with ``ring_spectrum``'s; Doo-Sabin is Doo and Sabin's corner rule.
"""

import sympy as sp

from symdecomp.schemes.stencils import J, KindRules, M, N, Rule, StencilScheme, Term

R = sp.Rational


def catmull_clark_stencils() -> StencilScheme:
    """Catmull-Clark: face points the corners' average, edge points from the ends and the two new face points."""
    face = KindRules("face", (Rule((Term(1 / M, over="face"),)),))
    edge = KindRules("edge", (Rule((Term(R(1, 4)), Term(R(1, 4), ("next",)), Term(R(1, 4), source="face"),
                                    Term(R(1, 4), ("twin",), source="face"))),))
    vertex = KindRules("vertex", (Rule((Term(1 - R(7, 4) / N), Term(R(3, 2) / N**2, ("next",), over="ring"),
                                        Term(R(1, 4) / N**2, ("next", "next"), over="ring"))),))
    return StencilScheme("catmull-clark", "quad", "primal", (face, edge, vertex))


def loop_beta(n):
    """Loop's vertex weight ``beta(n) = (5/8 - (3/8 + cos(2 pi/n)/4)^2)/n``."""
    return (R(5, 8) - (R(3, 8) + sp.cos(2 * sp.pi / n) / 4) ** 2) / n


def loop_stencils() -> StencilScheme:
    """Loop: edge points 3/8 at the ends and 1/8 at the opposite corners, vertex points ``(1 - n beta) v + beta sum a_j``."""
    edge = KindRules("edge", (Rule((Term(R(3, 8)), Term(R(3, 8), ("next",)), Term(R(1, 8), ("prev",)),
                                    Term(R(1, 8), ("twin", "prev")))),))
    vertex = KindRules("vertex", (Rule((Term(1 - N * loop_beta(N)), Term(loop_beta(N), ("next",), over="ring"))),))
    return StencilScheme("loop", "triangle", "primal", (edge, vertex))


def doo_sabin_weight(j, m):
    """Doo and Sabin's weight of corner ``j`` of an ``m``-gon in the new point of corner 0."""
    return sp.KroneckerDelta(j, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * j / m)) / (4 * m)


def doo_sabin_stencils() -> StencilScheme:
    """Doo-Sabin: one new point per face corner, weights over the face's corners."""
    corner = KindRules("corner", (Rule((Term(doo_sabin_weight(J, M), over="face"),)),))
    return StencilScheme("doo-sabin", "quad", "dual", (corner,))


def sqrt3_alpha(n):
    """Kobbelt's vertex weight ``alpha_n = (4 - 2 cos(2 pi/n))/9``."""
    return (4 - 2 * sp.cos(2 * sp.pi / n)) / 9


def sqrt3_stencils() -> StencilScheme:
    """Kobbelt's sqrt(3): face points the centroid, vertex points ``(1 - alpha_n) v + alpha_n/n sum a_j``; two steps."""
    face = KindRules("face", (Rule((Term(1 / M, over="face"),)),))
    vertex = KindRules("vertex", (Rule((Term(1 - sqrt3_alpha(N)), Term(sqrt3_alpha(N) / N, ("next",), over="ring"))),))
    return StencilScheme("sqrt3", "triangle", "sqrt3", (face, vertex), steps=2)


def butterfly_weight(j, k):
    """Zorin, Schroeder and Sweldens' weight of ring vertex ``j`` at an extraordinary end of valence ``k >= 5``."""
    return (R(1, 4) + sp.cos(2 * sp.pi * j / k) + sp.cos(4 * sp.pi * j / k) / 2) / k


def butterfly_stencils() -> StencilScheme:
    """The modified butterfly: the ten-point rule between regular ends, ``3/4`` and ring weights from an extraordinary end
    (valences 3 and 4 with their own weights); old vertices kept. Edge rules reach two rings."""
    d = sp.KroneckerDelta
    wings = [("prev", "twin", "prev"), ("next", "twin", "prev"), ("twin", "next", "twin", "prev"), ("twin", "prev", "twin", "prev")]
    regular = Rule((Term(R(1, 2)), Term(R(1, 2), ("next",)), Term(R(1, 8), ("prev",)), Term(R(1, 8), ("twin", "prev")),
                    *[Term(R(-1, 16), w) for w in wings]), origin="regular", tip="regular")
    three = Rule((Term(R(3, 4)), Term(R(5, 12) * d(J, 0) - R(1, 12) * (1 - d(J, 0)), ("next",), over="ring")), origin=3)
    four = Rule((Term(R(3, 4)), Term(R(3, 8) * d(J, 0) - R(1, 8) * d(J, 2), ("next",), over="ring")), origin=4)
    other = Rule((Term(R(3, 4)), Term(butterfly_weight(J, N), ("next",), over="ring")), origin="irregular")
    edge = KindRules("edge", (three, four, other, regular))
    vertex = KindRules("vertex", (Rule((Term(sp.Integer(1)),)),))
    return StencilScheme("modified-butterfly", "triangle", "primal", (edge, vertex), interpolatory=True)
