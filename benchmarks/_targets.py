"""What the ``bench_*.py`` scripts share: timing a command in a fresh interpreter, and printing target rows.

A row is the dict each script's ``targets()`` returns (``target``, ``limit_seconds``, ``seconds``, ``baseline``,
``baseline_seconds``; ``run.py`` reads the same rows). Imported as ``_targets``: the scripts run from this directory
(``python benchmarks/bench_x.py``, or loaded by ``run.py``, itself run from here).
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
from collections.abc import Callable

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def timed(*args: str, ok: tuple[int, ...] = (0,)) -> float:
    """Wall-clock seconds of ``python *args`` run from the repository root; a stop with an exit code not in ``ok``
    ends the benchmark with the command's last words."""
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, *args], cwd=ROOT, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - t0
    if done.returncode not in ok:
        raise SystemExit(f"{' '.join(args[:4])} failed ({done.returncode}): {done.stderr.strip()[-300:]}")
    return seconds


def print_rows(rows: list[dict], *, digits: int = 1) -> None:
    """One line per target: its seconds, its limit and whether it is met, and the baseline's seconds beside it, with
    their ratio (the baseline's seconds over the target's: above 1, the target is faster); ``digits`` after the point."""
    for row in rows:
        limit, seconds, base = row["limit_seconds"], row["seconds"], row["baseline_seconds"]
        verdict = "" if limit is None else ("  (target met)" if seconds <= limit else "  (TARGET MISSED)")
        ratio = f" (ratio {base / seconds:.1f})" if seconds else ""
        print(f"{row['target']}: {seconds:.{digits}f} s, limit {limit or '-'} s{verdict}; "
              f"{row['baseline']}: {base:.{digits}f} s{ratio}")


def machine_line() -> str:
    """The machine a reading was taken on, printed before the rows so that it can be judged: wall-clock figures depend
    on the CPUs and on what else runs."""
    return (f"machine: {platform.machine()}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} "
            f"(wall-clock; other processes share the CPUs), Python {platform.python_version()}")


def main_with_quick(doc: str, targets: Callable[[bool], list[dict]], quick: str) -> None:
    """The ``main()`` of a script whose output is its target rows: ``--help`` from the first line of ``doc`` (the
    script's docstring), ``--quick`` (``quick`` says what it runs instead), then :func:`print_rows` of ``targets``."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=quick)
    print_rows(targets(parser.parse_args().quick))
