"""The O(k) certificate of a boundary, crease or corner vertex (symdecomp.verify.sector_structural) and the numeric
check past the densely solved faces (symdecomp.verify.sector_numeric)."""

from __future__ import annotations

import json

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.cli import main
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.sector import sharp_matrix_rows
from symdecomp.verify import sector_numeric, sector_structural
from symdecomp.verify.sector_structural import certify_sector

CC, LOOP = sd.catmull_clark(), sd.loop()
CC_BLZ, LOOP_BLZ = load_scheme("catmull-clark-blz"), load_scheme("loop-blz")
def _moved_blz(tmp_path):
    from importlib import resources

    text = resources.files("symdecomp.schemes").joinpath("catmull-clark-blz.toml").read_text()
    moved = text.replace('name = "catmull-clark-blz"', 'name = "moved-blz"')
    moved = moved.replace('near_edge_centre = "3/8 + cos(theta_k)/4"', 'near_edge_centre = "3/8 + cos(theta_k)/4 - 1/64"')
    moved = moved.replace('near_edge_end = "3/8 - cos(theta_k)/4"', 'near_edge_end = "3/8 - cos(theta_k)/4 + 1/64"')
    assert moved.count("1/64") == 2
    path = tmp_path / "moved-blz.toml"
    path.write_text(moved)
    return load_scheme(path)


@pytest.mark.slow
@pytest.mark.parametrize("scheme, vertex", [
    (CC, sd.SharpVertex.boundary(1, sd.QUAD)), (CC, sd.SharpVertex.boundary(5, sd.QUAD)),
    (CC, sd.SharpVertex.corner(4, sd.QUAD)), (CC, sd.SharpVertex.crease(3, 5, sd.QUAD)),
    (LOOP, sd.SharpVertex.boundary(9, sd.TRIANGLE)), (LOOP, sd.SharpVertex.crease(4, 4, sd.TRIANGLE)),
    (CC_BLZ, sd.SharpVertex.boundary(7, sd.QUAD)), (CC_BLZ, sd.SharpVertex.corner(6, sd.QUAD)),
    (CC_BLZ, sd.SharpVertex.crease(5, 5, sd.QUAD)), (LOOP_BLZ, sd.SharpVertex.boundary(8, sd.TRIANGLE)),
    (LOOP_BLZ, sd.SharpVertex.corner(5, sd.TRIANGLE)),
])
def test_the_structural_certificate_proves_what_the_dense_route_proves(scheme, vertex):
    structural, dense = certify_sector(scheme, vertex), sd.certify_sharp(scheme, vertex)
    assert structural.ok and dense.ok and structural.multiplicities_certified
    assert (structural.route, dense.route) == ("structural", "charpoly")
    # the same distinct values (20 digits) with the same multiplicities; the dense ones are chi_S's roots
    assert sorted(zip(structural.values, structural.multiplicities)) == sorted(zip(dense.values, dense.multiplicities))
    assert sum(structural.multiplicities) == len(sharp_matrix_rows(scheme, vertex))


def test_the_rows_compared_are_every_entry_of_the_refined_matrix():
    vertex = sd.SharpVertex.crease(3, 5, sd.QUAD)
    entries = sum(1 for row in sharp_matrix_rows(CC, vertex) for w in row.values() if w != 0)
    c = certify_sector(CC, vertex)
    assert f"row by row ({entries} entries, exact in Q)" in c.method
    assert "exact in Q(cos(pi/7))" in certify_sector(CC_BLZ, sd.SharpVertex.boundary(7, sd.QUAD)).method


def test_a_moved_weight_in_a_users_scheme_file_is_refuted_with_the_entry(tmp_path):
    """The matrix refined by a scheme file whose BLZ weight moved by 1/64, held against BLZ's own blocks."""
    moved, vertex = _moved_blz(tmp_path), sd.SharpVertex.boundary(20, sd.QUAD)
    c = certify_sector(CC_BLZ, vertex, matrix=sharp_matrix_rows(moved, vertex))
    assert c.status.value == "disagree" and not c.ok
    ck = sp.cos(sp.pi / 20)
    refined, model = sp.Rational(3, 8) + ck / 4 - sp.Rational(1, 64), sp.Rational(3, 8) + ck / 4
    assert c.message == (f"boundary k=20: refuted: row a_1 (the refined point of a_1), column O: the refined matrix has "
                         f"{sp.sstr(refined)}, the mirror model {sp.sstr(model)} (exact)")
    assert certify_sector(moved, vertex).ok  # its own blocks describe its own matrix


