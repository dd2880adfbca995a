"""The characteristic map of a scheme of the zoo, as ``c1 --plot`` draws it: its patches, or its refined control net.

The control points are the zoo's engine's (:func:`~symdecomp.verify.zoo_characteristic.characteristic_points`: the
subdominant eigenvector of the frequency block, rotated sector by sector), under Reif's spectral conditions
(:func:`~symdecomp.verify.zoo_characteristic.spectral_conditions`; where they fail there is no map, and the error
says why). What is drawn from them depends on the scheme's model, never on its name:

* where the regular part is a spline this package evaluates (:func:`~symdecomp.verify.c1_zoo.spline_route`: the
  biquadratic B-spline of a dual quad scheme such as Doo-Sabin), the ring of patches the C1 test certifies
  (:func:`~symdecomp.verify.c1_dual.ring_patches`), each as its bicubic Bezier form
  (:func:`~symdecomp.verify.c1_dual.biquadratic_to_bicubic`): iso-parameter lines, and the sides that face the
  centre n-gon as the ring's inner boundary;
* where the regular part is a C1 piecewise quadratic on the four-direction mesh derived from the corner rule
  (:func:`~symdecomp.verify.c1_zoo.four_direction_route`: mid-edge's Zwart-Powell box spline), the same ring with
  each cell's four quadratic triangles (:func:`~symdecomp.verify.c1_four_direction.triangle_nets`): iso-parameter
  lines across the cell, and the sides that face the centre n-gon;
* otherwise (interpolatory, sqrt(3), a user's file) the control net on the neighbourhood one ring deeper than
  the smallest invariant one (each step loses what the local mesh cannot compute), refined :data:`REFINEMENTS` times by
  the scheme's own rules (:func:`~symdecomp.schemes.topology.refine_step`, a multiple of the steps that return the
  lattice): the refined net's faces joined to the centre (a local mesh's step also computes islands far out), and the
  boundary of the hole it leaves at the centre (the centre face, or the
  faces around the centre vertex) as the inner boundary. A net is not the map: the figure says which it drew.

The points are the balls' midpoints, in floating point: a picture, not a certificate.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> net = zoo_map_curves(load_zoo("modified-butterfly"), 4)
>>> print(net["drawn"])
the control net refined 3 times by the scheme's rules
>>> len(net["inner"][0]) - 2     # the hole: the 4 points of the refined 1-ring, closed, then a NaN
4
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import sympy as sp

from symdecomp.algebra.triangle_bezier import bernstein
from symdecomp.analysis.zoo_matrix import MAX_DEPTH, ZooMatrix, zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.errors import NotApplicableError
from symdecomp.output.plotting.characteristic import bicubic_points
from symdecomp.output.plotting.spectrum_chart import as_complex
from symdecomp.schemes.four_direction import OFFSETS, FourDirectionPatch, cell_triangle
from symdecomp.schemes.halfedge import HalfedgeMesh
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.schemes.topology import refine_step, topology_of
from symdecomp.validate import check_int, check_type, check_valence
from symdecomp.verify.c1_dual import biquadratic_to_bicubic, ring_patches
from symdecomp.verify.c1_four_direction import triangle_nets
from symdecomp.verify.c1_zoo import four_direction_route, spline_route
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import characteristic_points, engine_neighbourhood, real_matrix, spectral_conditions

__all__ = ["REFINEMENTS", "zoo_map_curves", "refined_net", "hole_boundary"]

#: How many times the control net is refined (rounded up to a multiple of the scheme's steps).
REFINEMENTS = 3

Curves = dict[str, Any]


def _side(name: str, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The parameters ``(s, t)`` of a patch's side as :class:`~symdecomp.verify.c1_dual.RingPatch` names it (``u0``: ``u = 0``)."""
    end = np.full(1, float(name[1]))
    return (end, t) if name[0] == "u" else (t, end)


def zoo_map_curves(scheme: StencilScheme, n: int, *, samples: int = 5, refinements: int = REFINEMENTS) -> Curves:
    """``{"lines", "inner", "rays", "drawn"}``: complex arrays (NaN between pieces) as
    :func:`~symdecomp.output.plotting.characteristic.ring_curves` gives them, and what was drawn, in words."""
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    n = check_valence(n)
    refinements = check_int(refinements, "refinements", minimum=1, maximum=5)
    if spline_route(scheme) is None:
        return _patch_curves(scheme, n, check_int(samples, "samples", minimum=2, maximum=64))
    if scheme.topology == "dual" and isinstance(patch := four_direction_route(scheme), FourDirectionPatch):
        return _four_direction_curves(scheme, n, check_int(samples, "samples", minimum=2, maximum=64), patch)
    return _net_curves(scheme, n, refinements)


def _no_map(n: int, reason: str) -> NotApplicableError:
    return NotApplicableError(f"n = {n}: {reason}")


def _patch_curves(scheme: StencilScheme, n: int, samples: int) -> Curves:
    """The ring of biquadratic patches the C1 test certifies (module docstring)."""
    nb = engine_neighbourhood(scheme, n)
    if nb.spectral.status is not C1Verdict.C1 or not nb.points:
        raise _no_map(n, nb.spectral.reason)
    t, grid = np.linspace(0.0, 1.0, 4 * samples + 1), np.linspace(0.0, 1.0, samples)
    lines, inner = [], []
    for patch in ring_patches(nb.mesh):
        z = np.array(biquadratic_to_bicubic([[as_complex(nb.points[v]) for v in row] for row in patch.grid]))
        for g in grid:
            lines += [bicubic_points(z, np.array([g]), t)[0], bicubic_points(z, t, np.array([g]))[:, 0]]
        inner += [bicubic_points(z, *_side(side, t)).ravel() for side in patch.hole_sides]
    return {"lines": lines, "inner": inner, "rays": [], "drawn": "the ring of biquadratic B-spline patches"}


