"""Certified cross-check: exact matrices, the polynomial identity, and rigorous refutations."""

import dataclasses

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.closed_forms import derived_closed_forms
from symdecomp.analysis.defective import jordan_block_size, jordan_vertex_weights
from symdecomp.errors import InvalidSchemeError, InvalidValenceError
from symdecomp.schemes.full_matrix import characteristic_polynomial, exact_subdivision_matrix
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import alpha, beta, lam
from symdecomp.verify.certify import certify
from symdecomp.verify.result import CrossCheckStatus
from symdecomp.verify.symmetric_functions import closed_form_characteristic_value, symmetric_functions

CC = catmull_clark()
FREE = catmull_clark(alpha, beta)
LAM = flint.fmpq_poly([0, 1])


def _fmpq(x):
    return flint.fmpq(int(x.p), int(x.q))


@pytest.mark.parametrize("n", [3, 4, 5, 7])
def test_exact_matrix_equals_sympy_matrix(n):
    weights = {alpha: sp.Rational(1, 7), beta: sp.Rational(-2, 9)}
    for scheme, params in ((CC, None), (FREE, weights)):
        E = exact_subdivision_matrix(scheme, n, params)
        M = subdivision_matrix(scheme.substitute(params) if params else scheme, n)
        assert all(E[i, j] == _fmpq(M[i, j]) for i in range(2 * n + 1) for j in range(2 * n + 1))


@pytest.mark.parametrize("n", [3, 4, 6])
def test_flint_characteristic_polynomial_equals_sympy(n):
    expected = subdivision_matrix(CC, n).charpoly(lam).all_coeffs()[::-1]
    assert characteristic_polynomial(CC, n) == flint.fmpq_poly([_fmpq(c) for c in expected])


def test_missing_or_bad_parameters_are_named():
    with pytest.raises(InvalidSchemeError, match="alpha"):
        certify(FREE, 4)
    with pytest.raises(InvalidSchemeError, match="float"):
        exact_subdivision_matrix(FREE, 4, {alpha: 0.1, beta: 0})
    with pytest.raises(InvalidValenceError):
        certify(CC, 2)


def test_symmetric_functions_of_the_derived_closed_forms():
    sym = symmetric_functions(derived_closed_forms(CC))
    # e_1 = trace M_k = 5/8 + (omega + 1/omega)/16 and e_2 = det M_k = 1/16 (Eq. 33)
    assert sym.trace == {-1: sp.Rational(1, 16), 0: sp.Rational(5, 8), 1: sp.Rational(1, 16)}
    assert sym.determinant == {0: sp.Rational(1, 16)}


@pytest.mark.parametrize("n", [5, 6])
def test_resultant_step_equals_direct_product_of_closed_forms(n):
    """Step 2 of the proof (resultants, signs) against a 40-digit product over the closed forms."""
    cf = derived_closed_forms(CC)
    points = [0, 1, sp.Rational(-3, 7), 2]
    rational_points = [flint.fmpq(int(p.p), int(p.q)) if isinstance(p, sp.Rational) else p for p in points]
    exact = closed_form_characteristic_value(symmetric_functions(cf), n, {}, rational_points)
    with mpmath.workdps(40):
        values = cf.values(n, {})
        for p, e in zip(points, exact):
            lam0 = mpmath.mpf(int(sp.Rational(p).p)) / int(sp.Rational(p).q)
            direct = mpmath.fprod(lam0 - v for v in values)
            assert abs(direct - mpmath.mpf(int(e.p)) / int(e.q)) <= mpmath.mpf(10) ** -35 * max(1, abs(direct))


@pytest.mark.parametrize("n", list(range(3, 41)))
def test_certified_for_every_valence_up_to_40(n):
    r = certify(CC, n)
    assert r.status is CrossCheckStatus.AGREE, r.message
    assert r.multiplicities_certified
    assert sum(r.multiplicities) == 2 * n + 1
    # the number of distinct eigenvalues is the degree of the squarefree part of chi_S
    chi = characteristic_polynomial(CC, n)
    assert r.distinct == chi.degree() - chi.gcd(chi.derivative()).degree()


def test_repeated_eigenvalue_quarter_three_times_at_n4():
    r = certify(CC, 4)
    assert r.ok
    assert dict(zip(r.values, r.multiplicities))["0.25"] == 3
    chi = characteristic_polynomial(CC, 4)
    q = LAM - flint.fmpq(1, 4)
    assert chi % q**3 == 0 and chi % q**4 != 0


@pytest.mark.parametrize("n", [6, 8, 10, 16])
def test_frequency_n_over_2_gives_a_double_quarter(n):
    """At j = n/2 the per-frequency matrix is I/4: 1/4 is a double eigenvalue of the full matrix."""
    r = certify(CC, n)
    assert r.ok and r.multiplicities_certified
    chi = characteristic_polynomial(CC, n)
    q = LAM - flint.fmpq(1, 4)
    assert chi % q**2 == 0
    S = exact_subdivision_matrix(CC, n)
    shifted = S - flint.fmpq(1, 4) * flint.fmpq_mat(2 * n + 1, 2 * n + 1, [int(i == j) for i in range(2 * n + 1) for j in range(2 * n + 1)])
    assert shifted.rank() == 2 * n + 1 - 2  # semisimple: two independent eigenvectors
    assert dict(zip(r.values, r.multiplicities))["0.25"] == 2


