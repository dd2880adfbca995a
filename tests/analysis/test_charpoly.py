"""The closed-form characteristic polynomial of S against the matrix's own, exactly (FLINT rationals)."""

import pytest
import sympy as sp

from symdecomp.analysis.charpoly import (
    closed_form_characteristic_polynomial,
    to_fmpq_poly,
    verify_closed_form,
)
from symdecomp.errors import InvalidSchemeError, SymdecompError
from symdecomp.schemes.full_matrix import characteristic_polynomial
from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule, catmull_clark
from symdecomp.symbols import alpha, beta, lam, n, omega

R = sp.Rational
STANDARD = catmull_clark()
FREE = catmull_clark(alpha, beta)


def test_closed_form_has_no_product_over_frequencies():
    cf = closed_form_characteristic_polynomial(FREE)
    assert not cf.expression.has(sp.Product, sp.Sum)
    assert cf.expression.free_symbols == {lam, n, alpha, beta}


def test_closed_form_matches_matrix_for_n_3_to_64_standard_weights():
    for k in range(3, 65):
        assert closed_form_characteristic_polynomial(STANDARD).at(k) == characteristic_polynomial(STANDARD, k), k


def test_closed_form_matches_matrix_for_n_3_to_64_free_weights():
    """Both sides are affine in (alpha, beta); equality at 3 affinely independent points is identity."""
    for k in range(3, 65):
        assert verify_closed_form(FREE, k), k


@pytest.mark.slow
def test_closed_form_matches_matrix_for_n_65_to_128():
    for k in range(65, 129):
        assert verify_closed_form(FREE, k), k
        assert verify_closed_form(STANDARD, k), k


def test_a_wrong_closed_form_is_caught():
    cf = closed_form_characteristic_polynomial(STANDARD)
    good = cf.at(5)
    assert good != characteristic_polynomial(catmull_clark(R(1, 50), R(1, 100)), 5)
    assert good.degree() == 11 and good.leading_coefficient() == 1


@pytest.mark.parametrize("k", [3, 4, 5, 6])
def test_sympy_expression_evaluates_to_the_same_polynomial(k):
    """The printed expression (with square roots) and the exact evaluator agree."""
    cf = closed_form_characteristic_polynomial(FREE)
    expr = sp.cancel(sp.expand(cf.expression.subs(n, k)))
    for a, b in ((0, 0), (R(3, 2) / k**2, R(1, 4) / k**2), (R(1, 7), R(-2, 5))):
        value = sp.expand(expr.subs({alpha: a, beta: b}))
        assert to_fmpq_poly(value) == cf.at(k, {alpha: a, beta: b})


def test_weights_enter_only_the_zero_frequency_factor_and_affinely():
    cf = closed_form_characteristic_polynomial(FREE)
    for part in (cf.frequency_factor, cf.frequency_product, cf.frequency_one, *cf.laurent_coefficients):
        assert not part.has(alpha, beta)
    poly = sp.Poly(cf.zero_frequency_factor, alpha, beta)
    assert poly.total_degree() == 1
    assert sp.expand(cf.zero_frequency_factor - (lam**2 - (R(3, 4) - n * alpha - n * beta) * lam + R(1, 16) - n * alpha / 8)) == 0


def test_per_frequency_factor_matches_the_matrix_frequencies():
    """prod_{k=0}^{n-1} q(x, omega_n^k) by brute force (roots of unity) equals the closed product at n = 4."""
    cf = closed_form_characteristic_polynomial(STANDARD)
    brute = sp.expand(sp.prod([cf.frequency_factor.subs(omega, sp.I**k) for k in range(4)]))
    closed = sp.expand(cf.frequency_product.subs(n, 4))
    assert sp.expand(brute - closed) == 0


def asymmetric_scheme():
    """An affine scheme with non-symmetric stencils (c_+ != c_-) whose q is still of Laurent degree 1."""
    edge = Stencil.from_weights(R(1, 8), {0: R(1, 2), 1: R(1, 4)}, {0: R(1, 8)}, name="edge")
    face = Stencil.from_weights(R(1, 6), {0: R(1, 3)}, {0: R(1, 3), -1: R(1, 6)}, name="face")
    return Scheme("asymmetric", edge, face, VertexRule.affine(alpha, beta))


def test_other_scheme_with_asymmetric_stencils():
    s = asymmetric_scheme()
    cf = closed_form_characteristic_polynomial(s)
    c_minus, _, c_plus = cf.laurent_coefficients
    assert sp.expand(c_minus - c_plus) != 0
    for k in range(3, 21):
        assert verify_closed_form(s, k), k


def test_wider_stencils_are_rejected_with_a_clear_error():
    edge = Stencil.from_weights(R(1, 2), {-1: R(1, 8), 0: R(1, 4), 1: R(1, 8)}, {}, name="edge")
    face = Stencil.from_weights(R(1, 2), {0: R(1, 4)}, {0: R(1, 8), 1: R(1, 8)}, name="face")
    s = Scheme("wide", edge, face, VertexRule.affine(R(1, 10), R(1, 20)))
    with pytest.raises(InvalidSchemeError, match="Laurent degree 1"):
        closed_form_characteristic_polynomial(s)


def test_free_parameters_must_be_given():
    with pytest.raises(SymdecompError, match="free"):
        closed_form_characteristic_polynomial(FREE).at(5)
    with pytest.raises(SymdecompError, match="free parameters"):
        characteristic_polynomial(FREE, 5)


@pytest.mark.parametrize("k", range(3, 10))
def test_symmetric_scheme_frequencies_pair_up(k):
    """Catmull-Clark: prod_{j=1}^{n-1} q(x, omega^j) is the square Psi_n^2 (frequency j pairs with n - j)."""
    cf = closed_form_characteristic_polynomial(STANDARD)
    psi_squared = sp.expand(sp.expand(cf.paired_factor.subs(n, k)) ** 2)
    rest = cf.at(k)
    rest, r = divmod(rest, to_fmpq_poly(cf.unit_factor) * to_fmpq_poly(cf.zero_frequency_factor.subs(n, k)))
    assert r == 0
    assert to_fmpq_poly(psi_squared) == rest


def test_asymmetric_scheme_has_no_paired_factor():
    assert closed_form_characteristic_polynomial(asymmetric_scheme()).paired_factor is None
