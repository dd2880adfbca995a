"""The structural route (the mirror decomposition's blocks, O(k)) against the dense one (the matrix built by refinement).

The dense route factors the characteristic polynomial of the matrix assembled without any block structure, so the two
are independent: every distinct dense eigenvalue (a certified ball, its exact multiplicity) must be met by exactly one
structural value with the same multiplicity and the same block names, for each sector kind and both lattices.
"""

from __future__ import annotations

import math
import subprocess
import sys

import flint
import pytest

import symdecomp as sd
from symdecomp.analysis.block_values import _Field, structural_values
from symdecomp.analysis.spectrum import sharp_spectrum
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.files import load_scheme

SLOW = pytest.mark.slow
SCHEMES = {"cc": sd.catmull_clark(), "loop": sd.loop(), "cc-blz": load_scheme("catmull-clark-blz"),
           "loop-blz": load_scheme("loop-blz")}


def _vertices(lattice, k: int):
    yield sd.SharpVertex.boundary(k, lattice)
    yield sd.SharpVertex.corner(k, lattice)
    if k >= 2:
        yield sd.SharpVertex.crease(k, k, lattice)
        yield sd.SharpVertex.crease(k - 1 or 1, k, lattice)


def _same(dense, structural) -> None:
    assert dense.route == "dense" and structural.route == "structural"
    assert dense.size == structural.size
    assert sum(e.multiplicity for e in structural.entries) == structural.size
    assert len(dense.entries) == len(structural.entries)
    for d in dense.entries:
        hits = [s for s in structural.entries if s.ball.overlaps(d.ball)]
        assert len(hits) == 1, (d.text, [h.text for h in hits])
        assert hits[0].multiplicity == d.multiplicity, d.text
        if dense.decomposed:
            assert set(hits[0].blocks) == set(d.blocks), d.text


@pytest.mark.slow
@pytest.mark.parametrize("name", ["cc", "loop"])
@pytest.mark.parametrize("k", [*range(1, 7), pytest.param(7, marks=SLOW), pytest.param(8, marks=SLOW)])
def test_structural_equals_dense_for_rational_rules(name, k):
    scheme = SCHEMES[name]
    for vertex in _vertices(scheme.lattice, k):
        _same(sharp_spectrum(scheme, vertex, route="dense", digits=30), sharp_spectrum(scheme, vertex, route="structural", digits=30))


@pytest.mark.parametrize("name", ["cc-blz", "loop-blz"])
@pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 6, pytest.param(7, marks=SLOW), pytest.param(8, marks=SLOW)])
def test_structural_equals_dense_over_the_cosine_field(name, k):
    scheme = SCHEMES[name]
    for vertex in (sd.SharpVertex.boundary(k, scheme.lattice), sd.SharpVertex.corner(k, scheme.lattice),
                   *([sd.SharpVertex.crease(k, k, scheme.lattice)] if 2 <= k <= 4 else [])):
        structural = sharp_spectrum(scheme, vertex, route="structural", digits=30)
        _same(sharp_spectrum(scheme, vertex, route="dense", digits=30), structural)
        assert structural.field == ("Q" if k <= 3 else f"Q(cos(pi/{k}))")


def test_half_is_decided_exactly_at_a_thousand_faces():
    """BLZ's first sine block has 1/2 for every k (its point); the field decides it, not a ball."""
    scheme = SCHEMES["cc-blz"]
    s = sharp_spectrum(scheme, sd.SharpVertex.boundary(1000, scheme.lattice))
    assert s.route == "structural" and s.size == 2002 and sum(e.multiplicity for e in s.entries) == 2002
    half = [e for e in s.entries if e.exact == "1/2"]
    assert len(half) == 1 and half[0].multiplicity == 2
    assert half[0].blocks == ("crease", "sine j=1 (theta = pi/1000)")
    assert s.entries[2].ball.real < flint.arb(1) / 2  # the next one is strictly below


def test_crease_with_equal_sides_doubles_every_sine_value():
    scheme = SCHEMES["loop"]
    s = sharp_spectrum(scheme, sd.SharpVertex.crease(500, 500, scheme.lattice))
    sine = [e for e in s.entries if any(b.startswith("sine") for b in e.blocks)]
    assert len(sine) == 499 and all(e.multiplicity == 2 for e in sine)


def test_the_field_is_the_real_cyclotomic_one():
    f = _Field(7)
    c = f.cos_multiple(1)
    assert not (f.cos_multiple(2) - (c * c * f.rational(2) - f.rational(1)))  # cos(2t) = 2 cos(t)^2 - 1 in K
    assert f.modulus.degree() == 3 and f.ball(c, 128).overlaps(flint.arb.cos_pi_fmpq(flint.fmpq(1, 7)))


