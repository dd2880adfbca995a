"""Crease, boundary and corner evaluation data against exact refinement at dyadic parameters, k = 1..6."""

import dataclasses

import flint
import pytest

from symdecomp.analysis.sector_evaldata import sector_evaldata
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.patch_eval import evaldata_dyadic_check

CC = catmull_clark()
BLZ = load_scheme("catmull-clark-blz")


def _vertices(k):
    out = [SharpVertex.boundary(k, "quad"), SharpVertex.corner(k, "quad")]
    return out + [SharpVertex.crease(k, k, "quad") if k > 1 else SharpVertex.crease(1, 2, "quad")]


@pytest.mark.parametrize("scheme", [CC, BLZ], ids=lambda s: s.name)
@pytest.mark.parametrize("k", [1, 2, 3, 4, pytest.param(5, marks=pytest.mark.slow), pytest.param(6, marks=pytest.mark.slow)])
def test_data_equal_exact_refinement(scheme, k):
    for vertex in _vertices(k):
        r = evaldata_dyadic_check(scheme, vertex, levels=(1, 2))
        assert r["points"] > 0 and r["mismatches"] == 0, (vertex, r)
        assert r["routes"] == (("eigen", "powers") if sector_evaldata(scheme, vertex).exact else ("powers",))


def _mutated_matrix(data):
    """Another weight in A: 1/64 moved from O's own weight to a_0's (rows still sum to 1)."""
    a = data.matrix.__class__(data.matrix)
    a[0, 0] -= flint.fmpq(1, 64) if data.exact else flint.arb(1) / 64
    a[0, 1] += flint.fmpq(1, 64) if data.exact else flint.arb(1) / 64
    return dataclasses.replace(data, matrix=a, decomposition=None, phi=None)


def _mutated_cell(data):
    cells = [list(face) for face in data.cells]
    p = cells[0][0].__class__(cells[0][0])
    p[5, 0] += 1
    p[5, 1] -= 1
    cells[0][0] = p
    return dataclasses.replace(data, cells=tuple(tuple(face) for face in cells), decomposition=None, phi=None)


@pytest.mark.parametrize("scheme, vertex", [(CC, SharpVertex.crease(2, 3, "quad")), (BLZ, SharpVertex.boundary(3, "quad")),
                                            (BLZ, SharpVertex.boundary(5, "quad"))], ids=lambda x: getattr(x, "name", repr(x)))
@pytest.mark.parametrize("mutate", [_mutated_matrix, _mutated_cell])
def test_another_weight_fails_the_check(scheme, vertex, mutate):
    data = sector_evaldata(scheme, vertex)
    assert evaldata_dyadic_check(scheme, vertex, levels=(1, 2), data=data)["mismatches"] == 0
    r = evaldata_dyadic_check(scheme, vertex, levels=(1, 2, 3), data=mutate(data))
    assert r["mismatches"] > 0


def test_unequal_irrational_sides_and_a_corner_angle():
    """BLZ's weights in two fields (cos(pi/4), cos(pi/5)) at one crease, and theta_k = (pi/2)/k at a corner."""
    import sympy as sp

    for vertex in (SharpVertex.crease(4, 5, "quad"), SharpVertex.corner(3, "quad", angle=sp.pi / 2)):
        data = sector_evaldata(BLZ, vertex)
        assert not data.exact and data.modified
        assert evaldata_dyadic_check(BLZ, vertex, levels=(1, 2))["mismatches"] == 0
