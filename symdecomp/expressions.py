"""Exact weights and expressions from user input, parsed and never evaluated.

Text a user gives (a weight on the command line, a value in a scheme file, a string handed to
the API) is read by :func:`parse_expression`: Python's own parser turns it into a syntax tree,
and only a whitelist of node types is turned into sympy objects. Nothing is executed, no
attribute is looked up, no name outside the whitelist resolves.

The grammar:

* integers (ASCII digits, ``_`` separators refused) and the rational operators ``+ - * /``,
  parentheses, and powers ``**`` with an integer exponent (or ``1/2`` for a square root);
* the names given by the caller (for a scheme: ``n`` and the parameters it declares) and
  ``pi``;
* the functions ``sqrt``, ``cos`` and ``sin``.

Decimal numbers (``0.375``, ``1e-3``) are refused: a float is not an exact weight. Limits keep
a hostile input from hanging the parser: at most :data:`MAX_LENGTH` characters, nesting of
at most :data:`MAX_DEPTH`, integers of at most :data:`MAX_DIGITS` digits and integer
exponents of magnitude at most :data:`MAX_EXPONENT`.

>>> import sympy as sp
>>> n = sp.Symbol("n", integer=True, positive=True)
>>> parse_expression("3/(2*n**2)", {"n": n})
3/(2*n**2)
>>> parse_expression("(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n", {"n": n})
(5/8 - (cos(2*pi/n)/4 + 3/8)**2)/n
>>> parse_expression("__import__('os')")
Traceback (most recent call last):
...
symdecomp.errors.InvalidExpressionError: expression "__import__('os')": calls only sqrt, cos, sin
>>> exact_value(0.375, argument="weight")
Traceback (most recent call last):
...
symdecomp.errors.InvalidExpressionError: weight 0.375 is a float; give an exact rational such as '3/8'
"""

from __future__ import annotations

import ast
import numbers
from collections.abc import Mapping
from fractions import Fraction

import sympy as sp

from symdecomp.errors import InvalidExpressionError

__all__ = ["parse_expression", "exact_value", "MAX_LENGTH", "MAX_DEPTH", "MAX_DIGITS", "MAX_EXPONENT"]

#: Longest text accepted.
MAX_LENGTH = 1000
#: Deepest nesting of operations accepted.
MAX_DEPTH = 50
#: Most digits of one integer literal.
MAX_DIGITS = 100
#: Largest magnitude of an integer exponent.
MAX_EXPONENT = 64
# Largest exact rational built along the way (numerator or denominator), in bits.
_MAX_BITS = 4096

_FUNCTIONS = {"sqrt": sp.sqrt, "cos": sp.cos, "sin": sp.sin}
_CONSTANTS = {"pi": sp.pi}
_BINARY = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
}


def _describe(text: str) -> str:
    return text if len(text) <= 60 else text[:57] + "..."


