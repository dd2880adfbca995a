"""Every bound of the limits table (``symdecomp.cli.common.LIMITS``, rendered by the docs) is enforced where it is named.

Each row has a case below: one step past the bound, which must be refused at once, in one line naming the bound
(exit status 2 on the command line, the package's error in the API). A new row without a case fails
:func:`test_every_bound_has_a_case`: a bound that nothing enforces is not a bound.
"""

import time

import pytest

from symdecomp import (
    artifact_indicators,
    c1_test,
    catmull_clark,
    certify_ring,
    classify_shape,
    closed_form_spectrum,
    jordan_block_size,
    patch_matrices,
    ring_masks,
    ring_spectrum,
    second_order_eigenstructure,
)
from symdecomp.analysis.tuning_region import interval_region, placed_points, tuning_region
from symdecomp.cli import main
from symdecomp.cli.common import LIMITS
from symdecomp.errors import SymdecompError
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA


def _over(key: str, kind=str):
    return kind(LIMITS[key][0] + 1)


#: A call one step past each bound: a command line (a list), or a function of the API.
CASES = {
    "digits": ["spectrum", "5", "--digits", _over("digits")],
    "dps": ["check", "--n", "5", "--dps", _over("dps")],
    "spectrum": ["spectrum", _over("spectrum")],
    "masks": ["masks", _over("masks")],
    "charpoly": ["charpoly", _over("charpoly")],
    "tune": ["tune", _over("tune")],
    "tune --table": ["tune", _over("tune --table"), "--table"],
    "check": ["check", "--n", _over("check")],
    "check --certify": ["check", "--n", _over("check --certify"), "--certify", "--route", "charpoly"],
    "check --certify --route structural": ["check", "--n", _over("check --certify --route structural"), "--certify"],
    "design": ["design", "--n", _over("design")],
    "oracle": ["oracle", "--n", _over("oracle")],
    "levels": ["oracle", "--levels", _over("levels")],
    "jobs": ["check", "--n", "5", "--jobs", _over("jobs")],
    "c1": ["c1", "--n", _over("c1")],
    "artifacts": ["artifacts", "--n", _over("artifacts")],
    "artifacts --n A:B": ["artifacts", "--n", "3:2000"],
    "c1 --k": ["c1", "--boundary", "--k", _over("c1 --k")],
    "c1 --depth": ["c1", "--n", "5", "--depth", _over("c1 --depth")],
    "rings": ["spectrum", "5", "--rings", _over("rings")],
    "budget": ["claims", "--budget", _over("budget")],
    "report": ["report", "--n", _over("report")],
    "--boundary, --corner, --crease, --dart: faces": ["spectrum", _over("--boundary, --corner, --crease, --dart: faces"),
                                                      "--dart"],
    "--boundary, --corner, --crease: faces by the blocks": ["spectrum", "2000", "--crease",
                                                            str(_over("--boundary, --corner, --crease: faces by the blocks", int) - 2000)],
    "evaldata --k": ["evaldata", "--boundary", "--k", _over("evaldata --k")],
    "evaldata": ["evaldata", "--n", _over("evaldata")],
    "artifact_indicators(n)": lambda: artifact_indicators(catmull_clark(), LIMITS["artifact_indicators(n)"][0] + 1),
    "second_order_eigenstructure(n)": lambda: second_order_eigenstructure(
        catmull_clark(), LIMITS["second_order_eigenstructure(n)"][0] + 1),
    "c1_test(n)": lambda: c1_test(catmull_clark(), _over("c1_test(n)", int)),
    "classify_shape(n)": lambda: classify_shape(catmull_clark(), _over("classify_shape(n)", int)),
    "closed_form_spectrum(n)": lambda: closed_form_spectrum(catmull_clark(), _over("closed_form_spectrum(n)", int)),
    "ring_spectrum(n)": lambda: ring_spectrum(catmull_clark(), _over("ring_spectrum(n)", int)),
    "ring_masks(n)": lambda: ring_masks(catmull_clark(), _over("ring_masks(n)", int)),
    "certify_ring(n)": lambda: certify_ring(catmull_clark(), _over("certify_ring(n)", int)),
    "patch_matrices(n)": lambda: patch_matrices(catmull_clark(), _over("patch_matrices(n)", int)),
    "jordan_block_size(n)": lambda: jordan_block_size(catmull_clark(), LIMITS["jordan_block_size(n)"][0] + 1, "1/4"),
    "jordan_vertex_weights(n)": lambda: __import__("symdecomp").jordan_vertex_weights(
        catmull_clark(ALPHA, BETA), LIMITS["jordan_vertex_weights(n)"][0] + 1, "1/4"),
    # phi(7) = 6 > 4: the exact signs of n = 7 take minutes; the forms themselves stay cheap
    "tune --region, interval_region, placed_points: phi(n)": lambda: interval_region(
        tuning_region(catmull_clark(ALPHA, __import__("sympy").Rational(1, 16)), 7)),
}

#: What the refusal says, where it is not the bound itself (a time limit is shown in minutes).
SAYS = {"artifacts --n A:B": "more than the limit of 10 minutes", "tune --region, interval_region, placed_points: phi(n)": "> 4"}


def test_every_bound_has_a_case():
    assert set(LIMITS) == set(CASES), f"rows without a case: {sorted(set(LIMITS) - set(CASES))}"


@pytest.mark.parametrize("key", sorted(CASES))
def test_each_bound_is_enforced_at_once(key, capsys):
    start = time.monotonic()
    case = CASES[key]
    says = SAYS.get(key, str(LIMITS[key][0]))
    if callable(case):
        with pytest.raises(SymdecompError) as refused:
            case()
        message = str(refused.value)
    else:
        code = main(case)
        err = capsys.readouterr().err.strip()
        assert code == 2, err
        assert "\n" not in err and "internal error" not in err, err
        message = err
    assert says in message, message
    assert time.monotonic() - start < 30  # refused before the work, not after it


def test_placed_points_share_the_region_bound():
    with pytest.raises(SymdecompError, match=r"phi\(n\) = 6 > 4"):
        placed_points(catmull_clark(ALPHA, BETA), 7)
