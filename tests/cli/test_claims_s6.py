"""The Section 6 claims: each check runs, and the findings about the paper are as established."""

import json

from symdecomp.cli import main


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
