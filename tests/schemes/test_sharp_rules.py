"""The rules at sharp features: SharpRules, the [sharp] section of scheme files, BLZ's shipped rules, and
OpenSubdiv's sharpness arithmetic (symdecomp.schemes.sharp, symdecomp.schemes.tagged_refinement)."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.errors import InvalidSchemeError, NotAffineError
from symdecomp.schemes.files import load_scheme, scheme_from_text, scheme_to_text
from symdecomp.schemes.mesh import QuadMesh
from symdecomp.schemes.sector import SharpVertex, sharp_subdivision_matrix
from symdecomp.schemes.sharp import (
    SharpOptions,
    SharpRules,
    check_sharpness,
    child_edge_sharpnesses,
    standard_sharp_rules,
)
from symdecomp.schemes.tagged_refinement import TaggedMesh, refine_tagged
from symdecomp.symbols import theta_k

CC, LOOP = sd.catmull_clark(), sd.loop()
CC_BLZ, LOOP_BLZ = load_scheme("catmull-clark-blz"), load_scheme("loop-blz")


def _cosine_polygon(vertex: SharpVertex, theta) -> sp.Matrix:
    """O = 0, a_i = cos(i theta) and (quads) b_i = a_i + a_{i+1}: the open cosine polyline of the sector."""
    a = [sp.cos(i * theta) for i in range(vertex.edge_count())]
    b = [a[i] + a[i + 1] for i in range(vertex.faces)] if vertex.lattice.face_neighbours else []
    return sp.Matrix([0, *a, *b])


@pytest.mark.parametrize("scheme, lattice, regular", [(CC_BLZ, sd.QUAD, 2), (LOOP_BLZ, sd.TRIANGLE, 3)],
                         ids=["catmull-clark-blz", "loop-blz"])
def test_blz_makes_the_cosine_polyline_an_eigenvector_of_one_half(scheme, lattice, regular):
    """BLZ choose gamma so that the sector's cosine polyline is an eigenvector with the boundary curve's
    subdominant eigenvalue 1/2, for every k (and at a corner of angle alpha with theta = alpha/k); the standard
    rules have it at the regular boundary only."""
    standard = CC if scheme is CC_BLZ else LOOP
    for k in range(1, 7):  # cos(pi/k) in radicals sympy reduces quickly
        vertex = SharpVertex.boundary(k, lattice)
        v = _cosine_polygon(vertex, sp.pi / k)
        S = sharp_subdivision_matrix(scheme, vertex)
        assert (S * v - v / 2).applyfunc(lambda x: sp.simplify(sp.expand(x))).is_zero_matrix, k
        T = sharp_subdivision_matrix(standard, vertex)
        fits = (T * v - v / 2).applyfunc(lambda x: sp.simplify(sp.expand(x))).is_zero_matrix
        trivial = all(sp.cos(i * sp.pi / k) == 0 for i in range(1, k))  # no smooth edge, or cos 0 at its end
        assert fits == (k == regular or trivial), k
    for angle in (sp.pi / 2, 3 * sp.pi / 2):
        vertex = SharpVertex.corner(3, lattice, angle=angle)
        v = _cosine_polygon(vertex, angle / 3)
        S = sharp_subdivision_matrix(scheme, vertex)
        assert (S * v - v / 2).applyfunc(lambda x: sp.simplify(sp.expand(x))).is_zero_matrix


def test_blz_is_the_standard_rule_at_the_regular_boundary():
    for blz, standard, lattice, k in ((CC_BLZ, CC, sd.QUAD, 2), (LOOP_BLZ, LOOP, sd.TRIANGLE, 3)):
        vertex = SharpVertex.boundary(k, lattice)
        for rings in (1, 2):
            S = sharp_subdivision_matrix(blz, vertex, rings=rings)
            assert (S - sharp_subdivision_matrix(standard, vertex, rings=rings)).applyfunc(sp.simplify).is_zero_matrix


def test_the_shipped_files_round_trip_and_keep_the_interior_rules():
    for blz, standard in ((CC_BLZ, CC), (LOOP_BLZ, LOOP)):
        assert scheme_from_text(scheme_to_text(blz)) == blz
        assert blz.stencils() == standard.stencils() and blz.vertex_rule == standard.vertex_rule
        assert blz.sharp != standard.sharp == standard_sharp_rules()
        assert blz.parameters == ()


HEAD = 'name = "s"\n[edge]\nO = "3/8"\na = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }\nb = { "-1" = "1/16", "0" = "1/16" }\n' \
       '[face]\nO = "1/4"\na = { "0" = "1/4", "1" = "1/4" }\nb = { "0" = "1/4" }\n[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n'


def test_a_sharp_section_with_a_parameter_round_trips():
    text = HEAD.replace('name = "s"', 'name = "s"\nparameters = ["g"]') + \
        '[sharp]\nnear_edge_centre = "3/4 - g*cos(2*theta_k)/k"\nnear_edge_end = "g*cos(2*theta_k)/k"\n'
    scheme = scheme_from_text(text)
    assert [str(p) for p in scheme.parameters] == ["g"]
    assert scheme_from_text(scheme_to_text(scheme)) == scheme
    fixed = scheme.substitute({"g": sp.Rational(3, 8)})
    assert fixed.parameters == () and fixed.sharp.near_edge_end == sp.Rational(3, 8) * sp.cos(2 * theta_k) / sd.symbols.sector_faces


@pytest.mark.parametrize("section, message", [
    ('[sharp]\ncrease_centre = "1/2"\n', "crease_centre \\+ 2\\*crease_end = 3/4, not 1"),
    ('[sharp]\ncrease_edge = "1/3"\n', "2\\*crease_edge = 2/3, not 1"),
    ('[sharp]\ncrease_edge = 0.5\n', "float"),
    ('[sharp]\nnear_edge_centre = "1/2"\n', "together"),
    ('[sharp]\nnear_edge_centre = "1/2"\nnear_edge_end = "1/2"\n', "must equal the edge rule's weights on the two ends, 3/4"),
    ('[sharp]\nnear_edge_centre = "3/4 - cos(theta)"\nnear_edge_end = "cos(theta)"\n', "theta"),
    ('[sharp]\nnear_edge_centre = "3/4 - cos(sqrt(theta_k))"\nnear_edge_end = "cos(sqrt(theta_k))"\n', "theta_k"),
    ('[sharp]\ncorner = "1"\n', "unknown key 'corner'"),
    ('sharp = 3\n', "sharp must be a table"),
    ('[sharp]\nnear_edge_centre = "' + "+".join(["1"] * 500) + '"\nnear_edge_end = "0"\n', "operations"),
], ids=range(10))
def test_bad_sharp_sections_are_refused_in_one_line(section, message):  # ids: the first key of each section
    with pytest.raises(InvalidSchemeError, match=message) as info:
        scheme_from_text(HEAD + section if section.startswith("[") else section + HEAD, source="my.toml")
    assert str(info.value).startswith("my.toml: ") and "\n" not in str(info.value)


def test_k_is_reserved():
    with pytest.raises(InvalidSchemeError, match="reserved"):
        scheme_from_text(HEAD.replace('name = "s"', 'name = "s"\nparameters = ["k"]'))


def test_sharp_rules_in_python_are_checked():
    with pytest.raises(NotAffineError, match="crease_centre"):
        SharpRules(1, 1, sp.Rational(1, 2))
    with pytest.raises(InvalidSchemeError, match="float"):
        SharpRules(0.75, sp.Rational(1, 8), sp.Rational(1, 2))
    with pytest.raises(NotAffineError, match="near_edge"):
        sd.Scheme("x", CC.edge_rule, CC.face_rule, CC.vertex_rule, sharp=SharpRules("3/4", "1/8", "1/2", "1/2", "1/2"))
    with pytest.raises(sd.InvalidTypeError, match="sharp"):
        sd.Scheme("x", CC.edge_rule, CC.face_rule, CC.vertex_rule, sharp={"crease_edge": "1/2"})


def test_chaikin_decay_keeps_the_sum_of_two_semi_sharp_edges_falling_by_two():
    """3/4 s1 + 1/4 s2 - 1 and 3/4 s2 + 1/4 s1 - 1 sum to s1 + s2 - 2; equal sharpness decays as the uniform rule."""
    chaikin, uniform = SharpOptions(crease_method="chaikin"), SharpOptions()
    for s1, s2 in ((Fraction(5, 2), Fraction(3, 2)), (Fraction(4), Fraction(7, 3)), (Fraction(3), Fraction(3))):
        c1, c2, smooth, sharp = child_edge_sharpnesses([s1, s2, 0, math.inf], chaikin)
        assert c1 + c2 == s1 + s2 - 2 and smooth == 0 and sharp == math.inf
        assert (c1 == c2) == (s1 == s2)
        if s1 == s2:
            assert [c1, c2] == child_edge_sharpnesses([s1, s2], uniform)
    assert check_sharpness(0.5) == Fraction(1, 2) and check_sharpness("5/2") == Fraction(5, 2)
    assert check_sharpness(10) == check_sharpness("inf") == math.inf


@pytest.mark.parametrize("scheme, lattice", [(CC, sd.QUAD), (LOOP, sd.TRIANGLE)], ids=["catmull-clark", "loop"])
def test_two_refinements_of_the_tagged_mesh_are_the_product_of_the_level_matrices(scheme, lattice):
    """Refining the tagged 2-ring mesh twice (its sharpness decayed by the refinement itself) moves the 1-ring by
    S(level 1) S(level 0): the level argument is the refinement's own decay."""
    vertex = SharpVertex.crease(2, 3, lattice, Fraction(3, 2))
    tagged, ids = vertex.tagged_mesh(3)
    size = vertex.one_ring_size()
    values = {i: tuple(sp.Integer(int(i == j)) for j in range(size)) for i in tagged.mesh.vertices()}
    tagged = TaggedMesh(tagged.mesh.with_values(values), tagged.edge_sharpness, tagged.vertex_sharpness, tagged.cut)
    once, _, where = refine_tagged(tagged, scheme)
    twice, _, where2 = refine_tagged(once, scheme)
    labels = vertex.ring_labels(1)
    first = [where[("vertex", 0)]] + [where[("edge", frozenset((0, ids[lab])))] for lab in labels[1:1 + vertex.edge_count()]]
    second = [where2[("vertex", first[0])]] + [where2[("edge", frozenset((first[0], x)))] for x in first[1:]]
    if lattice.face_neighbours:
        face_of = {frozenset(f): i for i, f in enumerate(once.mesh.faces)}
        second += [where2[("face", face_of[frozenset(_face(once.mesh, first[0], first[1 + i], first[2 + i] if i + 2 < len(first) else first[1]))])]
                   for i in range(vertex.faces)]
    got = sp.Matrix([list(twice.mesh.values[x]) for x in second])
    product = sharp_subdivision_matrix(scheme, vertex, level=1) * sharp_subdivision_matrix(scheme, vertex, level=0)
    assert (got - product).applyfunc(sp.simplify).is_zero_matrix
    assert product != sharp_subdivision_matrix(scheme, vertex) ** 2  # the decay does matter: 3/2 -> 1/2


def _face(mesh: QuadMesh, o, a, a_next):
    return next(f for f in mesh.faces if o in f and a in f and a_next in f)
