"""``symdecomp claims`` in seconds (issue 33), beside its baseline in the same run.

Target: ``symdecomp claims`` within 10 s on two cores, with the same verdicts (the claims on the shared pool, shared
computations made once before the workers fork). The figure is the wall-clock time of the command in a fresh process
(start-up included), so it depends on what else the machine runs: ``run.py`` prints the load.

Baseline, measured in the same run: ``claims --jobs 1`` (one process, every claim in turn, as before the pool).

    python benchmarks/bench_claims.py
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def _run(*argv: str) -> tuple[float, str]:
    """Wall-clock seconds and the JSON output of ``python -m symdecomp claims --json ...`` in a fresh process."""
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "symdecomp", "claims", "--json", *argv], cwd=ROOT, capture_output=True,
                          text=True)
    if done.returncode != 0:
        raise RuntimeError(f"claims {' '.join(argv)} failed: {done.stderr[-300:]}")
    return time.perf_counter() - start, done.stdout


def _verdicts(out: str) -> list[tuple]:
    import json

    return [(r["label"], r["status"], r["scope"]) for r in json.loads(out)["rows"]]


def targets(quick: bool = False) -> list[dict]:
    """The claims target beside ``claims --jobs 1``; both runs must give the same verdicts (``quick``: section 5)."""
    extra = ("--section", "5") if quick else ()
    seconds, out = _run(*extra)
    base, base_out = _run("--jobs", "1", *extra)
    if _verdicts(out) != _verdicts(base_out):
        raise RuntimeError("claims on the pool and claims --jobs 1 disagree")
    return [{"target": f"claims{' --section 5' if quick else ''} (shared pool, --jobs = CPUs)",
             "limit_seconds": None if quick else 10.0, "seconds": seconds, "baseline": "claims --jobs 1",
             "baseline_seconds": base}]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="section 5 only, for a smoke run")
    args = parser.parse_args(argv)
    for row in targets(args.quick):
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main())
