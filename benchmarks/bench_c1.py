"""Time Reif's test (``symdecomp c1``) per valence, against the target of 120 s for n = 3..64 on 2 cores.

Prints, for Catmull-Clark and for Loop, the time of each valence (one process; the test is
sequential per valence), the total, the largest subdivision depth used, and whether every
valence was certified C1. Run from the repository root:

    python benchmarks/bench_c1.py                    # Catmull-Clark and Loop, n = 3..64
    python benchmarks/bench_c1.py --scheme loop      # one of them
    python benchmarks/bench_c1.py --max 16           # a smoke run
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from symdecomp.schemes.files import load_scheme  # noqa: E402
from symdecomp.verify.c1 import c1_test  # noqa: E402

#: The target of the issue: seconds for n = 3..64.
TARGET_SECONDS = 120.0


def _run(name: str, largest: int) -> bool:
    scheme = load_scheme(name)
    print(f"\n{name}")
    start = time.perf_counter()
    c1_test(scheme, 3)  # one-time set-up: the ring blocks, the symbolic M_j (Loop: the box-spline basis)
    setup = time.perf_counter() - start
    print(f"set-up (ring blocks, symbolic M_j, regular patch, n = 3): {setup:.2f} s")
    print("  n   seconds   verdict   depth   lambda        gap         |J| lower bound")
    total, deepest, ok = 0.0, 0, True
    for n in range(3, largest + 1):
        t0 = time.perf_counter()
        r = c1_test(scheme, n)
        dt = time.perf_counter() - t0
        total += dt
        deepest = max(deepest, r.subdivision_depth or 0)
        ok = ok and r.verdict == "c1"
        row = r.as_json()
        print(f"{n:>3}   {dt:7.3f}   {r.verdict:<8}  {r.subdivision_depth!s:>5}   {row['lambda']:.8f}   "
              f"{row['gap']:.3e}   {row['jacobian_lower_bound']:.3e}")
    print(f"{name}: total n = 3..{largest}: {total:.1f} s (+ {setup:.1f} s set-up), target {TARGET_SECONDS:.0f} s for 3..64; "
          f"deepest subdivision {deepest}; all certified C1: {ok}")
    return ok


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max", type=int, default=64, help="largest valence (default 64)")
    parser.add_argument("--scheme", choices=("catmull-clark", "loop", "both"), default="both",
                        help="which scheme to time (default both)")
    args = parser.parse_args(argv)
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} "
          f"(wall-clock; other processes share the CPUs), Python {platform.python_version()}")
    names = ("catmull-clark", "loop") if args.scheme == "both" else (args.scheme,)
    results = [_run(name, args.max) for name in names]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