def parse_expression(text: str, symbols: Mapping[str, sp.Symbol] | None = None, *, argument: str = "expression") -> sp.Expr:
    """Parse ``text`` into an exact sympy expression in the given ``symbols``.

    ``symbols`` maps the names the text may use to the sympy symbols they stand for (a user's
    ``n`` becomes the package's valence symbol this way, never a free parameter of the same
    name). ``argument`` names the input in error messages (``"[edge] a.-1"``, ``"--alpha"``).
    Raises :class:`~symdecomp.errors.InvalidExpressionError` for anything outside the grammar
    in the module docstring, for a division by zero, and for a value that is not finite.
    """
    where = f"{argument} {_describe(text)!r}" if isinstance(text, str) else argument
    if not isinstance(text, str):
        raise InvalidExpressionError(f"{argument}: expected text, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise InvalidExpressionError(f"{argument}: longer than {MAX_LENGTH} characters")
    if not text.strip():
        raise InvalidExpressionError(f"{argument}: empty")
    if not text.isascii():
        raise InvalidExpressionError(f"{where}: only ASCII characters are allowed")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        raise InvalidExpressionError(f"{where}: not an arithmetic expression") from None
    names = dict(_CONSTANTS)
    names.update(symbols or {})
    try:
        value = _build(tree.body, names, where, 0, text.strip())
    except ZeroDivisionError:
        raise InvalidExpressionError(f"{where}: division by zero") from None
    if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise InvalidExpressionError(f"{where}: not finite")
    return value


def _build(node: ast.AST, names: Mapping[str, sp.Expr], where: str, depth: int, source: str) -> sp.Expr:
    if depth > MAX_DEPTH:
        raise InvalidExpressionError(f"{where}: nested deeper than {MAX_DEPTH}")
    deeper = depth + 1
    if isinstance(node, ast.Constant):
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float, complex)):
            raise InvalidExpressionError(f"{where}: {value!r} is not a number")
        if not isinstance(value, int):
            raise InvalidExpressionError(f"{where}: {value!r} is a float; give an exact rational such as '3/8'")
        if "_" in (ast.get_source_segment(source, node) or ""):
            raise InvalidExpressionError(f"{where}: digit separators '_' are not allowed")
        if len(str(abs(value))) > MAX_DIGITS:
            raise InvalidExpressionError(f"{where}: an integer has more than {MAX_DIGITS} digits")
        return sp.Integer(value)
    if isinstance(node, ast.Name):
        if node.id not in names:
            known = ", ".join(sorted(names)) or "none"
            raise InvalidExpressionError(f"{where}: unknown name {node.id!r} (known: {known})")
        return names[node.id]
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
        operand = _build(node.operand, names, where, deeper, source)
        return -operand if isinstance(node.op, ast.USub) else operand
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        left = _build(node.left, names, where, deeper, source)
        right = _build(node.right, names, where, deeper, source)
        if isinstance(node.op, ast.Div) and right == 0:
            raise ZeroDivisionError
        result = _BINARY[type(node.op)](left, right)
        if result.is_Rational and max(abs(result.p), result.q).bit_length() > _MAX_BITS:
            raise InvalidExpressionError(f"{where}: a number has more than {_MAX_BITS} bits")
        return result
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
        base = _build(node.left, names, where, deeper, source)
        exponent = _build(node.right, names, where, deeper, source)
        if not (exponent.is_Integer or exponent in (sp.Rational(1, 2), sp.Rational(-1, 2))):
            raise InvalidExpressionError(f"{where}: exponents must be integers or 1/2, got {exponent}")
        if abs(exponent) > MAX_EXPONENT:
            raise InvalidExpressionError(f"{where}: exponent {exponent} is larger than {MAX_EXPONENT} in magnitude")
        if base == 0 and exponent < 0:
            raise ZeroDivisionError
        if base.is_Rational and max(abs(base.p), base.q).bit_length() * abs(exponent) > _MAX_BITS:
            raise InvalidExpressionError(f"{where}: a number has more than {_MAX_BITS} bits")
        return base**exponent
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCTIONS:
            raise InvalidExpressionError(f"{where}: calls only {', '.join(_FUNCTIONS)}")
        if node.keywords or len(node.args) != 1:
            raise InvalidExpressionError(f"{where}: {node.func.id} takes one argument")
        return _FUNCTIONS[node.func.id](_build(node.args[0], names, where, deeper, source))
    raise InvalidExpressionError(
        f"{where}: only numbers, + - * / **, parentheses, {', '.join(sorted(names))} and {', '.join(_FUNCTIONS)} are allowed"
    )


def exact_value(value, symbols: Mapping[str, sp.Symbol] | None = None, *, argument: str = "value",
                other_symbols: bool = False) -> sp.Expr:
    """``value`` as an exact sympy expression: the one door for numbers given to the API.

    Accepts ``int`` (not ``bool``), :class:`fractions.Fraction`, sympy expressions without
    floats, and text (parsed by :func:`parse_expression` with ``symbols``). Refuses floats,
    booleans and anything else with :class:`~symdecomp.errors.InvalidExpressionError` naming
    ``argument``. A sympy expression may only contain the given ``symbols`` (and ``pi``) when
    ``symbols`` is given, unless ``other_symbols`` (then other symbols are free parameters).
    A symbol of the expression that has the *name* of one of ``symbols`` but other assumptions
    (a user's own ``Symbol('n')``) is read as that symbol, never as a second ``n``.

    >>> n = sp.Symbol("n", integer=True, positive=True)
    >>> exact_value(1 / sp.Symbol("n"), {"n": n}) == 1 / n
    True
    """
    if isinstance(value, bool):
        raise InvalidExpressionError(f"{argument} {value!r} is a boolean, not a number")
    if isinstance(value, str):
        return parse_expression(value, symbols, argument=argument)
    if isinstance(value, int):
        return sp.Integer(value)
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, sp.Basic):
        if not isinstance(value, sp.Expr):
            raise InvalidExpressionError(f"{argument} {value!r} is not an expression")
        if value.has(sp.Float):
            raise InvalidExpressionError(f"{argument} {value} contains a float; give exact rationals")
        if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise InvalidExpressionError(f"{argument} {value} is not finite")
        if symbols is not None:
            allowed = set(symbols.values())
            renames = {s: symbols[s.name] for s in value.free_symbols
                       if isinstance(s, sp.Symbol) and s.name in symbols and s not in allowed}
            if renames:
                value = value.xreplace(renames)
            stray = sorted(str(s) for s in value.free_symbols - allowed)
            if stray and not other_symbols:
                raise InvalidExpressionError(f"{argument} {value} has unknown symbols {', '.join(stray)}")
        return value
    if isinstance(value, numbers.Integral):  # numpy integers and the like
        return sp.Integer(int(value))
    if isinstance(value, numbers.Real):
        raise InvalidExpressionError(f"{argument} {value!r} is a float; give an exact rational such as '3/8'")
    raise InvalidExpressionError(f"{argument} {value!r} ({type(value).__name__}) is not a number")
