"""Rules of a 1-ring as polynomials in the index shift, and their composition (Section 4, Eq. 17-23).

A rule ``p_i -> o*O + sum_k x_k a_{i+k} + sum_k y_k b_{i+k}`` is the row ``(o, A(S), B(S))``
with ``A(S) = sum_k x_k S^k`` in the shift ``S: a_i -> a_{i+1}`` (written ``omega``; for a
regular n-gon ``v_j`` the shift is multiplication by ``omega_n^j``, Prop. 2.1). Shifts commute
and act alike for every ``n``, so applying one rule after another multiplies these Laurent
polynomials: a scheme given in stages (Eq. 17-21) composes to one rule per family
(:func:`composed_stages`).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> face = ShiftStencil.of(catmull_clark().face_rule)
>>> face.as_matrix()
Matrix([[1/4, omega/4 + 1/4, 1/4]])
>>> then_b(identity_b(), face) == face
True
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.symbols import omega

__all__ = ["ShiftStencil", "then_a", "then_b", "identity_a", "identity_b", "composed_stages"]


@dataclass(frozen=True)
class ShiftStencil:
    """A rule ``p_i -> o*O + A(S) a_i + B(S) b_i`` with ``S`` the index shift ``a_i -> a_{i+1}``.

    Shift operators commute and act the same way for every ``n`` (indices mod ``n``), so
    composing rules is multiplying Laurent polynomials in ``S`` (written ``omega``).
    """

    #: The weight ``o`` on the central vertex ``O``.
    o: sp.Expr
    #: ``A(S)``: the weights on the a's, a Laurent polynomial in the shift (written ``omega``).
    a: sp.Expr
    #: ``B(S)``: the weights on the b's, likewise.
    b: sp.Expr

    @classmethod
    def of(cls, rule) -> ShiftStencil:
        """A scheme's :class:`~symdecomp.schemes.scheme.Stencil` as a rule in the shift ``S``."""
        return cls(rule.center, sum((w * omega**k for k, w in rule.a), sp.Integer(0)), sum((w * omega**k for k, w in rule.b), sp.Integer(0)))

    def as_matrix(self) -> sp.Matrix:
        """The row ``(o, A(S), B(S))``."""
        return sp.Matrix([[self.o, self.a, self.b]])


def then_a(first: ShiftStencil, second: ShiftStencil) -> ShiftStencil:
    """Apply ``second`` to the a's produced by ``first`` (b's and O unchanged)."""
    return ShiftStencil(
        sp.expand(second.o + second.a.subs(omega, 1) * first.o),
        sp.expand(second.a * first.a),
        sp.expand(second.a * first.b + second.b),
    )


def then_b(first: ShiftStencil, second: ShiftStencil) -> ShiftStencil:
    """Apply ``second`` to the b's produced by ``first`` (a's and O unchanged)."""
    return ShiftStencil(
        sp.expand(second.o + second.b.subs(omega, 1) * first.o),
        sp.expand(second.b * first.a + second.a),
        sp.expand(second.b * first.b),
    )


def identity_a() -> ShiftStencil:
    """The rule that leaves every ``a_i`` where it is."""
    return ShiftStencil(sp.Integer(0), sp.Integer(1), sp.Integer(0))


def identity_b() -> ShiftStencil:
    """The rule that leaves every ``b_i`` where it is."""
    return ShiftStencil(sp.Integer(0), sp.Integer(0), sp.Integer(1))


def composed_stages(a_stages, b_stages) -> tuple[ShiftStencil, ShiftStencil]:
    """Compose staged rules: the a-steps in turn on the a's, the b-steps in turn on the b's (each chain
    reading the other family's points of the same level)."""
    a = identity_a()
    for stage in a_stages:
        a = then_a(a, stage)
    b = identity_b()
    for stage in b_stages:
        b = then_b(b, stage)
    return a, b
