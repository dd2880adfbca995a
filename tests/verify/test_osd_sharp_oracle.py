"""OpenSubdiv against the toolkit at boundary, corner, crease and dart vertices (skipped where OpenSubdiv is not installed).

As for the interior oracle (tests/verify/test_opensubdiv.py) a failing build is an error, not a skip.
"""

import json
import math
from fractions import Fraction

import pytest

from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

import numpy as np  # noqa: E402

from symdecomp.analysis.support import limit_mask  # noqa: E402
from symdecomp.cli import main  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark  # noqa: E402
from symdecomp.verify.comparisons import TOLERANCE  # noqa: E402
from symdecomp.verify.opensubdiv.sharp import OsdOptions  # noqa: E402
from symdecomp.verify.oracle import SharpCase, compare_sharp_case, sharp_cases  # noqa: E402

#: What must agree in every case: our exact matrices, their spectra, the ring's closure, the crease curve's tangent.
ALWAYS = {"matrix", "ring closed", "spectrum", "tangents independent", "curve tangent"}


def _check(results, name):
    return [c for r in results for c in r.checks if c.name == name]


def _sweep(scheme, ks, creasing=("uniform", "chaikin")):
    for case in sharp_cases(scheme, ks=ks):
        if case.creasing in creasing:
            results = compare_sharp_case(case)
            for check in (c for r in results for c in r.checks):
                if check.name in ALWAYS:
                    assert check.disagreement <= TOLERANCE, (case.label(), check)
            yield case, results


@pytest.mark.parametrize("scheme", ["catmull-clark", "loop"])
def test_matrices_spectra_limits_agree_with_opensubdiv(scheme):
    for case, results in _sweep(scheme, (1, 3), ("uniform",)):
        if case.kind == "dart" and case.sharpness == math.inf:
            continue  # OpenSubdiv's limit at a dart: see the next test
        for check in _check(results, "limit mask") + _check(results, "limit point"):
            assert not check.comparable or check.disagreement <= TOLERANCE, (case.label(), check)


@pytest.mark.slow
@pytest.mark.parametrize("scheme", ["catmull-clark", "loop"])
def test_the_whole_sweep_of_issue_20(scheme):
    for case, results in _sweep(scheme, range(1, 13)):
        if not (case.kind == "dart" and case.sharpness == math.inf):
            assert all(c.agrees for c in _check(results, "limit mask") + _check(results, "limit point")), case.label()


def test_chaikin_creasing_agrees_with_opensubdiv():
    for scheme in ("catmull-clark", "loop"):
        for case, results in _sweep(scheme, (3,), ("chaikin",)):
            assert len(results) == case.levels() + 1 > 1 and all(r.agrees for r in results), case.label()


def test_opensubdiv_takes_the_smooth_limit_mask_at_an_infinitely_sharp_dart():
    """OpenSubdiv's Limit at a dart applies the smooth vertex's mask; the dart's matrix (with its crease
    edge rule) has another fixed left eigenvector: ours, which the patch table approaches level by level."""
    for n in (3, 4, 5, 6):
        case = SharpCase("catmull-clark", "dart", n)
        ours = compare_sharp_case(case)[0]
        osd = case.fan().ring(OsdOptions())
        smooth = np.array([float(x) for x in limit_mask(catmull_clark(), n)])
        assert np.max(np.abs(osd.masks[0] - smooth)) < 1e-15
        (mask,) = _check([ours], "limit mask")
        assert mask.disagreement > 1e-2
        (point,) = _check([ours], "limit point")
        assert 1e-6 < point.disagreement < mask.disagreement


@pytest.mark.parametrize("scheme", ["catmull-clark", "loop"])
def test_opensubdiv_corner_tangents_follow_the_first_two_edges(scheme):
    """OpenSubdiv's corner tangent masks are (multiples of) a_0 - O and a_1 - O (Sdc's corner masks); with two or more faces
    a_1 is an interior edge, whose difference is not a tangent of the limit surface."""
    for k in (1, 2, 3, 4):
        case = SharpCase(scheme, "corner", k)
        masks = case.fan().ring(OsdOptions(scheme)).masks
        expected = np.zeros_like(masks[1:])
        expected[:, 0], expected[0, 1], expected[1, 2] = -1, 1, 1
        assert masks[1, 1] in (1, 3) and np.array_equal(masks[1:], masks[1, 1] * expected)  # Loop's masks are scaled by 3
        (second,) = _check(compare_sharp_case(case), "surface tangent 2")
        assert second.disagreement < TOLERANCE if k == 1 else second.disagreement > 0.1


def test_oracle_command_reports_agreement_and_disagreement(capsys):
    assert main(["oracle", "--kind", "boundary", "--k", "2", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [r["kind"] for r in rows] == ["boundary"] and rows[0]["agrees"]
    assert all(c["disagreement"] <= TOLERANCE for c in rows[0]["checks"])
    assert main(["oracle", "--kind", "corner", "--k", "3"]) == 1
    assert "DISAGREES: surface tangent 2" in capsys.readouterr().out
    assert main(["oracle", "--kind", "crease", "--k", "2", "--sharpness", "5/2", "--scheme", "loop", "--creasing", "uniform",
                 "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert {r["sharpness"] for r in rows} == {str(Fraction(5, 2))} and [r["level"] for r in rows][:4] == [0, 1, 2, 3]
