"""LaTeX output: the one entry point :func:`aslatex` and the document of derivations.

``aslatex`` is a :func:`functools.singledispatch` function (as in ampform): a sympy object
goes to sympy's printer, a mapping becomes an ``aligned`` block of ``lhs &= rhs`` rows, a
:class:`~symdecomp.claims.Step` a sentence and a displayed equation, a
:class:`~symdecomp.claims.CheckResult` its status (a coloured box when the paper was refuted
or corrected), evidence and derivation, a :class:`~symdecomp.claims.Claim` the whole entry
of the claim. The document (:func:`derivation_files`) is assembled from the same function;
``symdecomp derive`` writes it to disk.

The mathematics is never typed in here: every formula is printed by sympy from the objects
the checks computed. Displayed formulas are laid out by :mod:`symdecomp.output.texlayout`
(TeX breaks them, with ``breqn``); the preamble is the package file ``preamble.tex``. The
output is a pure function of its input (no dates, no global printing state), so regenerating
the files gives the same bytes.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping, Sequence
from fractions import Fraction
from importlib import resources

import sympy as sp

from symdecomp.algebra.numbers import to_sympy
from symdecomp.claims import CheckResult, Claim, Status, Step, Text, Verbatim, check_claim, scope_summary, section_key
from symdecomp.errors import InvalidTypeError
from symdecomp.output.texlayout import formula_display, latex, mapping_rows, rows_display, size

__all__ = ["aslatex", "text_latex", "findings_latex", "display_math", "SECTION_TITLES", "section_file_name",
           "derivation_files", "PREAMBLE"]

#: The paper's section titles, so that the document's sections mirror the paper's.
SECTION_TITLES = {
    "2": "Background",
    "3": "Suitable decomposition neighborhoods",
    "4": "1-ring decomposition for the Catmull-Clark scheme",
    "5": "Evolution of the eigencomponents",
    "5.1": "Tangent plane properties",
    "5.2": "Elliptic properties",
    "5.3": "Hyperbolic properties",
    "6": "Exact calculation on CB-matrices",
    "B.1": "Beyond the paper: curvature and shape",
    "B.2": "Beyond the paper: boundary and crease vertices",
}

PAPER = (
    "I.\\,P. Ivrissimtzis, R. Zayer, H.-P. Seidel, "
    "\\emph{Polygonal decompositions of quadrilateral subdivision meshes}"
)

#: The document preamble (``preamble.tex``, shipped with the package): packages of a basic
#: TeX Live only (latex-base and latex-recommended).
PREAMBLE = resources.files("symdecomp.output").joinpath("preamble.tex").read_text(encoding="utf-8")

# --------------------------------------------------------------------------------------
# Text


_TEXT_ESCAPES = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "&": r"\&", "%": r"\%", "#": r"\#", "$": r"\$",
    "_": r"\_\allowbreak{}",  # long identifiers may break after an underscore
    "^": r"\textasciicircum{}", "~": r"\textasciitilde{}", "<": r"\textless{}", ">": r"\textgreater{}",
    "|": r"\textbar{}",
}

#: The characters beyond ASCII that the preamble declares (``\DeclareUnicodeCharacter``).
_DECLARED = {chr(int(code, 16)) for code in re.findall(r"\\DeclareUnicodeCharacter\{([0-9A-F]+)\}", PREAMBLE)}

#: Inline formulas longer than this (characters, see :func:`~symdecomp.output.texlayout.size`)
#: are displayed instead: TeX does not break them well within a paragraph.
_INLINE_LIMIT = 30


def _unicode(ch: str) -> str:
    """A character as the document can set it: ASCII, Latin letters (inputenc), the declared
    ones (see the preamble), any other as its code point."""
    if ord(ch) < 128 or ch in _DECLARED or ch.isalpha() and ord(ch) < 0x250:
        return ch
    return r"\texttt{[U+%04X]}" % ord(ch)


def _escape_word(word: str) -> str:
    out = "".join(_TEXT_ESCAPES.get(ch) or _unicode(ch) for ch in word)
    if len(word) > 16:
        # a long "word" such as [[1,2],[3,4]] or n=3..16 may break after its punctuation
        out = re.sub(r"([,;/=\])]|\.\.)(?=.)", r"\1\\allowbreak{}", out)
    return out


def _escape_text(text: str) -> str:
    out = "".join(_escape_word(word) for word in re.split(r"(\s+)", text))
    # "Eq. 5" is not the end of a sentence: a normal, unbreakable space
    return re.sub(r"\b(Eqs?|Props?|Figs?|Secs?|cf|e\.g|i\.e|resp|vs)\. (?=\S)", r"\1.~", out)


def _clean_math(tex: str) -> str:
    """Inline math written by a claim's author, made safe: no comments or unknown Unicode."""
    # & separates cells inside an environment (pmatrix, cases...); elsewhere it is a character
    specials = "%#" if "\\begin" in tex else "%#&"
    out = []
    for i, ch in enumerate(tex):
        escaped = i > 0 and tex[i - 1] == "\\"
        if ch in specials and not escaped:
            out.append("\\" + ch)
        elif _unicode(ch) != ch:
            out.append(r"\text{%s}" % _unicode(ch))
        elif ch == "\n":
            out.append(" ")
        else:
            out.append(ch)
    return "".join(out)


