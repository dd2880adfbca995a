"""The evaluation data of an extraordinary face (dual quad schemes) against exact refinement, at dyadic parameters.

The reference uses neither the data's matrix, picking matrices, decomposition nor B-spline basis: a random exact
control net on a larger explicit mesh (the face-centred neighbourhood of depth :data:`REFERENCE_DEPTH`) is refined
``M`` times by the scheme's rules (:func:`~symdecomp.schemes.topology.refine_step`, the mesh cropped to that depth
around the tracked centre after each step), and at the level-``M`` face whose centre is the lattice point ``(p, q)``
of sector ``s`` (``p, q >= 0``, ``1 <= max(p, q) <= 4``) the limit position is the regular face's limit mask on its
16 points: the left eigenvector for 1 of the regular (``n = 4``) face's own matrix, summing to 1. That is the patch's
point at ``(u, v) = (p / 2^M, q / 2^M)``; a face is used when the mask's support lies in the sector's chart (so its
rules are the regular ones). With irrational rules (Doo-Sabin at ``n = 5, 7, ...``) both sides are Arb balls
containing the exact values: they agree when the balls overlap and are narrower than ``2^-100``.

>>> from symdecomp.schemes.stencil_files import load_zoo
>>> r = dyadic_check(load_zoo("doo-sabin"), 3, levels=(1,))
>>> r["points"], r["mismatches"], r["routes"]
(24, 0, ('eigen', 'powers'))
"""

from __future__ import annotations

import random
from fractions import Fraction

import flint

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.dual_evaldata import DEPTH, DualEvalData, dual_evaldata, mesh_chart
from symdecomp.analysis.dual_evaluation import evaluate
from symdecomp.analysis.sector_evaldata import PREC, limit_mask, matrix_numbers, real_ball
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.errors import InternalError, NotApplicableError
from symdecomp.schemes.halfedge import halfedge_mesh
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.neighbourhood import local_faces, neighbourhood
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.schemes.topology import refine_step, topology_of
from symdecomp.validate import check_int, check_type, check_valence

__all__ = ["dyadic_check", "regular_face_mask", "TOLERANCE", "REFERENCE_DEPTH"]

#: Widest ball accepted as a value (irrational rules).
TOLERANCE = 2.0**-100
#: The ring depth of the reference mesh around the centre face, at every level (points up to 11/2 from it).
REFERENCE_DEPTH = 5


def regular_face_mask(scheme: StencilScheme) -> dict[tuple[int, int], Fraction]:
    """``(2x, 2y) -> weight``: the limit of a regular face's centre on its 16 points (``(0, 0)`` the centre), nonzero only.

    The left eigenvector for 1 of the scheme's own matrix at a regular face (``n = 4``, depth 1), summing to 1;
    positions from the chart of each of the four sectors, turned into sector 0's.
    """
    zm = zoo_matrix(scheme, 4, 1)
    nb, a = zm.neighbourhood, zm.matrix
    rows = [{c: a[r, c] for c in range(a.cols) if a[r, c] != 0} for r in range(a.rows)]
    if not all(w.is_Rational for row in rows for w in row.values()):
        raise NotApplicableError(f"scheme {scheme.name!r}: the regular face's rules are not rational (a biquadratic "
                                 "B-spline's are)")
    mask = limit_mask(matrix_numbers(rows, a.cols, True), True)
    index, out = nb.index(), {}
    for s in range(4):
        start = nb.start
        for _ in range(s):
            start = nb.mesh.next[start]
        for (x, y), v in mesh_chart(nb.mesh, start, 3).items():
            for _ in range(s):  # sector s's chart turned into sector 0's by s quarter turns
                x, y = -y, x
            w = mask[index[v]]
            if w != 0:
                out[(x, y)] = Fraction(int(w.p), int(w.q))
    return out


def _refined_nets(scheme: StencilScheme, n: int, top: int, exact: bool, rng: random.Random):
    """Level ``0..top``: ``(mesh, start, positions)`` of the reference mesh, refined exactly and cropped each step."""
    nb = neighbourhood(lattice(scheme.lattice), n, REFERENCE_DEPTH, centred="face")
    mesh, start = nb.mesh, nb.start
    number = to_fmpq if exact else real_ball
    net = {v: [flint.fmpq(rng.randint(-99, 99), rng.randint(1, 9)) for _ in range(3)] for v in mesh.vertices()}
    out = [(mesh, start, net)]
    topology = topology_of(scheme)
    for step in range(top):
        st = refine_step(scheme, mesh, regular=4)
        origin, tip = topology.track(mesh, start, step)
        full, new_start = st.mesh, st.mesh.by_edge[(st.ids[origin], st.ids[tip])]
        faces = local_faces(full, new_start, REFERENCE_DEPTH, "face")
        mesh = halfedge_mesh(tuple(full.faces[f] for f in faces))
        start = mesh.halfedge(full.origin[new_start], full.tip(new_start))
        zero = flint.fmpq(0) if exact else flint.arb(0)
        net = {v: [sum((number(w) * net[u][k] for u, w in st.rows[v].items()), zero) for k in range(3)] for v in mesh.vertices()}
        out.append((mesh, start, net))
    return out


