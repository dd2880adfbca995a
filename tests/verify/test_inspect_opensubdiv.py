"""``symdecomp inspect`` against OpenSubdiv: limit points, normals and tangent planes at every extraordinary vertex
of whole meshes with valences 3, 5 and 6, to 1e-12 (skipped where OpenSubdiv is not installed)."""

import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from symdecomp.analysis.inspection import inspect_mesh
from symdecomp.schemes.loop import loop
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.meshformats import read_mesh
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

from symdecomp.verify.opensubdiv import load_bridge, osd_limit_frames  # noqa: E402

load_bridge()  # builds it if needed; raises (an error, not a skip) if the build fails

MODEL = Path(__file__).resolve().parents[2] / "notebooks" / "data" / "valences-3-5-6.obj"


def prismatoid() -> PolygonMesh:
    """A pentagon over a hexagon joined by quads and a triangle, split into quads: valences 3, 4, 5, 6, uneven heights."""
    def q(x):
        return Fraction(round(x * 997), 997)

    top = [(q(math.cos(1.3 * i)), q(0.8 * math.sin(1.3 * i + 0.2)), q(1 + 0.1 * i)) for i in range(5)]
    bottom = [(q(1.5 * math.cos(math.pi * i / 3)), q(1.3 * math.sin(math.pi * i / 3)), q(-1 - 0.05 * i * i)) for i in range(6)]
    faces = [(0, 1, 2, 3, 4), (10, 9, 8, 7, 6, 5)] + [(5 + i, 6 + i, 1 + i, i) for i in range(4)] + [(9, 10, 4), (10, 5, 0, 4)]
    return PolygonMesh.from_arrays(top + bottom, faces).split_into_quads()


def triangulated(mesh: PolygonMesh) -> PolygonMesh:
    return PolygonMesh.from_arrays(mesh.points, [t for f in mesh.faces for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))])


CASES = [(MODEL, catmull_clark()), ("prismatoid", catmull_clark()), (MODEL, loop()), ("prismatoid", loop())]


@pytest.mark.parametrize(("source", "scheme"), CASES, ids=["model-cc", "prismatoid-cc", "model-loop", "prismatoid-loop"])
def test_limit_points_normals_and_tangent_planes_agree_with_opensubdiv(source, scheme):
    mesh = read_mesh(source) if isinstance(source, Path) else prismatoid()
    loop_scheme = scheme.lattice.face_sides == 3
    if loop_scheme:
        mesh = triangulated(mesh)
    points = np.array([[float(c) for c in p] for p in mesh.points])
    limits, du, dv = osd_limit_frames(points, np.array(mesh.faces), loop=loop_scheme)
    result = inspect_mesh(mesh, scheme)
    if not loop_scheme:
        assert {3, 5, 6} <= {r.valence for r in result.vertices}
    for r in result.vertices:
        osd_normal = np.cross(du[r.vertex], dv[r.vertex])
        osd_normal /= np.linalg.norm(osd_normal)
        assert np.max(np.abs(np.array(r.limit) - limits[r.vertex])) < 1e-12
        assert np.max(np.abs(np.array(r.normal) - osd_normal)) < 1e-12
        for t in r.tangents:
            assert abs(np.dot(t, osd_normal)) < 1e-12 * np.linalg.norm(t)
