"""Time Zorin's test on sqrt(3) over its two steps (``c1 --n 3:10 --scheme sqrt3``) against 60 s, beside the first
refinement depth the test used to start from.

The target (issue 30): sqrt(3)'s C1 certified valence by valence, "for the N you can reach in seconds to a minute".
Measured: the whole command as a user runs it (start-up included), one worker (``--jobs 1``), wall-clock. The baseline,
measured in the same run on ``n = 3..5`` only (it takes about a minute per valence): the same test started at ``m = 4``,
the dyadic depth it started from before the first depth was chosen by points per coarse point (``3^8`` there against
``3^4``); both must certify.

    python benchmarks/bench_zoo_c1.py            # n = 3..10, the baseline at 3..5
    python benchmarks/bench_zoo_c1.py --quick    # n = 3..5, the baseline at 3
"""

from __future__ import annotations

from _targets import main_with_quick, timed

#: The target, seconds for ``c1 --n 3:10 --scheme sqrt3 --jobs 1``.
C1_SECONDS = 60.0

_FIXED_DEPTH = """
import sys
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.c1_zorin import c1_zorin_test
scheme = load_zoo("sqrt3")
for n in range(3, int(sys.argv[1]) + 1):
    assert c1_zorin_test(scheme, n, min_depth=4, max_depth=4).verdict.value == "c1", n
"""


def targets(quick: bool = False) -> list[dict]:
    """``c1 --n 3:10 --scheme sqrt3`` (``3:5`` if ``quick``) beside the test started at ``m = 4``."""
    last, base = (5, 3) if quick else (10, 5)
    seconds = timed("-m", "symdecomp", "c1", "--n", f"3:{last}", "--scheme", "sqrt3", "--jobs", "1", "--quiet")
    baseline = timed("-c", _FIXED_DEPTH, str(base))
    return [{"target": f"c1 --n 3:{last} --scheme sqrt3 --jobs 1", "limit_seconds": None if quick else C1_SECONDS,
             "seconds": seconds, "baseline": f"Zorin's test started at m = 4, n = 3..{base}", "baseline_seconds": baseline}]


def main() -> None:
    main_with_quick(__doc__, targets, "n = 3..5, the baseline at n = 3")


if __name__ == "__main__":
    main()
