"""Claims checked on the shared pool: the same verdicts and words as checked one by one here."""

from __future__ import annotations

import pytest

from symdecomp.claims import check_claim
from symdecomp.claims.batch import check_claims
from symdecomp.errors import InvalidInputError

#: Claims whose words hold unevaluated relations (``d >= 1``, ``cos(2 pi/3) = -cos(pi/3)``): unpickled as sympy
#: objects they would read ``True``.
LABELS = ["Eq. 1", "Eq. 35-37", "Section 5.3: smaller eigenvalues", "Eq. 34"]


@pytest.mark.slow
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


def test_groups_name_registered_claims_and_keep_the_claims_order():
    from symdecomp.claims import all_claims
    from symdecomp.claims.batch import COST_HINTS, GROUPS, work_items

    labels = [c.label for c in all_claims()]
    assert {x for group in GROUPS for x in group} <= set(labels) and set(COST_HINTS) <= set(labels)
    items = work_items(labels)
    assert sorted(x for item in items for x in item) == sorted(labels)  # every claim once
    assert [item[0] for item in items] == [x for x in labels if x in {item[0] for item in items}]
    assert all(tuple(x for x in labels if x in group) in items for group in GROUPS)


def test_a_group_on_the_pool_gives_the_sequential_verdicts_in_order():
    from symdecomp.claims.batch import GROUPS

    sine = next(group for group in GROUPS if "Sector: sine decomposition" in group)  # a cheap group (a second claim)
    labels = ["Eq. 34", *sine, "Eq. 1"]
    pooled = list(check_claims(labels, jobs=2))
    assert [(r.status, str(r.evidence)) for r in pooled] == [(h.status, str(h.evidence)) for h in map(check_claim, labels)]
