"""Exact weights and expressions from user input, parsed and never evaluated.

Text a user gives (a weight on the command line, a value in a scheme file, a string handed to
the API) is read by :func:`parse_expression`: Python's own parser turns it into a syntax tree,
and only a whitelist of node types is turned into sympy objects. Nothing is executed, no
attribute is looked up, no name outside the whitelist resolves.

The grammar:

* integers written in decimal (ASCII digits; ``_`` separators and Python's ``0x``, ``0o``, ``0b``
  forms refused) and the rational operators ``+ - * /``, parentheses, and powers ``**`` with an
  integer exponent (or ``1/2`` for a square root);
* the names given by the caller (for a scheme: ``n`` and the parameters it declares) and
  ``pi``;
* the functions ``sqrt``, ``cos`` and ``sin``; ``cos`` and ``sin`` of rational multiples of ``pi``
  only (``cos(2*pi/n)``): those are exact algebraic numbers in cyclotomic fields, the fields the
  toolkit computes in; ``cos(1)`` is refused. When the caller gives the names ``m`` (a face's size)
  and ``j`` (an index, as the zoo's stencil files do: :mod:`symdecomp.schemes.stencil_files`), the
  multiple may be ``P(n, m, j)/(d n)`` or ``P(n, m, j)/(d m)`` (``cos(2*pi*j/m)``);
* ``KroneckerDelta(a, b)`` (1 if ``a = b``, else 0) of two integer polynomials in the names, only when
  the caller asks for it (``kronecker=True``: the stencil files' ``KroneckerDelta(j, 0)``).

Decimal numbers (``0.375``, ``1e-3``) are refused: a float is not an exact weight.

**The expression budget** (:data:`BUDGET`, one set of bounds with their reasons): what an
expression may cost is measured on its tree, node by node, before sympy builds the node, so that
no input can exhaust the machine later (in a factorization, a characteristic polynomial, a
cyclotomic field): at most :data:`MAX_LENGTH` characters and :data:`MAX_NODES` operations,
numbers and names, nesting of at most :data:`MAX_DEPTH`, integers of at most :data:`MAX_DIGITS`
digits, exponents of magnitude at most :data:`MAX_EXPONENT`, degree in ``n`` at most
:data:`MAX_DEGREE` counted through nested powers (``(n**8)**16`` has degree 128, counted, never
expanded), numbers of at most :data:`MAX_BITS` bits at a valence (an upper bound counted on the
tree), ``sqrt``/``cos``/``sin`` nested at most :data:`MAX_FUNCTION_DEPTH` deep. Sympy expressions
given to the API meet the same bounds (:func:`check_budget`, called by :func:`exact_value` and
when a scheme is built).

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
import re
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction

import sympy as sp

from symdecomp.errors import InvalidExpressionError

__all__ = ["parse_expression", "exact_value", "check_budget", "BUDGET", "MAX_LENGTH", "MAX_NODES", "MAX_DEPTH",
           "MAX_DIGITS", "MAX_EXPONENT", "MAX_DEGREE", "MAX_BITS", "MAX_FUNCTION_DEPTH", "MAX_PI_DENOMINATOR",
           "MAX_OFFSET", "identically_zero"]

# The expression budget: what one weight may cost, measured on its tree before sympy builds anything large.
#: Longest text accepted.
MAX_LENGTH = 1000
#: Most operations, numbers and names in one expression.
MAX_NODES = 400
#: Deepest nesting of operations accepted.
MAX_DEPTH = 50
#: Most digits of one integer literal.
MAX_DIGITS = 100
#: Largest magnitude of one exponent.
MAX_EXPONENT = 64
#: Largest degree in ``n`` (numerator and denominator together), counted through nested powers.
MAX_DEGREE = 64
#: Largest size, in bits, that a numerator or denominator of the value may reach at a valence of the command
#: line (an upper bound counted on the tree: ``n`` and the parameters count as :data:`VALENCE_BITS` bits).
MAX_BITS = 4096
#: Deepest nesting of ``sqrt``, ``cos``, ``sin`` (and powers ``1/2``) inside each other.
MAX_FUNCTION_DEPTH = 2
#: ``cos`` and ``sin`` take ``pi`` times ``P(n) / (d n)`` or ``P(n) / d`` with ``d`` at most this.
MAX_PI_DENOMINATOR = 12
#: Largest magnitude of a stencil offset (a scheme's rules, checked where a scheme is built).
MAX_OFFSET = 8
#: Bits a valence (at most 2000 on the command line) or a parameter counts for in :data:`MAX_BITS`.
VALENCE_BITS = 11

#: The budget and the reason for each bound (``name: (bound, reason)``; the documentation's table is generated from it).
BUDGET = {
    "characters": (MAX_LENGTH, "a weight is a formula of a few terms"),
    "operations and numbers": (MAX_NODES, "each one is a step of every exact evaluation"),
    "nesting of operations": (MAX_DEPTH, "the parser and sympy recurse once per level"),
    "digits of an integer": (MAX_DIGITS, "numbers grow with every product of the exact arithmetic"),
    "exponent": (MAX_EXPONENT, "nested powers multiply their exponents"),
    "degree in n": (MAX_DEGREE, "characteristic polynomials and factorizations grow with it"),
    "bits of a value": (MAX_BITS, "FLINT's exact arithmetic on larger numbers runs out of memory"),
    "nesting of sqrt, cos, sin": (MAX_FUNCTION_DEPTH, "each level squares the degree of the number field"),
    "denominator of a cos/sin argument over pi": (MAX_PI_DENOMINATOR, "it multiplies the order of the cyclotomic field"),
    "stencil offset": (MAX_OFFSET, "closed forms are Laurent polynomials in omega of degree 2*offset; offset 16 takes minutes"),
}

_FUNCTIONS = {"sqrt": sp.sqrt, "cos": sp.cos, "sin": sp.sin}
#: The names that may stand in a cos/sin argument over pi (the valence, a face's size, an index of a family).
_TRIG_NAMES = ("n", "m", "j")
_CONSTANTS = {"pi": sp.pi}
_BINARY = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
}
_DECIMAL = re.compile(r"[0-9]+", re.ASCII)
_HALF = sp.Rational(1, 2)


@dataclass(frozen=True)
class _Cost:
    """What a subexpression costs: its nodes; bounds on the degrees in ``n`` and on the bits (at a valence) of
    the numerator and the denominator of its value; how deeply ``sqrt``, ``cos``, ``sin`` are nested in it."""

    nodes: int = 1
    num_degree: int = 0
    den_degree: int = 0
    num: int = 1
    den: int = 0
    functions: int = 0

    @property
    def degree(self) -> int:
        return max(self.num_degree, self.den_degree)

    @property
    def bits(self) -> int:
        return max(self.num, self.den)

    def inverse(self) -> _Cost:
        return _Cost(self.nodes, self.den_degree, self.num_degree, self.den, self.num, self.functions)


def _sum(parts) -> _Cost:
    # sum_i p_i/q_i = (sum_i p_i prod_{j != i} q_j) / prod_j q_j
    den = sum(p.den for p in parts)
    den_degree = sum(p.den_degree for p in parts)
    return _Cost(1 + sum(p.nodes for p in parts), max(p.num_degree + den_degree - p.den_degree for p in parts), den_degree,
                 max(p.num + den - p.den for p in parts) + (len(parts) - 1).bit_length(), den,
                 max(p.functions for p in parts))


def _product(parts, divide: bool = False) -> _Cost:
    if divide:  # a / b: the numerator and the denominator of b change places
        parts = [*parts[:-1], parts[-1].inverse()]
    return _Cost(1 + sum(p.nodes for p in parts), sum(p.num_degree for p in parts), sum(p.den_degree for p in parts),
                 sum(p.num for p in parts), sum(p.den for p in parts), max(p.functions for p in parts))


def _power(base: _Cost, exponent: sp.Rational, exponent_nodes: int = 1) -> _Cost:
    k = abs(int(exponent.p))
    b = base if exponent > 0 else base.inverse()
    return _Cost(base.nodes + exponent_nodes + 1, b.num_degree * k, b.den_degree * k, b.num * k, b.den * k,
                 base.functions + (exponent.q != 1))


def _trig(argument: _Cost) -> _Cost:
    return _Cost(argument.nodes + 1, 0, 0, 2, 2, argument.functions + 1)


def _leaf(*, degree: int = 0, bits: int = 1, den: int = 0) -> _Cost:
    return _Cost(1, degree, 0, bits, den, 0)


def _checked(cost: _Cost, where: str) -> _Cost:
    if cost.nodes > MAX_NODES:
        raise InvalidExpressionError(f"{where}: more than {MAX_NODES} operations, numbers and names")
    if cost.degree > MAX_DEGREE:
        raise InvalidExpressionError(f"{where}: degree {cost.degree} in n, more than {MAX_DEGREE}")
    if cost.bits > MAX_BITS:
        raise InvalidExpressionError(f"{where}: its numbers may reach {cost.bits} bits at a valence, more than {MAX_BITS}")
    if cost.functions > MAX_FUNCTION_DEPTH:
        raise InvalidExpressionError(f"{where}: sqrt, cos and sin nested {cost.functions} deep, more than {MAX_FUNCTION_DEPTH}")
    return cost


def _check_exponent(exponent: sp.Expr, where: str, *, halves: bool) -> None:
    if not exponent.is_Rational or (exponent.q != 1 and not (halves and exponent.q == 2)):
        allowed = "integers or 1/2" if not halves else "rational numbers with denominator 1 or 2"
        raise InvalidExpressionError(f"{where}: exponents must be {allowed}, got {exponent}")
    if abs(exponent) > MAX_EXPONENT:
        raise InvalidExpressionError(f"{where}: exponent {exponent} is larger than {MAX_EXPONENT} in magnitude")


def _check_trig(argument: sp.Expr, where: str) -> None:
    """``cos``/``sin`` of ``pi`` times ``P(n)/(d n^k)``, ``k <= 1``, ``d <= MAX_PI_DENOMINATOR``: an algebraic
    number of a cyclotomic field at every valence. Anything else (``cos(1)``) is outside the fields the toolkit
    computes in. A sharp rule's sector angle ``theta_k`` (:data:`symdecomp.symbols.theta_k`: ``pi/k`` or a corner
    angle over ``k``) may stand for ``pi``: ``cos(2*theta_k)``."""
    angle = next((s for s in argument.free_symbols if getattr(s, "name", "") == "theta_k"), None)
    if angle is not None:
        q = sp.cancel(argument / angle)
        if not q.is_Rational or q.q > MAX_PI_DENOMINATOR:
            raise InvalidExpressionError(f"{where}: cos/sin of {argument}: only rational multiples of theta_k such as "
                                         "2*theta_k are exact (theta_k is the sector angle of a sharp rule)")
        return
    r = argument / sp.pi
    symbols = r.free_symbols
    if (r.has(sp.pi) or r.atoms(sp.Function) or not all(getattr(s, "name", "") in _TRIG_NAMES for s in symbols)
            or not r.is_rational_function(*symbols)):
        raise InvalidExpressionError(
            f"{where}: cos/sin of {argument}: only rational multiples of pi such as 2*pi/n are exact in the number "
            "fields the toolkit computes in (cyclotomic fields)")
    _, den = sp.fraction(sp.cancel(sp.together(r)))
    poly = sp.Poly(den, *symbols) if symbols else None
    if poly is not None and (len(poly.terms()) != 1 or poly.total_degree() > 1 or any(getattr(s, "name", "") == "j"
                                                                                      for s in den.free_symbols)):
        raise InvalidExpressionError(f"{where}: cos/sin of {argument}: the argument over pi must have a denominator d or "
                                     "d*n (or d*m, m a face's size; a larger field at every valence otherwise)")
    if abs(poly.LC() if poly is not None else den) > MAX_PI_DENOMINATOR:
        raise InvalidExpressionError(
            f"{where}: cos/sin of {argument}: the denominator over pi is above {MAX_PI_DENOMINATOR} "
            "(it multiplies the order of the cyclotomic field the toolkit computes in)")


def _describe(text: str) -> str:
    return text if len(text) <= 60 else text[:57] + "..."


def parse_expression(text: str, symbols: Mapping[str, sp.Symbol] | None = None, *, argument: str = "expression",
                     kronecker: bool = False) -> sp.Expr:
    """Parse ``text`` into an exact sympy expression in the given ``symbols``.

    ``symbols`` maps the names the text may use to the sympy symbols they stand for (a user's
    ``n`` becomes the package's valence symbol this way, never a free parameter of the same
    name). ``argument`` names the input in error messages (``"[edge] a.-1"``, ``"--alpha"``).
    ``kronecker`` allows ``KroneckerDelta(a, b)`` of integer polynomials in the names.
    Raises :class:`~symdecomp.errors.InvalidExpressionError` for anything outside the grammar
    in the module docstring or the budget, for a division by zero, and for a value that is not finite.
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
    if kronecker:
        names[_KRONECKER_ALLOWED] = sp.KroneckerDelta
    try:
        value, _ = _build(tree.body, names, where, 0, text.strip())
    except ZeroDivisionError:
        raise InvalidExpressionError(f"{where}: division by zero") from None
    except RecursionError:
        raise InvalidExpressionError(f"{where}: nested deeper than {MAX_DEPTH}") from None
    if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise InvalidExpressionError(f"{where}: not finite")
    return value


