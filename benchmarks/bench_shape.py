"""Time the certified shape classification (``classify_shape``) for n = 3..64, beside pairwise Bernstein products.

The target (issue 21): the curvature-and-shape artifacts classify the elliptic input at every valence
``3..64`` for Catmull-Clark and for Loop within 2 minutes in all; here the classification alone, per
scheme, in one process (the valences one after another), wall-clock. A second target times the shape
chart (9 mixtures x 4 angles) at n = 16.

The baseline is the same classification with the products of Bernstein polynomials done as a loop over
all pairs of coefficients (:func:`~symdecomp.algebra.triangle_bezier.bezier_product` on triangles, its
tensor analogue on quads) instead of one Kronecker-substituted Arb polynomial product. Both routes
must give the same verdicts; the script says so.

    python benchmarks/bench_shape.py            # targets: n = 3..64 per scheme, and the chart
    python benchmarks/bench_shape.py --quick    # n = 3..16
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from contextlib import contextmanager
from dataclasses import replace
from math import comb

from _targets import machine_line, print_rows

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import flint  # noqa: E402

from symdecomp.algebra.triangle_bezier import bezier_product  # noqa: E402
from symdecomp.schemes.files import load_scheme  # noqa: E402
from symdecomp.schemes.lattice import QUAD, TRIANGLE  # noqa: E402
from symdecomp.verify import curvature  # noqa: E402
from symdecomp.verify.shape import classify_shape, shape_chart  # noqa: E402

#: Seconds for ``classify_shape`` at n = 3..64 per scheme (the artifacts' 2 minutes hold both and more).
TARGET_SECONDS = 60.0
#: Seconds for one shape chart (9 x 4 cells) at n = 16.
CHART_SECONDS = 30.0
SCHEMES = ("catmull-clark", "loop")
BASELINE = "pairwise Bernstein products (a loop over all coefficient pairs), same range, same process"


def _pairwise_tensor(f, g, df, dg):
    (p1, q1), (p2, q2) = df, dg
    out = [[flint.arb(0) for _ in range(q1 + q2 + 1)] for _ in range(p1 + p2 + 1)]
    for i in range(p1 + 1):
        for k in range(q1 + 1):
            for i2 in range(p2 + 1):
                for k2 in range(q2 + 1):
                    w = flint.fmpq(comb(p1, i) * comb(p2, i2) * comb(q1, k) * comb(q2, k2), comb(p1 + p2, i + i2) * comb(q1 + q2, k + k2))
                    out[i + i2][k + k2] += w * f[i][k] * g[i2][k2]
    return out


@contextmanager
def pairwise_products():
    """Swap the pairwise products in for the Kronecker ones, and back."""
    saved = dict(curvature._ALGEBRAS)
    curvature._ALGEBRAS[QUAD] = replace(saved[QUAD], product=_pairwise_tensor)
    curvature._ALGEBRAS[TRIANGLE] = replace(saved[TRIANGLE], product=bezier_product)
    try:
        yield
    finally:
        curvature._ALGEBRAS.update(saved)


def _run(scheme, valences):
    start = time.perf_counter()
    kinds = [classify_shape(scheme, n).kind for n in valences]
    return time.perf_counter() - start, kinds


def targets(quick: bool = False) -> list[dict]:
    """``classify_shape`` at n = 3..64 (``3..16`` if ``quick``) per scheme, and one chart, beside the pairwise products."""
    last = 16 if quick else 64
    valences = range(3, last + 1)
    out = []
    for name in SCHEMES:
        scheme = load_scheme(name)
        classify_shape(scheme, 5)  # one-time set-up (ring blocks, regular patch), outside both timings
        seconds, kinds = _run(scheme, valences)
        with pairwise_products():
            old_seconds, old = _run(scheme, valences)
        if kinds != old:
            raise SystemExit(f"{name}: the two product routes disagree")
        out.append({"target": f"classify_shape n = 3..{last}, {name}", "limit_seconds": TARGET_SECONDS if last == 64 else None,
                    "seconds": seconds, "baseline": BASELINE, "baseline_seconds": old_seconds})
    scheme = load_scheme("catmull-clark")
    start = time.perf_counter()
    chart = shape_chart(scheme, 16)
    seconds = time.perf_counter() - start
    with pairwise_products():
        start = time.perf_counter()
        old = shape_chart(scheme, 16)
        old_seconds = time.perf_counter() - start
    if chart.kinds != old.kinds:
        raise SystemExit("the shape charts of the two product routes disagree")
    out.append({"target": "shape_chart catmull-clark n = 16 (9 x 4)", "limit_seconds": CHART_SECONDS, "seconds": seconds,
                "baseline": BASELINE, "baseline_seconds": old_seconds})
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="n = 3..16 instead of 3..64")
    args = parser.parse_args(argv)
    print(machine_line())
    print_rows(targets(args.quick))
    print("the two product routes classify every valence alike and chart alike (targets() stops where they do not)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
