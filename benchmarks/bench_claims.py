"""``symdecomp claims`` in seconds (issue 33), beside its baseline in the same run.

Target: ``symdecomp claims`` within 10 s on two cores, with the same verdicts (the claims on the shared pool, the
costliest handed out first, the claims that share a computation on one worker; the slowest symbolic steps done in
FLINT or in sympy's polynomials over Q, trigonometric identities decided as exponential polynomials instead of by
``simplify``, exact cyclotomic numbers written to sympy without a second expansion, the Loop patch refined in fmpq;
derivation steps whose expressions cost more than the check built only when ``derive`` or a notebook reads them, never
on the pool, which drops them: ``LazySteps``). Building the steps was measured at about 4 % of the CPU of
``claims --jobs 1``: the checks themselves are the cost.
The figure is the wall-clock time of the command in a fresh process (start-up included), so it depends on what else
the machine runs (``run.py`` prints the load); the CPU seconds (user + system of the command and its workers) are
printed beside it, a figure the load changes much less.

Baseline, measured in the same run: ``claims --jobs 1`` (one process, every claim in turn, as before the pool). Both
runs must print the same rows (label, status, scope, evidence, ...), byte for byte.

    python benchmarks/bench_claims.py
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def _run(*argv: str) -> tuple[float, float, str]:
    """Wall-clock seconds, CPU seconds (user + system, the workers included) and the JSON output of
    ``python -m symdecomp claims --json ...`` in a fresh process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "symdecomp", "claims", "--json", *argv], cwd=ROOT, capture_output=True,
                          text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(f"claims {' '.join(argv)} failed: {done.stderr[-300:]}")
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), done.stdout


def _verdicts(out: str) -> list[dict]:
    import json

    return json.loads(out)["rows"]


def targets(quick: bool = False) -> list[dict]:
    """The claims target beside ``claims --jobs 1``; both runs must give the same verdicts (``quick``: section 5)."""
    extra = ("--section", "5") if quick else ()
    seconds, cpu, out = _run(*extra)
    base, base_cpu, base_out = _run("--jobs", "1", *extra)
    if _verdicts(out) != _verdicts(base_out):
        raise RuntimeError("claims on the pool and claims --jobs 1 disagree")
    return [{"target": f"claims{' --section 5' if quick else ''} (shared pool, --jobs = CPUs)",
             "limit_seconds": None if quick else 10.0, "seconds": seconds, "cpu_seconds": cpu, "baseline": "claims --jobs 1",
             "baseline_seconds": base, "baseline_cpu_seconds": base_cpu, "load": os.getloadavg()[0]}]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="section 5 only, for a smoke run")
    args = parser.parse_args(argv)
    for row in targets(args.quick):
        limit = row["limit_seconds"]
        print(f"{row['target']}: {row['seconds']:.2f} s wall, {row['cpu_seconds']:.2f} s CPU"
              + (f" (target {limit:g} s: {'met' if row['seconds'] <= limit else 'NOT met'})" if limit else "")
              + f"; {row['baseline']}: {row['baseline_seconds']:.2f} s wall, {row['baseline_cpu_seconds']:.2f} s CPU; "
              f"load average {row['load']:.2f} on {os.cpu_count()} CPUs; the same rows, byte for byte")
    return 0


if __name__ == "__main__":
    sys.exit(main())