def _literal(node: ast.Constant, where: str, source: str) -> tuple[sp.Expr, _Cost]:
    value = node.value
    if isinstance(value, bool) or not isinstance(value, (int, float, complex)):
        raise InvalidExpressionError(f"{where}: {value!r} is not a number")
    if not isinstance(value, int):
        raise InvalidExpressionError(f"{where}: {value!r} is a float; give an exact rational such as '3/8'")
    written = ast.get_source_segment(source, node) or ""
    if "_" in written:
        raise InvalidExpressionError(f"{where}: digit separators '_' are not allowed")
    if not _DECIMAL.fullmatch(written):
        raise InvalidExpressionError(f"{where}: {written!r} is not a decimal integer; write numbers with the digits 0-9")
    if len(written) > MAX_DIGITS:
        raise InvalidExpressionError(f"{where}: an integer has more than {MAX_DIGITS} digits")
    return sp.Integer(value), _leaf(bits=max(1, value.bit_length()))


def _build(node: ast.AST, names: Mapping[str, sp.Expr], where: str, depth: int, source: str) -> tuple[sp.Expr, _Cost]:
    """The sympy value of ``node`` and its cost; each node's cost is checked before its value is built."""
    if depth > MAX_DEPTH:
        raise InvalidExpressionError(f"{where}: nested deeper than {MAX_DEPTH}")
    deeper = depth + 1
    if isinstance(node, ast.Constant):
        return _literal(node, where, source)
    if isinstance(node, ast.Name):
        if node.id not in names:
            known = ", ".join(sorted(k for k in names if k.isidentifier())) or "none"
            raise InvalidExpressionError(f"{where}: unknown name {node.id!r} (known: {known})")
        value = names[node.id]
        return value, _leaf(degree=int(node.id == "n"), bits=2 if value is sp.pi else VALENCE_BITS)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
        operand, cost = _build(node.operand, names, where, deeper, source)
        return (-operand if isinstance(node.op, ast.USub) else operand), _checked(_product([cost]), where)
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        return _chain(node, names, where, deeper, source)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
        base, bcost = _build(node.left, names, where, deeper, source)
        exponent, ecost = _build(node.right, names, where, deeper, source)
        if not (exponent.is_Integer or exponent in (_HALF, -_HALF)):
            raise InvalidExpressionError(f"{where}: exponents must be integers or 1/2, got {exponent}")
        _check_exponent(exponent, where, halves=False)
        cost = _checked(_power(bcost, exponent, ecost.nodes), where)
        if base == 0 and exponent < 0:
            raise ZeroDivisionError
        return base**exponent, cost
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == _KRONECKER and _KRONECKER_ALLOWED in names:
        return _kronecker(node, names, where, deeper, source)
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCTIONS:
            raise InvalidExpressionError(f"{where}: calls only {', '.join(_FUNCTIONS)}")
        if node.keywords or len(node.args) != 1:
            raise InvalidExpressionError(f"{where}: {node.func.id} takes one argument")
        argument, acost = _build(node.args[0], names, where, deeper, source)
        if node.func.id == "sqrt":
            cost = _checked(_power(acost, _HALF), where)
        else:
            cost = _checked(_trig(acost), where)
            _check_trig(argument, where)
        return _FUNCTIONS[node.func.id](argument), cost
    raise InvalidExpressionError(
        f"{where}: only numbers, + - * / **, parentheses, {', '.join(sorted(k for k in names if k.isidentifier()))} and "
        f"{', '.join(_FUNCTIONS)} are allowed"
    )


