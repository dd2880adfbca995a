"""The exact tuning region (issue 21, item 5): Catmull-Clark's edge and face rules with free (alpha, beta), and
Loop's edge rule with a free beta."""

import numpy as np
import pytest
import sympy as sp

from symdecomp.algebra.algebraic_sign import exact_sign
from symdecomp.analysis.curvature_regime import CurvatureRegime as Regime
from symdecomp.analysis.tuning_region import interval_region, placed_points, tuning_region
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import scheme_from_text, scheme_to_text
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N

_X = sp.Symbol("x")


def cc_free():
    text = scheme_to_text(catmull_clark()).replace('a = "3/(2*n**2)"', 'a = "alpha"').replace('b = "1/(4*n**2)"', 'b = "beta"')
    return scheme_from_text('parameters = ["alpha", "beta"]\n' + text.replace('name = "catmull-clark"', 'name = "cc-free"'))


def loop_free():
    text = scheme_to_text(loop())
    head, _, _ = text.partition("[vertex]")
    return scheme_from_text('parameters = ["beta"]\n' + head + '[vertex]\nbeta = "beta"\n')


def is_zero(expr) -> bool:
    return sp.minimal_polynomial(sp.expand(expr), _X) == _X


OUTER = (sp.Rational(1, 8),)  # the largest outer eigenvalue of both regular rules (Catmull-Clark 1/8..1/64, Loop 1/8, 1/16)


def numeric_mu_vs_square(scheme, region, point, outer=OUTER):
    """Independent check: the eigenvalues of the 1-ring subdivision matrix (LAPACK, doubles) at the point; the callers
    only use it where the exact gap is far larger than the rounding."""
    concrete = scheme.substitute(dict(zip(region.parameters, point)))
    S = np.array(subdivision_matrix(concrete, region.n).evalf(30).tolist(), dtype=float)
    ev = sorted(np.abs(np.linalg.eigvals(S)), reverse=True)
    lam1 = float(sp.N(region.lambda1, 30))
    assert abs(ev[0] - 1) < 1e-9 and abs(ev[1] - lam1) < 1e-9 and abs(ev[2] - lam1) < 1e-9
    mu = max([ev[3]] + [float(o) for o in outer])
    return mu - lam1**2


def test_n4_standard_weights_on_the_bounded_set():
    scheme = cc_free()
    region = tuning_region(scheme, 4)
    cc = (sp.Rational(3, 32), sp.Rational(1, 64))
    assert region.fixed_vs_square == 0  # the frequency-2 eigenvalue 1/4 equals lambda_1^2 at n = 4
    assert region.lambda1 == sp.Rational(1, 2)
    assert region.classify(cc) is Regime.BOUNDED
    assert region.signs(cc)[1][0] == 0  # Q(lambda_1^2) = 0: 1/4 is an eigenvalue of T
    T = subdivision_matrix(catmull_clark(), 4)
    assert (T - sp.eye(T.rows) / 4).det() == 0
    # moving beta down makes Q(1/4) < 0: a root of Q above 1/4, so mu > lambda_1^2
    assert region.classify((cc[0], cc[1] - sp.Rational(1, 64))) is Regime.UNBOUNDED
    assert numeric_mu_vs_square(scheme, region, (cc[0], cc[1] - sp.Rational(1, 64))) > 1e-6
    assert region.classify((cc[0], cc[1] + sp.Rational(1, 64))) is Regime.BOUNDED  # nothing is below lambda_1^2 at n = 4
    assert region.conditions()[Regime.ZERO] == []


def test_moving_off_the_curve_changes_regime_as_predicted():
    scheme = cc_free()
    region = tuning_region(scheme, 3)
    label, point = next(p for p in placed_points(scheme, 3) if p[0] == "paper 5.2 condition 1")
    assert region.classify(point) is Regime.BOUNDED
    form = region.square_forms[0].expr  # Q(lambda_1^2), zero on the curve
    assert is_zero(form.subs(dict(zip(region.parameters, point))))
    alpha = region.parameters[0]
    slope = exact_sign(sp.diff(form, alpha))
    eps = sp.Rational(1, 1000)
    up = (point[0] + slope * eps, point[1])
    down = (point[0] - slope * eps, point[1])
    assert region.classify(up) is Regime.ZERO  # Q(lambda_1^2) > 0 with the other conditions kept: both roots below
    assert region.classify(down) is Regime.UNBOUNDED
    assert numeric_mu_vs_square(scheme, region, up) < -1e-6
    assert numeric_mu_vs_square(scheme, region, down) > 1e-6


@pytest.mark.parametrize("n, regime", [(3, Regime.BOUNDED), (4, Regime.BOUNDED), pytest.param(5, Regime.UNBOUNDED, marks=pytest.mark.slow),
                                      (6, Regime.UNBOUNDED)])
