"""The characteristic map's control net on a triangle neighbourhood, grown and refined by the scheme's regular rules.

The engine's eigenvector (:func:`~symdecomp.verify.zoo_characteristic.characteristic_points`) gives ``X`` on the
neighbourhood of depth ``K`` around the centre vertex. Sector 0 is the wedge ``x e_1 + y w`` with ``x >= 1, y >= 0``
(``e_1`` the start halfedge's direction, ``w`` the next spoke counter-clockwise); a point ``(x, y)`` is reached by
``x`` straight steps along the spoke and ``y`` after a turn of one sixth (:func:`wedge_points`; a straight step at a
regular vertex leaves it opposite to where it came in). The neighbouring sectors are the wedges turned by one sixth
each way, and the rotation by one sector multiplies ``X`` by ``rho = zeta^(j s)`` (read from the labels), so
:class:`WedgeNet` holds sector 0 only and answers any point of the three wedges.

One step of the regular rules (:class:`~symdecomp.verify.zorin_bounds.DifferenceBounds`' mask: the scheme's steps
that return the lattice to itself, refining it by ``1/a``) makes the next level's points whose stencil keeps clear of
the centre. Since ``S X = lambda X`` on the neighbourhood's labels, the
level-1 values past the known radius, divided by ``lambda``, are the level-0 values there (:func:`grow`): the net is
extended outwards as far as the test needs, then refined ``m`` times on an annulus (:func:`refine`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from fractions import Fraction

import flint

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.halfedge import HalfedgeMesh
from symdecomp.verify.zorin_bounds import DifferenceBounds, Point, turn

__all__ = ["WedgeNet", "wedge_points", "grow", "refine"]


def _ccw(mesh: HalfedgeMesh, g: int) -> int:
    """The next outgoing halfedge counter-clockwise around ``g``'s origin."""
    return mesh.twin[mesh.prev[g]]


def _straight(mesh: HalfedgeMesh, h: int) -> int:
    """The halfedge that continues ``h`` straight on through its (regular) tip: three turns from the way back."""
    g = mesh.twin[h]
    for _ in range(3):
        g = _ccw(mesh, g)
    return g


def wedge_points(mesh: HalfedgeMesh, start: int, depth: int) -> tuple[dict[Point, int], int]:
    """``(x, y) -> vertex`` for sector 0 up to graph distance ``depth``, and the first point of the next spoke."""
    out: dict[Point, int] = {}
    h = start
    for x in range(1, depth + 1):
        out[(x, 0)] = mesh.tip(h)
        if x < depth:
            g = _ccw(mesh, _straight(mesh, h))
            for y in range(1, depth - x + 1):
                out[(x, y)] = mesh.tip(g)
                if x + y < depth:
                    g = _straight(mesh, g)
            h = _straight(mesh, h)
    return out, mesh.tip(_ccw(mesh, start))


@dataclass
class WedgeNet:
    """Sector 0 of one level's net, ``(x, y) -> X`` (complex balls); ``rho`` the factor of the next sector."""

    values: dict[Point, flint.acb]
    rho: flint.acb

    def value(self, q: Point) -> flint.acb:
        """``X`` at any point of the sectors -1, 0, 1 (0 at the centre: the eigenvector's frequency is not 0)."""
        if q == (0, 0):
            return flint.acb(0)
        if q[0] >= 1 and q[1] >= 0:
            return self.values[q]
        back = (q[0] + q[1], -q[0])  # turned back by one sixth: sector 1 -> sector 0
        if back[0] >= 1 and back[1] >= 0:
            return self.rho * self.values[back]
        on = turn(q)  # sector -1 -> sector 0
        if on[0] >= 1 and on[1] >= 0:
            return self.values[on] / self.rho
        raise InvalidSchemeError(f"the point {q} is not in the three sectors around sector 0 (the ring is too close to "
                                 "the centre)")


def _step(net: WedgeNet, mask: Mapping[Point, flint.fmpq], a: int, low: int, high: int) -> dict[Point, flint.acb]:
    """The next level's sector-0 points with ``low <= |y| <= high``."""
    out = {}
    for x in range(1, high + 1):
        for y in range(0, high - x + 1):
            if x + y < low:
                continue
            total = flint.acb(0)
            for u, w in mask.items():
                d0, d1 = x - u[0], y - u[1]
                if d0 % a == 0 and d1 % a == 0:
                    total += w * net.value((d0 // a, d1 // a))
            out[(x, y)] = total
    return out


def _fmpq_mask(mask: Mapping[Point, Fraction]) -> dict[Point, flint.fmpq]:
    return {u: flint.fmpq(a.numerator, a.denominator) for u, a in mask.items()}


def grow(net: WedgeNet, radius: int, lam: flint.acb, bounds: DifferenceBounds, target: int) -> tuple[WedgeNet, int]:
    """Extend a level-0 net known up to ``radius`` to at least ``target``: ``X = (S X) / lambda`` outside."""
    fm, a, reach = _fmpq_mask(bounds.mask), bounds.dilation, bounds.reach
    while radius < target:
        high = a * radius - reach
        if high <= radius or radius + 1 < bounds.clear_radius:  # the new points keep their stencils clear of the centre
            raise InvalidSchemeError(f"the net of radius {radius} does not grow: the regular stencils reach {reach}")
        new = _step(net, fm, a, radius + 1, high)
        net = replace(net, values={**net.values, **{q: v / lam for q, v in new.items()}})  # a subclass stays one
        radius = high
    return net, radius


def refine(net: WedgeNet, low: int, high: int, bounds: DifferenceBounds) -> tuple[WedgeNet, int, int]:
    """One level finer on the annulus the old one ``[low, high]`` determines, away from the centre's stencils."""
    a, reach = bounds.dilation, bounds.reach
    new_low = max(a * low + reach, bounds.clear_radius)
    new_high = a * high - reach
    return replace(net, values=_step(net, _fmpq_mask(bounds.mask), a, new_low, new_high)), new_low, new_high

