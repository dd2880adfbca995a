"""The claims' steps done in the right field (FLINT rationals, Arb) against the sympy steps they replace."""

from __future__ import annotations

import sympy as sp

from symdecomp.algebra.cbmatrix import cb_eigensystem
from symdecomp.analysis.tuning import joint_obstruction
from symdecomp.claims.cb_examples import _random_cb, invertible
from symdecomp.claims.s6_closing import X, _defective_example, _multiplicities_at
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.symbols import n as N


def test_multiplicities_in_flint_are_sympys():
    weights, mu, S = _defective_example(catmull_clark(), 3)
    algebraic = sp.roots(sp.Poly(sp.expand((X * sp.eye(S.rows) - S).det()), X)).get(mu, 0)
    geometric = S.rows - (S - mu * sp.eye(S.rows)).rank(simplify=True)
    assert _multiplicities_at(S, mu) == (algebraic, geometric) == (2, 1)  # E_0 a Jordan block: S not diagonalizable


def test_multiplicities_of_an_irrational_value_take_sympys_route():
    S = sp.Matrix([[1, 1, 0], [0, 1, 0], [0, 0, 2]]) * sp.sqrt(2)
    assert _multiplicities_at(S, sp.sqrt(2)) == (2, 1)


def test_invertible_proves_with_arb_and_leaves_a_singular_matrix_to_the_exact_rank():
    eigvecs = sp.Matrix.hstack(*[V for _, _, vs in cb_eigensystem(_random_cb(2, 4, 11)) for V in vs])
    assert invertible(eigvecs) and eigvecs.shape == (8, 8)
    singular = sp.Matrix(eigvecs)
    singular[:, 7] = singular[:, 0] * (1 + sp.I) + singular[:, 1]  # rank 7: Arb's determinant ball holds 0
    assert not invertible(singular)


def test_the_joint_defect_is_simplified_when_read():
    joint = joint_obstruction(catmull_clark())
    assert sp.simplify(joint.defect - joint.derived_defect) == 0 and joint.defect.subs(N, 4) == 0
