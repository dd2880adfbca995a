"""``symdecomp check --n 3:64 [--certify]``: closed forms against the full matrix, per valence."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, Any, NamedTuple

from symdecomp.cli.common import (
    LIMITS,
    Once,
    add_pool_options,
    add_rings_option,
    add_scheme_option,
    digits,
    flag,
    general_path,
    given,
    print_json,
    progress,
    refuse_together,
    valence_range,
)
from symdecomp.cli.element import (
    MAX_FACES,
    MAX_STRUCTURAL_FACES,
    add_sharp_options,
    named_element,
    ring_depth,
    route,
    sector_range,
    steps_note,
)
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError
from symdecomp.validate import MAX_DOUBLE_DIGITS, check_memory

if TYPE_CHECKING:
    from symdecomp.analysis.closed_forms import ClosedForms
    from symdecomp.parallel import Executor
    from symdecomp.schemes.scheme import Scheme
    from symdecomp.schemes.stencils import StencilScheme

__all__ = ["register", "run", "check_valences", "ROUTES", "SOLVERS"]

#: The certificates of ``--certify`` (``--route``) and the eigen-solvers of numeric mode (``--solver``).
ROUTES = ("structural", "charpoly")
SOLVERS = ("flint", "mpmath")


#: ``check``'s help of ``--sharpness``: the mirror decomposition, which both modes check against, needs infinitely sharp edges.
SHARPNESS_HELP = ("with --crease or --dart: inf only (the default), in both modes: check compares the refined matrix with "
                  "the mirror decomposition, which a semi-sharp crease does not have; a finite S is refused before any "
                  "output (spectrum K --crease K2 --sharpness S and masks read semi-sharp vertices level by level)")


def register(sub) -> None:
    p = sub.add_parser(
        "check",
        help="cross-check the closed-form spectrum against the full subdivision matrix",
        description="For each valence, compare the closed-form eigenvalues (Eq. 34 and Eq. 43) with the "
        "spectrum of the full (2n+1)x(2n+1) matrix built from the rules. Numeric mode: the eigenvalues as "
        "certified Arb enclosures (--solver flint, the default, with mpmath for a valence it leaves undecided) or "
        "mpmath.eig (--solver mpmath) at rising precision, matched with multiplicities, agreement to --dps digits. "
        "Certified mode (--certify): an exact "
        "proof per valence, by the structural route where it applies (the full matrix equals the bordered "
        "circulant-block matrix entry by entry, and the closed forms are its frequency factors: O(n)) or the dense "
        "route (chi_S = product of the closed-form factors, checked with FLINT at 2n+1 rational points); the output "
        "names the route. For triangle schemes and --rings K > 1 the frequency matrices E_0, E(omega) of the K-ring "
        "matrix (built by exact refinement) are checked instead: numeric mode in double precision (--dps at most "
        f"{MAX_DOUBLE_DIGITS}, default 10), certified mode by the same two routes. "
        "Exit status 1 if any valence disagrees or is left without a verdict.",
    )
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--n", dest="valences", type=valence_range("check --certify --route structural"), action=Once,
                   metavar="A:B",
                   help=f"valences to check: an inclusive range A:B or a single N (at most {LIMITS['check'][0]}; with "
                   f"--certify {LIMITS['check --certify --route structural'][0]} on the structural route, "
                   f"{LIMITS['check --certify'][0]} on the dense one)")
    p.add_argument("--dps", type=digits("--dps", minimum=5, limit="dps"), action=Once, default=50,
                   help="numeric mode: digits of agreement required (default 50; 5 <= dps <= 1000)")
    p.add_argument("--solver", choices=SOLVERS, action=Once, default=None,
                   help="numeric mode, 1-ring closed forms: flint (Arb, certified enclosures: a cluster that does "
                   "not separate is undecided, never a pass) or mpmath (mpmath.eig at rising precision); default: flint, "
                   "and mpmath for a valence flint leaves undecided (a Jordan block), the row says so")
    flag(p, "--certify", help="prove each valence exactly instead of comparing numerically (not with --dps)")
    p.add_argument("--route", choices=ROUTES, action=Once, default=None,
                   help="with --certify: structural (O(n): the full matrix is the block matrix, entry by entry; Remark "
                   "6.1) or charpoly (the dense characteristic polynomial of the full matrix, FLINT); default: structural "
                   "where it applies (edge and face rules free of n, no free parameters), else charpoly, saying so")
    flag(p, "--structural", help="with --certify: the same as --route structural (kept for existing scripts)")
    add_pool_options(p)
    flag(p, "--json", help="print one JSON object: {rows: [...], summary: {...}}")
    which.add_argument("--k", dest="sectors", type=sector_range, action=Once, metavar="A:B",
                       help="with --boundary, --corner, --crease K2 or --dart: the faces K of the vertex's sector, K or an "
                       f"inclusive range A:B (1 <= K <= {MAX_STRUCTURAL_FACES}; darts at most {MAX_FACES}); with --certify "
                       "each K is proved, by the route --route names (charpoly: chi_S of the 1-ring matrix built by exact "
                       "refinement of the tagged mesh = the product of the mirror decomposition's blocks' characteristic "
                       f"polynomials, at most {MAX_FACES} faces; structural: O(K), the refined matrix = the mirror model row "
                       "by row, exactly, so its spectrum is the blocks'; default: charpoly for darts and, under rational rules, "
                       "up to 16 faces; structural otherwise); without, numerically (not darts): the blocks' values against the matrix's "
                       f"eigenvalues to --dps/2 digits up to {MAX_FACES} faces, past them the refined matrix applied to "
                       "every sine polyline against its block in double precision; on --jobs workers either way")
    add_scheme_option(p, zoo=True)
    add_rings_option(p)
    add_sharp_options(p, count="--k", sharpness_help=SHARPNESS_HELP)
    add_quiet_option(p)
    add_plot_option(p, "the agreement by valence (by sector at a sharp vertex): the digits of agreement against --dps, or "
                    "the distinct eigenvalues proved and the characteristic polynomial's size, coloured by status")
    p.set_defaults(func=run)


def _figure(scheme: str, rows: list):
    from symdecomp.output.plotting.check_chart import check_figure

    return check_figure(scheme, [r.as_json() for r in rows])


def _one(n, *, scheme, certified, dps, closed_forms, rings=None, method="charpoly", solver="mpmath"):
    from symdecomp.verify.certify import certify, certify_ring
    from symdecomp.verify.numeric import numeric_check, ring_numeric_check
    from symdecomp.verify.structural import certify_structural

    if rings is not None:  # the any-scheme route: K-ring frequency matrices
        return certify_ring(scheme, n, rings, method=method) if certified else ring_numeric_check(scheme, n, rings, digits=dps)
    if certified:
        if method == "structure":
            return certify_structural(scheme, n, closed_forms=closed_forms)
        return certify(scheme, n, closed_forms=closed_forms)
    return numeric_check(scheme, n, dps=dps, closed_forms=closed_forms, solver=solver)


def check_valences(scheme: Scheme, valences, *, certified: bool, dps: int = 50, closed_forms: ClosedForms | None = None,
                   jobs: int = 1, show_progress: bool = True, rings: int | None = None, method: str = "charpoly",
                   executor: str | Executor = "local", solver: str = "mpmath"):
    """Yield the check of each valence in order (a :class:`~symdecomp.verify.certify.Certificate` or
    :class:`~symdecomp.verify.numeric.NumericCheck`), in at most ``jobs`` processes.

    The pool is :func:`symdecomp.parallel.ordered_map` (``executor``: ``"local"``, ``"dask"`` or
    ``"dask=ADDRESS"``); the first valence is checked here first, so that the symbolic step is
    done once, before the workers fork. ``rings``: check the ``rings``-ring frequency matrices
    (any scheme) instead of the 1-ring closed forms; ``method``: the certificate (``"charpoly"``
    or ``"structure"``, see :func:`~symdecomp.verify.certify.certify_ring` and
    :mod:`~symdecomp.verify.structural`); ``solver``: numeric mode's eigen-solver (``"mpmath"`` or ``"flint"``).
    """
    from symdecomp.analysis.closed_forms import derived_closed_forms
    from symdecomp.parallel import ordered_map

    valences = list(valences)
    if rings is None:
        closed_forms = closed_forms or derived_closed_forms(scheme)
    job = dict(scheme=scheme, certified=certified, dps=dps, closed_forms=closed_forms, rings=rings, method=method, solver=solver)
    label = "certify" if certified else f"check {dps} digits"
    rows = ordered_map(_one, valences, shared=job, jobs=jobs, executor=executor, warm_up=True)
    yield from progress(rows, len(valences), label, enabled=show_progress)


def _route(args, rings) -> tuple[str, str]:
    """The certificate of ``--certify``: ``(route, note)``, the note saying why the default fell back."""
    from symdecomp.verify.structural import structural_obstacle

    refuse_together(args, "--route", "--structural", "--structural is --route structural")
    asked = args.route or ("structural" if args.structural else None)
    obstacle = structural_obstacle(args.scheme) if rings is None and asked != "charpoly" else None
    if asked == "structural" and obstacle is not None:
        raise InvalidInputError(f"--route structural: does not apply to scheme {args.scheme.name!r}: {obstacle}; "
                                "use --route charpoly")
    if obstacle is not None:
        return "charpoly", f"the structural certificate does not apply ({obstacle}): dense route"
    return asked or "structural", ""


def _check_options(args, rings) -> None:
    """Refuse options of the other mode, and valences beyond the bound of the route actually used."""
    refuse_together(args, "--certify", "--dps", "the certified check is exact and has no precision")
    refuse_together(args, "--certify", "--solver", "--solver chooses numeric mode's eigen-solver")
    top = max(args.valences)
    if not args.certify:
        if args.route or args.structural:
            raise InvalidInputError(f"{'--route' if args.route else '--structural'}: give it with --certify (it chooses the "
                                    "certificate)")
        bound, why = LIMITS["check"]
        if top > bound:
            raise InvalidInputError(f"check --n: numeric mode goes up to N = {bound}, got {top} ({why}); "
                                    "use --certify for larger valences")
        if rings is not None and args.solver:
            raise InvalidInputError("--solver: the numeric check of triangle schemes and --rings > 1 runs in double "
                                    "precision (numpy); --solver chooses the 1-ring closed forms' solver")
        return
    key = "check --certify --route structural" if args.route == "structural" else "check --certify"
    bound, why = LIMITS[key]
    if top > bound:
        route = "structural route" if args.route == "structural" else "dense route (--route charpoly)"
        raise InvalidInputError(f"check --n: the {route} goes up to N = {bound}, got {top} ({why})"
                                + (f"; {args.route_note}" if args.route_note else ""))
    if args.route == "structural":
        from symdecomp.verify.structural import STRUCTURAL_BYTES_PER_VALENCE

        check_memory(STRUCTURAL_BYTES_PER_VALENCE * (rings or 1) ** 2 * top, f"the structural certificate at n = {top}")


def run(args, *, closed_forms: ClosedForms | None = None) -> int:
    """Run the checks of the element the arguments name (:data:`ROUTES_BY_KIND`); ``closed_forms`` replaces the derived closed
    forms of an interior vertex's (tests inject wrong ones)."""
    plot = check_plot(args)
    return route("check", ROUTES_BY_KIND, named_element(args))(args, plot, closed_forms)


