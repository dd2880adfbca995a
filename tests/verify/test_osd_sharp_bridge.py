"""The OpenSubdiv bridge with boundaries, creases and corners, on its own (skipped where OpenSubdiv is not installed).

As for the interior bridge (tests/verify/test_opensubdiv.py) a failing build is an error, not a skip.
"""

import math

import pytest

from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

import numpy as np  # noqa: E402

from symdecomp.analysis.support import limit_mask  # noqa: E402
from symdecomp.errors import InvalidInputError  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix  # noqa: E402
from symdecomp.verify.opensubdiv.loop import osd_loop_one_ring_matrix, osd_loop_position_mask  # noqa: E402
from symdecomp.verify.opensubdiv.sharp import OsdOptions, fan_topology, osd_patch_limits, osd_sharp_ring  # noqa: E402

CC, LOOP = OsdOptions("catmull-clark"), OsdOptions("loop")


def _ring(n_faces, closed, options, level=0, sharp=None, corners=None):
    faces, o, a, rf = fan_topology(n_faces, closed=closed, quad=options.sides == 4)
    creases = {(0, a[i]): s for i, s in (sharp or {}).items()}
    return osd_sharp_ring(faces, o, a, rf, options=options, creases=creases, corners=corners, level=level)


@pytest.mark.parametrize("n", [3, 5, 7])
def test_an_untagged_closed_fan_gives_the_interior_results(n):
    got = _ring(n, True, CC)
    exact = subdivision_matrix(catmull_clark(), n)
    assert np.max(np.abs(got.matrix - np.array(exact.tolist(), dtype=float))) < 1e-15
    assert np.max(np.abs(got.masks[0] - [float(x) for x in limit_mask(catmull_clark(), n)])) < 1e-15
    loop = _ring(n, True, LOOP)
    assert np.max(np.abs(loop.matrix - np.array(osd_loop_one_ring_matrix(n)))) < 1e-15
    assert np.max(np.abs(loop.masks[0] - osd_loop_position_mask(n))) < 1e-15
    assert not np.any(got.leak) and not np.any(loop.leak)


@pytest.mark.parametrize("options", [OsdOptions(s, b) for s in ("catmull-clark", "loop") for b in ("edge-only", "edge-and-corner")])
def test_boundary_stencils_are_affine_and_the_boundary_curve_uses_only_boundary_vertices(options):
    for k in range(1, 13):
        ring = _ring(k, False, options)
        size = ring.matrix.shape[0]
        assert np.max(np.abs(ring.matrix.sum(axis=1) - 1)) < 1e-15 and not np.any(ring.leak)
        assert abs(ring.masks[0].sum() - 1) < 1e-15 and np.max(np.abs(ring.masks[1:].sum(axis=1))) < 1e-14
        curve = [0, 1, k + 1]  # O, a_0, a_k
        off = [c for c in range(size) if c not in curve]
        assert not np.any(ring.matrix[np.ix_(curve, off)]) and not np.any(ring.masks[0, off])
        if k == 1 and options.boundary == "edge-and-corner":  # a corner interpolates
            assert ring.matrix[0, 0] == 1 and ring.masks[0, 0] == 1
        else:  # the cubic B-spline rules and limit of the boundary curve
            assert list(ring.matrix[0, curve]) == [0.75, 0.125, 0.125] and list(ring.matrix[1, curve]) == [0.5, 0.5, 0]
            assert np.max(np.abs(ring.masks[0, curve] - [2 / 3, 1 / 6, 1 / 6])) < 1e-15


@pytest.mark.parametrize("options", [CC, LOOP])
def test_an_infinitely_sharp_crease_splits_the_fan_into_two_boundary_fans(options):
    """Sdc: infinitely sharp edges are boundaries; each sector of a crease vertex refines as a boundary fan."""
    for n in range(4, 13):
        j = n // 2
        crease = _ring(n, True, options, sharp={0: math.inf, j: math.inf})
        fan = _ring(j, False, OsdOptions(options.scheme, "edge-only"))
        rows = [0] + list(range(1, j + 2)) + ([1 + n + i for i in range(j)] if options.sides == 4 else [])
        sub = crease.matrix[np.ix_(rows, rows)]
        assert np.max(np.abs(sub - fan.matrix)) < 1e-15
        assert np.max(np.abs(crease.masks[0, rows] - fan.masks[0])) < 1e-15


