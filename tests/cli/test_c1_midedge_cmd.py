"""``symdecomp c1 --scheme midedge`` and a user's Midedge file whose corner rule is perturbed in pentagons only."""

import json
import math

import pytest

from symdecomp.cli import main

VARIANT = """name = "midedge-variant"
mesh = "quad"
topology = "dual"
steps = 1
interpolatory = false
source = "Midedge with the own corner's weight a in a pentagon"

[[corner]]
terms = [
  {{walk = "", weight = "1/2 + KroneckerDelta(m, 5)*({a} - 1/2)"}},
  {{walk = "next", weight = "1/4 - KroneckerDelta(m, 5)*({a} - 1/2)/2"}},
  {{walk = "prev", weight = "1/4 - KroneckerDelta(m, 5)*({a} - 1/2)/2"}},
]
"""


def test_midedge_is_certified_from_4_by_reif_and_at_3_by_the_jordan_chains(capsys):
    assert main(["c1", "--scheme", "midedge", "--n", "3:6", "--json", "--quiet"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [(r["n"], r["verdict"]) for r in rows] == [(3, "c1"), (4, "c1"), (5, "c1"), (6, "c1")]
    for r in rows[1:]:  # 1/2 + cos(2 pi/n)/2 at frequency 1, a regular ring winding once
        assert abs(r["lambda"] - (1 + math.cos(2 * math.pi / r["n"])) / 2) < 1e-12 and r["frequency"] == 1
        assert r["winding_number"] == r["jacobian_sign"] == 1 and r["jacobian_lower_bound"] > 0
    assert rows[0]["reason"].startswith("the subdominant eigenvalue 0.25 is not a real double eigenvalue")
    # no eigenvector gives the zero function; the eigenvectors of 1/4's Jordan chains (frequencies 1, 2) map regularly, once
    assert "so every eigenvector counts" in rows[0]["reason"] and rows[0]["frequency"] == 1
    assert rows[0]["reason"].endswith("C1 for every net with c_x x c_y != 0 (almost every control net)")
    assert rows[0]["winding_number"] == rows[0]["jacobian_sign"] == 1 and rows[0]["jacobian_lower_bound"] > 0


@pytest.mark.parametrize("a, verdict", [("3/4", "c1"), ("9/10", "not-c1")])
def test_a_perturbed_pentagon_rule_changes_only_valence_5(a, verdict, tmp_path, capsys):
    path = tmp_path / "variant.toml"
    path.write_text(VARIANT.format(a=a))
    assert main(["c1", "--scheme", str(path), "--n", "4:6", "--json", "--quiet"]) == (0 if verdict == "c1" else 1)
    rows = {r["n"]: r for r in json.loads(capsys.readouterr().out)["rows"]}
    assert rows[4]["verdict"] == rows[6]["verdict"] == "c1" and abs(rows[6]["lambda"] - 0.75) < 1e-12
    assert rows[5]["verdict"] == verdict
    if verdict == "c1":  # the pentagon's circulant: a + (1 - a) cos(2 pi/5)
        assert abs(rows[5]["lambda"] - (0.75 + 0.25 * math.cos(2 * math.pi / 5))) < 1e-12
    else:
        assert rows[5]["reason"].startswith("the Jacobian of the characteristic map changes sign (the patch of vertex ")


TRIANGLE = """name = "midedge-triangle"
mesh = "quad"
topology = "dual"
steps = 1
interpolatory = false
source = "Midedge with the own corner's weight a in a triangle"

[[corner]]
terms = [
  {{walk = "", weight = "1/2 + KroneckerDelta(m, 3)*({a} - 1/2)"}},
  {{walk = "next", weight = "1/4 - KroneckerDelta(m, 3)*({a} - 1/2)/2"}},
  {{walk = "prev", weight = "1/4 - KroneckerDelta(m, 3)*({a} - 1/2)/2"}},
]
"""


@pytest.mark.parametrize("a, verdict", [("3/4", "c1"), ("2/5", "not-c1")])
def test_a_mutated_triangle_decides_valence_3(a, verdict, tmp_path, capsys):
    """The triangle's circulant puts a - (1 - a)/2 at frequencies 1, 2: 5/8 is subdominant and the map is certified; 1/5
    leaves 1/4 at frequencies 0, 1, 2 with six independent functions and no Jordan block."""
    path = tmp_path / "triangle.toml"
    path.write_text(TRIANGLE.format(a=a))
    assert main(["c1", "--scheme", str(path), "--n", "3", "--json", "--quiet"]) == (0 if verdict == "c1" else 1)
    (row,) = json.loads(capsys.readouterr().out)["rows"]
    assert row["verdict"] == verdict
    if verdict == "c1":
        assert abs(row["lambda"] - (0.75 - 0.25 / 2)) < 1e-12 and row["winding_number"] == row["jacobian_sign"] == 1
    else:
        assert "Jordan blocks: 2 of size 1" in row["reason"] and row["reason"].endswith("fail on the functions")


def test_the_method_line_names_each_route_with_its_valences(capsys):
    assert main(["c1", "--scheme", "midedge", "--n", "3:4", "--quiet"]) == 0
    method = capsys.readouterr().out.splitlines()[1]
    assert method.startswith("method: the spectrum on the functions of the four-direction patch")
    assert "winding once (n = 3); Reif's test on the characteristic map's ring" in method and method.endswith("(n = 4)")