def _run_sector(args, plot, closed_forms: ClosedForms | None = None) -> int:
    """``check --k A:B`` with a sharp vertex's option: the mirror decomposition (:mod:`symdecomp.cli.check_mirror`)."""
    from symdecomp.cli.check_mirror import run_mirror

    if args.sectors is None:
        raise InvalidInputError("--n: valences of interior vertices; give the faces of a boundary, crease, corner or "
                                "dart vertex's sector with --k A:B")
    return run_mirror(args, plot)


def _run_vertex(args, plot, closed_forms: ClosedForms | None = None) -> int:
    """``check --n A:B``: the closed forms (or the K-ring frequency matrices) against the full matrix, per valence."""
    from symdecomp.verify.result import CrossCheckStatus

    if args.sectors is not None:
        raise InvalidInputError("--k: the faces of a sharp vertex's sector: give --boundary, --corner, --crease K2 or "
                                "--dart (interior valences are --n A:B)")
    rings = args.rings if general_path(args) else None
    args.route_note = ""
    if args.certify:
        args.route, args.route_note = _route(args, rings)
    _check_options(args, rings)
    solver = args.solver or "auto"
    if rings is not None and not args.certify:
        solver = "numpy"
        if not given(args, "dps"):
            args.dps = 10
        elif args.dps > MAX_DOUBLE_DIGITS:
            raise InvalidInputError(f"--dps: the numeric check of triangle schemes and --rings > 1 runs in double precision; "
                                    f"give at most {MAX_DOUBLE_DIGITS}, or use --certify")
    start = time.perf_counter()
    rows = []
    if not args.json:
        _header(args, rings, solver)
    for r in check_valences(args.scheme, args.valences, certified=args.certify, dps=args.dps,
                            closed_forms=closed_forms, jobs=args.jobs, show_progress=not args.quiet, rings=rings,
                            method="structure" if args.route == "structural" else "charpoly", solver=solver,
                            executor=args.executor):
        rows.append(r)
        if not args.json:
            _print_row(args, r)
    elapsed = time.perf_counter() - start
    counts = {s.value: sum(1 for r in rows if r.status is s) for s in CrossCheckStatus}
    failed = [r for r in rows if not r.ok]
    summary = {
        "mode": "certified" if args.certify else "numeric",
        "route": args.route if args.certify else None,
        "route_note": args.route_note or None,
        "solver": None if args.certify else {"auto": "flint"}.get(solver, solver),
        "dps": None if args.certify else args.dps,
        "valences": len(rows),
        **counts,
        "seconds": round(elapsed, 3),
        "ok": not failed,
    }
    if args.json:
        print_json(args, {"scheme": args.scheme.name, "rings": args.rings, "rows": [r.as_json() for r in rows], "summary": summary})
    else:
        tally = ", ".join(f"{v} {k}" for k, v in counts.items() if v)
        print(f"{len(rows)} valences: {tally} ({elapsed:.2f} s)")
        for r in failed:
            print(f"FAILED {r.message}")
    write_plot(plot, lambda: _figure(args.scheme.name, rows))
    return 1 if failed else 0


