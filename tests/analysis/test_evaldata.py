"""Stam's eigen-data: the patch matrix, its certified eigenstructure, the file and the evaluator."""

from __future__ import annotations

import random
from fractions import Fraction

import flint
import mpmath
import numpy as np
import pytest

from symdecomp.analysis.eigendata import (
    NotDiagonalizableError,
    certified_eigendata,
    patch_eigendata,
    round_ball,
)
from symdecomp.analysis.evaluation import EvaluationError, PatchEvaluator
from symdecomp.analysis.regular_basis import bspline_basis
from symdecomp.cli import main
from symdecomp.cli.files import write_output_file
from symdecomp.output.evaldata import binary_bytes, read_binary
from symdecomp.schemes.mesh import InvalidMeshError, ring_mesh
from symdecomp.schemes.patch import OUTER_POINTS, lattice_index, patch_matrices
from symdecomp.schemes.refinement import refinement_matrix
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.patch_eval import dyadic_limits

CC = catmull_clark()


def _random_values(seed):
    rnd = random.Random(seed)
    return lambda s, u, v: tuple(Fraction(rnd.randint(-1000, 1000), 997) for _ in range(3))


# --- the matrix ---------------------------------------------------------------------------------


def test_refinement_matrix_refuses_points_outside_the_columns():
    mesh = ring_mesh(5, 2)
    o, a, b = mesh.one_ring(0)
    with pytest.raises(InvalidMeshError, match="outside the given columns"):
        refinement_matrix(mesh, CC, (o,) + a, [o])  # the vertex point also needs the b_i
    rows = refinement_matrix(mesh, CC, (o,) + a + b, [o])
    assert sum(rows[0].values()) == 1 and rows[0][0] == Fraction(1) - Fraction(7, 20)


@pytest.mark.parametrize("n", [3, 4, 7])
def test_patch_matrix_rows_are_affine_and_block_triangular(n):
    p = patch_matrices(CC, n)
    k0 = 2 * n + 1
    assert all(sum(row.values()) == 1 for row in p.sparse)
    assert all(c < k0 for row in p.sparse[:k0] for c in row)  # the 1-ring never sees the outer points


def test_regular_patch_matrix_is_the_bspline_refinement():
    # N = 4: the new point at lattice (2, 0) is the vertex point of e_2 (regular: 9/16, 3/32, 1/64).
    p = patch_matrices(CC, 4)
    row = p.sparse[lattice_index(4, (2, 0))]
    assert row[lattice_index(4, (1, 0))] == Fraction(9, 16)
    assert row[lattice_index(4, (0, 0))] == Fraction(3, 32) and row[lattice_index(4, (2, 1))] == Fraction(1, 64)


# --- the eigenstructure ---------------------------------------------------------------------------


@pytest.mark.parametrize("n", [3, 4, 5, 8, 12])
def test_eigendata_certified_against_the_full_matrix(n):
    data = patch_eigendata(CC, n, 160)
    with flint.ctx.workprec(160):
        a = flint.arb_mat(patch_matrices(CC, n).matrix)
        lam = flint.arb_mat(data.size, data.size)
        for i, x in enumerate(data.values):
            lam[i, i] = x
        residual = a * data.vectors - data.vectors * lam
        identity = data.inverse * data.vectors
        assert all(residual[i, j].contains(0) for i in range(data.size) for j in range(data.size))
        assert all(identity[i, j].contains(int(i == j)) for i in range(data.size) for j in range(data.size))
        # A wrong eigenvalue is caught: shift one and the residual no longer contains 0.
        lam[1, 1] += flint.arb(10) ** -30
        residual = a * data.vectors - data.vectors * lam
        assert not all(residual[i, 1].contains(0) for i in range(data.size))


def test_rounding_is_correct_or_refused():
    assert round_ball(flint.arb(1) / 3) is None  # 53 bits (the default context) cannot decide
    with flint.ctx.workprec(200):
        assert round_ball(flint.arb(1) / 3) == 1 / 3
        assert round_ball(flint.arb(2) ** -1100) == 0.0
        assert round_ball(flint.arb("0.5 +/- 1e-10")) is None
        # just above and below the midpoint between 1 and its successor: both sides decided
        assert round_ball(1 + flint.arb(2) ** -53 + flint.arb(2) ** -120) == 1 + 2**-52
        assert round_ball(1 + flint.arb(2) ** -53 - flint.arb(2) ** -120) == 1.0
        third = [round_ball(flint.arb(k) / 3) for k in range(1, 200)]
        assert third == [float(Fraction(k, 3)) for k in range(1, 200)]


def test_regular_spectrum_exact():
    _, r = certified_eigendata(CC, 4)
    assert sorted(r.values.tolist()) == sorted([1, 0.5, 0.5, 0.25, 0.25, 0.25] + [0.125] * 4 + [0.0625] * 3 + [2**-5] * 2 + [2**-6])


def test_defective_block_is_refused():
    from symdecomp.algebra.small_eigen import rational_eigen

    with pytest.raises(NotDiagonalizableError, match="multiplicity 2 but 1"):
        rational_eigen([[Fraction(1, 4), Fraction(1)], [Fraction(0), Fraction(1, 4)]])


# --- the evaluator --------------------------------------------------------------------------------