_KRONECKER = "KroneckerDelta"
#: The key that allows it in a parse's names (not an identifier: no name in the text can reach it).
_KRONECKER_ALLOWED = "KroneckerDelta()"


def _kronecker(node: ast.Call, names, where: str, depth: int, source: str) -> tuple[sp.Expr, _Cost]:
    """``KroneckerDelta(a, b)`` of two integer polynomials in the names (``j`` and ``0``, ``j`` and ``m - 1``)."""
    if node.keywords or len(node.args) != 2:
        raise InvalidExpressionError(f"{where}: KroneckerDelta takes two arguments")
    parts = [_build(a, names, where, depth, source) for a in node.args]
    for value, _ in parts:
        symbols = sorted(value.free_symbols, key=str)
        if value.has(sp.pi) or not value.is_polynomial(*symbols) or not all(
                c.is_Integer for c in (sp.Poly(value, *symbols).coeffs() if symbols else [value])):
            raise InvalidExpressionError(f"{where}: KroneckerDelta takes integer polynomials in the names, got {value}")
    cost = _checked(_Cost(1 + sum(c.nodes for _, c in parts), 0, 0, 1, 0, max(c.functions for _, c in parts)), where)
    return sp.KroneckerDelta(parts[0][0], parts[1][0]), cost


