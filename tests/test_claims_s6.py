"""The Section 6 claims: each check runs, and the findings about the paper are as established."""

import json

import pytest
import sympy as sp

from symdecomp.claims import Status, all_claims, check_claim
from symdecomp.cli import main

EXPECTED = {
    "Proposition 6.1": Status.CORRECTED,  # index range 0<i,j<n-1 as printed
    "Proposition 6.2": Status.CORRECTED,  # same index range
    "Eq. 47": Status.CORRECTED,  # C_{1,n-1} in the first row
    "Eq. 48": Status.CORRECTED,  # e_{1,n-1} in the first row
    "Eq. 49": Status.PROVED,
    "Eq. 50": Status.PROVED,
    "Remark 6.1": Status.PROVED,
    "Proposition 6.3": Status.CORRECTED,  # t_ij = m a_ij, eigenvalues not eigenvectors, no diagonalizability needed
    "Eq. 51": Status.PROVED,
    "S' (after Eq. 51)": Status.PROVED,
    "Tuning weights (after Eq. 51)": Status.PROVED,
    "Tangent plane unaffected (after Eq. 51)": Status.CORRECTED,
    "Spectrum (Eq. 34, Eq. 43)": Status.VERIFIED,  # certified cross-check, n = 3..48
}


def test_every_section6_claim_is_registered():
    labels = {c.label for c in all_claims() if c.section == "6"}
    assert labels == set(EXPECTED)


@pytest.mark.parametrize("label", sorted(EXPECTED))
def test_claim_status(label):
    result = check_claim(label)
    assert result.status is EXPECTED[label], result.evidence
    assert result.steps, "a check shows its derivation"
    if result.status is Status.CORRECTED:
        assert result.counterexample and result.correction
    for step in result.steps:
        for obj in (step.expr, step.lhs):
            if obj is not None:
                assert isinstance(obj, (sp.Basic, sp.MatrixBase))
                assert sp.latex(obj)


def test_cli_charpoly_json(capsys):
    assert main(["charpoly", "7", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["n"] == 7 and out["matches_matrix"] is True
    assert len(out["coefficients"]) == 16 and out["coefficients"][0] == "1"


def test_cli_charpoly_free_weights(capsys):
    assert main(["charpoly", "4", "--free-weights"]) == 0
    text = capsys.readouterr().out
    assert "alpha" in text and "yes" in text


def test_cli_charpoly_rejects_bad_valence(capsys):
    assert main(["charpoly", "2"]) == 2
    assert "valence" in capsys.readouterr().err