#: A side of the cell (``u0``: ``u = -1/2``, as :class:`~symdecomp.verify.c1_dual.RingPatch` names it) at ``t``.
_CELL_SIDES: dict[str, Callable[[float], tuple[float, float]]] = {
    "u0": lambda t: (-0.5, t), "u1": lambda t: (0.5, t), "v0": lambda t: (t, -0.5), "v1": lambda t: (t, 0.5)}


def _four_direction_curves(scheme: StencilScheme, n: int, samples: int, patch: FourDirectionPatch) -> Curves:
    """The ring of four-direction patches the C1 test certifies (module docstring)."""
    nb = engine_neighbourhood(scheme, n)
    if nb.spectral.status is not C1Verdict.C1 or not nb.points:
        raise _no_map(n, nb.spectral.reason)
    t, grid = np.linspace(-0.5, 0.5, 4 * samples + 1), np.linspace(-0.5, 0.5, samples)
    lines, inner = [], []
    for ring_patch in ring_patches(nb.mesh):
        values = {b: nb.points[ring_patch.grid[1 + b[0]][1 + b[1]]] for b in OFFSETS}
        nets = [[as_complex(c) for c in net] for net in triangle_nets(patch, values)]

        def at(x: float, y: float, nets: list[list[complex]] = nets) -> complex:
            k, u, v = cell_triangle((x, y))
            return complex(sum(c * w for c, w in zip(nets[k], bernstein(2, u, v))))

        for g in grid:
            lines += [np.array([at(g, s) for s in t]), np.array([at(s, g) for s in t])]
        inner += [np.array([at(*_CELL_SIDES[side](s)) for s in t]) for side in ring_patch.hole_sides]
    return {"lines": lines, "inner": inner, "rays": [], "drawn": "the ring of piecewise quadratic patches on the four-direction mesh"}


def _net_curves(scheme: StencilScheme, n: int, refinements: int) -> Curves:
    """The control net refined by the scheme's rules (module docstring)."""
    zm = zoo_matrix(scheme, n, min(MAX_DEPTH, zoo_matrix(scheme, n).depth + 1))  # a ring more: refining loses the outer one
    spectral = spectral_conditions(zoo_spectrum(scheme, n, jordan=False), n, real_matrix=real_matrix(zm))
    if spectral.status is not C1Verdict.C1 or spectral.subdominant is None:
        raise _no_map(n, spectral.reason)
    points = characteristic_points(zm, spectral.subdominant)
    if points is None:
        raise _no_map(n, "the subdominant eigenvector could not be solved in the frequency block at this precision")
    steps = -(-refinements // scheme.steps) * scheme.steps
    mesh, start, position = refined_net(scheme, zm, {v: as_complex(z) for v, z in points.items()}, steps)
    lines = [_closed([position[v] for v in mesh.faces[f]]) for f in _connected(mesh, start)]
    return {"lines": [np.concatenate(lines)] if lines else [], "inner": [_closed(hole_boundary(mesh, start, zm.neighbourhood.centred, position))],
            "rays": [], "drawn": f"the control net refined {steps} times by the scheme's rules"}


def refined_net(scheme: StencilScheme, zm: ZooMatrix, points: dict[int, complex],
                steps: int) -> tuple[HalfedgeMesh, int, dict[int, complex]]:
    """``(mesh, start, points)``: the neighbourhood's net with ``points`` refined ``steps`` times by the scheme's rules
    (only the points the local mesh computes), and the halfedge at the centre that continues the neighbourhood's start."""
    topology, nb = topology_of(scheme), zm.neighbourhood
    mesh, start = nb.mesh, nb.start
    weights: dict[sp.Expr, complex] = {}
    for step in range(steps):
        st = refine_step(scheme, mesh, regular=nb.regular_valence)
        origin, tip = topology.track(mesh, start, step % scheme.steps)
        for row in st.rows.values():
            for w in row.values():
                if w not in weights:
                    weights[w] = complex(sp.N(w, 17))
        points = {i: sum((weights[w] * points[u] for u, w in row.items()), 0j) for i, row in st.rows.items()}
        mesh, start = st.mesh, st.mesh.by_edge[(st.ids[origin], st.ids[tip])]
    return mesh, start, points


def _connected(mesh: HalfedgeMesh, start: int) -> list[int]:
    """The faces joined to the centre's through edges, in order (a local mesh's step also computes islands far out)."""
    first = mesh.face[start]
    assert first is not None  # the tracked halfedge at the centre is inside the neighbourhood
    seen, todo = {first}, [first]
    while todo:
        for h in mesh.face_halfedges[todo.pop()]:
            f = mesh.face[mesh.twin[h]]
            if f is not None and f not in seen:
                seen.add(f)
                todo.append(f)
    return sorted(seen)


def hole_boundary(mesh: HalfedgeMesh, start: int, centred: str, position: dict[int, complex]) -> list[complex]:
    """The boundary of the centre face (``centred == "face"``), or of the faces around the centre vertex, counter-clockwise
    from the halfedge ``start`` at the centre."""
    if centred == "face":
        return [position[mesh.origin[h]] for h in mesh.around_face(start)]
    ring = mesh.ring(start)
    assert ring is not None  # the centre of a refined neighbourhood is interior (zoo_matrix's closure)
    return [position[mesh.origin[h]] for h in ring for h in mesh.around_face(h)[1:-1]]


def _closed(points: list[complex]) -> np.ndarray:
    """A closed polyline, then a NaN: pieces joined in one array are drawn apart."""
    return np.array([*points, points[0], complex(np.nan, np.nan)])
