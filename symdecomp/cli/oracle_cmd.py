"""``symdecomp oracle --n 3:12 [--scheme loop]``: the toolkit's Catmull-Clark or Loop predictions checked against OpenSubdiv."""

from __future__ import annotations

import argparse
import sys

from symdecomp.cli.common import LIMITS, Once, add_scheme_option, flag, integer, print_json, progress, valence_range
from symdecomp.errors import InvalidInputError


def register(sub) -> None:
    p = sub.add_parser(
        "oracle",
        help="compare the toolkit's predictions with OpenSubdiv's Catmull-Clark or Loop refinement",
        description="For each valence, push a random 1-ring in R^3 through OpenSubdiv (uniform "
        "Catmull-Clark, double precision) and print the largest disagreement of each prediction: the "
        "one-step subdivision matrix, 1-ring locality, the limit mask, the limit position, the shrink "
        "rate of every frequency (Eq. 34; Eq. 43 for j = 0; j = 2 is the hyperbolic decay), the ratio "
        "B^1/A^1 (Eq. 39) and the elliptic ratio (Eq. 44). 'exact' rows should agree to double "
        "precision; 'limit' rows converge, the disagreement shrinking by the stated rate per level. "
        "With --scheme loop: OpenSubdiv's Loop scheme against the one-step matrix, the spectrum, the limit "
        "position and tangent masks and the shrink rate of every frequency. "
        "Needs the OpenSubdiv bridge (built on demand with g++ if libosd-dev is installed).",
    )
    add_scheme_option(p)
    p.add_argument("--n", type=valence_range("oracle"), action=Once, default=list(range(3, 13)), metavar="A:B",
                   help="valence or inclusive range of valences (default 3:12, at most 64)")
    p.add_argument("--levels", type=_levels, action=Once, default=20, metavar="K",
                   help=f"refinement levels run in OpenSubdiv (default 20; 2 <= K <= {LIMITS['levels'][0]})")
    p.add_argument("--seed", type=_seed, action=Once, default=0, help="seed of the random 1-rings (default 0; 0 <= seed < 2^32)")
    flag(p, "--json",
                   help='print [{"n", "levels", "seed", "agrees", "predictions": [{"name", "kind", "predicted", '
                        '"observed", "disagreement", "rate", "observed_rate", "agrees"}]}]')
    p.set_defaults(func=run)


def _levels(text: str) -> int:
    return integer(text, "--levels", minimum=2, limit="levels")


def _seed(text: str) -> int:
    value = integer(text, "--seed", minimum=0)
    if value >= 2**32:
        raise argparse.ArgumentTypeError(f"--seed must be below 2^32, got {value}")
    return value


def _comparison(scheme):
    """The comparison for ``scheme``: OpenSubdiv has Catmull-Clark and Loop with their standard weights only."""
    from symdecomp.schemes.loop import loop
    from symdecomp.schemes.scheme import catmull_clark

    def rules(s):
        return (s.lattice, s.edge_rule, s.face_rule, s.vertex_rule)

    if rules(scheme) == rules(catmull_clark()):
        from symdecomp.verify.oracle import compare_with_opensubdiv

        return compare_with_opensubdiv
    if rules(scheme) == rules(loop()):
        from symdecomp.verify.oracle_loop import compare_loop_with_opensubdiv

        return compare_loop_with_opensubdiv
    raise InvalidInputError(f"--scheme {scheme.name}: OpenSubdiv implements Catmull-Clark and Loop with their standard "
                            "weights only; this scheme's rules are neither")


def run(args) -> int:
    from symdecomp.errors import BridgeUnavailableError
    from symdecomp.verify.opensubdiv import load_bridge

    compare = _comparison(args.scheme)
    try:
        load_bridge()
    except BridgeUnavailableError as exc:
        print(f"symdecomp oracle: {exc}", file=sys.stderr)
        return 3
    results = [compare(n, args.levels, args.seed) for n in progress(args.n, len(args.n), "oracle")]
    if args.json:
        print_json([r.as_json() for r in results])
    else:
        for r in results:
            print(f"n = {r.n}  ({r.levels} levels, seed {r.seed}): {'all agree' if r.agrees else 'DISAGREEMENT'}")
            for p in r.predictions:
                rate = "" if p.rate is None else f"  rate {p.rate:.4f}"
                seen = "" if p.observed_rate is None else f" (seen {p.observed_rate:.4f})"
                flag = "" if p.agrees else "  <-- disagrees"
                print(f"  {p.name:<30} {p.kind:<5} {p.disagreement:9.2e}{rate}{seen}{flag}")
    return 0 if all(r.agrees for r in results) else 1
