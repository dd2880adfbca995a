"""Section 3 (suitable decomposition neighbourhoods): supports of basis functions.

The paper separates the control vertices into those inside, on the boundary of and outside
the support of a vertex ``P`` and makes four claims about them. It defines the three classes
only informally; the checks use the definition of :mod:`symdecomp.analysis.support` (a vertex is
inside / on the boundary / outside when all / some / none of its sectors carry ``phi_P``),
computed from the Catmull-Clark rules on a mesh of rings around a vertex of valence ``n``
(all other vertices regular), and re-checked by exact refinement of ``e_P``.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

from symdecomp.analysis.support import Region, classify_support, support_relation
from symdecomp.claims.notation import eq, gt
from symdecomp.claims.notation import n as N
from symdecomp.claims.registry import CheckResult, Status, Step, Text, claim
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import cube_mesh, mesh_rules, refine, ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import Scheme

#: Valences the exact checks run for (kept small enough for seconds).
SYMMETRY_VALENCES = (3, 10)
SUPPORT_VALENCES = (3, 12)
INFLUENCE_VALENCES = (3, 12)


def _not_a_mesh_scheme(scheme: Scheme) -> CheckResult | None:
    """``not applicable`` when the scheme's 1-ring rules are not rules of a whole quad mesh (the supports of
    Section 3 are defined on meshes), else ``None``."""
    try:
        mesh_rules(scheme)
    except InvalidSchemeError as exc:
        return CheckResult(Status.NOT_APPLICABLE, f"the supports of Section 3 live on whole meshes, and {exc}")
    return None


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


@claim(
    "Section 3: symmetry",
    section="3",
    title="The support relation is symmetric",
    statement="$P'$ is inside, on the boundary, or outside the support of $P$ if and only if $P$ is "
    "inside, on the boundary, or outside the support of $P'$, correspondingly.",
)
def _symmetry(scheme: Scheme) -> CheckResult:
    # long: the symmetry check and its counterexample search share one loop over the valences.
    if (result := _not_a_mesh_scheme(scheme)) is not None:
        return result
    cc = scheme
    lo, hi = SYMMETRY_VALENCES
    pairs = 0
    steps = []
    for n in range(lo, hi + 1):
        rings = 5
        mesh = ring_mesh(n, rings)
        labels = ring_mesh_labels(n, rings)
        verts = [v for v in mesh.vertices() if _ring(labels, v) <= rings - 2]
        rel = support_relation(mesh, cc, verts)
        for p in verts:
            for q in verts:
                if rel[p, q] is not rel[q, p]:
                    return CheckResult(
                        Status.REFUTED,
                        f"asymmetric pair at valence {n}",
                        counterexample=f"n = {n}: vertex {labels[q]} is {rel[p, q].value} for the support of "
                        f"{labels[p]}, but {labels[p]} is {rel[q, p].value} for the support of {labels[q]}",
                    )
        pairs += len(verts) ** 2
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
        rel = support_relation(mesh, cc, verts)
        for p in verts:
            for q in verts:
                if rel[p, q] is not rel[q, p]:
                    return CheckResult(
                        Status.REFUTED,
                        f"asymmetric pair on the cube refined {level} times",
                        counterexample=f"cube refined {level} times: vertex {q} is {rel[p, q].value} for the support "
                        f"of {p}, but {p} is {rel[q, p].value} for the support of {q}",
                    )
        cube_pairs += len(verts) ** 2
    steps.append(Step(f"the cube refined 0, 1, 2 times (8, 26, 98 vertices): all {cube_pairs} ordered pairs agree", sp.Integer(cube_pairs)))
    return CheckResult(
        Status.VERIFIED,
        f"Catmull-Clark: all {pairs} ordered pairs of vertices within 3 rings of a vertex of valence "
        f"{lo}..{hi} (other vertices regular), and all {cube_pairs} pairs on the cube refined 0-2 times "
        "(several valence-3 vertices), are classified alike both ways",
        steps=tuple(steps),
        valences=SYMMETRY_VALENCES,
    )


@claim(
    "Section 3: 9 and 25 points",
    section="3",
    title="Regular Catmull-Clark: 9 points inside, 25 inside or on the boundary",
    statement="In the regular case of the Catmull-Clark scheme nine points determine the continuous "
    "derivatives at $P$, and 25 points are needed to prove continuity.",
)
def _regular_counts(scheme: Scheme) -> CheckResult:
    if (result := _not_a_mesh_scheme(scheme)) is not None:
        return result
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
        )
    return CheckResult(
        Status.VERIFIED,
        "regular Catmull-Clark: 9 vertices inside the support of P (P and its 8 neighbours), 16 on its "
        "boundary, 25 in all; that the 9 determine the derivatives is the claim 'Section 3: boundary "
        "influence'; '25 are needed to prove continuity' is the paper's reading of the count, not checked",
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
)
def _boundary_influence(scheme: Scheme) -> CheckResult:
    if (result := _not_a_mesh_scheme(scheme)) is not None:
        return result
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
    return CheckResult(
        Status.VERIFIED,
        f"valences {lo}..{hi}: the {checked} vertices within 3 rings that are on the boundary of or outside "
        f"the support of P have zero weight in the 1-ring of P at levels 0..{levels} of exact refinement "
        "(while their sum is nonzero on the 2-ring of P at every level); at every further level too, "
        "because the new 1-ring depends only on the old one "
        "(the subdivision matrix, checked against the mesh rules), and the 1-ring at all levels "
        "determines the limit position and the derivatives at P (the eigen-expansion of Section 5)",
        steps=(
            Step("weight of a boundary vertex in the 1-ring of $P$ at every checked level", sp.Integer(0)),
        ),
        valences=INFLUENCE_VALENCES,
    )


@claim(
    "Section 3: Catmull-Clark support",
    section="3",
    title="Catmull-Clark: inside = 1-ring, boundary = boundary of the 2-ring",
    statement="For the Catmull-Clark scheme the vertices inside the support of $P$ are in its 1-ring "
    "neighbourhood, while the vertices on the boundary of the support are the boundary vertices of the 2-ring.",
)
def _cc_support(scheme: Scheme) -> CheckResult:
    # long: one pass over the valences gathers the classification, the paper's counts and the
    # derivation steps together; split, each piece would re-run the exact refinement.
    if (result := _not_a_mesh_scheme(scheme)) is not None:
        return result
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
    return CheckResult(
        Status.VERIFIED,
        Text(
            f"valences {lo} to {hi}: inside = the closed 1-ring (", 2 * N + 1, " vertices), boundary = the ", 4 * N,
            " vertices at ring distance 2 (the boundary of the 2-ring), ring 3 outside; sector tests unchanged over 1-2 "
            "levels of exact refinement of ", sp.Symbol("e_P"), ", inside exactly where ", gt(phi_P(sp.Symbol("Q")), 0),
            f"; also every vertex of the cube refined once and twice ({checked}). The statement presupposes a 2-ring "
            f"that is a disk: on the unrefined cube (2-ring = whole surface) the corner opposite P is "
            f"{c0.regions[opposite].value} the support, ", eq(phi_P(sp.Symbol("Q")), c0.limit_values[opposite]),
            " there, not in the 1-ring",
        ),
        steps=tuple(steps),
        valences=SUPPORT_VALENCES,
    )
