"""Displayed formulas that fit the page: sympy prints, TeX breaks, long unbreakable parts are named.

A displayed formula is set in ``breqn``'s ``dmath*``, which breaks a long formula between the
terms of its sums (also inside ``\\left( ... \\right)``) by itself. sympy's printer is used with
one setting, ``long_frac_ratio``: a long numerator over a short denominator is printed as
``\\frac{1}{D} \\left(N\\right)``, so that its terms can break too.

What TeX cannot break (a denominator, the argument of a function or a root, an exponent, a
matrix entry, an item of a tuple) is *named* when it is long: it is replaced by
:math:`\\xi_k` and its definition is displayed below the formula ("where
:math:`\\xi_1 = \\dots`"). A matrix too wide for the page has its longest entries named
(:math:`m_{rc}`), and if its columns alone are too many, it is shown in blocks of columns.

Lengths are counted in characters of sympy's printing (:func:`size`), a generous proxy for
the printed width; nothing here measures glyphs. The tests compile the documents
and fail on any overfull box.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from fractions import Fraction

import sympy as sp
from sympy.printing.latex import LatexPrinter

__all__ = ["SETTINGS", "LINE", "ATOM", "latex", "size", "Names", "name_long_parts", "formula_display", "matrix_display",
           "matrix_width", "mapping_rows", "rows_display"]

#: The settings of sympy's LaTeX printer for everything this package typesets.
SETTINGS = {"long_frac_ratio": 6}
_PRINTER = LatexPrinter(SETTINGS)

#: A line of a displayed formula, in characters (:func:`size`, about 0.5 em each).
LINE = 80
#: A part TeX cannot break is named when its size is larger than this.
ATOM = 48
#: A matrix entry is named when the matrix is too wide and the entry longer than this;
#: when even short entries leave it too wide, it is shown in blocks of columns, and only an
#: entry longer than ``BLOCK_ENTRY`` is named.
ENTRY = 8
BLOCK_ENTRY = 24


def latex(obj) -> str:
    """``obj`` printed by sympy with :data:`SETTINGS`.

    >>> from sympy.abc import n
    >>> latex(sp.expand((n + 1) ** 6) / (8 * n))
    '\\\\frac{1}{8 n} \\\\left(n^{6} + 6 n^{5} + 15 n^{4} + 20 n^{3} + 15 n^{2} + 6 n + 1\\\\right)'
    """
    return obj if isinstance(obj, str) else _PRINTER.doprint(obj)


def size(obj) -> int:
    """The length of ``obj`` as printed, in characters: a command (``\\alpha``, ``\\frac``) counts as
    one, spaces, braces and ``\\left``/``\\right`` as none. A generous proxy for the printed width
    (a fraction counts as its numerator and denominator side by side).

    >>> size(r"\\frac{\\alpha}{2} + \\left(x_{1}\\right)")
    8
    """
    tex = latex(obj)
    return len(re.sub(r"\\[A-Za-z]+", "x", re.sub(r"\\(left|right)\b|[{}^_ ]", "", tex)))


# --------------------------------------------------------------------------------------
# Naming the long parts TeX cannot break


class Names:
    """The sub-expressions named in one display, in order of naming; equal parts share a name."""

    def __init__(self, stem: str = "xi"):
        self.stem = stem
        self.parts: dict[sp.Symbol, sp.Expr] = {}
        self._by_part: dict[sp.Basic, sp.Symbol] = {}

    def name(self, part: sp.Basic) -> sp.Symbol:
        if part not in self._by_part:
            symbol = sp.Symbol("%s_%d" % (self.stem, len(self.parts) + 1))
            self._by_part[part] = symbol
            self.parts[symbol] = part
        return self._by_part[part]


def _fraction(expr):
    """(numerator, denominator) of a product or power as sympy prints it."""
    if isinstance(expr, (sp.Mul, sp.Pow)):
        return sp.fraction(expr)
    return expr, sp.Integer(1)


def _named(expr, names: Names):
    """``expr``, in a place where TeX may break it, with its long unbreakable parts named.

    The terms of a sum, the factors of a product, the base of an integer power and the sides
    of a relation may go on separate lines; a denominator, a numerator that sympy keeps in
    its fraction, the arguments of anything else (a root, a function, a case) are boxes.
    """
    if not isinstance(expr, sp.Basic) or isinstance(expr, sp.MatrixBase) or size(expr) <= ATOM:
        return expr
    numer, denom = _fraction(expr)
    if denom != 1:
        top = _named(numer, names) if _pulled_out(numer, denom) else _boxed(numer, names)
        bottom = _boxed(denom, names)
        return expr if (top, bottom) == (numer, denom) else sp.Mul(top, sp.Pow(bottom, -1))
    if isinstance(expr, (sp.Add, sp.Mul)) or isinstance(expr, sp.Pow) and expr.exp.is_Integer:
        args = [_named(arg, names) for arg in expr.args]
    elif isinstance(expr, sp.Rel):
        args = [_named(expr.lhs, names), _named(expr.rhs, names)]
    elif isinstance(expr, sp.Piecewise):
        args = [piece.func(_boxed(piece.expr, names), piece.cond) for piece in expr.args]
    else:
        args = [_boxed(arg, names) for arg in expr.args]
    if args == list(expr.args):
        return expr  # unchanged, also a form the caller built unevaluated
    return expr.func(*args, evaluate=False) if isinstance(expr, sp.Rel) else expr.func(*args)


def _pulled_out(numer, denom) -> bool:
    """Whether sympy prints ``numer / denom`` as ``\\frac{1}{denom} (numer)`` (see :data:`SETTINGS`),
    taking into account that a long denominator will be named."""
    tokens = 1 if size(denom) > ATOM else len(latex(denom).split())
    return len(latex(numer).split()) > SETTINGS["long_frac_ratio"] * tokens


def _boxed(part, names: Names):
    """A part TeX cannot break: named if it is a long expression."""
    if isinstance(part, sp.Expr) and not part.is_Atom and size(part) > ATOM:
        return names.name(part)
    return part


def name_long_parts(expr, names: Names):
    """``expr`` with its long unbreakable parts replaced by names (recorded in ``names``).

    >>> from sympy.abc import x
    >>> names = Names()
    >>> name_long_parts(sp.sqrt(sp.expand((x + 1) ** 12)) + 1, names)
    sqrt(xi_1) + 1
    >>> list(names.parts.values())[0].has(x**12)
    True
    """
    return _named(expr, names)


# --------------------------------------------------------------------------------------
# Displays

_RELATIONS = {"==": "=", "!=": r"\neq", "<": "<", "<=": r"\leq", ">": ">", ">=": r"\geq"}


def _split(expr, lhs, rel: str = "="):
    """(lhs, relation symbol, rhs) of a step: a sympy relation is split at its operator."""
    if lhs is None and isinstance(expr, sp.Rel):
        return expr.lhs, _RELATIONS.get(expr.rel_op, latex(expr).split()[0]), expr.rhs
    return lhs, rel, expr


def _is_name(key) -> bool:
    """Whether a mapping's key names its value (``x = 1``) rather than maps to it (``2 \\mapsto 1``)."""
    if isinstance(key, str):
        return True
    if isinstance(key, (sp.Symbol, sp.Indexed, sp.MatrixSymbol, sp.IndexedBase)):
        return True
    return isinstance(key, sp.Function) and isinstance(key.func, sp.core.function.UndefinedFunction)


