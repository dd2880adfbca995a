"""Reference values for the patch evaluator: limit positions of refined vertices at dyadic parameters.

The vertex at lattice point ``(i, j)`` after ``L`` refinements of the patch's ring mesh sits at
the parameter ``(i/2^L, j/2^L)`` of the patch; its limit position (the scheme's limit mask on its
1-ring) is what the evaluator must return there. :func:`dyadic_limits` computes these exactly
with the toolkit's own refinement (:func:`~symdecomp.schemes.refinement.refine`) and limit masks
(:func:`~symdecomp.analysis.masks.limit_masks_at`).
"""

from __future__ import annotations

from fractions import Fraction

import mpmath

from symdecomp.algebra.cyclotomic import to_acb
from symdecomp.algebra.numbers import to_fraction, to_mpf
from symdecomp.analysis.masks import limit_masks_at
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.mesh import QuadMesh, TriangleMesh, triangle_ring_labels, triangle_ring_mesh
from symdecomp.schemes.patch import centre_weights, patch_mesh, position_mask, triangle_patch_rows
from symdecomp.schemes.refinement import refine, refine_triangles, triangle_mesh_rules
from symdecomp.schemes.scheme import Scheme

__all__ = [
    "dyadic_limits", "numpy_baseline", "opensubdiv_dyadic_errors", "refined_lattice", "baseline_error",
    "triangle_patch_mesh", "refined_triangle_lattice", "triangle_dyadic_limits", "exact_to_mpf",
]


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
            masks[m] = [to_fraction(w) for w in limit_masks_at(scheme, m).position]
        limits[(u, v)] = tuple(sum(w * p[c] for w, p in zip(masks[m], ring)) for c in range(len(ring[0])))
    return control, limits


def triangle_patch_mesh(n: int, values=None):
    """``(mesh, columns)``: the 3-ring triangle mesh of valence ``n`` and the ids of the ``n + 6`` control points."""
    mesh = triangle_ring_mesh(n, 3, values)
    ids = {lab: i for i, lab in enumerate(triangle_ring_labels(n, 3))}
    return mesh, [ids[lab] for lab in triangle_patch_rows(n)[: n + 6]]


