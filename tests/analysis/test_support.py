"""Section 3: support classification, checked against the bicubic B-spline and for symmetry."""

import itertools
from fractions import Fraction

import pytest
import sympy as sp

from symdecomp.analysis.support import Region, classify_support, limit_mask, support_relation
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import InvalidMeshError, ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import alpha, beta


def _bspline(t):
    """The uniform cubic B-spline centred at 0 (support [-2, 2]), written out independently."""
    t = abs(Fraction(t))
    if t >= 2:
        return Fraction(0)
    if t >= 1:
        return (2 - t) ** 3 / 6
    return Fraction(2, 3) - t**2 + t**3 / 2


def _grid_xy(label):
    """Grid coordinates of a ring_mesh(4, .) vertex: sector s is the quadrant rotated s quarter turns."""
    s, u, v = label
    x, y = u, v
    for _ in range(s):
        x, y = -y, x
    return x, y


def test_regular_case_matches_the_tensor_product_bspline():
    rings = 5
    mesh = ring_mesh(4, rings)
    labels = ring_mesh_labels(4, rings)
    c = classify_support(mesh, 0, catmull_clark(), levels=2)
    assert c.stable and c.consistent
    eps = Fraction(1, 100)
    for v, region in c.regions.items():
        qx, qy = _grid_xy(labels[v])
        # phi_P = B(x) B(y); sample each quadrant around Q just off Q
        carried = [_bspline(qx + sx * eps) * _bspline(qy + sy * eps) != 0 for sx, sy in itertools.product((1, -1), repeat=2)]
        expected = Region.INSIDE if all(carried) else Region.OUTSIDE if not any(carried) else Region.BOUNDARY
        assert region is expected, labels[v]
        phi_q = _bspline(qx) * _bspline(qy)
        assert c.limit_values[v] == sp.Rational(phi_q.numerator, phi_q.denominator)
    assert (c.count(Region.INSIDE), c.count(Region.BOUNDARY)) == (9, 16)


@pytest.mark.parametrize("n", [3, 5, 7])
def test_extraordinary_support_is_the_closed_1_ring_and_the_2_ring_boundary(n):
    rings = 5
    c = classify_support(ring_mesh(n, rings), 0, catmull_clark(), levels=2)
    labels = ring_mesh_labels(n, rings)
    assert c.stable and c.consistent
    ring = {v: max(labels[v][1:]) for v in c.regions}
    assert c.vertices_in(Region.INSIDE) == {v for v, d in ring.items() if d <= 1}
    assert c.vertices_in(Region.BOUNDARY) == {v for v, d in ring.items() if d == 2}
    assert c.vertices_in(Region.OUTSIDE) == {v for v, d in ring.items() if d == 3}
    assert c.count(Region.INSIDE) == 2 * n + 1 and c.count(Region.BOUNDARY) == 4 * n
    # phi_P(P) is the centre weight of the limit mask; n/(n+5) for Catmull-Clark (independently known)
    assert c.limit_values[0] == sp.Rational(n, n + 5) == limit_mask(catmull_clark(), n)[0]


@pytest.mark.parametrize("n", [3, 6])
def test_relation_is_symmetric_and_agrees_with_classify_support(n):
    rings = 5
    mesh = ring_mesh(n, rings)
    labels = ring_mesh_labels(n, rings)
    verts = [v for v in mesh.vertices() if max(labels[v][1:]) <= 3]
    rel = support_relation(mesh, catmull_clark(), verts)
    assert all(rel[p, q] is rel[q, p] for p in verts for q in verts)
    for p in verts[:: max(1, len(verts) // 6)]:
        c = classify_support(mesh, p, catmull_clark(), vertices=verts)
        assert all(c.regions[q] is rel[p, q] for q in verts)


def test_tuned_positive_vertex_weights_give_the_same_support():
    scheme = catmull_clark(sp.Rational(1, 10) / 3, sp.Rational(1, 50) / 3)  # arbitrary positive weights
    c = classify_support(ring_mesh(5, 5), 0, scheme, levels=1)
    assert c.stable and (c.count(Region.INSIDE), c.count(Region.BOUNDARY)) == (11, 20)


def test_schemes_outside_the_method_are_refused():
    with pytest.raises(InvalidSchemeError, match="vertex-rule"):
        classify_support(ring_mesh(5, 4), 0, catmull_clark(alpha, beta))
    with pytest.raises(InvalidSchemeError, match="vertex-rule"):
        classify_support(ring_mesh(5, 4), 0, catmull_clark(sp.Rational(1, 5), sp.Rational(-1, 100)))


def test_vertices_too_close_to_the_boundary_are_refused():
    mesh = ring_mesh(4, 3)
    labels = ring_mesh_labels(4, 3)
    edge = next(v for v in mesh.vertices() if max(labels[v][1:]) == 2)
    with pytest.raises(InvalidMeshError, match="boundary"):
        classify_support(mesh, 0, catmull_clark(), vertices=[edge])


def test_unrefined_cube_opposite_corner_is_inside_but_phi_vanishes_there():
    """On the cube the 2-ring of a corner is the whole surface (not a disk): the corner opposite P
    has every sector carrying phi_P, phi_P(Q) = 0, and phi_P > 0 at every nearby vertex of the
    refined meshes: an isolated zero inside the support, outside the 1-ring of P."""
    from symdecomp.analysis.support import _mask_fractions
    from symdecomp.schemes.mesh import cube_mesh
    from symdecomp.schemes.refinement import mesh_rules, refine

    cc = catmull_clark()
    cube = cube_mesh(lambda i: (Fraction(int(i == 0)),))
    c = classify_support(cube, 0, cc)
    assert c.regions[7] is Region.INSIDE and c.limit_values[7] == 0 and not c.consistent
    assert not cube.neighbourhood(0, 2).is_disk()
    rules, mesh, q = mesh_rules(cc), cube, 7
    for level in range(1, 4):
        step = refine(mesh, rules)
        mesh, q = step.mesh, step.vertex_point[q]
        near = mesh.neighbourhood(q, 2 ** (level - 1)).vertices()
        limits = {v: sum(w * x[0] for w, x in zip(_mask_fractions(cc, mesh.valence(v)), mesh.one_ring_values(v))) for v in near}
        assert [v for v, x in limits.items() if x == 0] == [q]
        assert all(x > 0 for v, x in limits.items() if v != q)


def test_an_asymmetric_support_relation_is_refuted_with_the_pair_both_ways(monkeypatch):
    from symdecomp.claims import Status, s3_support

    rel = {(p, q): Region.INSIDE for p in "PQ" for q in "PQ"}
    rel["Q", "P"] = Region.OUTSIDE  # P is outside the support of Q, Q inside that of P
    monkeypatch.setattr(s3_support, "support_relation", lambda mesh, scheme, verts: rel)
    _, refuted = s3_support._relation_or_refutation(None, None, "PQ", "at valence 5", "n = 5", str.lower)
    assert refuted.status is Status.REFUTED and refuted.evidence == "asymmetric pair at valence 5"
    assert refuted.counterexample == "n = 5: vertex q is inside for the support of p, but p is outside for the support of q"
    rel["Q", "P"] = Region.INSIDE
    assert s3_support._relation_or_refutation(None, None, "PQ", "", "")[1] is None