def _agree(got, want, exact: bool) -> bool:
    if exact:
        return all(flint.fmpq(a) == b for a, b in zip(got, want))
    return all(a.overlaps(b) and a.rad() < TOLERANCE and b.rad() < TOLERANCE for a, b in zip(got, want))


def _levels(u, v) -> tuple:
    """Both levels whose ring holds ``(u, v)``: the chosen one and, on its outer edge (``2^m max = 2``), the coarser."""
    top = max(u, v)
    m = next(m for m in range(1, 64) if 2**m * top > 1)
    return (m, m - 1) if 2**m * top == 2 and m > 1 else (m,)


def dyadic_check(scheme: StencilScheme, n: int, *, levels=(1, 2, 3), seed: int = 0, data: DualEvalData | None = None) -> dict:
    """Evaluate every sector at ``(p / 2^M, q / 2^M)``, ``M`` in ``levels``, against the reference (module docstring).

    ``data``: the data to check (default :func:`~symdecomp.analysis.dual_evaldata.dual_evaldata`'s; a test passes
    altered data to see the check fail). Returns ``{"points", "mismatches", "routes"}``: the parameters checked, how
    many evaluations (every route the data have, every level whose ring holds the point) differ from the reference.
    """
    check_type(scheme, StencilScheme, "scheme", hint="a StencilScheme")
    n = check_valence(n)
    levels = tuple(check_int(m, "level", minimum=1, maximum=6) for m in levels)
    data = dual_evaldata(scheme, n) if data is None else check_type(data, DualEvalData, "data")
    rng = random.Random(seed)
    routes = ("eigen", "powers") if data.decomposition is not None else ("powers",)
    mask = regular_face_mask(scheme)
    points = mismatches = 0
    with flint.ctx.workprec(PREC):
        number = flint.fmpq if data.exact else (lambda p, q: flint.arb(p) / q)
        weights, zero = [number(w.numerator, w.denominator) for w in mask.values()], number(0, 1)
        nets = _refined_nets(scheme, n, max(levels), data.exact, rng)
        control = _control_net(scheme, n, *nets[0])
        for big_m in sorted(set(levels)):
            mesh, start, net = nets[big_m]
            for s in range(n):
                chart = mesh_chart(mesh, start, 2 * REFERENCE_DEPTH + 1)
                for p, q in ((p, q) for p in range(5) for q in range(5) if 1 <= max(p, q) <= min(4, 2**big_m)):
                    spots = [(2 * p + x, 2 * q + y) for x, y in mask]
                    if not all(spot in chart for spot in spots):
                        continue
                    want = [sum((weights[i] * net[chart[spot]][k] for i, spot in enumerate(spots)), zero) for k in range(3)]
                    u, v = Fraction(p, 2**big_m), Fraction(q, 2**big_m)
                    for route, level in ((r, m) for r in routes for m in _levels(u, v)):
                        got = evaluate(data, s, u, v, control, route=route, level=level)["point"]
                        mismatches += not _agree(got, want, data.exact)
                    points += 1
                start = mesh.next[start]
    return {"points": points, "mismatches": mismatches, "routes": routes}


def _control_net(scheme: StencilScheme, n: int, mesh, start: int, net: dict) -> list:
    """The data's control points ``C`` (the depth-2 neighbourhood, in its order) read off the level-0 reference net."""
    nb = neighbourhood(lattice(scheme.lattice), n, DEPTH, centred="face")
    order = nb.index()
    out: list = [None] * len(order)
    small_start, big_start = nb.start, start
    for _ in range(n):  # sector by sector: the same chart point in both meshes
        big = mesh_chart(mesh, big_start, 2 * DEPTH + 1)
        for spot, v in mesh_chart(nb.mesh, small_start, 2 * DEPTH + 1).items():
            out[order[v]] = [Fraction(int(x.p), int(x.q)) for x in net[big[spot]]]
        small_start, big_start = nb.mesh.next[small_start], mesh.next[big_start]
    if any(p is None for p in out):
        raise InternalError("the sectors' charts do not cover the neighbourhood of the data")
    return out
