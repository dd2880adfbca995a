"""The hyperbolic part dominates on fine rings for every n from a valence on (verify/dominance_every_n.py, issue 32)."""

import pytest
import sympy as sp

from symdecomp import catmull_clark, loop, loop_warren, symbols
from symdecomp.claims import Scope, Status
from symdecomp.claims import b1_curvature as b1
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.loop import triangle_scheme
from symdecomp.verify.dominance_every_n import hyperbolic_dominates_from
from symdecomp.verify.second_order_spectrum import dominant_part, second_order_eigenstructure

n = symbols.n


def test_catmull_clark_from_5_by_the_bound_in_n_and_not_from_4_where_the_parts_tie():
    step = hyperbolic_dominates_from(catmull_clark(), 5)
    assert step.status == "proved" and step.valences == (5, None)
    # the frequency-0 roots come from the vertex rule: q(x) of E_0 (weights 3/(2n^2), 1/(4n^2)), signs from n = 9
    assert "16*n*x**2 - 12*n*x + n + 28*x - 3" in step.text and "signs for every n >= 9" in step.text
    assert "at n = 5..8 certified one by one" in step.text
    assert hyperbolic_dominates_from(catmull_clark(), 4).status == "open"  # n = 4: the regular valence, a tie


def test_loop_from_7_is_the_regime_inequality_and_not_from_6():
    step = hyperbolic_dominates_from(loop(), 7)
    assert step.status == "proved"
    # e_0 derived from Loop's weight is lambda_1^2 = (s/4 + 3/8)^2, lambda_2 = lambda(2 s^2 - 1) = s^2/2 + 1/8
    assert "e_0 = s**2/16 + 3*s/16 + 9/64" in step.text and "lambda_2 = s**2/2 + 1/8" in step.text
    assert hyperbolic_dominates_from(loop(), 6).status == "open"


def test_warrens_weight_from_its_rule_for_n_beyond_3():
    step = hyperbolic_dominates_from(loop_warren(), 7)  # 3/(8n) past the piece at n = 3: e_0 = 5/8 - 3/8
    assert step.status == "proved" and "e_0 = 1/4 " in step.text
    assert hyperbolic_dominates_from(loop_warren(), 6).status == "open"  # cos(4 pi/6) = -1/2: lambda_2 = 1/4 = e_0


def test_a_frequency_0_eigenvalue_rational_in_n_by_signs_and_certified_valences():
    # beta = 3/(8n) + (n - 6)/(8n^2): Loop's at n = 6, e_0 = 1/8 + 3/(4n), above lambda(t_n) at n = 7
    s = triangle_scheme("rational e0", sp.Rational(3, 8) / n + (n - 6) / (8 * n**2))
    step = hyperbolic_dominates_from(s, 7)
    assert step.status == "proved" and "|e_0| = |1/8 + 3/(4*n)|" in step.text and "certified one by one" in step.text
    assert b1.check_dominance(s, b1.DOMINANCE[BOX_SPLINE]).status is Status.PROVED


def test_the_claim_is_proved_and_flips_with_the_printed_first_n():
    assert b1.check_dominance(catmull_clark(), b1.DOMINANCE[BICUBIC]).status is Status.PROVED
    assert b1.check_dominance(loop(), b1.DOMINANCE[BOX_SPLINE]).status is Status.PROVED
    for printed, at in ((((3, 5, None), (6, None, 2)), 5), (((3, 3, None), (4, None, 2)), 4)):
        r = b1.check_dominance(catmull_clark(), printed)
        assert r.status is Status.REFUTED and r.scope is Scope.SINGLE_CASE and f"n = {at}:" in str(r.counterexample)
    later = ((3, 3, None), (4, 5, 0), (6, 7, None), (8, None, 2))
    r = b1.check_dominance(loop(), later)
    assert r.status is Status.REFUTED and "n = 7: the statement says neither part" in str(r.counterexample)


@pytest.mark.slow
def test_a_vertex_weight_whose_dominance_changes_late_gets_the_first_valence_where_it_does():
    s = catmull_clark(sp.Rational(3, 2) / n**2 - (n - 4) / (40 * n**2), sp.Rational(1, 4) / n**2)
    assert hyperbolic_dominates_from(s, 5).status == "open"
    r = b1.check_dominance(s, b1.DOMINANCE[BICUBIC])
    assert r.status is Status.REFUTED and r.scope is Scope.SINGLE_CASE
    k = int(str(r.counterexample).split("n = ")[1].split(":")[0])
    assert 32 < k <= b1.SHAPE_VALENCES[1] and "computed: the elliptic part" in str(r.counterexample)
    assert all(dominant_part(second_order_eigenstructure(s, m)) == 2 for m in (5, k - 1))  # the first valence it changes


def test_a_vertex_weight_with_a_cosine_on_quads_is_open_with_the_reason():
    s = catmull_clark(sp.Rational(3, 2) / n**2 + sp.cos(2 * sp.pi / n) ** 2 / (100 * n**2), sp.Rational(1, 4) / n**2)
    step = hyperbolic_dominates_from(s, 5)
    assert step.status == "open" and "E_0 is not a rational function of n" in step.text
