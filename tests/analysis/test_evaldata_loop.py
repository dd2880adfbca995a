"""Loop's eigen-data: the (N+6)-point patch matrix, its certified eigenstructure, the evaluator, the JSON file."""

from __future__ import annotations

import json
import random
from fractions import Fraction

import flint
import mpmath
import numpy as np
import pytest
import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic, to_acb
from symdecomp.analysis.eigendata import certified_eigendata, patch_eigendata
from symdecomp.analysis.evaluation import EvaluationError, PatchEvaluator
from symdecomp.analysis.regular_basis import box_basis
from symdecomp.cli import main
from symdecomp.output.evaldata import read_json
from symdecomp.schemes.box_spline import BOX_POINTS, LATTICE_RAYS, regular_patch
from symdecomp.schemes.loop import loop
from symdecomp.schemes.patch import TRIANGLE_OUTER_POINTS as OUTER_POINTS
from symdecomp.schemes.patch import patch_matrices
from symdecomp.verify.patch_eval import exact_to_mpf, triangle_dyadic_limits

LOOP = loop()


def _random_values(seed):
    rnd = random.Random(seed)
    return lambda s, u, v: tuple(Fraction(rnd.randint(-1000, 1000), 997) for _ in range(3))


def _arb_matrix(p) -> flint.arb_mat:
    with flint.ctx.workprec(256):
        return flint.arb_mat([[to_acb(w, 256).real if isinstance(w, Cyclotomic) else flint.arb(flint.fmpq(w.numerator, w.denominator))
                               for w in (p.sparse[i].get(j, Fraction(0)) for j in range(p.size))] for i in range(p.size)])


# --- the matrix ---------------------------------------------------------------------------------


@pytest.mark.parametrize("n", [3, 5, 7])
def test_patch_matrix_rows_are_affine_and_block_triangular(n):
    p = patch_matrices(LOOP, n)
    assert p.size == n + 6 and len(p.sparse) == n + 12
    assert all(sum(row.values(), Fraction(0)) == 1 for row in p.sparse)  # exact, cyclotomic centre row included
    assert all(c <= n for row in p.sparse[: n + 1] for c in row)  # the 1-ring never sees the outer points
    assert isinstance(p.sparse[0][0], Cyclotomic if n in (5, 7) else Fraction)


def test_n3_is_defective_and_the_data_has_its_jordan_pair():
    p = patch_matrices(LOOP, 3)
    A = sp.Matrix(p.size, p.size, lambda i, j: sp.Rational(str(p.sparse[i].get(j, 0))))
    assert not A.is_diagonalizable()
    data = patch_eigendata(LOOP, 3, 256)
    assert [(i, c) for i, c, _ in data.jordan] == [(4, 1), (5, 1)]
    with flint.ctx.workprec(256):
        J = flint.arb_mat(p.size, p.size)
        for i, lam in enumerate(data.values):
            J[i, i] = lam
        for i, c, g in data.jordan:
            J[i, c] = g
        residual = _arb_matrix(p) * data.vectors - data.vectors * J
        assert all(residual[i, j].contains(0) and residual[i, j].rad() < 1e-60 for i in range(p.size) for j in range(p.size))


@pytest.mark.parametrize("n", [4, 7, 12])
def test_certified_eigenvectors(n):
    p = patch_matrices(LOOP, n)
    data = patch_eigendata(LOOP, n, 256)
    assert data.jordan == ()
    with flint.ctx.workprec(256):
        V = data.vectors
        AV = _arb_matrix(p) * V
        assert all((AV[i, j] - data.values[j] * V[i, j]).contains(0) for i in range(p.size) for j in range(p.size))
        identity = data.inverse * V
        assert all(identity[i, j].contains(int(i == j)) for i in range(p.size) for j in range(p.size))
    # the subdominant pair is Loop's 3/8 + cos(2 pi/n)/4
    with flint.ctx.workprec(256):
        assert (data.values[2] - flint.arb(3) / 8 - flint.arb.cos_pi_fmpq(flint.fmpq(2, n)) / 4).contains(0)
        assert data.values[2].rad() < 1e-60


# --- the evaluator ------------------------------------------------------------------------------


def test_regular_case_is_the_box_spline_patch():
    _, r = certified_eigendata(LOOP, 6)
    ev = PatchEvaluator.from_rounded(LOOP, r)
    index = {(0, 0): 0, **{ray: 1 + i for i, ray in enumerate(LATTICE_RAYS)}, **{q: 7 + i for i, q in enumerate(OUTER_POINTS)}}
    rng = np.random.default_rng(0)
    c = rng.normal(size=(12, 3))
    box = c[[index[q] for q in BOX_POINTS]]
    u, v = rng.random(400), rng.random(400)
    u, v = u[u + v <= 1], v[u + v <= 1]
    got = ev.evaluate(c, u, v)
    assert np.abs(got["point"] - np.array(regular_patch().basis(u, v)).T @ box).max() < 1e-14
    for key, (ds, dt) in {"du": (1, 0), "dv": (0, 1), "duv": (1, 1), "dvv": (0, 2)}.items():
        assert np.abs(got[key] - box_basis(u, v, ds, dt, float) @ box).max() < 1e-12, key


