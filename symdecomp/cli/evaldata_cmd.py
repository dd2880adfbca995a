"""``symdecomp evaldata --n 3:N --out FILE``: Stam's eigen-data file, every float64 correctly rounded.

``--scheme loop --format json``: the same for Loop's (N+6)-point patch (JSON only; layout in
:mod:`symdecomp.output.evaldata`); a binary Loop request is refused with one line.

Binary (default): the published file's layout (``int32 Nmax``, then per valence ``3..Nmax`` the
eigenvalues, ``V^-1`` and the three sub-patch tables, little-endian), a drop-in replacement.
``--format json``: the same data as decimal strings: the correctly rounded float64s in their
shortest round-trip form (``--digits 17``, the default), or with ``--digits D > 17`` the exact
values correctly rounded to ``D`` significant digits. The file is streamed valence by valence.
Before any work the memory and time are estimated (:func:`~symdecomp.analysis.eigendata.eigendata_cost`)
and a request beyond the memory limit is refused in one line naming the estimate.
``--json``: a summary for programs (``{"out", "format", "nmax", "bytes", "precision_bits",
"jordan_valences", "estimate": {"megabytes", "seconds"}}``).

``--boundary --k 1:8`` (or ``--corner``): the exact data of the patches next to a boundary (corner) vertex
with K faces, K in the range, as JSON of exact rationals (format ``sharp-patches`` in
:mod:`symdecomp.output.evaldata`; evaluation in :func:`symdecomp.analysis.evaluation.evaluate`). ``--json``:
``{"out", "format", "scheme", "kind", "k", "bytes", "sizes"}``.

``--scheme doo-sabin --n A:B`` (a scheme of the zoo): the data of its extraordinary faces, or one line saying why
there are none (:mod:`symdecomp.cli.evaldata_formats`).

``--crease --k A:B`` (crease vertices with K faces on each side), and ``--boundary``/``--corner`` under BLZ's rules:
the sector evaluation data (format ``sector-evaldata``, :mod:`symdecomp.output.sector_evaldata`), written by
:mod:`symdecomp.cli.evaldata_formats`.

``--plot FILE``: the eigenvalues of the data written, one line per rank over the valences (or ``K``)
(:mod:`symdecomp.cli.evaldata_plot`), gathered from the file's pieces as they are written, and only then.

The element (interior vertex, sector, a zoo scheme's face) is read once (:mod:`symdecomp.cli.element`) and routed by
:data:`ROUTES_BY_KIND`.
"""

from __future__ import annotations

from symdecomp.cli.common import (
    LIMITS,
    Once,
    add_pool_options,
    add_scheme_option,
    digits,
    face_range,
    flag,
    given,
    print_json,
    progress,
    valence_range,
)
from symdecomp.cli.element import named_element, route
from symdecomp.cli.evaldata_plot import EigenvaluesDrawn, check_evaldata_plot, factor_roots, piece_values
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.cli.plot_file import add_plot_option
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import EvalDataFileError, InvalidInputError
from symdecomp.parallel import pool_size
from symdecomp.validate import FLOAT_DIGITS


def register(sub) -> None:
    p = sub.add_parser(
        "evaldata",
        help="Stam's eigen-data file for exact evaluation near an extraordinary vertex",
        description="Write the eigenvalues, inverse eigenvector matrix and sub-patch tables of the (2N+8)-point "
        "patch matrix for valences 3..N, each float64 the correctly rounded value of the exact number "
        "(certified Arb balls), in the layout of the published data file; or as JSON decimal strings. "
        "With --scheme loop (JSON only): the same for Loop's (N+6)-point patch. With --boundary or --corner and "
        "--k A:B: the exact data (rationals) of the patches next to a boundary or corner vertex with K faces; with --crease "
        "(or BLZ's rules): the sector data, an eigen-decomposition and the spline cells, exact or in Arb balls. With a scheme of the zoo whose "
        "regular part is the biquadratic B-spline (--scheme doo-sabin) and --n A:B: the data of its n-sided faces (JSON).",
    )
    p.add_argument("--n", type=valence_range("evaldata"), action=Once, metavar="3:N",
                   help="valences 3..N (the binary file starts at 3); or a sharp vertex with --boundary or --corner")
    flag(p, "--boundary", help="the patches of boundary vertices with K faces (--k): exact JSON, format sharp-patches")
    flag(p, "--corner", help="the patches of corner vertices (interpolated) with K faces (--k): exact JSON")
    flag(p, "--crease", help="crease vertices with K faces on each side (--k): JSON, format sector-evaldata")
    p.add_argument("--k", dest="faces", type=face_range("--k", "evaldata --k"), action=Once, metavar="A:B",
                   help=f"faces of the boundary or corner vertex: a range A:B or a single K (1 to {LIMITS['evaldata --k'][0]})")
    p.add_argument("--out", action=Once, required=True, metavar="FILE",
                   help="output file, checked before the work starts (a regular file is replaced atomically; a device or a "
                   "FIFO is written in place; a symbolic link is followed)")
    p.add_argument("--format", choices=("binary", "json"), action=Once, default="binary",
                   help="binary (default) or json (--boundary and --corner: json only)")
    p.add_argument("--digits", type=digits(minimum=FLOAT_DIGITS), action=Once, default=FLOAT_DIGITS,
                   help="JSON numbers: 17 (default) = the correctly rounded float64, shortest text that reads back as it; "
                   "D > 17 = the exact value correctly rounded to D significant digits (slower, one process)")
    add_pool_options(p, default_jobs=2)  # the binary file and JSON at 17 digits; JSON at D > 17 digits runs in this process
    flag(p, "--json", help="print a JSON summary")
    add_scheme_option(p, zoo=True)  # a scheme of the zoo: its faces' data (symdecomp.cli.evaldata_formats)
    add_quiet_option(p)
    add_plot_option(p, "the eigenvalues of the data written, one line per rank (the largest distinct eigenvalue, 1; "
                    "the next, lambda_1; then mu, ...) against the valence n, or against K with --boundary, --corner and "
                    "--crease (their factors' roots, or the decomposition's), by modulus where one is complex; not the "
                    "same file as --out")
    p.set_defaults(func=run)


