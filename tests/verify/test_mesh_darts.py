"""verify/mesh_verdicts.py at darts: a tagged mesh's dart vertices get a computed C1 verdict (``inspect --json``).

A semi-sharp dart is smooth once its sharpness has decayed, so its verdict is Reif's test at its valence; an infinitely
sharp dart's verdict comes from Reif's test on its closed fan (``verify/c1_closed_fan.py``): the exact spectrum of its 1-ring
matrix, checked here against sympy's own eigenvectors of the matrix built by exact refinement, then the map."""

import json
from fractions import Fraction

import sympy as sp

from symdecomp.analysis.mesh_kinds import NeighbourhoodKind
from symdecomp.cli import main
from symdecomp.schemes.lattice import QUAD
from symdecomp.schemes.meshformats import encode_mesh
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex, exact_sharp_matrix
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_closed_fan import c1_dart_test
from symdecomp.verify.mesh_verdicts import kind_verdict
from tests.analysis.test_mesh_limits import grid, idx


def tagged_obj(tmp_path, sharpness: str):
    """The 5 x 5 grid of quads with one tagged edge inside, (1,2)-(2,2): both ends are darts of valence 4."""
    path = tmp_path / "dart.obj"
    path.write_bytes(encode_mesh(grid(), "obj") + f"t crease 2/1/0 {idx(1, 2)} {idx(2, 2)} {sharpness}\n".encode())
    return path


def inspect_json(path, capsys) -> dict:
    status = main(["inspect", str(path), "--json", "--quiet"])
    data = json.loads(capsys.readouterr().out)
    assert status == data["exit_status"] == 0
    return data


def test_a_semi_sharp_dart_gets_reif_s_verdict_at_its_valence(tmp_path, capsys):
    data = inspect_json(tagged_obj(tmp_path, "1.5"), capsys)
    darts = [k for k in data["kinds"] if k["kind"].startswith("dart")]
    interior = c1_test(catmull_clark(), 4)
    assert [(k["count"], k["c1"]) for k in darts] == [(2, interior.verdict.value)] and interior.verdict.value == "c1"
    verdict = kind_verdict(catmull_clark(), NeighbourhoodKind("dart", 4, (4,), True, sharpness=Fraction(3, 2)))
    assert verdict.c1_reason.startswith("semi-sharp dart (sharpness 3/2): smooth from level 2 on")
    assert verdict.c1_reason.endswith(interior.reason) and verdict.regime == "bounded"  # the regime of smooth n = 4


def test_an_infinitely_sharp_dart_s_spectral_facts_are_the_matrix_s(tmp_path, capsys):
    """Catmull-Clark's dart of valence 4: 1 simple, then 1/2 twice with two eigenvectors (non-defective), every other
    eigenvalue of modulus below 1/2 (sympy on the exact matrix); the characteristic map is regular and winds once: c1."""
    data = inspect_json(tagged_obj(tmp_path, "10"), capsys)
    (dart,) = [k for k in data["kinds"] if k["kind"].startswith("dart")]
    direct = c1_dart_test(catmull_clark(), 4)
    assert (dart["count"], dart["c1"]) == (2, direct.verdict.value) and direct.verdict.value == "c1"
    reason = kind_verdict(catmull_clark(), NeighbourhoodKind("dart", 4, (4,), True)).c1_reason
    assert "lambda_1 = 0.5, lambda_2 = 0.5 real, positive, strictly dominant" in reason and reason == direct.reason
    assert reason.endswith("its ring winds once around O: injective")
    S = sp.Matrix(exact_sharp_matrix(catmull_clark(), SharpVertex.dart(4, QUAD)).tolist())
    half = sp.Rational(1, 2)
    assert len((S - half * sp.eye(S.rows)).nullspace()) == 2 and len((S - sp.eye(S.rows)).nullspace()) == 1
    x = sp.Symbol("x")
    rest, remainder = sp.div(S.charpoly(x).as_expr(), (x - 1) * (x - half) ** 2, x)
    assert remainder == 0 and rest.subs(x, half) != 0  # 1/2 exactly twice
    factors = [f for f, _ in sp.factor_list(rest, x)[1]]  # irreducible, so their roots are simple
    assert all(abs(complex(r)) < 0.5 - 1e-3 for f in factors for r in sp.Poly(f, x).nroots(n=30))