def _chain(node: ast.BinOp, names, where: str, depth: int, source: str) -> tuple[sp.Expr, _Cost]:
    """A chain ``a + b - c + ...`` (or ``a * b / c ...``), which Python's parser nests to the left, as one level."""
    additive = isinstance(node.op, (ast.Add, ast.Sub))
    family = (ast.Add, ast.Sub) if additive else (ast.Mult, ast.Div)
    operations = []
    while isinstance(node, ast.BinOp) and isinstance(node.op, family):
        operations.append((type(node.op), node.right))
        node = node.left
        if len(operations) > MAX_NODES:
            raise InvalidExpressionError(f"{where}: more than {MAX_NODES} operations, numbers and names")
    value, cost = _build(node, names, where, depth, source)
    costs = [cost]
    for op, operand in reversed(operations):
        right, rcost = _build(operand, names, where, depth, source)
        if additive:
            cost = _checked(_sum([*costs, rcost]), where)
        else:
            cost = _checked(_product([*costs, rcost.inverse() if op is ast.Div else rcost]), where)
        if op is ast.Div and right == 0:
            raise ZeroDivisionError
        costs.append(rcost.inverse() if op is ast.Div else rcost)
        value = _BINARY[op](value, right)
    return value, cost


def check_budget(expr: sp.Expr, argument: str = "expression") -> None:
    """Refuse a sympy expression beyond the budget (the same bounds as text; :data:`BUDGET`).

    Walks the tree without changing it and stops at the first bound exceeded, so a huge expression costs
    at most :data:`MAX_NODES` steps. Raises :class:`~symdecomp.errors.InvalidExpressionError` naming ``argument``.
    """
    _tree_cost(expr, argument, 0, [0])