def _refuse_ignored(args) -> None:
    """An option the chosen format would ignore is refused, not dropped: --digits is JSON's; --jobs and
    --executor are the binary file's and JSON's at 17 digits (D > 17 digits are computed in one process)."""
    if args.format == "binary" and given(args, "digits"):
        raise InvalidInputError("--digits applies to --format json only: the binary file holds float64 values, each "
                                "correctly rounded")
    if args.format == "json" and args.digits > FLOAT_DIGITS:
        for option in ("jobs", "executor"):
            if given(args, option):
                raise InvalidInputError(f"--{option}: --format json --digits {args.digits} computes the valences in one "
                                        f"process (workers apply to the binary file and to --digits {FLOAT_DIGITS})")


def rounded_eigendata(*args, **kwargs):
    """:func:`symdecomp.analysis.eigendata.rounded_eigendata`, imported when the command runs."""
    from symdecomp.analysis.eigendata import rounded_eigendata

    return rounded_eigendata(*args, **kwargs)


def _sharp_kind(args) -> str | None:
    """``"boundary"``, ``"corner"`` or ``None`` (interior valences, --n), or a one-line error for a bad mix."""
    kinds = [name for name in ("boundary", "corner", "crease") if given(args, name)]
    if len(kinds) > 1:
        raise InvalidInputError(f"{' and '.join('--' + k for k in kinds)} cannot be used together: give one kind of vertex")
    if not kinds:
        if given(args, "faces"):
            raise InvalidInputError("--k needs --boundary, --corner or --crease")
        if not given(args, "n"):
            raise InvalidInputError("give --n 3:N (interior vertices), or --boundary/--corner with --k A:B")
        return None
    if given(args, "n"):
        raise InvalidInputError(f"--n (interior vertices) and --{kinds[0]} cannot be used together: give one kind of vertex")
    if not given(args, "faces"):
        raise InvalidInputError(f"--{kinds[0]} needs --k A:B, the faces of the vertex")
    for option in ("digits", "jobs", "executor"):
        if given(args, option):
            raise InvalidInputError(f"--{option} does not apply to --{kinds[0]}: its data are exact rationals, computed "
                                    "in this process")
    if args.format == "binary" and given(args, "format"):
        raise EvalDataFileError(f"--format binary: the binary layout is Stam's interior file; --{kinds[0]} writes json")
    return kinds[0]


def _run_sharp(args, kind: str, plot=None) -> int:
    from symdecomp.analysis.subpatch_data import sharp_patch_data
    from symdecomp.output.evaldata import SHARP_FORMAT, sharp_entry, sharp_json_chunks
    from symdecomp.schemes.sector import SharpVertex

    if kind == "crease" or getattr(args.scheme.sharp, "near_edge_centre", None) is not None:  # creases, BLZ's rules
        from symdecomp.cli.evaldata_formats import run_sector

        return run_sector(args, kind, plot)
    scheme, ks = args.scheme, args.faces
    check_output_file(args.out)
    show = not args.quiet
    sizes = []
    drawn = EigenvaluesDrawn(plot)

    def entries():
        for k in progress(ks, len(ks), "evaldata", enabled=show):
            data = sharp_patch_data(scheme, getattr(SharpVertex, kind)(k, scheme.lattice))
            sizes.append(data.size)
            drawn.add(k, factor_roots, data.spectrum)
            yield sharp_entry(data)

    size = write_output_file(args.out, sharp_json_chunks(entries(), scheme.name, scheme.lattice.name))
    drawn.write("K (faces)", f"{scheme.name}, {kind} vertices: eigenvalues of the data written (roots of its factors)")
    if args.json:
        print_json(args, {"out": args.out, "format": SHARP_FORMAT, "scheme": scheme.name, "kind": kind, "k": ks, "bytes": size,
                    "sizes": sizes})
    else:
        print(f"wrote {args.out}: {SHARP_FORMAT} ({scheme.name}), {kind} vertices with K = {ks[0]}..{ks[-1]} faces, "
              f"{size} bytes (exact rationals; control points: the closed 2-ring, {sizes[0]}..{sizes[-1]} points)")
    return 0