def _regular_control_grid():
    pts = {(0, 0): 0, (-1, 0): 1, (-1, 1): 2, (0, 1): 3, (1, 1): 4, (1, 0): 5, (1, -1): 6, (0, -1): 7, (-1, -1): 8}
    pts.update({p: 9 + i for i, p in enumerate(OUTER_POINTS)})
    return pts


def test_regular_case_is_the_bicubic_bspline_patch():
    _, r = certified_eigendata(CC, 4)
    ev = PatchEvaluator.from_rounded(CC, r)
    rng = np.random.default_rng(0)
    c = rng.normal(size=(16, 3))
    u, v = rng.random(200), rng.random(200)
    got = ev.evaluate(c, u, v)
    nu, nv = bspline_basis(u), bspline_basis(v)
    ref = sum(nu[a + 1][:, None] * nv[b + 1][:, None] * c[i] for (a, b), i in _regular_control_grid().items())
    assert np.abs(got["point"] - ref).max() < 1e-14
    du = sum(bspline_basis(u, 1)[a + 1][:, None] * nv[b + 1][:, None] * c[i] for (a, b), i in _regular_control_grid().items())
    assert np.abs(got["du"] - du).max() < 1e-13


@pytest.mark.parametrize("n,level", [(3, 1), (5, 2), (6, 1)])
def test_dyadic_points_are_limit_positions(n, level):
    _check_dyadic(n, level)


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 13))
@pytest.mark.parametrize("level", [1, 2, 3, 4])
def test_dyadic_points_are_limit_positions_all(n, level):
    _check_dyadic(n, level)


def _check_dyadic(n, level):
    control, limits = dyadic_limits(CC, n, level, _random_values(100 * n + level))
    ev = PatchEvaluator.exact(CC, n, dps=40)
    with mpmath.workdps(50):
        c = np.array([[mpmath.mpf(x.numerator) / x.denominator for x in p] for p in control], dtype=object)
        keys = sorted(limits)
        u = [mpmath.mpf(a) / 2**level for a, _ in keys]
        v = [mpmath.mpf(b) / 2**level for _, b in keys]
        got = ev.evaluate(c, u, v)["point"]
        err = max(abs(got[i][j] - mpmath.mpf(limits[k][j].numerator) / limits[k][j].denominator) for i, k in enumerate(keys) for j in range(3))
    assert err < mpmath.mpf(10) ** -30


def test_origin_gives_the_limit_point_and_tangent_plane():
    _, r = certified_eigendata(CC, 5)
    ev = PatchEvaluator.from_rounded(CC, r)
    c = np.random.default_rng(2).normal(size=(18, 3))
    at0 = ev.evaluate(c, 0.0, 0.0)
    near = ev.evaluate(c, 1e-10, 1e-10)
    assert np.abs(at0["point"] - near["point"]).max() < 1e-6
    assert np.abs(at0["normal"] - near["normal"]).max() < 1e-4
    assert np.isnan(at0["du"]).all()
    with pytest.raises(EvaluationError):
        ev.evaluate(c, 1.5, 0.2)


# --- the file ----------------------------------------------------------------------------------


def test_file_round_trip(tmp_path):
    rounded = [certified_eigendata(CC, n)[1] for n in range(3, 7)]
    path = tmp_path / "cc.dat"
    write_output_file(path, binary_bytes(rounded))
    back = read_binary(path)
    assert sorted(back) == [3, 4, 5, 6]
    for r in rounded:
        b = back[r.n]
        assert np.array_equal(b.values, r.values) and np.array_equal(b.inverse, r.inverse) and np.array_equal(b.phi, r.phi)
    # the bytes as a reader of the published file sees them: Nmax, then val[K] of N = 3
    raw = path.read_bytes()
    assert int.from_bytes(raw[:4], "little") == 6
    assert np.frombuffer(raw, "<f8", 14, 4).tolist() == rounded[0].values.tolist()
    # every float is the correctly rounded exact value: compare with the balls
    data, r = certified_eigendata(CC, 5)
    assert all(round_ball(x) == y for x, y in zip(data.inverse.entries(), r.inverse.ravel()))


def test_cli_writes_binary_and_json(tmp_path, capsys):
    out = tmp_path / "cc.dat"
    assert main(["evaldata", "--n", "3:5", "--out", str(out), "--json"]) == 0
    assert read_binary(out)[5].values.size == 18
    js = tmp_path / "cc.json"
    assert main(["evaldata", "--n", "3:4", "--out", str(js), "--format", "json", "--digits", "40"]) == 0
    import json

    doc = json.loads(js.read_text())
    assert doc["nmax"] == 4 and len(doc["valences"][1]["inverse"]) == 16 * 16
    exact = read_binary(out)[4]
    assert [float(x) for x in doc["valences"][1]["values"]] == exact.values.tolist()


def test_cli_errors(tmp_path, capsys):
    assert main(["evaldata", "--n", "4:6", "--out", str(tmp_path / "x")]) == 2
    assert "3..N" in capsys.readouterr().err
    assert main(["evaldata", "--n", "3:4", "--out", str(tmp_path / "no" / "x")]) == 2
    assert "parent directory" in (err := capsys.readouterr().err) and "does not exist" in err
    assert main(["evaldata", "--n", "3:x", "--out", "x"]) == 2
    assert "argument --n" in capsys.readouterr().err