def _header(args, rings, solver) -> None:
    if args.certify:
        route = ("structural route: the full matrix = the block matrix, entry by entry (no characteristic polynomial)"
                 if args.route == "structural" else "dense route: chi_S of the full matrix (FLINT)")
        mode = f"certified (exact), {route}"
    else:
        mode = f"numeric, {args.dps} digits, solver " + ("flint (mpmath where flint leaves a valence undecided)" if solver == "auto" else solver)
    what = "closed forms" if rings is None else f"{rings}-ring frequency matrices E_0, E(omega)"
    print(f"{args.scheme.name}: {what} vs full matrix, {mode}")
    if args.route_note:
        print(f"note: {args.route_note}")
    if args.certify:
        print(f"{'n':>4}  {'status':<9} {'distinct':>8}  {'mult.':<9} {'route':<10} {'chi_S bits':>10}  certificate")
    else:
        print(f"{'n':>4}  {'status':<13} {'distinct':>8}  {'max deviation':>13}  {'max spread':>10}  precisions")


def _print_row(args, r) -> None:
    import mpmath

    if args.certify:
        mult = "certified" if r.multiplicities_certified else "-"
        bits = r.height_bits if r.route == "charpoly" else "-"
        line = f"{r.n:>4}  {r.status.value:<9} {r.distinct:>8}  {mult:<9} {r.route:<10} {bits:>10}  {r.method}"
    else:
        line = (f"{r.n:>4}  {r.status.value:<13} {len(r.matches):>8}  {mpmath.nstr(r.max_deviation, 3):>13}  "
                f"{mpmath.nstr(r.max_spread, 3):>10}  {','.join(map(str, r.precisions))}")
    print(line if r.ok else f"{line}\n      {r.message}", flush=True)


