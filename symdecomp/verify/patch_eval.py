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

__all__ = ["dyadic_limits", "numpy_baseline", "opensubdiv_dyadic_errors", "refined_lattice", "baseline_error"]


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


def opensubdiv_dyadic_errors(scheme: Scheme, n: int, level: int, evaluator, seed: int = 0) -> tuple[float, float]:
    """``(match, error)`` against OpenSubdiv at the dyadic points ``(i/2^L, j/2^L)`` of the patch.

    The ring mesh gets random values; OpenSubdiv refines it ``level`` times and takes limits
    (``Far::PrimvarRefiner::Limit``). Each lattice vertex of the toolkit's exact refinement is
    found among OpenSubdiv's vertices by its position (``match``: the largest distance, which
    must be at rounding level), and ``evaluator`` (a float64
    :class:`~symdecomp.analysis.evaluation.PatchEvaluator`) is compared with OpenSubdiv's limit
    there (``error``: the largest coordinate difference). Needs the OpenSubdiv bridge.
    """
    import random

    import numpy as np

    from symdecomp.verify.opensubdiv import osd_limit_points

    rnd = random.Random(seed)
    mesh, vid, columns = patch_mesh(n, lambda s, u, v: tuple(Fraction(rnd.randint(-2**20, 2**20), 2**20) for _ in range(3)))
    refined, ids = refined_lattice(mesh, vid, scheme, level)
    points, limits = osd_limit_points(mesh, level)
    keys = sorted(ids)
    ours = np.array([[float(x) for x in refined.values[ids[k]]] for k in keys])
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
