"""The lattice objects: what they say about a kind of mesh agrees with the meshes, patches and schemes built on it."""

import random
from fractions import Fraction

import pytest

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.lattice import LATTICES, QUAD, TRIANGLE, lattice
from symdecomp.schemes.loop import loop
from symdecomp.schemes.patch import SUBPATCH_CORNERS, TRIANGLE_SUBPATCHES
from symdecomp.schemes.scheme import Scheme, catmull_clark, subdivision_matrix

BOTH = [QUAD, TRIANGLE]


@pytest.mark.parametrize("lat", BOTH, ids=str)
@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_ring_sizes_and_labels_are_the_ring_meshes(lat, n):
    for rings in (1, 2, 3):
        labels = lat.ring_labels(n, rings)
        mesh = lat.ring_mesh(n, rings)
        assert lat.ring_size(n, rings) == len(labels) == len(mesh.vertices())
        # ring by ring: the closed r-ring is a prefix, and the labels of ring r are at distance r
        for r in range(rings + 1):
            assert {lat.ring_of(u, v) for _, u, v in labels[: lat.ring_size(n, r)]} == set(range(r + 1))
        assert all(lat.canonical(s, u, v) == (s, u, v) for s, u, v in labels[1:])
    ring = lat.one_ring_labels(n)
    assert lat.one_ring_size(n) == len(ring) == len(lat.vertex_order(n)) == len(set(ring))
    assert set(ring) <= set(lat.ring_labels(n, 1)) and all(lat.ring_of(u, v) <= 1 for _, u, v in ring)


@pytest.mark.parametrize("lat", BOTH, ids=str)
def test_the_regular_valence_is_every_inner_vertex_of_the_regular_ring_mesh(lat):
    mesh = lat.ring_mesh(lat.regular_valence, 3)
    inner = [v for v in mesh.vertices() if mesh.is_interior(v)]
    assert len(inner) == lat.ring_size(lat.regular_valence, 2)
    assert all(mesh.valence(v) == lat.regular_valence for v in inner)


@pytest.mark.parametrize("lat, scheme", [(QUAD, catmull_clark()), (TRIANGLE, loop())], ids=str)
def test_the_reference_scheme_lives_on_its_lattice(lat, scheme):
    assert lat.reference() == scheme and scheme.lattice is lat and lattice(lat.name) is lat
    assert subdivision_matrix(scheme, 5).shape == (lat.one_ring_size(5),) * 2
    assert scheme.stencils() == ((scheme.edge_rule, scheme.face_rule) if lat.face_neighbours else (scheme.edge_rule,))


def test_a_lattice_by_name():
    assert LATTICES == {"quad": QUAD, "triangle": TRIANGLE} and lattice(QUAD) is QUAD
    tri = Scheme("named", loop().edge_rule, None, loop().vertex_rule, lattice="triangle")
    assert tri.lattice is TRIANGLE and tri.mesh == "triangle" and tri == loop().substitute({}, name="named")
    with pytest.raises(InvalidSchemeError, match=r"mesh must be one of \('quad', 'triangle'\), got 'hex'"):
        lattice("hex")
    with pytest.raises(InvalidSchemeError, match="a triangle scheme has no face rule"):
        Scheme("bad", catmull_clark().edge_rule, catmull_clark().face_rule, catmull_clark().vertex_rule, lattice=TRIANGLE)


@pytest.mark.parametrize("seed", range(5))
def test_locate_is_the_sub_patch_layout_of_the_patch(seed):
    """A point of measure in (1, 2] is ``corner_k + sigma_k (s, t)`` of the sub-patch the lattice names, with (s, t) in its domain."""
    rng = random.Random(seed)
    corners = {QUAD: [(c, 1) for c in SUBPATCH_CORNERS], TRIANGLE: list(TRIANGLE_SUBPATCHES)}
    for lat in BOTH:
        for _ in range(200):
            x, y = Fraction(rng.randint(0, 2**10), 2**9), Fraction(rng.randint(0, 2**10), 2**9)
            if not 1 < lat.level_measure(x, y, None) <= 2 or not lat.in_domain(x / 2, y / 2):
                continue
            k, s, t, sigma = lat.locate(x, y)
            (cu, cv), sign = corners[lat][k]
            assert sigma == sign and (cu + sigma * s, cv + sigma * t) == (x, y)
            assert 0 <= s <= 1 and 0 <= t <= 1 and lat.in_domain(s, t)
