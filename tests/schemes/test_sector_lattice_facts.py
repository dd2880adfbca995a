"""A sharp vertex's fan asks its lattice (issue 30): the rings of a sector, the cells' faces, the refined points."""

import dataclasses

import pytest

from symdecomp.errors import LatticeFactMissing
from symdecomp.schemes.lattice import QUAD, TRIANGLE, Lattice, QuadLattice
from symdecomp.schemes.sector import SharpVertex


@pytest.mark.parametrize("lat", [QUAD, TRIANGLE], ids=str)
@pytest.mark.parametrize("rings", [1, 2, 3])
def test_a_dart_fan_has_the_points_and_faces_of_the_closed_ring(lat, rings):
    n = 5
    dart = SharpVertex.dart(n, lat)
    labels = dart.ring_labels(rings)
    # a dart's fan is the whole ring around a valence-n vertex: the same points as the lattice's ring, one each
    assert len(labels) == len(set(labels)) == lat.ring_size(n, rings)
    assert set(labels) == set(lat.ring_labels(n, rings))
    mesh, ids = dart.tagged_mesh(rings)[0].mesh, dart.tagged_mesh(rings)[1]
    # faces: rings^2 quads per sector, or rings^2 triangles (1 + 3 + 5 + ...) per sector
    assert len(mesh.faces) == n * rings * rings
    assert all(len(f) == lat.face_sides for f in mesh.faces)
    assert sorted(ids.values()) == list(range(len(labels)))


def test_the_one_ring_names_come_from_the_lattice():
    assert SharpVertex.boundary(2, QUAD).vertex_order() == ("O", "a_0", "a_1", "a_2", "b_0", "b_1")
    assert SharpVertex.boundary(2, TRIANGLE).vertex_order() == ("O", "a_0", "a_1", "a_2")
    assert SharpVertex.crease(2, 3, QUAD).one_ring_size() == 1 + 5 + 5


def _lacking(fact: str) -> Lattice:
    cls = type("LackingLattice", (QuadLattice,), {fact: getattr(Lattice, fact)})
    return cls(**{f.name: getattr(QUAD, f.name) for f in dataclasses.fields(QUAD)} | {"name": "stub"})


def test_a_fan_on_a_lattice_without_its_sectors_rings_fails_naming_the_fact():
    vertex = SharpVertex.boundary(3, _lacking("sector_ring"))
    assert len(vertex.ring_labels(1)) == 1 + 4 + 3  # the 1-ring needs no sector rings
    with pytest.raises(LatticeFactMissing, match=r"^the stub lattice has no 'sector_ring'$"):
        vertex.ring_labels(2)
