"""``symdecomp evaldata --n 3:N --out FILE``: Stam's eigen-data file, every float64 correctly rounded.

``--scheme loop --format json``: the same for Loop's (N+6)-point patch (JSON only; layout in
:mod:`symdecomp.output.evaldata`); a binary Loop request is refused with one line.

Binary (default): the published file's layout (``int32 Nmax``, then per valence ``3..Nmax`` the
eigenvalues, ``V^-1`` and the three sub-patch tables, little-endian), a drop-in replacement.
``--format json --digits D``: the same data as decimal strings of ``D`` significant digits.
``--json``: a summary for programs (``{"out", "format", "nmax", "bytes", "precision_bits"}``).
"""

from __future__ import annotations

import sys

from symdecomp.analysis.eigendata import patch_eigendata, rounded_eigendata
from symdecomp.cli.common import (
    Once,
    add_scheme_option,
    digits,
    flag,
    given,
    positive_int,
    print_json,
    progress,
    valence_range,
)
from symdecomp.errors import EvalDataFileError, InvalidInputError
from symdecomp.output.evaldata import binary_bytes, check_writable, dumps, json_document, write_atomic
from symdecomp.schemes.lattice import PAPER_LATTICE


def register(sub) -> None:
    p = sub.add_parser(
        "evaldata",
        help="Stam's eigen-data file for exact evaluation near an extraordinary vertex",
        description="Write the eigenvalues, inverse eigenvector matrix and sub-patch tables of the (2N+8)-point "
        "patch matrix for valences 3..N, each float64 the correctly rounded value of the exact number "
        "(certified Arb balls), in the layout of the published data file; or as JSON decimal strings. "
        "With --scheme loop (JSON only): the same for Loop's (N+6)-point patch.",
    )
    p.add_argument("--n", type=valence_range("evaldata"), action=Once, required=True, metavar="3:N",
                   help="valences 3..N (the binary file starts at 3)")
    p.add_argument("--out", action=Once, required=True, metavar="FILE", help="output file (written atomically)")
    p.add_argument("--format", choices=("binary", "json"), action=Once, default="binary", help="binary (default) or json")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits in the JSON form (default 20; --format json only)")
    p.add_argument("--jobs", type=positive_int("--jobs", "jobs"), action=Once, default=2,
                   help="worker processes for the binary file (default 2; binary format only)")
    flag(p, "--json", help="print a JSON summary")
    add_scheme_option(p)
    p.set_defaults(func=run)


def _refuse_ignored(args) -> None:
    """An option the chosen format would ignore is refused, not dropped: --digits is JSON's, --jobs the binary file's."""
    if args.format == "binary" and given(args, "digits"):
        raise InvalidInputError("--digits applies to --format json only: the binary file holds float64 values, each "
                                "correctly rounded")
    if args.format == "json" and given(args, "jobs"):
        raise InvalidInputError("--jobs applies to the binary format only: --format json computes the valences in one process")


def run(args) -> int:
    _refuse_ignored(args)
    ns = args.n
    if ns[0] != 3:
        raise EvalDataFileError(f"--n {ns[0]}:{ns[-1]}: the file holds valences 3..N; give --n 3:{ns[-1]}")
    if args.format == "binary" and args.scheme.lattice != PAPER_LATTICE:
        raise EvalDataFileError(f"--format binary: the binary layout is Stam's Catmull-Clark file; for --scheme {args.scheme.name} use --format json")
    check_writable(args.out)
    show = sys.stderr.isatty() and not args.json
    precs = []
    if args.format == "binary":
        rounded = []
        for prec, r in progress(rounded_eigendata(args.scheme, ns, args.jobs), len(ns), "evaldata", enabled=show):
            precs.append(prec)
            rounded.append(r)
        content = binary_bytes(rounded)
    else:
        balls = []
        for n in progress(ns, len(ns), "evaldata", enabled=show):
            prec = max(1200, int(3.33 * args.digits) + 128)
            data = patch_eigendata(args.scheme, n, prec)
            precs.append(prec)
            balls.append(data)
        content = dumps(json_document(balls, args.digits, args.scheme.name))
    write_atomic(args.out, content)
    defective = [] if args.format == "binary" else [d.n for d in balls if d.jordan]
    summary = {"out": args.out, "format": args.format, "nmax": ns[-1], "bytes": len(content), "precision_bits": max(precs)}
    summary["jordan_valences"] = defective
    if args.json:
        print_json(summary)
    else:
        print(f"wrote {args.out}: {args.format}, valences 3..{ns[-1]}, {len(content)} bytes (working precision up to {max(precs)} bits)")
        if defective:  # the matrix has no eigenvector basis there: the file carries its Jordan pairs
            print(f"not diagonalizable at N = {', '.join(map(str, defective))}: the file holds the Jordan pairs (\"jordan\") for those valences")
    return 0
