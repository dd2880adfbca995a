"""``symdecomp check --k A:B --boundary --certify``: the mirror decomposition proved against the refined matrix."""

from __future__ import annotations

import json

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis import mirror_threshold
from symdecomp.cli import main
from symdecomp.schemes.files import load_scheme


def _rows(capsys, argv):
    code = main(argv + ["--json"])
    return code, json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("scheme", [pytest.param("catmull-clark", marks=pytest.mark.slow), "loop"])
def test_boundary_vertices_k_1_to_16_are_proved(capsys, scheme):
    code, out = _rows(capsys, ["check", "--k", "1:16", "--boundary", "--certify", "--scheme", scheme])
    assert code == 0 and out["summary"]["ok"] and out["summary"]["agree"] == 16
    for row in out["rows"]:
        assert row["status"] == "agree" and row["route"] == "charpoly" and row["multiplicities_certified"]
        vertex = (sd.SharpVertex.boundary(row["n"], sd.QUAD if scheme == "catmull-clark" else sd.TRIANGLE))
        chi = sd.exact_sharp_matrix(sd.catmull_clark() if scheme == "catmull-clark" else sd.loop(), vertex).charpoly()
        # the distinct count is the squarefree part's degree; the multiplicities add up to the degree
        assert row["distinct"] == sum(f.degree() for f, _ in chi.factor()[1])
        assert sum(row["multiplicities"]) == chi.degree()


@pytest.mark.parametrize("argv", [["--corner"], ["--crease", "3"], ["--dart"]])
def test_corners_creases_and_darts_are_proved(capsys, argv):
    code, out = _rows(capsys, ["check", "--k", "3:6", "--certify"] + argv)
    assert code == 0 and [r["status"] for r in out["rows"]] == ["agree"] * 4


def test_a_wrong_sine_part_is_refuted_exactly(capsys, monkeypatch):
    real = mirror_threshold.sine_part

    def shifted(scheme, k, rules=None, *, dart=False):  # one block's eigenvalue moved by 1/1024
        p = real(scheme, k, rules, dart=dart)
        x = mirror_threshold.X
        return sp.Poly(p.as_expr().subs(x, x + sp.Rational(1, 1024)), x)

    monkeypatch.setattr(mirror_threshold, "sine_part", shifted)
    code, out = _rows(capsys, ["check", "--k", "4", "--boundary", "--certify"])
    assert code == 1 and out["rows"][0]["status"] == "disagree"
    assert "refuted: chi_S = " in out["rows"][0]["message"]


def test_text_rows_look_like_the_interior_check(capsys):
    assert main(["check", "--k", "3:4", "--boundary", "--certify", "--scheme", "loop"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith("loop: mirror decomposition vs full matrix, certified (exact)")
    assert lines[1].split()[:4] == ["K", "status", "distinct", "mult."]
    assert lines[2].split()[:2] == ["3", "agree"] and lines[-1].startswith("2 vertices: 2 agree")


def test_numeric_mode_compares_the_blocks_with_the_matrix_on_the_pool(capsys):
    assert main(["check", "--k", "1:6", "--corner", "--scheme", "loop-blz", "--jobs", "2", "--dps", "30", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["summary"]["mode"] == "numeric" and out["summary"]["ok"] and out["summary"]["sectors"] == 6
    assert [r["k"] for r in out["rows"]] == [1, 2, 3, 4, 5, 6] and all(r["status"] == "agree" for r in out["rows"])
    assert [r["size"] for r in out["rows"]] == [k + 2 for k in range(1, 7)]  # O, a_0..a_k on triangles


def test_numeric_mode_finds_a_wrong_block(monkeypatch, capsys):
    """The matrix is built without the blocks: spoil the blocks and the numeric check says where."""
    from symdecomp.analysis import block_values

    real = block_values.eval_arb
    monkeypatch.setattr(block_values, "eval_arb", lambda terms, c, ck: real(terms, c, ck) * 1.001)
    assert main(["check", "--k", "4", "--boundary", "--jobs", "1"]) == 1
    out = capsys.readouterr().out
    assert "disagree" in out and "is no block's value to 25 digits" in out


@pytest.mark.parametrize("argv, words", [
    (["check"], "required"),
    (["check", "--k", "3", "--dart"], "a dart's symmetric part is not a small block"),
    (["check", "--k", "3", "--boundary", "--solver", "flint"], "--solver applies to interior valences (--n)"),
    (["check", "--k", "3", "--certify"], "give --boundary, --corner, --crease K2 or --dart"),
    (["check", "--n", "3", "--boundary", "--certify"], "--k A:B"),
    (["check", "--n", "3", "--k", "3"], "not allowed with argument"),
    (["check", "--k", "0:3", "--boundary", "--certify"], "--k"),
    (["check", "--k", "3:10001", "--boundary", "--certify"], "expected face counts <= 10000, got 10001"),
    (["check", "--k", "65", "--dart", "--certify"], "the vertex has more than 64 faces"),
    (["check", "--k", "70", "--boundary", "--certify", "--route", "charpoly"], "--route charpoly: boundary k=70 has 70 "
     "faces; the dense route reads at most 64"),
    (["check", "--k", "5", "--dart", "--certify", "--route", "structural"], "--route structural: dart n=5: the "
     "structural route reads boundary, crease and corner vertices"),
    (["check", "--k", "20", "--boundary", "--route", "structural"], "--route: give it with --certify"),
    (["check", "--k", "20", "--boundary", "--certify", "--dps", "30"], "the certified check is exact"),
    (["check", "--k", "20", "--boundary", "--certify", "--route", "charpoly", "--structural"], "--structural is --route"),
    (["check", "--k", "5:3", "--boundary", "--certify"], "empty range"),
    (["check", "--k", "3", "--boundary", "--certify", "--rings", "2"], "--rings: not available"),
    (["check", "--k", "3", "--crease", "3", "--sharpness", "1", "--certify"], "semi-sharp"),
])
def test_check_bad_input(capsys, argv, words):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1


def test_a_users_rational_sharp_rules_from_a_file(capsys, tmp_path):
    path = tmp_path / "soft-crease.toml"
    path.write_text('name = "soft-crease"\n[edge]\nO = "3/8"\na = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }\n'
                    'b = { "-1" = "1/16", "0" = "1/16" }\n[face]\nO = "1/4"\na = { "0" = "1/4", "1" = "1/4" }\n'
                    'b = { "0" = "1/4" }\n[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n'
                    '[sharp]\ncrease_centre = "5/8"\ncrease_end = "3/16"\ncrease_edge = "1/2"\n')
    code, out = _rows(capsys, ["check", "--k", "2:6", "--boundary", "--certify", "--scheme", str(path)])
    assert code == 0 and out["summary"]["agree"] == 5
    assert main(["spectrum", "3", "--boundary", "--scheme", str(path), "--json"]) == 0
    crease = [e for e in json.loads(capsys.readouterr().out)["levels"][0]["eigenvalues"] if "crease" in e["blocks"]]
    # the crease block [[c, e, e], [h, 1 - h, 0], [h, 0, 1 - h]] has the eigenvalues 1, 1 - h and, by its trace,
    # c + 2 (1 - h) - 1 - (1 - h) = c - h: here 5/8 - 1/2
    rules = load_scheme(str(path)).sharp
    c, h = rules.crease_centre, rules.crease_edge
    assert sorted(sp.Rational(e["exact"]) for e in crease) == sorted([sp.Integer(1), 1 - h, c - h])