def mapping_rows(mapping: Mapping) -> tuple[list, str]:
    """The rows of a mapping and their relation: names in the given order (``x = 1``);
    anything else, e.g. eigenvalues with multiplicities, in sympy's sort order (``2 \\mapsto 1``)."""
    items = list(mapping.items())
    if all(_is_name(k) for k, _ in items):
        return items, "="
    return sorted(items, key=lambda kv: sp.default_sort_key(kv[0])), r"\mapsto"


def _sympify(obj):
    """Plain Python numbers, fractions, tuples and matrices as sympy objects (else LaTeX)."""
    if isinstance(obj, (tuple, list)):
        try:
            return sp.Tuple(*obj)
        except (sp.SympifyError, TypeError):
            return latex(obj)
    if isinstance(obj, sp.MatrixBase):
        return sp.ImmutableMatrix(obj)
    if isinstance(obj, (int, float, complex, Fraction)):
        return sp.sympify(obj, strict=True)
    return obj


def _dmath(tex: str) -> str:
    return "\\begin{dmath*}\n%s\n\\end{dmath*}\n" % tex


def _side(obj, names: Names) -> str:
    return latex(name_long_parts(obj, names))


def _definitions(names: Names, start: int = 0) -> str:
    """``where`` and the definitions of the names from ``start`` on (they may name more parts)."""
    out, done = [], start
    while done < len(names.parts):
        symbol, part = list(names.parts.items())[done]
        out.append(_dmath(latex(symbol) + " = " + _side(part, names)))
        done += 1
    return "where\n" + "".join(out) if out else ""


