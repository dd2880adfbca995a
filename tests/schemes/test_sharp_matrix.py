"""The subdivision matrices of boundary, crease, corner and dart vertices (symdecomp.schemes.sector)."""

from __future__ import annotations

import math
from fractions import Fraction

import flint
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.errors import InvalidInputError, InvalidMeshError, InvalidTypeError
from symdecomp.schemes.sector import SharpVertex, exact_sharp_matrix, sharp_subdivision_matrix
from symdecomp.schemes.sharp import SharpOptions

CC, LOOP = sd.catmull_clark(), sd.loop()
SCHEMES = [(CC, sd.QUAD), (LOOP, sd.TRIANGLE)]
EDGE_ONLY = SharpOptions("edge-only")


def _vertices(lattice):
    out = [SharpVertex.boundary(k, lattice) for k in range(1, 9)]
    out += [SharpVertex.corner(k, lattice) for k in (1, 2, 3)]
    out += [SharpVertex.crease(k1, k2, lattice) for k1, k2 in ((1, 2), (2, 2), (3, 5))]
    out += [SharpVertex.dart(n, lattice) for n in (3, 5)]
    return out


@pytest.mark.parametrize("scheme, lattice", SCHEMES, ids=["catmull-clark", "loop"])
@pytest.mark.parametrize("rings", [1, 2])
def test_rows_sum_to_one_exactly(scheme, lattice, rings):
    for vertex in _vertices(lattice):
        if vertex.closed and scheme is LOOP:  # Loop's smooth vertex weight has cos(2 pi/n): not rational
            S = sharp_subdivision_matrix(scheme, vertex, rings=rings)
            assert all(sp.simplify(sp.expand(sum(S.row(r))) - 1) == 0 for r in range(S.rows))
            continue
        S = exact_sharp_matrix(scheme, vertex, rings=rings)
        assert S.nrows() == len(vertex.ring_labels(rings))
        for r in range(S.nrows()):
            assert sum((S[r, c] for c in range(S.ncols())), flint.fmpq(0)) == 1, (vertex, r)


def _curve_indices(vertex, rings):
    """Indices of the points on the sharp edges through O (O included), in matrix order."""
    rays = set(vertex.sharp_rays())
    if not vertex.closed:
        rays.add(vertex.faces)
    labels = vertex.ring_labels(rings)
    return [i for i, (s, u, v) in enumerate(labels) if (u, v) == (0, 0) or (v == 0 and s in rays)]


@pytest.mark.parametrize("scheme, lattice", SCHEMES, ids=["catmull-clark", "loop"])
@pytest.mark.parametrize("rings", [1, 2])
def test_the_crease_curve_depends_only_on_the_crease_points(scheme, lattice, rings):
    """Block-triangular: the rows of the points on the boundary (or crease) have no entry off the curve's columns."""
    vertices = [SharpVertex.boundary(k, lattice) for k in range(1, 9)] + [SharpVertex.crease(k, 3, lattice) for k in range(1, 9)]
    for vertex in vertices:
        S = sharp_subdivision_matrix(scheme, vertex, rings=rings)
        curve = _curve_indices(vertex, rings)
        others = [c for c in range(S.cols) if c not in curve]
        assert len(curve) == 1 + 2 * rings
        assert S.extract(curve, others).is_zero_matrix, vertex
        assert not others or not S.extract(others, curve).is_zero_matrix  # the rest does see the curve


def _cubic_bspline_refinement(points):
    """One step of uniform cubic B-spline subdivision, with the mask derived from (1 + z)^4 / 8 (the two-scale
    relation of the cubic B-spline, the 4-fold convolution of the box function): fine point ``m`` (fine indices
    ``-len + 1 .. len - 1`` around the middle coarse point) is ``sum_j c[m - 2 j + 2] p_j``."""
    z = sp.Symbol("z")
    mask = [c / 8 for c in reversed(sp.Poly((1 + z) ** 4, z).all_coeffs())]
    half = len(points) // 2
    fine = {}
    for m in range(-half, half + 1):
        taps = [(m - 2 * j + 2, p) for j, p in zip(range(-half, half + 1), points) if 0 <= m - 2 * j + 2 < len(mask)]
        if sum(mask[k] for k, _ in taps) == 1:  # every tap of the mask inside the polygon
            fine[m] = sum((mask[k] * p for k, p in taps), sp.Integer(0))
    return fine


