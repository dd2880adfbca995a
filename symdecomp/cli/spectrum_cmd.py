"""``symdecomp spectrum N``: the eigenvalues of the valence-N subdivision matrix, from the closed forms."""

from __future__ import annotations

from symdecomp.cli.common import (
    Once,
    add_rings_option,
    add_scheme_option,
    digits,
    flag,
    general_path,
    print_json,
)
from symdecomp.cli.element import (
    add_sharp_options,
    describe,
    exact_only,
    faces_or_valence,
    named_element,
    refuse_sharp_options,
    ring_depth,
    route,
    sharp_vertex,
    steps_note,
)
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.errors import InvalidInputError

#: Above this valence the any-scheme route leaves out the exact expressions unless --exact is given.
EXACT_UP_TO = 64


def register(sub) -> None:
    p = sub.add_parser(
        "spectrum",
        help="eigenvalues of the valence-N subdivision matrix from the closed forms",
        description="Evaluate the closed-form eigenvalues (Eq. 34 for the frequencies k = 1..N-1, the "
        "3x3 matrix of Eq. 43 for k = 0) at valence N and print each distinct value with its "
        "multiplicity and the n-gon frequencies k it comes from. For triangle schemes (loop, loop-warren) and "
        "--rings K > 1: the eigenvalues of the frequency matrices E_0 and E(omega_N^k) of the K-ring matrix, "
        "closed forms where their characteristic polynomials factor into degrees <= 2, certified Arb balls "
        "otherwise, with exact values and Jordan block sizes where decidable. With --boundary, --corner, --crease K2 or "
        "--dart: the exact eigenvalues of the vertex's 1-ring matrix (built by exact refinement of the tagged mesh), "
        "each with the block of the mirror decomposition it comes from (the crease block; the sine block j of a "
        "sector of K faces, theta = pi j/K; the last mode j = K), and with --sharpness S at each level whose "
        "matrix differs until the sharpness has decayed.",
    )
    p.add_argument("n", type=faces_or_valence("spectrum"), metavar="N",
                   help="the valence (an integer, 3 <= N <= 2000), or the faces K of a sharp vertex's sector")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of the values (default 20, at most 1000)")
    flag(p, "--json", help='print {"n", "scheme", "eigenvalues": [{"value", "multiplicity", "frequencies"}]}')
    flag(p, "--exact", help=f"any-scheme route: print exact expressions also for N > {EXACT_UP_TO} (slower)")
    add_scheme_option(p, zoo=True)
    add_rings_option(p)
    add_sharp_options(p)
    add_plot_option(p, "the eigenvalues by the frequency k of the block M_k they come from (by block of the mirror "
                    "decomposition at a sharp vertex), real ones by value, complex ones by modulus")
    p.set_defaults(func=run)


def _run_sector(args, plot) -> int:
    """``spectrum K --boundary`` (``--corner``, ``--crease K2``, ``--dart``): the exact eigenvalues, level by level."""
    from symdecomp.analysis.spectrum import sharp_levels

    refuse_sharp_options(args, "--rings", "--exact")
    vertex = sharp_vertex(args, args.n, structural=True)
    levels = exact_only(args, vertex, lambda: sharp_levels(args.scheme, vertex, digits=args.digits))
    write_plot(plot, lambda: _figure(levels, describe(vertex)))
    if args.json:
        print_json(args, {"scheme": args.scheme.name, "vertex": describe(vertex), "lattice": vertex.lattice.name,
                    "levels": [s.as_json() for s in levels]})
        return 0
    for s in levels:
        distinct = len(s.entries)
        where = "" if len(levels) == 1 else f", level {s.level} (sharpness {s.sharpness})"
        names = ("blocks of the mirror decomposition" if s.decomposed else "parts of the matrix (no mirror decomposition: "
                 + ("semi-sharp edges)" if s.sharpness != float("inf") else "see check --k K --certify)"))
        print(f"{args.scheme.name}, {describe(vertex)}{where} ({vertex.lattice} mesh): {s.size} eigenvalues, {distinct} "
              f"distinct; {names}")
        if s.route == "structural":
            print(f"from the blocks (O(k)): each value a root of its block's polynomial over {s.field}, certified by Arb; "
                  "multiplicities exact (equal blocks, and overlapping values decided in the field)")
        elif s.field != "Q":
            print(f"entries in {s.field}: eigenvalues and multiplicities exact (roots of irreducible rational factors of the "
                  "norm of chi_S, matched to this embedding by Arb)")
        width = max(len(e.text) for e in s.entries)
        print(f"{'value':<{width}}  mult  block; exact")
        for e in s.entries:
            print(f"{e.text:<{width}}  {e.multiplicity:>4}  {', '.join(e.blocks)}; {e.exact}")
    return 0


def _figure(spectrum, vertex: str | None = None):
    from symdecomp.output.plotting.spectrum_chart import sharp_spectrum_figure, spectrum_figure

    return spectrum_figure(spectrum) if vertex is None else sharp_spectrum_figure(spectrum, vertex)


