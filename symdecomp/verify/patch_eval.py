"""Reference values for the patch evaluator: limit positions of refined vertices at dyadic parameters.

The vertex at lattice point ``(i, j)`` after ``L`` refinements of the patch's ring mesh sits at
the parameter ``(i/2^L, j/2^L)`` of the patch; its limit position (the scheme's limit mask on its
1-ring) is what the evaluator must return there. :func:`dyadic_limits` computes these exactly
with the toolkit's own refinement (:func:`~symdecomp.schemes.mesh.refine`) and limit masks
(:func:`~symdecomp.analysis.masks.limit_masks_at`).
"""

from __future__ import annotations

from fractions import Fraction

from symdecomp.analysis.masks import limit_masks_at
from symdecomp.schemes.mesh import QuadMesh, refine
from symdecomp.schemes.patch import patch_mesh
from symdecomp.schemes.scheme import Scheme

__all__ = ["refined_lattice", "dyadic_limits"]


def refined_lattice(mesh: QuadMesh, vid, scheme: Scheme, level: int):
    """``(mesh_L, ids)``: the mesh after ``level`` refinements and the ids of lattice points ``0..2^L``."""
    ids = {(u, v): vid(u, v) for u in range(2) for v in range(2)}
    for lev in range(1, level + 1):
        step = refine(mesh, scheme)
        corners = {frozenset(f): fi for fi, f in enumerate(mesh.faces)}
        new = {}
        for u in range(2**lev + 1):
            for v in range(2**lev + 1):
                us = (u // 2,) if u % 2 == 0 else (u // 2, u // 2 + 1)
                vs = (v // 2,) if v % 2 == 0 else (v // 2, v // 2 + 1)
                old = frozenset(ids[(a, b)] for a in us for b in vs)
                if len(old) == 1:
                    new[(u, v)] = step.vertex_point[next(iter(old))]
                elif len(old) == 2:
                    new[(u, v)] = step.edge_point[old]
                else:
                    new[(u, v)] = step.face_point[corners[old]]
        mesh, ids = step.mesh, new
    return mesh, ids


def dyadic_limits(scheme: Scheme, n: int, level: int, values) -> tuple[list, dict]:
    """``(control_points, limits)``: the patch's control values and ``{(i, j): exact limit}``.

    ``values(s, u, v)`` gives the ring mesh's (exact) vertex values, as in
    :func:`~symdecomp.schemes.mesh.ring_mesh`.
    """
    mesh, vid, columns = patch_mesh(n, values)
    control = [mesh.values[c] for c in columns]
    refined, ids = refined_lattice(mesh, vid, scheme, level)
    masks = {}
    limits = {}
    for (u, v), x in ids.items():
        ring = refined.one_ring_values(x)
        m = (len(ring) - 1) // 2
        if m not in masks:
            masks[m] = [Fraction(int(w.p), int(w.q)) for w in limit_masks_at(scheme, m).position]
        limits[(u, v)] = tuple(sum(w * p[c] for w, p in zip(masks[m], ring)) for c in range(len(ring[0])))
    return control, limits
