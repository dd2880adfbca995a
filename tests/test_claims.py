"""The registry: result invariants, the claims command (statuses: tests/test_claim_statuses.py)."""

import json

import pytest

from symdecomp.claims import CheckResult, Status, check_claim
from symdecomp.cli import main


def test_result_invariants():
    with pytest.raises(ValueError, match="counterexample"):
        CheckResult(Status.REFUTED, "x")
    with pytest.raises(ValueError, match="corrected statement"):
        CheckResult(Status.CORRECTED, "x")
    with pytest.raises(ValueError, match="digits"):
        CheckResult(Status.NUMERIC, "x")
    with pytest.raises(ValueError, match="range of valences"):
        CheckResult(Status.VERIFIED, "x")


def test_claims_command_json(capsys):
    assert main(["claims", "--json", "--section", "5.1"]) == 0
    rows = json.loads(capsys.readouterr().out)
    by_label = {r["label"]: r for r in rows}
    section_51 = {"Eq. 25-30", "Eq. 31-32", "Eq. 33", "Eq. 34", "Eq. 35-37", "Eq. 38", "Proposition 5.1"}
    section_51 |= {"Remark 5.1", "Eq. 39", "Eq. 39 (n = 4)", "Eq. 39 (n → ∞)", "C1 (Reif's test)"}
    assert set(by_label) == section_51
    assert by_label["Remark 5.1"]["status"] == "refuted" and "counterexample" in by_label["Remark 5.1"]
    assert by_label["Proposition 5.1"]["status"] == "proved"  # certified range plus the exact tail bound
    for r in rows:
        assert {"label", "status", "evidence"} <= set(r)


def test_claims_command_unknown_label(capsys):
    assert main(["claims", "--label", "Eq. 99"]) == 2
    assert "no claim labelled Eq. 99" in capsys.readouterr().err


def test_prop51_check_can_fail():
    # with the vertex held fixed (alpha = beta = 0) an Eq. 43 eigenvalue exceeds lambda_1 at n = 3
    from symdecomp.schemes.scheme import catmull_clark

    result = check_claim("Proposition 5.1", catmull_clark(0, 0))
    assert result.status is Status.REFUTED and "n = 3" in str(result.counterexample)
