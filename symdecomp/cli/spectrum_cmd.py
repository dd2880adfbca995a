"""``symdecomp spectrum N``: the eigenvalues of the valence-N subdivision matrix, from the closed forms."""

from __future__ import annotations

from symdecomp.analysis.spectrum import closed_form_spectrum
from symdecomp.cli.common import Once, add_scheme_option, digits, flag, print_json, valence


def register(sub) -> None:
    p = sub.add_parser(
        "spectrum",
        help="eigenvalues of the valence-N subdivision matrix from the closed forms",
        description="Evaluate the closed-form eigenvalues (Eq. 34 for the frequencies k = 1..N-1, the "
        "3x3 matrix of Eq. 43 for k = 0) at valence N and print each distinct value with its "
        "multiplicity and the n-gon frequencies k it comes from.",
    )
    p.add_argument("n", type=valence("spectrum"), metavar="N", help="the valence (an integer, 3 <= N <= 2000)")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of the values (default 20, at most 1000)")
    flag(p, "--json", help='print {"n", "scheme", "eigenvalues": [{"value", "multiplicity", "frequencies"}]}')
    add_scheme_option(p)
    p.set_defaults(func=run)


def run(args) -> int:
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
