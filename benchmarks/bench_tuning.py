"""Time the certified tuning region (``symdecomp tune N --region``) and its figure.

Targets: the certified regions of Catmull-Clark's rules with free ``(alpha, beta)`` for n = 3..32
(3..8 quick) within 60 s in one process; the figure's 120 x 120 cells at n = 3 (certified signs of
the linear forms at the exact corners, Arb) within 20 s. Baseline for the cells: classifying cell
centres one by one with exact signs (:meth:`~symdecomp.analysis.tuning_region.TuningRegion.classify`),
measured on a 12 x 12 grid and scaled to 120 x 120.

    python benchmarks/bench_tuning.py [--quick]
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import sympy as sp  # noqa: E402

from symdecomp.analysis.tuning_region import tuning_region  # noqa: E402
from symdecomp.output.plotting.tuning import cell_regimes  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark  # noqa: E402
from symdecomp.symbols import alpha, beta  # noqa: E402
from symdecomp.verify.tuning_c1 import certified_tuning_region  # noqa: E402

REGION_SECONDS, CELLS_SECONDS = 60.0, 20.0


def _grid(cells: int) -> list[Fraction]:
    return [Fraction(-2, 5) + Fraction(6, 5) * k / cells for k in range(cells + 1)]


def targets(quick: bool = False) -> list[dict]:
    scheme = catmull_clark(alpha, beta)
    nmax = 8 if quick else 32
    start = time.perf_counter()
    verdicts = {certified_tuning_region(scheme, n).witness_verdict for n in range(3, nmax + 1)}
    regions = time.perf_counter() - start
    region = tuning_region(scheme, 3)
    start = time.perf_counter()
    cell_regimes(region, _grid(120), _grid(120))
    cells = time.perf_counter() - start
    start = time.perf_counter()
    grid = _grid(12)
    for x0, x1 in zip(grid, grid[1:]):
        for y0, y1 in zip(grid, grid[1:]):
            region.classify((sp.Rational((x0 + x1) / 2), sp.Rational((y0 + y1) / 2)))
    exact = (time.perf_counter() - start) * 100
    return [
        {"target": f"certified tuning regions, Catmull-Clark rules with free (alpha, beta), n = 3..{nmax} (verdicts {sorted(verdicts)})",
         "limit_seconds": REGION_SECONDS, "seconds": round(regions, 2), "baseline": None, "baseline_seconds": None},
        {"target": "tuning figure: 120 x 120 cells at n = 3, certified corner signs (Arb)", "limit_seconds": CELLS_SECONDS,
         "seconds": round(cells, 2), "baseline": "exact sign at each cell centre (12 x 12, scaled to 120 x 120)",
         "baseline_seconds": round(exact, 2)},
    ]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="n = 3..8 instead of 3..32")
    print(json.dumps(targets(parser.parse_args().quick), indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
