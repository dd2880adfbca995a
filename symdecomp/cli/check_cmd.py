"""``symdecomp check --n 3:64 [--certify]``: closed forms against the full matrix, per valence."""

from __future__ import annotations

import time

import mpmath

from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
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
from symdecomp.errors import InvalidInputError
from symdecomp.parallel import Executor, ordered_map
from symdecomp.schemes.scheme import Scheme
from symdecomp.verify.certify import certify
from symdecomp.verify.numeric import numeric_check
from symdecomp.verify.result import CrossCheckStatus
from symdecomp.verify.ring_certify import certify_ring
from symdecomp.verify.ring_numeric import MAX_DOUBLE_DIGITS, ring_numeric_check

__all__ = ["register", "run", "check_valences"]


def register(sub) -> None:
    p = sub.add_parser(
        "check",
        help="cross-check the closed-form spectrum against the full subdivision matrix",
        description="For each valence, compare the closed-form eigenvalues (Eq. 34 and Eq. 43) with the "
        "spectrum of the full (2n+1)x(2n+1) matrix built from the rules. Numeric mode: mpmath.eig at "
        "rising precision until the answer stops moving, matched with multiplicities, agreement to "
        "--dps digits. Certified mode (--certify): an exact proof, chi_S = product of the closed-form "
        "factors, checked with FLINT at 2n+1 rational points, with certified multiplicities. "
        "For triangle schemes and --rings K > 1 the frequency matrices E_0, E(omega) of the K-ring matrix "
        "(built by exact refinement) are checked instead: numeric mode in double precision (--dps at most "
        f"{MAX_DOUBLE_DIGITS}, default 10), certified mode by chi_S = product of the frequency factors "
        "(or, with --structural, the O(n) proof that the refined matrix is the block matrix). "
        "Exit status 1 if any valence disagrees or is left without a verdict.",
    )
    p.add_argument("--n", dest="valences", type=valence_range("check --certify"), action=Once, required=True, metavar="A:B",
                   help="valences to check: an inclusive range A:B or a single N (at most 128; with --certify 512)")
    p.add_argument("--dps", type=digits("--dps", minimum=5, limit="dps"), action=Once, default=50,
                   help="numeric mode: digits of agreement required (default 50; 5 <= dps <= 1000)")
    flag(p, "--certify", help="prove each valence exactly instead of comparing numerically (not with --dps)")
    flag(p, "--structural", help="with --certify: the O(n) proof (the refined matrix equals the bordered circulant-block "
         "matrix of the frequency matrices, entry by entry; Remark 6.1) instead of the dense characteristic polynomial; "
         "multiplicities are certified from the frequency factors where exact arguments apply (the mult. column says)")
    add_pool_options(p)
    flag(p, "--json", help="print one JSON object: {rows: [...], summary: {...}}")
    add_scheme_option(p)
    add_rings_option(p)
    p.set_defaults(func=run)


def _one(n, *, scheme, certified, dps, closed_forms, rings=None, method="charpoly"):
    if rings is not None:  # the any-scheme route: K-ring frequency matrices
        return certify_ring(scheme, n, rings, method=method) if certified else ring_numeric_check(scheme, n, rings, digits=dps)
    if certified:
        return certify(scheme, n, closed_forms=closed_forms)
    return numeric_check(scheme, n, dps=dps, closed_forms=closed_forms)


def check_valences(scheme: Scheme, valences, *, certified: bool, dps: int = 50, closed_forms: ClosedForms | None = None,
                   jobs: int = 1, show_progress: bool = True, rings: int | None = None, method: str = "charpoly",
                   executor: str | Executor = "local"):
    """Yield the check of each valence in order (a :class:`~symdecomp.verify.certify.Certificate` or
    :class:`~symdecomp.verify.numeric.NumericCheck`), in at most ``jobs`` processes.

    The pool is :func:`symdecomp.parallel.ordered_map` (``executor``: ``"local"``, ``"dask"`` or
    ``"dask=ADDRESS"``); the first valence is checked here first, so that the symbolic step is
    done once, before the workers fork. ``rings``: check the ``rings``-ring frequency matrices
    (any scheme) instead of the 1-ring closed forms; ``method``: their certificate
    (``"charpoly"`` or ``"structure"``, see :func:`~symdecomp.verify.ring_certify.certify_ring`).
    """
    valences = list(valences)
    if rings is None:
        closed_forms = closed_forms or derived_closed_forms(scheme)
    job = dict(scheme=scheme, certified=certified, dps=dps, closed_forms=closed_forms, rings=rings, method=method)
    label = "certify" if certified else f"check {dps} digits"
    rows = ordered_map(_one, valences, shared=job, jobs=jobs, executor=executor, warm_up=True)
    yield from progress(rows, len(valences), label, enabled=show_progress)