def test_darts_and_semi_sharp_edges_are_out_of_this_routes_reach():
    from fractions import Fraction

    with pytest.raises(NotApplicableError, match="dart"):
        certify_sector(CC, sd.SharpVertex.dart(6, sd.QUAD))
    with pytest.raises(NotApplicableError, match="semi-sharp"):
        certify_sector(CC, sd.SharpVertex.crease(3, 3, sd.QUAD, sharpness=Fraction(1, 2)))
    assert sector_structural.default_route(CC, sd.SharpVertex.dart(40, sd.QUAD)) == "charpoly"
    assert sector_structural.default_route(CC, sd.SharpVertex.boundary(17, sd.QUAD)) == "structural"
    assert sector_structural.default_route(CC, sd.SharpVertex.boundary(16, sd.QUAD)) == "charpoly"
    # cos(theta_k) weights: the dense route works in Q(cos(pi/k)), minutes at 16 faces; the structural one at every size
    assert sector_structural.default_route(CC_BLZ, sd.SharpVertex.boundary(3, sd.QUAD)) == "structural"
    assert sector_structural.default_route(CC_BLZ, sd.SharpVertex.dart(5, sd.QUAD)) == "charpoly"


@pytest.mark.slow
def test_check_takes_the_dense_route_up_to_16_faces_and_the_structural_one_past(capsys):
    """Faces K + K2: 15, 16 on the dense route, 17, 18 past it."""
    assert main(["check", "--k", "13:16", "--crease", "2", "--certify", "--json", "--quiet", "--jobs", "2"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert [r["route"] for r in out["rows"]] == ["charpoly", "charpoly", "structural", "structural"]
    assert [r["n"] for r in out["rows"]] == [13, 14, 15, 16] and all(r["status"] == "agree" for r in out["rows"])
    assert out["summary"]["route"] == "mixed" and out["summary"]["routes"] == {"charpoly": 2, "structural": 2}
    for row in out["rows"]:
        assert sum(row["multiplicities"]) == 2 * (row["n"] + 2) + 1  # O, a_0..a_(K+K2-1), b's: 2 (K + 2) + 1 at K2 = 2


def test_check_refutes_a_moved_weight_by_both_modes(capsys, monkeypatch, tmp_path):
    moved = _moved_blz(tmp_path)

    def refined_by_moved(scheme, vertex, **options):
        return sharp_matrix_rows(moved, vertex, **options)

    monkeypatch.setattr(sector_structural, "sharp_matrix_rows", refined_by_moved)
    assert main(["check", "--k", "40", "--boundary", "--certify", "--scheme", "catmull-clark-blz", "--json", "--quiet"]) == 1
    row = json.loads(capsys.readouterr().out)["rows"][0]
    assert row["status"] == "disagree" and row["route"] == "structural" and "row a_1 (the refined point of a_1), column O" in row["message"]
    monkeypatch.setattr(sector_numeric, "sharp_matrix_rows", refined_by_moved)
    assert main(["check", "--k", "70", "--boundary", "--scheme", "catmull-clark-blz", "--json", "--quiet"]) == 1
    row = json.loads(capsys.readouterr().out)["rows"][0]
    assert row["status"] == "disagree" and row["compared"] == "polylines"
    assert float(row["deviation"]) > 1 / 64 * 0.1  # the moved weight, times a polyline's entry


def test_numeric_mode_past_the_dense_faces_compares_polylines(capsys):
    assert main(["check", "--k", "64:66", "--boundary", "--scheme", "loop", "--json", "--quiet", "--jobs", "2"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert [r["compared"] for r in out["rows"]] == ["eigenvalues", "polylines", "polylines"]
    assert all(r["status"] == "agree" for r in out["rows"]) and [r["size"] for r in out["rows"]] == [66, 67, 68]
    assert all(float(r["deviation"]) < sector_numeric.TOLERANCE for r in out["rows"][1:])


@pytest.mark.parametrize("argv", [["--crease", "1"], ["--crease", "2", "--scheme", "loop-blz"], ["--corner"]])
def test_polylines_of_every_sector_kind_agree_past_64_faces(capsys, argv):
    """A one-face sector (no interior edge: no a-polyline) included."""
    assert main(["check", "--k", "65", *argv, "--json", "--quiet", "--jobs", "1"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    assert row["compared"] == "polylines" and row["status"] == "agree" and float(row["deviation"]) < 1e-12


def test_the_polylines_see_a_block_that_is_not_the_matrixs(monkeypatch):
    """The polylines' block read from the plain edge rule where BLZ's modified one acts: the check sees it."""
    vertex = sd.SharpVertex.boundary(80, sd.QUAD)
    assert sector_numeric.polyline_deviation(CC_BLZ, vertex) < 1e-12
    real = sector_numeric._block_function
    monkeypatch.setattr(sector_numeric, "_block_function", lambda scheme, modified: real(CC, modified))
    assert sector_numeric.polyline_deviation(CC_BLZ, vertex) > 1e-3


@pytest.mark.slow
@pytest.mark.parametrize("scheme", ["catmull-clark", "loop-blz"])
def test_ten_thousand_faces_are_proved(capsys, scheme):
    assert main(["check", "--k", "10000", "--boundary", "--certify", "--scheme", scheme, "--json", "--quiet"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    lattice = sd.QUAD if scheme == "catmull-clark" else sd.TRIANGLE
    assert row["route"] == "structural" and row["status"] == "agree"
    assert sum(row["multiplicities"]) == sd.SharpVertex.boundary(10000, lattice).one_ring_size()
