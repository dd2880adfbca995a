"""The certificate from the structural blocks against the explicit route, and at n = 1000 and 10,000."""

import time

import pytest

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import structural_applies
from symdecomp.analysis.zoo_structure import READ_AT
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.certify import certify_zoo
from symdecomp.verify.result import CrossCheckStatus
from symdecomp.verify.zoo_structural import structural_zoo_certificate

FAMILIES = ("doo-sabin", "midedge", "sqrt3", "modified-butterfly")


@pytest.mark.slow
@pytest.mark.parametrize("name", FAMILIES)
def test_the_structural_certificate_is_the_explicit_one(name):
    """Beyond the reading, the explicit route (the whole matrix, block circulant entry by entry) and the structural
    one find the same distinct values with the same multiplicities."""
    scheme, n = load_zoo(name), READ_AT + 5
    explicit = certify_zoo(scheme, n, zoo_matrix(scheme, n).depth)  # a depth given: the explicit route
    structural = structural_zoo_certificate(scheme, n)
    assert explicit.route != "structural-form" and structural.route == "structural-form"
    assert explicit.status == structural.status == CrossCheckStatus.AGREE
    assert structural.multiplicities_certified
    assert structural.multiplicities == explicit.multiplicities
    assert len(structural.values) == len(explicit.values)
    for a, b in zip(structural.values, explicit.values):
        assert abs(complex(a) - complex(b)) < 1e-15, (a, b)


def test_check_certify_takes_the_structural_route_beyond_the_checks():
    scheme = load_zoo("doo-sabin")
    assert not structural_applies(scheme, READ_AT + 3) and structural_applies(scheme, READ_AT + 4)
    assert certify_zoo(scheme, READ_AT + 4).route == "structural-form"


@pytest.mark.parametrize("name", FAMILIES)
@pytest.mark.parametrize("n", [1000, 10_000])
def test_certificate_at_large_n(name, n):
    scheme = load_zoo(name)
    start = time.perf_counter()
    c = certify_zoo(scheme, n)
    assert time.perf_counter() - start < 60  # generous: a guard against the O(n^2) route, not a benchmark
    assert c.status == CrossCheckStatus.AGREE and c.route == "structural-form" and c.multiplicities_certified
    size = zoo_matrix(scheme, 5).matrix.shape[0] // 5 * n + (zoo_matrix(scheme, 5).neighbourhood.centre is not None)
    assert sum(c.multiplicities) == size  # every eigenvalue of the matrix, from the blocks
    assert c.values[0] == "1.0" and c.multiplicities[0] == 1  # affine invariance, and the leading value simple