@pytest.mark.parametrize("n", [5, 6, 9])
def test_defective_eigenvalue_is_certified_with_its_multiplicity(n):
    mu = sp.Rational(3, 8)
    weights = jordan_vertex_weights(FREE, n, mu)
    assert jordan_block_size(FREE.substitute(weights), n, mu) == 2
    r = certify(FREE, n, parameters=weights)
    assert r.ok and r.multiplicities_certified, r.message
    # the full matrix has a 2x2 Jordan block at 3/8: algebraic multiplicity 2, geometric 1
    chi = characteristic_polynomial(FREE, n, weights)
    q = LAM - flint.fmpq(3, 8)
    assert chi % q**2 == 0 and chi % q**3 != 0
    size = 2 * n + 1
    S = exact_subdivision_matrix(FREE, n, weights)
    eye = flint.fmpq_mat(size, size, [int(i == j) for i in range(size) for j in range(size)])
    assert (S - flint.fmpq(3, 8) * eye).rank() == size - 1
    assert dict(zip(r.values, r.multiplicities))["0.375"] == 2


def _shifted(cf, offset, which=0):
    pair = list(cf.frequency_k)
    pair[which] = pair[which] + offset
    return dataclasses.replace(cf, frequency_k=tuple(pair))


def test_wrong_dominant_closed_form_is_refuted_naming_valence_and_eigenvalue():
    wrong = _shifted(derived_closed_forms(CC), sp.Rational(1, 10**40))
    r = certify(CC, 5, closed_forms=wrong)
    assert r.status is CrossCheckStatus.DISAGREE
    assert "n = 5" in r.message and "Eq. 34 dominant" in r.message and "0.5499883545" in r.message
    assert "distance 1.00e-40" in r.message


def test_tiny_error_below_any_tolerance_is_still_refuted():
    """1e-60 in both closed forms: the symmetric functions stay polynomial, the identity fails."""
    cf = derived_closed_forms(CC)
    eps = sp.Rational(1, 10**60)
    wrong = dataclasses.replace(cf, frequency_k=(cf.frequency_k[0] + eps, cf.frequency_k[1] + eps))
    assert symmetric_functions(wrong).trace is not None
    r = certify(CC, 7, closed_forms=wrong)
    assert r.status is CrossCheckStatus.DISAGREE and "n = 7" in r.message
    # at too low a precision nothing can be shown either way: undecided, never agree
    r = certify(CC, 7, closed_forms=wrong, max_prec=128)
    assert r.status is CrossCheckStatus.UNDECIDED and not r.ok


def test_wrong_multiplicity_is_refuted():
    cf = derived_closed_forms(CC)
    wrong = dataclasses.replace(cf, frequency_k=(cf.frequency_k[0], cf.frequency_k[0]))
    r = certify(CC, 5, closed_forms=wrong)
    assert r.status is CrossCheckStatus.DISAGREE
    assert "n = 5" in r.message and "multiplicity in the full matrix is 2" in r.message


def test_wrong_frequency_zero_closed_form_is_refuted():
    cf = derived_closed_forms(CC)
    zero = list(cf.frequency_zero)
    zero[1] = zero[1] * (1 + sp.Rational(1, 10**30))
    r = certify(CC, 7, closed_forms=dataclasses.replace(cf, frequency_zero=tuple(zero)))
    assert r.status is CrossCheckStatus.DISAGREE
    assert "n = 7" in r.message and "Eq. 43 root 2" in r.message


@pytest.mark.slow
def test_certified_up_to_128():
    for n in range(41, 129):
        r = certify(CC, n)
        assert r.ok and r.multiplicities_certified, r.message


def test_claim_full_spectrum_is_proved_for_every_n():
    from symdecomp.claims import Status, check_claim
    from symdecomp.symbols import lam, omega

    result = check_claim("Spectrum (Eq. 34, Eq. 43)")
    assert result.status is Status.PROVED and "n = 3..48" in str(result.evidence)
    steps = {step.text.split(" (")[0].split(",")[0]: step.expr for step in result.steps}
    trace = next(e for t, e in steps.items() if t.startswith("Sum of the two closed forms"))
    product = next(e for t, e in steps.items() if t.startswith("Their product"))
    assert sp.simplify(trace - (omega / 16 + sp.Rational(5, 8) + 1 / (16 * omega))) == 0
    assert product == sp.Rational(1, 16)
    # the chain's last identity: x^2 - trace x + product is det(xI - M(omega)) of Catmull-Clark
    q = next(e for t, e in steps.items() if t.startswith("$q(x"))
    assert sp.expand(q - (lam**2 - trace * lam + product)) == 0


def test_complex_frequency_zero_eigenvalues_are_certified():
    weights = {alpha: sp.Rational(-1, 5), beta: sp.Rational(1, 3)}
    r = certify(FREE, 5, parameters=weights)
    assert r.ok and r.multiplicities_certified, r.message
    assert "0.041666666666666666667+0.43100335136619168624j" in r.values
    assert "0.041666666666666666667-0.43100335136619168624j" in r.values
    # the pair is the root pair of lambda^2 - lambda/12 + c: its discriminant is negative, exactly
    chi = characteristic_polynomial(FREE, 5, weights)
    assert chi(flint.fmpq(1)) == 0
