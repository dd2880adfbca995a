"""The report's section on every valence: C1 and the curvature regime for every n, as ``symdecomp c1 --every-n`` and
``symdecomp artifacts --every-n`` prove them.

The same propositions as the derivations' ``c1-every-n.tex`` (:mod:`symdecomp.output.every_n_derivations`), kept
short: each proposition as its proof's outcome allows it, and the proof's named steps with their status and the valences
they cover (the formulas are in the derivations and in ``--json``).
"""

from __future__ import annotations

from symdecomp.claims import Verbatim
from symdecomp.errors import SymdecompError
from symdecomp.output.every_n_derivations import c1_statement, every_n_proofs, regime_statement, step_where
from symdecomp.output.report import Paragraph, ReportInput, Section, Table
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.verify.c1_every_n import EveryNStep

__all__ = ["TITLE", "DUAL_TITLE", "CERTIFIED", "every_n_section", "dual_every_n_section"]

#: The section's title.
TITLE = "Every valence: C1 and the curvature regime"

#: The title of a dual scheme's section (a zoo report: Doo-Sabin and its variants files).
DUAL_TITLE = "Every valence: C1"

#: The valences Reif's test certifies one by one in a report (the C1 claim's table; the derivations and the command go
#: to 64): a report stays quick, and where the map's proof starts at n = 3 the range changes nothing but that step.
CERTIFIED = 16


def _rows(steps: tuple[EveryNStep, ...]) -> tuple[tuple, ...]:
    """A step per row: its name (a regime step has none: what it covers), status and valences."""
    return tuple((Verbatim(s.name or ("per valence" if s.status == "verified" else "every n")), s.status, step_where(s))
                 for s in steps)


def every_n_section(inp: ReportInput) -> Section:
    """C1 and the curvature regime for every valence of the report's scheme, or why they are not shown."""
    try:
        result, regime = every_n_proofs(inp.scheme, CERTIFIED)
    except SymdecompError as exc:  # a scheme the proofs do not apply to: the section says why, as the commands do
        return Section(TITLE, (Paragraph(("Not applicable: ", Verbatim(str(exc)))),))
    blocks: list = [
        Paragraph(("C1 for every $n$. ", c1_statement(result))),
        Table(("step", "status", "valences"), _rows(result.steps), (0.3, 0.2, 0.5)),
    ]
    if isinstance(regime, str):
        blocks.append(Paragraph(("The curvature regime for every $n$: not applicable: ", Verbatim(regime))))
    else:
        blocks += [Paragraph(("The curvature regime for every $n$. ", regime_statement(regime))),
                   Table(("step", "status", "valences"), _rows(regime.steps), (0.3, 0.2, 0.5))]
    return Section(TITLE, tuple(blocks))


def dual_every_n_section(scheme: StencilScheme, valences: tuple[int, ...] = ()) -> Section:
    """C1 for every valence of a dual scheme of the zoo (:mod:`symdecomp.output.dual_every_n_derivations`: the dual test at
    ``3..CERTIFIED``), or why it is not shown (a section of :data:`~symdecomp.output.report_zoo.ZOO_SECTIONS`; the report's
    own valences do not change it)."""
    from symdecomp.output.dual_every_n_derivations import dual_every_n_proof
    from symdecomp.verify.c1_dual_every_n import ngon_spectrum

    try:
        ngon_spectrum(scheme)  # asked first: a scheme it does not apply to is refused at once, with no valence certified
        result = dual_every_n_proof(scheme, CERTIFIED)
    except SymdecompError as exc:
        return Section(DUAL_TITLE, (Paragraph(("Not applicable: ", Verbatim(str(exc)))),))
    return Section(DUAL_TITLE, (
        Paragraph(("C1 for every $n$. ", c1_statement(result, "face"),
                   f" Reif's test is certified one by one at $n = 3, \\dots, {CERTIFIED}$.")),
        Table(("step", "status", "valences"), _rows(result.steps), (0.3, 0.2, 0.5)),
    ))
