"""What the ``bench_*.py`` scripts share: timing a command in a fresh interpreter, and printing target rows.

A row is the dict each script's ``targets()`` returns (``target``, ``limit_seconds``, ``seconds``, ``baseline``,
``baseline_seconds``; ``run.py`` reads the same rows). Imported as ``_targets``: the scripts run from this directory
(``python benchmarks/bench_x.py``, or loaded by ``run.py``, itself run from here).
"""

from __future__ import annotations

import argparse
import os
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


def print_rows(rows: list[dict]) -> None:
    """One line per target: its seconds, its limit and whether it is met, and the baseline's seconds beside it."""
    for row in rows:
        limit = row["limit_seconds"]
        verdict = "" if limit is None else ("  (target met)" if row["seconds"] <= limit else "  (TARGET MISSED)")
        print(f"{row['target']}: {row['seconds']:.1f} s, limit {limit or '-'} s{verdict}; "
              f"{row['baseline']}: {row['baseline_seconds']:.1f} s")


def main_with_quick(doc: str, targets: Callable[[bool], list[dict]], quick: str) -> None:
    """The ``main()`` of a script whose output is its target rows: ``--help`` from the first line of ``doc`` (the
    script's docstring), ``--quick`` (``quick`` says what it runs instead), then :func:`print_rows` of ``targets``."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=quick)
    print_rows(targets(parser.parse_args().quick))
