"""Time Reif's test (``symdecomp c1``) per valence, against the target of 120 s for n = 3..64 on 2 cores.

Prints the time of each valence (one process; the test is sequential per valence), the total,
the largest subdivision depth used, and whether every valence was certified C1. Run from the
repository root:

    python benchmarks/bench_c1.py              # Catmull-Clark, n = 3..64
    python benchmarks/bench_c1.py --max 16     # a smoke run
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from symdecomp.schemes.scheme import catmull_clark  # noqa: E402
from symdecomp.verify.c1 import c1_test  # noqa: E402

#: The target of the issue: seconds for n = 3..64.
TARGET_SECONDS = 120.0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max", type=int, default=64, help="largest valence (default 64)")
    args = parser.parse_args(argv)
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} "
          f"(wall-clock; other processes share the CPUs), Python {platform.python_version()}")
    scheme = catmull_clark()
    start = time.perf_counter()
    c1_test(scheme, 3)  # one-time set-up: the B-spline stencils and the symbolic M_j
    setup = time.perf_counter() - start
    print(f"set-up (stencils, symbolic M_j, n = 3): {setup:.2f} s")
    print("  n   seconds   verdict   depth   lambda        gap         |J| lower bound")
    total, deepest, ok = 0.0, 0, True
    for n in range(3, args.max + 1):
        t0 = time.perf_counter()
        r = c1_test(scheme, n)
        dt = time.perf_counter() - t0
        total += dt
        deepest = max(deepest, r.subdivision_depth or 0)
        ok = ok and r.verdict == "c1"
        row = r.as_json()
        print(f"{n:>3}   {dt:7.3f}   {r.verdict:<8}  {r.subdivision_depth!s:>5}   {row['lambda']:.8f}   "
              f"{row['gap']:.3e}   {row['jacobian_lower_bound']:.3e}")
    print(f"\ntotal n = 3..{args.max}: {total:.1f} s (+ {setup:.1f} s set-up), target {TARGET_SECONDS:.0f} s for 3..64; "
          f"deepest de Casteljau subdivision {deepest}; all certified C1: {ok}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
