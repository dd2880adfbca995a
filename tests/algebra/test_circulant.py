"""Section 2: F_n, circ's convention and Proposition 2.1 on concrete matrices."""

import pytest
import sympy as sp

from symdecomp.algebra.circulant import circ, circ_from_offsets, circulant_eigenvalue, fourier_matrix, root_of_unity
from symdecomp.algebra.cyclotomic import CyclotomicField


def test_convention_of_eq7():
    # EQUATIONS.md: (circ(1/2, 0, ..., 0, 1/2) B)_i = (b_i + b_{i-1})/2
    b = sp.symbols("b0:5")
    C = circ([sp.Rational(1, 2), 0, 0, 0, sp.Rational(1, 2)])
    out = C * sp.Matrix(b)
    assert [sp.expand(out[i] - (b[i] + b[i - 1]) / 2) for i in range(5)] == [0] * 5


@pytest.mark.parametrize("n", range(3, 11))
def test_fourier_matrix_inverse_exactly_in_the_cyclotomic_field(n):
    K = CyclotomicField(n)
    for k in range(n):
        for l in range(n):
            s = sum((K.root(n, (k - l) * m) for m in range(n)), K(0))
            assert s == (n if k == l else 0)


@pytest.mark.parametrize("n", [3, 4, 7])
def test_prop21_on_concrete_circulants_to_40_digits(n):
    offsets = {0: sp.Rational(3, 4), 1: sp.Rational(1, 8), -1: sp.Rational(1, 8)}
    C = circ_from_offsets(offsets, n)
    F = fourier_matrix(n)
    for k in range(n):
        v = F.row(k).T
        residual = (C * v - circulant_eigenvalue(offsets, n, k) * v).evalf(50)
        assert max(abs(x) for x in residual) < 1e-40


def test_offsets_colliding_mod_n_are_rejected():
    from symdecomp import InvalidSchemeError

    with pytest.raises(InvalidSchemeError, match="coincide mod n = 3"):
        circ_from_offsets({-1: 1, 2: 1}, 3)


def test_root_of_unity_is_exact():
    assert root_of_unity(4, 1) == sp.I
    assert sp.simplify(root_of_unity(6, 2) ** 3 - 1) == 0
