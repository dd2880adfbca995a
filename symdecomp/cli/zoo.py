"""The commands ``spectrum``, ``masks`` and ``check`` for a scheme of the zoo (a StencilScheme): the zoo's engine.

Each command hands a StencilScheme here (:func:`symdecomp.cli.common.is_stencil_scheme`); the output has the
shape of the command's any-scheme route (``spectrum --json``: the eigenvalues; ``masks``: position and
tangent masks by orbit class; ``check``: one certificate per valence). ``--rings K`` is the neighbourhood's
ring depth (default: the smallest invariant one). Options about sharp vertices do not apply.
"""

from __future__ import annotations

import argparse
import textwrap
import time
from typing import TYPE_CHECKING, Any, NamedTuple

from symdecomp.cli.common import print_json, sharp_given
from symdecomp.cli.plot_file import PlotTarget, write_plot
from symdecomp.cli.progress import progress
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.stencils import StencilScheme

if TYPE_CHECKING:
    from symdecomp.analysis.spectrum import RingSpectrum

__all__ = ["run_zoo_spectrum", "run_zoo_masks", "run_zoo_check"]


def _depth(args: argparse.Namespace) -> int | None:
    if sharp_given(args):
        raise InvalidInputError(f"--scheme {args.scheme.name}: boundary, crease, corner and dart vertices are not analysed "
                                "for schemes of the zoo (interior vertices and faces only)")
    rings = int(getattr(args, "rings", 1))
    return None if rings == 1 else rings


def _steps(scheme: StencilScheme) -> str:
    return f", over {scheme.steps} steps (the lattice returns after {scheme.steps})" if scheme.steps > 1 else ""


def run_zoo_spectrum(args: argparse.Namespace, plot: PlotTarget | None = None) -> int:
    """``spectrum N --scheme <zoo scheme>``."""
    from symdecomp.analysis.zoo_spectrum import zoo_spectrum

    spectrum = zoo_spectrum(args.scheme, args.n, _depth(args), digits=args.digits)
    write_plot(plot, lambda: _spectrum_figure(args.scheme, spectrum))
    if args.json:
        print_json(args, spectrum.as_json())
        return 0
    print(f"{spectrum.scheme} ({args.scheme.topology}, {spectrum.mesh} mesh), n = {spectrum.n}, neighbourhood of depth "
          f"{spectrum.rings}{_steps(args.scheme)}: {spectrum.size} eigenvalues, {len(spectrum.eigenvalues)} distinct")
    width = max(len(e.text) for e in spectrum.eigenvalues)
    print(f"{'value':<{width}}  mult  jordan  frequencies k; exact")
    for e in spectrum.eigenvalues:
        jordan = "?" if e.jordan is None else ("-" if max(e.jordan) == 1 else "+".join(map(str, e.jordan)))
        ks = ", ".join(map(str, e.frequencies)) if len(e.frequencies) <= 8 else f"{len(e.frequencies)} frequencies"
        print(f"{e.text:<{width}}  {e.multiplicity:>4}  {jordan:>6}  {ks}{'' if e.exact is None else f'; {e.exact}'}")
    return 0


def _spectrum_figure(scheme: StencilScheme, spectrum: RingSpectrum) -> Any:
    """``spectrum --plot``: the eigenvalues by the frequency block they come from, titled as the text's first line."""
    from symdecomp.output.plotting.spectrum_chart import spectrum_figure

    title = textwrap.fill(f"{spectrum.scheme} ({scheme.topology}, {spectrum.mesh} mesh), n = {spectrum.n}, neighbourhood of depth "
                          f"{spectrum.rings}{_steps(scheme)}: {len(spectrum.eigenvalues)} distinct eigenvalues by frequency", 90)
    return spectrum_figure(spectrum, title=title, xlabel="frequency k (the block B(omega^k) of the neighbourhood's orbit labelling)")


def run_zoo_masks(args: argparse.Namespace) -> int:
    """``masks N --scheme <zoo scheme>``."""
    from symdecomp.analysis.zoo_masks import zoo_masks

    data = zoo_masks(args.scheme, args.n, _depth(args), digits=args.digits)
    if args.json:
        print_json(args, data)
        return 0
    print(f"{data['scheme']}, n = {data['n']}, neighbourhood of depth {data['rings']}{_steps(args.scheme)}: "
          f"subdominant eigenvalue {data['subdominant']}")
    for title, mask in [("position", data["position"]), ("tangent 1", data["tangents"][0]), ("tangent 2", data["tangents"][1])]:
        print(f"{title}:")
        if "O" in mask:
            print(f"  centre: {mask['O']}")
        for key, weights in mask["classes"].items():
            print(f"  class {key}, sectors 0..{args.n - 1}: {', '.join(weights)}")
    return 0


class _Certified(NamedTuple):
    """What the command prints of one valence's certificate (made in a worker)."""

    ok: bool
    message: str
    json: dict[str, Any]


def _certify_one(n: int, scheme: StencilScheme, depth: int | None) -> _Certified:
    from symdecomp.verify.certify import certify_zoo

    c = certify_zoo(scheme, n, depth, digits=20)
    return _Certified(c.ok, c.message, c.as_json())


#: The options of the check of a scheme of the zoo that it has no use for, with the reason.
_NOT_FOR_THE_ZOO = {
    "dps": "the certified check is exact and has no precision",
    "solver": "numeric mode's eigen-solver; a scheme of the zoo is checked with --certify only",
    "route": "the zoo's certificate chooses its route itself (the structural blocks read once for every n, past the valences "
             "they are read at, else the dense characteristic polynomial)",
    "structural": "the zoo's certificate chooses its route itself (see --route)",
}


def run_zoo_check(args: argparse.Namespace, plot: PlotTarget | None = None) -> int:
    """``check --n A:B --certify --scheme <zoo scheme>``: one certificate per valence, on the pool (--jobs, --executor)."""
    from symdecomp.cli.common import given
    from symdecomp.parallel import ordered_map

    if not args.certify:
        raise InvalidInputError(f"--scheme {args.scheme.name}: a scheme of the zoo is checked with --certify (the blocks "
                                "against the full matrix, exactly)")
    for option, why in _NOT_FOR_THE_ZOO.items():
        if given(args, option):
            raise InvalidInputError(f"--{option}: not used for --scheme {args.scheme.name} (a scheme of the zoo): {why}")
    depth = _depth(args)
    start = time.perf_counter()
    work = ordered_map(_certify_one, args.valences, shared={"scheme": args.scheme, "depth": depth}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    rows = []
    for row in progress(work, len(args.valences), "certify", enabled=not args.quiet):
        rows.append(row)
        if not args.json:
            print(row.message)
    failed = [r for r in rows if not r.ok]
    summary = {"mode": "certified", "route": "zoo", "valences": len(rows), "ok": not failed,
               "seconds": round(time.perf_counter() - start, 3)}
    write_plot(plot, lambda: _check_figure(args.scheme.name, [r.json for r in rows]))
    if args.json:
        print_json(args, {"scheme": args.scheme.name, "rings": args.rings, "rows": [r.json for r in rows], "summary": summary})
    else:
        print(f"{len(rows)} valences: {len(rows) - len(failed)} agree{_steps(args.scheme)}")
        for r in failed:
            print(f"FAILED {r.message}")
    return 1 if failed else 0


def _check_figure(name: str, rows: list[dict[str, Any]]) -> Any:
    from symdecomp.output.plotting.check_chart import check_figure

    return check_figure(name, rows)
