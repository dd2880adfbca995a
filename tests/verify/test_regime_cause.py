"""The hyperbolic cause of Catmull-Clark's unbounded curvature for every n >= 5 (issue 32): frequency 0 against a bound
on cos(4 pi/n), rational functions of n."""

from __future__ import annotations

import math

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
