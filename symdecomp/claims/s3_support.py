"""Section 3 (suitable decomposition neighbourhoods): supports of basis functions.

The paper separates the control vertices into those inside, on the boundary of and outside
the support of a vertex ``P`` and makes four claims about them. It defines the three classes
only informally; the checks use the definition of :mod:`symdecomp.analysis.support` (a vertex is
inside / on the boundary / outside when all / some / none of its sectors carry ``phi_P``),
computed from the Catmull-Clark rules on a mesh of rings around a vertex of valence ``n``
(all other vertices regular), and re-checked by exact refinement of ``e_P``.

**For every n.** Valences ``3 .. FIRST_VALENCE - 1`` are computed on the mesh. From ``FIRST_VALENCE`` on,
:mod:`symdecomp.analysis.support_window` gives every support test as the test on one window of sectors (the
same for every such ``n`` up to rotation and relabelling), a rule for far pairs and one for the centre's ``n``
sectors; the hypotheses of the propagation argument are checked for every ``n`` at once as rational functions
of ``n`` (:func:`~symdecomp.analysis.support_window.hypotheses_for_every_valence`). A mesh scheme for which
they fail at some valence keeps the exact range (``verified``). The exact valences above ``FIRST_VALENCE - 1``
(to 7) cross-check the window. "9 and 25 points" is about ``n = 4`` only: its exact computation is its proof.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

from symdecomp.analysis.support import Region, classify_support, support_relation
from symdecomp.analysis.support_window import (
    CENTRE,
    FIRST_VALENCE,
    NEAR,
    centre_hoods_local,
    centre_region,
    far_region,
    hypotheses_for_every_valence,
    predicted_region,
    ring_of,
    window,
)
from symdecomp.analysis.support_window import (
    region as window_region,
)
from symdecomp.claims.applicability import FACE_NEIGHBOURS, WHOLE_MESH
from symdecomp.claims.notation import eq, gt
from symdecomp.claims.notation import n as N
from symdecomp.claims.registry import CheckResult, Scope, Status, Step, Text, claim
from symdecomp.schemes.mesh import cube_mesh, ring_mesh, ring_mesh_labels
from symdecomp.schemes.refinement import mesh_rules, point_stencils, refine
from symdecomp.schemes.scheme import Scheme

#: Valences the exact checks run for: below FIRST_VALENCE they are the proof, from there on a cross-check of the
#: window argument (and the whole evidence when that argument does not apply to the scheme).
SYMMETRY_VALENCES = (3, 7)
SUPPORT_VALENCES = (3, 7)
INFLUENCE_VALENCES = (3, 7)


def _every_valence(scheme: Scheme) -> tuple[list[str], tuple[Step, ...]]:
    """The part of the argument for every ``n >= FIRST_VALENCE`` shared by the Section 3 claims: the rules' hypotheses
    for every valence (exact, in ``n``) and the locality of the window (:mod:`symdecomp.analysis.support_window`).
    Returns the failures (empty: the argument applies) and the steps."""
    failures, shown = hypotheses_for_every_valence(scheme)
    w = window()
    if not w.local_labels_within(NEAR):
        failures.append(f"N_loc of a face at a vertex of sector 0 reaches beyond sectors -{NEAR}..{NEAR}")
    if not centre_hoods_local(w):
        failures.append("N_loc of the centre's faces is not the rotation of one local set")
    if any(centre_region(w, t)[1] >= FIRST_VALENCE for t in w.types if ring_of(t) > 1):
        failures.append(f"a vertex off the star is carried by {FIRST_VALENCE} or more of the centre's sectors")
    steps = tuple(Step(f"for every $n \\ge 3$, exactly: {what}", expr) for what, expr in shown)
    steps += (Step(f"window of sectors $-3..3$: $N_{{loc}}(F)$ for the faces $F$ at the {len(w.types)} vertex types of "
                   f"sector 0 lies in sectors $-{NEAR}..{NEAR}$, so for $n \\ge {FIRST_VALENCE}$ every support test is the "
                   "window's up to relabelling", sp.Integer(len(w.types))),)
    return failures, steps


def _ring(labels, v):
    _, u, w = labels[v]
    return max(u, w)


def _cubes(scheme: Scheme, levels=(0, 1, 2)):
    """The cube refined 0, 1, 2 times: closed meshes with eight valence-3 vertices close together."""
    rules = mesh_rules(scheme)
    mesh = cube_mesh(lambda i: (Fraction(0),))
    out = {}
    for level in range(max(levels) + 1):
        if level in levels:
            out[level] = mesh
        mesh = refine(mesh, rules).mesh
    return out


def _relation_or_refutation(mesh, scheme: Scheme, verts, where: str, case: str, name=str):
    """The support relation on ``verts``, and the refutation at the first ordered pair it classifies differently both
    ways (``None`` when there is none); ``where`` and ``case`` say where in the evidence and the counterexample,
    ``name`` names a vertex."""
    rel = support_relation(mesh, scheme, verts)
    pair = next(((p, q) for p in verts for q in verts if rel[p, q] is not rel[q, p]), None)
    if pair is None:
        return rel, None
    p, q = map(name, pair)
    forward, backward = rel[pair].value, rel[pair[::-1]].value
    return rel, CheckResult(Status.REFUTED, f"asymmetric pair {where}", counterexample=f"{case}: vertex {q} is {forward} for the "
                            f"support of {p}, but {p} is {backward} for the support of {q}")


@claim(
    "Section 3: symmetry",
    section="3",
    title="The support relation is symmetric",
    statement="$P'$ is inside, on the boundary, or outside the support of $P$ if and only if $P$ is "
    "inside, on the boundary, or outside the support of $P'$, correspondingly.",
    requires=(FACE_NEIGHBOURS, WHOLE_MESH),
)
def _symmetry(scheme: Scheme) -> CheckResult:
    # long: the symmetry check and its counterexample search share one loop over the valences.
    cc = scheme
    lo, hi = SYMMETRY_VALENCES
    pairs = 0
    steps = []
    for n in range(lo, hi + 1):
        rings = 5
        mesh = ring_mesh(n, rings)
        labels = ring_mesh_labels(n, rings)
        verts = [v for v in mesh.vertices() if _ring(labels, v) <= rings - 2]
        rel, refuted = _relation_or_refutation(mesh, cc, verts, f"at valence {n}", f"n = {n}", labels.__getitem__)
        if refuted is not None:
            return refuted
        pairs += len(verts) ** 2
        w = window()
        if n >= FIRST_VALENCE and any(rel[p, q] is not predicted_region(w, labels[p], labels[q], n) for p in verts for q in verts):
            return CheckResult(Status.ERROR, f"n = {n}: the window of sectors does not predict the support relation of the mesh")
        if n in (lo, hi):
            steps.append(
                Step(
                    f"$n = {n}$: {len(verts)} vertices within {rings - 2} rings of the valence-{n} vertex, "
                    f"all {len(verts) ** 2} ordered pairs agree",
                    sp.Integer(len(verts)),
                )
            )
    cube_pairs = 0
    for level, mesh in _cubes(scheme).items():
        verts = mesh.vertices()
        rel, refuted = _relation_or_refutation(mesh, cc, verts, f"on the cube refined {level} times", f"cube refined {level} times")
        if refuted is not None:
            return refuted
        cube_pairs += len(verts) ** 2
    steps.append(Step(f"the cube refined 0, 1, 2 times (8, 26, 98 vertices): all {cube_pairs} ordered pairs agree", sp.Integer(cube_pairs)))
    failures, general = _every_valence(scheme)
    w = window()
    asymmetric = _window_asymmetry(w)
    if asymmetric is not None and not failures:
        return CheckResult(Status.REFUTED, f"asymmetric pair for every n >= {FIRST_VALENCE}",
                           counterexample=f"every n >= {FIRST_VALENCE}: {asymmetric}", steps=tuple(steps) + general)
    direct = (f"all {pairs} ordered pairs of vertices within 3 rings of a vertex of valence {lo}..{hi} (other vertices "
              f"regular), and all {cube_pairs} pairs on the cube refined 0-2 times (several valence-3 vertices), are "
              "classified alike both ways")
    if failures:
        return CheckResult(Status.VERIFIED, f"{direct}; not for every n: {'; '.join(failures)}", steps=tuple(steps),
                           valences=SYMMETRY_VALENCES)
    pair_types = len(w.types) ** 2
    steps.append(Step(f"the window's prediction equals the relation computed on the whole mesh for every pair at $n = {FIRST_VALENCE}, "
                      f"\\dots, {hi}$ (a cross-check of the relabelling)"))
    steps.append(Step(f"$n \\ge {FIRST_VALENCE}$: the {pair_types} pairs of vertex types at sector offsets $-{NEAR}..{NEAR}$ "
                      "(window), the far pairs (they meet only through the star of the centre) and the pairs with the "
                      "centre agree both ways", sp.Integer(pair_types * (2 * NEAR + 2) + len(w.types))))
    return CheckResult(
        Status.PROVED,
        f"for every n, for the pairs of vertices within 3 rings of the vertex of valence n (the claim's neighbourhood; the "
        f"regular part beyond is not covered): n = {lo}..{FIRST_VALENCE - 1} exactly on the mesh; for n >= {FIRST_VALENCE} "
        "the support test of a pair reads the faces near it and, through the faces at the centre, the star of the centre, so it is the test on "
        f"one window of sectors -3..3 (the same for every such n, up to rotation and relabelling), a far-pair rule and a "
        "rule for the centre's n sectors, all computed and symmetric; the rules' hypotheses (nonnegative weights, positive "
        f"vertex weights and limit mask, a simple eigenvalue 1) hold for every n as rational functions of n. Also {direct}",
        steps=tuple(steps) + general,
    )


def _window_asymmetry(w) -> str | None:
    """The first pair the window classifies differently both ways (near, far or with the centre), or ``None``."""
    for p in w.types:
        for q in w.types:
            for t in range(-NEAR, NEAR + 1):
                one, other = window_region(w, (t, *p[1:]), q), window_region(w, (-t, *q[1:]), p)
                if one is not other:
                    return f"Q = {q} is {one.value} for the support of P = {(t, *p[1:])}, but P is {other.value} for Q's"
            if far_region(w, p, q) is not far_region(w, q, p):
                return f"far pair of types {p}, {q}: {far_region(w, p, q).value} one way, {far_region(w, q, p).value} the other"
        if window_region(w, CENTRE, p) is not centre_region(w, p)[0]:
            return f"Q = {p} is {window_region(w, CENTRE, p).value} for the support of the centre, but not conversely"
    return None


@claim(
    "Section 3: 9 and 25 points",
    section="3",
    title="Regular Catmull-Clark: 9 points inside, 25 inside or on the boundary",
    statement="In the regular case of the Catmull-Clark scheme nine points determine the continuous "
    "derivatives at $P$, and 25 points are needed to prove continuity.",
    requires=(FACE_NEIGHBOURS, WHOLE_MESH),
)
def _regular_counts(scheme: Scheme) -> CheckResult:
    c = classify_support(ring_mesh(4, 5), 0, scheme, levels=2)
    inside, boundary = c.count(Region.INSIDE), c.count(Region.BOUNDARY)
    steps = (
        Step("vertices inside the support of $P$ (valence 4)", sp.Integer(inside)),
        Step("vertices on its boundary", sp.Integer(boundary)),
        Step("inside or on the boundary", sp.Integer(inside + boundary)),
    )
    if not (c.stable and c.consistent):
        return CheckResult(Status.ERROR, "the sector tests were not stable under refinement", steps=steps)
    if (inside, inside + boundary) != (9, 25):
        return CheckResult(
            Status.REFUTED,
            f"{inside} inside and {inside + boundary} inside or on the boundary",
            steps=steps,
            counterexample=f"regular Catmull-Clark: {inside} vertices inside, {boundary} on the boundary",
            scope=Scope.SINGLE_CASE,  # the statement is about the regular vertex alone
        )
    return CheckResult(
        Status.VERIFIED,
        "the statement concerns one case, the regular vertex (n = 4), and the exact computation there settles it: "
        "9 vertices inside the support of P (P and its 8 neighbours), 16 on its boundary, 25 in all (the rules' "
        "hypotheses checked at valence 4, the sector tests stable over 2 levels of exact refinement); that the 9 "
        "determine the derivatives is the claim 'Section 3: boundary influence'; '25 are needed to prove continuity' "
        "is the paper's reading of the count, not checked",
        steps=steps,
        valences=(4, 4),
    )


@claim(
    "Section 3: boundary influence",
    section="3",
    title="Vertices on the support boundary do not influence P",
    statement="If $P'$ is outside the support of $P$, then it has no influence on the position or any of "
    "the continuous derivatives of $P$; this is also the case when $P'$ is on the boundary of the support "
    "of $P$.",
    requires=(FACE_NEIGHBOURS, WHOLE_MESH),
)
def _boundary_influence(scheme: Scheme) -> CheckResult:
    # long: the exact refinement (the proof below FIRST_VALENCE) and the argument for every n give one verdict.
    cc = scheme
    rules = mesh_rules(cc)
    lo, hi = INFLUENCE_VALENCES
    levels = 3
    checked = 0
    for n in range(lo, hi + 1):
        rings = 5
        mesh = ring_mesh(n, rings)
        c = classify_support(mesh, 0, cc, levels=0)
        others = {v for v, r in c.regions.items() if r is not Region.INSIDE}
        # The sum of the basis functions of all these vertices: the rules have nonnegative weights,
        # so each one's share of a value is >= 0 and a zero value means a zero share for each.
        current = mesh.with_values({v: (Fraction(int(v in others)),) for v in mesh.values})
        centre, first = 0, mesh.one_ring(0)[1][0]
        for level in range(levels + 1):
            ring = current.one_ring_values(centre, first)
            if any(val[0] != 0 for val in ring):
                return CheckResult(
                    Status.REFUTED,
                    f"n = {n}: a vertex outside or on the boundary of the support reaches the 1-ring of P",
                    counterexample=f"n = {n}: the basis functions of the non-inside vertices have weight "
                    f"{max(val[0] for val in ring)} in the 1-ring of P at level {level}",
                )
            if level < levels:
                # the part of the mesh within 4 face-rings of P: enough for exact values on P's 1-ring
                # at the next level, and where these basis functions are nonzero
                step = refine(current.neighbourhood(centre, 4), rules)
                centre, first = step.vertex_point[centre], step.edge_point[frozenset((centre, first))]
                current = step.mesh
            two_ring = current.neighbourhood(centre, 2).values
            if not any(val[0] != 0 for val in two_ring.values()):
                return CheckResult(Status.ERROR, f"n = {n}: the test data vanished on the 2-ring of P; the check would be empty")
        checked += len(others)
    direct = (f"valences {lo}..{hi}: the {checked} vertices within 3 rings that are on the boundary of or outside the support "
              f"of P have zero weight in the 1-ring of P at levels 0..{levels} of exact refinement (while their sum is "
              "nonzero on the 2-ring of P at every level)")
    failures, general = _every_valence(scheme)
    closure = _one_ring_closure(scheme)
    if closure is not None:
        failures.append(closure)
    w = window()
    non_inside_ok = all((window_region(w, CENTRE, t) is Region.INSIDE) == (ring_of(t) <= 1) for t in w.types)
    if not non_inside_ok:
        failures.append("the vertices inside the support of P are not its closed 1-ring")
    steps = (Step("weight of a boundary vertex in the 1-ring of $P$ at every checked level", sp.Integer(0)),)
    if failures:
        return CheckResult(
            Status.VERIFIED,
            f"{direct}; at every further level too, because the new 1-ring depends only on the old one; not for every n: "
            + "; ".join(failures),
            steps=steps,
            valences=INFLUENCE_VALENCES,
        )
    return CheckResult(
        Status.PROVED,
        f"for every n: the vertices inside the support of P are its closed 1-ring (n = {lo}..{FIRST_VALENCE - 1} exactly, "
        f"n >= {FIRST_VALENCE} by the window argument of 'Section 3: Catmull-Clark support'), and the new 1-ring of P reads "
        "only the old closed 1-ring (vertex point: the vertex rule at valence n; edge and face points at P: the corners of "
        "the faces at P, computed on the window, the same for every n), so by induction no other vertex has weight in the "
        "1-ring of P at any level, and the 1-rings at all levels determine the limit position and derivatives at P (the "
        f"eigen-expansion of Section 5). Also {direct}",
        steps=steps + general,
    )


def _one_ring_closure(scheme: Scheme) -> str | None:
    """On the window: the edge points of the centre's edges and the face points of its faces read only the closed
    1-ring of the centre (``None``), or which point reads what else."""
    w = window()
    face, edge, _ = point_stencils(w.mesh, mesh_rules(scheme))
    star = {i for i, lab in w.labels.items() if ring_of(lab) <= 1}
    for fi in w.mesh.faces_of(0):
        if {x for _, x in face[fi]} - star:
            return f"the face point of the centre's face {w.mesh.faces[fi]} reads outside the 1-ring"
    for key, stencil in edge.items():
        if 0 in key and {x for _, x in stencil} - star:
            return f"the edge point of {sorted(w.labels[v] for v in key)} reads outside the 1-ring"
    return None


@claim(
    "Section 3: Catmull-Clark support",
    section="3",
    title="Catmull-Clark: inside = 1-ring, boundary = boundary of the 2-ring",
    statement="For the Catmull-Clark scheme the vertices inside the support of $P$ are in its 1-ring "
    "neighbourhood, while the vertices on the boundary of the support are the boundary vertices of the 2-ring.",
    requires=(FACE_NEIGHBOURS, WHOLE_MESH),
)
def _cc_support(scheme: Scheme) -> CheckResult:
    # long: one pass over the valences gathers the classification, the paper's counts and the
    # derivation steps together; split, each piece would re-run the exact refinement.
    cc = scheme
    lo, hi = SUPPORT_VALENCES
    rings = 5
    steps = []
    for n in range(lo, hi + 1):
        c = classify_support(ring_mesh(n, rings), 0, cc, levels=2 if n <= 6 else 1)
        labels = ring_mesh_labels(n, rings)
        expected = {0: Region.INSIDE, 1: Region.INSIDE, 2: Region.BOUNDARY, 3: Region.OUTSIDE}
        for v, region in c.regions.items():
            d = _ring(labels, v)
            if expected[d] is not region:
                return CheckResult(
                    Status.REFUTED,
                    f"n = {n}: a ring-{d} vertex is {region.value}",
                    counterexample=f"valence {n}: vertex {labels[v]} at ring distance {d} is {region.value} for the support of P",
                )
        if not (c.stable and c.consistent):
            return CheckResult(Status.ERROR, f"n = {n}: the sector tests changed under refinement or disagreed with phi_P(Q)")
        if n in (lo, 4, hi):
            steps.append(
                Step(
                    f"$n = {n}$: inside {c.count(Region.INSIDE)} $= 2n+1$, boundary {c.count(Region.BOUNDARY)} "
                    f"$= 4n$, outside {c.count(Region.OUTSIDE)} (ring 3)",
                    sp.Integer(c.count(Region.INSIDE) + c.count(Region.BOUNDARY)),
                )
            )
    # Meshes with several extraordinary vertices: the cube refined once and twice, every vertex as P.
    cubes = _cubes(scheme)
    checked = 0
    for level in (1, 2):
        mesh = cubes[level]
        verts = mesh.vertices()
        rel = support_relation(mesh, cc, verts)
        for p in verts:
            two = mesh.neighbourhood(p, 2)
            if not two.is_disk():
                return CheckResult(Status.ERROR, f"cube level {level}: the 2-ring of {p} is not a disk")
            one = set(mesh.neighbourhood(p, 1).vertices())
            rim = two.boundary_vertices()
            for q in verts:
                want = Region.INSIDE if q in one else Region.BOUNDARY if q in rim else Region.OUTSIDE
                if rel[p, q] is not want:
                    return CheckResult(
                        Status.REFUTED,
                        f"cube refined {level} times: vertex {q} is {rel[p, q].value} for the support of {p}",
                        counterexample=f"cube refined {level} times, P = {p}, Q = {q}: {rel[p, q].value}, expected {want.value}",
                    )
            checked += 1
    steps.append(Step(f"the cube refined once and twice: all {checked} vertices as $P$ agree", sp.Integer(checked)))
    # The statement presupposes that the 2-ring of P is a disk (it speaks of its boundary vertices).
    # On the unrefined cube it is the whole closed surface, and the corner opposite P is inside the
    # support by the sector definition while phi_P vanishes there (and it is not in the 1-ring).
    cube = cubes[0]
    c0 = classify_support(cube, 0, cc)
    opposite = 7
    steps.append(
        Step(
            "unrefined cube, $P$ = a corner: the 2-ring of $P$ is the whole cube (no boundary); the opposite "
            f"corner is {c0.regions[opposite].value} the support although $\\varphi_P$ vanishes there",
            c0.limit_values[opposite],
        )
    )
    phi_P = sp.Function("phi_P")
    failures, general = _every_valence(scheme)
    w = window()
    expected = {0: Region.INSIDE, 1: Region.INSIDE, 2: Region.BOUNDARY, 3: Region.OUTSIDE}
    wrong = [t for t in w.types if window_region(w, CENTRE, t) is not expected[ring_of(t)]]
    if wrong and not failures:
        t = wrong[0]
        return CheckResult(Status.REFUTED, f"every n >= {FIRST_VALENCE}: a ring-{ring_of(t)} vertex is {window_region(w, CENTRE, t).value}",
                           counterexample=f"every valence n >= {FIRST_VALENCE}: vertex {t} (sector, u, v) at ring distance "
                           f"{ring_of(t)} is {window_region(w, CENTRE, t).value} for the support of P", steps=tuple(steps) + general)
    counts = {r: sum(1 for t in w.types if window_region(w, CENTRE, t) is r) for r in Region}
    steps.append(Step(f"$n \\ge {FIRST_VALENCE}$ (window, $n$ sectors): inside $1 + n \\cdot {counts[Region.INSIDE]}$, boundary "
                      f"$n \\cdot {counts[Region.BOUNDARY]}$", 1 + N * counts[Region.INSIDE] + N * counts[Region.BOUNDARY]))
    every = not failures and not wrong
    return CheckResult(
        Status.PROVED if every else Status.VERIFIED,
        Text(
            *((f"for every n: n = {lo}..{FIRST_VALENCE - 1} exactly on the mesh, n >= {FIRST_VALENCE} on one window of "
               "sectors (the support test of a vertex reads the faces near it and the star of the centre, the same for every "
               "such n up to rotation; the rules' hypotheses hold for every n as rational functions of n): inside = the "
               "closed 1-ring (", 1 + N * counts[Region.INSIDE], " vertices), boundary = the ", N * counts[Region.BOUNDARY],
               " vertices at ring distance 2 (the boundary of the 2-ring), ring 3 outside. Also, exactly, ") if every else ()),
            f"valences {lo} to {hi}: inside = the closed 1-ring (", 2 * N + 1, " vertices), boundary = the ", 4 * N,
            " vertices at ring distance 2 (the boundary of the 2-ring), ring 3 outside; sector tests unchanged over 1-2 "
            "levels of exact refinement of ", sp.Symbol("e_P"), ", inside exactly where ", gt(phi_P(sp.Symbol("Q")), 0),
            f"; also every vertex of the cube refined once and twice ({checked}). The statement presupposes a 2-ring "
            f"that is a disk: on the unrefined cube (2-ring = whole surface) the corner opposite P is "
            f"{c0.regions[opposite].value} the support, ", eq(phi_P(sp.Symbol("Q")), c0.limit_values[opposite]),
            " there, not in the 1-ring",
            *(() if every else ("; not for every n: ", "; ".join(failures) or "the window disagrees")),
        ),
        steps=tuple(steps) + (general if every else ()),
        valences=None if every else SUPPORT_VALENCES,
    )
