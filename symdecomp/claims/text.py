"""The findings' words: prose with mathematics in it (:class:`Text`), words from outside shown as given (:class:`Verbatim`).

A check's evidence, counterexample and corrected statement are :class:`Text`, so that LaTeX typesets their objects
as formulas (:func:`symdecomp.output.latex.aslatex`) and a terminal prints them readably, from one source; the
registry (:mod:`symdecomp.claims.registry`) carries them in its results.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from sympy.printing.str import StrPrinter

__all__ = ["Text", "Verbatim"]


class _TextPrinter(StrPrinter):
    """sympy's ``str`` printer, with relations and intervals written as in prose (``x = 1``, ``[0, 1)``)."""

    def _print_Relational(self, expr: Any) -> str:
        op = "=" if expr.rel_op == "==" else expr.rel_op
        return "%s %s %s" % (self._print(expr.lhs), op, self._print(expr.rhs))

    def _print_MatrixBase(self, expr: Any) -> str:
        return "[%s]" % ", ".join("[%s]" % ", ".join(self._print(e) for e in row) for row in expr.tolist())

    def _print_Derivative(self, expr: Any) -> str:
        variables = "".join(" d%s" % self._print(v) for v in expr.variables)
        return "d%s/%s" % (self._print(expr.expr), variables.strip())

    def _print_Product(self, expr: Any, name: str = "prod") -> str:
        limits = ", ".join("%s=%s..%s" % tuple(self._print(x) for x in lim) for lim in expr.limits)
        return "%s_{%s} %s" % (name, limits, self.parenthesize(expr.function, 50))

    def _print_Sum(self, expr: Any) -> str:
        return self._print_Product(expr, "sum")

    def _print_Abs(self, expr: Any) -> str:
        return "|%s|" % self._print(expr.args[0])

    def _print_Interval(self, expr: Any) -> str:
        left = "(" if expr.left_open else "["
        right = ")" if expr.right_open else "]"
        return "%s%s, %s%s" % (left, self._print(expr.start), self._print(expr.end), right)


class Verbatim(str):
    """Words from outside the package, shown exactly as given: a scheme's name, an error message.

    A finding (or a part of a :class:`Text`) may be one. LaTeX escapes every character of it (a
    ``$`` in a scheme's name is a dollar sign, never the start of a formula, and a backslash is
    a backslash, never a command); a terminal prints it as it is. Every text that a check writes
    from its input is one: the scheme's name, the messages of the errors it caught.
    """

    __slots__ = ()


@dataclass(frozen=True, init=False)
class Text:
    """Prose with mathematics in it: words (``str``) and computed objects (sympy), in order.

    The findings of a check (evidence, counterexample, corrected statement) are ``Text``, so
    that LaTeX typesets the objects as formulas (:func:`symdecomp.output.latex.aslatex`) and a
    terminal prints them readably (``str``), from the same source. A plain ``str`` part is
    prose and is never parsed as mathematics; a :class:`Verbatim` part is shown exactly as given.

    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> str(Text("the root ", sp.sqrt(x) / 2, " is simple"))
    'the root sqrt(x)/2 is simple'
    >>> str(Text("where ", sp.Eq(x, 1, evaluate=False), " in ", sp.Interval.Ropen(0, 1)))
    'where x = 1 in [0, 1)'
    """

    #: The words and objects, in reading order.
    parts: tuple[object, ...]

    def __init__(self, *parts: object) -> None:
        flat: list[object] = []
        for part in parts:
            flat.extend(part.parts if isinstance(part, Text) else (part,))
        object.__setattr__(self, "parts", tuple(flat))

    def __str__(self) -> str:
        return "".join(part if isinstance(part, str) else _TextPrinter().doprint(part) for part in self.parts)

    def __bool__(self) -> bool:
        return bool(self.parts)

    def __add__(self, other: object) -> Text:
        return Text(self, other)

    def __radd__(self, other: object) -> Text:
        return Text(other, self)
