"""Time Stam's eigen-data file, certified, against a numpy ``eig`` baseline.

In one run:

(a) the certified file (every float64 correctly rounded) for N = 3..50 (Stam's range) and
    N = 3..128, on ``--jobs`` processes (default 2), wall-clock and CPU seconds;
(b) the baseline: the same patch matrices in float64 through ``numpy.linalg.eig``, ``inv`` and
    the sub-patch tables, timed, and its largest error against the certified values: the
    eigenvalues (sorted) and the surface evaluated from both at random parameters and control
    points (values of order 1).

Target: N = 3..128 correctly rounded in <= 60 s on 2 cores. Run from the repository root:

    python benchmarks/bench_evaldata.py           # 3..50 and 3..128
    python benchmarks/bench_evaldata.py --quick   # 3..12 and 3..24
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import numpy as np  # noqa: E402

from symdecomp.analysis.eigendata import rounded_eigendata  # noqa: E402
from symdecomp.analysis.evaluation import PatchEvaluator  # noqa: E402
from symdecomp.cli.files import write_output_file  # noqa: E402
from symdecomp.output.evaldata import binary_bytes  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark  # noqa: E402
from symdecomp.verify.patch_eval import baseline_error, numpy_baseline  # noqa: E402

TARGET_SECONDS = 60.0


def certified_file(scheme, nmax: int, jobs: int, folder: str):
    start = time.perf_counter()
    rounded = [r for _, r in rounded_eigendata(scheme, range(3, nmax + 1), jobs)]
    write_output_file(os.path.join(folder, f"cc{nmax}.dat"), binary_bytes(rounded))
    return time.perf_counter() - start, rounded


def baseline_errors(scheme, rounded):
    seconds, worst_value, worst_point = 0.0, 0.0, 0.0
    for r in rounded:
        spent, base = numpy_baseline(scheme, r.n)
        seconds += spent
        worst_value = max(worst_value, float(np.abs(np.sort_complex(base.values) - np.sort(r.values)).max()))
        worst_point = max(worst_point, baseline_error(PatchEvaluator.from_rounded(scheme, r), base, seed=r.n))
    return seconds, worst_value, worst_point


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small ranges (3..12, 3..24)")
    parser.add_argument("--jobs", type=int, default=2, help="processes for the certified file (default 2)")
    args = parser.parse_args()
    ranges = (12, 24) if args.quick else (50, 128)
    scheme = catmull_clark()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, load {os.getloadavg()[0]:.1f}")
    with tempfile.TemporaryDirectory() as folder:
        for nmax in ranges:
            load = os.getloadavg()[0]
            wall, rounded = certified_file(scheme, nmax, args.jobs, folder)
            size = os.path.getsize(os.path.join(folder, f"cc{nmax}.dat"))
            base_seconds, err_value, err_point = baseline_errors(scheme, rounded)
            print(f"N = 3..{nmax}: certified file {wall:.1f} s ({args.jobs} processes, load {load:.1f} at the start), {size} bytes")
            print(f"  numpy eig baseline (eig, inv, tables; matrices given): {base_seconds:.2f} s; largest error: eigenvalues {err_value:.2e}, "
                  f"evaluated points {err_point:.2e}")
            if nmax == 128:
                verdict = "met" if wall <= TARGET_SECONDS else "NOT met"
                print(f"  target N = 3..128 in <= {TARGET_SECONDS:.0f} s on 2 cores: {verdict}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
