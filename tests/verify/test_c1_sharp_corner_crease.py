"""Zorin's test at corners and creases: where the standard rules fail, what BLZ's near-edge rule fixes, and what not."""

from fractions import Fraction

import flint
import pytest
import sympy as sp

from symdecomp.errors import InvalidTypeError, NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sharp import SharpRules
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_sector_matrix import c1_sharp_test
from symdecomp.verify.mirror_parts import mirror_label, sector_eigenvalues, sector_matrices
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_injectivity import injective_condition

CC, LOOP = catmull_clark(), loop()


def test_a_crease_is_two_boundary_sectors():
    # each side of an infinitely sharp crease is tested on its own, and the crease vertex's spectrum is the union
    crease = sector_matrices(CC, SharpVertex.crease(2, 3, "quad"), 1)
    alone = sector_matrices(CC, SharpVertex.boundary(3, "quad"))
    assert crease.matrix == alone.matrix and crease.labels == alone.labels
    r = c1_sharp_test(CC, SharpVertex.crease(2, 3, "quad"))
    assert r.verdict is C1Verdict.C1 and r.reason.startswith("side 1 (2 faces): ") and "side 2 (3 faces): " in r.reason


def test_a_crease_fails_with_its_worse_side():
    r = c1_sharp_test(CC, SharpVertex.crease(3, 6, "quad"))
    assert r.verdict is C1Verdict.NOT_C1
    assert "side 2 (6 faces): the tangent of the boundary curve" in r.reason
    blz = c1_sharp_test(load_scheme("catmull-clark-blz"), SharpVertex.crease(3, 6, "quad"))
    assert blz.verdict is C1Verdict.C1 and "past the modified edges" in blz.reason  # BLZ's rule makes both sides C1


def test_a_semi_sharp_crease_is_the_interior_vertex():
    r = c1_sharp_test(CC, SharpVertex.crease(2, 3, "quad", sharpness=Fraction(5, 2)))
    interior = c1_test(CC, 5)
    assert r.verdict is interior.verdict and r.reason.endswith(interior.reason)
    assert "smooth from level 3 on" in r.reason


@pytest.mark.parametrize("scheme, k", [(CC, 3), (CC, 4), (LOOP, 4), (LOOP, 5)], ids=str)
def test_standard_corners_with_many_faces_fail(scheme, k):
    # a corner has two boundary curves, both tangents (eigenvalue 1/2 twice) must be subdominant; the first sine
    # mode of the standard rules exceeds 1/2 from these k on
    r = c1_sharp_test(scheme, SharpVertex.corner(k, scheme.lattice))
    assert r.verdict is C1Verdict.NOT_C1 and "tangents of the 2 boundary curves" in r.reason
    assert r.lambdas[0] > 0.5 and abs(r.lambdas[1] - 0.5) < 1e-12


def test_a_concave_corner_folds_with_the_standard_rules():
    convex = c1_sharp_test(CC, SharpVertex.corner(1, "quad", sp.pi / 2))
    concave = c1_sharp_test(CC, SharpVertex.corner(1, "quad", 3 * sp.pi / 2))
    assert convex.verdict is C1Verdict.C1 and 0 < convex.opening < 1
    assert concave.verdict is C1Verdict.NOT_C1 and "a convex sector, but the corner is concave" in concave.reason


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_blz_convex_corners_are_c1(k):
    scheme = load_scheme("loop-blz")
    r = c1_sharp_test(scheme, SharpVertex.corner(k, "triangle", sp.pi / 2))
    assert all(abs(x - 0.5) < 1e-12 for x in r.lambdas)
    assert r.verdict is C1Verdict.C1 and 0 < r.opening < 1, r.reason  # a convex image
    # no smooth edge at O for k = 1: the usual ring; else the ring past the modified edges, whose patches are splines
    assert ("past the modified edges" in r.reason) is (k > 1)


@pytest.mark.parametrize("k", [2, 3, 4])
def test_blz_near_edge_rule_alone_does_not_make_concave_corners(k):
    # theta_k = alpha/k with alpha > pi lifts the first sine mode above 1/2: the corner's two tangents are no longer both
    # subdominant (BLZ modify concave corners further; a SharpRules near-edge rule cannot express that)
    r = c1_sharp_test(load_scheme("loop-blz"), SharpVertex.corner(k, "triangle", 3 * sp.pi / 2))
    assert r.verdict is C1Verdict.NOT_C1 and "tangents of the 2 boundary curves" in r.reason
    assert r.lambdas[0] > 0.5


def test_the_sector_spectrum_is_split_by_the_mirror():
    sm = sector_matrices(CC, SharpVertex.boundary(3, "quad"))
    assert all(mirror_label(mirror_label(lab, 3), 3) == lab for lab in sm.labels)
    values = sector_eigenvalues(sm)
    assert len(values) == sm.matrix.rows
    assert {p.name for _, p, _ in values} == {"even", "odd"}
    # the trace is the sum of the eigenvalues
    total = sum((v for v, _, _ in values), flint.acb(0))
    assert total.contains(flint.acb(flint.fmpq(int(sm.matrix.trace().p), int(sm.matrix.trace().q))))


def test_the_injectivity_criterion_from_the_sweeps():
    pi = flint.arb.pi()
    vertex = SharpVertex.boundary(3, "quad")
    assert injective_condition(None, vertex, 1, None, (pi, pi))[0] is C1Verdict.C1
    assert injective_condition(None, vertex, -1, None, (-pi, -pi))[0] is C1Verdict.C1
    fold = injective_condition(None, vertex, 1, None, (-pi / 2, -pi / 2))
    assert fold[0] is C1Verdict.NOT_C1 and "folds" in fold[1]
    over = injective_condition(None, vertex, 1, None, (5 * pi / 2, 5 * pi / 2))
    assert over[0] is C1Verdict.NOT_C1 and "overlaps" in over[1]
    assert injective_condition(None, vertex, 1, None, (pi, 3 * pi))[0] is C1Verdict.UNDECIDED  # a zero of chi inside the ring


def test_what_the_sector_test_refuses():
    with pytest.raises(InvalidTypeError):
        c1_sharp_test(CC, (3, "quad"))
    with pytest.raises(NotApplicableError, match="lives on quad meshes"):
        c1_sharp_test(CC, SharpVertex.boundary(3, "triangle"))
    with pytest.raises(NotApplicableError, match="a dart has one sharp edge"):
        c1_sharp_test(CC, SharpVertex.dart(5, "quad"))
    import dataclasses

    odd = dataclasses.replace(CC, sharp=SharpRules(sp.Rational(7, 8), sp.Rational(1, 16), sp.Rational(1, 2)))
    with pytest.raises(NotApplicableError, match="not the cubic B-spline's"):
        c1_sharp_test(odd, SharpVertex.boundary(3, "quad"))