def formula_display(lhs, rel: str, rhs) -> str:
    """``lhs rel rhs`` (or ``rhs`` alone) in ``dmath*``, with the definitions of named parts below;
    a sympy relation without ``lhs`` is split at its operator, a matrix goes to :func:`matrix_display`."""
    names = Names()
    lhs, rel, rhs = _split(_sympify(rhs), lhs, rel)
    if isinstance(rhs, sp.MatrixBase):
        return matrix_display(lhs, rel, rhs)
    tex = _side(rhs, names)
    if lhs is not None:
        tex = _side(lhs, names) + " " + rel + " " + tex
    return _dmath(tex) + _definitions(names)


def _entry_name(r: int, c: int, shape) -> sp.Symbol:
    sep = "," if max(shape) > 9 else ""
    return sp.Symbol("m_{%d%s%d}" % (r + 1, sep, c + 1))


def matrix_width(matrix: sp.MatrixBase) -> int:
    """Plain-text width of a matrix: its widest entry per column, and room between columns."""
    columns = [max(size(matrix[r, c]) for r in range(matrix.rows)) for c in range(matrix.cols)]
    return sum(columns) + 2 * len(columns)


def _name_entries(matrix: sp.MatrixBase, budget: int, longer_than: int) -> tuple[sp.Matrix, list]:
    """The matrix with its longest entries named (longest first) until it fits in ``budget`` or
    no entry is ``longer_than``; and the positions named."""
    shown = sp.Matrix(matrix)
    entries = sorted((-size(matrix[r, c]), r, c) for r in range(matrix.rows) for c in range(matrix.cols))
    named = []
    for negative, r, c in entries:
        if matrix_width(shown) <= budget or -negative <= longer_than:
            break
        shown[r, c] = _entry_name(r, c, matrix.shape)
        named.append((r, c))
    return shown, sorted(named)


def _column_blocks(matrix: sp.MatrixBase, budget: int) -> list[tuple[int, int]]:
    """Consecutive column ranges ``[start, stop)`` each of which fits in ``budget``."""
    blocks, start = [], 0
    for stop in range(1, matrix.cols + 1):
        if stop - start > 1 and matrix_width(matrix[:, start:stop]) > budget:
            blocks.append((start, stop - 1))
            start = stop - 1
    blocks.append((start, matrix.cols))
    return blocks


def matrix_display(lhs, rel: str, matrix: sp.MatrixBase) -> str:
    """A matrix, readable when too wide: long entries named and listed, or blocks of columns."""
    matrix = sp.ImmutableMatrix(matrix)
    prefix = "" if lhs is None else latex(lhs) + " " + rel + " "
    budget = LINE - size(prefix)
    shown, named = _name_entries(matrix, budget, ENTRY)
    if matrix_width(shown) <= budget:
        out = "\\[\n%s%s\n\\]\n" % (prefix, latex(sp.ImmutableMatrix(shown)))
    else:  # too many columns: blocks of them, naming only the entries too long for a block
        shown, named = _name_entries(matrix, 0, BLOCK_ENTRY)
        out = ""
        for start, stop in _column_blocks(shown, LINE):
            label = "columns %d to %d" % (start + 1, stop) if stop - start > 1 else "column %d" % (start + 1)
            if lhs is not None:
                label = "$%s$, %s" % (latex(lhs), label)
            out += "%s:\n\\[\n%s\n\\]\n" % (label[0].upper() + label[1:], latex(sp.ImmutableMatrix(shown[:, start:stop])))
    if named:
        rows = [(_entry_name(r, c, matrix.shape), matrix[r, c]) for r, c in named]
        out += "where\n" + rows_display(rows)
    return out


def rows_display(rows: Sequence[tuple[object, object]], rel: str = "=") -> str:
    """Equations ``lhs rel rhs``, one ``dmath*`` each, grouped (aligned at the relation)."""
    out, group = [], []

    def flush():
        if group:
            out.append("\\begin{dgroup*}\n" + "".join(group) + "\\end{dgroup*}\n")
            group.clear()

    for lhs, rhs in rows:
        if isinstance(rhs, sp.MatrixBase):
            flush()
            out.append(matrix_display(lhs, rel, rhs))
            continue
        names = Names()
        group.append(_dmath(_side(lhs, names) + " " + rel + " " + _side(rhs, names)))
        if names.parts:
            flush()
            out.append(_definitions(names))
    flush()
    return "".join(out)
