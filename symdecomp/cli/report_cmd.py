"""``symdecomp report SCHEME --n A:B --out report.pdf``: everything about one scheme in one document.

The document (:mod:`symdecomp.output.report`) holds the paper's claims checked for the scheme, its
spectrum with the closed forms, the limit and tangent masks, the C1 table, the curvature regime and
artifact indicators with an elliptic height field, and the figures (the characteristic map, the
eigen-polygons), computed by the same functions as ``claims``, ``spectrum``, ``masks``, ``c1`` and
``artifacts``. The suffix of ``--out`` chooses the format: ``.pdf`` (typeset by pdflatex, which
must be installed: exit status 3 otherwise, as for any missing optional component), ``.html`` (one
self-contained file, MathML and inline SVG) or ``.tex`` (the LaTeX source; its figures are written
next to it as ``<stem>-<figure>.pdf``, the stem's characters other than letters, digits, ``.``, ``_``
and ``-`` written as ``_``). The same command writes the same bytes.
"""

from __future__ import annotations

import argparse
import re
from pathlib import Path

from symdecomp.cli.common import LIMITS, SCHEME_FORMAT, Once, add_budget_option, any_scheme_by_name, is_stencil_scheme, progress, valence_range
from symdecomp.cli.files import check_output_file, write_output_file, write_output_files
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError, UnavailableError

__all__ = ["register", "run", "FORMATS"]

#: The formats of ``--out``, by suffix.
FORMATS = (".pdf", ".html", ".tex")


def register(sub) -> None:
    p = sub.add_parser(
        "report",
        help="one document (PDF, HTML or LaTeX) with everything about a scheme",
        description="Write one deterministic document about SCHEME at the valences --n A:B: the paper's claims checked "
        "for the scheme (as 'claims --scheme'), the spectrum with its closed forms ('spectrum'), the limit "
        "and tangent masks ('masks'), Reif's C1 test ('c1'), the curvature regime and artifact indicators with the "
        "elliptic height field ('artifacts'; 'Not applicable' with the reason for regular "
        "rules other than Catmull-Clark's and Loop's) and the figures of the characteristic map and of the eigen-polygons. "
        "The suffix of --out chooses the format: .pdf (needs pdflatex; exit status 3 without it), .html "
        "(one self-contained file: formulas as MathML, figures as inline SVG) or .tex (LaTeX source; figures written "
        "next to it as STEM-NAME.pdf). Running it twice writes the same bytes. Catmull-Clark at 3:8 takes about half a "
        "minute, most of it the claims' checks. A scheme with free parameters is refused at once (a report needs their "
        "values), and --out is checked first: a FIFO must have its reader running. A scheme of the zoo (doo-sabin, midedge, "
        "sqrt3, modified-butterfly, or a file in their format) gets its spectrum at each valence and its C1 verdicts, through "
        "the zoo's engine (no claims, masks, artifacts or figures: see 'masks', 'check --certify' and 'derive').",
    )
    p.add_argument("scheme", type=any_scheme_by_name, metavar="SCHEME",
                   help=f"a known scheme name (catmull-clark, loop, ..., or a family of the zoo: doo-sabin, ...) or a TOML "
                   f"scheme file {SCHEME_FORMAT}")
    p.add_argument("--n", dest="valences", type=valence_range("report"), action=Once, required=True, metavar="A:B",
                   help=f"valences: an inclusive range A:B or a single N (at most {LIMITS['report'][0]})")
    p.add_argument("--out", action=Once, required=True, metavar="FILE",
                   help="the document to write: FILE.pdf, FILE.html or FILE.tex; checked before any work starts and "
                   "written whole (an interrupted run leaves the old file)")
    add_budget_option(p)
    add_quiet_option(p)
    p.set_defaults(func=run)


def _format(out: str) -> str:
    suffix = Path(out).suffix.lower()
    if suffix not in FORMATS:
        shown = suffix or "no suffix"
        raise InvalidInputError(f"--out {out}: {shown} is not a report format; give a file ending in {', '.join(FORMATS)}")
    return suffix


def _figure_path(out: Path, name: str) -> Path:
    """Where the ``.tex`` report's figure ``name`` goes: next to it, named after it in characters LaTeX reads as they are."""
    return out.with_name(re.sub(r"[^A-Za-z0-9._-]", "_", out.stem) + f"-{name}.pdf")


def run(args: argparse.Namespace) -> int:
    from symdecomp.output.report import FIGURES, SECTIONS, build_report, check_values

    fmt = _format(args.out)
    if is_stencil_scheme(args.scheme):
        return _run_zoo(args, fmt)
    check_values(args.scheme, SECTIONS)  # free parameters: refused now, not after the claims' minutes
    out = check_output_file(args.out)
    _require_matplotlib()
    if fmt == ".pdf":
        from symdecomp.output.report_tex import require_pdflatex

        require_pdflatex()  # before the work: a missing pdflatex is known now, not after a minute
    figure_paths = {name + ".pdf": check_output_file(_figure_path(out, name)) for name in FIGURES} if fmt == ".tex" else {}
    sections = progress(SECTIONS, len(SECTIONS), "report", enabled=not args.quiet)
    report = build_report(args.scheme, args.valences, budget=args.budget, sections=sections)
    if fmt == ".html":
        from symdecomp.output.report_html import report_html

        write_output_file(out, report_html(report))
    else:
        from symdecomp.output.report_tex import compile_pdf, report_latex

        tex, figures = report_latex(report)
        if fmt == ".pdf":
            write_output_file(out, compile_pdf(tex, figures))
        else:
            # the document and its figures all or nothing: a full disk leaves no new figure beside an old document
            write_output_files({**{figure_paths[name]: data for name, data in figures.items()},
                                out: _with_figure_names(tex, out, figures)})
    print(out)
    return 0


def _run_zoo(args: argparse.Namespace, fmt: str) -> int:
    """``report`` for a scheme of the zoo: its spectrum and C1 sections (:mod:`symdecomp.output.report_zoo`), no figures."""
    from symdecomp.output.report_zoo import ZOO_SECTIONS, build_zoo_report

    out = check_output_file(args.out)
    if fmt == ".pdf":
        from symdecomp.output.report_tex import require_pdflatex

        require_pdflatex()
    sections = progress(ZOO_SECTIONS, len(ZOO_SECTIONS), "report", enabled=not args.quiet)
    report = build_zoo_report(args.scheme, args.valences, sections=sections)
    if fmt == ".html":
        from symdecomp.output.report_html import report_html

        write_output_file(out, report_html(report))
    else:
        from symdecomp.output.report_tex import compile_pdf, report_latex

        tex, figures = report_latex(report)
        write_output_file(out, compile_pdf(tex, figures) if fmt == ".pdf" else tex)
    print(out)
    return 0


def _require_matplotlib() -> None:
    """The figures need matplotlib: without it, one line saying how to get it (exit status 3), before the work."""
    from symdecomp.output.plotting._mpl import require_matplotlib

    try:
        require_matplotlib()
    except ImportError:
        raise UnavailableError("the report's figures need matplotlib; install it with  pip install 'symdecomp[report]'") from None


def _with_figure_names(tex: str, out: Path, figures) -> str:
    """The LaTeX with each figure under the name it is written to next to the ``.tex`` file."""
    for name in figures:
        tex = tex.replace("{%s}" % name, "{%s}" % _figure_path(out, name[: -len(".pdf")]).name)
    return tex
