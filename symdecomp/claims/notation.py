"""The paper's notation as sympy objects, for the findings of the claims (:class:`~symdecomp.claims.Text`).

A finding names an eigenvalue, a root of unity or a component as a formula, not as ASCII:
``Text("the ratio ", ratio(A(1), B(1)), " is ", value)`` is typeset by LaTeX and printed as
``the ratio A^1/B^1 is ...`` on a terminal. Symbols carry names that sympy's printers turn into
the paper's (``lambda_1,2`` becomes ``\\lambda_{1,2}``).

>>> from symdecomp.claims.registry import Text
>>> print(Text("for ", ne(cos_j_theta, 0)))
for cos(j*theta) != 0
"""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp
from sympy.printing.precedence import PRECEDENCE

from symdecomp.claims.registry import Text
from symdecomp.symbols import cos_jtheta, j, lam, n, omega

__all__ = [
    "A", "B", "I", "Kron", "M", "c", "cos_j_theta", "eq", "ge", "gt", "j", "lam", "lambda_1", "lambda_2",
    "lambda_12", "le", "listed", "lt", "n", "ne", "omega", "omega_2n", "omega_n", "theta", "tup",
]

#: ``c = cos(j theta)``, the variable of Eq. 34 (the same symbol as the analysis uses).
c = cos_jtheta
#: ``theta = pi/n`` of Eq. 34, as a name.
theta = sp.Symbol("theta")
#: ``cos(j theta)`` written as in the paper.
cos_j_theta = sp.cos(j * theta)
#: The eigenvalues of Eq. 34.
lambda_1 = sp.Symbol("lambda_1")
lambda_2 = sp.Symbol("lambda_2")
lambda_12 = sp.Symbol("lambda_1,2")
#: The roots of unity of Eq. 3 (``omega_n``) and of the 2n-gon (``omega_2n``).
omega_n = sp.Symbol("omega_n")
omega_2n = sp.Symbol("omega_2n")
#: The identity matrix, as a name.
I = sp.Symbol("I")  # noqa: E741 (the paper's name)


class Kron(sp.Expr):
    """The Kronecker product ``alpha (x) v`` of named vectors (Section 6), as the paper writes it.

    >>> a, v = sp.Symbol("alpha", commutative=False), sp.Symbol("v", commutative=False)
    >>> print(Text(Kron(a, v)), sp.latex(Kron(a, v)))
    alpha (x) v \\alpha \\otimes v
    """

    is_commutative = False
    #: binds less than a product: ``B (alpha (x) v)``
    precedence = PRECEDENCE["Add"]

    def _sympystr(self, printer):
        return " (x) ".join(printer.parenthesize(a, PRECEDENCE["Mul"]) for a in self.args)

    def _latex(self, printer):
        return " \\otimes ".join(printer.parenthesize(a, PRECEDENCE["Mul"]) for a in self.args)


def A(k) -> sp.Symbol:
    """The component ``A^k`` of the a's (Eq. 11)."""
    return sp.Symbol(f"A^{k}")


def B(k) -> sp.Symbol:
    """The component ``B^k`` of the b's (Eq. 11)."""
    return sp.Symbol(f"B^{k}")


def M(k) -> sp.Symbol:
    """The per-frequency matrix ``M_k`` (Eq. 33), as a name."""
    return sp.Symbol(f"M_{k}")


def _relation(kind, written: str):
    """A builder of the relation ``kind`` between two expressions, as written (not evaluated)."""

    def build(lhs, rhs) -> sp.Basic:
        return kind(sp.sympify(lhs, strict=True), sp.sympify(rhs, strict=True), evaluate=False)

    build.__doc__ = f"``lhs {written} rhs`` as written (not evaluated)."
    return build


eq = _relation(sp.Eq, "=")
ne = _relation(sp.Ne, "!=")
gt = _relation(sp.StrictGreaterThan, ">")
ge = _relation(sp.GreaterThan, ">=")
lt = _relation(sp.StrictLessThan, "<")
le = _relation(sp.LessThan, "<=")


def tup(*entries) -> sp.Tuple:
    """A vector or a row written as a tuple ``(x, y, ...)``."""
    return sp.Tuple(*entries)


def listed(items: Iterable, sep: str = ", ") -> Text:
    """Several objects in a row, separated by words (``1, 2, 3``): each one typeset on its own.

    >>> print(listed(sp.sqrt(k) for k in (2, 3)))
    sqrt(2), sqrt(3)
    """
    parts = []
    for item in items:
        parts.extend((sep, sp.sympify(item, strict=True)) if parts else (sp.sympify(item, strict=True),))
    return Text(*parts)