def run(args, *, closed_forms: ClosedForms | None = None) -> int:
    """Run the checks; ``closed_forms`` replaces the derived closed forms (tests inject wrong ones)."""
    refuse_together(args, "--certify", "--dps", "the certified check is exact and has no precision")
    bound, why = LIMITS["check"]
    if not args.certify and max(args.valences) > bound:
        raise InvalidInputError(f"check --n: numeric mode goes up to N = {bound}, got {max(args.valences)} ({why}); "
                                "use --certify for larger valences")
    if args.structural and not args.certify:
        raise InvalidInputError("--structural: give it with --certify (it is a kind of certificate)")
    rings = args.rings if general_path(args) or args.structural else None
    if rings is not None and not args.certify:
        if not given(args, "dps"):
            args.dps = 10
        elif args.dps > MAX_DOUBLE_DIGITS:
            raise InvalidInputError(f"--dps: the numeric check of triangle schemes and --rings > 1 runs in double precision; "
                                    f"give at most {MAX_DOUBLE_DIGITS}, or use --certify")
    start = time.perf_counter()
    rows = []
    if not args.json:
        mode = "certified (exact)" if args.certify else f"numeric, {args.dps} digits"
        what = "closed forms" if rings is None else f"{rings}-ring frequency matrices E_0, E(omega)"
        print(f"{args.scheme.name}: {what} vs full matrix, {mode}")
        if args.certify:
            print(f"{'n':>4}  {'status':<9} {'distinct':>8}  {'mult.':<9} {'chi_S bits':>10}  certificate")
        else:
            print(f"{'n':>4}  {'status':<13} {'distinct':>8}  {'max deviation':>13}  {'max spread':>10}  precisions")
    for r in check_valences(args.scheme, args.valences, certified=args.certify, dps=args.dps,
                            closed_forms=closed_forms, jobs=args.jobs, show_progress=True, rings=rings,
                            method="structure" if args.structural else "charpoly", executor=args.executor):
        rows.append(r)
        if args.json:
            continue
        if args.certify:
            mult = "certified" if r.multiplicities_certified else "-"
            line = f"{r.n:>4}  {r.status.value:<9} {r.distinct:>8}  {mult:<9} {r.height_bits:>10}  {r.method}"
        else:
            line = (f"{r.n:>4}  {r.status.value:<13} {len(r.matches):>8}  {mpmath.nstr(r.max_deviation, 3):>13}  "
                    f"{mpmath.nstr(r.max_spread, 3):>10}  {','.join(map(str, r.precisions))}")
        print(line if r.ok else f"{line}\n      {r.message}", flush=True)
    elapsed = time.perf_counter() - start
    counts = {s.value: sum(1 for r in rows if r.status is s) for s in CrossCheckStatus}
    failed = [r for r in rows if not r.ok]
    summary = {
        "mode": "certified" if args.certify else "numeric",
        "dps": None if args.certify else args.dps,
        "valences": len(rows),
        **counts,
        "seconds": round(elapsed, 3),
        "ok": not failed,
    }
    if args.json:
        print_json({"scheme": args.scheme.name, "rings": args.rings, "rows": [r.as_json() for r in rows], "summary": summary})
    else:
        tally = ", ".join(f"{v} {k}" for k, v in counts.items() if v)
        print(f"{len(rows)} valences: {tally} ({elapsed:.2f} s)")
        for r in failed:
            print(f"FAILED {r.message}")
    return 1 if failed else 0
