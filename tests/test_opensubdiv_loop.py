"""OpenSubdiv's Loop scheme against the toolkit (skipped where OpenSubdiv is not installed).

As for Catmull-Clark (tests/test_opensubdiv.py) a failing build is an error, not a skip.
"""

import pytest

from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

import numpy as np  # noqa: E402

from symdecomp.analysis.ring_masks import ring_masks  # noqa: E402
from symdecomp.schemes.loop import loop  # noqa: E402
from symdecomp.schemes.rings import ring_subdivision_matrix  # noqa: E402
from symdecomp.verify.opensubdiv.loop import osd_loop_one_ring_matrix, osd_loop_position_mask, osd_loop_tangent_masks  # noqa: E402


@pytest.mark.parametrize("n", range(3, 13))
def test_loop_one_step_matrix_and_limit_mask_match_opensubdiv(n):
    exact = ring_subdivision_matrix(loop(), n, 1).exact_matrix()
    osd = osd_loop_one_ring_matrix(n)
    assert max(abs(osd[r][c] - float(exact[r, c])) for r in range(n + 1) for c in range(n + 1)) < 1e-15
    masks = ring_masks(loop(), n, 1, digits=20)
    ours = [float(masks["position"]["O"])] + [float(x) for x in masks["position"]["a"]]
    assert max(abs(a - b) for a, b in zip(osd_loop_position_mask(n), ours)) < 1e-15


@pytest.mark.parametrize("n", range(3, 13))
def test_loop_tangent_masks_span_opensubdiv_tangents(n):
    masks = ring_masks(loop(), n, 1, digits=20)
    ours = np.array([[float(m["O"])] + [float(x) for x in m["a"]] for m in masks["tangents"]])
    theirs = np.array(osd_loop_tangent_masks(n))
    # OpenSubdiv's tangents are a basis of the same plane: solve theirs = C ours, residual ~ 0
    C, *_ = np.linalg.lstsq(ours.T, theirs.T, rcond=None)
    assert np.abs(ours.T @ C - theirs.T).max() < 1e-13 * max(1.0, np.abs(theirs).max())
    assert abs(np.linalg.det(C)) > 1e-8  # and they span it (two independent tangents)
