"""Numeric cross-check: mpmath spectra of the full matrix, matched with multiplicities."""

import dataclasses

import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.closed_forms import derived_closed_forms
from symdecomp.analysis.defective import jordan_vertex_weights
from symdecomp.schemes.full_matrix import sparse_subdivision_matrix
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import alpha, beta
from symdecomp.verify.numeric import full_matrix_eigenvalues, numeric_check
from symdecomp.verify.result import CrossCheckStatus

CC = catmull_clark()
FREE = catmull_clark(alpha, beta)


def _group(result, text):
    return next(m for m in result.matches if m.eigenvalue.text == text)


@pytest.mark.parametrize("n", [3, 5, 7])
def test_closed_forms_agree_to_30_digits(n):
    r = numeric_check(CC, n, dps=30)
    assert r.status is CrossCheckStatus.AGREE, r.message
    assert r.max_deviation < mpmath.mpf(10) ** -30
    assert len(r.precisions) >= 2  # at least two precisions: the answer was seen to stop moving
    assert sum(m.matched for m in r.matches) == 2 * n + 1


def test_repeated_quarter_at_n4_is_matched_three_times():
    r = numeric_check(CC, 4, dps=30)
    assert r.ok
    quarter = _group(r, "0.25")
    assert quarter.eigenvalue.multiplicity == 3 and quarter.matched == 3
    assert sorted({lab.frequency for lab in quarter.eigenvalue.labels}) == [0, 2]


def test_frequency_n_over_2_at_n6():
    """j = n/2: M_j = I/4 gives 1/4 twice, from the dominant and the subdominant closed form."""
    r = numeric_check(CC, 6, dps=30)
    assert r.ok
    quarter = _group(r, "0.25")
    assert quarter.eigenvalue.multiplicity == 2 and quarter.matched == 2
    assert {(lab.frequency, lab.label) for lab in quarter.eigenvalue.labels} == {(3, "Eq. 34 dominant"), (3, "Eq. 34 subdominant")}


def test_defective_eigenvalue_splits_by_sqrt_eps_and_is_matched_by_its_mean():
    n, mu = 5, sp.Rational(3, 8)
    weights = jordan_vertex_weights(FREE, n, mu)
    r = numeric_check(FREE, n, parameters=weights, dps=30)
    assert r.status is CrossCheckStatus.AGREE, r.message
    m = _group(r, "0.375")
    assert m.eigenvalue.multiplicity == 2 and m.matched == 2
    work = r.precisions[-1]
    # the two computed eigenvalues sit about sqrt(10^-work) from 3/8; their mean is far closer
    assert mpmath.mpf(10) ** (-(work / 2) - 4) < m.spread < mpmath.mpf(10) ** (-(work / 2) + 4)
    assert m.deviation < mpmath.mpf(10) ** (-work + 5)


def test_perturbed_defective_eigenvalue_moves_by_sqrt_eps():
    n, mu = 5, sp.Rational(3, 8)
    weights = jordan_vertex_weights(FREE, n, mu)
    entries = sparse_subdivision_matrix(FREE, n, weights)
    with mpmath.workdps(80):
        A = mpmath.matrix(2 * n + 1, 2 * n + 1)
        for (r, c), x in entries.items():
            A[r, c] = mpmath.mpf(int(x.p)) / int(x.q)
        A[1, 0] += mpmath.mpf(10) ** -40
        moved = sorted(abs(v - mpmath.mpf(3) / 8) for v in mpmath.eig(A, left=False, right=False))[:2]
        for d in moved:
            assert mpmath.mpf(10) ** -22 < d < mpmath.mpf(10) ** -18
    # a simple eigenvalue under the same perturbation moves by about eps itself
    with mpmath.workdps(80):
        A = mpmath.matrix(2 * n + 1, 2 * n + 1)
        for (r, c), x in sparse_subdivision_matrix(CC, n).items():
            A[r, c] = mpmath.mpf(int(x.p)) / int(x.q)
        before = full_matrix_eigenvalues(CC, n, 80)
        A[1, 0] += mpmath.mpf(10) ** -40
        after = mpmath.eig(A, left=False, right=False)

        def one(vs):
            return min(vs, key=lambda v: abs(v - 1))
        assert abs(one(after) - one(before)) < mpmath.mpf(10) ** -38


def test_wrong_closed_form_fails_naming_valence_and_eigenvalue():
    cf = derived_closed_forms(CC)
    wrong = dataclasses.replace(cf, frequency_k=(cf.frequency_k[0] + sp.Rational(1, 10**40), cf.frequency_k[1]))
    r = numeric_check(CC, 5, dps=50, closed_forms=wrong)
    assert r.status is CrossCheckStatus.DISAGREE
    assert "n = 5" in r.message and "Eq. 34 dominant" in r.message and "0.549988354518297177894305358956" in r.message
    assert "1.0e-40" in r.message


def test_wrong_multiplicity_fails():
    cf = derived_closed_forms(CC)
    wrong = dataclasses.replace(cf, frequency_k=(cf.frequency_k[0], cf.frequency_k[0]))
    r = numeric_check(CC, 5, dps=20, closed_forms=wrong)
    assert r.status is CrossCheckStatus.DISAGREE
    assert "n = 5" in r.message and "not 4" in r.message


def test_error_below_the_requested_digits_is_not_seen():
    """The numeric check is a tolerance: 1e-60 passes at 50 digits (certify refutes it)."""
    cf = derived_closed_forms(CC)
    eps = sp.Rational(1, 10**60)
    wrong = dataclasses.replace(cf, frequency_k=(cf.frequency_k[0] + eps, cf.frequency_k[1] + eps))
    assert numeric_check(CC, 4, dps=50, closed_forms=wrong).ok


def test_an_answer_that_keeps_moving_is_not_converged():
    def drifting(A):
        # eigenvalues whose error depends on the working precision: they never settle
        return [v + mpmath.mpf(10) ** -25 * mpmath.mp.dps for v in mpmath.eig(A, left=False, right=False)]

    r = numeric_check(CC, 3, dps=30, eigensolver=drifting, max_dps=100)
    assert r.status is CrossCheckStatus.NOT_CONVERGED and not r.ok
    assert "n = 3" in r.message and "did not converge" in r.message


def test_qr_failure_everywhere_is_not_converged():
    def failing(A):
        raise RuntimeError("qr: failed to converge")

    r = numeric_check(CC, 3, dps=20, eigensolver=failing, max_dps=60)
    assert r.status is CrossCheckStatus.NOT_CONVERGED and "n = 3" in r.message


def test_bad_arguments():
    with pytest.raises(ValueError, match="max_dps"):
        numeric_check(CC, 3, dps=50, max_dps=55)


def test_complex_frequency_zero_eigenvalues():
    """Vertex weights with a negative Eq. 43 discriminant: a complex pair, matched as such."""
    weights = {alpha: sp.Rational(-1, 5), beta: sp.Rational(1, 3)}
    r = numeric_check(FREE, 5, parameters=weights, dps=30)
    assert r.ok, r.message
    complex_matches = [m for m in r.matches if mpmath.im(m.eigenvalue.value) != 0]
    assert len(complex_matches) == 2
    with mpmath.workdps(60):
        assert abs(complex_matches[0].eigenvalue.value - mpmath.conj(complex_matches[1].eigenvalue.value)) < mpmath.mpf(10) ** -30