def test_what_the_structural_route_refuses():
    with pytest.raises(NotApplicableError, match="dart"):
        structural_values(sd.catmull_clark(), sd.SharpVertex.dart(5, sd.QUAD))
    with pytest.raises(NotApplicableError, match="semi-sharp"):
        structural_values(sd.catmull_clark(), sd.SharpVertex.crease(3, 3, sd.QUAD, sharpness=2))
    with pytest.raises(InvalidInputError, match="route: expected one of auto, dense, structural"):
        sharp_spectrum(sd.catmull_clark(), sd.SharpVertex.boundary(3, sd.QUAD), route="fast")
    with pytest.raises(InvalidInputError, match="built for at most 64 faces"):
        sharp_spectrum(sd.catmull_clark(), sd.SharpVertex.boundary(65, sd.QUAD), route="dense")


def test_semi_sharp_and_infinite_agree_on_their_sharp_levels():
    vertex = sd.SharpVertex.crease(3, 4, sd.QUAD)
    assert vertex.sharpness == math.inf
    a = sharp_spectrum(sd.catmull_clark(), vertex, route="structural")
    b = sharp_spectrum(sd.catmull_clark(), vertex, route="dense")
    assert [e.multiplicity for e in a.entries] == [e.multiplicity for e in b.entries]


def test_command_line_reads_a_thousand_faces():
    out = subprocess.run([sys.executable, "-m", "symdecomp", "spectrum", "1000", "--corner", "--scheme", "loop-blz"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("loop-blz, corner k=1000 (triangle mesh): 1002 eigenvalues")
    assert "from the blocks (O(k))" in out.stdout


def test_unequal_sides_under_blz_reach_two_fields_and_agree_with_the_matrix():
    """Crease 4+5 with BLZ's rules: entries in Q(cos(pi/4), cos(pi/5)), which the dense route refuses; 1/2 is an
    eigenvalue of the crease block and of each side's first sine block (decided through the rational), and the
    values agree with the refined matrix's eigenvalues (numeric check, nothing shared)."""
    from symdecomp.verify.numeric import numeric_sharp

    scheme = SCHEMES["cc-blz"]
    vertex = sd.SharpVertex.crease(4, 5, scheme.lattice)
    with pytest.raises(NotApplicableError, match="beyond one field"):
        sharp_spectrum(scheme, vertex, route="dense")
    s = sharp_spectrum(scheme, vertex)
    assert s.field == "Q(cos(pi/4), cos(pi/5))" and s.route == "structural"
    assert [e.multiplicity for e in s.entries if e.exact == "1/2"] == [3]
    assert numeric_sharp(scheme, vertex, dps=40).ok


def test_block_names_print_theta_as_sympy_does():
    from fractions import Fraction

    import sympy as sp

    from symdecomp.analysis.eigenvalue import pi_multiple

    assert all(pi_multiple(Fraction(j, k)) == sp.sstr(sp.pi * j / k) for k in range(1, 40) for j in range(1, 2 * k + 1))


def test_the_joined_values_are_plain_eigenvalues():
    """While equal values are joined each carries the witness that decides equality exactly; no result keeps it, and a
    witness never makes two equal values unequal."""
    from symdecomp.analysis.eigenvalue import Eigenvalue

    values, size = structural_values(sd.catmull_clark(), sd.SharpVertex.crease(3, 4, sd.QUAD))
    assert all(v.witness is None for v in values) and sum(v.multiplicity for v in values) == size
    assert Eigenvalue(1, "1", 1, witness=object()) == Eigenvalue(1, "1", 1)


def test_each_block_names_itself_at_its_vertex():
    """The names the structural route prints are the blocks' own (MirrorBlock.name): at a crease of 3 and 4 faces the
    sine blocks of both sectors, sector by sector, and the last modes with b_i = (-1)^i."""
    s = sharp_spectrum(sd.catmull_clark(), sd.SharpVertex.crease(3, 4, sd.QUAD), route="structural")
    names = {n for e in s.entries for n in e.blocks}
    import sympy as sp

    sines = {f"sine j={j} (theta = {sp.sstr(sp.pi * j / k)}), sector {s_ + 1}" for s_, k in enumerate((3, 4)) for j in range(1, k)}
    assert sines <= names and "crease" in names
    assert {"last mode j=3 (b_i = (-1)^i), sector 1", "last mode j=4 (b_i = (-1)^i), sector 2"} <= names


def test_crease_values_read_once_are_not_shared_between_vertices():
    """The crease block's eigenvalues are derived once per scheme and kind of vertex; each vertex still gets its own list
    of items (a shared one, grown by one vertex's sine blocks, would count them again at the next)."""
    scheme = SCHEMES["cc-blz"]
    vertices = [sd.SharpVertex.boundary(k, scheme.lattice) for k in (5, 9, 5)] + [sd.SharpVertex.crease(4, 6, scheme.lattice)]
    first, second, again, crease = [structural_values(scheme, v) for v in vertices]
    for values, size in (first, second, again, crease):
        assert sum(v.multiplicity for v in values) == size  # every eigenvalue of the matrix, each once
    assert [(v.key, v.multiplicity, v.exact) for v in again[0]] == [(v.key, v.multiplicity, v.exact) for v in first[0]]
    assert second[1] - first[1] == 4 * 2  # four more faces, an edge point and a face point each (1-ring, quads)
