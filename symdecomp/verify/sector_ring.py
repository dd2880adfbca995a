"""The ring of a sector's characteristic map: its Bezier nets, the Jacobian's sign on them, the sweeps of its arcs.

The sector tests (:mod:`.c1_sector_matrix`, :mod:`.c1_closed_fan`, the closed-form modes' :mod:`.fourier_map`) certify the map on one
ring of patches around ``O``, face by face: the spline ring of ``3 k`` sub-patches at ``O`` (:func:`ring_nets`, the phantom
points of :mod:`symdecomp.schemes.sector_patch` at the sharp rays), or, where a modified near-edge rule makes the patches
at ``O`` non-splines, the wide ring below (:func:`wide_nets`); the Jacobian's sign by de Casteljau subdivision of its
Bernstein-Bezier coefficients (:func:`jacobian_sign`) and the arguments swept by the images of the ring's inner and outer
arcs (:func:`arc_sweeps`, what :mod:`.sector_injectivity` decides injectivity from).

**The wide ring.** With BLZ's rule for the smooth edges at ``O`` (:func:`~symdecomp.schemes.sector_patch.modified_edges`), every
level's points next to ``O`` are made by other weights than the spline's, so the level-1 patches at ``O``
(:func:`ring_nets`' ring, lattice distance ``1..2``) are not splines. A level-1 patch ``[a, a + 1] x [b, b + 1]``
(quads, face chart of sector face ``s``) with ``max(a, b) >= 2`` is: its refinement reads only points at level-2
distance ``>= 2 max(a, b) - 1 >= 3``, which the scheme makes by the regular rules (the tensor cubic B-spline's,
with the phantom points of :mod:`symdecomp.schemes.sector_patch` across the sharp rays). That last statement is
*checked exactly*: :func:`irregular_rows` compares every row of the exact refinement (level-0 2-ring to level-1
3-ring) at level-1 distance ``>= 2`` with the regular rule through :func:`~symdecomp.schemes.sector_patch.sector_net`
(the lattice is regular beyond, by translation). The ring used here is the twelve level-1 patches per face with
``2 <= max(a, b) <= 4`` side, i.e. the level-0 annulus between distance 1 and 2: ``chi(x / 2) = A chi(x)`` maps it
onto its inner neighbour, so its scaled copies cover the sector, and the injectivity argument of :mod:`.sector_injectivity`
holds with this ``R`` (inner arc at level-1 distance 2, outer at 4).

The nets need level-1 values up to distance 5: up to 3 from the exact refinement of the eigenvectors, beyond by
the regular rule from the level-0 3-ring, whose values are the level-1 ones divided by ``A`` (an eigenvector
scales by its eigenvalue from one level to the next). Triangles (Loop): the same with the level-1 triangles
between distance 2 and 4 (``u + v``), box-spline patches of their 12-point nets, and Loop's regular rules.

>>> from symdecomp.schemes.lattice import QUAD, TRIANGLE
>>> ring_faces(QUAD)[:3], len(ring_faces(QUAD)), len(ring_faces(TRIANGLE))   # 12 patches per face: the annulus
(((0, 2), (0, 3), (1, 2)), 12, 12)
"""

from __future__ import annotations

import functools

import flint
import sympy as sp

from symdecomp.algebra.triangle_bezier import bezier_indices
from symdecomp.analysis.characteristic import SUBPATCH_FACES, TRIANGLES, triangle_patch_points
from symdecomp.schemes.box_spline import DEGREE
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.sector_patch import ORIGIN, sector_net, sector_point
from symdecomp.verify.bezier import bspline_to_bezier, certify_sign, certify_sign_triangles, curve_angle, jacobian_net, triangle_jacobian_net
from symdecomp.verify.c1 import box_nets
from symdecomp.verify.mirror_parts import ball_matrix

__all__ = ["ring_faces", "irregular_rows", "wide_nets", "wide_arcs", "level_one_map", "ring_nets", "jacobian_sign", "arc_sweeps"]


