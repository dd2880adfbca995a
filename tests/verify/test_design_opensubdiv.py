"""Designed and redesigned nets against OpenSubdiv: its limit position and normal at the designed vertex agree with
the prescribed ones to 1e-12 (Catmull-Clark and Loop, valences 3, 5, 6, 8; skipped where OpenSubdiv is not installed)."""

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from symdecomp.analysis.design import design_ring
from symdecomp.analysis.redesign import redesign_vertex
from symdecomp.schemes.loop import loop
from symdecomp.schemes.meshformats import read_mesh
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

from symdecomp.verify.opensubdiv import load_bridge, osd_limit_frames  # noqa: E402

load_bridge()  # builds it if needed; raises (an error, not a skip) if the build fails

MODEL = Path(__file__).resolve().parents[2] / "notebooks" / "data" / "valences-3-5-6.obj"


def osd_frame(mesh, vertex, loop_scheme):
    points = np.array([[float(c) for c in p] for p in mesh.points])
    limits, du, dv = osd_limit_frames(points, np.array(mesh.faces), loop=loop_scheme)
    normal = np.cross(du[vertex], dv[vertex])
    return limits[vertex], normal / np.linalg.norm(normal)


@pytest.mark.parametrize("loop_scheme", [False, True], ids=["catmull-clark", "loop"])
@pytest.mark.parametrize("n", [3, 5, 6, 8])
def test_opensubdiv_sees_the_prescribed_limit_point_and_normal(n, loop_scheme):
    scheme = loop() if loop_scheme else catmull_clark()
    normal, position = np.array([1.0, -2.0, 2.0]), (Fraction(1, 4), 2, -1)
    hyperbolic = Fraction(1, 10) if n >= 5 else 0
    design = design_ring(scheme, n, normal=(1, -2, 2), position=position, tangent=(0, 1, 0), elliptic=Fraction(1, 3),
                         hyperbolic=hyperbolic, angle=Fraction(1, 2))
    limit, osd_normal = osd_frame(design.mesh, 0, loop_scheme)
    assert np.max(np.abs(limit - np.array([float(x) for x in position]))) < 1e-12
    assert np.max(np.abs(osd_normal - normal / 3)) < 1e-12


def test_opensubdiv_sees_the_redesigned_normal():
    mesh = read_mesh(MODEL)
    design = redesign_vertex(catmull_clark(), mesh, 11, normal=(1, 1, 8), flatten_hyperbolic=True)
    _, osd_normal = osd_frame(design.mesh, 11, False)
    assert np.max(np.abs(osd_normal - np.array([1.0, 1.0, 8.0]) / np.sqrt(66))) < 1e-12
    assert np.max(np.abs(osd_normal - np.array(design.achieved.normal))) < 1e-12
