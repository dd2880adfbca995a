"""The boundary patch: the spline of the control net with phantom points reproduces the sharp rules, exactly."""

import pytest
import sympy as sp

from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.lattice import QUAD, TRIANGLE
from symdecomp.schemes.sector_patch import ORIGIN, check_spline_sharp_rules, phantom_reproduction, sector_net, sector_point
from symdecomp.schemes.sharp import SharpRules, standard_sharp_rules


@pytest.mark.parametrize("lat", [QUAD, TRIANGLE])
def test_phantom_points_reproduce_the_standard_crease_rules(lat):
    # the regular rules on the extended net give the crease rules on the boundary, and the refined phantoms are again
    # phantoms of the refined real points: every residual expands to 0
    assert phantom_reproduction(lat, standard_sharp_rules()) == {"vertex": 0, "edge": 0, "phantom": 0}


@pytest.mark.parametrize("lat", [QUAD, TRIANGLE])
def test_other_crease_rules_are_not_reproduced(lat):
    # an affine crease vertex rule other than the B-spline's leaves a residual on the boundary vertex
    other = SharpRules(sp.Rational(7, 8), sp.Rational(1, 16), sp.Rational(1, 2))
    out = phantom_reproduction(lat, other)
    assert out["vertex"] != 0 and out["edge"] == 0
    p0 = sp.Symbol("p_0_0")
    assert sp.expand(out["vertex"]).coeff(p0) == sp.Rational(3, 4) - sp.Rational(7, 8)


def test_loop_point_reflection_would_not_do():
    # the point reflection 2 p_b - p_i (the quad phantom) on triangles: Loop's vertex rule 5/8, 1/16 x 6 becomes 7/8, 1/16
    # (two phantoms 2 p_0 - q each), which is why the triangle phantom is the mirror image instead
    beta = sp.Rational(1, 16)
    q1, q2, p0, pm, pp = sp.symbols("q1 q2 p0 pm pp")
    reflected = (1 - 6 * beta) * p0 + beta * (pm + pp + q1 + q2 + (2 * p0 - q1) + (2 * p0 - q2))
    mirrored = (1 - 6 * beta) * p0 + beta * (pm + pp + q1 + q2 + (p0 + pm - q2) + (p0 + pp - q1))
    assert sp.expand(reflected - (sp.Rational(7, 8) * p0 + beta * (pm + pp))) == 0
    assert sp.expand(mirrored - (sp.Rational(3, 4) * p0 + sp.Rational(1, 8) * (pm + pp))) == 0


def test_sector_points_resolve_to_canonical_labels_and_phantoms():
    assert sector_point(QUAD, 1, 0, 0, 0) == ((1, ORIGIN),)
    assert sector_point(QUAD, 1, 0, 2, -1) == ((2, (0, 2, 0)), (-1, (0, 2, 1)))  # across ray 0
    assert sector_point(QUAD, 1, 0, -1, 2) == ((2, (1, 2, 0)), (-1, (0, 1, 2)))  # across ray k = 1
    assert sector_point(QUAD, 3, 1, 2, -1) == ((1, (0, 1, 2)),)  # the neighbouring face, no phantom
    assert sector_point(TRIANGLE, 2, 0, 1, -1) == ((1, ORIGIN), (1, (0, 1, 0)), (-1, (1, 1, 0)))
    with pytest.raises(InvalidInputError, match="more than one step"):
        sector_point(QUAD, 1, 0, 2, -2)
    with pytest.raises(InvalidInputError, match="0 <= s < k"):
        sector_point(QUAD, 2, 2, 1, 1)


def test_sector_net_of_a_linear_function_is_linear_across_the_boundary():
    # quads: the reflection of a function linear in v continues it (p(u, -1) = 2 p(u, 0) - p(u, 1))
    value = lambda lab: 0 if lab == ORIGIN else (lab[1] + 2 * lab[2] if lab[0] == 0 else 7)  # noqa: E731
    assert sector_net(QUAD, 2, 0, [(3, -1), (1, -1)], value) == [3 - 2, 1 - 2]


def test_non_spline_crease_rules_are_not_applicable():
    check_spline_sharp_rules(standard_sharp_rules())
    with pytest.raises(NotApplicableError, match="not the cubic B-spline's"):
        check_spline_sharp_rules(SharpRules(sp.Rational(7, 8), sp.Rational(1, 16), sp.Rational(1, 2)))
