"""Results in a notebook: short HTML tables (:func:`ashtml`) and typeset LaTeX (:func:`notebook_latex`).

Jupyter calls ``_repr_html_`` and ``_repr_latex_`` of the results users meet first
(:class:`~symdecomp.analysis.display.NotebookDisplay`), which come here. The LaTeX of every
expression comes from the one entry point :func:`~symdecomp.output.latex.aslatex`; this module
registers it for those results (a table as a math ``array``: the numbers and exact values as
mathematics, the words as ``\\text``), and re-exports it, so that ``symdecomp.aslatex`` knows them.

>>> from symdecomp.analysis.masks import limit_masks_at
>>> from symdecomp.schemes.scheme import catmull_clark
>>> print(aslatex(limit_masks_at(catmull_clark(), 4)))
\\begin{array}{ll}
\\text{valence } n & 4 \\\\
\\lambda_1 & \\frac{1}{2} \\\\
w_O & \\frac{4}{9} \\\\
w_a & \\frac{1}{9} \\\\
w_b & \\frac{1}{36}
\\end{array}
"""

from __future__ import annotations

import functools
import html
import re
from collections.abc import Sequence
from typing import Any

from symdecomp.analysis.inspection import MeshInspection
from symdecomp.analysis.masks import MasksAtValence
from symdecomp.analysis.spectrum import Spectrum
from symdecomp.claims.registry import CheckResult
from symdecomp.errors import InvalidTypeError
from symdecomp.output.latex import aslatex
from symdecomp.verify.artifacts import ArtifactIndicators
from symdecomp.verify.c1 import C1Result

__all__ = ["aslatex", "ashtml", "notebook_latex", "ROWS_SHOWN"]

#: Rows a table shows at most; the rest is counted in its last row.
ROWS_SHOWN = 12

#: Characters kept in ``\\text{...}`` (the rest becomes a space): safe in LaTeX and in MathJax alike.
_TEXT = re.compile(r"[^A-Za-z0-9 ,.;:()=<>+\-/'|]")


def _html_table(caption: str, header: tuple[str, ...], rows: list[tuple]) -> str:
    """A small HTML table: the caption, the header, at most :data:`ROWS_SHOWN` rows (the rest counted)."""
    more = len(rows) - ROWS_SHOWN
    rows = rows[:ROWS_SHOWN] + ([(f"... {more} more",) + ("",) * (len(header) - 1)] if more > 0 else [])
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><caption>{html.escape(caption)}</caption><tr>{head}</tr>{body}</table>"


def _text(words) -> str:
    """Words as ``\\text{...}``, without the characters LaTeX or MathJax would read as commands."""
    return r"\text{%s}" % _TEXT.sub(" ", str(words))


def _mixed(text: str) -> str:
    """A claim's text with ``$...$`` mathematics: the words as :func:`_text`, the mathematics as it is.

    >>> print(_mixed("the trace $\\\\operatorname{tr}(M_j)$, exact"))
    \\text{the trace }\\operatorname{tr}(M_j)\\text{, exact}
    """
    parts = str(text).split("$")
    return "".join(part if i % 2 else (_text(part) if part else "") for i, part in enumerate(parts))


def _array(rows: Sequence[tuple[str, ...]]) -> str:
    """A LaTeX ``array`` of cells already in LaTeX, left aligned."""
    width = max(len(r) for r in rows)
    return "\\begin{array}{%s}\n" % ("l" * width) + " \\\\\n".join(" & ".join(r) for r in rows) + "\n\\end{array}"


@functools.singledispatch
def ashtml(obj) -> str:
    """A short HTML table of a result, for Jupyter (``_repr_html_``)."""
    raise InvalidTypeError(f"ashtml cannot render a {type(obj).__name__}")


def notebook_latex(obj) -> str:
    """``obj``'s LaTeX for Jupyter (``_repr_latex_``): :func:`aslatex` in display math; a claim's check as its status
    and the derivation's formulas (its document LaTeX, :func:`aslatex`, needs the report's preamble)."""
    if isinstance(obj, CheckResult):
        rows = [(_text("status"), _text(obj.status.value))]
        rows += [(_mixed(step.text) if step.text else "", aslatex(step.expr)) for step in obj.steps if step.expr is not None]
        return "$$" + _array(rows[:ROWS_SHOWN]) + "$$"
    return "$$" + aslatex(obj) + "$$"


# ----------------------------------------------------------------------------------------------
# the spectrum and the masks (exact where the result is)


@ashtml.register(Spectrum)
def _(obj: Spectrum) -> str:
    rows = [(e.text, e.multiplicity, ", ".join(map(str, e.frequencies))) for e in obj.eigenvalues]
    caption = f"{obj.scheme}, valence n = {obj.n}: {2 * obj.n + 1} eigenvalues, {len(obj.eigenvalues)} distinct"
    return _html_table(caption, ("value", "mult", "frequencies k"), rows)


