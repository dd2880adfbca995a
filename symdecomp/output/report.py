"""Everything about one scheme in one document: the report of ``symdecomp report``.

A report is an ordered list of sections (:data:`SECTIONS`), each built by one function from the
same library calls as the commands that print the same things: the claims (``claims --scheme``,
:func:`~symdecomp.claims.check_claim`), the spectrum (``spectrum``:
:func:`~symdecomp.analysis.spectrum.closed_form_spectrum` on the paper's quad 1-ring,
:func:`~symdecomp.analysis.spectrum.ring_spectrum` otherwise), the limit and tangent masks
(``masks``), the C1 table (``c1``, :func:`~symdecomp.verify.c1.c1_test`) and the figures of
:mod:`symdecomp.output.plotting` (the characteristic map; the eigen-polygons: the rows of the
Fourier matrix, into which every ring decomposes, and, where the paper's closed forms apply, the
1-ring spanned by the subdominant eigenvector, Fig. 6), the curvature regime and artifact indicators
(``artifacts``, :func:`~symdecomp.verify.artifacts.artifact_indicators`, with the columns of
:mod:`symdecomp.output.artifact_table`) and the elliptic height field (:mod:`symdecomp.output.plotting.shape`).
A new section (boundary results) is one more function in :data:`SECTIONS`.

A section is data, not markup: paragraphs, formulas, tables and figures (:class:`Paragraph`,
:class:`Formula`, :class:`Table`, :class:`Figure`), whose parts are one of

* ``str``: prose written by the package, with inline math between ``$`` (as the claims write it);
* :class:`~symdecomp.claims.Verbatim`: text from outside (the scheme's name, a message): shown
  exactly as given, every character escaped;
* a sympy object or an int: mathematics, printed by sympy;
* a :class:`~symdecomp.claims.Status`: a claim's status, coloured.

:mod:`symdecomp.output.report_tex` typesets a report as LaTeX (and PDF),
:mod:`symdecomp.output.report_html` as one HTML file. Nothing here depends on the time or the
machine, so the same input gives the same document.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from symdecomp.analysis.masks import limit_masks, limit_masks_at, ring_masks
from symdecomp.analysis.spectrum import closed_form_spectrum, recursion_eigenvalues, ring_spectrum
from symdecomp.analysis.tangent import complex_at, tangent_eigenvalues
from symdecomp.claims import Status, Verbatim, all_claims, check_claim, scope_summary
from symdecomp.claims.applicability import closed_form_obstacle
from symdecomp.claims.guards import DEFAULT_BUDGET
from symdecomp.errors import InvalidInputError, InvalidSchemeError, NotApplicableError, SymdecompError
from symdecomp.output.artifact_table import COLUMNS as ARTIFACT_COLUMNS
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import MAX_REPORT_VALENCE as MAX_VALENCES
from symdecomp.validate import check_valence
from symdecomp.verify.artifacts import artifact_indicators
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_spectrum import spectral_conditions
from symdecomp.verify.result import C1Verdict

__all__ = ["MAX_VALENCES", "FIGURES", "DIGITS", "Paragraph", "Formula", "Table", "Figure", "Section", "Report", "ReportInput",
           "SECTIONS", "build_report", "shape_section", "every_n_section"]


#: The names of the figures a report may hold (a ``.tex`` report writes them next to itself).
FIGURES = ("characteristic-map", "eigen-polygons", "subdominant-ring", "height-field")

#: Significant digits of the numbers in a report's tables.
DIGITS = 10

#: Digits of a mask weight (a row holds n of them).
MASK_DIGITS = 6


@dataclass(frozen=True)
class Paragraph:
    """A paragraph: its parts in order (the module docstring says what a part may be)."""

    parts: tuple


@dataclass(frozen=True)
class Formula:
    """A displayed formula ``lhs = expr`` (both sympy objects)."""

    lhs: object
    expr: object


@dataclass(frozen=True)
class Table:
    """A table: a header of prose and rows of parts; ``widths`` are the columns' shares of the line."""

    header: tuple[str, ...]
    rows: tuple[tuple, ...]
    widths: tuple[float, ...]


