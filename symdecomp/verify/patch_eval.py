"""Reference values for the patch evaluator: limit positions of refined vertices at dyadic parameters.

The vertex at lattice point ``(i, j)`` after ``L`` refinements of the patch's ring mesh sits at
the parameter ``(i/2^L, j/2^L)`` of the patch; its limit position (the scheme's limit mask on its
1-ring) is what the evaluator must return there. :func:`dyadic_limits` computes these exactly
with the toolkit's own refinement (:func:`~symdecomp.schemes.refinement.refine`) and limit masks
(:func:`~symdecomp.analysis.masks.limit_masks_at`).

At a boundary or corner vertex (a sector, :class:`~symdecomp.schemes.sector.SharpVertex`), :func:`dyadic_check`
does not use the evaluator's sub-patches, phantom points or matrix powers: a random exact
control net on the ``R``-ring of the vertex is refined ``m`` times by the ``R``-ring matrix
(:func:`~symdecomp.schemes.sector.exact_sharp_matrix`, the whole mesh with the sharp rules), and at the
lattice point ``(p, q)`` of face ``s`` of the refined net, a regular vertex, the limit position is its
1-ring times the limit mask of a regular vertex: the exact left eigenvector for 1 of the 1-ring matrix of
a smooth valence-4 (quads) or 6 (triangles) vertex, or of a boundary vertex with 2 (quads) or 3
(triangles) faces on a boundary ray. That is the patch's point at ``(u, v) = (p/2^m, q/2^m)``. At
``(0, 0)`` the reference is the vertex's own limit mask applied to the net.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> r = dyadic_check(catmull_clark(), SharpVertex.corner(2, "quad"), levels=(1,), seed=1)
>>> r["points"], r["exact_mismatches"], r["float_error"] < 1e-13
(17, 0, True)

The crease, boundary and corner evaluation data (:mod:`symdecomp.analysis.sector_evaldata`, BLZ's rules
included) are checked the same way (:func:`evaldata_dyadic_check`), the reference using neither the data's
picking matrices, their phantom points nor the eigen-decomposition: a random exact control net on the 3-ring
of the vertex is refined ``m`` times by the 3-ring matrix of the tagged mesh
(:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`, the scheme's rules for the whole mesh), and at
the lattice point ``(p, q)`` of face ``s`` with ``max(p, q) = 2`` (a regular point whose neighbourhood is
refined by the regular rules from level ``m`` on, BLZ's included) the limit position is the regular limit mask
on its 1-ring (:func:`regular_limit`: the smooth valence-4 vertex's, or the crease vertex's on a sharp ray,
each the exact left eigenvector of its 1-ring matrix). That is the patch's point
at ``(u, v) = (p / 2^m, q / 2^m)``. With irrational rules (BLZ, ``k >= 4``) the reference and the data are Arb
balls containing the exact values: they agree when the balls overlap and are narrower than ``2^-100``.

>>> r = evaldata_dyadic_check(catmull_clark(), SharpVertex.crease(2, 2, "quad"), levels=(1,))
>>> r["points"], r["mismatches"]
(20, 0)
"""

from __future__ import annotations

import random
from fractions import Fraction

import flint
import mpmath

from symdecomp.algebra.cyclotomic import to_acb
from symdecomp.algebra.numbers import to_fmpq, to_fraction, to_mpf
from symdecomp.analysis.evaluation import evaluate
from symdecomp.analysis.masks import limit_masks_at
from symdecomp.analysis.sector_evaldata import PREC, SectorEvalData, real_ball, sector_evaldata
from symdecomp.analysis.sector_evaluation import evaluate as evaluate_data
from symdecomp.analysis.subpatch_data import limit_mask, sharp_patch_data
from symdecomp.errors import InternalError, InvalidInputError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice
from symdecomp.schemes.mesh import QuadMesh, TriangleMesh, triangle_ring_labels, triangle_ring_mesh
from symdecomp.schemes.patch import centre_weights, patch_mesh, position_mask, triangle_patch_rows
from symdecomp.schemes.refinement import refine, refine_triangles, triangle_mesh_rules
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import SharpVertex, exact_sharp_matrix, sharp_subdivision_matrix
from symdecomp.schemes.sector_patch import sector_point
from symdecomp.validate import check_int, check_type

