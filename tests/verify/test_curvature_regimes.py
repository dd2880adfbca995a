"""The certified curvature regime (verify/second_order_spectrum.py) and the artifact indicators (verify/artifacts.py).

The regimes by valence are what the shape literature reports for Catmull-Clark and Loop (Karciauskas, Peters,
Reif 2004); each verdict is shown to change when the vertex weights change, and ties are decided exactly.
"""

import flint
import pytest
import sympy as sp

from symdecomp import catmull_clark, loop, loop_warren, symbols
from symdecomp.analysis.curvature_regime import CurvatureRegime
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.analysis.masks import ring_masks
from symdecomp.errors import NotApplicableError
from symdecomp.verify.artifacts import artifact_indicators
from symdecomp.verify.second_order_spectrum import SquareComparison, second_order_eigenstructure

B, Z, U = CurvatureRegime.BOUNDED, CurvatureRegime.ZERO, CurvatureRegime.UNBOUNDED


def _regimes(scheme, valences):
    return [(second_order_eigenstructure(scheme, n).regime, second_order_eigenstructure(scheme, n).cause) for n in valences]


def test_catmull_clark_flat_at_3_bounded_at_4_hyperbolic_divergence_from_5():
    assert _regimes(catmull_clark(), range(3, 13)) == [(Z, "elliptic"), (B, "elliptic, hyperbolic")] + [(U, "hyperbolic")] * 8


def test_loop_outer_divergence_at_3_exact_elliptic_ties_at_4_5_hyperbolic_from_7():
    assert _regimes(loop(), range(3, 11)) == [(U, "regular rules (every frequency)"), (B, "elliptic"), (B, "elliptic"),
                                               (B, "elliptic, hyperbolic")] + [(U, "hyperbolic")] * 4
    r = second_order_eigenstructure(loop(), 3)
    assert r.mu[0].value.contains(flint.fmpq(1, 8)) and r.mu[0].multiplicity == 3  # the outer blocks' 1/8, once per frequency


def test_ties_are_exact_and_the_regular_valence_has_mu_three_times():
    for scheme, n in ((catmull_clark(), 4), (loop(), 6)):
        r = second_order_eigenstructure(scheme, n)
        assert r.regime is B and all(r.compared(e) == SquareComparison(0, True) for e in r.mu)
        assert r.mu_multiplicity == 3 and {e.frequency for e in r.mu} == {0, 2}
    r = second_order_eigenstructure(loop(), 5)  # lambda_1^2 irrational: (3/8 + cos(2 pi/5)/4)^2, an exact tie all the same
    assert r.compared(r.mu[0]).exact and not r.mu[0].value.contains(flint.fmpq(1, 4))


def _off_regular(alpha0, beta0, n0=3):
    """Catmull-Clark with the vertex weights ``alpha0, beta0`` at ``n0``, its own at the regular valence 4 (linear in n)."""
    n, a, b = symbols.n, sp.Rational(3, 2) / symbols.n**2, sp.Rational(1, 4) / symbols.n**2
    return catmull_clark(a + (alpha0 - a.subs(n, n0)) * (n - 4) / (n0 - 4), b + (beta0 - b.subs(n, n0)) * (n - 4) / (n0 - 4))


def _tuned_at_3():
    """Vertex weights that make the frequency-0 roots the squares of the frequency-1 roots at n = 3, solved exactly."""
    a, b, x, n = symbols.alpha, symbols.beta, sp.Symbol("x"), 3
    M, E0 = one_ring_matrices(catmull_clark(a, b))
    q = sp.Poly(sp.cancel((x * sp.eye(3) - E0.subs(symbols.n, n)).det() / (x - 1)), x).all_coeffs()
    Mn = M.subs({symbols.n: n, symbols.omega: sp.exp(2 * sp.pi * sp.I / n)})
    c1, c2 = [sp.simplify(sp.expand_complex(c)) for c in sp.Poly((x * sp.eye(2) - Mn).det(), x).all_coeffs()[1:]]
    assert c1.is_Rational and c2.is_Rational
    solution = sp.solve([q[1] + (c1**2 - 2 * c2), q[2] - c2**2], [a, b], dict=True)[0]
    return solution[a], solution[b]


def test_a_vertex_rule_tuned_to_mu_equal_lambda_1_squared_turns_the_flat_spot_bounded():
    alpha, beta = _tuned_at_3()
    tuned = second_order_eigenstructure(_off_regular(alpha, beta), 3)
    assert tuned.regime is B and tuned.compared(tuned.mu[0]).exact and tuned.mu[0].frequency == 0
    assert second_order_eigenstructure(catmull_clark(), 3).regime is Z
    eps = sp.Rational(1, 1000)
    moved = {second_order_eigenstructure(_off_regular(alpha + d, beta), 3).regime for d in (eps, -eps)}
    assert moved == {Z, U}  # either side of the tie, the other verdict