@pytest.mark.parametrize("n,level", [(3, 2), (5, 1), (7, 2)])
def test_dyadic_points_are_limit_positions(n, level):
    _check_dyadic(n, level)


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 13))
@pytest.mark.parametrize("level", [1, 2, 3, 4])
def test_dyadic_points_are_limit_positions_all(n, level):
    _check_dyadic(n, level)


def _check_dyadic(n, level):
    control, limits = triangle_dyadic_limits(LOOP, n, level, _random_values(100 * n + level))
    ev = PatchEvaluator.exact(LOOP, n, dps=40)
    with mpmath.workdps(50):
        c = np.array([[exact_to_mpf(x) for x in p] for p in control], dtype=object)
        keys = sorted(limits)
        assert len(keys) == (2**level + 1) * (2**level + 2) // 2
        u = [mpmath.mpf(a) / 2**level for a, _ in keys]
        v = [mpmath.mpf(b) / 2**level for _, b in keys]
        got = ev.evaluate(c, u, v)["point"]
        err = max(abs(got[i][j] - exact_to_mpf(limits[k][j])) for i, k in enumerate(keys) for j in range(3))
    assert err < mpmath.mpf(10) ** -30


def test_origin_gives_the_limit_point_and_tangent_plane():
    _, r = certified_eigendata(LOOP, 5)
    ev = PatchEvaluator.from_rounded(LOOP, r)
    c = np.random.default_rng(2).normal(size=(11, 3))
    at0, near = ev.evaluate(c, 0.0, 0.0), ev.evaluate(c, 1e-10, 1e-10)
    assert np.abs(at0["point"] - near["point"]).max() < 1e-6
    assert np.abs(at0["normal"] - near["normal"]).max() < 1e-4
    assert np.isnan(at0["du"]).all()
    with pytest.raises(EvaluationError, match="u \\+ v <= 1"):
        ev.evaluate(c, 0.7, 0.5)


def test_a_wrong_jordan_coupling_is_caught():
    # N = 3 without its Jordan pair is a different (wrong) surface: the exact limits tell
    control, limits = triangle_dyadic_limits(LOOP, 3, 2, _random_values(7))
    ev = PatchEvaluator.from_rounded(LOOP, certified_eigendata(LOOP, 3)[1])
    bad = PatchEvaluator(**{**ev.__dict__, "jordan": ()})
    c = np.array([[float(x) for x in p] for p in control])
    keys = sorted(limits)
    u, v = np.array([a / 4 for a, _ in keys]), np.array([b / 4 for _, b in keys])
    want = np.array([[float(x) for x in limits[k]] for k in keys])
    assert np.abs(ev.evaluate(c, u, v)["point"] - want).max() < 1e-14
    assert np.abs(bad.evaluate(c, u, v)["point"] - want).max() > 1e-6


# --- the file -----------------------------------------------------------------------------------


def test_cli_writes_loop_json_and_refuses_binary(tmp_path, capsys):
    js = tmp_path / "loop.json"
    assert main(["evaldata", "--scheme", "loop", "--n", "3:5", "--out", str(js), "--format", "json", "--digits", "30"]) == 0
    out = capsys.readouterr().out
    assert "not diagonalizable at N = 3:" in out  # said, not only stored
    doc = json.loads(js.read_text())
    assert doc["format"] == "stam-loop" and doc["scheme"] == "loop" and doc["nmax"] == 5
    assert len(doc["valences"][2]["inverse"]) == 11 * 11 and len(doc["valences"][2]["phi"][0]) == 11 * 12
    assert len(doc["valences"][0]["jordan"]) == 2 and doc["valences"][1]["jordan"] == []
    back = read_json(js)
    for n in (3, 4, 5):
        r = certified_eigendata(LOOP, n)[1]
        assert np.array_equal(back[n].values, r.values) and np.array_equal(back[n].inverse, r.inverse)
        assert np.array_equal(back[n].phi, r.phi) and [g for *_, g in back[n].jordan] == [g for *_, g in r.jordan]
    capsys.readouterr()
    assert main(["evaldata", "--scheme", "loop", "--n", "3:4", "--out", str(tmp_path / "x.dat")]) == 2
    err = capsys.readouterr().err
    assert "binary" in err and "--format json" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "x.dat").exists()