@dataclass(frozen=True)
class Figure:
    """A matplotlib figure and its caption (prose parts, as a :class:`Paragraph`'s)."""

    name: str
    caption: tuple
    figure: object


@dataclass(frozen=True)
class Section:
    """One section of the report: a title (prose) and its blocks in order."""

    title: str
    blocks: tuple


@dataclass(frozen=True)
class ReportInput:
    """What a report is about: the scheme, its valences (ascending), the time budget of one claim's check."""

    scheme: Scheme
    valences: tuple[int, ...]
    budget: float = DEFAULT_BUDGET


@dataclass(frozen=True)
class Report:
    """The whole report: the scheme's name (shown verbatim), the valences and the sections."""

    scheme: Verbatim
    valences: tuple[int, ...]
    sections: tuple[Section, ...]
    #: What the report holds, as package prose (``$...$`` math) after "Everything symdecomp computes ... by the analysis
    #: of <the paper>:"; ``None``: the claims, spectrum, masks, C1 and figures of a 1-ring primal scheme's report.
    contents: str | None = None


def _para(*parts) -> Paragraph:
    return Paragraph(tuple(parts))


def _name(inp: ReportInput) -> Verbatim:
    return Verbatim(inp.scheme.name)


def _range(valences) -> str:
    return f"$n = {valences[0]}, \\dots, {valences[-1]}$" if len(valences) > 1 else f"$n = {valences[0]}$"


# --------------------------------------------------------------------------------------
# The sections, in the order of the document


def scheme_section(inp: ReportInput) -> Section:
    """The scheme: its name, its mesh, its parameters, and whether the paper's closed forms apply."""
    scheme = inp.scheme
    obstacle = closed_form_obstacle(scheme)
    blocks = [_para("Scheme ", _name(inp), f" on {scheme.lattice} meshes, valences {_range(inp.valences)}.")]
    if scheme.parameters:
        blocks.append(_para("Free parameters: ", *sum(([p, " "] for p in scheme.parameters), [])))
    blocks.append(_para("The closed forms of the paper (Section 5, in $c = \\cos(k\\pi/n)$) apply to this scheme."
                        if obstacle is None else "The closed forms of the paper (Section 5) do not apply: ",
                        *([] if obstacle is None else [Verbatim(obstacle), "; its values come from the exact frequency blocks."])))
    return Section("The scheme", tuple(blocks))


def claims_section(inp: ReportInput) -> Section:
    """The claims of the paper checked for the scheme (``symdecomp claims --scheme``), one row each."""
    claims = sorted(all_claims(), key=lambda c: c.sort_key())
    results = [check_claim(c.label, inp.scheme, budget=inp.budget) for c in claims]
    counts = {s: sum(r.status is s for r in results) for s in Status}
    tally = [part for s in Status if counts[s] for part in (f"{counts[s]} ", s, ", ")][:-1]
    summary = scope_summary(results)
    rows = tuple((c.section, c.label, c.title, r.status, r.scope_text or "-")
                 for c, r in zip(claims, results))
    return Section("The paper's claims", (
        _para(f"{len(claims)} claims, each checked for this scheme within {inp.budget:g} s: ", *tally, "."),
        _para(f"Verdicts established for every $n$: {summary.every_n} of {summary.total}; for a range of $n$ only: "
              f"{summary.range_of_n}; in a single case: {summary.single_case}; no verdict: {summary.no_verdict}. The "
              "derivations are written by symdecomp derive."),
        Table(("Sec.", "Claim", "Title", "Status", "Scope"), rows, (0.06, 0.2, 0.46, 0.13, 0.15)),
    ))


