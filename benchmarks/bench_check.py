"""Time the cross-checks against the baseline a researcher would use today.

In one run, on the same valences:

(a) baseline: the full subdivision matrix (sympy, from the rules) handed to ``mpmath.eig``
    at 50 digits, eigenvalues only (retried on the transpose when mpmath's QR stalls);
(b) ``symdecomp check`` in numeric mode (mpmath at rising precision, matched with the closed
    forms to 50 digits);
(c) ``symdecomp check --certify`` (an exact proof per valence);

then the certified check over a long range (default 3..128) in one and in two processes.
Prints the figures and the ratios. Run from the repository root:

    python benchmarks/bench_check.py            # baseline range 3..24, certified range 3..128
    python benchmarks/bench_check.py --quick    # a smoke run: 3..8 and 3..32
    python benchmarks/bench_check.py --targets  # only issue 24's targets (printed first in every run)

:func:`targets` measures issue 24's commands beside their baselines in one run: ``check --n
1000 --certify`` and ``check --n 3:256 --certify`` (structural route) beside the dense
characteristic-polynomial route on a subrange (3..64; the dense route at 256 takes minutes),
and ``check --n 3:32 --dps 60`` by the Arb solver beside mpmath's, with numpy's float64
``eigvals`` of the same matrices as a baseline figure.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import mpmath  # noqa: E402

from symdecomp.analysis.closed_forms import derived_closed_forms  # noqa: E402
from symdecomp.cli.check_cmd import check_valences  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix  # noqa: E402
from symdecomp.verify.certify import certify  # noqa: E402
from symdecomp.verify.numeric import numeric_check  # noqa: E402
from symdecomp.verify.symmetric_functions import symmetric_functions  # noqa: E402


def baseline(scheme, n: int, dps: int) -> tuple[float, int]:
    """Seconds for mpmath.eig of the full matrix at ``dps`` digits, and the number of QR retries."""
    M = subdivision_matrix(scheme, n)
    retries = 0
    start = time.perf_counter()
    with mpmath.workdps(dps):
        A = mpmath.matrix([[mpmath.mpf(int(x.p)) / int(x.q) for x in M.row(i)] for i in range(M.rows)])
        try:
            mpmath.eig(A, left=False, right=False)
        except RuntimeError:
            retries += 1
            mpmath.eig(A.T, left=False, right=False)
    return time.perf_counter() - start, retries


def timed(f, *args, **kwargs):
    start = time.perf_counter()
    out = f(*args, **kwargs)
    return time.perf_counter() - start, out


def _cli_seconds(*argv: str) -> float:
    """Wall-clock seconds of ``python -m symdecomp check ...`` in a fresh process (its exit code must be 0)."""
    import subprocess

    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "symdecomp", "check", *argv], cwd=root, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"check {' '.join(argv)} failed: {done.stdout[-300:]} {done.stderr[-300:]}")
    return time.perf_counter() - start


def _numpy_seconds(valences) -> float:
    import numpy as np

    from symdecomp.schemes.full_matrix import sparse_subdivision_matrix

    scheme = catmull_clark()
    start = time.perf_counter()
    for n in valences:
        A = np.zeros((2 * n + 1, 2 * n + 1))
        for (r, c), x in sparse_subdivision_matrix(scheme, n).items():
            A[r, c] = int(x.p) / int(x.q)
        np.linalg.eigvals(A)
    return time.perf_counter() - start


def targets(quick: bool = False) -> list[dict]:
    """Issue 24's targets, each measured beside its baseline in this run (``quick``: smaller ranges)."""
    big, long, dense, numeric = ("300", "3:64", "3:32", "3:12") if quick else ("1000", "3:256", "3:64", "3:32")
    rows = []
    t_dense = _cli_seconds("--n", dense, "--certify", "--route", "charpoly")
    for valences in (big, long):
        rows.append({"target": f"check --n {valences} --certify", "limit_seconds": None if quick else 60.0,
                     "seconds": _cli_seconds("--n", valences, "--certify"),
                     "baseline": f"check --n {dense} --certify --route charpoly (dense chi_S, on a subrange)",
                     "baseline_seconds": t_dense})
    lo, hi = map(int, numeric.split(":"))
    rows.append({"target": f"check --n {numeric} --dps 60", "limit_seconds": None if quick else 30.0,
                 "seconds": _cli_seconds("--n", numeric, "--dps", "60", "--solver", "flint"),
                 "baseline": f"check --n {numeric} --dps 60 --solver mpmath",
                 "baseline_seconds": _cli_seconds("--n", numeric, "--dps", "60", "--solver", "mpmath")})
    rows.append({"target": f"numpy float64 eigvals, n = {numeric} (a baseline figure: no certificate, 15 digits)",
                 "limit_seconds": None, "seconds": _numpy_seconds(range(lo, hi + 1)), "baseline": "none", "baseline_seconds": None})
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline-max", type=int, default=24, help="largest n of the baseline comparison (default 24)")
    parser.add_argument("--certify-max", type=int, default=128, help="largest n of the long certified run (default 128)")
    parser.add_argument("--dps", type=int, default=50, help="digits of the baseline and of the numeric mode (default 50)")
    parser.add_argument("--quick", action="store_true", help="small ranges (3..8 and 3..32), for a smoke run")
    parser.add_argument("--targets", action="store_true", help="only issue 24's targets (targets()), printed first in any run")
    args = parser.parse_args(argv)
    for row in targets(args.quick):
        print(row)
    if args.targets:
        return 0
    if args.quick:
        args.baseline_max, args.certify_max = 8, 32
    scheme = catmull_clark()
    valences = list(range(3, args.baseline_max + 1))
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} "
          f"(other processes share the CPUs: figures are wall-clock), Python {platform.python_version()}, "
          f"mpmath backend {mpmath.libmp.BACKEND}")

    # the one-time symbolic step (closed forms and their symmetric functions) for this scheme
    setup, _ = timed(lambda: symmetric_functions(derived_closed_forms(scheme)))

    base_total, retries = 0.0, 0
    num_total, cert_total = 0.0, 0.0
    print(f"\n n   baseline eig {args.dps}d   numeric check {args.dps}d   certified   baseline/certified")
    for n in valences:
        t_base, r = baseline(scheme, n, args.dps)
        t_num, num = timed(numeric_check, scheme, n, dps=args.dps)
        t_cert, cert = timed(certify, scheme, n)
        if not (num.ok and cert.ok):
            print(f"check failed at n = {n}: {num.message} / {cert.message}")
            return 1
        base_total += t_base
        num_total += t_num
        cert_total += t_cert
        retries += r
        print(f"{n:>3}   {t_base:>14.3f} s   {t_num:>17.3f} s   {t_cert:>7.4f} s   {t_base / t_cert:>10.0f}x")
    lo, hi = valences[0], valences[-1]
    print(f"\nn = {lo}..{hi}, totals:")
    print(f"  (a) baseline mpmath.eig, {args.dps} digits:  {base_total:9.3f} s  ({retries} QR retries on the transpose)")
    print(f"  (b) numeric check, {args.dps} digits:        {num_total:9.3f} s  ratio baseline/numeric   = {base_total / num_total:8.2f}x")
    print(f"  (c) certified check (exact):        {cert_total:9.3f} s  ratio baseline/certified = {base_total / cert_total:8.0f}x")
    print(f"      one-time symbolic step per scheme: {setup:.3f} s; "
          f"ratio including it = {base_total / (cert_total + setup):.0f}x")

    long = list(range(3, args.certify_max + 1))
    for jobs in (1, 2):
        t, rows = timed(lambda: list(check_valences(scheme, long, certified=True, jobs=jobs, show_progress=False)))  # noqa: B023 (called at once)
        ok = all(r.ok for r in rows)
        print(f"  certified check, n = 3..{args.certify_max}, {jobs} process(es): {t:8.3f} s  "
              f"({'all agree' if ok else 'FAILURES'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