def _displayed(math: str) -> str:
    """Author-written math, displayed (TeX breaks it at its relations and operators)."""
    return "\n\\begin{dmath*}\n%s\n\\end{dmath*}\n" % math.strip()


def _inline(obj, displays: bool) -> str:
    """A computed object inside prose: inline math, or a display when it is long."""
    if displays and size(obj) > _INLINE_LIMIT:
        return "\n" + display_math(obj)
    return "$%s$" % _clean_math(latex(obj))


def findings_latex(text, *, displays: bool = True) -> str:
    """A finding (:class:`~symdecomp.claims.Text` or ``str``) as LaTeX: words as text, objects as math."""
    if not isinstance(text, Text):
        return text_latex(text, displays=displays)
    out = []
    for part in text.parts:
        if isinstance(part, str):
            out.append(text_latex(part, displays=displays))
        else:
            out.append(_inline(part, displays))
    return "".join(out)


def text_latex(text: str, *, displays: bool = True) -> str:
    """Prose as LaTeX: special characters escaped, inline math between ``$`` kept.

    An inline formula too wide to sit in a line of text becomes a displayed one (unless
    ``displays`` is false, e.g. in a table cell). An unmatched ``$`` is a dollar sign.
    Text from outside the package (:class:`~symdecomp.claims.Verbatim`: a scheme's name, an
    error message) is shown exactly as given: every character escaped, no formulas.

    >>> print(text_latex("50% of a & b: $\\\\omega_n^j$"))
    50\\% of a \\& b: $\\omega_n^j$
    >>> print(text_latex("costs $5"))
    costs \\$5
    >>> print(text_latex(Verbatim("c $\\\\input{x}$")))
    c \\$\\textbackslash{}input\\{x\\}\\$
    """
    if isinstance(text, Verbatim):
        return _escape_text(text)
    if "$$" in text:  # displayed math written as $$...$$
        chunks = re.split(r"(?<!\\)\$\$(.*?)(?<!\\)\$\$", text, flags=re.S)
        if len(chunks) > 1:
            return "".join(
                text_latex(chunk, displays=displays) if k % 2 == 0
                else (_displayed(_clean_math(chunk)) if displays else "$%s$" % _clean_math(chunk))
                for k, chunk in enumerate(chunks)
            )
    parts = re.split(r"(?<!\\)\$", text)
    if len(parts) % 2 == 0:  # an odd number of $: the last one is a dollar sign
        parts[-2:] = [parts[-2] + "$" + parts[-1]]
    out = []
    for k, part in enumerate(parts):
        if k % 2 == 0:
            out.append(_escape_text(part.replace("\\$", "$")))
            continue
        math = _clean_math(part)
        if not math.strip():
            continue
        if displays and size(math) > _INLINE_LIMIT:
            out.append(_displayed(math))
        else:
            out.append("$" + math + "$")
    return "".join(out)


# --------------------------------------------------------------------------------------
# Displayed formulas

def display_math(expr, lhs=None, *, rel: str = "=") -> str:
    """``expr`` (or ``lhs = expr``) as a displayed formula that fits in the text width.

    TeX breaks the formula between the terms of its sums (``dmath*``); the long parts it
    cannot break are named and defined below it; a wide matrix has its long entries named,
    or is shown in blocks of columns; a mapping becomes a group of equations.

    >>> from sympy.abc import x
    >>> print(display_math(x**2, lhs="f(x)"), end="")
    \\begin{dmath*}
    f(x) = x^{2}
    \\end{dmath*}
    """
    if isinstance(expr, Mapping):
        return rows_display(*mapping_rows(expr))
    if isinstance(expr, str):
        return text_latex(expr) + "\n"
    return formula_display(lhs, rel, expr)


