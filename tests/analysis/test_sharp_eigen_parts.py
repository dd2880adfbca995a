"""The block-triangular parts of a sharp vertex's matrix, found from the matrix (symdecomp.analysis.triangular_eigen)."""

from __future__ import annotations

import math

import flint
import pytest

import symdecomp as sd
from symdecomp.analysis.triangular_eigen import matrix_parts, merge, part_eigenvalues, submatrix

CC, LOOP = sd.catmull_clark(), sd.loop()


@pytest.mark.parametrize("scheme, vertex, labels", [
    (CC, sd.SharpVertex.boundary(4, sd.QUAD), ["crease", "sector 1"]),
    (CC, sd.SharpVertex.crease(2, 3, sd.QUAD), ["crease", "sector 1", "sector 2"]),
    (LOOP, sd.SharpVertex.corner(3, sd.TRIANGLE), ["crease", "sector 1"]),
    (CC, sd.SharpVertex.dart(5, sd.QUAD), ["whole"]),
    (LOOP, sd.SharpVertex.crease(3, 3, sd.TRIANGLE, sharpness=2), ["crease", "sector 1", "sector 2"]),
])
def test_the_parts_multiply_to_the_characteristic_polynomial(scheme, vertex, labels):
    S = sd.exact_sharp_matrix(scheme, vertex)
    parts = matrix_parts(S, vertex.crease_points())
    assert [p.label for p in parts] == labels
    assert sorted(i for p in parts for i in p.indices) == list(range(S.nrows()))
    product = flint.fmpq_poly([1])
    for p in parts:
        product *= submatrix(S, p.indices).charpoly()
    assert product == S.charpoly()
    # block lower-triangular: a part's rows read only itself and the crease
    crease = set(parts[0].indices)
    for p in parts[1:]:
        for i in p.indices:
            assert {j for j in range(S.ncols()) if S[i, j] != 0} <= crease | set(p.indices)
    values = merge(part_eigenvalues(S, parts))
    assert sum(v.multiplicity for v in values) == S.nrows()


def test_a_semi_sharp_crease_below_sharpness_1_has_no_block_structure():
    from fractions import Fraction

    vertex = sd.SharpVertex.crease(3, 3, sd.QUAD, sharpness=Fraction(1, 2))
    S = sd.exact_sharp_matrix(CC, vertex)
    assert [p.label for p in matrix_parts(S, vertex.crease_points())] == ["whole"]
    assert vertex.sharpness != math.inf
