"""analysis/mesh_kinds.py and mesh_limits.py: every vertex classified as OpenSubdiv tags it, exact masks once per kind,
and the numpy application equal to the exact per-vertex limits."""

import math
import random
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.masks import sharp_masks
from symdecomp.analysis.mesh_kinds import NeighbourhoodKind, classify_vertices
from symdecomp.analysis.mesh_limits import exact_as_floats, exact_position, kind_masks, mesh_limits
from symdecomp.schemes.lattice import QUAD
from symdecomp.schemes.loop import loop
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex

N = 5


def idx(x, y):
    return y * (N + 1) + x


def grid(tags=None, seed=3, triangles=False) -> PolygonMesh:
    """An N x N grid of quads (or triangles) with random rational heights, a smooth interior and a boundary."""
    rng = random.Random(seed)
    points = [(x, y, Fraction(rng.randint(-8, 8), 8)) for y in range(N + 1) for x in range(N + 1)]
    faces = []
    for y in range(N):
        for x in range(N):
            a, b, c, d = idx(x, y), idx(x + 1, y), idx(x + 1, y + 1), idx(x, y + 1)
            faces += [(a, b, c), (a, c, d)] if triangles else [(a, b, c, d)]
    mesh = PolygonMesh.from_arrays(points, faces)
    return PolygonMesh(mesh.points, mesh.faces, tags=MeshTags() if tags is None else tags)


CREASE = {(idx(0, 2), idx(1, 2)): Fraction(10), (idx(1, 2), idx(2, 2)): Fraction(10), (idx(2, 2), idx(3, 2)): Fraction(10)}


@pytest.mark.parametrize("n", [3, 5, 6, 7])
def test_smooth_catmull_clark_masks_are_the_closed_forms(n):
    """The position mask of a smooth valence-n kind, exactly: n/(n+5) on O, 4/(n(n+5)) on a_i, 1/(n(n+5)) on b_i."""
    m = kind_masks(catmull_clark(), NeighbourhoodKind("smooth", n, (n,), True))
    exact = exact_position(catmull_clark(), m)
    assert exact == (sp.Rational(n, n + 5),) + (sp.Rational(4, n * (n + 5)),) * n + (sp.Rational(1, n * (n + 5)),) * n
    assert m.position == pytest.approx([float(x) for x in exact], abs=1e-15)
    assert m.position.sum() == pytest.approx(1, abs=1e-15)


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_boundary_masks_are_the_boundary_curves(k):
    """A boundary vertex's limit is the cubic B-spline boundary curve's: (a_0 + 4 O + a_k)/6; a corner (one face,
    edge-and-corner) stays where it is; both are the sector model's exact eigenvectors."""
    kind = classify_vertices(grid(), QUAD).kinds
    m = kind_masks(catmull_clark(), NeighbourhoodKind("boundary", k, (k,), False, corner=(k == 1)))
    exact = list(m.exact_position)
    want = [1] + [0] * (len(exact) - 1) if k == 1 else [sp.Rational(2, 3), sp.Rational(1, 6)] + [0] * (k - 1) + [sp.Rational(1, 6)] + [0] * k
    assert exact == want
    assert exact == sharp_masks(catmull_clark(), SharpVertex(QUAD, (k,), False, k == 1)).position.exact()
    assert len(kind) == 3


def test_every_vertex_is_classified_as_opensubdiv_tags_it():
    """An infinitely sharp crease from the boundary into the grid: its inner vertices are creases k = 2,2 (the
    last one, where it ends, a dart), its boundary end a boundary vertex with sectors (1, 1); the rest smooth."""
    kinds = classify_vertices(grid(MeshTags(creases=CREASE)), QUAD)
    by_vertex = {int(v): str(k) for k in kinds.kinds for v in kinds.rings[k][0]}
    assert by_vertex[idx(0, 2)] == "boundary k = 1,1"
    assert by_vertex[idx(1, 2)] == by_vertex[idx(2, 2)] == "crease k = 2,2"
    assert by_vertex[idx(3, 2)] == "dart k = 4"
    assert by_vertex[idx(0, 0)] == "boundary k = 1, corner" and by_vertex[idx(4, 4)] == "smooth n = 4"
    assert kinds.not_analysed == {}