@pytest.mark.parametrize("scheme, lattice, k", [(CC, sd.QUAD, 2), (LOOP, sd.TRIANGLE, 3)], ids=["catmull-clark", "loop"])
def test_the_regular_boundary_curve_is_the_cubic_b_spline(scheme, lattice, k):
    """At a regular boundary vertex (2 quads, 3 triangles) the refined boundary points are the cubic B-spline's."""
    vertex = SharpVertex.boundary(k, lattice)
    rings = 3
    labels = vertex.ring_labels(rings)
    S = sharp_subdivision_matrix(scheme, vertex, rings=rings)
    values = sp.Matrix(sp.symbols(f"x0:{len(labels)}"))
    index = {lab: i for i, lab in enumerate(labels)}
    # the boundary polygon, from the far end of the last ray through O to the far end of the first one
    polygon = [index[(k, u, 0)] for u in range(rings, 0, -1)] + [0] + [index[(0, u, 0)] for u in range(1, rings + 1)]
    new = S * values
    expected = _cubic_bspline_refinement([values[i] for i in polygon])
    fine_labels = {0: 0, **{u: index[(0, u, 0)] for u in range(1, rings + 1)}, **{-u: index[(k, u, 0)] for u in range(1, rings + 1)}}
    assert len(expected) >= 5
    for m, value in expected.items():
        assert sp.expand(new[fine_labels[m]] - value) == 0, m


@pytest.mark.parametrize("scheme, lattice", SCHEMES, ids=["catmull-clark", "loop"])
def test_a_crease_has_the_union_spectrum_of_its_two_boundary_sectors(scheme, lattice):
    """charpoly(boundary k1) * charpoly(boundary k2) = charpoly(crease k1, k2) * charpoly(curve block): the curve
    (O and its two crease neighbours) is shared, each sector's interior points see only their own sector."""
    for k1, k2 in ((1, 2), (1, 4), (2, 2), (2, 5), (3, 3), (4, 1)):
        crease = exact_sharp_matrix(scheme, SharpVertex.crease(k1, k2, lattice), options=EDGE_ONLY)
        curve = [0, 1, 1 + k1]
        block = flint.fmpq_mat(3, 3, [crease[r, c] for r in curve for c in curve])
        left = exact_sharp_matrix(scheme, SharpVertex.boundary(k1, lattice), options=EDGE_ONLY).charpoly()
        right = exact_sharp_matrix(scheme, SharpVertex.boundary(k2, lattice), options=EDGE_ONLY).charpoly()
        assert left * right == crease.charpoly() * block.charpoly(), (k1, k2)


def test_edge_and_corner_makes_a_one_face_boundary_vertex_a_corner():
    for scheme, lattice in SCHEMES:
        corner = sharp_subdivision_matrix(scheme, SharpVertex.boundary(1, lattice))
        assert list(corner.row(0)) == [1] + [0] * (corner.cols - 1)
        crease = sharp_subdivision_matrix(scheme, SharpVertex.boundary(1, lattice), options=EDGE_ONLY)
        assert crease[0, 0] == scheme.sharp.crease_centre and crease[0, 1] == crease[0, 2] == scheme.sharp.crease_end
        assert sharp_subdivision_matrix(scheme, SharpVertex.corner(1, lattice), options=EDGE_ONLY) == corner


def _smooth(scheme, n):
    """The interior matrix in the sharp vertex's order (the same on quads and triangles: O, a_i, b_i)."""
    return sp.ImmutableMatrix(sd.subdivision_matrix(scheme, n))


@pytest.mark.parametrize("scheme, lattice", SCHEMES, ids=["catmull-clark", "loop"])
def test_semi_sharp_blends_smooth_and_sharp_as_opensubdiv_does(scheme, lattice):
    """Sharpness 0 is the smooth interior matrix, sharpness >= 1 the infinitely sharp one, and 0 < s < 1 their blend
    ``s * sharp + (1 - s) * smooth``: OpenSubdiv's edge rule weighs the crease mask by s, and its vertex rule the
    parent (crease) mask by the mean sharpness of the edges that turn smooth (``ComputeFractionalWeightAtVertex``)."""
    for vertex in (SharpVertex.crease(2, 3, lattice), SharpVertex.dart(5, lattice), SharpVertex.crease(1, 3, lattice)):
        def at(s, level=0, sectors=vertex.sectors):
            v = SharpVertex(lattice, sectors, True, False, s)
            return sharp_subdivision_matrix(scheme, v, level=level)

        smooth, sharp = at(0), at(math.inf)
        assert (smooth - _smooth(scheme, vertex.faces)).applyfunc(sp.simplify).is_zero_matrix
        assert smooth != sharp
        for s in (1, Fraction(5, 2), 10):
            assert at(s) == sharp
        for s in (Fraction(1, 2), Fraction(3, 10)):
            blend = sp.Rational(s.numerator, s.denominator)
            assert (at(s) - (blend * sharp + (1 - blend) * smooth)).applyfunc(sp.simplify).is_zero_matrix
        # one level later the sharpness has decayed by 1: 5/2 -> 3/2 -> 1/2 -> 0
        assert at(Fraction(5, 2), level=1) == at(Fraction(3, 2)) == sharp
        assert at(Fraction(5, 2), level=2) == at(Fraction(1, 2))
        assert at(Fraction(5, 2), level=3) == smooth
        assert at(math.inf, level=5) == sharp


