"""Issue 32 item 1: a weight that is a long polynomial in n is checked for affinity by polynomial arithmetic.

Catmull-Clark's vertex weights times 1 - L(n), with L the Lagrange basis polynomial of degree 17 that is 1 at n = 7
and 0 at 3..6 and 8..20: Catmull-Clark's rule except a fixed centre at n = 7. Reading it used to run sp.simplify on
the affinity sum, which did not return in ten minutes; a question at one valence substitutes n first.
"""

from __future__ import annotations

import math
import signal

import pytest
import sympy as sp

from symdecomp.errors import NotAffineError
from symdecomp.expressions import identically_zero
from symdecomp.schemes.files import scheme_from_text
from symdecomp.schemes.scheme import VertexRule, subdivision_matrix
from symdecomp.symbols import n

NODES = [k for k in range(3, 21) if k != 7]
LAGRANGE = "*".join(f"(n - {k})" for k in NODES) + f"/({math.prod(7 - k for k in NODES)})"
TEXT = f'''name = "fixed centre at 7"
[edge]
O = "3/8"
a = {{ "-1" = "1/16", "0" = "3/8", "1" = "1/16" }}
b = {{ "-1" = "1/16", "0" = "1/16" }}
[face]
O = "1/4"
a = {{ "0" = "1/4", "1" = "1/4" }}
b = {{ "0" = "1/4" }}
[vertex]
a = "3/(2*n**2)*(1 - {LAGRANGE})"
b = "1/(4*n**2)*(1 - {LAGRANGE})"
'''


@pytest.fixture
def deadline():
    """Fail (instead of hanging) if the body takes more than a minute."""
    def expire(*_):
        raise TimeoutError("no answer within 60 s")
    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(60)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, previous)


def test_the_degree_17_file_reads_and_answers_at_n_7(deadline):
    from symdecomp.verify.c1 import c1_test

    s = scheme_from_text(TEXT)
    assert len(NODES) == 17 and sp.degree(sp.numer(sp.together(s.vertex_rule.each_a)), n) == 17
    row = subdivision_matrix(s, 7)[0, :]
    assert list(row) == [1] + [0] * 14  # the fixed centre at n = 7 ...
    assert subdivision_matrix(s, 5)[0, :5] == sp.Matrix([[Q(13, 20), Q(3, 50), Q(3, 50), Q(3, 50), Q(3, 50)]])  # ... CC's at 5
    r = c1_test(s, 7)
    assert r.verdict == "not-c1" and "frequency 0" in r.reason


Q = sp.Rational


def test_identically_zero_decides_by_cancellation():
    lagrange = sp.sympify(LAGRANGE.replace("n", "m")).subs(sp.Symbol("m"), n)
    assert identically_zero(sp.expand(lagrange) - lagrange)
    assert not identically_zero(lagrange - 1)
    # cosines: cos(2 pi/n) = 2 cos(pi/n)^2 - 1 is an identity that cancellation alone does not see
    assert identically_zero(sp.cos(2 * sp.pi / n) - 2 * sp.cos(sp.pi / n) ** 2 + 1)
    assert not identically_zero(sp.cos(2 * sp.pi / n) - sp.cos(sp.pi / n))


def test_a_long_weight_that_is_not_affine_is_refused_in_one_line(deadline):
    with pytest.raises(NotAffineError, match="not affine"):
        VertexRule.from_weights(1, sp.sympify(LAGRANGE.replace("n", "m")).subs(sp.Symbol("m"), n), 0)
