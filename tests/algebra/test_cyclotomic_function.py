"""An expression read once (``CyclotomicFunction``) and evaluated at many valences equals the expression
substituted by sympy at each (``cyclotomic_value``), exactly; what is not of that kind is refused."""

from fractions import Fraction

import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.algebra.cyclotomic import CyclotomicField, CyclotomicFunction, cyclotomic_value
from symdecomp.symbols import n as N

x = sp.Symbol("x")


@pytest.mark.parametrize("weight", ["center", "each_a"])
def test_loop_centre_weights_at_every_valence(weight):
    expr = sp.sympify(getattr(sd.loop().vertex_rule, weight))
    f = CyclotomicFunction(expr, N)
    for n in range(3, 41):
        field = CyclotomicField(2 * n)
        assert (f(n, field) - cyclotomic_value(expr, {N: n}, field=field)).poly == 0


def test_sines_exponentials_and_rational_arguments():
    expr = sp.sin(sp.pi / x) ** 2 * sp.exp(sp.I * 3 * sp.pi / (2 * x)) - sp.cos(sp.pi * (x + 1) / (3 * x)) / (x - 1)
    f = CyclotomicFunction(expr, x)
    for value in (2, 3, 5, Fraction(3, 2)):
        field = cyclotomic_value(expr, {x: value}).field
        big = CyclotomicField(4 * field.N)  # a larger field holds the same number
        assert (f(value, big) - cyclotomic_value(expr, {x: value}, field=big)).poly == 0
    # sin^2(pi/4) = 1/2 exactly, read in Q(zeta_8)
    assert (CyclotomicFunction(sp.sin(sp.pi / x) ** 2, x)(4, CyclotomicField(8)) - Fraction(1, 2)).poly == 0


def test_what_is_not_a_cyclotomic_number_is_refused():
    with pytest.raises(ValueError, match="not a rational function of roots of unity"):
        CyclotomicFunction(sp.sqrt(x) + 1, x)
    with pytest.raises(ValueError, match="not a cosine, sine or exponential of a rational multiple of pi"):
        CyclotomicFunction(sp.cos(sp.pi * x ** sp.Rational(1, 2)), x)
    with pytest.raises(ValueError, match=r"not in Q\(zeta_6\)"):
        CyclotomicFunction(sp.cos(2 * sp.pi / x), x)(4, CyclotomicField(6))
    with pytest.raises(ValueError, match="not defined at 0"):
        CyclotomicFunction(sp.cos(2 * sp.pi / x), x)(0, CyclotomicField(6))


@pytest.mark.parametrize("N", [3, 4, 5, 8, 12, 20, 24, 60])
def test_to_sympy_is_expanded_and_the_number(N):
    # to_sympy builds the sum without sp.expand: it must already be expanded, and be the number to_mpc gives
    import mpmath

    field = CyclotomicField(N)
    zeta = field.root(N, 1)
    for coeffs in ([1], [0, 1], [Fraction(3, 7), -2, 0, Fraction(1, 5)], [Fraction(k * k - 3, k + 1) for k in range(N)]):
        x = field(0)
        for k, c in enumerate(coeffs):
            x = x + field(c) * zeta**k
        value = x.to_sympy()
        assert value == sp.expand(value)
        with mpmath.workdps(40):
            near = sp.N(value, 40)
            assert abs(mpmath.mpc(str(sp.re(near)), str(sp.im(near))) - x.to_mpc()) < mpmath.mpf(10) ** -35


def test_a_given_root_of_unity_is_the_exponential_substituted():
    """``omega`` given as ``zeta_2n^(2j)`` gives what substituting ``exp(2 pi i j/n)`` gives (the C1 test's blocks)."""
    from symdecomp.analysis.frequency import one_ring_matrices
    from symdecomp.symbols import omega

    M = one_ring_matrices(sd.loop())[0][0, 0] + one_ring_matrices(sd.catmull_clark())[0].det()
    f = CyclotomicFunction(M, N, (omega,))
    for n in (3, 5, 8):
        field = CyclotomicField(2 * n)
        for j in range(n):
            substituted = M.xreplace({omega: sp.exp(2 * sp.pi * sp.I * sp.Rational(j, n))})
            assert (f(n, field, field.zeta(2 * j)) - cyclotomic_value(substituted, {N: n}, field=field)).poly == 0
