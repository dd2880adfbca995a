"""Reif's test for Midedge over its derived four-direction patch, against a matrix built here by refining an explicit mesh.

The local mesh, the one-step matrix from corner weights and the orbit labels are those of the Doo-Sabin tests
(:mod:`tests.verify.test_c1_dual`): Midedge's two mid-edge steps are one dual step whose corner rule is ``1/2`` on the
corner and ``1/4`` on each neighbour in the face, in the centre ``n``-gon as in the quads. Its ring-1 blocks have
repeated eigenvalues (Midedge's zero weight on the opposite corner), so the spectrum is taken with Arb's
``multiple=True`` here.
"""

from fractions import Fraction as F

import flint
import pytest
import sympy as sp

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.four_direction import four_direction_patch
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.c1_four_direction import FOUR_DIRECTION_METHOD, certify_four_direction_ring
from symdecomp.verify.c1_four_direction_jordan import JORDAN_CHAIN_METHOD
from symdecomp.verify.c1_zoo import NO_METHOD, ZooNeighbourhood, c1_dual_test, c1_zoo, four_direction_route
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import engine_neighbourhood
from tests.verify.test_c1_dual import (
    CLASSES,
    doo_sabin_matrix,
    doo_sabin_scheme,
    eigenvector,
    frequency_block,
    local_mesh,
    spectral_result,
    weights_with_eigenvalues,
)

MIDEDGE = (F(1, 2), F(1, 4), F(0), F(1, 4))


def _arb(x):
    return flint.arb(flint.fmpq(x.numerator, x.denominator))


def midedge_centre(n):
    """The corner rule in the centre n-gon: 1/2 on the corner, 1/4 on each neighbour."""
    centre = [flint.arb(0)] * n
    centre[0] += _arb(F(1, 2))
    centre[1] += _arb(F(1, 4))
    centre[n - 1] += _arb(F(1, 4))
    return centre


def spectrum(n, centre, S):
    """Every eigenvalue with its frequency: the centre's circulant, ring 1's blocks (repeated roots allowed), ring 2's zeros."""
    out = []
    ring1 = [r for r, c in enumerate(CLASSES) if max(c) == 1]
    for j in range(n):
        out.append((flint.acb(sum((centre[k] * flint.arb.cos_pi_fmpq(flint.fmpq(2 * j * k, n)) for k in range(n)), flint.arb(0))), j))
        B = frequency_block(n, S, j)
        out += [(e, j) for e in flint.acb_mat([[B[r][k] for k in ring1] for r in ring1]).eig(multiple=True)]
        out += [(flint.acb(0), j)] * sum(1 for c in CLASSES if max(c) == 2)
    return out


def neighbourhood(n, centre=None) -> ZooNeighbourhood:
    centre = midedge_centre(n) if centre is None else centre
    S = doo_sabin_matrix(n, centre, [_arb(w) for w in MIDEDGE])
    spectral = spectral_result(n, spectrum(n, centre, S))
    j = spectral.subdominant.frequency
    v = eigenvector(frequency_block(n, S, j), spectral.subdominant.value)
    points = {(s, *c): flint.acb(flint.fmpq(2 * j * s, n)).exp_pi_i() * v[i] for s in range(n) for i, c in enumerate(CLASSES)}
    return ZooNeighbourhood(local_mesh(n), points, spectral)


@pytest.fixture(scope="module")
def patch():
    return four_direction_patch(MIDEDGE)


@pytest.mark.parametrize("n", [4, 5, 6, 7, 8, 12, 16])
def test_midedge_is_c1_at_valences_4_to_8_12_and_16(n, patch):
    r = c1_dual_test(neighbourhood(n), scheme="midedge", n=n, patch=patch)
    assert r.verdict is C1Verdict.C1, r.reason
    cos = flint.arb.cos_pi_fmpq(flint.fmpq(2, n))
    assert r.spectral.subdominant.value.overlaps(flint.acb(1 + cos) / 2) and r.frequency == 1  # 1/2 + cos(2 pi/n)/2
    assert r.winding_number == r.jacobian_sign == 1 and r.jacobian_lower_bound > 0
    assert r.method == FOUR_DIRECTION_METHOD


@pytest.mark.parametrize("n", [4, 5, 7])
def test_the_engine_agrees_with_the_matrix_built_here(n):
    ours = c1_dual_test(neighbourhood(n), scheme="midedge", n=n, patch=four_direction_patch(MIDEDGE))
    engine = c1_zoo(load_zoo("midedge"), n, neighbourhood=engine_neighbourhood)
    assert engine.verdict is ours.verdict is C1Verdict.C1
    assert engine.spectral.subdominant.value.overlaps(ours.spectral.subdominant.value) and engine.frequency == ours.frequency
    assert (engine.jacobian_sign, engine.winding_number) == (ours.jacobian_sign, ours.winding_number) == (1, 1)
    assert abs(engine.jacobian_lower_bound - ours.jacobian_lower_bound) < 1e-3 * ours.jacobian_lower_bound  # 3 digits
    assert engine.as_json()["method"] == FOUR_DIRECTION_METHOD


