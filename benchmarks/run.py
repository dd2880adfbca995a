"""Every performance target of the toolkit beside its baseline, in one run.

Each ``benchmarks/bench_*.py`` that defines ``targets(quick=False)`` returns one dict per
target: ``target`` (what is measured), ``limit_seconds`` (the target, or None), ``seconds``
(measured), ``baseline`` (the route measured beside it), ``baseline_seconds``, and optionally
``megabytes``/``baseline_megabytes`` (peak resident memory). This script calls them all in one
process run and prints one table: the figure, the baseline, their ratio and whether the
target is met. Run from the repository root:

    python benchmarks/run.py             # all targets (minutes on 2 cores)
    python benchmarks/run.py --quick     # a smoke run on smaller ranges
    python benchmarks/run.py --only check --json

Figures depend on the machine and on what else it runs; the table prints the CPU count and the
load average so that a reading can be judged.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import platform
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def _modules(only: str | None):
    for path in sorted(HERE.glob("bench_*.py")):
        if only and only not in path.stem:
            continue
        spec = importlib.util.spec_from_file_location(path.stem, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        if hasattr(module, "targets"):
            yield path.stem, module


def _fmt(value, unit="") -> str:
    if value is None:
        return "-"
    return f"{value:.3g}{unit}" if value < 100 else f"{value:.0f}{unit}"


def _row(bench: str, t: dict) -> dict:
    seconds, base = t.get("seconds"), t.get("baseline_seconds")
    limit = t.get("limit_seconds")
    return {
        "bench": bench,
        **t,
        "ratio": (base / seconds) if seconds and base else None,
        "met": None if limit is None or seconds is None else seconds <= limit,
    }


def _print(rows: list[dict]) -> None:
    print(f"{'target':<44} {'limit':>6} {'seconds':>8} {'MB':>6}  {'baseline':<30} {'seconds':>8} {'MB':>6} {'speed-up':>8}  met")
    for r in rows:
        met = {None: "-", True: "yes", False: "NO"}[r["met"]]
        print(f"{r['target'][:44]:<44} {_fmt(r.get('limit_seconds')):>6} {_fmt(r.get('seconds')):>8} "
              f"{_fmt(r.get('megabytes')):>6}  {str(r.get('baseline') or '-')[:30]:<30} {_fmt(r.get('baseline_seconds')):>8} "
              f"{_fmt(r.get('baseline_megabytes')):>6} {_fmt(r['ratio'], 'x'):>8}  {met}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller ranges (a smoke run)")
    parser.add_argument("--only", help="run only the benchmark files whose name contains this text")
    parser.add_argument("--json", action="store_true", help="print the rows as one JSON object")
    args = parser.parse_args(argv)
    sys.path.insert(0, str(HERE.parent))
    rows = []
    for name, module in _modules(args.only):
        if not args.json:
            print(f"== {name}", file=sys.stderr, flush=True)
        try:
            rows.extend(_row(name, t) for t in module.targets(quick=args.quick))
        except (Exception, SystemExit) as exc:  # one failing benchmark is a row that says so, not the loss of the others
            print(f"{name}: FAILED: {exc}", file=sys.stderr, flush=True)
            rows.append({"bench": name, "target": f"{name}: FAILED: {exc}", "seconds": None, "ratio": None, "met": False})
    machine = {"cpus": os.cpu_count(), "load": [round(x, 2) for x in os.getloadavg()], "python": platform.python_version()}
    if args.json:
        print(json.dumps({"machine": machine, "rows": rows}, indent=1, default=str))
    else:
        print(f"machine: {machine['cpus']} CPUs, load average {machine['load']}, Python {machine['python']}")
        _print(rows)
    return 0 if all(r["met"] is not False for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
