"""The registered claims of Sections 5.2 and 5.3 run and report the statuses their derivations establish."""

import pytest

from symdecomp.claims import Status, all_claims, check_claim

EXPECTED = {
    "Eq. 40": Status.PROVED,
    "Eq. 41": Status.PROVED,
    "Proposition 5.2": Status.PROVED,
    "Eq. 42": Status.PROVED,
    "Eq. 43": Status.CORRECTED,
    "Eq. 44": Status.PROVED,
    "Eq. 45": Status.VERIFIED,
    "Remark 5.2": Status.CORRECTED,
    "Section 5.2: Catmull-Clark example": Status.PROVED,
    "Section 5.3: smaller eigenvalues": Status.CORRECTED,
    "Section 5.3: quadratic speed": Status.PROVED,
    "Section 5.3: construction": Status.VERIFIED,
    "Section 5.3: basis function": Status.VERIFIED,
}


def test_all_registered():
    labels = {c.label for c in all_claims() if c.section in ("5.2", "5.3")}
    assert set(EXPECTED) <= labels


@pytest.mark.parametrize("label", sorted(EXPECTED))
def test_status(label):
    result = check_claim(label)
    assert result.status is EXPECTED[label], result.evidence
    assert result.evidence
