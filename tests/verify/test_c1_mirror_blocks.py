"""Zorin's conditions from the sector's blocks against the dense test (the sector's exact 2-ring matrix), k = 1..8.

The blocks route decides alone only failures of the spectral or tangent conditions; there the dense test, built
without the blocks, must reach the same verdict with the same subdominant eigenvalues, and it must find every such
failure the dense test finds by the tangent condition (same reason). Elsewhere the route is the dense test itself up to
``MAP_FACES`` faces, and past it undecided with the blocks' finding.
"""

from __future__ import annotations

import json
import math

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.cli import main
from symdecomp.cli.common import LIMITS
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import MAX_DENSE_FACES
from symdecomp.verify.c1_mirror_blocks import BLOCKS_METHOD, MAP_FACES, c1_mirror_blocks
from symdecomp.verify.c1_sector_matrix import SHARP_METHOD, c1_sharp_test
from symdecomp.verify.result import C1Verdict

SCHEMES = {"cc": sd.catmull_clark, "loop": sd.loop, "cc-blz": lambda: load_scheme("catmull-clark-blz"),
           "loop-blz": lambda: load_scheme("loop-blz")}
TANGENT = "not in the tangent plane"


def _vertices(lattice):
    for k in range(1, 9):
        yield sd.SharpVertex.boundary(k, lattice)
        yield sd.SharpVertex.corner(k, lattice)
        yield sd.SharpVertex.crease(k, 3, lattice)


@pytest.mark.parametrize("name", [pytest.param("cc", marks=pytest.mark.slow), "loop", pytest.param("cc-blz", marks=pytest.mark.slow),
                                  pytest.param("loop-blz", marks=pytest.mark.slow)])
def test_the_blocks_fail_a_sector_exactly_where_the_dense_test_does_by_the_tangent(name):
    scheme = SCHEMES[name]()
    decided, by_tangent = 0, 0
    for vertex in _vertices(scheme.lattice):
        blocks = c1_mirror_blocks(scheme, vertex, map_faces=0, certify_map=False)  # the blocks alone
        dense = c1_sharp_test(scheme, vertex)
        assert blocks.verdict is not C1Verdict.C1 and blocks.method == BLOCKS_METHOD
        by_tangent += dense.verdict is C1Verdict.NOT_C1 and TANGENT in dense.reason
        if blocks.verdict is C1Verdict.NOT_C1:
            decided += 1
            assert dense.verdict is C1Verdict.NOT_C1 and blocks.lambdas == pytest.approx(dense.lambdas, abs=1e-12)
            assert blocks.reason.split("; side 2")[0] == dense.reason.split("; side 2")[0]
    # every failure of the tangent condition the dense test finds, the blocks find (BLZ's rules fail none)
    assert decided == by_tangent and (decided > 0) == (name in ("cc", "loop"))


def test_an_exact_tie_of_the_blocks_is_the_dense_tests_verdict_without_it():
    # Catmull-Clark at a boundary of 4 faces: lambda_2 = lambda_3 = 1/2 exactly (one value of the blocks, multiplicity
    # counted exactly); the dense test finds the same double root, so its minutes are not spent (BLZ's corners: 1/2 thrice)
    scheme = sd.catmull_clark()
    vertex = sd.SharpVertex.boundary(4, "quad")
    blocks, dense = c1_mirror_blocks(scheme, vertex), c1_sharp_test(scheme, vertex)
    assert blocks.verdict is dense.verdict is C1Verdict.UNDECIDED and dense.method == SHARP_METHOD
    assert blocks.method == BLOCKS_METHOD and "one exact value of the blocks" in blocks.reason
    assert "exactly equal" in dense.reason and blocks.lambdas == pytest.approx(dense.lambdas, abs=1e-12)


@pytest.mark.parametrize("name, kind, k", [("cc", "boundary", 1000), ("cc", "corner", 777), ("loop", "boundary", 2000),
                                           ("loop", "corner", 500)])
def test_standard_rules_fail_at_many_faces_with_the_dominant_sine_block(name, kind, k):
    # lambda_1, lambda_2: the sine blocks j = 1, 2 (their closed forms in c = cos(pi j/k)), neither 1/2
    scheme = SCHEMES[name]()
    r = c1_mirror_blocks(scheme, getattr(sd.SharpVertex, kind)(k, scheme.lattice))
    assert r.verdict is C1Verdict.NOT_C1 and TANGENT in r.reason
    lam = []
    for j in (1, 2):
        c = math.cos(math.pi * j / k)
        if scheme.face_rule is None:  # Loop: the 1 x 1 block c/4 + 3/8
            lam.append(c / 4 + 3 / 8)
        else:  # Catmull-Clark: trace c/8 + 5/8, determinant 1/16, the larger root
            t = c / 8 + 5 / 8
            lam.append((t + math.sqrt(t * t - 1 / 4)) / 2)
    assert r.lambdas == pytest.approx(lam, abs=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["cc-blz", "loop-blz"])
def test_past_map_faces_a_sector_the_blocks_pass_is_undecided_without_the_modes(name, monkeypatch):
    # BLZ's double 1/2: the crease block's mirror-odd tangent and the mirror-even sine block j = 1, one in each part;
    # the closed-form modes certify the map (:mod:`symdecomp.verify.fourier_map`), without them it is undecided
    scheme = SCHEMES[name]()
    vertex = sd.SharpVertex.crease(100, 40, scheme.lattice)
    assert c1_mirror_blocks(scheme, vertex).verdict is C1Verdict.C1
    monkeypatch.setattr("symdecomp.verify.c1_mirror_blocks.applies", lambda *args: False)
    r = c1_mirror_blocks(scheme, vertex)
    assert r.verdict is C1Verdict.UNDECIDED and r.lambdas == pytest.approx([0.5, 0.5])
    assert r.spectral.status is C1Verdict.C1 and r.spectral.gap > 0
    assert "the spectral and tangent conditions hold (blocks)" in r.reason and f"at most {MAP_FACES} faces" in r.reason


@pytest.mark.slow
@pytest.mark.parametrize("name", ["cc-blz", "loop-blz"])
def test_the_blocks_spectral_verdict_at_blz_boundaries_is_the_dense_one(name):
    scheme = SCHEMES[name]()
    for k in range(2, 9):
        vertex = sd.SharpVertex.boundary(k, scheme.lattice)
        blocks, dense = c1_mirror_blocks(scheme, vertex, map_faces=0, certify_map=False), c1_sharp_test(scheme, vertex)
        assert blocks.spectral.status is dense.spectral.status is C1Verdict.C1
        assert blocks.lambdas == pytest.approx(dense.lambdas, abs=1e-12)


def test_a_corner_given_an_angle_is_refused_past_map_faces():
    with pytest.raises(NotApplicableError, match="dense matrices"):
        c1_mirror_blocks(sd.catmull_clark(), sd.SharpVertex.corner(MAP_FACES + 1, "quad", sp.pi / 2))


def test_the_command_line_reads_a_thousand_faces(capsys):
    assert main(["c1", "--boundary", "--k", "1000", "--json"]) == 1
    (row,) = json.loads(capsys.readouterr().out)["rows"]
    assert row["verdict"] == "not-c1" and row["method"] == BLOCKS_METHOD and row["vertex"] == "boundary k = 1000"
    assert LIMITS["c1 --k"][0] == 10000 and f"at most {MAX_DENSE_FACES} faces" in LIMITS["c1 --k"][1]
