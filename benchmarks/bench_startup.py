"""Time the start of the ``symdecomp`` program beside importing its dependencies, in one run.

Target (issue 23, item 5): ``symdecomp --version``, ``symdecomp --help`` and ``symdecomp c1 --help``
each take at most 0.3 s more than ``python -c "import sympy, mpmath, flint, numpy"``: the program
may cost its dependencies, not the toolkit's own computation modules (imported when a command
runs; ``tests/cli/test_lazy_commands.py`` checks which modules a parser loads).

Every figure is the best of several fresh interpreters, the commands taken in turns so that a
change of the machine's load falls on all of them alike. The target is judged on CPU time (user
and system, of the process and every child it waited for), which other work on a shared machine
does not inflate; the wall-clock figures are printed beside it (on an idle machine they agree
within a few hundredths). The program runs as ``python -m symdecomp`` from this checkout: its first
process and the forked child that runs the command (:func:`symdecomp.parallel.run_killable`) are
both in the figure. Run from the repository root:

    python benchmarks/bench_startup.py           # best of 9
    python benchmarks/bench_startup.py --quick   # best of 4
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

#: Seconds the program may take beyond importing its dependencies.
LIMIT = 0.3

DEPENDENCIES = "import sympy, mpmath, flint, numpy"
COMMANDS = {"--version": ["--version"], "--help": ["--help"], "c1 --help": ["c1", "--help"]}


def _seconds(argv: list[str]) -> tuple[float, float]:
    """``(cpu, wall)`` seconds of one run of ``argv``."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, cwd=ROOT, env={**os.environ, "PYTHONPATH": ROOT}, stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(argv[1:])} exited with {proc.returncode}")
    return usage.ru_utime + usage.ru_stime, wall


def measure(rounds: int) -> dict[str, tuple[float, float]]:
    """Best ``(cpu, wall)`` seconds of ``rounds`` fresh runs of the dependencies' import and of each command."""
    runs = {"dependencies": [sys.executable, "-c", DEPENDENCIES]}
    runs.update({name: [sys.executable, "-m", "symdecomp", *argv] for name, argv in COMMANDS.items()})
    cpu, wall = dict.fromkeys(runs, float("inf")), dict.fromkeys(runs, float("inf"))
    for _ in range(rounds):
        for name, argv in runs.items():
            c, w = _seconds(argv)
            cpu[name], wall[name] = min(cpu[name], c), min(wall[name], w)
    return {name: (cpu[name], wall[name]) for name in runs}


def targets(quick: bool = False) -> list[dict]:
    best = measure(4 if quick else 9)
    base, base_wall = best["dependencies"]
    return [{"target": f"symdecomp {name}: CPU s beyond the dependencies' (wall {best[name][1] - base_wall:+.2f} s)",
             "limit_seconds": LIMIT, "seconds": max(best[name][0] - base, 0.0),
             "baseline": "import sympy, mpmath, flint, numpy", "baseline_seconds": base}
            for name in COMMANDS]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="best of 4 instead of 9")
    args = parser.parse_args()
    print(f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} at the start")
    best = measure(4 if args.quick else 9)
    base, base_wall = best.pop("dependencies")
    print(f"{'':<48} {'CPU s':>7} {'wall s':>7}  beyond the dependencies (target: CPU <= {LIMIT} s)")
    print(f"{'python -c ' + repr(DEPENDENCIES):<48} {base:7.3f} {base_wall:7.3f}")
    met = True
    for name, (cpu, wall) in best.items():
        extra = cpu - base
        met &= extra <= LIMIT
        print(f"{'symdecomp ' + name:<48} {cpu:7.3f} {wall:7.3f}  CPU {extra:+.3f} s, wall {wall - base_wall:+.3f} s: "
              f"{'met' if extra <= LIMIT else 'NOT met'}")
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