def test_a_vertex_weight_that_lifts_the_elliptic_eigenvalue_above_lambda_1_squared_makes_it_unbounded():
    for n in (4, 5):  # Warren's 3/(8n): the elliptic eigenvalue is 5/8 - 3/8 = 1/4 above lambda_1^2
        r = second_order_eigenstructure(loop_warren(), n)
        assert (r.regime, r.cause) == (U, "elliptic") and r.mu[0].value.contains(flint.fmpq(1, 4))
        assert second_order_eigenstructure(loop(), n).regime is B
    # Catmull-Clark at n = 3 with a smaller weight on the edge points: the elliptic eigenvalue rises above lambda_1^2
    lifted = second_order_eigenstructure(_off_regular(sp.Rational(1, 8), sp.Rational(1, 64)), 3)
    assert (lifted.regime, lifted.cause) == (U, "elliptic")


def test_no_lambda_1_no_regime_and_schemes_outside_the_test_say_so():
    broken = catmull_clark(sp.Rational(3, 32) * (symbols.n - 3), sp.Rational(1, 64) * (symbols.n - 3))  # alpha = beta = 0 at n = 3
    r = second_order_eigenstructure(broken, 3)
    assert r.regime is CurvatureRegime.NOT_APPLICABLE and "spectral conditions" in r.reason
    with pytest.raises(NotApplicableError):
        second_order_eigenstructure(catmull_clark(symbols.alpha, symbols.beta), 5)


def test_density_is_lambda_1_against_one_half_exact_at_the_regular_valence():
    assert [artifact_indicators(catmull_clark(), n).density_text for n in (3, 4, 5)] == ["dense", "regular", "sparse"]
    assert [artifact_indicators(loop(), n).density_text for n in (5, 6, 7)] == ["dense", "regular", "sparse"]


def _negative_classes_by_ring_masks(scheme, n):
    """The limit mask's negative classes from the certified numeric route of analysis/masks.py (ring_masks)."""
    m = ring_masks(scheme, n, 1, digits=12)["position"]
    out = ["O"] if m["O"].startswith("-") else []
    return tuple(out + [k for k, v in m["classes"].items() if v[0].startswith("-")])


NEGATIVE_FACE = _off_regular(sp.Rational(1, 18), sp.Rational(1, 36) + sp.Rational(1, 20))  # beta = -1/25 at n = 5, -71/490 at n = 7
SCHEMES = [catmull_clark(), NEGATIVE_FACE, _off_regular(sp.Rational(1, 8), sp.Rational(1, 64)), loop(), loop_warren()]


@pytest.mark.parametrize("scheme", SCHEMES, ids=range(len(SCHEMES)))
def test_negative_limit_weights_agree_with_the_numeric_masks(scheme):
    for n in (3, 5, 7):
        assert artifact_indicators(scheme, n).negative_position == _negative_classes_by_ring_masks(scheme, n)


def test_a_negative_vertex_weight_is_flagged():
    assert artifact_indicators(catmull_clark(), 5).negative_position == ()
    assert artifact_indicators(NEGATIVE_FACE, 5).negative_position == ()  # a small negative weight is not yet enough
    assert artifact_indicators(NEGATIVE_FACE, 7).negative_position == ("1,1",)
    assert "limit mask: 1,1" in artifact_indicators(NEGATIVE_FACE, 7).masks_text


def test_the_characteristic_maps_ring_spacing_is_one_exactly_where_the_mesh_is_regular():
    for scheme, regular in ((catmull_clark(), 4), (loop(), 6)):
        assert artifact_indicators(scheme, regular).spacing.contains(1)
        assert artifact_indicators(scheme, 3).spacing > 1 and artifact_indicators(scheme, 8).spacing < 1
    assert artifact_indicators(loop(), 3).spacing.contains(3)  # Loop's characteristic ring at n = 3: 1/4 -> spacing 3


def test_the_shape_indicator_names_the_central_surface_and_the_part_that_dominates():
    regular = artifact_indicators(catmull_clark(), 4).shape
    assert (regular[0], regular[2]) == ("elliptic", None)  # x^2 + y^2; the two parts tie at 1/4
    assert artifact_indicators(catmull_clark(), 5).shape == ("elliptic", "hyperbolic", 2)
    assert artifact_indicators(catmull_clark(), 5).shape_text == "elliptic, hyperbolic part dominates"
    # a vertex rule that lifts the elliptic eigenvalue above the hyperbolic one at n = 5: the elliptic part dominates
    lifted = artifact_indicators(_off_regular(sp.Rational(1, 20), sp.Rational(1, 100), 5), 5)
    assert lifted.shape[2] == 0 and lifted.curvature.cause == "elliptic"
    assert artifact_indicators(loop(), 64).shape[0] == "hybrid"  # elliptic input, yet the curvature changes sign
