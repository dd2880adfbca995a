"""``symdecomp masks K --boundary`` (and --corner, --crease K2, --dart): exact limit and tangent masks of a sharp vertex.

The masks are checked as what they claim to be: exact left eigenvectors of the refined matrix (in ``Q(lambda)``),
the position mask the limit of repeated refinement, the tangent masks annihilating constants, the curve tangent
vanishing off the crease points.
"""

from __future__ import annotations

import json

import flint
import pytest

import symdecomp as sd
from symdecomp.algebra.number_field import FieldElement
from symdecomp.cli import main

CC, LOOP = sd.catmull_clark(), sd.loop()


def _left_residual(S, mask) -> list:
    """``w S - lambda w`` exactly in ``Q(lambda)``: one field element per column."""
    p = mask.eigenvalue.factor
    lam = FieldElement(flint.fmpq_poly([0, 1]) % p, p)
    out = []
    for j in range(S.nrows()):
        acc = FieldElement(flint.fmpq_poly([]), p)
        for i, w in enumerate(mask.weights):
            if S[i, j] != 0:
                acc = acc + w * FieldElement(flint.fmpq_poly([S[i, j]]), p)
        out.append(acc - lam * mask.weights[j])
    return out


VERTICES = [(s, v) for s in (CC, LOOP) for v in (
    sd.SharpVertex.boundary(2, s.lattice), sd.SharpVertex.boundary(3, s.lattice), sd.SharpVertex.boundary(6, s.lattice),
    sd.SharpVertex.corner(2, s.lattice), sd.SharpVertex.crease(2, 3, s.lattice), sd.SharpVertex.dart(4, s.lattice))]


@pytest.mark.parametrize("scheme, vertex", VERTICES, ids=lambda x: getattr(x, "name", None) or str(x.sectors))
def test_every_mask_is_an_exact_left_eigenvector_and_the_tangents_annihilate_constants(scheme, vertex):
    S = sd.exact_sharp_matrix(scheme, vertex)
    masks = sd.sharp_masks(scheme, vertex)
    assert sum((w.poly for w in masks.position.weights), flint.fmpq_poly([])) == 1
    for mask in (masks.position, *masks.tangents):
        assert all(not r for r in _left_residual(S, mask)), mask.name
        assert any(mask.weights)
    for mask in masks.tangents:
        assert not sum((w.poly for w in mask.weights), flint.fmpq_poly([])) % mask.eigenvalue.factor, mask.name


def test_the_position_mask_is_the_limit_of_repeated_refinement():
    for scheme, vertex in [(CC, sd.SharpVertex.boundary(5, sd.QUAD)), (LOOP, sd.SharpVertex.crease(2, 4, sd.TRIANGLE)),
                           (CC, sd.SharpVertex.dart(5, sd.QUAD))]:
        S = sd.exact_sharp_matrix(scheme, vertex)
        size = S.nrows()
        points = flint.fmpq_mat(size, 1, [flint.fmpq((7 * i * i + 3) % 11, 1 + i % 4) for i in range(size)])
        weights = [w.poly[0] for w in sd.sharp_masks(scheme, vertex).position.weights]
        limit = sum((w * points[i, 0] for i, w in enumerate(weights)), flint.fmpq(0))
        refined = points
        for _ in range(40):  # level 40: the centre's distance to its limit is below 1e-12 (|lambda_2|^40 < 1e-9 * 1e-3)
            refined = S * refined
        assert abs(float(refined[0, 0] - limit)) < 1e-12
        # and the mask applied at any level gives the same limit, exactly
        assert sum((w * refined[i, 0] for i, w in enumerate(weights)), flint.fmpq(0)) == limit


def test_the_boundary_curve_tangent_vanishes_off_the_crease_and_the_cross_tangent_is_the_first_sine_block(capsys):
    assert main(["masks", "3", "--boundary", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    curve, cross = out["tangents"]
    assert curve["name"] == "boundary curve tangent" and cross["name"] == "cross tangent"
    assert {k for k, v in curve["exact"].items() if v != "0"} == {"a_0", "a_3"}
    assert out["tangent_plane"] is True and out["subdominant"]["blocks"] == "sine j=1 (theta = pi/3)"
    assert out["subdominant"]["value"] == cross["eigenvalue"]


def test_catmull_clark_boundary_k5_tangents_are_not_the_subdominant_pair(capsys):
    # the first two sine blocks exceed the boundary curve's 1/2 at k = 5: the curve tangent is not subdominant
    assert main(["masks", "5", "--boundary"]) == 1
    captured = capsys.readouterr()
    assert "the two subdominant eigenvalues are 0.62634127, 0.54998835, not the tangents' 0.5, 0.62634127" in captured.out
    assert captured.err.count("\n") == 1 and "not the tangent plane's" in captured.err


def test_text_output_names_each_weight(capsys):
    assert main(["masks", "2", "--corner", "--scheme", "loop"]) == 0
    out = capsys.readouterr().out
    assert "boundary curve tangent along O-a_0 (eigenvalue 0.5, crease):" in out
    assert "boundary curve tangent along O-a_2 (eigenvalue 0.5, crease):" in out
    assert "  O: -1.0\n  a_0: 1.0\n  a_1: 0.0\n  a_2: 0.0" in out


@pytest.mark.parametrize("argv, words", [
    (["masks", "3", "--boundary", "--rings", "2"], "--rings: not available"),
    (["masks", "3", "--boundary", "--dart"], "cannot be used together"),
    (["masks", "2"], "argument N: expected a valence: an integer >= 3 and <= 1000"),
    (["masks", "5", "--dart", "--scheme", "loop"], "not rational"),
])
def test_masks_bad_input(capsys, argv, words):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1
