"""The expression parser's additions for the zoo's stencil files: ``m`` and ``j`` in cos/sin arguments over pi, and
``KroneckerDelta`` only when the caller asks for it; everything else is refused as before, in one line."""

from __future__ import annotations

import pytest
import sympy as sp

from symdecomp.errors import InvalidExpressionError
from symdecomp.expressions import parse_expression

n, m, j = sp.Symbol("n", positive=True, integer=True), sp.Symbol("m", positive=True, integer=True), sp.Symbol("j", integer=True)
NAMES = {"n": n, "m": m, "j": j}


def test_doo_sabin_s_corner_weight_is_read_exactly():
    weight = parse_expression("KroneckerDelta(j, 0)/4 + (3 + 2*cos(2*pi*j/m))/(4*m)", NAMES, kronecker=True)
    assert weight.subs({m: 4, j: 0}) == sp.Rational(9, 16) and weight.subs({m: 4, j: 2}) == sp.Rational(1, 16)
    assert sum(weight.subs({m: 6, j: k}) for k in range(6)).equals(1)


@pytest.mark.parametrize(("text", "kronecker", "message"), [
    ("KroneckerDelta(j, 0)", False, "calls only sqrt, cos, sin"),
    ("KroneckerDelta(j, 1/2)", True, "KroneckerDelta takes integer polynomials in the names, got 1/2"),
    ("KroneckerDelta(j)", True, "KroneckerDelta takes two arguments"),
    ("KroneckerDelta", True, "unknown name 'KroneckerDelta' (known: j, m, n, pi)"),
    ("cos(pi/j)", False, "the argument over pi must have a denominator d or d*n"),
    ("cos(2*pi*j/(n*m))", False, "the argument over pi must have a denominator d or d*n"),
    ("cos(j)", False, "only rational multiples of pi"),
])
def test_what_the_additions_still_refuse(text, kronecker, message):
    with pytest.raises(InvalidExpressionError) as caught:
        parse_expression(text, NAMES, kronecker=kronecker)
    assert str(caught.value).startswith(f"expression {text!r}: ") and message in str(caught.value)


def test_m_and_j_are_names_only_where_the_caller_gives_them():
    with pytest.raises(InvalidExpressionError, match="unknown name 'j'"):
        parse_expression("cos(2*pi*j/n)", {"n": n})
