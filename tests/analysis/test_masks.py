"""Limit masks: left eigenvectors of the exact subdivision matrix, closed forms in n."""

import json

import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.masks import check_masks_exactly, limit_masks
from symdecomp.cli import main
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import n as N

CC = catmull_clark()


def test_position_mask_closed_form():
    m = limit_masks(CC)
    assert [sp.simplify(a - b) for a, b in zip(m.position, (N / (N + 5), 4 / (N * (N + 5)), 1 / (N * (N + 5))))] == [0, 0, 0]
    # weights sum to 1 for every n
    assert sp.simplify(m.position[0] + N * m.position[1] + N * m.position[2] - 1) == 0


@pytest.mark.parametrize("n", list(range(3, 21)) + [31, 50])
def test_masks_are_exact_left_eigenvectors(n):
    assert check_masks_exactly(CC, n) == (True, True, True)


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 51))
def test_masks_are_exact_left_eigenvectors_all_valences(n):
    assert check_masks_exactly(CC, n) == (True, True, True)


def _residual(mask_json, n, value, dps=30):
    S = subdivision_matrix(CC, n)
    with mpmath.workdps(dps):
        w = [mpmath.mpf(mask_json["O"])] + [mpmath.mpf(x) for x in mask_json["a"]] + [mpmath.mpf(x) for x in mask_json["b"]]
        lam = mpmath.mpf(value)
        worst = mpmath.mpf(0)
        for col in range(2 * n + 1):
            acc = sum(w[r] * (mpmath.mpf(S[r, col].p) / S[r, col].q) for r in range(2 * n + 1) if S[r, col] != 0)
            worst = max(worst, abs(acc - lam * w[col]))
        return worst


@pytest.mark.parametrize("n", [3, 4, 7, 50])
def test_cli_masks_json_satisfies_the_eigen_equations(n, capsys):
    assert main(["masks", str(n), "--json", "--digits", "30"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert list(data)[3:] == ["n", "position", "tangents", "subdominant", "lambda_1_subdominant", "subdominance"] and data["n"] == n
    assert data["lambda_1_subdominant"] is True
    assert len(data["tangents"]) == 2
    for mask in [data["position"], *data["tangents"]]:
        assert list(mask) == ["O", "a", "b"] and len(mask["a"]) == n and len(mask["b"]) == n
        assert all(isinstance(x, str) for x in mask["a"] + mask["b"] + [mask["O"]])
    assert _residual(data["position"], n, 1) < 1e-25
    for t in data["tangents"]:
        assert _residual(t, n, data["subdominant"]) < 1e-25
    with mpmath.workdps(30):
        total = mpmath.mpf(data["position"]["O"]) + sum(mpmath.mpf(x) for x in data["position"]["a"] + data["position"]["b"])
        assert abs(total - 1) < 1e-25


def test_the_residual_check_can_fail(capsys):
    # A tangent mask with the wrong b-scaling is not a left eigenvector.
    assert main(["masks", "5", "--json", "--digits", "30"]) == 0
    data = json.loads(capsys.readouterr().out)
    bad = dict(data["tangents"][0])
    bad["b"] = [str(2 * mpmath.mpf(x)) for x in bad["b"]]
    assert _residual(bad, 5, data["subdominant"]) > 1e-3


def test_cli_masks_text_and_bad_valence(capsys):
    assert main(["masks", "5", "--digits", "8"]) == 0
    out = capsys.readouterr().out
    assert "n/(n + 5)" in out and "tangent 2" in out
    assert main(["masks", "1"]) == 2


def test_the_exact_check_can_fail(monkeypatch):
    import symdecomp.analysis.masks as masks_module
    from symdecomp.analysis.frequency import CirculantBlocks, circulant_blocks

    real = circulant_blocks(CC)
    wrong = CirculantBlocks(real.aa, {k: 2 * w for k, w in real.ab.items()}, real.ba, real.bb)
    monkeypatch.setattr(masks_module, "circulant_blocks", lambda scheme: wrong)
    masks_module.limit_masks.cache_clear()
    try:
        assert check_masks_exactly(CC, 5) == (True, False, False)
    finally:
        masks_module.limit_masks.cache_clear()
