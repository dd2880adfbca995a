"""The method line ``c1`` prints for a scheme of the zoo names the test that ran, and none when no test applies."""

from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.c1_zoo import NO_METHOD, c1_zoo
from symdecomp.verify.result import C1Verdict


def test_a_scheme_no_test_applies_to_is_not_reported_as_reif_s_spline_test():
    # mid-edge (no B-spline regular part, an n-gon at the centre) was printed under "Reif's test on the characteristic
    # map's ring of biquadratic B-spline patches", a test that never ran for it
    r = c1_zoo(load_zoo("midedge"), 5)
    assert r.verdict is C1Verdict.UNDECIDED and r.as_json()["method"] == NO_METHOD
    assert r.reason.endswith("Zorin's test, which needs no spline patch, is written here for a net around a vertex of the "
                             "triangle lattice, and this scheme centres on a face")
