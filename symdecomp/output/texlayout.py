"""Laying out sympy's LaTeX on a page: estimated widths and line breaks for long formulas.

The derivations are printed by sympy's LaTeX printer, whose output is one long line. A
formula wider than the text block must be broken (``multline``) instead of running past
the margin. This module estimates the printed width of a LaTeX math string without running
TeX (so that the generated files do not depend on whether TeX is installed) and cuts a
sympy expression into pieces that may be set on separate lines: the terms of a sum, the
factors of a product, the numerator of a long fraction, the items of a tuple.

The estimate is deliberately generous (it overestimates real widths, checked against TeX
in the tests), so a formula the layout accepts as one line fits. A piece that cannot be
broken further and is still too wide is wrapped in ``\\fitwidth{...}``, a macro of the
document template that lets TeX measure it and shrink it only if it really is too wide.

Widths are in ``em`` of the document's body font in display style.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import sympy as sp
from sympy.printing.latex import LatexPrinter

__all__ = ["estimate_width", "Piece", "break_pieces", "pack_lines", "LINE_WIDTH_EM"]

#: The width available to one line of a displayed formula, in em. The template's text block
#: is 160 mm (A4, 25 mm margins) = 41.6 em of the 11 pt body font; ``multline`` indents the
#: first and last lines by 10 pt, and the estimate of this module runs high, so 36 em is safe.
LINE_WIDTH_EM = 36.0

_TOKEN = re.compile(r"\\[A-Za-z]+\*?|\\.|[{}^_&]|\s+|.", re.S)

# Widths (em, at full size) of single characters in math mode, spacing included.
_BINARY = 1.25  # + - \cdot with medium spaces around
_RELATION = 1.4  # = < > with thick spaces around
_CHAR = {
    "+": _BINARY, "-": _BINARY, "=": _RELATION, "<": _RELATION, ">": _RELATION,
    ",": 0.45, ";": 0.45, ".": 0.3, ":": 0.5, "!": 0.35, "'": 0.35, "|": 0.35,
    "(": 0.45, ")": 0.45, "[": 0.35, "]": 0.35, "/": 0.55, "*": 0.55,
}
_SPACING = {"\\,": 0.17, "\\:": 0.23, "\\;": 0.28, "\\ ": 0.35, "\\!": 0.0, "\\quad": 1.0, "\\qquad": 2.0}
_ZERO = {"\\displaystyle", "\\textstyle", "\\limits", "\\nolimits", "\\left.", "\\right.", "\\middle"}
_BIG_OPERATORS = {"\\sum": 1.5, "\\prod": 1.5, "\\int": 1.0, "\\oint": 1.0, "\\bigcup": 1.3, "\\bigcap": 1.3}
_WIDE_SYMBOLS = {
    "\\cdot": 0.8, "\\times": _BINARY, "\\pm": _BINARY, "\\mp": _BINARY, "\\circ": 1.0,
    "\\leq": _RELATION, "\\geq": _RELATION, "\\neq": _RELATION, "\\le": _RELATION, "\\ge": _RELATION,
    "\\ne": _RELATION, "\\approx": _RELATION, "\\equiv": _RELATION, "\\sim": _RELATION,
    "\\to": 1.6, "\\rightarrow": 1.6, "\\mapsto": 1.6, "\\Rightarrow": 1.6, "\\in": 1.2,
    "\\ldots": 1.3, "\\dots": 1.3, "\\cdots": 1.3, "\\vdots": 0.5, "\\ddots": 1.3,
    "\\infty": 1.1, "\\nabla": 0.9, "\\wedge": _BINARY, "\\vee": _BINARY, "\\otimes": _BINARY, "\\oplus": _BINARY,
    "\\lbrace": 0.55, "\\rbrace": 0.55, "\\{": 0.55, "\\}": 0.55, "\\langle": 0.45, "\\rangle": 0.45,
}
# Commands that take one argument and are (about) as wide as it.
_WRAPPERS = {
    "\\mathrm", "\\mathit", "\\mathbf", "\\boldsymbol", "\\mathsf", "\\mathtt", "\\mathcal",
    "\\mathbb", "\\mathfrak", "\\mathscr", "\\overline", "\\underline", "\\hat", "\\bar",
    "\\tilde", "\\dot", "\\ddot", "\\vec", "\\check", "\\breve", "\\acute", "\\grave",
    "\\widehat", "\\widetilde", "\\operatorname", "\\text", "\\textrm", "\\textit", "\\textbf",
    "\\mbox", "\\displaystyle",
}
_TEXT_WRAPPERS = {"\\text", "\\textrm", "\\textit", "\\textbf", "\\mbox", "\\operatorname", "\\mathrm"}


def _char_width(ch: str, upright: bool) -> float:
    if ch in _CHAR:
        return _CHAR[ch]
    if ch.isspace():
        return 0.35 if upright else 0.0
    if ch.isdigit():
        return 0.52
    if ch in "MWNHKQUVX":
        return 1.1
    if ch.isupper():
        return 0.9
    if ch in "mw":
        return 0.9
    return 0.62


class _Reader:
    """Recursive reader of a LaTeX math token stream, summing estimated widths."""

    def __init__(self, tex: str):
        self.tokens = _TOKEN.findall(tex)
        self.i = 0

    def peek(self):
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def next(self):
        tok = self.peek()
        self.i += 1
        return tok

    def skip_space(self):
        while self.peek() is not None and self.peek().isspace():
            self.i += 1

    def group(self, scale: float, upright: bool = False) -> float:
        """Width of the next argument: a braced group or a single token."""
        self.skip_space()
        tok = self.peek()
        if tok == "{":
            self.next()
            width = self.sequence(scale, upright, stop="}")
            self.next()
            return width
        if tok is None:
            return 0.0
        return self.atom(scale, upright)

    def raw_group(self) -> str:
        """The text of the next braced group (environment names, array column specs)."""
        self.skip_space()
        if self.peek() != "{":
            return ""
        self.next()
        depth, out = 1, []
        while self.peek() is not None:
            tok = self.next()
            if tok == "{":
                depth += 1
            elif tok == "}":
                depth -= 1
                if depth == 0:
                    break
            out.append(tok)
        return "".join(out)

    def sequence(self, scale: float, upright: bool = False, stop=None) -> float:
        width = 0.0
        while self.peek() is not None and self.peek() != stop:
            if stop is not None and isinstance(stop, tuple) and self.peek() in stop:
                break
            width += self.atom(scale, upright)
        return width

    def atom(self, scale: float, upright: bool = False) -> float:
        tok = self.next()
        script = max(scale * 0.72, 0.5)
        if tok is None or tok == "}":
            return 0.0
        if tok == "{":
            width = self.sequence(scale, upright, stop="}")
            self.next()
            return width
        if tok in ("^", "_"):
            return self.group(script) + 0.1 * scale
        if tok.isspace():
            return _char_width(" ", upright) * scale
        if not tok.startswith("\\"):
            return _char_width(tok, upright) * scale
        if tok in _SPACING:
            return _SPACING[tok] * scale
        if tok in _ZERO:
            return 0.0
        if tok in ("\\left", "\\right", "\\bigl", "\\bigr", "\\Bigl", "\\Bigr", "\\biggl", "\\biggr", "\\big", "\\Big"):
            self.skip_space()
            delim = self.next() or ""
            return 0.0 if delim == "." else 0.75 * scale
        if tok in ("\\frac", "\\dfrac", "\\tfrac", "\\binom"):
            inner = scale if scale >= 1.0 and tok != "\\tfrac" else script
            num = self.group(inner)
            den = self.group(inner)
            return max(num, den) + 0.4 * scale + (1.6 * scale if tok == "\\binom" else 0.0)
        if tok == "\\sqrt":
            self.skip_space()
            index = 0.0
            if self.peek() == "[":
                self.next()
                index = self.sequence(script * 0.8, stop="]")
                self.next()
            return self.group(scale) + 1.0 * scale + index
        if tok == "\\begin":
            return self.environment(self.raw_group(), scale)
        if tok == "\\end":
            self.raw_group()
            return 0.0
        if tok in _BIG_OPERATORS:
            width = _BIG_OPERATORS[tok] * scale
            self.skip_space()
            limits = 0.0
            while self.peek() in ("_", "^", "\\limits"):
                if self.next() == "\\limits":
                    continue
                limits = max(limits, self.group(script))
            return max(width, limits) + 0.3 * scale
        if tok in _TEXT_WRAPPERS:
            return self.group(scale, upright=True) + 0.2 * scale
        if tok in _WRAPPERS:
            return self.group(scale, upright) * 1.05
        if tok in _WIDE_SYMBOLS:
            return _WIDE_SYMBOLS[tok] * scale
        if tok in ("\\{", "\\}", "\\%", "\\&", "\\#", "\\$", "\\_"):
            return 0.6 * scale
        if tok == "\\\\":
            return 0.0
        name = tok[1:]
        if name in {"sin", "cos", "tan", "cot", "sec", "csc", "log", "ln", "exp", "det", "arg", "max",
                    "min", "sinh", "cosh", "tanh", "lim", "gcd", "deg", "dim", "ker", "Pr", "sup", "inf"}:
            return (0.5 * len(name) + 0.3) * scale
        if name in {"operatorname", "mathrm"}:
            return self.group(scale, upright=True)
        # Greek letters and other single symbols; an unknown command with a braced argument
        # is counted as its argument plus the symbol.
        width = (0.95 if name[:1].isupper() else 0.7) * scale
        self.skip_space()
        if self.peek() == "{":
            width += self.group(scale, upright)
        return width

    def environment(self, name: str, scale: float) -> float:
        """Width of an array-like environment: sum of its widest cells per column."""
        name = name.rstrip("*")
        if name in ("array", "tabular"):
            self.raw_group()  # column specification
        # cells of matrices and cases are in text style: their fractions are script size
        grids = ("matrix", "pmatrix", "bmatrix", "vmatrix", "Vmatrix", "smallmatrix", "cases", "array")
        cell_scale = scale if name not in grids else min(scale, 0.999)
        if name == "smallmatrix":
            cell_scale = scale * 0.72
        columns: list[float] = []
        column = 0
        cell = 0.0
        while self.peek() is not None:
            tok = self.peek()
            if tok == "\\end":
                self.next()
                self.raw_group()
                break
            if tok in ("&", "\\\\"):
                self.next()
                while len(columns) <= column:
                    columns.append(0.0)
                columns[column] = max(columns[column], cell)
                cell = 0.0
                column = column + 1 if tok == "&" else 0
                continue
            cell += self.atom(cell_scale)
        while len(columns) <= column:
            columns.append(0.0)
        columns[column] = max(columns[column], cell)
        gap = 1.0 * scale  # 2 \arraycolsep = 10 pt, plus the cells' own margins
        width = sum(columns) + gap * max(len(columns) - 1, 0)
        if name == "cases":
            width += 1.0 * scale + 1.0 * scale  # brace and \quad before the condition
        if name in ("pmatrix", "bmatrix", "vmatrix", "Vmatrix"):
            width += 1.2 * scale
        return width


def estimate_width(tex: str) -> float:
    """Estimated width, in em of the body font, of ``tex`` set in display math.

    Generous by design: a string whose estimate is below :data:`LINE_WIDTH_EM` fits on a line.

    >>> estimate_width("x") < estimate_width("x + y") < estimate_width(r"x + y + \\frac{1}{2}")
    True
    >>> estimate_width(r"\\frac{a + b + c}{2}") < estimate_width("a + b + c + 2")
    True
    """
    return _Reader(tex).sequence(1.0)


@dataclass(frozen=True)
class Piece:
    """A fragment of a displayed formula after which a line may be broken."""

    #: The LaTeX of the fragment, including the operator that joins it to the previous one.
    tex: str
    #: Its estimated width (em).
    width: float

    @classmethod
    def of(cls, tex: str) -> Piece:
        return cls(tex, estimate_width(tex))


_PRINTER = LatexPrinter()


def _delimiters(tex: str) -> tuple[str, str]:
    """Fixed-size parentheses for a group split across lines (``\\left``/``\\right`` cannot be)."""
    if "\\frac" in tex or "\\sqrt" in tex or "matrix" in tex:
        return r"\Bigl(", r"\Bigr)"
    return r"\bigl(", r"\bigr)"


def _attach(prefix: str, pieces: list[Piece], suffix: str = "") -> list[Piece]:
    """Glue ``prefix`` to the first piece and ``suffix`` to the last."""
    if not pieces:
        return [Piece.of(prefix + suffix)]
    out = list(pieces)
    out[0] = Piece.of(prefix + out[0].tex)
    out[-1] = Piece.of(out[-1].tex + suffix)
    return out


def _add_terms(expr: sp.Add) -> list[tuple[str, sp.Expr]]:
    """The terms of a sum in sympy's printing order, each with the sign sympy prints before it."""
    out = []
    for i, term in enumerate(_PRINTER._as_ordered_terms(expr, order=None)):
        if i == 0:
            out.append(("", term))
        elif term.could_extract_minus_sign():
            out.append((" - ", -term))
        else:
            out.append((" + ", term))
    return out