@aslatex.register(Spectrum)
def _(obj: Spectrum) -> str:
    rows = [(_text("value"), _text("mult"), _text("frequencies k"))]
    rows += [(e.text, str(e.multiplicity), ", ".join(map(str, e.frequencies))) for e in obj.eigenvalues[:ROWS_SHOWN]]
    return _array(rows)


def _mask_rows(obj: MasksAtValence) -> list[tuple[str, Any]]:
    """``lambda_1`` and the position mask's weight on ``O``, on each ``a_i`` and (quads) on each ``b_i``, exact."""
    w = obj.position
    rows = [("lambda_1", obj.subdominant), ("w_O", w[0]), ("w_a", w[1])]
    return rows + ([("w_b", w[1 + obj.n])] if len(w) > 1 + obj.n else [])


@ashtml.register(MasksAtValence)
def _(obj: MasksAtValence) -> str:
    rows = [(name, str(value), f"{float(value):.12g}") for name, value in _mask_rows(obj)]
    return _html_table(f"limit masks at valence n = {obj.n} (the position mask: w_O on O, w_a on each a_i, w_b on each "
                       "b_i)", ("", "exact", "value"), rows)


@aslatex.register(MasksAtValence)
def _(obj: MasksAtValence) -> str:
    names = {"lambda_1": r"\lambda_1", "w_O": "w_O", "w_a": "w_a", "w_b": "w_b"}
    return _array([(_text("valence ") + " n", str(obj.n))] + [(names[k], aslatex(v)) for k, v in _mask_rows(obj)])


# ----------------------------------------------------------------------------------------------
# verdicts: C1, the curvature regime and artifacts, a claim, a mesh


def _c1_rows(obj: C1Result) -> list[tuple[str, object]]:
    data = obj.as_json()
    return [("verdict", data["verdict"]), ("lambda_1", data["lambda"]), ("spectral gap >=", data["gap"]),
            ("|J| >= (certified)", data["jacobian_lower_bound"]), ("winding number", data["winding_number"]),
            ("method", data["method"])]


@ashtml.register(C1Result)
def _(obj: C1Result) -> str:
    return _html_table(f"{obj.scheme}, n = {obj.n}: {obj.reason}", ("", ""), _c1_rows(obj))


@aslatex.register(C1Result)
def _(obj: C1Result) -> str:
    names = {"lambda_1": r"\lambda_1", "|J| >= (certified)": r"|J| \geq"}
    return _array([(names.get(k) or _text(k), _text(v) if isinstance(v, str) or v is None else aslatex(v))
                   for k, v in _c1_rows(obj)[:5]])


def _artifact_rows(obj: ArtifactIndicators) -> list[tuple[str, object]]:
    data = obj.as_json()
    c = data["curvature"]
    mu = ", ".join(f"{m['value']} (k = {m['frequency']})" for m in c.get("mu", ()))
    return [("regime", c["regime"]), ("lambda_1", c.get("lambda1")), ("lambda_1^2", c.get("lambda1_squared")), ("mu", mu),
            ("density", data["density"]), ("negative weights", data["negative_weights"]),
            ("ring spacing", data["ring_spacing_ratio"]), ("shape", data["shape"]["text"])]


@ashtml.register(ArtifactIndicators)
def _(obj: ArtifactIndicators) -> str:
    return _html_table(f"n = {obj.n}: {obj.curvature.reason}", ("", ""), _artifact_rows(obj))


@aslatex.register(ArtifactIndicators)
def _(obj: ArtifactIndicators) -> str:
    names = {"lambda_1": r"\lambda_1", "lambda_1^2": r"\lambda_1^2", "mu": r"\mu"}
    return _array([(_text("valence ") + " n", str(obj.n))]
                  + [(names.get(k) or _text(k), _text(v)) for k, v in _artifact_rows(obj)])


@ashtml.register(CheckResult)
def _(obj: CheckResult) -> str:
    rows = [("status", obj.status.value), ("scope", obj.scope_text or "-"), ("evidence", str(obj.evidence))]
    rows += [(name, str(value)) for name in ("counterexample", "correction") if (value := getattr(obj, name))]
    return _html_table(f"{obj.status.value}: {len(obj.steps)} steps of derivation", ("", ""), rows)


@ashtml.register(MeshInspection)
def _(obj: MeshInspection) -> str:
    rows = [(v.vertex, v.valence, ", ".join(f"{x:.6g}" for x in v.limit),
             "-" if v.normal is None else ", ".join(f"{x:.4f}" for x in v.normal)) for v in obj.vertices]
    caption = f"{obj.scheme}: {len(obj.vertices)} extraordinary vertices"
    return _html_table(caption, ("vertex", "valence", "limit position", "normal"), rows)


@aslatex.register(MeshInspection)
def _(obj: MeshInspection) -> str:
    rows = [(_text("vertex"), "n", _text("limit position"))]
    rows += [(str(v.vertex), str(v.valence), aslatex(tuple(v.limit_exact))) for v in obj.vertices[:ROWS_SHOWN]]
    return _array(rows)
