"""Section 5.1: the closed forms at concrete n, j against M_j's own eigenvalues."""

import mpmath
import pytest
import sympy as sp

from symdecomp import catmull_clark, per_frequency_matrix_at, tangent_eigenvalues
from symdecomp.analysis.tangent import invariant_ratio_at, invariant_ratio_limit


def to_mpc(x):
    re, im = sp.N(x, 60).as_real_imag()
    return mpmath.mpc(str(re), str(im))


@pytest.mark.parametrize("n", [3, 4, 5, 6, 9])
def test_closed_forms_match_each_M_j_to_40_digits(n):
    cc = catmull_clark()
    ev = tangent_eigenvalues(cc)
    for j in range(2 * n):  # every 2n-gon component, both parities of n, j = n/2 included
        M = per_frequency_matrix_at(cc, n, j)
        with mpmath.workdps(50):
            A = mpmath.matrix([[to_mpc(x) for x in row] for row in M.tolist()])
            direct = sorted(mpmath.eig(A, left=False, right=False), key=lambda z: -z.real)
            closed = [mpmath.mpmathify(str(sp.N(e, 60))) for e in ev.at(n, j)]
            assert abs(direct[0] - closed[0]) < mpmath.mpf(10) ** -40
            assert abs(direct[1] - closed[1]) < mpmath.mpf(10) ** -40
            assert closed[0] >= closed[1]


def test_product_of_eigenvalues_is_one_sixteenth_for_every_frequency():
    ev = tangent_eigenvalues(catmull_clark())
    assert sp.simplify(ev.dominant * ev.subdominant) == sp.Rational(1, 16)


def test_invariant_ratio_values():
    cc = catmull_clark()
    assert sp.simplify(invariant_ratio_limit(cc) - 4 / (sp.sqrt(5) + 1)) == 0
    # the ratio's argument is j*pi/n: no rotation beyond the initial offset of B against A
    r6 = sp.N(invariant_ratio_at(cc, 6, 1), 30)
    assert abs(sp.arg(r6) - sp.pi / 6) < 1e-25