def _run_general(args, plot) -> int:
    from symdecomp.analysis.spectrum import ring_spectrum

    spectrum = ring_spectrum(args.scheme, args.n, args.rings, digits=args.digits, exact=args.exact or args.n <= EXACT_UP_TO)
    write_plot(plot, lambda: _figure(spectrum))
    if args.json:
        print_json(args, spectrum.as_json())
        return 0
    print(f"{spectrum.scheme} ({spectrum.mesh} mesh), valence n = {spectrum.n}, {spectrum.rings}-ring: "
          f"{spectrum.size} eigenvalues, {len(spectrum.eigenvalues)} distinct")
    _print_entries(spectrum)
    return 0


def _print_entries(spectrum) -> None:
    """The table of a spectrum by frequency blocks (any scheme, or the zoo's engine): value, multiplicity, Jordan
    blocks, frequencies and the exact value where known."""
    width = max(len(e.text) for e in spectrum.eigenvalues)
    print(f"{'value':<{width}}  mult  jordan  frequencies k; exact")
    for e in spectrum.eigenvalues:
        jordan = "?" if e.jordan is None else ("-" if max(e.jordan) == 1 else "+".join(map(str, e.jordan)))
        ks = ", ".join(map(str, e.frequencies)) if len(e.frequencies) <= 8 else f"{len(e.frequencies)} frequencies"
        exact = "" if e.exact is None else f"; {e.exact}"
        print(f"{e.text:<{width}}  {e.multiplicity:>4}  {jordan:>6}  {ks}{exact}")


def run(args) -> int:
    """``spectrum``: the route of the element the arguments name (:data:`ROUTES_BY_KIND`)."""
    plot = check_plot(args)
    return route("spectrum", ROUTES_BY_KIND, named_element(args))(args, plot)


def _run_vertex(args, plot) -> int:
    """``spectrum N``: an interior vertex, from the closed forms on the paper's 1-ring, else the any-scheme route."""
    from symdecomp.analysis.spectrum import closed_form_spectrum

    if general_path(args):
        return _run_general(args, plot)
    if args.exact:
        raise InvalidInputError(f"--exact applies to the any-scheme route (a triangle scheme or --rings > 1); --scheme "
                                f"{args.scheme.name} on the 1-ring is read from the closed forms, which it would ignore")
    spectrum = closed_form_spectrum(args.scheme, args.n, digits=args.digits)
    write_plot(plot, lambda: _figure(spectrum))
    if args.json:
        print_json(args, spectrum.as_json())
        return 0
    print(f"{spectrum.scheme}, valence n = {spectrum.n}: {2 * spectrum.n + 1} eigenvalues, {len(spectrum.eigenvalues)} distinct")
    width = max(len(e.text) for e in spectrum.eigenvalues)
    print(f"{'value':<{width}}  mult  frequencies k")
    for e in spectrum.eigenvalues:
        print(f"{e.text:<{width}}  {e.multiplicity:>4}  {', '.join(map(str, e.frequencies))}")
    return 0


def _run_zoo(args, plot) -> int:
    """``spectrum N --scheme <zoo scheme>``: the engine's spectrum on the neighbourhood of the vertex or face."""
    from symdecomp.analysis.zoo_spectrum import zoo_spectrum

    spectrum = zoo_spectrum(args.scheme, args.n, ring_depth(args), digits=args.digits)
    write_plot(plot, lambda: _zoo_figure(args.scheme, spectrum))
    if args.json:
        print_json(args, spectrum.as_json())
        return 0
    print(f"{spectrum.scheme} ({args.scheme.topology}, {spectrum.mesh} mesh), n = {spectrum.n}, neighbourhood of depth "
          f"{spectrum.rings}{steps_note(args.scheme)}: {spectrum.size} eigenvalues, {len(spectrum.eigenvalues)} distinct")
    _print_entries(spectrum)
    return 0


def _zoo_figure(scheme, spectrum):
    """``spectrum --plot``: the eigenvalues by the frequency block they come from, titled as the text's first line."""
    import textwrap

    from symdecomp.output.plotting.spectrum_chart import spectrum_figure

    title = textwrap.fill(f"{spectrum.scheme} ({scheme.topology}, {spectrum.mesh} mesh), n = {spectrum.n}, neighbourhood of depth "
                          f"{spectrum.rings}{steps_note(scheme)}: {len(spectrum.eigenvalues)} distinct eigenvalues by frequency", 90)
    return spectrum_figure(spectrum, title=title, xlabel="frequency k (the block B(omega^k) of the neighbourhood's orbit labelling)")


#: The route of each kind of element (:mod:`symdecomp.cli.element`); the zoo's engine refuses a sharp option itself.
ROUTES_BY_KIND = {"vertex": _run_vertex, "sector": _run_sector, "zoo": _run_zoo, "zoo sector": _run_zoo}