def ring_faces(lat) -> tuple:
    """The level-1 patches of the wide ring in a face's chart: quads ``(a, b)`` (lower-left corner), triangles their corners."""
    if lat.handled("the wide ring's patches", BICUBIC, BOX_SPLINE) == BICUBIC:
        return tuple((a, b) for a in range(4) for b in range(4) if max(a, b) >= 2)
    up = tuple(((u, d - u), (u + 1, d - u), (u, d - u + 1)) for d in (2, 3) for u in range(d + 1))
    down = tuple(((u + 1, d - u), (u + 1, d - u + 1), (u, d - u + 1)) for d in (1, 2) for u in range(d + 1))
    return up + down


def _distance(lat, label) -> int:
    s, u, v = label
    return lat.ring_of(u, v)


def _weights(x: int) -> dict:
    """The cubic B-spline's refinement weights of level-1 index ``x`` on the level-0 indices."""
    i, odd = divmod(x, 2)
    if odd:
        return {i: sp.Rational(1, 2), i + 1: sp.Rational(1, 2)}
    return {i - 1: sp.Rational(1, 8), i: sp.Rational(3, 4), i + 1: sp.Rational(1, 8)}


def _chart(k: int, label) -> tuple:
    """``(face, X, Y)``: a canonical label in the chart of one face."""
    s, u, v = label
    return (k - 1, 0, u) if s == k else (s, u, v)


_EIGHTH = sp.Rational(1, 8)
_OPPOSITE = {(1, 0): ((0, 1), (1, -1)), (0, 1): ((1, 0), (-1, 1)), (1, -1): ((1, 0), (0, -1))}