def refined_triangle_lattice(mesh: TriangleMesh, scheme: Scheme, level: int):
    """``(mesh_L, ids)``: the triangle mesh after ``level`` exact refinements and the ids of the patch's
    lattice points ``(i, j)``, ``i + j <= 2^L`` (the patch is the ring mesh's sector 0).

    The centre's vertex rule is applied exactly (``Q(zeta_2n)`` when irrational, e.g. Loop's
    ``cos(2 pi/n)``), so every value is exact.
    """
    n = len(mesh.one_ring(0)[1])
    rules = triangle_mesh_rules(scheme)
    centre = centre_weights(scheme, n)
    weights = lambda m: centre if m == n else rules.vertex_weights(m)  # noqa: E731
    ids = {(0, 0): 0, (1, 0): mesh.one_ring(0)[1][0], (0, 1): mesh.one_ring(0)[1][1]}
    for lev in range(1, level + 1):
        step = refine_triangles(mesh, rules, vertex_weights=weights)
        new = {}
        for u in range(2**lev + 1):
            for v in range(2**lev + 1 - u):
                if u % 2 == 0 and v % 2 == 0:
                    new[(u, v)] = step.vertex_point[ids[(u // 2, v // 2)]]
                    continue
                if u % 2 and v % 2:  # the diagonal edge
                    a, b = ((u - 1) // 2, (v + 1) // 2), ((u + 1) // 2, (v - 1) // 2)
                else:
                    a, b = ((u - u % 2) // 2, (v - v % 2) // 2), ((u + u % 2) // 2, (v + v % 2) // 2)
                new[(u, v)] = step.edge_point[frozenset((ids[a], ids[b]))]
        mesh, ids = step.mesh, new
    return mesh, ids


def _refined_quad_patch(scheme: Scheme, n: int, level: int, values):
    mesh, vid, columns = patch_mesh(n, values)
    return (mesh, columns, *refined_lattice(mesh, vid, scheme, level))


def _refined_triangle_patch(scheme: Scheme, n: int, level: int, values):
    mesh, columns = triangle_patch_mesh(n, values)
    return (mesh, columns, *refined_triangle_lattice(mesh, scheme, level))


#: ``(mesh, control point ids, refined mesh, {lattice point: id})`` of the patch's ring mesh refined ``level`` times.
_REFINED_PATCH = {BICUBIC: _refined_quad_patch, BOX_SPLINE: _refined_triangle_patch}


def exact_to_mpf(x):
    """A Fraction or a (real) cyclotomic number as an mpmath number at the current precision."""
    if isinstance(x, Fraction):
        return to_mpf(x)
    return mpmath.mpf(to_acb(x, mpmath.mp.prec + 32).real.mid().str(mpmath.mp.dps + 10, radius=False))


def triangle_dyadic_limits(scheme: Scheme, n: int, level: int, values) -> tuple[list, dict]:
    """``(control_points, limits)`` of the Loop patch: control values and ``{(i, j): exact limit}``.

    Limits are the position mask (:func:`~symdecomp.schemes.patch.position_mask`, at
    valence ``n`` for the centre, 6 elsewhere) on the 1-ring of the vertex at ``(i/2^L, j/2^L)``
    after ``L`` exact refinements; values are Fractions or elements of ``Q(zeta_2n)``.
    """
    mesh, columns = triangle_patch_mesh(n, values)
    control = [mesh.values[c] for c in columns]
    refined, ids = refined_triangle_lattice(mesh, scheme, level)
    masks = {}
    limits = {}
    for key, x in ids.items():
        _, ring = refined.one_ring(x)
        if len(ring) not in masks:
            masks[len(ring)] = position_mask(scheme, len(ring))
        w_o, w_a = masks[len(ring)]
        val = refined.values[x]
        limits[key] = tuple(w_o * val[c] + w_a * sum((refined.values[r][c] for r in ring[1:]), refined.values[ring[0]][c]) for c in range(len(val)))
    return control, limits


def opensubdiv_dyadic_errors(scheme: Scheme, n: int, level: int, evaluator, seed: int = 0) -> tuple[float, float]:
    """``(match, error)`` against OpenSubdiv at the dyadic points ``(i/2^L, j/2^L)`` of the patch.

    The ring mesh gets random values; OpenSubdiv refines it ``level`` times and takes limits
    (``Far::PrimvarRefiner::Limit``). Each lattice vertex of the toolkit's exact refinement is
    found among OpenSubdiv's vertices by its position (``match``: the largest distance, which
    must be at rounding level), and ``evaluator`` (a float64
    :class:`~symdecomp.analysis.evaluation.PatchEvaluator`) is compared with OpenSubdiv's limit
    there (``error``: the largest coordinate difference). Needs the OpenSubdiv bridge. Catmull-Clark
    on the ``(2n + 8)``-point patch's quad mesh, Loop (triangle schemes) on the ``(n + 6)``-point one.
    """
    import random

    import numpy as np

    from symdecomp.verify.opensubdiv import osd_limit_points

    rnd = random.Random(seed)
    values = lambda s, u, v: tuple(Fraction(rnd.randint(-2**20, 2**20), 2**20) for _ in range(3))  # noqa: E731
    mesh, columns, refined, ids = scheme.lattice.select(_REFINED_PATCH, "the refined patch")(scheme, n, level, values)
    points, limits = osd_limit_points(mesh, level)
    keys = sorted(ids)
    with mpmath.workdps(30):
        ours = np.array([[float(exact_to_mpf(x)) for x in refined.values[ids[k]]] for k in keys])
    dist = ((ours[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
    nearest = dist.argmin(axis=1)
    match = float(np.sqrt(dist[np.arange(len(keys)), nearest]).max())
    control = np.array([[float(x) for x in mesh.values[c]] for c in columns])
    u = np.array([a / 2**level for a, _ in keys])
    v = np.array([b / 2**level for _, b in keys])
    got = evaluator.evaluate(control, u, v)["point"]
    return match, float(np.abs(got - limits[nearest]).max())


def numpy_baseline(scheme: Scheme, n: int):
    """``(seconds, evaluator)``: the patch data from ``numpy.linalg.eig`` in float64, as others compute it.

    Complex arrays (``eig`` gives complex bases for repeated eigenvalues); take the real part of
    what the evaluator returns. ``seconds`` times ``eig``, ``inv`` and the tables only.
    """
    import time

    import numpy as np

    from symdecomp.analysis.evaluation import PatchEvaluator, patch_masks
    from symdecomp.schemes.patch import patch_matrices

    p = patch_matrices(scheme, n)
    size = p.size
    ext = np.array([[float(p.extended[i, j]) for j in range(size)] for i in range(size + 9)])
    start = time.perf_counter()
    values, vectors = np.linalg.eig(ext[:size])
    inverse = np.linalg.inv(vectors)
    beyond = ext @ vectors
    phi = np.stack([beyond[list(rows)].T for rows in p.subpatches])
    seconds = time.perf_counter() - start
    return seconds, PatchEvaluator(n, values, inverse, phi, *patch_masks(scheme, n))


def baseline_error(certified, baseline, samples: int = 200, seed: int = 0) -> float:
    """Largest coordinate difference of the two evaluators' points at random parameters and control points."""
    import numpy as np

    rng = np.random.default_rng(seed)
    control = rng.uniform(-1, 1, size=(certified.values.size, 3))
    u, v = rng.random(samples), rng.random(samples)
    diff = baseline.evaluate(control, u, v)["point"].real - certified.evaluate(control, u, v)["point"]
    return float(np.abs(diff).max())
