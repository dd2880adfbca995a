"""Claims checked on the shared pool: the same verdicts and words as checked one by one here."""

from __future__ import annotations

import pytest

from symdecomp.claims import check_claim
from symdecomp.claims.batch import check_claims
from symdecomp.errors import InvalidInputError

#: Claims whose words hold unevaluated relations (``d >= 1``, ``cos(2 pi/3) = -cos(pi/3)``): unpickled as sympy
#: objects they would read ``True``.
LABELS = ["Eq. 1", "Eq. 35-37", "Section 5.3: smaller eigenvalues", "Eq. 34"]


def test_pool_gives_the_words_and_verdicts_of_the_sequential_run():
    pooled = list(check_claims(LABELS, jobs=2))
    for label, r in zip(LABELS, pooled):
        here = check_claim(label)
        assert (r.status, r.scope, r.scope_text) == (here.status, here.scope, here.scope_text)
        assert str(r.evidence) == str(here.evidence) and " True" not in str(r.counterexample or "")
        assert str(r.counterexample) == str(here.counterexample) and str(r.correction) == str(here.correction)
        assert r.steps == ()


def test_one_job_is_check_claim_itself():
    assert list(check_claims(["Eq. 34"], jobs=1)) == [check_claim("Eq. 34")]


def test_an_unknown_label_is_refused_before_any_work():
    with pytest.raises(InvalidInputError, match="no claim labelled 'Eq. 999'"):
        list(check_claims(["Eq. 34", "Eq. 999"], jobs=2))


def test_the_command_prints_the_same_table_on_the_pool(capsys):
    import json

    from symdecomp.cli import main

    tables = []
    for jobs in ("1", "2"):
        assert main(["claims", "--section", "5.3", "--json", "--jobs", jobs]) == 0
        tables.append(json.loads(capsys.readouterr().out)["rows"])
    assert tables[0] == tables[1] and len(tables[0]) >= 2
    assert all(" True" not in row.get("counterexample", "") for row in tables[1])
