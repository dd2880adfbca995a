"""One home for the number conversions (symdecomp.algebra.numbers): each is exact, and refuses what is not a rational."""

from fractions import Fraction

import flint
import mpmath
import pytest
import sympy as sp

from symdecomp.algebra.numbers import to_arb, to_fmpq, to_fraction, to_mpf, to_sympy
from symdecomp.errors import InvalidInputError

#: The same rational, -7/12, as every exact type the package uses (and an integer, 5).
FORMS = [Fraction(-7, 12), sp.Rational(-7, 12), flint.fmpq(-7, 12)]
INTEGERS = [5, Fraction(5), sp.Integer(5), flint.fmpq(5), flint.fmpz(5)]


@pytest.mark.parametrize("x", FORMS, ids=lambda x: type(x).__name__)
def test_every_form_converts_to_every_type_exactly(x):
    assert to_fraction(x) == Fraction(-7, 12) and type(to_fraction(x)) is Fraction
    assert to_fmpq(x) == flint.fmpq(-7, 12) and type(to_fmpq(x)) is flint.fmpq
    assert to_sympy(x) - sp.Rational(-7, 12) == 0 and isinstance(to_sympy(x), sp.Rational)
    assert to_arb(x).contains(flint.fmpq(-7, 12)) and to_arb(x).rad() < 2.0**-50


@pytest.mark.parametrize("x", INTEGERS, ids=lambda x: type(x).__name__)
def test_integers_keep_denominator_one(x):
    assert (to_fraction(x).denominator, to_fmpq(x).q, to_sympy(x).q) == (1, 1, 1)
    assert to_arb(x).is_exact() and to_arb(x) == 5


def test_dyadic_balls_are_exact_and_mpf_is_correctly_rounded():
    assert to_arb(Fraction(3, 8)).is_exact() and to_arb(Fraction(3, 8)) == flint.arb(0.375)
    with mpmath.workdps(40):
        assert abs(to_mpf(sp.Rational(1, 3)) - mpmath.mpf(1) / 3) == 0
        assert mpmath.almosteq(to_mpf(flint.fmpq(-7, 12)) * 12, -7, rel_eps=mpmath.mpf(10) ** -39)


@pytest.mark.parametrize("bad", [0.5, "1/2", sp.sqrt(2), sp.Symbol("n"), None])
def test_what_is_not_an_exact_rational_is_refused_in_one_line(bad):
    for convert in (to_fraction, to_fmpq, to_arb, to_mpf):
        with pytest.raises(InvalidInputError, match="expected an exact rational number"):
            convert(bad)


def test_sympy_objects_pass_through_to_sympy_unchanged():
    n = sp.Symbol("n")
    assert to_sympy(n / 2) == n / 2 and to_sympy(sp.sqrt(2)) is sp.sqrt(2)