def break_pieces(expr, budget: float = LINE_WIDTH_EM) -> list[Piece]:
    """Cut ``expr`` into pieces, each at most ``budget`` em wide where the structure allows.

    Concatenating the pieces' LaTeX gives ``expr`` as sympy prints it, except that a group
    split across lines is written with fixed-size parentheses, and a long fraction
    ``N/D`` as ``\\frac{1}{D} (N)``. A piece that cannot be cut is returned whole (the
    caller shrinks it with ``\\fitwidth``).

    >>> from sympy.abc import x
    >>> parts = break_pieces(sum(x**k for k in range(40)), budget=20)
    >>> len(parts) > 1 and all(p.width <= 20 for p in parts)
    True
    """
    tex = sp.latex(expr)
    whole = Piece.of(tex)
    if whole.width <= budget or not isinstance(expr, sp.Basic):
        return [whole]
    if isinstance(expr, sp.Add):
        pieces: list[Piece] = []
        for sign, term in _add_terms(expr):
            term_tex = sp.latex(term)
            if _PRINTER._needs_add_brackets(term):
                inner = break_pieces(term, budget - 2)
                if len(inner) == 1:
                    pieces.append(Piece.of(sign + r"\left(" + term_tex + r"\right)"))
                    continue
                left, right = _delimiters(term_tex)
                pieces.extend(_attach(sign + left, inner, right))
            else:
                pieces.extend(_attach(sign, break_pieces(term, budget - 2)))
        return pieces
    if isinstance(expr, sp.Mul):
        if expr.could_extract_minus_sign():
            return _attach("- ", break_pieces(-expr, budget - 2))
        numer, denom = sp.fraction(expr)
        if denom != 1:
            front = r"\frac{1}{%s}" % sp.latex(denom)
            inner = break_pieces(numer, budget - 2)
            if isinstance(numer, sp.Add):
                if len(inner) == 1:
                    return [Piece.of(front + r" \left(" + inner[0].tex + r"\right)")]
                left, right = _delimiters(sp.latex(numer))
                return _attach(front + " " + left, inner, right)
            return _attach(front + " ", inner)
        factors = expr.as_ordered_factors()
        pieces = []
        for k, factor in enumerate(factors):
            factor_tex = sp.latex(factor)
            # sympy separates a factor that starts with a digit by \cdot; so do we
            joiner = "" if k == 0 else (r" \cdot " if factor_tex[:1].isdigit() else " ")
            if isinstance(factor, sp.Add):
                inner = break_pieces(factor, budget - 2)
                if len(inner) == 1:
                    pieces.append(Piece.of(joiner + r"\left(" + factor_tex + r"\right)"))
                else:
                    left, right = _delimiters(factor_tex)
                    pieces.extend(_attach(joiner + left, inner, right))
            else:
                pieces.extend(_attach(joiner, break_pieces(factor, budget - 2)))
        return pieces
    if isinstance(expr, sp.Pow) and isinstance(expr.base, (sp.Add, sp.Mul)):
        # (long)^k, and also sqrt(long) and 1/long, as a power of a group split across lines
        inner = break_pieces(expr.base, budget - 3)
        left, right = _delimiters(sp.latex(expr.base))
        return _attach(left, inner, right + "^{%s}" % sp.latex(expr.exp))
    if isinstance(expr, sp.Abs):
        inner = break_pieces(expr.args[0], budget - 2)
        return _attach(r"\bigl|", inner, r"\bigr|")
    if isinstance(expr, sp.Function) and len(expr.args) == 1 and isinstance(expr.args[0], (sp.Add, sp.Mul)):
        # f(long): the name as sympy prints it for a short argument, then the argument broken
        if expr.func == sp.exp:
            head = r"\exp"
        else:
            name = sp.latex(expr.func(sp.Symbol("x")))
            head = name[: name.rfind("x")].replace(r"{\left(", "").replace(r"\left(", "")
        if r"\right" not in head and head.count("{") == head.count("}"):
            inner = break_pieces(expr.args[0], budget - 3)
            left, right = _delimiters(sp.latex(expr.args[0]))
            return _attach(head + left, inner, right)
    if isinstance(expr, sp.Tuple):
        return _sequence_pieces(list(expr), budget)
    return [whole]


def _sequence_pieces(items: list, budget: float) -> list[Piece]:
    """The items of a tuple as pieces ``(x_1,``, ``x_2,`` ..., ``x_k)``."""
    texts = [sp.latex(item) for item in items]
    left, right = _delimiters(" ".join(texts))
    pieces: list[Piece] = []
    for k, item in enumerate(items):
        inner = break_pieces(item, budget - 2)
        prefix = left if k == 0 else ""
        suffix = right if k == len(items) - 1 else ",\\ "
        pieces.extend(_attach(prefix, inner, suffix))
    return pieces or [Piece.of(r"\left(\right)")]


def pack_lines(pieces: list[Piece], budget: float = LINE_WIDTH_EM) -> list[str]:
    """Greedily fill lines of at most ``budget`` em with consecutive pieces.

    >>> pack_lines([Piece("a", 10), Piece(" + b", 10), Piece(" + c", 20)], budget=25)
    ['a + b', ' + c']
    """
    lines: list[str] = []
    current, width = "", 0.0
    for piece in pieces:
        if current and width + piece.width > budget:
            lines.append(current)
            current, width = "", 0.0
        current += piece.tex
        width += piece.width
    if current:
        lines.append(current)
    return lines
