"""The wide ring for Biermann-Levin-Zorin's near-edge rule: its patches are splines (exact rows), and the map it certifies."""

import pytest
import sympy as sp

from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.c1_sector_matrix import c1_sharp_test
from symdecomp.verify.mirror_parts import sector_matrices
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_ring import irregular_rows, ring_faces


@pytest.mark.parametrize("k", [3, 4, 5])
def test_blz_rows_are_regular_from_distance_two(k):
    sm = sector_matrices(load_scheme("catmull-clark-blz"), SharpVertex.boundary(k, "quad"))
    assert irregular_rows(sm) == []  # every new point at level-1 distance >= 2: the tensor B-spline rule, exactly
    # the check sees the modified rule: at distance 1 the points next to O on the smooth rays are not regular
    assert irregular_rows(sm, 1) == [(s, 1, 0) for s in range(1, k)]


def test_standard_rules_are_regular_from_distance_one():
    sm = sector_matrices(catmull_clark(), SharpVertex.boundary(4, "quad"))
    assert irregular_rows(sm, 1) == []
    sm = sector_matrices(loop(), SharpVertex.boundary(5, "triangle"))
    assert irregular_rows(sm, 1) == []


def test_a_convex_corner_with_blz_is_certified_on_the_wide_ring():
    r = c1_sharp_test(load_scheme("catmull-clark-blz"), SharpVertex.corner(3, "quad", sp.pi / 2))
    assert r.verdict is C1Verdict.C1 and "past the modified edges" in r.reason and r.jacobian_lower_bound > 0
    assert 0 < r.opening < 1  # convex, as the corner's angle pi/2 asks


@pytest.mark.parametrize("k", [2, 4, 6])
def test_loop_blz_rows_are_regular_from_distance_two(k):
    sm = sector_matrices(load_scheme("loop-blz"), SharpVertex.boundary(k, "triangle"))
    assert irregular_rows(sm) == []  # Loop's regular rules (with the mirror phantoms), exactly
    assert irregular_rows(sm, 1) == [(s, 1, 0) for s in range(1, k)]
    assert len(ring_faces(sm.lattice)) == 12  # the annulus between distance 2 and 4: 16 / 2 - 4 / 2 unit squares, 2 triangles each