# --------------------------------------------------------------------------------------
# aslatex


@functools.singledispatch
def aslatex(obj) -> str:
    """LaTeX for ``obj``: the one entry point used by the documents, notebooks and CLI.

    >>> import sympy as sp
    >>> aslatex(sp.Rational(3, 8) + sp.Symbol("alpha"))
    '\\\\alpha + \\\\frac{3}{8}'
    >>> print(aslatex({sp.Symbol("x"): 1, sp.Symbol("y"): sp.sqrt(2)}))
    \\begin{aligned}
    x &= 1 \\\\
    y &= \\sqrt{2}
    \\end{aligned}
    """
    raise InvalidTypeError(f"aslatex cannot render a {type(obj).__name__}")


@aslatex.register(sp.Basic)
@aslatex.register(sp.MatrixBase)
@aslatex.register(int)
@aslatex.register(float)
@aslatex.register(complex)
@aslatex.register(tuple)
@aslatex.register(list)
@aslatex.register(set)
@aslatex.register(frozenset)
def _(obj) -> str:
    return latex(obj)


@aslatex.register(Fraction)
def _(obj: Fraction) -> str:
    return latex(to_sympy(obj))


@aslatex.register(str)
def _(obj: str) -> str:
    return text_latex(obj)


@aslatex.register(Mapping)
def _(obj: Mapping) -> str:
    items, rel = mapping_rows(obj)
    rows = [(k if isinstance(k, str) else aslatex(k)) + " &" + rel + " " + aslatex(v) for k, v in items]
    return "\\begin{aligned}\n" + " \\\\\n".join(rows) + "\n\\end{aligned}"


@aslatex.register(Status)
def _(obj: Status) -> str:
    if " " in obj.value:  # the preamble's \status[colour]{text} would name the colour "sd<colour><text>"
        return r"\textcolor{sd%s}{\textbf{%s}}" % (obj.value.replace(" ", ""), obj.value)
    return r"\status{%s}" % obj.value


@aslatex.register(Step)
def _(obj: Step) -> str:
    out = text_latex(obj.text).strip() + "\n" if obj.text else ""
    if obj.expr is not None:
        try:
            out += display_math(obj.expr, obj.lhs)
        except Exception as exc:  # sympy's printer has gaps; say so in the document, visibly
            message = f"sympy could not print this {type(obj.expr).__name__}: {type(exc).__name__}: {exc}"
            out += "\\finding{sderror}{Not printed}{%s}\n" % text_latex(message, displays=False)
    return out


def _scope(result: CheckResult) -> str:
    """What the status rests on: the valences, the digits."""
    if result.valences is not None:
        lo, hi = result.valences
        # verified: exact arithmetic or certified intervals (the evidence says which), per valence
        p = result.parameter
        return f" (for each ${p} = {lo}, \\dots, {hi}$)" if hi > lo else f" (for ${p} = {lo}$)"
    if result.digits is not None:
        return f" (to {result.digits} significant digits)"
    return ""


@aslatex.register(CheckResult)
def _(obj: CheckResult) -> str:
    evidence = findings_latex(obj.evidence).strip()
    if obj.status in (Status.REFUTED, Status.CORRECTED, Status.ERROR):
        heading = {
            Status.REFUTED: "Refuted: the claim is false as printed.",
            Status.CORRECTED: "Corrected: the claim is false as printed; the corrected statement is proved.",
            Status.ERROR: "Error: the check failed to run (this says nothing about the paper).",
        }[obj.status]
        body = [evidence + _scope(obj)]
        if obj.counterexample:
            body.append(r"\textbf{Counterexample.} " + findings_latex(obj.counterexample).strip())
        if obj.correction:
            body.append(r"\textbf{Corrected statement.} " + findings_latex(obj.correction).strip())
        out = "\\finding{sd%s}{%s}{%%\n%s}\n" % (obj.status.value, heading, "\\par\n".join(body))
    else:
        out = "\\textbf{Status:} %s. %s%s\n" % (aslatex(obj.status), evidence, _scope(obj))
    if obj.steps:
        out += "\n\\textbf{Derivation.}\\par\\nopagebreak\n" + "\n".join(aslatex(step) for step in obj.steps)
    return out


def _one_line(text: str) -> str:
    """Text for a heading or a table cell: one line, no displayed formulas."""
    return text_latex(" ".join(text.split()), displays=False)


def _anchor(label: str) -> str:
    return "claim:" + re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-")


