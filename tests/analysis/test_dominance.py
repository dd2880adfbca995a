"""The tail bound of Proposition 5.1 (symdecomp.analysis.dominance): its facts hold, and it refuses a false tail."""

import mpmath
import sympy as sp

from symdecomp.analysis.dominance import COS_LOWER, tail_bound
from symdecomp.analysis.spectrum import recursion_eigenvalues
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import cos_jtheta, n


def test_catmull_clark_tail_starts_at_4_and_its_facts_are_positive_there():
    bound = tail_bound(catmull_clark())
    assert bound is not None and bound.start == 4
    for fact in bound.facts:
        assert all(fact.subs(n, m) > 0 for m in (4, 5, 10, 100, 10**6))


def test_cos_lower_bound_is_below_cos_pi_over_n():
    for m in (3, 4, 7, 50, 10**4):
        assert sp.N(sp.cos(sp.pi / m) - COS_LOWER.subs(n, m), 30) > 0


def test_no_bound_where_the_inequality_fails_for_large_n():
    # mu tends to 0.6546 > lambda_1's limit 0.6545: the proposition fails beyond some n, so no tail bound may exist
    scheme = catmull_clark(sp.Rational(3, 2) / n**2 - sp.Rational(1, 3000) / n, sp.Rational(1, 4) / n**2)
    assert tail_bound(scheme) is None
    dominant = tangent_eigenvalues(scheme).dominant
    with mpmath.workdps(40):
        m = 10**6
        lam1 = sp.N(dominant.subs(cos_jtheta, sp.cos(sp.pi / m)), 40)
        mu = max(abs(sp.N(e.subs(n, m), 40)) for e in recursion_eigenvalues(scheme) if e != 1)
    assert mu > lam1
