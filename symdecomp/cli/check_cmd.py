"""``symdecomp check --n 3:64 [--certify]``: closed forms against the full matrix, per valence."""

from __future__ import annotations

import argparse
import itertools
import multiprocessing
import os
import time
from concurrent.futures import ProcessPoolExecutor
from functools import partial

import mpmath

from symdecomp.analysis.closed_forms import ClosedForms, derived_closed_forms
from symdecomp.cli.common import add_scheme_option, positive_int, print_json, progress, valence_range
from symdecomp.schemes.scheme import Scheme
from symdecomp.verify.certify import certify
from symdecomp.verify.numeric import numeric_check
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["register", "run", "check_valences"]


def _digits(text: str) -> int:
    """argparse type: digits of agreement, at least 5."""
    value = positive_int(text)
    if value < 5:
        raise argparse.ArgumentTypeError(f"--dps must be at least 5, got {value}")
    return value


def register(sub) -> None:
    p = sub.add_parser(
        "check",
        help="cross-check the closed-form spectrum against the full subdivision matrix",
        description="For each valence, compare the closed-form eigenvalues (Eq. 34 and Eq. 43) with the "
        "spectrum of the full (2n+1)x(2n+1) matrix built from the rules. Numeric mode: mpmath.eig at "
        "rising precision until the answer stops moving, matched with multiplicities, agreement to "
        "--dps digits. Certified mode (--certify): an exact proof, chi_S = product of the closed-form "
        "factors, checked with FLINT at 2n+1 rational points, with certified multiplicities. "
        "Exit status 1 if any valence disagrees or is left without a verdict.",
    )
    p.add_argument("--n", dest="valences", type=valence_range, required=True, metavar="A:B",
                   help="valences to check: an inclusive range A:B or a single N")
    p.add_argument("--dps", type=_digits, default=50, help="numeric mode: digits of agreement required (default 50)")
    p.add_argument("--certify", action="store_true", help="prove each valence exactly instead of comparing numerically")
    p.add_argument("--jobs", type=positive_int, default=os.cpu_count() or 1,
                   help="worker processes, one valence each at a time (default: the number of CPUs)")
    p.add_argument("--json", action="store_true", help="print one JSON object: {rows: [...], summary: {...}}")
    add_scheme_option(p)
    p.set_defaults(func=run)


def _one(n, *, scheme, certified, dps, closed_forms):
    if certified:
        return certify(scheme, n, closed_forms=closed_forms)
    return numeric_check(scheme, n, dps=dps, closed_forms=closed_forms)


#: The job of the forked workers, set before they start (so only valences are sent to them).
_JOB: dict = {}


def _one_forked(n):
    return _one(n, **_JOB)


def check_valences(scheme: Scheme, valences, *, certified: bool, dps: int = 50, closed_forms: ClosedForms | None = None,
                   jobs: int = 1, show_progress: bool = True):
    """Yield the check of each valence in order (a :class:`~symdecomp.verify.certify.Certificate` or
    :class:`~symdecomp.verify.numeric.NumericCheck`), in ``jobs`` processes."""
    valences = list(valences)
    closed_forms = closed_forms or derived_closed_forms(scheme)
    job = dict(scheme=scheme, certified=certified, dps=dps, closed_forms=closed_forms)
    label = "certify" if certified else f"check {dps} digits"
    if jobs > 1 and len(valences) > 1 and "fork" in multiprocessing.get_all_start_methods():
        first = _one(valences[0], **job)  # also does the symbolic step once, before the workers fork
        _JOB.clear()
        _JOB.update(job)
        try:
            with ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("fork")) as pool:
                rest = pool.map(_one_forked, valences[1:], chunksize=1)
                yield from progress(itertools.chain([first], rest), len(valences), label, enabled=show_progress)
        finally:
            _JOB.clear()
    else:
        work = partial(_one, **job)
        yield from progress(map(work, valences), len(valences), label, enabled=show_progress)


def run(args, *, closed_forms: ClosedForms | None = None) -> int:
    """Run the checks; ``closed_forms`` replaces the derived closed forms (tests inject wrong ones)."""
    start = time.perf_counter()
    rows = []
    if not args.json:
        mode = "certified (exact)" if args.certify else f"numeric, {args.dps} digits"
        print(f"{args.scheme.name}: closed forms vs full matrix, {mode}")
        if args.certify:
            print(f"{'n':>4}  {'status':<9} {'distinct':>8}  {'mult.':<9} {'chi_S bits':>10}  certificate")
        else:
            print(f"{'n':>4}  {'status':<13} {'distinct':>8}  {'max deviation':>13}  {'max spread':>10}  precisions")
    for r in check_valences(args.scheme, args.valences, certified=args.certify, dps=args.dps,
                            closed_forms=closed_forms, jobs=args.jobs, show_progress=True):
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
        print_json({"scheme": args.scheme.name, "rows": [r.as_json() for r in rows], "summary": summary})
    else:
        tally = ", ".join(f"{v} {k}" for k, v in counts.items() if v)
        print(f"{len(rows)} valences: {tally} ({elapsed:.2f} s)")
        for r in failed:
            print(f"FAILED {r.message}")
    return 1 if failed else 0