def test_paper_tuning_has_eigenvalue_lambda1_squared(n, regime):
    scheme = cc_free()
    region = tuning_region(scheme, n)
    point = dict(placed_points(scheme, n))["paper 5.2 condition 1"]
    values = dict(zip(region.parameters, point))
    # exactly: lambda_1^2 is a root of det(x - T)/(x - 1) at the paper's weights
    assert is_zero(sp.sympify(region.quadratic).subs(values).subs(LAM, region.lambda1**2))
    assert region.classify(point) is regime
    # m (weight-independent) against lambda_1^2 decides n >= 5: the frequency-2 eigenvalue is larger
    assert region.fixed_vs_square == (-1 if n == 3 else 0 if n == 4 else 1)
    if n >= 5:
        assert numeric_mu_vs_square(scheme, region, point) > 1e-3


@pytest.mark.parametrize("n, expected", [
    (3, {"Catmull-Clark": Regime.ZERO, "paper 5.2 condition 2": Regime.UNBOUNDED}),
    (4, {"Catmull-Clark": Regime.BOUNDED, "paper 5.2 condition 2": Regime.BOUNDED}),
    pytest.param(5, {"Catmull-Clark": Regime.UNBOUNDED, "paper 5.2 condition 2": Regime.UNBOUNDED}, marks=pytest.mark.slow),
])
def test_published_weights_placed(n, expected):
    scheme = cc_free()
    region = tuning_region(scheme, n)
    points = dict(placed_points(scheme, n))
    for name, regime in expected.items():
        assert region.classify(points[name]) is regime, name
        if regime is not Regime.BOUNDED:
            gap = numeric_mu_vs_square(scheme, region, points[name])
            assert (gap < 0) == (regime is Regime.ZERO)


@pytest.mark.parametrize("n", [3, 4])
def test_corners_of_the_closed_set(n):
    """Q(lambda_1^2) = Q(-lambda_1^2) = 0: roots +-lambda_1^2, bounded. Where Q has a double root +-lambda_1^2 the
    block T is not diagonalizable ((T - r)(T - 1) != 0, so its minimal polynomial has (x - r)^2): unbounded."""
    region = tuning_region(cc_free(), n)
    forms = [f.expr for f in region.square_forms]
    sol = sp.solve([forms[0], forms[1]], region.parameters, dict=True)[0]
    assert is_zero(forms[0].subs(sol)) and is_zero(forms[1].subs(sol))
    assert region.classify(tuple(sp.radsimp(sol[v]) for v in region.parameters)) is Regime.BOUNDED
    corners = region.corners()
    assert [c[0] for c in corners] == ["lambda_1^2", "-lambda_1^2"]
    for name, point, jordan in corners:
        values = dict(zip(region.parameters, point))
        r = region.lambda1**2 * (1 if name == "lambda_1^2" else -1)
        assert is_zero(forms[2].subs(values))  # q = lambda_1^4: a double root
        T = region.block.subs(values)
        product = ((T - r * sp.eye(3)) * (T - sp.eye(3))).applyfunc(sp.expand)
        assert jordan == any(not is_zero(e) for e in product)
        assert jordan and region.classify(point) is Regime.UNBOUNDED


def test_loop_intervals_exact_and_loop_warren_placed():
    scheme = loop_free()
    region = tuning_region(scheme, 5)
    pieces = interval_region(region)
    assert [p.regime for p in pieces] == [Regime.NOT_APPLICABLE, Regime.UNBOUNDED, Regime.BOUNDED, Regime.ZERO, Regime.BOUNDED,
                                          Regime.UNBOUNDED, Regime.NOT_APPLICABLE]
    forms = [f.expr for f in region.c1_forms + region.square_forms]
    for piece in pieces:
        for end in (piece.lo, piece.hi):
            if end is not None:  # every end is a root of a defining form, exactly
                assert any(is_zero(f.subs(region.parameters[0], end)) for f in forms)
    points = dict(placed_points(scheme, 5))
    assert region.classify(points["Loop"]) is Regime.BOUNDED  # Loop's beta puts 5/8 - n beta at lambda_1^2
    assert region.classify(points["Warren"]) is Regime.UNBOUNDED
    assert numeric_mu_vs_square(scheme, region, points["Warren"]) > 1e-6
    at7 = tuning_region(scheme, 7)
    assert at7.fixed_vs_square == 1  # frequency 2 beats lambda_1^2: no beta bounds the curvature
    assert at7.conditions()[Regime.BOUNDED] == [] and at7.conditions()[Regime.ZERO] == []


def test_refused_schemes():
    with pytest.raises(NotApplicableError, match="no free parameters"):
        tuning_region(catmull_clark(), 5)
    text = scheme_to_text(catmull_clark()).replace('a = "3/(2*n**2)"', 'a = "alpha + gamma"').replace('b = "1/(4*n**2)"', 'b = "beta"')
    three = scheme_from_text('parameters = ["alpha", "beta", "gamma"]\n' + text)
    with pytest.raises(NotApplicableError, match="3 parameters"):
        tuning_region(three, 5)
    square = scheme_from_text('parameters = ["alpha", "beta"]\n' + text.replace("alpha + gamma", "alpha**2"))
    with pytest.raises(NotApplicableError, match="not affine"):
        tuning_region(square, 5)
    assert N not in region_symbols(tuning_region(cc_free(), 5))


def region_symbols(region):
    return set().union(*(f.expr.free_symbols for f in region.c1_forms + region.square_forms))