def _tree_cost(e: sp.Basic, where: str, depth: int, seen: list) -> _Cost:
    seen[0] += 1
    if seen[0] > MAX_NODES:
        raise InvalidExpressionError(f"{where}: more than {MAX_NODES} operations, numbers and names")
    if depth > MAX_DEPTH:
        raise InvalidExpressionError(f"{where}: nested deeper than {MAX_DEPTH}")
    if e.is_Rational:
        return _checked(_leaf(bits=max(1, abs(int(e.p)).bit_length()), den=int(e.q).bit_length() - 1), where)
    if e.is_Symbol:
        return _leaf(degree=int(e.name == "n"), bits=VALENCE_BITS)
    if e.is_Atom or not e.args:
        return _leaf(bits=2)
    if len(e.args) > MAX_NODES:
        raise InvalidExpressionError(f"{where}: more than {MAX_NODES} operations, numbers and names")
    if isinstance(e, sp.Pow):
        _check_exponent(e.exp, where, halves=True)
        return _checked(_power(_tree_cost(e.base, where, depth + 1, seen), e.exp), where)
    parts = [_tree_cost(a, where, depth + 1, seen) for a in e.args]
    if isinstance(e, sp.Add):
        return _checked(_sum(parts), where)
    if isinstance(e, sp.Mul):
        return _checked(_product(parts), where)
    if isinstance(e, (sp.cos, sp.sin)):
        _check_trig(e.args[0], where)
        return _checked(_trig(parts[0]), where)
    # anything else (cases of a Piecewise, relations): its parts' cost, one more level of functions
    return _checked(_Cost(1 + sum(p.nodes for p in parts), max(p.num_degree for p in parts), max(p.den_degree for p in parts),
                          max(p.num for p in parts), max(p.den for p in parts),
                          max(p.functions for p in parts) + isinstance(e, (sp.Function, sp.Piecewise))), where)


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
    if isinstance(value, (int, Fraction)):
        value = sp.Rational(value.numerator, value.denominator)
        check_budget(value, argument)
        return value
    if isinstance(value, sp.Basic):
        if not isinstance(value, sp.Expr):
            raise InvalidExpressionError(f"{argument} {value!r} is not an expression")
        check_budget(value, argument)  # first: the checks below walk the whole tree
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
        return exact_value(int(value), argument=argument)
    if isinstance(value, numbers.Real):
        raise InvalidExpressionError(f"{argument} {value!r} is a float; give an exact rational such as '3/8'")
    raise InvalidExpressionError(f"{argument} {value!r} ({type(value).__name__}) is not a number")


