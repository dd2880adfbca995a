"""Time the toolkit's one worker pool (symdecomp.parallel) beside one process, in one run.

Targets:

(a) ``check --certify`` over a range on the local pool (``--jobs 2``), baseline one process;
(b) the same on a Dask LocalCluster of two workers started for the run (``--executor dask``),
    baseline the local pool; skipped without dask installed;
(c) SIGTERM to ``evaldata --jobs 2`` while its workers compute, to exit code 130 with no
    process left (the issue's "within a few seconds"), baseline the same with ``--jobs 1``
    (no pool: the command stops when the valence it is in returns from FLINT).

Run from the repository root:

    python benchmarks/bench_parallel.py           # check over 3..96, evaldata over 3..300
    python benchmarks/bench_parallel.py --quick   # 3..40
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import signal
import subprocess
import sys
import tempfile
import time

from _targets import machine_line, print_rows

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, ROOT)

from symdecomp.cli.check_cmd import check_valences  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark  # noqa: E402

INTERRUPT_LIMIT = 5.0


def _timed(fn) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def _check_rows(nmax: int, **pool) -> float:
    scheme = catmull_clark()
    return _timed(lambda: list(check_valences(scheme, range(3, nmax + 1), certified=True, show_progress=False, **pool)))


def _children(pid: int) -> list[int]:
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as fh:
                    if int(fh.read().rsplit(")", 1)[1].split()[1]) == pid:
                        out.append(int(entry))
            except OSError:
                continue
    return out


def _interrupt(jobs: int, nmax: int) -> float:
    """Seconds from SIGTERM to exit code 130 and no child left, once the command (its process and reaper) has worked 4 s."""
    with tempfile.TemporaryDirectory() as folder:
        proc = subprocess.Popen([sys.executable, "-m", "symdecomp", "evaldata", "--n", f"3:{nmax}", "--out", "cc.dat",
                                 "--jobs", str(jobs)], cwd=folder, env={**os.environ, "PYTHONPATH": ROOT},
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 120  # a loaded machine starts Python slowly: a signal before the command is
        while len(_children(proc.pid)) < 2 and proc.poll() is None and time.monotonic() < deadline:  # up is no test
            time.sleep(0.1)
        time.sleep(4)
        children = _children(proc.pid)
        start = time.perf_counter()
        proc.send_signal(signal.SIGTERM)
        code = proc.wait()
        while any(os.path.exists(f"/proc/{c}") and _zombie_free(c) for c in children):
            time.sleep(0.02)
        seconds = time.perf_counter() - start
        if code != 130:
            raise SystemExit(f"evaldata --jobs {jobs} ended with {code}, not 130")
        return seconds


def _zombie_free(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def targets(quick: bool = False) -> list[dict]:
    nmax = 40 if quick else 96
    rows = []
    one, two = _check_rows(nmax, jobs=1), _check_rows(nmax, jobs=2)
    rows.append({"target": f"check --n 3:{nmax} --certify --jobs 2", "limit_seconds": None, "seconds": two,
                 "baseline": "--jobs 1 (one process)", "baseline_seconds": one})
    if importlib.util.find_spec("distributed") is not None:
        dask = _check_rows(nmax, jobs=2, executor="dask")
        rows.append({"target": f"check --n 3:{nmax} --certify --jobs 2 --executor dask (LocalCluster started and closed)",
                     "limit_seconds": None, "seconds": dask, "baseline": "--executor local --jobs 2", "baseline_seconds": two})
    if sys.platform.startswith("linux"):
        span = 200 if quick else 300
        rows.append({"target": f"SIGTERM to evaldata --n 3:{span} --jobs 2: exit 130, no process left",
                     "limit_seconds": INTERRUPT_LIMIT, "seconds": _interrupt(2, span),
                     "baseline": "the same with --jobs 1 (no pool)", "baseline_seconds": _interrupt(1, span)})
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small ranges")
    args = parser.parse_args()
    print(machine_line())
    print_rows(targets(args.quick), digits=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
