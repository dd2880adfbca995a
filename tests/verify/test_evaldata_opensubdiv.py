"""The patch evaluator (Catmull-Clark and Loop) against OpenSubdiv's limit positions (skipped where OpenSubdiv is not installed)."""

from __future__ import annotations

import pytest

from symdecomp.analysis.eigendata import certified_eigendata
from symdecomp.analysis.evaluation import PatchEvaluator
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

from symdecomp.verify.patch_eval import opensubdiv_dyadic_errors  # noqa: E402

CC = catmull_clark()
LOOP = loop()


def _check(n, level, scheme=CC):
    ev = PatchEvaluator.from_rounded(scheme, certified_eigendata(scheme, n)[1])
    match, error = opensubdiv_dyadic_errors(scheme, n, level, ev, seed=n)
    assert match < 1e-14  # the same refined vertices (values of order 1)
    assert error < 4e-15  # the evaluated surface equals OpenSubdiv's limit to double precision


@pytest.mark.parametrize("n,level", [(3, 2), (5, 1), (8, 2)])
def test_dyadic_points_match_opensubdiv(n, level):
    _check(n, level)


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 13))
@pytest.mark.parametrize("level", [1, 2, 3, 4])
def test_dyadic_points_match_opensubdiv_all(n, level):
    _check(n, level)


@pytest.mark.parametrize("n,level", [(3, 2), (6, 1), (8, 2)])
def test_loop_dyadic_points_match_opensubdiv(n, level):
    _check(n, level, LOOP)


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 13))
@pytest.mark.parametrize("level", [1, 2, 3, 4])
def test_loop_dyadic_points_match_opensubdiv_all(n, level):
    _check(n, level, LOOP)


def test_a_wrong_table_is_caught():
    data = certified_eigendata(CC, 5)[1]
    ev = PatchEvaluator.from_rounded(CC, data)
    bad = PatchEvaluator(ev.n, ev.values, ev.inverse, ev.phi * (1 + 1e-9), ev.position_mask, ev.tangent_masks)
    _, error = opensubdiv_dyadic_errors(CC, 5, 1, bad, seed=5)
    assert error > 1e-12
