"""Time ``artifacts --n 64 --scheme sqrt3`` beside ``spectrum 64 --scheme sqrt3`` (issue 30).

The target: the curvature regime of a zoo scheme at n = 64 in well under a minute (it ran past 3 minutes while the
tie ``|mu| = lambda_1^2`` asked sympy for a minimal polynomial; it is decided in a cyclotomic field now,
``verify/zoo_artifacts``). Measured: the whole command as a user runs it (start-up included), wall-clock. Beside it,
the baseline measured in the same run: ``spectrum 64`` of the same scheme (its invariant 1-ring by the structural route;
artifacts reads the 2-ring, the neighbourhood the C1 test reads).

    python benchmarks/bench_zoo_artifacts.py            # n = 64
    python benchmarks/bench_zoo_artifacts.py --quick    # n = 24
"""

from __future__ import annotations

from _targets import main_with_quick, timed

#: The target, seconds.
ARTIFACTS_SECONDS = 30.0


def targets(quick: bool = False) -> list[dict]:
    """``artifacts --n N --scheme sqrt3`` beside ``spectrum N --scheme sqrt3``."""
    n = 24 if quick else 64
    # exit 1: a regime undecided, still a full run
    seconds = timed("-m", "symdecomp", "artifacts", "--n", str(n), "--scheme", "sqrt3", "--json", "--quiet", ok=(0, 1))
    baseline = timed("-m", "symdecomp", "spectrum", str(n), "--scheme", "sqrt3", "--json")
    return [{"target": f"artifacts --n {n} --scheme sqrt3", "limit_seconds": None if quick else ARTIFACTS_SECONDS,
             "seconds": seconds, "baseline": f"spectrum {n} --scheme sqrt3", "baseline_seconds": baseline}]


def main() -> None:
    main_with_quick(__doc__, targets, "n = 24")


if __name__ == "__main__":
    main()
