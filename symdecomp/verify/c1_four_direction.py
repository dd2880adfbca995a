"""Reif's test on a quad neighbourhood whose regular part is a piecewise quadratic on the four-direction mesh (Midedge).

The dual route of :mod:`symdecomp.verify.c1_dual` with another patch: the same explicit local mesh and ring (the
patches of the vertices that share a face with the centre ``n``-gon, :func:`~symdecomp.verify.c1_dual.ring_patches`,
each with its 3 x 3 control grid), but over each vertex's cell the surface is the patch derived from the scheme's
corner rule by :func:`~symdecomp.schemes.four_direction.four_direction_patch` (for Midedge the four-direction,
Zwart-Powell, box spline): four quadratic triangles, each in Bernstein-Bezier form, ``sum_b P_b c_{k, b}``.

**Regularity**: the Jacobian of each triangle (degree 2, :func:`~symdecomp.verify.bezier.triangle_jacobian_net`) of
one strict sign on every triangle of the ring (:func:`~symdecomp.verify.bezier.certify_sign_triangles`, bisection
where a ball straddles 0). The triangles (centre, ``r_k``, ``r_(k+1)``) are counter-clockwise in the cell's
``(u, v)`` frame, so their signs are the cell's. The patch is C1 (it is a box spline), so the Jacobian is continuous
across the triangles and the cells. **Injectivity**: the ring's inner boundary (the cell sides facing a centre
vertex; each is the outer edge of one triangle, a quadratic curve) traversed with the hole on its left winds once
around the origin, as in :mod:`symdecomp.verify.c1_dual`.

>>> from fractions import Fraction as F
>>> from symdecomp.schemes.four_direction import four_direction_patch
>>> from symdecomp.verify.c1_dual import DualNeighbourhood
>>> patch = four_direction_patch((F(1, 2), F(1, 4), F(0), F(1, 4)))
>>> grid = {(i, k): (F(i), F(k)) for i in range(-2, 3) for k in range(-2, 3)}  # the identity map on a 4 x 4 grid
>>> faces = tuple(((i, k), (i + 1, k), (i + 1, k + 1), (i, k + 1)) for i in range(-2, 2) for k in range(-2, 2))
>>> ring = certify_four_direction_ring(DualNeighbourhood(faces, ((0, 0),)), grid, patch)
>>> ring.status, ring.jacobian_sign, ring.patches, ring.winding_number
('regular', 1, 8, 1)
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import flint

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.four_direction import OFFSETS, FourDirectionPatch
from symdecomp.verify.bezier import certify_sign_triangles, curve_angle, triangle_jacobian_net
from symdecomp.verify.c1_dual import DualNeighbourhood, RingCertificate, control_ball, ring_patches, winding_of

__all__ = ["FOUR_DIRECTION_METHOD", "HOLE_TRIANGLE", "triangle_nets", "certify_four_direction_ring"]

#: The method, as reported with each verdict of this route.
FOUR_DIRECTION_METHOD = ("Reif's test on the characteristic map's ring of patches derived from the corner rule as a piecewise "
                         "quadratic on the four-direction mesh (Midedge: the Zwart-Powell box spline; four quadratic "
                         "triangles per cell in Bernstein-Bezier form): the Jacobian (degree 2 per triangle) of one strict "
                         "sign in interval arithmetic with bisection; injective by winding number 1 of the ring's inner boundary")

#: The triangle whose outer edge is each side of the cell (``u1``: ``u = 1/2``, then the top, the left, the bottom).
HOLE_TRIANGLE = {"u1": 0, "v1": 1, "u0": 2, "v0": 3}
#: The outer edge's coefficients (``w = 0``: from ``r_k`` to ``r_(k+1)``) reversed, so that the cell is on the right.
_EDGE = (5, 4, 2)


def triangle_nets(patch: FourDirectionPatch, values: Mapping[tuple[int, int], flint.acb]) -> list[list[flint.acb]]:
    """The four triangles' quadratic Bezier nets over the cell whose control grid has ``values[b]`` at offset ``b``."""
    nets = []
    for k in range(4):
        net = [flint.acb(0)] * 6
        for m, b in enumerate(OFFSETS):
            for i, c in enumerate(patch.coefficients[k][m]):
                if c:
                    net[i] += values[b] * flint.fmpq(c.numerator, c.denominator)
        nets.append(net)
    return nets


def certify_four_direction_ring(mesh: DualNeighbourhood, points: Mapping[Any, Any], patch: FourDirectionPatch, *,
                                max_depth: int = 6) -> RingCertificate:
    """Certify the characteristic map's ring of ``patch`` on ``mesh`` (module docstring) at the current FLINT precision;
    a triangle is bisected up to ``2 max_depth`` times (two bisections halve it as a tensor split does a square)."""
    patches = ring_patches(mesh)
    jacobians = []
    angle: flint.arb | None = flint.arb(0)
    for ring_patch in patches:
        try:
            values = {b: control_ball(points[ring_patch.grid[1 + b[0]][1 + b[1]]], ring_patch.grid[1 + b[0]][1 + b[1]])
                      for b in OFFSETS}
        except KeyError as e:
            raise InvalidMeshError(f"points: no control point for vertex {e.args[0]!r:.20}") from None
        nets = triangle_nets(patch, values)
        for net in nets:
            x, y = [z.real for z in net], [z.imag for z in net]
            jacobians.append(triangle_jacobian_net(x, y, 2))
        for side in ring_patch.hole_sides:
            piece = curve_angle([nets[HOLE_TRIANGLE[side]][i] for i in _EDGE])
            angle = None if angle is None or piece is None else angle + piece
    sign = certify_sign_triangles(jacobians, 2, 2 * max_depth)
    winding = winding_of(angle)
    if sign.status in ("changes", "undecided"):
        where = None
        if sign.where is not None:
            p, corners = sign.where
            v = patches[p // 4].vertex
            where = (f"the patch of vertex {v!r} (orbit {mesh.labels.get(v, '?')}), triangle {p % 4}, the piece with corners "
                     f"{', '.join(f'({a:g}, {b:g})' for a, b in corners)} in the triangle's own parameters")
        return RingCertificate(sign.status, None, None, sign.depth, winding, len(patches), where)
    s = 1 if sign.status == "positive" else -1
    return RingCertificate("regular", s, sign.lower_bound, sign.depth, winding, len(patches))