def identically_zero(expr) -> bool:
    """Whether an expression of weights vanishes identically in ``n`` and the parameters (the affinity checks).

    Decided by polynomial arithmetic, never by an unbounded ``simplify``: the expression is brought over one
    denominator and cancelled, with any cosine, sine or square root taken as one more indeterminate, so that a
    weight that is a polynomial of degree 17 in ``n`` costs a few polynomial products. Zero there is zero for every
    value. A rational function of ``n`` and the parameters that does not cancel to zero is not zero (cancellation over
    Q is canonical); only a remainder holding cosines or square roots, which may still vanish by their relations
    (``cos(2*pi/n) = 2*cos(pi/n)**2 - 1``), goes to sympy's ``simplify``, on an expression within the budget.

    >>> n = sp.Symbol("n")
    >>> identically_zero(3/(2*n**2) * (n - 3) * (n - 5) - (3*n**2 - 24*n + 45)/(2*n**2))
    True
    >>> identically_zero(n/(n + 1) - 1)
    False
    """
    rest = sp.cancel(sp.together(sp.expand(sp.sympify(expr, strict=True))))
    if rest == 0:
        return True
    if all(atom.is_Rational for atom in rest.atoms(sp.Number)) and rest.is_rational_function(*rest.free_symbols):
        return False
    return sp.simplify(rest) == 0
