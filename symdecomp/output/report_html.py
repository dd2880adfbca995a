"""The report (:mod:`symdecomp.output.report`) as one self-contained HTML file.

Everything is inside the file, so that it renders offline in a browser: the style sheet is inline,
figures are inline SVG (saved with fixed metadata and ids, each figure's ids prefixed with its name
so that two figures never share one), and formulas are MathML, which browsers render natively:
sympy's presentation printer (:func:`sympy.printing.mathml.mathml`) for every computed object, and
for the short formulas the package writes in its prose (``$A^j$``, ``$\\omega_{2n}^j$``) a small
translation of their TeX into HTML (letters, Greek, sub- and superscripts; any other command is shown
by its name). Text from outside (:class:`~symdecomp.claims.Verbatim`: the scheme's name, messages)
and every other string is escaped with :func:`html.escape`.
"""

from __future__ import annotations

import html
import re

import sympy as sp

from symdecomp.claims import Status, Verbatim
from symdecomp.output.plotting._mpl import figure_bytes
from symdecomp.output.report import Figure, Formula, Paragraph, Report, Table

__all__ = ["report_html", "tex_math_html"]

_STYLE = """
body { font-family: Georgia, serif; max-width: 60em; margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.3em; border-bottom: 1px solid #ccc; margin-top: 2em; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; width: 100%; }
th, td { border-bottom: 1px solid #ddd; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }
th { border-bottom: 2px solid #444; }
figure { margin: 1.5em 0; } figure svg { width: 100%; height: auto; } figcaption { font-size: 0.9em; }
math[display="block"] { margin: 0.6em 0; overflow-x: auto; }
.m { font-style: italic; }
.status { font-weight: bold; }
.s-proved { color: #007326; } .s-verified { color: #0d7359; } .s-numeric { color: #1a4099; }
.s-refuted { color: #bf0d0d; } .s-corrected { color: #bf6600; } .s-error { color: #730073; }
.s-undecided, .s-notapplicable { color: #666; }
"""

#: TeX commands of the package's prose, as characters.
_COMMANDS = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "varepsilon": "ε", "epsilon": "ε", "theta": "θ",
    "lambda": "λ", "mu": "μ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "varphi": "φ", "phi": "φ",
    "omega": "ω", "Omega": "Ω", "Delta": "Δ", "Lambda": "Λ", "Sigma": "Σ", "infty": "∞", "to": "→",
    "times": "×", "cdot": "·", "leq": "≤", "geq": "≥", "le": "≤", "ge": "≥", "neq": "≠", "pm": "±", "dots": "…",
    "ldots": "…", "cdots": "⋯", "in": "∈", "approx": "≈", "cos": "cos", "sin": "sin", "sqrt": "√", ",": " ",
    ";": " ", "{": "{", "}": "}",
}

_TOKEN = re.compile(r"\\([A-Za-z]+|.)|([_^])|(\{)|(\})|([^\\_^{}]+)", re.S)


def _group(tokens: list, i: int) -> tuple[str, int]:
    """The HTML of one argument of ``^``/``_`` starting at token ``i``: a braced group or one character."""
    if i < len(tokens) and tokens[i][2]:
        return _convert(tokens, i + 1, closing=True)
    if i < len(tokens) and tokens[i][4]:
        text = tokens[i][4]
        tokens[i] = (None, None, None, None, text[1:]) if len(text) > 1 else tokens[i]
        return html.escape(text[0]), (i if len(text) > 1 else i + 1)
    if i < len(tokens) and tokens[i][0]:
        return _command(tokens[i][0]), i + 1
    return "", i


def _command(name: str) -> str:
    return html.escape(_COMMANDS.get(name, name))


def _convert(tokens: list, i: int, closing: bool = False) -> tuple[str, int]:
    out = []
    while i < len(tokens):
        command, script, opening, close, text = tokens[i]
        if close:
            if closing:
                return "".join(out), i + 1
            i += 1
        elif opening:
            inner, i = _convert(tokens, i + 1, closing=True)
            out.append(inner)
        elif script:
            inner, i = _group(tokens, i + 1)
            out.append(f"<{'sup' if script == '^' else 'sub'}>{inner}</{'sup' if script == '^' else 'sub'}>")
        elif command:
            out.append(_command(command))
            i += 1
        else:
            out.append(html.escape(text))
            i += 1
    return "".join(out), i


