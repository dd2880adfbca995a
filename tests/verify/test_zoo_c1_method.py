"""The method line ``c1`` prints for a scheme of the zoo names the test that ran, and none when no test applies."""

import sympy as sp

from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencils import KindRules, Rule, StencilScheme, Term
from symdecomp.verify.c1_four_direction import FOUR_DIRECTION_METHOD
from symdecomp.verify.c1_zoo import NO_METHOD, c1_zoo
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import engine_neighbourhood


def test_a_scheme_no_test_applies_to_is_not_reported_as_reif_s_spline_test():
    # a dual rule with no spline patch here (its corner weights are neither the biquadratic B-spline's nor a piecewise
    # quadratic's on the four-direction mesh) was printed under "Reif's test on the characteristic map's ring of
    # biquadratic B-spline patches", a test that never ran for it
    corner = KindRules("corner", (Rule((Term(sp.Rational(5, 8)), Term(sp.Rational(1, 8), ("next",)),
                                        Term(sp.Rational(1, 8), ("next", "next")), Term(sp.Rational(1, 8), ("prev",)))),))
    r = c1_zoo(StencilScheme("skewed", "quad", "dual", (corner,)), 5)
    assert r.verdict is C1Verdict.UNDECIDED and r.as_json()["method"] == NO_METHOD
    assert "Zorin's test, which needs no spline patch, is written here for a net around a vertex of the triangle lattice, " \
           "and this scheme centres on a face; nor on the four-direction mesh: corner rule (5/8, 1/8, 1/8, 1/8)" in r.reason


def test_midedge_is_reported_under_the_four_direction_test_that_ran():
    r = c1_zoo(load_zoo("midedge"), 5, neighbourhood=engine_neighbourhood)
    assert r.verdict is C1Verdict.C1 and r.as_json()["method"] == FOUR_DIRECTION_METHOD