def _closed_form_blocks(scheme: Scheme) -> list:
    if closed_form_obstacle(scheme) is not None:
        return []
    ev = tangent_eigenvalues(scheme)
    blocks = [_para("Closed forms: the three eigenvalues of the $3 \\times 3$ matrix of Eq. 43 (frequency $k = 0$), in $n$,")]
    blocks += [Formula(sp.Symbol(f"mu_{i + 1}"), e) for i, e in enumerate(recursion_eigenvalues(scheme))]
    blocks.append(_para("and the two eigenvalues of $M_k$ (Eq. 34) at each frequency $k = 1, \\dots, n-1$, in "
                        "$c = \\cos(k\\pi/n)$:"))
    for name, e in (("lambda_k^+", ev.dominant), ("lambda_k^-", ev.subdominant)):
        blocks.append(Formula(sp.Symbol(name), e))
    return blocks


def spectrum_section(inp: ReportInput) -> Section:
    """The spectrum: closed forms where the paper's apply, and each valence's distinct eigenvalues (``spectrum N``)."""
    blocks = _closed_form_blocks(inp.scheme)
    rows = []
    if inp.scheme.lattice.paper_claims:
        for n in inp.valences:
            for e in closed_form_spectrum(inp.scheme, n, digits=DIGITS).eigenvalues:
                rows.append((str(n), e.text, str(e.multiplicity), ", ".join(map(str, e.frequencies))))
        blocks.append(_para("The eigenvalues at each valence, from the closed forms, with their multiplicities and the "
                            f"frequencies $k$ they come from ({DIGITS} significant digits):"))
        blocks.append(Table(("$n$", "eigenvalue", "mult.", "frequencies $k$"), tuple(rows), (0.08, 0.4, 0.1, 0.42)))
        return Section("Spectrum", tuple(blocks))
    for n in inp.valences:
        for e in ring_spectrum(inp.scheme, n, 1, digits=DIGITS).eigenvalues:
            exact = "-" if e.exact is None else e.exact
            rows.append((str(n), e.text, str(e.multiplicity), ", ".join(map(str, e.frequencies)), exact))
    blocks.append(_para("The eigenvalues of the 1-ring matrix at each valence, from its frequency blocks: distinct values, "
                        "multiplicities, frequencies $k$ and exact values where the characteristic polynomials factor "
                        f"into degrees at most 2 ({DIGITS} significant digits):"))
    blocks.append(Table(("$n$", "eigenvalue", "mult.", "frequencies $k$", "exact"), tuple(rows), (0.07, 0.25, 0.08, 0.2, 0.4)))
    return Section("Spectrum", tuple(blocks))


def _masks_at(scheme: Scheme, n: int) -> tuple[dict | None, str]:
    """The masks at ``n`` as ``symdecomp masks N --json`` gives them (``None``: no mask defined), and whether
    ``lambda_1`` is certified the subdominant eigenvalue, in words."""
    try:
        r = spectral_conditions(scheme, n, one_ring=True)
    except SymdecompError as exc:
        certified, why, simple = False, f"not certified: {exc}", True
    else:
        certified = r.status is C1Verdict.C1 and r.subdominant is not None and r.subdominant.frequency == 1
        why, simple = r.reason, r.one_simple
    if not simple:
        return None, why
    if closed_form_obstacle(scheme) is not None or complex_at(scheme, n):
        data = ring_masks(scheme, n, 1, digits=MASK_DIGITS)
    else:
        data = limit_masks_at(scheme, n).as_json(MASK_DIGITS)
    return data, "certified subdominant" if certified else f"not the subdominant eigenvalue: {why}"


def _weights(mask: dict) -> str:
    classes = mask.get("classes") or {"a": mask["a"], "b": mask["b"]}
    return "; ".join(f"({key}): {', '.join(ws)}" for key, ws in classes.items())