def test_a_semi_sharp_vertex_row_blends_with_the_mean_of_the_sharpness_that_turns_smooth():
    """A corner-like vertex with three semi-sharp edges of sharpness 1/2: corner rule in the parent, smooth in the
    child; the vertex row is 1/2 corner + 1/2 smooth (the mean of the three parent sharpnesses)."""
    vertex = SharpVertex(sd.QUAD, (2, 2, 1), True, False, Fraction(1, 2))
    row = sharp_subdivision_matrix(CC, vertex).row(0)
    smooth = _smooth(CC, 5).row(0)
    corner = sp.Matrix([[1] + [0] * 10])
    assert row == (smooth + corner) / 2


def test_the_one_ring_is_the_leading_block_of_the_two_ring():
    for scheme, lattice in SCHEMES:
        for vertex in (SharpVertex.boundary(3, lattice), SharpVertex.crease(2, 3, lattice, Fraction(1, 2))):
            one, two = (sharp_subdivision_matrix(scheme, vertex, rings=r) for r in (1, 2))
            size = vertex.one_ring_size()
            assert two.extract(list(range(size)), list(range(size))) == one
            assert two.extract(list(range(size)), list(range(size, two.cols))).is_zero_matrix


def test_vertex_order_and_sizes():
    v = SharpVertex.boundary(3, sd.QUAD)
    assert v.vertex_order() == ("O", "a_0", "a_1", "a_2", "a_3", "b_0", "b_1", "b_2")
    assert v.one_ring_size() == len(v.vertex_order()) == len(v.ring_labels(1))
    assert SharpVertex.crease(2, 3, sd.TRIANGLE).vertex_order() == ("O",) + tuple(f"a_{i}" for i in range(5))
    assert SharpVertex.crease(2, 3, sd.QUAD).sharp_rays() == (0, 2)
    assert SharpVertex.corner(2, "quad", angle=sp.pi / 2).corner is True
    assert SharpVertex.boundary(2, "quad").corner is False


@pytest.mark.parametrize("build, message", [
    (lambda: SharpVertex.boundary(0, sd.QUAD), "faces of a sector"),
    (lambda: SharpVertex.boundary(2.0, sd.QUAD), "faces of a sector"),
    (lambda: SharpVertex.boundary(2, "hexagon"), "hexagon"),
    (lambda: SharpVertex.crease(1, 1, sd.QUAD), "3 or more"),
    (lambda: SharpVertex.dart(5, sd.QUAD, sharpness=-1), "sharpness"),
    (lambda: SharpVertex.dart(5, sd.QUAD, sharpness="x"), "sharpness"),
    (lambda: SharpVertex.corner(2, sd.QUAD, angle=7), "angle"),
    (lambda: SharpVertex.corner(2, sd.QUAD, angle=0.5), "angle"),
    (lambda: SharpVertex(sd.QUAD, "12", False), "sectors"),
    (lambda: SharpVertex(sd.QUAD, (2,), "no"), "closed"),
])
def test_bad_vertices_are_refused_in_one_line(build, message):
    with pytest.raises((InvalidInputError, InvalidTypeError, sd.InvalidSchemeError), match=message) as info:
        build()
    assert "\n" not in str(info.value)


def test_bad_arguments_of_the_matrix_are_refused():
    with pytest.raises(InvalidTypeError, match="vertex"):
        sharp_subdivision_matrix(CC, (3, False))
    with pytest.raises(InvalidMeshError, match="triangle"):
        sharp_subdivision_matrix(CC, SharpVertex.boundary(3, sd.TRIANGLE))
    with pytest.raises(InvalidTypeError, match="options"):
        sharp_subdivision_matrix(CC, SharpVertex.boundary(3, sd.QUAD), options="chaikin")
    with pytest.raises(InvalidInputError, match="crease_method"):
        SharpOptions(crease_method="linear")
