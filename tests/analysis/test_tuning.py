"""Tuning the vertex rule: each condition alone, both together; checked against the exact matrices."""

import json

import mpmath
import pytest
import sympy as sp

from symdecomp.analysis.elliptic import MU, eq44_ratio, nice_elliptic_conditions, recursion_eigenvector
from symdecomp.analysis.tuning import condition_line, joint_obstruction, ratio_target, tune
from symdecomp.cli import main
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import cos_theta
from symdecomp.symbols import n as N

CC = catmull_clark()


def _tuned_scheme_in_mu():
    """Catmull-Clark with alpha on the condition line for a symbolic target MU and the standard beta."""
    line = condition_line(CC, MU)
    std_beta = CC.vertex_rule.each_b
    return catmull_clark(alpha=line.alpha_on_line.subs(BETA, std_beta), beta=std_beta)


@pytest.mark.parametrize("n", [3, 4, 5, 8, 13, 50])
def test_line_makes_the_target_an_exact_eigenvalue(n):
    _check_line_exactly(n)


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 51))
def test_line_makes_the_target_an_exact_eigenvalue_all_valences(n):
    _check_line_exactly(n)
    t = tune(CC, n)
    assert t.jointly_possible == (n == 4)
    assert t.standard_beta_admissible == (True, True) and t.below_lambda1 == (True, True)


def _check_line_exactly(n):
    # Identically in MU: S(alpha(MU)) V(MU) = MU V(MU), with V the lifted Eq. 43 eigenvector.
    scheme = _tuned_scheme_in_mu()
    (target,) = scheme.parameters  # MU, in the users' namespace (a Parameter named MU)
    S = subdivision_matrix(scheme, n).subs(target, MU)
    u = recursion_eigenvector(CC, MU, n)
    V = sp.Matrix([u[0]] + [u[1]] * n + [u[2]] * n)
    residual = S * V - MU * V
    assert all(sp.cancel(e) == 0 for e in residual)
    # and V's Eq. 44 ratio is the vertex-rule-free formula
    assert sp.cancel((V[n + 1] - V[0]) / (V[1] - V[0]) - eq44_ratio(CC, MU)) == 0


def test_ratio_target_has_the_required_ratio():
    R = nice_elliptic_conditions(CC).scale_ratio_squared
    assert sp.simplify(eq44_ratio(CC, MU).subs(MU, ratio_target(CC)) - R) == 0


def _numeric_matrix(S, dps):
    return mpmath.matrix([[mpmath.mpf(sp.Float(sp.N(e, dps + 10), dps + 10)._mpf_) for e in row] for row in S.tolist()])


@pytest.mark.parametrize("n", [3, 5, 7])
def test_tuned_weights_give_the_spectrum_claimed(n):
    t = tune(CC, n)
    with mpmath.workdps(30):
        lam1 = mpmath.mpf(str(sp.N(t.lambda1, 40)))
        for (a, b), line in zip(t.at_standard_beta, (t.eigenvalue_condition, t.ratio_condition)):
            M = _numeric_matrix(subdivision_matrix(CC, n), 30)
            # put the tuned vertex row in (exactly as the rule says: centre 1 - n alpha - n beta)
            a_num = mpmath.mpf(str(sp.N(a, 40)))
            b_num = mpmath.mpf(str(sp.N(b, 40)))
            M[0, 0] = 1 - n * a_num - n * b_num
            for i in range(n):
                M[0, 1 + i], M[0, 1 + n + i] = a_num, b_num
            ev = sorted((mpmath.re(v) for v in mpmath.eig(M, left=False, right=False)), reverse=True)
            goal = mpmath.mpf(str(sp.N(line.target, 40)))
            assert abs(ev[0] - 1) < mpmath.mpf(10) ** -25
            assert abs(ev[1] - lam1) < mpmath.mpf(10) ** -25  # tangent plane untouched
            assert min(abs(v - goal) for v in ev) < mpmath.mpf(10) ** -25
    assert t.standard_beta_admissible == (True, True) and t.below_lambda1 == (True, True)


def test_joint_obstruction_only_n4():
    j = joint_obstruction(CC)
    assert j.valences == (4,)
    c = cos_theta  # cos(pi/n)
    assert sp.expand(j.polynomial - c**4 * (2 * c**2 - 1) * (4 * c**4 + 10 * c**2 - 25) / 4) == 0
    assert sp.simplify(j.defect.subs(N, 4)) == 0
    assert sp.N(j.defect.subs(N, 5)) < 0


def test_n4_standard_weights_satisfy_both():
    t = tune(CC, 4)
    assert t.jointly_possible
    for a, _b in t.at_standard_beta:
        assert sp.simplify(a - sp.Rational(3, 32)) == 0


def test_cli_tune_json_and_table(capsys):
    assert main(["tune", "50", "--json", "--digits", "12"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["n"] == 50 and data["jointly_possible"] is False
    assert set(data["eigenvalue_condition"]) >= {"target", "alpha", "beta", "beta_interval"}
    assert main(["tune", "6", "--table", "--json", "--digits", "10"]) == 0
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert [r["n"] for r in rows] == [3, 4, 5, 6]
    assert rows[1]["eigenvalue_defect"] == "0.0" and rows[1]["ratio_defect"] == "0.0"


def test_cli_tune_rejects_bad_valence(capsys):
    assert main(["tune", "2"]) == 2
    assert "valence" in capsys.readouterr().err


def test_condition_one_line_is_a_closed_form_in_n():
    cond = nice_elliptic_conditions(CC)
    line = condition_line(CC, cond.lambda1**2)
    alpha_n = line.alpha_on_line.subs(BETA, CC.vertex_rule.each_b)
    assert alpha_n.free_symbols == {N}
    assert sp.simplify(alpha_n.subs(N, 4) - sp.Rational(3, 32)) == 0  # the standard weight already works at n = 4
    with mpmath.workdps(30):  # and agrees with tune() at another valence
        t = tune(CC, 9)
        assert abs(mpmath.mpf(str(sp.N(alpha_n.subs(N, 9) - t.at_standard_beta[0][0], 40)))) < mpmath.mpf(10) ** -25


def test_tune_rejects_free_parameters():
    from symdecomp.errors import InvalidSchemeError
    from symdecomp.symbols import alpha

    with pytest.raises(InvalidSchemeError, match="free parameters"):
        tune(catmull_clark(alpha, BETA), 5)
