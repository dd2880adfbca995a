"""Eq. 51's displayed closed form expanded exactly at each valence: one square root reduced over Q(lambda) (issue 33)."""

from __future__ import annotations

import pytest
import sympy as sp

from symdecomp.algebra.quadratic_extension import polynomial_in
from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial
from symdecomp.analysis.tuning import with_free_vertex_rule
from symdecomp.claims.registry import get_claim
from symdecomp.claims.s6_cb_subdivision import _displayed_expression_agrees
from symdecomp.schemes.files import SCHEMES, SHIPPED_FILES, load_scheme
from symdecomp.schemes.scheme import Scheme, catmull_clark
from symdecomp.schemes.stencil_files import ZOO_FILES
from symdecomp.symbols import lam
from symdecomp.symbols import n as N


def test_the_displayed_expression_is_checked_against_the_matrix():
    """Catmull-Clark's displayed closed form agrees with the matrix at n = 3..6; one with lambda^n changed by a factor
    1 + 1/1000 does not, at the first valence."""
    free = with_free_vertex_rule(catmull_clark())
    expression = closed_form_characteristic_polynomial(free).expression
    assert _displayed_expression_agrees(free, expression, range(3, 7)) is None
    wrong = expression.xreplace({(lam / 16) ** N: sp.Rational(1001, 1000) * (lam / 16) ** N})
    assert wrong != expression
    assert _displayed_expression_agrees(free, wrong, range(3, 7)) == "n = 3, alpha = 0, beta = 0"


_SHIPPED = [load_scheme(name) for name in (*SCHEMES, *SHIPPED_FILES, *ZOO_FILES)]
#: The zoo's schemes (StencilScheme) reach no claim's check on the 1-ring of a quad mesh.
_EQ51_APPLIES = [s for s in _SHIPPED if isinstance(s, Scheme) and get_claim("Eq. 51").unmet(s) is None]


def test_eq51_applies_to_the_shipped_quad_schemes():
    assert [s.name for s in _EQ51_APPLIES] == ["catmull-clark", "catmull-clark-blz"]


@pytest.mark.parametrize("scheme", _EQ51_APPLIES, ids=lambda s: s.name)
def test_every_shipped_quad_scheme_is_expanded_in_the_extension(scheme):
    """The shipped schemes Eq. 51 applies to have a displayed form rational in lambda and one
    square root at n = 3..8, vertex weights 0 and 1: it reduces to a polynomial, the matrix's characteristic polynomial
    (so no other route is needed)."""
    from symdecomp.schemes.full_matrix import characteristic_polynomial
    from symdecomp.symbols import alpha, beta

    free = with_free_vertex_rule(scheme)
    expression = closed_form_characteristic_polynomial(free).expression
    for k in range(3, 9):
        for values in ({alpha: 0, beta: 0}, {alpha: 1, beta: 0}, {alpha: 0, beta: 1}):
            value = expression.subs({N: k, **values})
            assert polynomial_in(value, lam) == characteristic_polynomial(free, k, values)


def test_a_form_with_a_second_root_is_undecided_not_passed():
    """A displayed form outside Q(lambda) and one square root (a second root added) is not expanded: the claim says so
    (undecided, naming the reason) where the evaluator agrees, and refutes where it does not."""
    from symdecomp.claims.registry import Status
    from symdecomp.claims.s6_cb_subdivision import _against_the_matrix

    free = with_free_vertex_rule(catmull_clark())
    expression = closed_form_characteristic_polynomial(free).expression + sp.sqrt(lam + 2)
    result = _against_the_matrix(free, expression, True)
    assert result is not None and result.status is Status.UNDECIDED and "2 square roots" in str(result.evidence)
    assert _against_the_matrix(free, expression, False).status is Status.REFUTED
    assert _against_the_matrix(free, closed_form_characteristic_polynomial(free).expression, True) is None
