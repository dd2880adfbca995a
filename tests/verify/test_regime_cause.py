"""The hyperbolic cause of Catmull-Clark's unbounded curvature for every n >= 5 (issue 32): frequency 0 against a bound
on cos(4 pi/n), rational functions of n."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import n as N
from symdecomp.verify.regime_cause import frequency_zero_below_hyperbolic, hyperbolic_cause_on_quads
from symdecomp.verify.regime_every_n import hyperbolic_cause_from


def test_catmull_clark_frequency_zero_is_below_the_hyperbolic_eigenvalue_from_9():
    start, how = frequency_zero_below_hyperbolic(catmull_clark())
    assert start == 9 and "t_n = 1 - 3872/(49*n**2)" in how
    # the bound t_n is below cos(4 pi/n) (cos x >= 1 - x^2/2, pi < 22/7) and tends to it
    t_n = 1 - 8 * sp.Rational(22, 7) ** 2 / N**2
    assert all(float(t_n.subs(N, n)) < math.cos(4 * math.pi / n) for n in (9, 10, 100, 10**4))


def test_the_cause_is_proved_for_every_n_from_5():
    """n = 5..8 certified one by one, n >= 9 by the signs in n; the claim's statement is then proved."""
    step = hyperbolic_cause_from(catmull_clark(), 5)
    assert step is not None and step.status == "proved" and step.valences == (5, None)
    assert "at n = 5..8 certified one by one" in step.text


def test_an_elliptic_eigenvalue_above_the_hyperbolic_one_is_not_called_below():
    """Vertex weights 3/(2 n^2) - (n - 4)/100, 1/(4 n^2): the larger frequency-0 eigenvalue besides 1 is above the
    hyperbolic one from n = 5 (0.364 against 0.340) and grows without bound (3.74 at n = 20): no start, no proof."""
    s = catmull_clark(sp.Rational(3, 2) / N**2 - (N - 4) / 100, sp.Rational(1, 4) / N**2)
    assert frequency_zero_below_hyperbolic(s) is None
    assert hyperbolic_cause_on_quads(s, 5) is None


#: Catmull-Clark with a vertex weight alpha that has a term in cos(2 pi/n), zero at n = 3 and n = 4 (cos = -1/2, 0).
COS_VERTEX = """name = "cos-vertex"
[edge]
O = "3/8"
a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }
b = { "-1" = "1/16", "0" = "1/16" }
[face]
O = "1/4"
a = { "0" = "1/4", "1" = "1/4" }
b = { "0" = "1/4" }
[vertex]
a = "3/(2*n**2) + (2*cos(2*pi/n) + 1)*cos(2*pi/n)/(1000*n**2)"
b = "1/(4*n**2)"
"""


@pytest.mark.slow
def test_a_vertex_rule_in_cos_2pi_over_n_is_not_shown_rather_than_a_polynomial_error():
    """q's coefficients are not rational in n, so the signs in n do not apply: ``None`` (not shown), not sympy's
    PolynomialError; the rest of the regime's argument still runs."""
    from symdecomp.analysis.frequency import one_ring_matrices
    from symdecomp.schemes.files import scheme_from_text

    s = scheme_from_text(COS_VERTEX)
    _, E0 = one_ring_matrices(s)
    assert sp.Matrix(E0).has(sp.cos(2 * sp.pi / N))  # what the signs in n cannot take
    assert frequency_zero_below_hyperbolic(s) is None
    assert hyperbolic_cause_on_quads(s, 5) is None


def test_artifacts_every_n_reaches_it_and_answers(tmp_path, capsys):
    """``artifacts --every-n`` asked it and stopped with an internal error; now the regime is proved and its cause left
    out (not shown), exit code 0."""
    from symdecomp.cli import main

    path = tmp_path / "cos-vertex.toml"
    path.write_text(COS_VERTEX)
    assert main(["artifacts", "--every-n", "--scheme", str(path), "--quiet"]) == 0
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    assert captured.err == "" and lines[0] == "cos-vertex: the curvature regime at the extraordinary vertex, every valence"
    assert lines[2].startswith("  [proved] n >= 5: for every n >= 5 the hyperbolic eigenvalue exceeds lambda_1^2")
    assert not any("is the largest after 1 and lambda_1" in line for line in lines)
