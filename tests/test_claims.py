"""The registry: every claim of Sections 2-5.1 is checked, with the status the mathematics gives."""

import json

import pytest
import sympy as sp

from symdecomp.claims import CheckResult, Status, all_claims, check_claim
from symdecomp.cli import main

# What the checks establish about the paper (a change here is a change in the mathematics, reviewed).
EXPECTED = {
    "Eq. 2-4": Status.PROVED,
    "Eq. 5": Status.PROVED,
    "Eq. 6": Status.PROVED,
    "Proposition 2.1": Status.PROVED,
    "Eq. 10-11": Status.PROVED,
    "Eq. 12-13": Status.PROVED,
    "Eq. 14-15": Status.PROVED,
    "Eq. 16": Status.CORRECTED,
    "Eq. 17-21": Status.PROVED,
    "Proposition 4.1": Status.PROVED,
    "Proposition 4.2": Status.PROVED,
    "Proposition 4.3": Status.PROVED,
    "Eq. 24": Status.PROVED,
    "Eq. 25-30": Status.PROVED,
    "Eq. 31-32": Status.PROVED,
    "Eq. 33": Status.PROVED,
    "Eq. 34": Status.PROVED,
    "Eq. 35-37": Status.CORRECTED,
    "Eq. 38": Status.CORRECTED,
    "Proposition 5.1": Status.VERIFIED,
    "Remark 5.1": Status.REFUTED,
    "Eq. 39": Status.CORRECTED,
    "Eq. 39 (n = 4)": Status.VERIFIED,
    "Eq. 39 (n → ∞)": Status.PROVED,
    "C1 (Reif's test)": Status.VERIFIED,
}


@pytest.mark.parametrize("label", sorted(EXPECTED))
def test_status(label):
    result = check_claim(label)
    assert result.status is EXPECTED[label], result.evidence
    assert result.evidence
    for step in result.steps:
        if step.expr is not None:
            sp.latex(step.expr)  # every displayed step is printable by sympy


def test_every_claim_of_sections_2_to_5_1_is_registered():
    labels = {c.label for c in all_claims() if c.section in {"2", "4", "5.1"}}
    assert labels == set(EXPECTED)


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
    assert by_label["Proposition 5.1"]["valences"] == [3, 1000]
    for r in rows:
        assert {"label", "status", "evidence"} <= set(r)


def test_claims_command_unknown_label(capsys):
    assert main(["claims", "--label", "Eq. 99"]) == 2
    assert "no claim labelled Eq. 99" in capsys.readouterr().err


def test_prop51_check_can_fail(monkeypatch):
    # with the vertex held fixed (alpha = beta = 0) an Eq. 43 eigenvalue exceeds lambda_1 at n = 3
    from symdecomp.claims import s5_1_tangent
    from symdecomp.schemes.scheme import catmull_clark

    monkeypatch.setattr(s5_1_tangent, "_cc", lambda: catmull_clark(0, 0))
    result = s5_1_tangent._prop51()
    assert result.status is Status.REFUTED and str(result.counterexample) == "n = 3"
