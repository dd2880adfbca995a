"""analysis/mesh_outcomes.py and mesh_transient.py: a vertex of no kind gets a computed outcome (issue 31): off the
limit surface, the kind it becomes once its semi-sharp tags have decayed (with its limit point from exact refinement),
or its fan's exact spectrum. Each case is a small mesh built here."""

import math
from fractions import Fraction

import numpy as np
import sympy as sp

from symdecomp.analysis.mesh_kinds import NeighbourhoodKind, classify_vertices
from symdecomp.analysis.mesh_limits import mesh_limits
from symdecomp.analysis.mesh_outcomes import decay, transition_weights
from symdecomp.schemes.mesh_refine import refine_mesh
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.mesh_verdicts import kind_verdict, outcome_verdict

CUBE_POINTS = [(x, y, z) for z in (0, 2) for y in (0, 2) for x in (0, 2)]
CUBE_FACES = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def cube(**tags) -> PolygonMesh:
    return PolygonMesh.from_arrays(CUBE_POINTS, CUBE_FACES, tags=MeshTags(**tags))


def grid(n: int, **tags) -> PolygonMesh:
    """An n x n grid of quads in the plane z = 0, vertex (x, y) = y (n + 1) + x."""
    faces = [(y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x)
             for y in range(n) for x in range(n)]
    return PolygonMesh.from_arrays([(x, y, 0) for y in range(n + 1) for x in range(n + 1)], faces, tags=MeshTags(**tags))


def test_decay_follows_opensubdiv_uniform_and_chaikin_rules():
    # uniform: one per level, the longest-lived semi-sharp tag decides; infinite edges stay
    assert decay([Fraction(5, 2), Fraction(1, 2), math.inf, Fraction(0)], Fraction(0), "uniform") == (3, [0, 0, math.inf, 0], 0)
    assert decay([Fraction(0)] * 3, Fraction(7, 10), "uniform") == (1, [0, 0, 0], 0)
    # Chaikin (Sdc::Crease::SubdivideEdgeSharpnessesAroundVertex), by hand: 3 and 1 become 3/4 3 + 1/4 1 - 1 = 3/2 and
    # 3/4 1 + 1/4 3 - 1 = 1/2; then 9/8 + 1/8 - 1 = 1/4 and 3/8 + 3/8 - 1 < 0, so 0; then 1/4 alone decrements to 0
    assert decay([Fraction(3), Fraction(1)], Fraction(0), "chaikin") == (3, [0, 0], 0)
    # the crease rule turns into the dart's at level 2 (1/2 reaches 0 while 1/4 does not), blended by the sharpness that
    # reached 0, 1/2; from the dart on the smooth mask is not blended
    assert transition_weights([Fraction(3), Fraction(1)], Fraction(0), "chaikin") == (Fraction(1, 2),)


def test_a_semi_sharp_corner_tag_is_transient_with_the_eventual_kinds_verdict_and_an_exact_limit():
    mesh = cube(corners={0: Fraction(3, 2)})
    kinds = classify_vertices(mesh, catmull_clark().lattice)
    outcome = kinds.outcomes[0]
    assert outcome.eventual == NeighbourhoodKind("smooth", 3, (3,), True) and outcome.levels == 2
    assert kinds.kind_of[0] == -1 and not kinds.not_analysed and set(kinds.outcomes) == {0}
    verdict, smooth = outcome_verdict(catmull_clark(), outcome), kind_verdict(catmull_clark(), outcome.eventual)
    assert (verdict.c1, verdict.regime) == (smooth.c1, smooth.regime) and verdict.c1_reason.endswith(smooth.c1_reason)
    assert "a semi-sharp vertex tag (3/2): after 2 levels" in verdict.c1_reason
    # the limit point from the 2-ring refined twice equals the limit of the whole cube refined twice exactly (its corner
    # tag decayed to 0 there), evaluated by the untagged smooth masks
    ours = mesh_limits(mesh, catmull_clark()).limits[0]
    refined = refine_mesh(mesh, catmull_clark(), 2)
    assert refined.corners == {}
    whole = mesh_limits(PolygonMesh.from_arrays(refined.points, refined.faces), catmull_clark()).limits
    assert np.min(np.linalg.norm(whole - ours, axis=1)) < 1e-14


