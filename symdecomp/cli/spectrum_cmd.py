"""``symdecomp spectrum N``: the eigenvalues of the valence-N subdivision matrix, from the closed forms."""

from __future__ import annotations

from symdecomp.cli.common import Once, add_rings_option, add_scheme_option, digits, flag, general_path, print_json, valence
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
        "otherwise, with exact values and Jordan block sizes where decidable.",
    )
    p.add_argument("n", type=valence("spectrum"), metavar="N", help="the valence (an integer, 3 <= N <= 2000)")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of the values (default 20, at most 1000)")
    flag(p, "--json", help='print {"n", "scheme", "eigenvalues": [{"value", "multiplicity", "frequencies"}]}')
    flag(p, "--exact", help=f"any-scheme route: print exact expressions also for N > {EXACT_UP_TO} (slower)")
    add_scheme_option(p)
    add_rings_option(p)
    p.set_defaults(func=run)


def _run_general(args) -> int:
    from symdecomp.analysis.ring_spectrum import ring_spectrum

    spectrum = ring_spectrum(args.scheme, args.n, args.rings, digits=args.digits, exact=args.exact or args.n <= EXACT_UP_TO)
    if args.json:
        print_json(spectrum.as_json())
        return 0
    print(f"{spectrum.scheme} ({spectrum.mesh} mesh), valence n = {spectrum.n}, {spectrum.rings}-ring: "
          f"{spectrum.size} eigenvalues, {len(spectrum.eigenvalues)} distinct")
    width = max(len(e.text) for e in spectrum.eigenvalues)
    print(f"{'value':<{width}}  mult  jordan  frequencies k; exact")
    for e in spectrum.eigenvalues:
        jordan = "?" if e.jordan is None else ("-" if max(e.jordan) == 1 else "+".join(map(str, e.jordan)))
        ks = ", ".join(map(str, e.frequencies)) if len(e.frequencies) <= 8 else f"{len(e.frequencies)} frequencies"
        exact = "" if e.exact is None else f"; {e.exact}"
        print(f"{e.text:<{width}}  {e.multiplicity:>4}  {jordan:>6}  {ks}{exact}")
    return 0


def run(args) -> int:
    from symdecomp.analysis.spectrum import closed_form_spectrum

    if general_path(args):
        return _run_general(args)
    if args.exact:
        raise InvalidInputError(f"--exact applies to the any-scheme route (a triangle scheme or --rings > 1); --scheme "
                                f"{args.scheme.name} on the 1-ring is read from the closed forms, which it would ignore")
    spectrum = closed_form_spectrum(args.scheme, args.n, digits=args.digits)
    if args.json:
        print_json(spectrum.as_json())
        return 0
    print(f"{spectrum.scheme}, valence n = {spectrum.n}: {2 * spectrum.n + 1} eigenvalues, {len(spectrum.eigenvalues)} distinct")
    width = max(len(e.text) for e in spectrum.eigenvalues)
    print(f"{'value':<{width}}  mult  frequencies k")
    for e in spectrum.eigenvalues:
        print(f"{e.text:<{width}}  {e.multiplicity:>4}  {', '.join(map(str, e.frequencies))}")
    return 0