def test_at_the_regular_valence_the_ring_is_the_plane_cut_in_unit_cells(patch):
    """n = 4, the lattice's own coordinates: every triangle's Jacobian is that of the identity (1/2 in its parameters)."""
    half = flint.fmpq(1, 2)
    rot = {0: (1, 0), 1: (0, 1), 2: (-1, 0), 3: (0, -1)}
    points = {}
    for s in range(4):
        for a, b in CLASSES:
            c, d = rot[s]
            points[(s, a, b)] = (c * (a + half) - d * (b + half), d * (a + half) + c * (b + half))
    ring = certify_four_direction_ring(local_mesh(4), points, patch)
    assert (ring.status, ring.jacobian_sign, ring.winding_number, ring.patches) == ("regular", 1, 1, 12)
    assert 0.5 - 1e-12 < ring.jacobian_lower_bound <= 0.5


def test_a_subdominant_eigenvalue_at_frequency_two_winds_twice_and_is_not_c1(patch):
    mu = {0: 1, 1: flint.fmpq(1, 2), 2: flint.fmpq(3, 5)}
    centre = weights_with_eigenvalues(6, lambda j: flint.arb(mu.get(min(j, 6 - j), flint.fmpq(1, 4))))
    r = c1_dual_test(neighbourhood(6, centre), scheme="mutated", n=6, patch=patch)
    assert r.verdict is C1Verdict.NOT_C1 and r.frequency == 2 and r.winding_number == 2


@pytest.mark.parametrize("lam, verdict", [(F(4, 5), C1Verdict.C1), (F(9, 10), C1Verdict.NOT_C1)])
def test_the_centre_triangle_s_eigenvalue_decides_whether_the_map_folds(lam, verdict, patch):
    """A perturbed corner rule at n = 3 (its frequency-1 eigenvalue moved to lam): 4/5 keeps the ring regular, 9/10 folds it."""
    centre = weights_with_eigenvalues(3, lambda j: flint.arb(1) if j == 0 else _arb(lam))
    r = c1_dual_test(neighbourhood(3, centre), scheme="mutated", n=3, patch=patch)
    assert r.verdict is verdict, r.reason
    if verdict is C1Verdict.NOT_C1:
        assert r.reason.startswith("the Jacobian of the characteristic map changes sign (the patch of vertex (")


def test_midedge_at_valence_3_is_c1_by_the_map_of_the_jordan_chains():
    """Every eigenvector gives a nonzero function, and 1/4 has a Jordan block at frequencies 1, 2
    (:mod:`tests.verify.test_c1_four_direction_quotient` checks the structure against sympy); the map of the chains'
    eigenvectors is regular and winds once (:mod:`symdecomp.verify.c1_four_direction_jordan`)."""
    r = c1_zoo(load_zoo("midedge"), 3, neighbourhood=engine_neighbourhood)
    assert r.verdict is C1Verdict.C1 and r.method == JORDAN_CHAIN_METHOD
    assert r.reason.startswith("the subdominant eigenvalue 0.25 is not a real double eigenvalue of one pair of frequencies")
    assert "so every eigenvector counts" in r.reason and "Jordan blocks: 1 of size 2, 1 of size 1" in r.reason
    assert "the rings grow as m (1/4)^m on the eigenvectors e = (S - 1/4) g" in r.reason
    assert r.reason.endswith("C1 for every net with c_x x c_y != 0 (almost every control net)")
    assert r.winding_number == r.jacobian_sign and r.jacobian_lower_bound > 0.0065


def test_the_route_is_read_from_the_corner_rule():
    assert four_direction_route(load_zoo("midedge")).corner_weights == MIDEDGE
    assert four_direction_route(doo_sabin_scheme()).startswith("corner rule (9/16, 3/16, 1/16, 3/16): its regular part is no "
                                                               "continuous piecewise quadratic on the four-direction mesh")
    assert four_direction_route(load_zoo("sqrt3")) == "its steps are sqrt3, not dual"
    r = c1_zoo(doo_sabin_scheme("equal-weights", corner=sp.Rational(1, 4)), 5)
    assert r.verdict is C1Verdict.UNDECIDED and r.as_json()["method"] == NO_METHOD
    assert r.reason.endswith("; nor on the four-direction mesh: corner rule (1/4, 1/4, 1/4, 1/4): its regular part, a piecewise "
                             "quadratic on the four-direction mesh, is not C1 (its gradient jumps across an edge), so Reif's "
                             "test does not apply")


def test_a_ring_needs_a_point_for_every_grid_vertex(patch):
    nb = neighbourhood(5)
    points = {v: z for v, z in nb.points.items() if v != (1, 2, 2)}
    with pytest.raises(InvalidMeshError, match=r"^points: no control point for vertex \(1, 2, 2\)$"):
        certify_four_direction_ring(nb.mesh, points, patch)