def _stencil(lat, X: int, Y: int) -> dict:
    """``{level-0 chart point: weight}`` of the regular rule for the level-1 chart point ``(X, Y)``.

    Quads: the tensor cubic B-spline's; triangles: Loop's regular rules (``5/8, 1/16 x 6``; ``3/8, 3/8, 1/8, 1/8``).
    """
    if lat.handled('the regular refinement stencil', BICUBIC, BOX_SPLINE) == BICUBIC:
        return {(x, y): wx * wy for x, wx in _weights(X).items() for y, wy in _weights(Y).items()}
    if X % 2 == 0 and Y % 2 == 0:
        p = (X // 2, Y // 2)
        out = {(p[0] + a, p[1] + b): sp.Rational(1, 16) for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, -1), (-1, 1))}
        return out | {p: sp.Rational(5, 8)}
    d = (X % 2, Y % 2) if (X % 2, Y % 2) != (1, 1) else (1, -1)
    p = ((X - d[0]) // 2, (Y - d[1]) // 2)
    out = {p: 3 * _EIGHTH, (p[0] + d[0], p[1] + d[1]): 3 * _EIGHTH}
    return out | {(p[0] + a, p[1] + b): _EIGHTH for a, b in _OPPOSITE[d]}


@functools.lru_cache(maxsize=256)
def _ball_stencil(lat, X: int, Y: int) -> tuple:
    """:func:`_stencil` as ``((chart point, weight), ...)`` with exact Arb weights, read once per chart point and lattice."""
    return tuple(((x, y), flint.acb(flint.fmpq(int(w.p), int(w.q)))) for (x, y), w in _stencil(lat, X, Y).items())


def _regular(lat, k: int, label, point):
    """The regular rule (with phantoms across the sharp rays) for the level-1 ``label`` from the level-0 values
    ``point(s, x, y)`` of face ``s``'s chart points."""
    s, X, Y = _chart(k, label)
    total = None
    for (x, y), w in _ball_stencil(lat, X, Y):
        term = point(s, x, y) * w
        total = term if total is None else total + term
    return total


def _net_points(lat, k: int, value):
    """``point(s, u, v)``: :func:`~symdecomp.schemes.sector_patch.sector_net` of one chart point of face ``s``, each point
    resolved once (neighbouring patches and stencils share their points)."""
    cache: dict = {}

    def point(s: int, u: int, v: int):
        key = (s, u, v)
        if key not in cache:
            cache[key] = sector_net(lat, k, s, [(u, v)], value)[0]
        return cache[key]

    return point


def irregular_rows(sm, distance: int = 2) -> list:
    """The level-1 labels at ``distance`` or more from ``O`` whose exact refinement row is not the regular rule (``[]``: all are).

    At ``distance = 1`` BLZ's near-edge rule shows: its points ``(s, 1, 0)`` are listed.
    """
    cols = {lab: j for j, lab in enumerate(sm.labels)}
    rows: dict = {}
    for (i, j), e in sm.refine.todok().items():
        rows.setdefault(i, {})[sm.labels[j]] = e
    bad = []
    for i, lab in enumerate(sm.fine_labels):
        if lab == ORIGIN or _distance(sm.lattice, lab) < distance:
            continue
        row: dict = {}
        s, X, Y = _chart(sm.k, lab)
        for (x, y), wxy in _stencil(sm.lattice, X, Y).items():
            for w, src in sector_point(sm.lattice, sm.k, s, x, y):
                row[src] = row.get(src, 0) + w * wxy
        have = rows.get(i, {})
        if set(row) - set(cols) or any(sp.expand(have.get(c, 0) - row.get(c, 0)) != 0 for c in set(have) | set(row)):
            bad.append(lab)
    return bad


def wide_nets(sm, chi, lambdas, sectors=None) -> list:
    """The Bezier nets (complex balls) of the wide ring, face by face (``len(ring_faces)`` per face).

    ``chi``: level-1 values on the 3-ring (a mapping: ``label in chi``, ``chi[label]``); ``lambdas = (lambda_1,
    lambda_2)`` (real balls); ``sectors``: the faces whose nets are built (default: all ``k``), in that order.
    """
    l1, l2 = lambdas
    cache: dict = {}

    def coarse(label):
        z = chi[label]
        return type(z)(z.real / l1, z.imag / l2)

    coarse_point = _net_points(sm.lattice, sm.k, coarse)

    def value(label):
        if label not in cache:
            cache[label] = chi[label] if label in chi else _regular(sm.lattice, sm.k, label, coarse_point)
        return cache[label]

    point = _net_points(sm.lattice, sm.k, value)
    out, faces = [], ring_faces(sm.lattice)
    for s in range(sm.k) if sectors is None else sectors:
        if sm.lattice.handled("the wide ring's nets", BICUBIC, BOX_SPLINE) == BOX_SPLINE:
            values = []
            for t in faces:
                pts = triangle_patch_points(t)
                values.append({p: point(s, *p) for p in pts})
            out += box_nets(values, faces)
            continue
        for a, b in faces:
            vals = [point(s, a - 1 + i, b - 1 + j) for i in range(4) for j in range(4)]
            out.append(bspline_to_bezier([vals[4 * i: 4 * i + 4] for i in range(4)]))
    return out


def wide_arcs(sm, nets) -> tuple[list, list]:
    """``(inner, outer)``: the Bezier curves of the ring's arcs at level-1 distance 2 and 4, from ray 0 to ray ``k``."""
    faces = ring_faces(sm.lattice)
    per = len(faces)
    inner, outer = [], []
    for s in range(sm.k):
        net = dict(zip(faces, nets[per * s: per * (s + 1)]))
        # triangles: inner, the down triangles' edges corner 0 -> 2; outer, the up ones' corner 1 -> 2
        if sm.lattice.handled("the wide ring's arcs", BICUBIC, BOX_SPLINE) == BOX_SPLINE:
            pos = {i: n for n, i in enumerate(bezier_indices(DEGREE))}
            inner += [[net[((u + 1, 1 - u), (u + 1, 2 - u), (u, 2 - u))][pos[(DEGREE - t, 0, t)]] for t in range(DEGREE + 1)]
                      for u in (1, 0)]
            outer += [[net[((u, 3 - u), (u + 1, 3 - u), (u, 4 - u))][pos[(0, DEGREE - t, t)]] for t in range(DEGREE + 1)]
                      for u in (3, 2, 1, 0)]
            continue
        inner += [[net[(2, b)][0][j] for j in range(4)] for b in (0, 1)]
        inner += [[net[(a, 2)][i][0] for i in range(3, -1, -1)] for a in (1, 0)]
        outer += [[net[(3, b)][3][j] for j in range(4)] for b in range(4)]
        outer += [[net[(a, 3)][i][3] for i in range(3, -1, -1)] for a in range(3, -1, -1)]
    return inner, outer


def level_one_map(sm, vectors) -> dict:
    """``{level-1 label: chi}`` (complex balls ``x + i y``) from the two real eigenvectors ``vectors`` (2-ring, matrix order,
    real balls) refined once by the sector's exact refinement rows: the values the ring's nets read."""
    R = ball_matrix(sm.refine.tolist(), sm.weight)
    fine = []
    for v in vectors:
        col = R * flint.acb_mat([[flint.acb(x)] for x in v])
        fine.append([col[i, 0].real for i in range(len(sm.fine_labels))])
    return {lab: flint.acb(fine[0][i], fine[1][i]) for i, lab in enumerate(sm.fine_labels)}


def ring_nets(sm, chi) -> list:
    """The Bezier nets (complex) of the ring's ``3 k`` sub-patches, face by face (quads ``4 x 4``; triangles, 15)."""
    out = []
    for s in range(sm.k):
        if sm.lattice.handled("the sharp ring's nets", BICUBIC, BOX_SPLINE) == BICUBIC:
            for a, b in SUBPATCH_FACES:
                pts = [(a - 1 + i, b - 1 + j) for i in range(4) for j in range(4)]
                vals = sector_net(sm.lattice, sm.k, s, pts, chi.__getitem__)
                out.append(bspline_to_bezier([vals[4 * i: 4 * i + 4] for i in range(4)]))
        else:
            values = []
            for t in TRIANGLES:
                pts = triangle_patch_points(t)
                values.append(dict(zip(pts, sector_net(sm.lattice, sm.k, s, pts, chi.__getitem__))))
            out += box_nets(values)
    return out


def jacobian_sign(sm, nets, max_depth: int):
    """The Jacobian's sign on the ring's nets, certified by de Casteljau subdivision to ``max_depth`` (or where it fails)."""
    if sm.lattice.handled("the sharp ring's Jacobian", BICUBIC, BOX_SPLINE) == BICUBIC:
        return certify_sign([jacobian_net([[z.real for z in row] for row in net], [[z.imag for z in row] for row in net])
                             for net in nets], max_depth)
    return certify_sign_triangles([triangle_jacobian_net([z.real for z in net], [z.imag for z in net]) for net in nets],
                                  DEGREE, 2 * max_depth)


def arc_sweeps(sm, nets, wide: bool = False):
    """``(Delta_in, Delta_out)``: the arguments swept by the images of the ring's inner and outer arcs (``None``: not decided)."""
    inner, outer = wide_arcs(sm, nets) if wide else ([], [])
    for s in range(0 if wide else sm.k):
        p0, p1, p2 = nets[3 * s: 3 * s + 3]
        if sm.lattice.handled("the sharp ring's arcs", BICUBIC, BOX_SPLINE) == BICUBIC:
            inner += [[p0[0][j] for j in range(4)], [p2[i][0] for i in range(3, -1, -1)]]
            outer += [[p0[3][j] for j in range(4)], [p1[3][j] for j in range(4)], [p1[i][3] for i in range(3, -1, -1)],
                      [p2[i][3] for i in range(3, -1, -1)]]
        else:
            pos = {i: n for n, i in enumerate(bezier_indices(DEGREE))}
            inner.append([p1[pos[(DEGREE - t, 0, t)]] for t in range(DEGREE + 1)])
            outer += [[p[pos[(0, DEGREE - t, t)]] for t in range(DEGREE + 1)] for p in (p0, p2)]
    totals = []
    for curves in (inner, outer):
        angles = [curve_angle(c) for c in curves]
        totals.append(None if any(a is None for a in angles) else sum(angles, flint.arb(0)))
    return tuple(totals)