def tex_math_html(tex: str) -> str:
    """The short TeX formula of a sentence as HTML (see the module docstring).

    >>> tex_math_html(r"\\omega_{2n}^j")
    '<span class="m">ω<sub>2n</sub><sup>j</sup></span>'
    >>> tex_math_html("<b>")
    '<span class="m">&lt;b&gt;</span>'
    """
    tokens = [m.groups() for m in _TOKEN.finditer(tex)]
    return '<span class="m">' + _convert(tokens, 0)[0] + "</span>"


def _prose(text: str) -> str:
    """Package prose: text escaped, ``$...$`` through :func:`tex_math_html`."""
    parts = re.split(r"(?<!\\)\$", text)
    if len(parts) % 2 == 0:
        parts[-2:] = [parts[-2] + "$" + parts[-1]]
    return "".join(html.escape(p.replace("\\$", "$")) if k % 2 == 0 else tex_math_html(p) for k, p in enumerate(parts))


def _math(obj) -> str:
    return "<math>" + sp.mathml(sp.sympify(obj, strict=True), printer="presentation") + "</math>"


def _part(part) -> str:
    if isinstance(part, Verbatim):
        return html.escape(part)
    if isinstance(part, Status):
        return f'<span class="status s-{part.value.replace(" ", "")}">{html.escape(part.value)}</span>'
    if isinstance(part, str):
        return _prose(part)
    return _math(part)


def _parts(parts) -> str:
    return "".join(_part(p) for p in parts)


def _svg(figure: Figure) -> str:
    """The figure as inline SVG: no XML prologue, its ids prefixed with the figure's name."""
    svg = figure_bytes(figure.figure, "svg").decode("utf-8")
    svg = svg[svg.index("<svg"):]
    prefix = figure.name + "-"
    svg = re.sub(r'\bid="([^"]+)"', lambda m: f'id="{prefix}{m.group(1)}"', svg)
    return re.sub(r'(href="#|url\(#)([^")]+)', lambda m: f"{m.group(1)}{prefix}{m.group(2)}", svg)


def _block(block) -> str:
    if isinstance(block, Paragraph):
        return f"<p>{_parts(block.parts)}</p>\n"
    if isinstance(block, Formula):
        body = sp.mathml(sp.sympify(block.lhs, strict=True), printer="presentation") + "<mo>=</mo>" + sp.mathml(block.expr, printer="presentation")
        return f'<math display="block"><mrow>{body}</mrow></math>\n'
    if isinstance(block, Table):
        head = "".join(f"<th>{_part(h)}</th>" for h in block.header)
        rows = "\n".join("<tr>" + "".join(f"<td>{_part(c)}</td>" for c in row) + "</tr>" for row in block.rows)
        return f"<table>\n<thead><tr>{head}</tr></thead>\n<tbody>\n{rows}\n</tbody>\n</table>\n"
    return f"<figure>\n{_svg(block)}\n<figcaption>{_parts(block.caption)}</figcaption>\n</figure>\n"


def report_html(report: Report) -> str:
    """The report as one HTML document (a ``str``), the same for the same report."""
    name = html.escape(report.scheme)
    valences = report.valences
    body = "".join(f"<h2>{_part(s.title)}</h2>\n" + "".join(_block(b) for b in s.blocks) for s in report.sections)
    return (
        "<!DOCTYPE html>\n<!-- Generated by `symdecomp report`. Do not edit: regenerate. -->\n"
        '<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        f"<title>Report on the subdivision scheme {name}</title>\n<style>{_STYLE}</style>\n</head>\n<body>\n"
        f"<h1>Report on the subdivision scheme {name}</h1>\n"
        f"<p>Everything symdecomp computes about the scheme {name} at the valences n = {valences[0]}, …, {valences[-1]}, "
        "by the analysis of I. P. Ivrissimtzis, R. Zayer, H.-P. Seidel, <em>Polygonal decompositions of quadrilateral "
        "subdivision meshes</em>: " + (_part(report.contents) if report.contents is not None else "the paper's claims checked "
        "for the scheme, its spectrum, its limit and tangent masks, Reif's test for C<sup>1</sup> and figures")
        + ". Every formula is printed by sympy from the computed objects.</p>\n"
        + body + "</body>\n</html>\n"
    )
