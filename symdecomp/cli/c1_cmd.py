"""``symdecomp c1 --n 3:64``: Reif's sufficient test for C1 at an extraordinary vertex, certified, per valence."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, NamedTuple

from symdecomp.cli.common import LIMITS, Once, add_pool_options, add_scheme_option, flag, integer, print_json, progress, valence_range

if TYPE_CHECKING:
    from symdecomp.schemes.scheme import Scheme
    from symdecomp.verify.result import C1Verdict

__all__ = ["register", "run"]


def _depth(text: str) -> int:
    """argparse type: a subdivision depth, 0 to 12."""
    return integer(text, "--depth", minimum=0, limit="c1 --depth")


def register(sub) -> None:
    p = sub.add_parser(
        "c1",
        help="certify C1 at an extraordinary vertex (Reif's test on the characteristic map)",
        description="For each valence: Reif's spectral conditions (eigenvalue 1 simple; the subdominant "
        "eigenvalue real, double, non-defective, strictly dominant), then regularity of the characteristic "
        "map (the Jacobian of its sub-patches, bicubic for Catmull-Clark-type and quartic box-spline for "
        "Loop-type schemes, in Bernstein-Bezier form, all coefficients of one sign, "
        "in interval arithmetic with de Casteljau subdivision) and injectivity (winding number 1 of the "
        "ring's inner boundary). Prints 'C1 certified', 'not C1' with the failing condition, or "
        "'undecided' with what would decide it. Exit status 1 unless every valence is certified C1.",
    )
    p.add_argument("--n", dest="valences", type=valence_range("c1"), action=Once, required=True, metavar="A:B",
                   help=f"valences to test: an inclusive range A:B or a single N (at most {LIMITS['c1'][0]})")
    p.add_argument("--depth", type=_depth, action=Once, default=6,
                   help="largest de Casteljau subdivision depth, 0 to 12 (default 6; each level splits a quad piece "
                   "in four, or a triangle twice by bisection)")
    flag(p, "--json",
                   help='print a list with one object per valence: {"n", "verdict" (c1/not-c1/undecided), "reason", '
                   '"lambda", "gap", "jacobian_lower_bound", "winding_number", "method", ...}')
    add_scheme_option(p)
    add_pool_options(p)
    p.set_defaults(func=run)


class _Row(NamedTuple):
    """What the command prints of one valence's :class:`~symdecomp.verify.c1.C1Result` (its Arb balls stay in the worker)."""

    n: int
    verdict: C1Verdict
    reason: str
    json: dict


def _one(n: int, scheme: Scheme, max_depth: int) -> _Row:
    from symdecomp.verify.c1 import c1_test

    r = c1_test(scheme, n, max_depth=max_depth)
    return _Row(r.n, r.verdict, r.reason, r.as_json())


def run(args) -> int:
    from symdecomp.parallel import ordered_map
    from symdecomp.verify.result import C1Verdict

    label = {C1Verdict.C1: "C1 certified", C1Verdict.NOT_C1: "not C1", C1Verdict.UNDECIDED: "undecided"}
    valences = args.valences
    rows = ordered_map(_one, valences, shared={"scheme": args.scheme, "max_depth": args.depth}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    results = list(progress(rows, len(valences), "c1", enabled=sys.stderr.isatty()))
    if args.json:
        print_json([r.json for r in results])
    else:
        print(f"{args.scheme.name}: Reif's test, valences {valences[0]}..{valences[-1]}")
        print(f"method: {args.scheme.lattice.c1_method}")
        for r in results:
            print(f"n = {r.n:>3}: {label[r.verdict]}: {r.reason}")
    return 0 if all(r.verdict is C1Verdict.C1 for r in results) else 1