def masks_section(inp: ReportInput) -> Section:
    """The limit position and tangent masks of the centre (``symdecomp masks N``): closed forms and each valence's weights."""
    blocks = []
    if closed_form_obstacle(inp.scheme) is None:
        closed = limit_masks(inp.scheme)
        blocks.append(_para("Closed forms (Section 5.1): the position mask's weights $w_O$, $w_a$, $w_b$ on $O$, on each $a_i$, on each $b_i$; "
                            "the two tangent masks' weights $t^1, t^2$ on $a_i$ and $b_i$, with $\\lambda_1$ the subdominant eigenvalue:"))
        names = ("w_O", "w_a", "w_b")
        blocks += [Formula(sp.Symbol(name), w) for name, w in zip(names, closed.position)]
        for k in range(2):
            blocks.append(Formula(sp.Symbol(f"t_a^{k + 1}"), closed.tangent_a[k]))
            blocks.append(Formula(sp.Symbol(f"t_b^{k + 1}"), closed.tangent_b[k]))
        blocks.append(Formula(sp.Symbol("lambda_1"), closed.subdominant))
    rows = []
    for n in inp.valences:
        data, status = _masks_at(inp.scheme, n)
        if data is None:
            rows.append((str(n), "-", "no mask: ", Verbatim(status)))
            continue
        rows.append((str(n), data["subdominant"], Verbatim(status), "position: O " + data["position"]["O"] + "; "
                     + _weights(data["position"])))
        for k, t in enumerate(data["tangents"], 1):
            rows.append(("", "", "", f"tangent {k}: O {t['O']}; " + _weights(t)))
    blocks.append(_para(f"The masks at each valence ({MASK_DIGITS} significant digits; the weights of each class of "
                        "1-ring vertices for the sectors $0, \\dots, n-1$). The position mask sums to 1; the tangent masks "
                        "have weights $\\cos(2\\pi i/n)$ and $\\sin(2\\pi i/n)$ on $a_i$."))
    blocks.append(Table(("$n$", "$\\lambda_1$", "$\\lambda_1$ is", "weights"), tuple(rows), (0.05, 0.13, 0.17, 0.65)))
    return Section("Limit and tangent masks", tuple(blocks))


def c1_section(inp: ReportInput) -> Section:
    """Reif's test for C1 at each valence (``symdecomp c1 --n A:B``)."""
    rows = []
    try:
        c1_test(inp.scheme, inp.valences[0])
    except NotApplicableError as exc:  # not a regular spline the test knows: the section says why, as the command does
        return Section("C1 at the extraordinary vertex", (_para("Not applicable: ", Verbatim(str(exc))),))
    for n in inp.valences:
        r = c1_test(inp.scheme, n)
        lam = r.as_json()["lambda"]
        rows.append((str(n), str(r.verdict), "-" if lam is None else f"{lam:.{DIGITS}g}",
                     "-" if r.winding_number is None else str(r.winding_number), Verbatim(r.reason)))
    return Section("C1 at the extraordinary vertex", (
        _para("Certified in interval arithmetic. ", Verbatim(inp.scheme.lattice.c1_method), "."),
        Table(("$n$", "verdict", "$\\lambda$", "winding", "reason"), tuple(rows), (0.05, 0.1, 0.14, 0.08, 0.63)),
    ))


#: The artifact table's headers in the report (the command's headers, as mathematics where they are symbols).
ARTIFACT_HEADERS = {"n": "$n$", "lambda_1": "$\\lambda_1$", "lambda_1^2": "$\\lambda_1^2$", "mu": "$\\mu$",
                    "negative weights": "negative weights"}
ARTIFACT_WIDTHS = (0.04, 0.085, 0.085, 0.085, 0.05, 0.045, 0.11, 0.11, 0.075, 0.09, 0.085, 0.14)

