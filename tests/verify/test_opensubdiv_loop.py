"""OpenSubdiv's Loop scheme against the toolkit (skipped where OpenSubdiv is not installed).

As for Catmull-Clark (tests/verify/test_opensubdiv.py) a failing build is an error, not a skip.
"""

import pytest

from symdecomp.verify.opensubdiv import build as osd_build

if not osd_build.headers_present():
    pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed", allow_module_level=True)

import numpy as np  # noqa: E402

from symdecomp.analysis.masks import ring_masks  # noqa: E402
from symdecomp.schemes.loop import loop  # noqa: E402
from symdecomp.schemes.rings import ring_subdivision_matrix  # noqa: E402
from symdecomp.verify.opensubdiv.loop import osd_loop_one_ring_matrix, osd_loop_position_mask, osd_loop_tangent_masks  # noqa: E402


@pytest.mark.parametrize("n", range(3, 13))
def test_loop_one_step_matrix_and_limit_mask_match_opensubdiv(n):
    exact = ring_subdivision_matrix(loop(), n, 1).exact_matrix()
    osd = osd_loop_one_ring_matrix(n)
    assert max(abs(osd[r][c] - float(exact[r, c])) for r in range(n + 1) for c in range(n + 1)) < 1e-15
    masks = ring_masks(loop(), n, 1, digits=20)
    ours = [float(masks["position"]["O"])] + [float(x) for x in masks["position"]["a"]]
    assert max(abs(a - b) for a, b in zip(osd_loop_position_mask(n), ours)) < 1e-15


@pytest.mark.parametrize("n", range(3, 13))
def test_loop_tangent_masks_span_opensubdiv_tangents(n):
    masks = ring_masks(loop(), n, 1, digits=20)
    ours = np.array([[float(m["O"])] + [float(x) for x in m["a"]] for m in masks["tangents"]])
    theirs = np.array(osd_loop_tangent_masks(n))
    # OpenSubdiv's tangents are a basis of the same plane: solve theirs = C ours, residual ~ 0
    C, *_ = np.linalg.lstsq(ours.T, theirs.T, rcond=None)
    assert np.abs(ours.T @ C - theirs.T).max() < 1e-13 * max(1.0, np.abs(theirs).max())
    assert abs(np.linalg.det(C)) > 1e-8  # and they span it (two independent tangents)


@pytest.mark.parametrize("n", range(3, 13))
def test_the_loop_oracle_agrees_row_by_row(n):
    from symdecomp.verify.oracle import compare_loop_with_opensubdiv

    result = compare_loop_with_opensubdiv(n, levels=16)
    names = [p.name for p in result.predictions]
    assert {"one-step matrix", "spectrum", "limit mask", "tangent plane", "limit position"} <= set(names)
    assert [x for x in names if x.startswith("shrink rate")] == [f"shrink rate j={j}" for j in range(n // 2 + 1)]
    assert result.agrees, [p for p in result.predictions if not p.agrees]


def test_the_loop_oracle_catches_a_wrong_vertex_weight(monkeypatch):
    """Predicting with Warren's weight (equal to Loop's only at n = 3 and 6) flips the rows it enters."""
    import symdecomp.verify.oracle as oracle
    from symdecomp.schemes.loop import loop_warren

    monkeypatch.setattr(oracle, "loop", loop_warren)
    wrong = {p.name: p.agrees for p in oracle.compare_loop_with_opensubdiv(5, levels=16).predictions}
    assert not wrong["one-step matrix"] and not wrong["spectrum"] and not wrong["limit mask"] and not wrong["shrink rate j=0"]
    assert wrong["shrink rate j=1"] and wrong["shrink rate j=2"]  # the edge rule is Loop's: other frequencies agree
    assert oracle.compare_loop_with_opensubdiv(6, levels=16).agrees  # Warren's weight is Loop's at n = 6


def test_oracle_command_for_loop(capsys):
    from symdecomp.cli import main

    assert main(["oracle", "--scheme", "loop", "--n", "5:6", "--levels", "12", "--json"]) == 0
    import json

    data = json.loads(capsys.readouterr().out)["rows"]
    assert [r["n"] for r in data] == [5, 6] and all(r["agrees"] for r in data)
