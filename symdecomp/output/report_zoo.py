"""The report of a scheme of the zoo (a StencilScheme): ``symdecomp report doo-sabin --n 3:8 --out r.pdf``.

The sections are data (:mod:`symdecomp.output.report`'s :class:`~symdecomp.output.report.Section`), typeset by the
same :mod:`symdecomp.output.report_tex` and :mod:`symdecomp.output.report_html` as any report: the scheme (its
lattice, topology, steps and source), its spectrum at each valence through the zoo's engine
(:func:`symdecomp.analysis.zoo_spectrum.zoo_spectrum`, as ``spectrum N --scheme``), and its C1 verdicts
(:func:`symdecomp.verify.c1_zoo.c1_zoo` with the engine's neighbourhood, as ``c1 --scheme``: Reif's test on the
biquadratic patches of a dual scheme, Zorin's test on the characteristic net of a triangle scheme without a spline
patch (the modified butterfly, about a minute per valence; sqrt(3) over its two steps, seconds), or undecided with the
reason). The paper's claims,
the masks' closed forms, the artifact indicators and the figures are about 1-ring primal schemes and are not part
of it; the document says where the rest is (``masks``, ``check --certify``, the derivations' ``zoo.tex``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.claims import Verbatim
from symdecomp.errors import InvalidSchemeError, InvalidTypeError
from symdecomp.output.report import DIGITS, Paragraph, Report, Section, Table, check_valences
from symdecomp.output.report_every_n import dual_every_n_section
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.verify.c1_zoo import c1_zoo
from symdecomp.verify.zoo_characteristic import engine_neighbourhood

__all__ = ["ZOO_SECTIONS", "build_zoo_report", "zoo_scheme_section", "zoo_spectrum_section", "zoo_c1_section"]


def _steps(scheme: StencilScheme) -> str:
    return (f" The lattice comes back to itself after {scheme.steps} steps: the matrices, spectra and verdicts are "
            f"those of {scheme.steps} steps." if scheme.steps > 1 else "")


def zoo_scheme_section(scheme: StencilScheme, valences: tuple[int, ...]) -> Section:
    """The scheme: its name, lattice, topology, steps and source, and what the report holds."""
    kind = "interpolatory " if scheme.interpolatory else ""
    blocks = [Paragraph(("Scheme ", Verbatim(scheme.name), f", a {kind}{scheme.topology} scheme on the {scheme.lattice} "
                         f"lattice, analysed by the zoo's engine at the valences {_range(valences)}.{_steps(scheme)}"))]
    if scheme.source:
        blocks.append(Paragraph(("Source of the weights: ", Verbatim(scheme.source), ".")))
    blocks.append(Paragraph((
        "This report holds the spectrum and the $C^1$ verdicts. The paper's claims, the artifact indicators and the "
        "figures are about 1-ring primal schemes; for this scheme the masks are printed by symdecomp masks, the blocks "
        "are checked against the whole matrix by symdecomp check --certify, and symdecomp derive writes the derivation "
        "of each shipped family (its rules' symbols and frequency blocks) to zoo.tex.",)))
    return Section("The scheme", tuple(blocks))


def _range(valences: tuple[int, ...]) -> str:
    return f"$n = {valences[0]}, \\dots, {valences[-1]}$" if len(valences) > 1 else f"$n = {valences[0]}$"


def zoo_spectrum_section(scheme: StencilScheme, valences: tuple[int, ...]) -> Section:
    """The distinct eigenvalues at each valence, with multiplicity and frequencies (``spectrum N --scheme``)."""
    rows = []
    for n in valences:
        for e in zoo_spectrum(scheme, n, digits=DIGITS).eigenvalues:
            value = e.exact if e.exact is not None else Verbatim(f"{e.text} (certified ball's midpoint)")
            ks = ", ".join(map(str, e.frequencies)) if len(e.frequencies) <= 8 else f"{len(e.frequencies)} frequencies"
            rows.append((str(n), value, str(e.multiplicity), Verbatim(ks)))
    return Section("The spectrum", (
        Paragraph(("The distinct eigenvalues of the subdivision matrix of the neighbourhood of depth 1 at each valence, "
                   "from its frequency blocks: exact where a factor of a block's characteristic polynomial has degree at "
                   "most 2, otherwise isolated by certified balls.",)),
        Table(("$n$", "eigenvalue", "multiplicity", "frequencies $k$"), tuple(rows), (0.06, 0.5, 0.14, 0.3)),
    ))


def zoo_c1_section(scheme: StencilScheme, valences: tuple[int, ...]) -> Section:
    """The C1 verdict at each valence (``c1 --scheme``): the test the scheme's model allows, or undecided with the reason."""
    rows = []
    method = ""
    for n in valences:
        r = c1_zoo(scheme, n, neighbourhood=engine_neighbourhood)
        lam = r.as_json()["lambda"]
        method = r.method if r.spectral is not None else method
        rows.append((str(n), str(r.verdict), "-" if lam is None else f"{lam:.{DIGITS}g}",
                     "-" if r.winding_number is None else str(r.winding_number), Verbatim(r.reason)))
    intro = (Paragraph(("Certified in interval arithmetic. ", Verbatim(method), ".")) if method
             else Paragraph(("Reif's test did not run at these valences; each row gives the reason.",)))
    return Section("C1 at the extraordinary element", (
        intro, Table(("$n$", "verdict", "$\\lambda$", "winding", "reason"), tuple(rows), (0.05, 0.1, 0.14, 0.08, 0.63)),
    ))


#: What a zoo scheme's report holds (the report's opening sentence).
CONTENTS = "its decomposition carried out by the zoo's engine, giving the scheme's spectrum and its $C^1$ verdicts"

#: The sections of a zoo scheme's report, in order.
ZOO_SECTIONS = (zoo_scheme_section, zoo_spectrum_section, zoo_c1_section, dual_every_n_section)


def build_zoo_report(scheme: StencilScheme, valences: Iterable[int], *,
                     sections: Iterable[Callable[[StencilScheme, tuple[int, ...]], Section]] = ZOO_SECTIONS) -> Report:
    """The report of the zoo scheme ``scheme`` at ``valences`` (``sections``: :data:`ZOO_SECTIONS`, or a progress bar over them)."""
    if not isinstance(scheme, StencilScheme):
        raise InvalidTypeError(f"build_zoo_report takes a scheme of the zoo (a StencilScheme), got {type(scheme).__name__}")
    if scheme.parameters:
        raise InvalidSchemeError(f"scheme {scheme.name!r} has free parameters {[str(p) for p in scheme.parameters]}; a report "
                                 "needs their values for the spectrum: write them into the scheme file")
    shown = check_valences(valences)
    return Report(Verbatim(scheme.name), shown, tuple(build(scheme, shown) for build in sections), CONTENTS)