_ARTIFACT_LEGEND = (
    "Certified in interval arithmetic, as symdecomp artifacts prints it (6 significant digits). $\\mu$: the largest "
    "eigenvalue of the 2-ring matrix after 1 and $\\lambda_1$, with its frequency (0 elliptic, 1 tangent, 2 hyperbolic, "
    "outer: the regular rules) and multiplicity; a ? after it: eigenvalues of that modulus not separated. Regime: the "
    "curvature at the vertex is bounded ($|\\mu| = \\lambda_1^2$, shown exactly), zero (a flat spot, "
    "$|\\mu| < \\lambda_1^2$) or unbounded ($|\\mu| > \\lambda_1^2$). Density: $\\lambda_1$ against the regular "
    "$1/2$ (dense below, sparse above). Negative weights: in the limit and tangent masks. Spacing: the characteristic "
    "map's second ring spacing over the first (1 on the regular mesh). Shape: the certified class of the central surface "
    "for elliptic input, and whether the hyperbolic part dominates on fine rings.")


def _artifact_row(scheme: Scheme, n: int) -> tuple:
    """One valence's cells, the command's (``artifacts --json`` through the same columns); a valence the analysis
    does not reach gets its reason."""
    try:
        row = artifact_indicators(scheme, n).as_json()
    except NotApplicableError as exc:
        return (str(n), "not applicable: ", Verbatim(str(exc)), *[""] * (len(ARTIFACT_COLUMNS) - 3))
    return tuple(c.cell(row) if c.header == "n" else Verbatim(c.cell(row)) for c in ARTIFACT_COLUMNS)


def _height_field_blocks(inp: ReportInput) -> list:
    from symdecomp.output.plotting.shape import height_field_figure

    shown = tuple(sorted({inp.valences[0], inp.valences[-1]}))
    try:
        fig = height_field_figure(inp.scheme, shown, "elliptic", samples=7)
    except SymdecompError as exc:
        return [_para("The height field is not drawn: ", Verbatim(str(exc)))]
    return [Figure("height-field", ("The elliptic second-order height field of ", _name(inp), " (frequency 0, like "
                                    f"$x^2 + y^2$) over the characteristic ring at $n = {', '.join(map(str, shown))}$: "
                                    "colour the height, black the zero line of the Gaussian curvature; each panel's "
                                    "title gives the certified shape class."),
                   _titled(fig, "Elliptic height field"))]


def shape_section(inp: ReportInput) -> Section:
    """The curvature regime and the artifact indicators at each valence (``symdecomp artifacts --n A:B``), one height field."""
    title = "Curvature and shape"
    try:
        artifact_indicators(inp.scheme, inp.valences[0])
    except NotApplicableError as exc:  # free parameters, or regular rules not Catmull-Clark's or Loop's: say why
        return Section(title, (_para("Not applicable: ", Verbatim(str(exc))),))
    rows = tuple(_artifact_row(inp.scheme, n) for n in inp.valences)
    header = tuple(ARTIFACT_HEADERS.get(c.header, c.header) for c in ARTIFACT_COLUMNS)
    return Section(title, (_para(_ARTIFACT_LEGEND), Table(header, rows, ARTIFACT_WIDTHS), *_height_field_blocks(inp)))


