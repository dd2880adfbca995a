"""The tie ``|mu| = lambda_1^2`` with ``lambda_1`` inexact asks whether ``sqrt(|mu|)`` is a root of ``lambda_1``'s
factor: decided in a cyclotomic field (``f(c) = E(q) + c O(q)``), the same answer as sympy's minimal polynomial of
``f(c)``, which took most of a minute per valence for sqrt(3) at n = 16 and 24 and past 3 minutes at n = 64."""

from __future__ import annotations

import pytest
import sympy as sp

from symdecomp.symbols import lam as LAM
from symdecomp.verify.zoo_artifacts import _root_at_square_root

X = sp.Symbol("x")
Q = (2 + sp.sqrt(2)) / 4  # cos(pi/8)^2, as sympy writes it: sqrt(q) = cos(pi/8)
C = sp.sqrt(Q)


def _by_minimal_polynomial(factor: sp.Expr, c: sp.Expr) -> bool:
    return sp.minimal_polynomial(sp.expand(factor.xreplace({LAM: c})), X) == X


@pytest.mark.parametrize("factor, c, expected", [
    (sp.expand((LAM - sp.cos(sp.pi / 8)) * (LAM - sp.Rational(1, 5))), C, True),
    (sp.expand((LAM - sp.cos(sp.pi / 8)) * (LAM - sp.Rational(1, 5))), -C, False),
    (sp.expand((LAM + sp.cos(sp.pi / 8)) * (LAM - sp.Rational(1, 5))), C, False),  # -c is the root: the sign decides
    (sp.expand((LAM + sp.cos(sp.pi / 8)) * (LAM - sp.Rational(1, 5))), -C, True),
    (sp.expand(LAM ** 2 - Q), C, True),  # O(q) = 0: E(q) decides
    (sp.expand(LAM ** 2 - Q - sp.Rational(1, 7)), C, False),
    (sp.expand((LAM - sp.cos(sp.pi / 8)) * (LAM - sp.exp(sp.I * sp.pi / 8))), C, True),  # complex coefficients
])
def test_square_root_roots_in_a_cyclotomic_field(factor, c, expected) -> None:
    assert _by_minimal_polynomial(factor, c) is expected
    assert _root_at_square_root(factor, c, 16) is expected


def test_other_values_are_left_to_the_caller() -> None:
    assert _root_at_square_root(LAM - sp.Rational(1, 3), sp.Rational(1, 3), 16) is None
    assert _root_at_square_root(LAM ** 2 - 2, sp.sqrt(sp.pi), 16) is None