@pytest.mark.parametrize("options", [CC, LOOP])
def test_a_boundary_corner_of_one_face_is_the_corner_tag(options):
    """EDGE_AND_CORNER makes a boundary vertex of one face a corner: the same as an infinitely sharp corner tag."""
    tagged = _ring(1, False, OsdOptions(options.scheme, "edge-only"), corners={0: math.inf})
    untagged = _ring(1, False, OsdOptions(options.scheme, "edge-and-corner"))
    assert np.array_equal(tagged.matrix, untagged.matrix) and np.array_equal(tagged.masks, untagged.masks)


@pytest.mark.parametrize("options", [CC, LOOP])
def test_semi_sharpness_blends_and_decays(options):
    """A sharpness in (0, 1) blends the sharp and smooth rules linearly; each level takes 1 off (uniform)."""
    n = 6
    smooth, sharp = _ring(n, True, options), _ring(n, True, options, sharp={0: math.inf, 3: math.inf})
    half = _ring(n, True, options, sharp={0: 0.5, 3: 0.5})
    assert np.max(np.abs(half.matrix - (smooth.matrix + sharp.matrix) / 2)) < 1e-15
    semi = {0: 2.5, 3: 2.5}
    assert np.max(np.abs(_ring(n, True, options, level=2, sharp=semi).matrix - half.matrix)) < 1e-15
    assert np.max(np.abs(_ring(n, True, options, level=1, sharp=semi).matrix - sharp.matrix)) < 1e-15
    assert np.max(np.abs(_ring(n, True, options, level=3, sharp=semi).matrix - smooth.matrix)) < 1e-15


def test_chaikin_decays_by_the_average_of_the_other_creases():
    """Chaikin: a child edge at O gets 3/4 its sharpness + 1/4 the others' average - 1 (uniform: - 1)."""
    chaikin = OsdOptions(creasing="chaikin")
    got = _ring(6, True, chaikin, level=1, sharp={0: 1.5, 3: 0.5})
    assert np.max(np.abs(got.matrix - _ring(6, True, CC, sharp={0: 0.25}).matrix)) < 1e-15
    uniform = _ring(6, True, CC, level=1, sharp={0: 1.5, 3: 0.5})
    assert np.max(np.abs(uniform.matrix - _ring(6, True, CC, sharp={0: 0.5}).matrix)) < 1e-15
    assert np.max(np.abs(got.matrix - uniform.matrix)) > 1e-3


@pytest.mark.parametrize("options", [CC, LOOP])
def test_patch_limit_at_the_vertex_is_the_limit_mask(options):
    """The patch table's limit at the boundary vertex's corner of a face equals the limit mask applied to the ring."""
    for k in (1, 2, 3, 5):
        faces, o, a, rf = fan_topology(k, closed=False, quad=options.sides == 4)
        rng = np.random.default_rng(k)
        pos = rng.standard_normal((max(max(f) for f in faces) + 1, 3))
        ring = osd_sharp_ring(faces, o, a, rf, options=options)
        limits, du, dv = osd_patch_limits(faces, pos, [(0, 0.0, 0.0)], options=options)
        assert np.max(np.abs(limits[0] - ring.masks[0] @ pos)) < 1e-12


def test_bad_input_is_refused():
    faces, o, a, rf = fan_topology(3, closed=False)
    with pytest.raises(InvalidInputError, match="boundary"):
        OsdOptions(boundary="sharp")
    with pytest.raises(InvalidInputError, match="sharpness"):
        osd_sharp_ring(faces, o, a, rf, creases={(0, 1): 12})
    with pytest.raises(InvalidInputError, match="single-precision"):
        osd_sharp_ring(faces, o, a, rf, creases={(0, 1): 0.1})
    with pytest.raises(InvalidInputError, match="faces"):
        osd_sharp_ring(faces, o, a, rf, options=LOOP)
    with pytest.raises(InvalidInputError, match="queries"):
        osd_patch_limits(faces, np.zeros((8, 3)), [(9, 0.0, 0.0)])
