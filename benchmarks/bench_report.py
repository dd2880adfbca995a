"""Time ``symdecomp report`` against the target of 60 s for Catmull-Clark at n = 3..8 (issue 23, item 3).

Measured: the report built and written as PDF (HTML if pdflatex is missing) in one fresh process, as the
command runs it (``python -m symdecomp report catmull-clark --n 3:8 --out FILE``), wall-clock, including
the program's start-up. Most of it is the 65 claims' checks. The baseline is what the report replaces:
the commands a researcher ran one by one for the same content (``claims --scheme``, ``spectrum N`` and
``masks N`` per valence, ``c1 --n A:B``), each a fresh process.

    python benchmarks/bench_report.py            # catmull-clark 3:8, and the baseline
    python benchmarks/bench_report.py --quick    # loop 3:5 (no claims: a triangle scheme)
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

from _targets import print_rows

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

#: The target: seconds for ``report catmull-clark --n 3:8``.
TARGET_SECONDS = 60.0
BASELINE = "claims, spectrum, masks, c1 one by one"


def _seconds(*commands: list[str]) -> float:
    start = time.perf_counter()
    for command in commands:
        done = subprocess.run([sys.executable, "-m", "symdecomp", *command], cwd=ROOT, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        if done.returncode not in (0, 1):  # masks and c1 exit 1 for a valence they cannot certify
            raise SystemExit(f"symdecomp {' '.join(command)} failed: {done.stderr.strip()}")
    return time.perf_counter() - start


def targets(quick: bool = False) -> list[dict]:
    """``report catmull-clark --n 3:8`` (``loop --n 3:5`` if ``quick``) beside the commands it replaces."""
    scheme, lo, hi = ("loop", 3, 5) if quick else ("catmull-clark", 3, 8)
    suffix = ".pdf" if shutil.which("pdflatex") else ".html"
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "report" + suffix)
        seconds = _seconds(["report", scheme, "--n", f"{lo}:{hi}", "--out", out])
    one_by_one = [["c1", "--scheme", scheme, "--n", f"{lo}:{hi}", "--jobs", "1"]]
    one_by_one += [[command, str(n), "--scheme", scheme] for n in range(lo, hi + 1) for command in ("spectrum", "masks")]
    if not quick:
        one_by_one.append(["claims", "--scheme", scheme])
    return [{
        "target": f"report {scheme} --n {lo}:{hi} --out FILE{suffix}", "limit_seconds": None if quick else TARGET_SECONDS,
        "seconds": seconds, "baseline": BASELINE, "baseline_seconds": _seconds(*one_by_one),
    }]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="loop at n = 3..5")
    args = parser.parse_args(argv)
    print_rows(targets(args.quick))
    return 0


if __name__ == "__main__":
    sys.exit(main())