def _label_text(label: str) -> str:
    """``Eq. 43`` -> ``Eq.~43``: a label never breaks before its number."""
    return re.sub(r" (?=\d)", "~", _one_line(label))


def _anchors(claims: Sequence[Claim]) -> dict[str, str]:
    """A distinct cross-reference target for each claim (``Eq. 43`` -> ``claim:eq-43``)."""
    anchors: dict[str, str] = {}
    taken: set[str] = set()
    for c in claims:
        anchor, k = _anchor(c.label), 1
        while anchor in taken:
            k += 1
            anchor = f"{_anchor(c.label)}-{k}"
        anchors[c.label] = anchor
        taken.add(anchor)
    return anchors


def claim_latex(claim: Claim, result: CheckResult, anchor: str | None = None) -> str:
    """The entry of one claim: heading, statement as printed, status, derivation."""
    return (
        "\\claimheading{%s}{%s}{%s}\n" % (anchor or _anchor(claim.label), _label_text(claim.label), _one_line(claim.title))
        + "\\textit{Statement, as printed.} %s\n\n" % text_latex(claim.statement).strip()
        + aslatex(result)
    )


@aslatex.register(Claim)
def _(obj: Claim) -> str:
    return claim_latex(obj, check_claim(obj.label))


# --------------------------------------------------------------------------------------
# The document


def section_file_name(section: str) -> str:
    """The file holding a section's derivations: ``"5.1"`` -> ``"section-5-1.tex"``, the toolkit's own ``"B.1"`` -> ``"beyond-1.tex"``."""
    if _beyond(section):
        return "beyond-" + section.partition(".")[2].replace(".", "-") + ".tex"
    return "section-" + section.replace(".", "-") + ".tex"


def _beyond(section: str) -> bool:
    return section_key(section)[0] == 1  # the toolkit's own claims (``BEYOND``), after the paper's


def _heading(section: str) -> str:
    """``\\section``/``\\subsection`` numbered as in the paper; a section of the toolkit's own claims is unnumbered."""
    if _beyond(section):
        title = _one_line(SECTION_TITLES.get(section, f"Beyond the paper {section}"))  # unnumbered, in the contents
        return f"\\section*{{{title}}}\n\\addcontentsline{{toc}}{{section}}{{{title}}}\n"
    parts = section.split(".")
    depth = min(len(parts), 3)
    command = ("section", "subsection", "subsubsection")[depth - 1]
    number = parts[min(len(parts), 3) - 1]
    title = _one_line(SECTION_TITLES.get(section, f"Section {section}"))
    counter = f"\\setcounter{{{command}}}{{{int(number) - 1}}}\n" if number.isdigit() else ""
    return f"{counter}\\{command}{{{title}}}\n"


def _summary(pairs: Sequence[tuple[Claim, CheckResult]], anchors: Mapping[str, str]) -> str:
    counts: dict[str, int] = {}
    for _, result in pairs:
        counts[result.status.value] = counts.get(result.status.value, 0) + 1
    tally = ", ".join(f"{counts[s.value]} {aslatex(s)}" for s in Status if s.value in counts)
    rows = []
    for claim, result in pairs:
        anchor = anchors[claim.label]
        rows.append(
            f"{_one_line(claim.section)} & \\hyperref[{anchor}]{{{_label_text(claim.label)}}} & "
            f"{_one_line(claim.title)} & {aslatex(result.status)} & \\pageref{{{anchor}}} \\\\"
        )
    table = (
        "\\begin{longtable}{@{}>{\\raggedright\\arraybackslash}p{0.07\\linewidth}"
        ">{\\raggedright\\arraybackslash}p{0.17\\linewidth}"
        ">{\\raggedright\\arraybackslash}p{0.47\\linewidth}"
        ">{\\raggedright\\arraybackslash}p{0.13\\linewidth}r@{}}\n"
        "\\toprule\nSec. & Claim & Title & Status & Page \\\\\n\\midrule\n\\endhead\n"
        "\\bottomrule\n\\endfoot\n" + "\n".join(rows) + ("\n" if rows else "") + "\\end{longtable}\n"
    )
    return (
        "\\section*{Summary of the claims}\n"
        f"{len(pairs)} claims: {tally or 'none registered'}.\n"
        "A claim is \\status{proved} when shown symbolically for every valence $n$, "
        "\\status{verified} when shown in exact arithmetic for a stated range of $n$, "
        "\\status{numeric} when it agrees to a stated number of digits; "
        "\\status{refuted} and \\status{corrected} are findings about the paper as printed; "
        "\\status{error} means that the check itself failed to run.\n"
        + _scope_sentence(scope_summary(result for _, result in pairs))
        + "\n\n" + table
    )


