"""analysis/inspection.py: exact limit positions (against exact refinement and the closed-form masks), the tangent
plane of symmetric rings, and the frequency sizes of the 1-ring decomposition (Parseval, pure components)."""

import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.inspection import inspect_mesh, inspect_vertex, position_weights
from symdecomp.analysis.masks import limit_masks_at
from symdecomp.schemes.loop import loop
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.meshformats import read_mesh
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix

MODEL = Path(__file__).resolve().parents[2] / "notebooks" / "data" / "valences-3-5-6.obj"


def quad_fan(n: int, height) -> PolygonMesh:
    """``n`` quads around vertex 0 with ``a_i``, ``b_i`` on circles (doubles); ``height(i, kind)`` lifts them."""
    def at(r, angle, z):
        return (r * math.cos(angle), r * math.sin(angle), z)

    points = [(0, 0, 0)] + [at(1, 2 * math.pi * i / n, height(i, "a")) for i in range(n)]
    points += [at(1.5, 2 * math.pi * (i + 0.5) / n, height(i, "b")) for i in range(n)]
    return PolygonMesh.from_arrays(points, [(0, 1 + i, 1 + n + i, 1 + (i + 1) % n) for i in range(n)])


def triangle_fan(n: int, height) -> PolygonMesh:
    points = [(0, 0, 0)] + [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), height(i, "a")) for i in range(n)]
    return PolygonMesh.from_arrays(points, [(0, 1 + i, 1 + (i + 1) % n) for i in range(n)])


def _ring_rows(mesh, report):
    return sp.Matrix([[sp.Rational(c.numerator, c.denominator) for c in mesh.points[v]] for v in report.ring])


@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=["catmull-clark", "loop"])
def test_the_exact_limit_survives_exact_subdivision_and_is_where_the_centre_goes(scheme):
    """``w S = w``: the limit of the once-subdivided 1-ring is the same point, exactly; and 40 steps bring ``O`` to it."""
    mesh = read_mesh(MODEL)
    if scheme.lattice.face_sides == 3:
        mesh = PolygonMesh.from_arrays(mesh.points, [t for f in mesh.faces for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))])
    result = inspect_mesh(mesh, scheme)
    assert len(result.vertices) >= 4
    for report in result.vertices[:4] + result.vertices[-2:]:
        n = report.valence
        weights = position_weights(scheme, n)
        w = sp.Matrix([[weights[0]] + [x for x in weights[1:] for _ in range(n)]])
        S = subdivision_matrix(scheme, n)
        P = _ring_rows(mesh, report)
        assert [sp.simplify(x) for x in (w * S * P - w * P)] == [0, 0, 0]
        assert [sp.simplify(x - y) for x, y in zip(w * P, report.limit_exact)] == [0, 0, 0]
        A, X = np.array(S.tolist(), dtype=float), np.array(P.tolist(), dtype=float)
        for _ in range(40):
            X = A @ X
        assert np.max(np.abs(X[0] - np.array(report.limit))) < 1e-8


@pytest.mark.parametrize("n", [3, 5, 6, 7])
def test_catmull_clark_position_weights_are_the_closed_forms(n):
    """The E_0 solve agrees with the closed form of Eq. 43 (n/(n+5), 4/(n(n+5)), 1/(n(n+5)))."""
    closed = limit_masks_at(catmull_clark(), n).position
    assert position_weights(catmull_clark(), n) == (closed[0], closed[1], closed[n + 1])
    assert position_weights(catmull_clark(), n) == (sp.Rational(n, n + 5), sp.Rational(4, n * (n + 5)), sp.Rational(1, n * (n + 5)))


def test_loop_position_weight_is_loops_closed_form():
    """Loop's limit: O weighs 1 - n chi with chi = 1/(3/(8 beta) + n), beta = (5/8 - (3/8 + cos(2 pi/n)/4)^2)/n."""
    for n in (3, 5, 8):
        beta = (sp.Rational(5, 8) - (sp.Rational(3, 8) + sp.cos(2 * sp.pi / n) / 4) ** 2) / n
        chi = 1 / (3 / (8 * beta) + n)
        weights = position_weights(loop(), n)
        assert sp.simplify(weights[0] - (1 - n * chi)) == 0 and sp.simplify(weights[1] - chi) == 0


@pytest.mark.parametrize("n", [3, 5, 6])
def test_a_flat_ring_has_the_plane_as_tangent_plane_and_no_elliptic_or_hyperbolic_part(n):
    report = inspect_vertex(quad_fan(n, lambda i, kind: 0), 0, catmull_clark())
    assert report.normal == pytest.approx((0, 0, 1), abs=1e-15)
    assert report.elliptic_heights == (0, 0) and report.tangent_off_plane == 0
    assert report.hyperbolic_off_plane in (None, 0)


@pytest.mark.parametrize("n", [5, 6, 8])
def test_a_saddle_is_all_hyperbolic_and_a_cap_all_elliptic(n):
    saddle = inspect_vertex(quad_fan(n, lambda i, kind: math.cos(4 * math.pi * (i + (kind == "b") / 2) / n)),
                            0, catmull_clark())
    # heights h cos(2 theta) on the a's and b's: the 2n-gon's frequencies 2 and 2n - 2 off the plane, nothing else
    assert saddle.normal == pytest.approx((0, 0, 1), abs=1e-12)
    assert saddle.elliptic_heights == pytest.approx((0, 0), abs=1e-12)
    heights = [c.off_plane for c in saddle.components]
    assert saddle.hyperbolic_off_plane == pytest.approx(math.sqrt(sum(x * x for x in heights)), rel=1e-12)
    cap = inspect_vertex(quad_fan(n, lambda i, kind: Fraction(-1, 4) if kind == "a" else Fraction(-1, 2)), 0, catmull_clark())
    assert cap.elliptic_heights == pytest.approx((-0.25, -0.5), abs=1e-15)
    assert cap.hyperbolic_off_plane == pytest.approx(0, abs=1e-15) and cap.tangent_off_plane == pytest.approx(0, abs=1e-15)


def test_sizes_add_up_in_squares_to_the_rings_mean_square_distance():
    """Parseval: the squared sizes of all components sum to the mean squared distance of the 1-ring from O."""
    mesh = read_mesh(MODEL)
    for report in inspect_mesh(mesh, catmull_clark()).vertices:
        rows = np.array([[float(c) for c in mesh.points[v]] for v in report.ring])
        mean_square = float(np.mean(np.sum((rows[1:] - rows[0]) ** 2, axis=1)))
        assert sum(c.size**2 for c in report.components) == pytest.approx(mean_square, rel=1e-12)
        # the pair radii of Eq. 6: |u_j|^2 + |u_{N-j}|^2 = 2 (|z_j|^2 + |z_{N-j}|^2)/2 for a real polygon (|z_j| = |z_{N-j}|)
        for c in report.components:
            if len(c.frequencies) == 2:
                assert c.radii[0] ** 2 + c.radii[1] ** 2 == pytest.approx(c.size**2, rel=1e-9, abs=1e-15)


def test_loop_rings_have_no_face_neighbours_and_a_tangent_plane():
    report = inspect_vertex(triangle_fan(5, lambda i, kind: 0.125 * math.cos(4 * math.pi * i / 5)), 0, loop())
    assert len(report.ring) == 6 and len(report.elliptic_heights) == 1
    assert report.normal == pytest.approx((0, 0, 1), abs=1e-12) and report.hyperbolic_off_plane > 0.05
