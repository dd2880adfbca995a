"""Time Reif's test (``symdecomp c1``) against the target of 60 s for n = 3..256, beside the old per-frequency route.

The target (issue 24): ``c1 --n 3:256`` for Catmull-Clark and for Loop within 60 s each on 2 cores.
Measured here: the valences one after another in one process (the command's loop, without its
start-up of about 1.5 s and without worker processes), so one core; the seconds are wall-clock.

The baseline is the old route, run in the same process on the same range: each frequency block
computed ``n`` powers of omega and substituted ``n`` into the rules again (a copy of the old
``frequency_block`` below), and each of the ``n/2 + 1`` outer blocks was bounded by matrix norms
(:func:`symdecomp.analysis.characteristic.outer_bounds`, still there for a block polynomial that
depends on omega, and for the reported gap at small n). The old route here shares what this change does once per scheme (the applicability
check, the symmetry of M_j's polynomial, Loop's box-spline weights), so the ratio understates
the change a little. Both routes must give the same verdicts and lambdas; the script says so.

    python benchmarks/bench_c1.py                    # targets: n = 3..256, both schemes, new and old route
    python benchmarks/bench_c1.py --quick            # n = 3..48
    python benchmarks/bench_c1.py --table --max 16   # per valence: time, verdict, depth, lambda, gap, |J| bound
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from contextlib import contextmanager

from _targets import machine_line, print_rows

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import flint  # noqa: E402
import sympy as sp  # noqa: E402

from symdecomp.algebra.numbers import to_fmpq  # noqa: E402
from symdecomp.analysis import characteristic  # noqa: E402
from symdecomp.schemes.files import load_scheme  # noqa: E402
from symdecomp.verify import c1_spectrum  # noqa: E402
from symdecomp.verify.c1 import c1_test  # noqa: E402

#: The issue's target: seconds for ``c1 --n 3:256`` per scheme.
TARGET_SECONDS = 60.0
SCHEMES = ("catmull-clark", "loop")
BASELINE = ("old route (n powers of omega and the rules substituted per frequency block, a norm bound per outer "
            "block), same range, same process")


def _old_frequency_block(scheme, n, j, *, rows=None):
    """The frequency block as the old route computed it: all ``n`` powers of omega, the rules at ``n`` substituted per block."""
    layout = characteristic.ring_layout(scheme.lattice)
    rows = layout.two_ring if rows is None else rows
    powers = [characteristic.omega_ball(n, j * d % n) for d in range(n)]
    B = flint.acb_mat(rows, layout.two_ring)
    for r, weights in enumerate(characteristic.one_ring_rows(scheme, n)):
        for (d, m), w in weights.items():
            B[r, m] += flint.acb(to_fmpq(sp.sympify(w, strict=True))) * powers[d % n]
    for r in range(layout.one_ring, rows):
        for q, terms in enumerate(layout.offsets[r]):
            for l, w in terms:
                B[r, q] += w * powers[l % n]
    return B


@contextmanager
def old_route():
    """Swap the old route in (norm bounds per outer block, the old blocks) and back."""
    saved = (c1_spectrum.outer_radius, c1_spectrum.frequency_blocks, c1_spectrum.frequency_block, characteristic.frequency_block)
    c1_spectrum.outer_radius = lambda mesh: None
    c1_spectrum.frequency_blocks = lambda scheme, n: (lambda j, rows=None: _old_frequency_block(scheme, n, j, rows=rows))
    c1_spectrum.frequency_block = characteristic.frequency_block = _old_frequency_block
    try:
        yield
    finally:
        c1_spectrum.outer_radius, c1_spectrum.frequency_blocks, c1_spectrum.frequency_block, characteristic.frequency_block = saved


def _run(scheme, valences):
    """``(seconds, [(verdict, lambda), ...])`` for the valences, one after another."""
    start = time.perf_counter()
    results = [c1_test(scheme, n) for n in valences]
    seconds = time.perf_counter() - start
    return seconds, [(r.verdict, r.as_json()["lambda"]) for r in results]


def targets(quick: bool = False) -> list[dict]:
    """``c1 --n 3:256`` (``3:48`` if ``quick``) per scheme, the new route beside the old one on the same range."""
    last = 48 if quick else 256
    valences = range(3, last + 1)
    out = []
    for name in SCHEMES:
        scheme = load_scheme(name)
        c1_test(scheme, 3)  # one-time set-up (ring blocks, symbolic M_j, regular patch), outside both timings
        with old_route():
            c1_test(scheme, 3)
            old_seconds, old = _run(scheme, valences)
        seconds, new = _run(scheme, valences)
        if new != old or any(verdict != "c1" for verdict, _ in new):
            raise SystemExit(f"{name}: the routes disagree or a valence is not certified C1")
        out.append({
            "target": f"c1 --n 3:{last} --scheme {name}", "limit_seconds": TARGET_SECONDS if last == 256 else None,
            "seconds": seconds, "baseline": BASELINE, "baseline_seconds": old_seconds,
        })
    return out


def _table(name: str, largest: int) -> None:
    scheme = load_scheme(name)
    c1_test(scheme, 3)
    print(f"\n{name}\n  n   seconds   verdict   depth   lambda        gap         |J| lower bound")
    for n in range(3, largest + 1):
        t0 = time.perf_counter()
        r = c1_test(scheme, n)
        row = r.as_json()
        print(f"{n:>3}   {time.perf_counter() - t0:7.3f}   {r.verdict:<8}  {r.subdivision_depth!s:>5}   {row['lambda']:.8f}   "
              f"{row['gap']:.3e}   {row['jacobian_lower_bound']:.3e}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="n = 3..48 instead of 3..256")
    parser.add_argument("--table", action="store_true", help="print one row per valence instead of the targets")
    parser.add_argument("--max", type=int, default=64, help="largest valence of --table (default 64)")
    args = parser.parse_args(argv)
    print(machine_line())
    if args.table:
        for name in SCHEMES:
            _table(name, args.max)
        return 0
    print_rows(targets(args.quick))
    print("the two routes' verdicts and lambdas agree at every valence, all C1 (targets() stops where they do not)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