def _shown(valences: tuple[int, ...]) -> tuple[int, ...]:
    """At most three valences for a figure: the first, the middle one and the last."""
    return tuple(sorted({valences[0], valences[len(valences) // 2], valences[-1]}))


def _titled(fig, title: str):
    """The figure with its own title, which names no scheme: a name from outside is set by the document, escaped."""
    fig.suptitle(title)
    return fig


def figures_section(inp: ReportInput) -> Section:
    """The characteristic map (Reif's test) and the eigen-polygons."""
    from symdecomp.output.plotting.characteristic import characteristic_map_figure
    from symdecomp.output.plotting.polygons import regular_polygons_figure
    from symdecomp.output.plotting.tangent import invariant_ring_figure

    shown, name = _shown(inp.valences), _name(inp)
    try:
        characteristic = characteristic_map_figure(inp.scheme, shown, samples=5)
    except NotApplicableError as exc:
        blocks = [_para("No characteristic map: ", Verbatim(str(exc)))]
    else:
        blocks = [Figure("characteristic-map", ("The characteristic map of ", name, " at the valences "
                                                f"{', '.join(map(str, shown))}: the ring at level 1, its inner boundary "
                                                "(thick) and the sector boundaries (dashed); each panel gives the verdict."),
                         _titled(characteristic, "Characteristic map"))]
    ends = tuple(sorted({inp.valences[0], inp.valences[-1]}))
    blocks.append(Figure("eigen-polygons", ("The eigen-polygons $v_k$ (the rows of the Fourier matrix $F_n$, Eq. 2-4) "
                                            f"for $n = {', '.join(map(str, ends))}$: every ring of ", name,
                                            " decomposes into them, one frequency $k$ each."),
                         _titled(regular_polygons_figure(ends), "Eigen-polygons of the circulant blocks")))
    if closed_form_obstacle(inp.scheme) is None and not inp.scheme.parameters:
        try:
            fig = invariant_ring_figure(inp.scheme, shown)
        except SymdecompError as exc:
            blocks.append(_para("The subdominant eigen-polygons are not drawn: ", Verbatim(str(exc))))
        else:
            blocks.append(Figure("subdominant-ring", ("The 1-ring spanned by the subdominant eigenvector of ", name,
                                                      " (Eq. 39, Fig. 6): $A^1$ is the regular $n$-gon $v_1$, "
                                                      "$B^1 = r A^1$."), _titled(fig, "Subdominant eigen-polygons")))
    return Section("Figures", tuple(blocks))


def every_n_section(inp: ReportInput) -> Section:
    """C1 and the curvature regime for every valence (:mod:`symdecomp.output.report_every_n`)."""
    from symdecomp.output.report_every_n import every_n_section as build

    return build(inp)


#: The sections of a report, in order: each takes a :class:`ReportInput` and returns a :class:`Section`.
SECTIONS: tuple[Callable[[ReportInput], Section], ...] = (
    scheme_section, claims_section, spectrum_section, masks_section, c1_section, every_n_section, shape_section,
    figures_section,
)


#: The sections that need numbers for a scheme's free parameters (the others work with symbols or say why not).
NEEDS_VALUES = {spectrum_section: "the spectrum", masks_section: "the limit masks"}


def check_values(scheme: Scheme, sections=SECTIONS) -> None:
    """Refuse a scheme with free parameters at once if one of ``sections`` needs their values (not after the claims'
    minutes of work)."""
    needing = [NEEDS_VALUES[s] for s in sections if s in NEEDS_VALUES]
    if scheme.parameters and needing:
        raise InvalidSchemeError(f"scheme {scheme.name!r} has free parameters {[str(p) for p in scheme.parameters]}; "
                                 f"a report needs their values for {' and '.join(needing)}: write them into the scheme file")


def check_valences(valences) -> tuple[int, ...]:
    """``valences`` as an ascending tuple of distinct valences ``3 <= n <= MAX_VALENCES``; else the package's error."""
    if isinstance(valences, (str, bytes)) or not hasattr(valences, "__iter__"):
        raise InvalidInputError(f"valences: expected a list of valences, got {type(valences).__name__}")
    out = tuple(sorted({check_valence(n) for n in valences}))
    if not out:
        raise InvalidInputError("valences: expected at least one valence")
    if out[-1] > MAX_VALENCES:
        raise InvalidInputError(f"valences: a report goes up to n = {MAX_VALENCES}, got {out[-1]}")
    return out


def build_report(scheme: Scheme, valences, *, budget: float = DEFAULT_BUDGET, sections=SECTIONS) -> Report:
    """Compute every section of the report on ``scheme`` at ``valences`` (``budget``: seconds per claim's check)."""
    scheme = check_scheme(scheme)
    valences = check_valences(valences)
    if isinstance(sections, (tuple, list)):  # an iterator (a progress bar) is checked by its caller, before
        check_values(scheme, sections)
    for n in valences:
        scheme.fitting_valence(n, real=True)
    inp = ReportInput(scheme, valences, budget)
    return Report(Verbatim(scheme.name), valences, tuple(build(inp) for build in sections))
