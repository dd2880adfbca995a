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

Where the CPU goes (``claims --jobs 1``'s order, one process, CPU seconds at load 5 to 6; before -> after the cuts of
the second pass): C1 (Reif's test) 1.61 -> 1.24 (the ring layout's 3-ring blocks, checked against the refinement at two
more valences with dense sympy matrices, now entry by entry and sparse; the exact 1-ring entries at each valence and
frequency, now read once per expression into a ``CyclotomicFunction``); Curvature regime: Catmull-Clark 1.12 -> 0.93
(the certified second-order structure per valence, the same exact entries; the hyperbolic cause's sympy ``cancel``);
Eq. 51 0.91 -> 0.44 (the displayed closed form at n = 3..6, now reduced in FLINT as ``(a + b r)/d`` with ``r^2 = D``;
left: the exact check against the matrix to n = 16); Remark 5.2 0.81 -> 0.29 (the elliptic components, sympy's
``simplify`` of quotients of radicals, now exact in ``Q(sqrt d)``); Shape 0.67 (certified curvature per valence, Arb);
Section 3: Catmull-Clark support 0.64 (exact mesh refinement in Fractions); Eq. 1 0.58 (exact polygon decompositions
written to sympy); Eq. 50 0.55 and Eq. 46 0.53 (sympy's symbolic CB-matrix and block-matrix identities); 1-ring
suffices 0.52 -> 0.39 (the K-ring blocks). In all 16.4 -> 14.9 CPU seconds in one process. Side by side with the code
before (``--against``, medians of 3 alternated runs, at load 6 to 8 from other jobs, so the wall-clock figures are far
above the target and say little): Catmull-Clark 19.4 -> 17.3 CPU seconds (45.8 -> 43.3 s wall), Loop 11.2 -> 10.3 (33.1
-> 25.0 s wall), the same rows byte for byte. On an idle two-core machine the pool's wall time should be about the start-up
(1.2 s) plus half the CPU (an estimate: no idle machine was at hand in this pass).

Third pass (one process, ``claims --jobs 1``'s order, CPU seconds, load 5 to 7): Section 3: Catmull-Clark support 0.8 ->
0.55 (refinement of a basis function, mostly zeros: a rational weight's term on a rational zero left out, a mesh's
interior vertices found once); Section 5.2: Catmull-Clark example 0.73 -> 0.3 (its defects at n = 3, 5 read as digits
without ``simplify``; n = 4 still simplified to an exact zero); Spectrum (Eq. 34, Eq. 43) 0.69 -> 0.65 (the charpoly's bit
bound from the nonzero entries). Where the rest goes (top ten, CPU seconds): C1 (Reif's test) 1.34 (the ring layout's
3-ring blocks and the every-n route's uniform map), Curvature regime: Catmull-Clark 0.98 (the second-order structure per
valence, sympy ``cancel`` in the hyperbolic cause), Shape 0.72 (certified curvature Gram matrices per valence, Bernstein
products), Eq. 1 0.66 (of which about 0.4 is sympy.physics.units, imported by the first ``simplify`` of a process; the
rest the exact decompositions written to sympy), Eq. 50 0.61 and Remark 6.1 0.43 (sympy ``eigenvects`` of 2 x 2 blocks
over Q(i): roots by factoring over an algebraic field), Eq. 46 0.59 (``block_collapse`` of symbolic block matrices),
Spectrum 0.5 (FLINT charpolys and closed forms at n = 3..48), Proposition 6.2 0.47 (the lift identity, sympy matrix
products), Eq. 51 0.45. Fixed costs: import 0.5 s, the claims registry (every section's module) 0.7 s, both before the
workers fork; each worker pays sympy.physics.units (about 0.5 s) at its first ``simplify``. The first group of
:data:`~symdecomp.claims.batch.GROUPS` costs 3.45 CPU-s together and 7.0 with each claim in its own process.
Side by side (``--against`` main, alternately, the same rows byte for byte): Catmull-Clark 20.06 -> 19.38 CPU seconds
(medians of 3, load about 5 with other jobs and a test run: 75 -> 87 s wall, which says nothing) and 19.26 -> 18.02
(medians of 2, load 4.7: 34.8 -> 35.6 s wall); Loop 10.7 -> 10.8 and 11.05 -> 11.0 (unchanged: none of its costly claims
was cut). The 10 s target is not reached: on an idle machine main took 12.4 s wall (18.8 CPU-s) in this pass, and
these cuts save about 1 CPU-s, so about half a second of wall.

Baseline, measured in the same run: ``claims --jobs 1`` (one process, every claim in turn, as before the pool). Both
runs must print the same rows (label, status, scope, evidence, ...), byte for byte.

    python benchmarks/bench_claims.py
    python benchmarks/bench_claims.py --against ../before --repeat 3   # the code before, run alternately with this one
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def _run(*argv: str, root: str = ROOT) -> tuple[float, float, str]:
    """Wall-clock seconds, CPU seconds (user + system, the workers included) and the JSON output of
    ``python -m symdecomp claims --json ...`` in a fresh process, with the package of the checkout ``root``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    env = {**os.environ, "PYTHONPATH": os.path.abspath(root)}
    done = subprocess.run([sys.executable, "-m", "symdecomp", "claims", "--json", *argv], cwd=root, capture_output=True,
                          text=True, env=env)
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


def side_by_side(before: str, repeat: int, schemes: tuple[str, ...] = ("catmull-clark", "loop")) -> list[dict]:
    """``claims`` (the pool) of the checkout ``before`` and of this one, run alternately ``repeat`` times per scheme (so
    that both meet the same load), with the rows compared: the median wall-clock and CPU seconds of each."""
    import statistics

    rows = []
    for scheme in schemes:
        runs: dict[str, list[tuple[float, float]]] = {"before": [], "after": []}
        for _ in range(repeat):
            for which, root in (("before", before), ("after", ROOT)):
                wall, cpu, out = _run("--scheme", scheme, root=root)
                runs[which].append((wall, cpu))
                if which == "before":
                    expected = _verdicts(out)
                elif _verdicts(out) != expected:
                    raise RuntimeError(f"claims --scheme {scheme}: this checkout's rows differ from those before")
        rows.append({"scheme": scheme, **{f"{which}_{what}": statistics.median(x[i] for x in runs[which])
                                          for which in runs for i, what in enumerate(("seconds", "cpu_seconds"))}})
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="section 5 only, for a smoke run")
    parser.add_argument("--against", metavar="CHECKOUT", help="a checkout of the code before (a git worktree of main, "
                        "say): its claims and this one's, run alternately, the median of each beside the other")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each with --against (default 3)")
    args = parser.parse_args(argv)
    if args.against:
        for row in side_by_side(args.against, args.repeat):
            print(f"claims --scheme {row['scheme']}: before {row['before_seconds']:.2f} s wall, {row['before_cpu_seconds']:.2f} "
                  f"s CPU; after {row['after_seconds']:.2f} s wall, {row['after_cpu_seconds']:.2f} s CPU (medians of "
                  f"{args.repeat}, alternately); load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs; the same "
                  "rows, byte for byte")
        return 0
    for row in targets(args.quick):
        limit = row["limit_seconds"]
        print(f"{row['target']}: {row['seconds']:.2f} s wall, {row['cpu_seconds']:.2f} s CPU"
              + (f" (target {limit:g} s: {'met' if row['seconds'] <= limit else 'NOT met'})" if limit else "")
              + f"; {row['baseline']}: {row['baseline_seconds']:.2f} s wall, {row['baseline_cpu_seconds']:.2f} s CPU; "
              f"load average {row['load']:.2f} on {os.cpu_count()} CPUs; the same rows, byte for byte")
    return 0


if __name__ == "__main__":
    sys.exit(main())