def test_creases_of_different_sharpness_decay_to_the_infinitely_sharp_ones():
    """Vertex 0 of the cube: edges 0-1 infinitely sharp, 0-2 and 0-4 of sharpness 2 and 1/2: a corner for two levels,
    then a dart (one infinitely sharp edge), whose verdict it takes."""
    creases = {(0, 1): Fraction(10), (0, 2): Fraction(2), (0, 4): Fraction(1, 2)}
    outcome = classify_vertices(cube(creases=creases), catmull_clark().lattice).outcomes[0]
    assert outcome.eventual == NeighbourhoodKind("dart", 3, (3,), True) and outcome.levels == 2
    assert "sharp edges of different sharpness (1/2, 2, inf) meet there" in outcome.reason
    assert outcome_verdict(catmull_clark(), outcome).c1 == kind_verdict(catmull_clark(), outcome.eventual).c1


def test_interpolateboundary_none_puts_the_boundary_off_the_surface_unless_its_edges_are_tagged():
    mesh = grid(3, interpolate_boundary="none")
    kinds = classify_vertices(mesh, catmull_clark().lattice)
    boundary = {v for v in range(16) if v % 4 in (0, 3) or v // 4 in (0, 3)}
    assert set(kinds.outcomes) == boundary and not kinds.not_analysed
    assert all(not o.on_surface and outcome_verdict(catmull_clark(), o).c1 == "n/a" for o in kinds.outcomes.values())
    assert "under interpolateboundary none its faces are holes" in kinds.outcomes[0].reason
    # the interior vertices keep their kind (their faces are holes only in part: holes change no rule)
    assert {int(v) for k in kinds.kinds for v in kinds.rings[k][0]} == {5, 6, 9, 10}
    rim = [(0, 1), (1, 2), (2, 3), (3, 7), (7, 11), (11, 15), (14, 15), (13, 14), (12, 13), (8, 12), (4, 8), (0, 4)]
    tagged = classify_vertices(grid(3, interpolate_boundary="none", creases={e: Fraction(10) for e in rim}),
                               catmull_clark().lattice)
    assert not tagged.not_analysed and all(o.fan for o in tagged.outcomes.values())  # the 4 one-face corners: spectrum
    assert set(tagged.outcomes) == {0, 3, 12, 15}


def test_holes_change_no_rule_and_a_vertex_of_holes_only_is_off_the_surface():
    plain, holed = grid(3), grid(3, holes=frozenset({4}))
    ours = mesh_limits(holed, catmull_clark())
    assert np.array_equal(ours.limits, mesh_limits(plain, catmull_clark()).limits)
    corner = grid(3, holes=frozenset({0}))
    outcome = classify_vertices(corner, catmull_clark().lattice).outcomes
    assert list(outcome) == [0] and outcome[0].reason == "no point on the limit surface: every face of it is tagged as a hole"


def test_a_one_face_boundary_vertex_under_edge_only_is_judged_by_its_exact_spectrum():
    mesh = grid(1, interpolate_boundary="edge-only")
    outcome = classify_vertices(mesh, catmull_clark().lattice).outcomes[0]
    c1, why = outcome_verdict(catmull_clark(), outcome).c1, outcome_verdict(catmull_clark(), outcome).c1_reason
    # OpenSubdiv's crease rule on the ring (O, a_0, b_0, a_1), written out: O' = (6 O + a_0 + a_1)/8, the boundary edge
    # points (O + a)/2, the face point the centroid
    r = sp.Rational
    matrix = sp.Matrix([[r(6, 8), r(1, 8), 0, r(1, 8)], [r(1, 2), r(1, 2), 0, 0], [r(1, 4)] * 4, [r(1, 2), 0, 0, r(1, 2)]])
    values = sorted(matrix.eigenvals().items(), key=lambda vm: -abs(vm[0]))
    spectrum = ", ".join(f"{v}" + (" (twice)" if m == 2 else "") for v, m in values)
    assert c1 == "undecided" and f"has the eigenvalues {spectrum};" in why
    assert outcome.label == "boundary vertex of 1 face (spectrum)" and outcome.on_surface
