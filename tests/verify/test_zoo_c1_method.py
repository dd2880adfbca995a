"""The method line ``c1`` prints for a scheme of the zoo names the test that ran, and none when no test applies."""

import pytest

from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.c1_zoo import NO_METHOD, c1_zoo
from symdecomp.verify.result import C1Verdict


@pytest.mark.parametrize("name", ["sqrt3", "midedge"])
def test_a_scheme_no_test_applies_to_is_not_reported_as_reif_s_spline_test(name):
    # sqrt(3) (two steps on triangles) and mid-edge (no B-spline regular part) were printed under "Reif's test on the
    # characteristic map's ring of biquadratic B-spline patches", a test that never ran for them
    r = c1_zoo(load_zoo(name), 5)
    assert r.verdict is C1Verdict.UNDECIDED and r.as_json()["method"] == NO_METHOD
