"""Closed forms with fourth and eighth roots compile to principal roots, and an unsupported one fails in one short line."""

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.errors import UnsupportedExpressionError

x = sp.Symbol("x")


@pytest.mark.parametrize("exponent", [sp.Rational(1, 4), sp.Rational(3, 4), sp.Rational(-5, 8), sp.Rational(7, 2)])
@pytest.mark.parametrize("value", [mpmath.mpf(2) / 7, mpmath.mpc(-3, 1) / 5, mpmath.mpc(-2, 0), mpmath.mpc(0, -1)])
def test_power_of_two_denominators_are_the_principal_power(exponent, value):
    with mpmath.workdps(40):
        expected = mpmath.power(mpmath.mpc(value), mpmath.mpf(exponent.p) / exponent.q)  # exp(p/q log z), principal
        got = compile_expression(x**exponent, (x,))(mpmath.mpc(value))
        assert abs(got - expected) < mpmath.mpf(10) ** -30
    with flint.ctx.workprec(160):
        ball = compile_expression(x**exponent, (x,), engine="arb")(flint.acb(str(value.real), str(value.imag))
                                                                  if isinstance(value, mpmath.mpc) else flint.acb(str(value)))
        mid = mpmath.mpc(mpmath.mpf(ball.real.mid().str(40, radius=False)), mpmath.mpf(ball.imag.mid().str(40, radius=False)))
        assert abs(mid - expected) < mpmath.mpf(10) ** -12  # decimal input rounded to 15 digits by str()


def test_a_fourth_root_squared_twice_is_its_radicand_exactly_in_arb():
    f = compile_expression(x ** sp.Rational(1, 4), (x,), engine="arb")
    with flint.ctx.workprec(128):
        ball = f(flint.acb(flint.fmpq(5, 3)))
        assert (ball**4 - flint.fmpq(5, 3)).contains(0)
        assert abs(ball**4 - flint.fmpq(5, 3)).upper() < flint.arb(2) ** -100


def test_other_denominators_stay_unsupported_in_one_short_line():
    long = sum(x**k / (k + 1) for k in range(200))
    with pytest.raises(UnsupportedExpressionError) as caught:
        compile_expression(long ** sp.Rational(1, 3), (x,), engine="arb")
    message = str(caught.value)
    assert "\n" not in message and len(message) < 400
    assert "more characters; a Pow" in message