def run(args) -> int:
    """``evaldata``: the route of the element the arguments name (:data:`ROUTES_BY_KIND`), ``--plot`` checked first."""
    answer = route("evaldata", ROUTES_BY_KIND, named_element(args))
    return answer(args, check_evaldata_plot(args))


def _run_sector(args, plot=None) -> int:
    kind = _sharp_kind(args)  # two kinds, or --n with one: one line
    assert kind is not None  # a sector element names its kind
    return _run_sharp(args, kind, plot)


def _run_zoo(args, plot=None) -> int:  # a scheme of the zoo: the data of its extraordinary faces, or why there are none
    from symdecomp.cli.evaldata_formats import run_dual

    return run_dual(args, plot)


def _run_vertex(args, plot=None) -> int:
    from symdecomp.analysis.eigendata import check_eigendata_cost
    from symdecomp.output.evaldata import binary_chunks, binary_valence, decimal_valence, json_chunks, json_valence_text

    _sharp_kind(args)  # --k without a kind, or no --n: one line
    _refuse_ignored(args)
    ns = args.n
    if ns[0] != 3:
        raise EvalDataFileError(f"--n {ns[0]}:{ns[-1]}: the file holds valences 3..N; give --n 3:{ns[-1]}")
    if args.format == "binary" and not args.scheme.lattice.paper_claims:
        raise EvalDataFileError(f"--format binary: the binary layout is Stam's Catmull-Clark file; for --scheme {args.scheme.name} use --format json")
    digits = args.digits if args.format == "json" else FLOAT_DIGITS
    jobs = pool_size(args.jobs, len(ns)) if digits == FLOAT_DIGITS else 1
    memory, seconds = check_eigendata_cost(args.scheme, ns[-1], jobs, digits, text=args.format == "json")  # the waiting text
    check_output_file(args.out)
    show = not args.quiet
    precs, defective = [], []
    drawn = EigenvaluesDrawn(plot)

    encode = binary_valence if args.format == "binary" else json_valence_text  # in the workers, in parallel

    def rounded():  # the valences as they come, in order, each already the file's piece; nothing holds the whole file
        valences = rounded_eigendata(args.scheme, ns, args.jobs, args.executor, encode=encode)
        for prec, r in progress(valences, len(ns), "evaldata", enabled=show):
            precs.append(prec)
            defective.extend([r.n] if r.jordan else [])
            drawn.add(r.n, piece_values, r)
            yield r

    def decimal():
        for n in progress(ns, len(ns), "evaldata", enabled=show):
            prec, entry = decimal_valence(args.scheme, n, digits)
            precs.append(prec)
            defective.extend([n] if entry.get("jordan") else [])
            drawn.add(n, piece_values, entry)
            yield entry

    if args.format == "binary":
        size = write_output_file(args.out, binary_chunks(rounded(), ns[-1]))
    else:
        entries = rounded() if digits == FLOAT_DIGITS else decimal()
        size = write_output_file(args.out, json_chunks(entries, ns[-1], digits, args.scheme.name))
    drawn.write("valence n", f"{args.scheme.name}: eigenvalues of the data written, valences 3..{ns[-1]}")
    summary = {"out": args.out, "format": args.format, "nmax": ns[-1], "bytes": size, "precision_bits": max(precs)}
    summary["jordan_valences"] = defective
    summary["estimate"] = {"megabytes": round(memory / 2**20), "seconds": round(seconds, 1)}
    if args.json:
        print_json(args, summary)
    else:
        print(f"wrote {args.out}: {args.format}, valences 3..{ns[-1]}, {size} bytes (working precision up to {max(precs)} bits)")
        if defective:  # the matrix has no eigenvector basis there: the file carries its Jordan pairs
            print(f"not diagonalizable at N = {', '.join(map(str, defective))}: the file holds the Jordan pairs (\"jordan\") for those valences")
    return 0


#: The route of each kind of element (:mod:`symdecomp.cli.element`); a zoo scheme's faces refuse a sharp option themselves.
ROUTES_BY_KIND = {"vertex": _run_vertex, "sector": _run_sector, "zoo": _run_zoo, "zoo sector": _run_zoo}