def _scope_sentence(summary) -> str:
    """How many verdicts hold for every n (proved, or an erratum established for every n), a range, a single case."""
    return (
        f"Verdicts established for every $n$: {summary.every_n} of {summary.total} ({summary.proved} \\status{{proved}}, "
        f"{summary.errata_every_n} \\status{{corrected}} or \\status{{refuted}} with the corrected statement proved for "
        f"every $n$ and an exact counterexample); for a range of $n$ only: {summary.range_of_n}; in a single case: "
        f"{summary.single_case}; no verdict: {summary.no_verdict}. A statement about $n = 4$ alone is proved by the exact "
        "computation at $n = 4$."
    )


def wrap_source(tex: str, width: int = 100) -> str:
    """Break long source lines at spaces (not after a backslash), keeping the typeset result.

    TeX reads a newline as a space, and spaces in math are ignored, so this changes nothing
    on the page; it keeps diffs of the committed files readable and every line far below
    TeX's input buffer. Lines with a comment are left alone.

    >>> wrap_source("a + b + c + d", width=6)
    'a + b\\n+ c +\\nd'
    """
    out = []
    for line in tex.split("\n"):
        if re.search(r"(?<!\\)%", line):
            out.append(line)
            continue
        while len(line) > width:
            cut = next((i for i in range(width, 0, -1) if line[i] == " " and line[i - 1] not in " \\"), None)
            if cut is None:
                cut = next((i for i in range(width + 1, len(line)) if line[i] == " " and line[i - 1] not in " \\"), None)
            if cut is None:
                break
            out.append(line[:cut])
            line = line[cut + 1:]
        out.append(line)
    return "\n".join(out)


GENERATED = "% Generated by `symdecomp derive` from the claims registry. Do not edit: regenerate.\n"


def derivation_files(pairs: Sequence[tuple[Claim, CheckResult]], appendices: Sequence[str] = ()) -> dict[str, str]:
    """The document: ``{file name: contents}``, ``main.tex`` and one file per section (``appendices``: files input after them).

    ``pairs`` are the claims with the results of their checks, in any order (they are
    sorted in the paper's order). The result depends on nothing else.
    """
    pairs = sorted(pairs, key=lambda pair: pair[0].sort_key())
    anchors = _anchors([c for c, _ in pairs])
    sections: dict[str, list[tuple[Claim, CheckResult]]] = {}
    for claim, result in pairs:
        sections.setdefault(claim.section, []).append((claim, result))
    files: dict[str, str] = {}
    inputs = []
    introduced: set[str] = set()
    for section in sorted(sections, key=section_key):
        parts = [] if _beyond(section) else section.split(".")
        for depth in range(1, len(parts)):
            parent = ".".join(parts[:depth])
            if parent not in introduced and parent not in sections:
                inputs.append(_heading(parent))
            introduced.add(parent)
        introduced.add(section)
        name = section_file_name(section)
        body = "\n".join(claim_latex(c, r, anchors[c.label]) for c, r in sections[section])
        files[name] = GENERATED + _heading(section) + "\n" + wrap_source(body)
        inputs.append("\\input{%s}\n" % name[: -len(".tex")])
    files["main.tex"] = (
        GENERATED
        + PREAMBLE
        + "\n\\title{Derivations and checks of the claims of\\\\[0.3em] \\emph{Polygonal decompositions of "
        "quadrilateral subdivision meshes}}\n"
        "\\author{Generated by symdecomp}\n\\date{}\n\n\\begin{document}\n\\maketitle\n\n"
        "This appendix lists the claims of " + PAPER + ", section by section with the paper's "
        "numbering, each with its statement as printed, the outcome of its check, and the "
        "derivation computed by symdecomp (every formula is printed by sympy from the computed "
        "objects). Claims the check found false as printed are marked in colour.\n\n"
        + ("After the paper's sections come the toolkit's own claims (\\emph{Beyond the paper}): statements from the literature "
           "the paper builds on, each citing its source, checked in the same way.\n\n" if any(map(_beyond, sections)) else "")
        + _summary(pairs, anchors)
        + "\n"
        + "".join(inputs) + "".join("\\input{%s}\n" % name.removesuffix(".tex") for name in appendices)
        + "\n\\end{document}\n"
    )
    return dict(sorted(files.items()))
