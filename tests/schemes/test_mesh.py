"""Local quad meshes: mesh rules derived from the 1-ring rules, exact refinement."""

import random
from fractions import Fraction

import pytest
import sympy as sp

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import InvalidMeshError, QuadMesh, ring_mesh
from symdecomp.schemes.refinement import central_rings, mesh_rules, refine
from symdecomp.schemes.scheme import Scheme, Stencil, catmull_clark, subdivision_matrix
from symdecomp.symbols import alpha, beta
from symdecomp.symbols import n as N


def _random_mesh(n, rings, seed, dim=1):
    rng = random.Random(seed)
    return ring_mesh(n, rings, lambda s, u, v: tuple(Fraction(rng.randint(-99, 99), rng.randint(1, 17)) for _ in range(dim)))


def _column(ring, coord=0):
    return sp.Matrix(
        [sp.sympify(x[coord]) if not isinstance(x[coord], Fraction) else sp.Rational(x[coord].numerator, x[coord].denominator) for x in ring]
    )


def test_catmull_clark_mesh_rules_are_the_textbook_ones():
    r = mesh_rules(catmull_clark())
    assert (r.face_corner, r.edge_end, r.edge_side) == (sp.Rational(1, 4), sp.Rational(3, 8), sp.Rational(1, 16))
    # (Q + 2R + (m-3)S)/m with Q the mean of the face points, R the mean of the edge midpoints
    for m in range(3, 9):
        S_, A, B = sp.symbols("S A B")  # S: the vertex, A/B: each edge/face neighbour (all equal weight)
        Q = (S_ + 2 * A + B) / 4  # every face point; the mean over m faces is the same
        R = (S_ + A) / 2
        textbook = sp.expand((Q + 2 * R + (m - 3) * S_) / m)
        c, wa, wb = r.vertex_weights(m)
        # total weight on the m edge neighbours is m*wa, on the m face neighbours m*wb
        assert textbook.coeff(S_) == c
        assert textbook.coeff(A) == m * wa
        assert textbook.coeff(B) == m * wb


@pytest.mark.parametrize("n", range(3, 9))
@pytest.mark.parametrize("rings", [1, 3])
def test_refinement_reproduces_the_subdivision_matrix(n, rings):
    mesh = _random_mesh(n, rings, seed=10 * n + rings)
    S = subdivision_matrix(catmull_clark(), n)
    levels = central_rings(mesh, catmull_clark(), 0, 2, keep_rings=None)
    for k in range(2):
        assert S * _column(levels[k]) == _column(levels[k + 1])


@pytest.mark.parametrize("n", [3, 5])
def test_refinement_with_free_vertex_weights(n):
    scheme = catmull_clark(alpha, beta)
    mesh = _random_mesh(n, 2, seed=n)
    before, after = central_rings(mesh, scheme, 0, 1)
    diff = (subdivision_matrix(scheme, n) * _column(before) - _column(after)).applyfunc(sp.expand)
    assert diff == sp.zeros(2 * n + 1, 1)
    assert any(e.has(alpha) for e in _column(after))


@pytest.mark.parametrize("n,rings", [(3, 1), (5, 2), (6, 3)])
def test_refining_r_rings_leaves_2r_minus_1_exact_rings(n, rings):
    step = refine(ring_mesh(n, rings), catmull_clark())
    assert len(step.mesh.faces) == n * (2 * rings - 1) ** 2


def test_new_one_ring_depends_only_on_the_old_one():
    n = 5
    a = _random_mesh(n, 3, seed=1)
    b_values = dict(a.values)
    ring_ids = set(a.neighbourhood(0, 1).values)
    rng = random.Random(2)
    for v in b_values:
        if v not in ring_ids:
            b_values[v] = (Fraction(rng.randint(-999, 999)),)
    b = a.with_values(b_values)
    assert central_rings(a, catmull_clark(), 0, 3, keep_rings=None) == central_rings(b, catmull_clark(), 0, 3, keep_rings=None)
    # and the outer rings did change something further out
    assert refine(a, catmull_clark()).mesh.values != refine(b, catmull_clark()).mesh.values


def test_bad_meshes_are_rejected():
    with pytest.raises(InvalidMeshError, match="quad"):
        QuadMesh(((0, 1, 2),), {0: (0,), 1: (0,), 2: (0,)})
    with pytest.raises(InvalidMeshError, match="oriented"):
        QuadMesh(((0, 1, 2, 3), (0, 1, 4, 5)), {i: (0,) for i in range(6)})
    with pytest.raises(InvalidMeshError, match="no value"):
        QuadMesh(((0, 1, 2, 3),), {0: (0,)})
    m = ring_mesh(4, 1)
    with pytest.raises(InvalidMeshError, match="boundary"):
        m.one_ring(1)
    with pytest.raises(InvalidMeshError, match="not a corner"):
        m.one_ring(99)
    with pytest.raises(InvalidMeshError, match="rings"):
        ring_mesh(4, 0)


def test_schemes_that_are_not_mesh_rules_are_rejected():
    cc = catmull_clark()
    R = sp.Rational
    lopsided_face = Stencil.from_weights(R(1, 2), {0: R(1, 4), 1: R(1, 8)}, {0: R(1, 8)})
    with pytest.raises(InvalidSchemeError, match="corner"):
        mesh_rules(Scheme("lopsided", cc.edge_rule, lopsided_face, cc.vertex_rule))
    valence_edge = Stencil.from_weights(R(3, 8), {-1: 1 / (4 * N), 0: R(3, 8), 1: R(1, 8) - 1 / (4 * N)}, {-1: R(1, 16), 0: R(1, 16)})
    with pytest.raises(InvalidSchemeError, match="valence"):
        mesh_rules(Scheme("valence-dependent", valence_edge, cc.face_rule, cc.vertex_rule))
    ends_differ = Stencil.from_weights(R(1, 2), {-1: R(1, 16), 0: R(1, 4), 1: R(1, 16)}, {-1: R(1, 16), 0: R(1, 16)})
    with pytest.raises(InvalidSchemeError, match="other end"):
        mesh_rules(Scheme("ends differ", ends_differ, cc.face_rule, cc.vertex_rule))
    skewed = Stencil.from_weights(R(3, 8), {-1: R(1, 8), 0: R(3, 8), 1: R(0)}, {-1: R(0), 0: R(1, 8)})
    with pytest.raises(InvalidSchemeError, match="mirror"):
        mesh_rules(Scheme("skewed", skewed, cc.face_rule, cc.vertex_rule))


@pytest.mark.parametrize("n", [3, 5, 7])
def test_triangle_meshes_share_the_topology_questions(n):
    """The 2-ring triangle mesh: its centre's faces are the 1-ring (a disk of n triangles, bounded by the a_i)."""
    from symdecomp.schemes.mesh import triangle_ring_mesh

    mesh = triangle_ring_mesh(n, 2)
    _, ring = mesh.one_ring(0)
    one = mesh.neighbourhood(0, 1)
    assert len(one.faces) == mesh.valence(0) == n and one.is_disk() and not mesh.neighbourhood(0, 2).boundary_vertices() & {0, *ring}
    assert one.boundary_vertices() == frozenset(ring) and one.is_interior(0) and not any(one.is_interior(a) for a in ring)
    assert all(mesh.valence(a) == 6 for a in ring) and type(one.with_values(one.values)) is type(mesh)