class _Certified(NamedTuple):
    """What the command prints of one valence's certificate of a scheme of the zoo (made in a worker)."""

    ok: bool
    message: str
    json: dict[str, Any]


def _certify_zoo_one(n: int, scheme: StencilScheme, depth: int | None) -> _Certified:
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


def _run_zoo(args, plot, closed_forms: ClosedForms | None = None) -> int:
    """``check --n A:B --certify --scheme <zoo scheme>``: one certificate per valence, on the pool (--jobs, --executor)."""
    from symdecomp.parallel import ordered_map

    if not args.certify:
        raise InvalidInputError(f"--scheme {args.scheme.name}: a scheme of the zoo is checked with --certify (the blocks "
                                "against the full matrix, exactly)")
    for option, why in _NOT_FOR_THE_ZOO.items():
        if given(args, option):
            raise InvalidInputError(f"--{option}: not used for --scheme {args.scheme.name} (a scheme of the zoo): {why}")
    depth = ring_depth(args)
    start = time.perf_counter()
    work = ordered_map(_certify_zoo_one, args.valences, shared={"scheme": args.scheme, "depth": depth}, jobs=args.jobs,
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
        print(f"{len(rows)} valences: {len(rows) - len(failed)} agree{steps_note(args.scheme)}")
        for r in failed:
            print(f"FAILED {r.message}")
    return 1 if failed else 0


def _check_figure(name: str, rows: list[dict[str, Any]]) -> Any:
    from symdecomp.output.plotting.check_chart import check_figure

    return check_figure(name, rows)


#: The route of each kind of element (:mod:`symdecomp.cli.element`); the zoo's engine refuses a sharp option itself.
ROUTES_BY_KIND = {"vertex": _run_vertex, "sector": _run_sector, "zoo": _run_zoo, "zoo sector": _run_zoo}
