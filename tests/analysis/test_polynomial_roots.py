"""The certified roots of the printed characteristic polynomial (``charpoly --plot``) are the spectrum: each root's
ball meets the ball of one eigenvalue of :func:`~symdecomp.analysis.spectrum.ring_spectrum` (found from the frequency
blocks, not from the polynomial), with the same multiplicity."""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from symdecomp.analysis.charpoly import ring_charpoly_exact
from symdecomp.analysis.polynomial_roots import polynomial_roots
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.errors import SymdecompError
from symdecomp.schemes.files import load_scheme


@pytest.mark.parametrize("name, n, rings", [("catmull-clark", 5, 1), ("loop", 7, 1), ("catmull-clark", 4, 2)])
def test_the_roots_are_the_eigenvalues_with_their_multiplicities(name, n, rings):
    scheme = load_scheme(name)
    coefficients = ring_charpoly_exact(scheme, n, rings)[1]
    roots = polynomial_roots(coefficients)
    spectrum = ring_spectrum(scheme, n, rings, digits=30, exact=False, jordan=False)
    found = sorted((next(i for i, e in enumerate(spectrum.eigenvalues) if e.value.overlaps(z)), m) for z, m in roots.roots)
    assert found == sorted(enumerate(e.multiplicity for e in spectrum.eigenvalues))
    assert roots.degree == len(coefficients) - 1
    assert roots.one_is_root and all(z.rad() < 1e-25 for z, _ in roots.roots)


def test_lambda_1_is_the_largest_modulus_once_the_root_one_is_taken_away():
    x = sp.Rational
    # (x - 1)(x - 1/2)^2 (x + 1/4): lambda_1 = 1/2; (x - 1)^2 (x - 1/3): lambda_1 = 1; (x - 2)(x - 1/3): no root 1
    assert abs(float(polynomial_roots([1, x(-7, 4), x(3, 4), x(1, 16), x(-1, 16)]).lambda_1) - 0.5) < 1e-25
    twice = polynomial_roots([sp.Integer(1), x(-7, 3), x(5, 3), x(-1, 3)])
    assert float(twice.lambda_1) == pytest.approx(1.0, abs=1e-25) and twice.degree == 3
    assert polynomial_roots([sp.Integer(1), x(-7, 3), x(2, 3)]).lambda_1 is None


def test_a_constant_has_no_roots():
    with pytest.raises(SymdecompError, match="degree at least 1"):
        polynomial_roots([sp.Integer(3)])
    assert isinstance(polynomial_roots([sp.Integer(1), sp.Integer(-1)]).roots[0][0], flint.acb)
