"""Time ``symdecomp artifacts --n 3:64`` (curvature regime and artifact indicators) against the target of 120 s per scheme.

The target (issue 21): ``artifacts --n 3:64`` for Catmull-Clark and for Loop under 2 minutes each on 2 cores,
every valence with a certified regime (bounded, zero or unbounded; never undecided). Measured here: the whole
command as a user runs it (``python -m symdecomp artifacts --n 3:64 --scheme S --json --jobs 2``, start-up
included), wall-clock. Beside it, the baseline: ``symdecomp c1`` on the same range (Reif's test, whose spectrum
the regime reuses), so that the ratio shows what the second-order analysis adds.

    python benchmarks/bench_artifacts.py            # n = 3..64, both schemes
    python benchmarks/bench_artifacts.py --quick    # n = 3..16
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time

from _targets import main_with_quick

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

#: The issue's target: seconds for ``artifacts --n 3:64`` per scheme.
TARGET_SECONDS = 120.0
SCHEMES = ("catmull-clark", "loop")
BASELINE = "symdecomp c1 on the same range (Reif's test: the spectrum the regime builds on, plus the characteristic map)"


def _command(*args: str) -> tuple[float, str]:
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "symdecomp", *args], cwd=ROOT, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - t0
    if done.returncode not in (0, 1):
        raise SystemExit(f"symdecomp {' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")
    return seconds, done.stdout


def targets(quick: bool = False) -> list[dict]:
    """``artifacts --n 3:64`` (``3:16`` if ``quick``) per scheme, beside ``c1`` on the same range."""
    last = 16 if quick else 64
    out = []
    for name in SCHEMES:
        seconds, text = _command("artifacts", "--n", f"3:{last}", "--scheme", name, "--json", "--jobs", "2")
        regimes = [row["curvature"]["regime"] for row in json.loads(text)["rows"]]
        if len(regimes) != last - 2 or any(r not in ("bounded", "zero", "unbounded") for r in regimes):
            raise SystemExit(f"{name}: a valence has no certified regime: {regimes}")
        baseline, _ = _command("c1", "--n", f"3:{last}", "--scheme", name, "--json", "--jobs", "2")
        out.append({
            "target": f"artifacts --n 3:{last} --scheme {name}", "limit_seconds": TARGET_SECONDS if last == 64 else None,
            "seconds": seconds, "baseline": BASELINE, "baseline_seconds": baseline,
        })
    return out


def main() -> None:
    main_with_quick(__doc__, targets, "n = 3..16 instead of 3..64")


if __name__ == "__main__":
    main()
