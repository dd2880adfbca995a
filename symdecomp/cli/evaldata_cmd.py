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
from symdecomp.cli.common import Once, add_pool_options, add_scheme_option, digits, print_json, progress, valence_range
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.errors import EvalDataFileError
from symdecomp.output.evaldata import binary_bytes, dumps, json_document
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
    p.add_argument("--out", action=Once, required=True, metavar="FILE",
                   help="output file, checked before the work starts (a regular file is replaced atomically; a device or a "
                   "FIFO is written in place; a symbolic link is followed)")
    p.add_argument("--format", choices=("binary", "json"), action=Once, default="binary", help="binary (default) or json")
    p.add_argument("--digits", type=digits(), action=Once, default=20, help="significant digits in the JSON form (default 20)")
    add_pool_options(p, default_jobs=2)  # the binary file's valences; the JSON form is computed in this process
    p.add_argument("--json", action="store_true", help="print a JSON summary")
    add_scheme_option(p)
    p.set_defaults(func=run)


def run(args) -> int:
    ns = args.n
    if ns[0] != 3:
        raise EvalDataFileError(f"--n {ns[0]}:{ns[-1]}: the file holds valences 3..N; give --n 3:{ns[-1]}")
    if args.format == "binary" and args.scheme.lattice != PAPER_LATTICE:
        raise EvalDataFileError(f"--format binary: the binary layout is Stam's Catmull-Clark file; for --scheme {args.scheme.name} use --format json")
    check_output_file(args.out)
    show = sys.stderr.isatty() and not args.json
    precs = []
    if args.format == "binary":
        rounded = []
        for prec, r in progress(rounded_eigendata(args.scheme, ns, args.jobs, args.executor), len(ns), "evaldata", enabled=show):
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
    write_output_file(args.out, content)
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