__all__ = [
    "dyadic_limits", "numpy_baseline", "opensubdiv_dyadic_errors", "refined_lattice", "baseline_error",
    "triangle_patch_mesh", "refined_triangle_lattice", "triangle_dyadic_limits", "exact_to_mpf",
    "dyadic_check", "regular_limit", "evaldata_dyadic_check", "BALL_TOLERANCE",
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
    size, extended = p.size, p.extended
    if extended is None:
        raise InternalError(f"n = {n}: the patch matrices were built without the extended matrix")
    ext = np.array([[float(extended[i, j]) for j in range(size)] for i in range(size + 9)])
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


#: Rings of the reference net: lattice points up to distance ``RINGS - 1`` have their 1-ring in it.
RINGS = 3


def _random_net(vertex: SharpVertex, seed: int) -> tuple[dict, list]:
    """``(index, net)``: a random exact control net on the vertex's ``RINGS``-ring, three coordinates per point, and each
    label's row in it (the reference of both sector checks)."""
    rng = random.Random(seed)
    labels = vertex.ring_labels(RINGS)
    return {lab: i for i, lab in enumerate(labels)}, [[Fraction(rng.randint(-99, 99), rng.randint(1, 9)) for _ in range(3)] for _ in labels]


def _rows(m) -> list[dict]:
    return [{c: to_fraction(m[i, c]) for c in range(m.ncols()) if m[i, c] != 0} for i in range(m.nrows())]


def _mask(scheme: Scheme, vertex: SharpVertex) -> tuple[Fraction, ...]:
    return limit_mask(_rows(exact_sharp_matrix(scheme, vertex)), vertex.one_ring_size())


def _one_ring(lat: Lattice, p: int, q: int, where: str) -> list[tuple[int, int]]:
    """The 1-ring of ``(p, q)`` in SharpVertex order (``O``, edge neighbours, face neighbours) in face coordinates."""
    out = [(p, q)]
    for offsets in lat.neighbour_offsets:  # edge neighbours, then face neighbours, counter-clockwise from (1, 0)
        if where != "inside":  # on ray 0 the half-plane v >= 0; on ray k its mirror u >= 0, clockwise from (0, 1)
            offsets = tuple((du, dv) if where == "ray0" else (dv, du) for du, dv in offsets if dv >= 0)
        out += [(p + du, q + dv) for du, dv in offsets]
    return out


def regular_limit(scheme: Scheme, vertex: SharpVertex, face: int, p: int, q: int, value) -> list:
    """The limit position at the regular lattice point ``(p, q) != (0, 0)`` of ``face``; ``value(label)`` of the net."""
    lat, k = vertex.lattice, vertex.faces
    if face == 0 and q == 0:
        where, fan = "ray0", SharpVertex.boundary(lat.regular_boundary_faces, lat)
    elif face == k - 1 and p == 0:
        where, fan = "rayk", SharpVertex.boundary(lat.regular_boundary_faces, lat)
    else:
        where, fan = "inside", SharpVertex.dart(lat.regular_valence, lat, sharpness=0)
    mask = _mask(scheme, fan)
    total = None
    for w, (x, y) in zip(mask, _one_ring(lat, p, q, where)):
        (one, label), = sector_point(lat, k, face, x, y)  # a real point: the 1-ring of a regular point
        term = [w * c for c in value(label)]
        total = term if total is None else [a + b for a, b in zip(total, term)]
    return total


def _parameters(lat: Lattice, m: int):
    top = min(2**m, RINGS - 1)  # the 1-ring of a point at distance top is in the RINGS-ring
    for p in range(top + 1):
        for q in range(top + 1):
            if (p, q) != (0, 0) and lat.level_measure(p, q, None) <= top and lat.in_domain(Fraction(p, 2**m), Fraction(q, 2**m)):
                yield p, q


def dyadic_check(scheme: Scheme, vertex: SharpVertex, *, levels=(1, 2, 3), seed: int = 0) -> dict:
    """Evaluate every face at ``(p/2^m, q/2^m)`` (``m`` in ``levels``) and at ``(0, 0)`` against the reference.

    Returns ``{"points", "exact_mismatches", "float_error"}``: the number of parameters checked, how many
    exact (Fraction) evaluations differ from the exact reference, and the largest float64 deviation.
    """
    scheme = check_scheme(scheme)
    levels = tuple(check_int(m, "level", minimum=0, maximum=20) for m in levels)
    data = sharp_patch_data(scheme, vertex)
    index, net = _random_net(vertex, seed)
    big = _rows(exact_sharp_matrix(scheme, vertex, rings=RINGS))
    coarse, coarse_f = net[:data.size], [[float(x) for x in p] for p in net[:data.size]]
    cases: list[tuple[int, int, int, int, tuple[Fraction, ...] | None, list[list[Fraction]]]] = [(0, 0, 0, 1, data.limit, net)]
    refined, done = net, 0
    for m in sorted(set(levels)):
        while done < m:
            refined = [[sum((w * refined[c][i] for c, w in row.items()), Fraction(0)) for i in range(3)] for row in big]
            done += 1
        cases += [(s, p, q, 2**m, None, refined) for s in range(vertex.faces) for p, q in _parameters(vertex.lattice, m)]
    mismatches, error = 0, 0.0
    for s, p, q, scale, mask, values in cases:
        if mask is not None:
            if len(net) < len(mask):
                raise InvalidInputError("the reference net is smaller than the 2-ring")
            want = [sum((w * values[i][d] for i, w in enumerate(mask)), Fraction(0)) for d in range(3)]
        else:
            want = regular_limit(scheme, vertex, s, p, q, lambda lab, v=values: v[index[lab]])
        u, v = Fraction(p, scale), Fraction(q, scale)
        got = evaluate(data, s, u, v, coarse)["point"]
        mismatches += got != want
        got_f = evaluate(data, s, float(u), float(v), coarse_f)["point"]
        error = max(error, float(max(abs(a - float(b)) for a, b in zip(got_f, want)) / max(1.0, *(abs(float(b)) for b in want))))
    return {"points": len(cases), "exact_mismatches": mismatches, "float_error": error}


#: Widest ball accepted as a value (irrational rules).
BALL_TOLERANCE = 2.0**-100


def _evaldata_matrix(scheme: Scheme, vertex: SharpVertex, exact: bool):
    m = sharp_subdivision_matrix(scheme, vertex, rings=3)
    if exact:
        rational = flint.fmpq_mat(m.rows, m.cols)
        for (i, j), w in m.todok().items():
            rational[i, j] = to_fmpq(w)
        return rational
    balls = flint.arb_mat(m.rows, m.cols)
    for (i, j), w in m.todok().items():
        balls[i, j] = real_ball(w)
    return balls


def _sector(vertex: SharpVertex, face: int) -> tuple[int, int]:
    start = 0
    for k in vertex.sectors:
        if face < start + k:
            return start, k
        start += k
    raise ValueError(face)  # pragma: no cover - faces come from range(vertex.faces)


def _sector_reference(scheme, vertex, face, p, q, value):
    """The regular limit at ``(p, q)`` of ``face``, read in the face's sector as a boundary fan of its faces."""
    start, k = _sector(vertex, face)

    def local(label):
        s, u, v = label
        if (u, v) == (0, 0):
            return value(label)
        g = start + s
        return value((g % vertex.faces if vertex.closed else g, u, v))

    fan = SharpVertex.boundary(k, vertex.lattice)
    return regular_limit(scheme, fan, face - start, p, q, local)


class _Ball:
    """An Arb ball that the reference's exact mask weights (``Fraction``) multiply."""

    __slots__ = ("x",)

    def __init__(self, x):
        self.x = x

    def __rmul__(self, w):
        return _Ball(self.x * flint.arb(w.numerator) / w.denominator)

    def __add__(self, other):
        return _Ball(self.x + other.x)


def _value(x, exact: bool):
    return Fraction(int(x.p), int(x.q)) if exact else _Ball(x)


def _agree(got, want, exact: bool) -> bool:
    if exact:
        return all(Fraction(int(a.p), int(a.q)) == b for a, b in zip(got, want))
    want = [b.x for b in want]
    return all(a.overlaps(b) and a.rad() < BALL_TOLERANCE and b.rad() < BALL_TOLERANCE for a, b in zip(got, want))


def _data_levels(u, v) -> tuple:
    """Both levels whose wide ring holds ``(u, v)``: its outer edge (``2^n max = 4``) and its inner one (``= 2``)."""
    m = max(u, v)
    n = next(n for n in range(2, 64) if 2**n * m > 2)
    return (n, n - 1) if 2**n * m == 4 and n > 2 else (n,)


def evaldata_dyadic_check(scheme: Scheme, vertex: SharpVertex, *, levels=(1, 2, 3), seed: int = 0,
                 data: SectorEvalData | None = None) -> dict:
    """Evaluate every face at ``(p / 2^m, q / 2^m)``, ``max(p, q) = 2``, ``m`` in ``levels``, against the reference.

    Each point is evaluated at both levels whose wide ring holds it (on its outer and on its inner edge), so that
    every cell of the ring is read.

    ``data``: the data to check (default: :func:`~symdecomp.analysis.sector_evaldata.sector_evaldata`'s; a test
    passes altered data to see the check fail). Returns ``{"points", "mismatches", "routes"}``: the parameters
    checked, how many evaluations (by every route the data have) differ from the reference, and the routes.
    """
    scheme = check_scheme(scheme)
    levels = tuple(check_int(m, "level", minimum=1, maximum=12) for m in levels)
    data = sector_evaldata(scheme, vertex) if data is None else check_type(data, SectorEvalData, "data")
    index, net = _random_net(vertex, seed)
    routes = ("eigen", "powers") if data.decomposition is not None else ("powers",)
    points = mismatches = 0
    with flint.ctx.workprec(PREC):
        big = _evaldata_matrix(scheme, vertex, data.exact)
        kind = flint.fmpq_mat if data.exact else flint.arb_mat
        refined = kind(len(net), 3, [to_fmpq(x) for row in net for x in row])
        done = 0
        for m in sorted(set(levels)):
            while done < m:
                refined, done = big * refined, done + 1
            values = refined
            for s in range(vertex.faces):
                for p, q in ((p, q) for p in range(3) for q in range(3) if max(p, q) == 2 and max(p, q) <= 2**m):
                    want = _sector_reference(scheme, vertex, s, p, q, lambda lab, v=values: [_value(v[index[lab], c], data.exact) for c in range(3)])
                    u, v = Fraction(p, 2**m), Fraction(q, 2**m)
                    for route, level in ((r, n) for r in routes for n in _data_levels(u, v)):
                        got = evaluate_data(data, s, u, v, net[:data.size], route=route, level=level)["point"]
                        mismatches += not _agree(got, want, data.exact)
                    points += 1
    return {"points": points, "mismatches": mismatches, "routes": routes}