def test_vertices_the_sector_model_cannot_take_get_computed_outcomes():
    tags = MeshTags(creases={(idx(1, 2), idx(2, 2)): Fraction(1), (idx(2, 2), idx(3, 2)): Fraction(2)},
                    corners={idx(4, 4): Fraction(1, 2)}, holes=frozenset({0}))
    kinds = classify_vertices(grid(tags), QUAD)
    assert not kinds.not_analysed and kinds.kind_of[idx(2, 2)] == -1
    mixed, semi = kinds.outcomes[idx(2, 2)], kinds.outcomes[idx(4, 4)]
    assert mixed.reason.startswith("sharp edges of different sharpness (1, 2) meet there: after 2 levels")
    assert mixed.eventual == NeighbourhoodKind("smooth", 4, (4,), True) and semi.levels == 1
    assert semi.reason.startswith("a semi-sharp vertex tag (1/2): after 1 level ")
    assert kinds.kind_of[idx(1, 1)] >= 0  # a corner of a hole keeps its kind: holes change no rule
    assert kinds.outcomes[idx(0, 0)].reason == "no point on the limit surface: every face of it is tagged as a hole"
    none = classify_vertices(grid(MeshTags(interpolate_boundary="none")), QUAD)
    assert sorted(none.outcomes) == sorted(v for v in range(36) if v % 6 in (0, 5) or v // 6 in (0, 5))
    assert not any(o.on_surface for o in none.outcomes.values())


@pytest.mark.parametrize("tags", [MeshTags(), MeshTags(creases=CREASE), MeshTags(corners={idx(2, 2): Fraction(10)})],
                         ids=["smooth", "crease", "corner"])
def test_the_numpy_application_is_the_exact_limit_to_1e_12(tags):
    """Per vertex, the float64 masks applied with one product per kind equal the exact masks applied to the exact
    coordinates (vertex by vertex, ``exact=True``), to 1e-12."""
    r = mesh_limits(grid(tags), catmull_clark(), exact=True)
    assert set(r.exact) == set(range(36))
    exact = np.array([exact_as_floats(r.exact[v]) for v in range(36)])
    assert np.max(np.abs(exact - r.limits)) < 1e-12
    assert np.allclose(np.linalg.norm(r.normals, axis=1), 1)


@pytest.mark.parametrize("n", [3, 5, 7, 9])
def test_loop_s_position_mask_is_the_exact_one(n):
    """Loop's smooth masks, evaluated without closed forms, equal the closed-form exact weights to 1e-15."""
    m = kind_masks(loop(), NeighbourhoodKind("smooth", n, (n,), True))
    assert m.position == pytest.approx(exact_as_floats(exact_position(loop(), m)), abs=1e-15)


def test_loop_on_triangles_and_its_exact_limits():
    r = mesh_limits(grid(triangles=True), loop(), exact=True)
    exact = np.array([exact_as_floats(r.exact[v]) for v in sorted(r.exact)])
    assert np.max(np.abs(exact - r.limits[sorted(r.exact)])) < 1e-12
    assert {str(k) for k in r.kinds.kinds} >= {"smooth n = 6", "boundary k = 1, corner", "boundary k = 3"}


def test_a_semi_sharp_crease_folds_its_levels_into_the_masks():
    """Sharpness 2: the masks are the settled masks at level 2 times the two exact one-step matrices, so the limit lies
    between the smooth one and the infinitely sharp crease's."""
    crease = {e: Fraction(2) for e in CREASE}
    m = kind_masks(catmull_clark(), NeighbourhoodKind("crease", 4, (2, 2), True, sharpness=Fraction(2)))
    sharp = kind_masks(catmull_clark(), NeighbourhoodKind("crease", 4, (2, 2), True))
    assert m.levels == 2 and sharp.levels == 0 and m.exact_position is None
    assert m.position.sum() == pytest.approx(1, abs=1e-14)
    assert not np.allclose(m.position, sharp.position)
    r = mesh_limits(grid(MeshTags(creases=crease)), catmull_clark())
    assert r.analysed().all() and math.isfinite(float(r.limits.sum()))


def test_coordinates_near_the_double_range_give_finite_limits_and_no_warnings():
    """Issue 35, item 17: a mesh near 1e308 printed nan tangents and numpy warnings. The masks are applied to the
    points scaled into range: the limits are the exact ones (a cube's corner: its limit (1/2)(x, y, z) at scale), the
    normals unit vectors, and nothing is warned."""
    import warnings

    big = Fraction(3, 2) * 10**308
    cube = PolygonMesh.from_arrays([(x * big, y * big, z * big) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)],
                                   [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = mesh_limits(cube, catmull_clark(), exact=True)
    assert r.not_analysed() == {} and np.isfinite(r.normals).all()
    assert r.limits[0] == pytest.approx([float(x) for x in r.exact[0]], rel=1e-15)
    assert r.normals[0] == pytest.approx(-np.ones(3) / math.sqrt(3), abs=1e-15)


@pytest.mark.parametrize("shape", ["catmark_car", "catmark_pawn", "loop_icos_semisharp", "catmark_bishop"])
def test_the_numpy_route_gathers_the_same_rings_as_the_vertex_by_vertex_walk(shape, monkeypatch):
    """The untagged interior vertices are classified valence by valence with numpy; forced through the walk that takes
    the other vertices, every kind gets the same vertices and the same ordered 1-rings (OpenSubdiv's shapes: valences
    3 to 12, creases, darts, boundaries)."""
    from pathlib import Path

    from symdecomp.analysis import mesh_kinds
    from symdecomp.schemes.lattice import TRIANGLE
    from symdecomp.schemes.meshformats import read_mesh

    mesh = read_mesh(Path(__file__).resolve().parents[1] / "verify" / "opensubdiv_shapes" / f"{shape}.obj")
    if mesh.face_sizes() != (3,) and mesh.face_sizes() != (4,):
        from symdecomp.schemes.polygon_step import catmull_clark_polygon_step

        mesh = catmull_clark_polygon_step(mesh).mesh
    lattice = TRIANGLE if mesh.face_sizes() == (3,) else QUAD
    fast = classify_vertices(mesh, lattice)
    monkeypatch.setattr(mesh_kinds, "_smooth_at_once", lambda mesh, candidates, quads: ({}, candidates))
    walked = classify_vertices(mesh, lattice)
    assert sorted(fast.rings) == sorted(walked.rings) and fast.not_analysed == walked.not_analysed
    for kind, (ids, rings) in walked.rings.items():
        assert np.array_equal(fast.rings[kind][0], ids) and np.array_equal(fast.rings[kind][1], rings), kind
    assert np.array_equal(fast.kind_of, walked.kind_of)
    assert sum(len(ids) for k, (ids, _) in fast.rings.items() if k.name == "smooth") > len(mesh.points) // 3
