"""Sharp vertices at the speed of interior ones (issue 33), each figure beside its baseline.

Targets (issue 33): ``spectrum 1000 --boundary --scheme catmull-clark-blz`` within 5 s, the same for corners,
creases and Loop's rules (the structural route: the mirror decomposition's blocks, O(k)); ``c1 --boundary --k
1:1000`` within 60 s, the same for corners and Loop (the spectral and tangent conditions from the blocks, O(log k)
per k; where they hold, the characteristic map: for BLZ's boundary sectors from the subdominant eigenvectors in closed
form, Fourier modes between the sharp rays, read on a few faces per k). Last measured (``--c1``, one run, 2 cores at
load 3 to 5 from other jobs, so these are pessimistic): ``c1 --boundary --k 1:1000`` 6.3 s for Catmull-Clark, 2.8 s
for Loop, 31.4 s for ``catmull-clark-blz`` (all 1000 certified C1; 64.3 s in the run before, at load 3 to 4, and 4 min
9 s with 65..1000 undecided before the closed-form modes) and 31.8 s for ``loop-blz`` (40.3 s before); ``--corner``
9.6 s (Catmull-Clark), 3.8 s (Loop), 6.8 s (``catmull-clark-blz``: undecided from k = 2 on, its eigenvalue 1/2 is
triple with a Jordan block of size 2, so Zorin's condition that lambda_2 be strictly dominant fails and the test does
not apply; the block is now computed for the reason, exact kernels in Q(cos(pi/k)) up to 12 faces: about 2 s at 8
faces, not measured side by side here; since then the block's own test certifies C1 at every k = 2..64, past 12 faces
from the 1-ring block's kernels and the blocks' spectrum: ``c1 --corner --k 1:64`` 88.6 s wall, 101 CPU-s, for
``catmull-clark-blz`` and 23.2 s (43.6 CPU-s) for ``loop-blz``, one run at load 1 to 2; one vertex 3 s at 48 faces,
5 s at 64, 30 s at 128, growing about like k^3 with the field's degree, so the route stops at 64 faces and
``--k 1:1000`` is not feasible through it; each dense test at
k = 1..8 1.1 to 4.5 s. Side by side with the code before, fresh processes at load 2: ``catmull-clark-blz`` boundary
26.9 s (51.8 CPU seconds) before, 15.6 s (28.8) after; ``loop-blz`` 30.1 CPU seconds before, 24.0 after. Per ``k``
(``catmull-clark-blz``, CPU) the closed-form route took 45 ms: the wide ring's nets 15, the Jacobian's certificate 20,
the leading values 6; now 23 (6, 11, 4): each net point and stencil is resolved once, the crease block's eigenvalues
and parities are derived once per scheme, the Bezier sums skip their exact zeros (the balls are bit for bit the same).
Once per worker: the closed-form modes, about 2 s.
Every figure is the wall-clock time of the command in a fresh process (start-up included), so it depends on what else
the machine runs: ``run.py`` prints the load. ``claims`` has its own file (``bench_claims.py``).

Baselines, measured in the same run: the dense route (the vertex's matrix built by refinement, its characteristic
polynomial factored, over ``Q(cos(pi/k))`` for BLZ's rules) on a small vertex, ``k = 8`` (at ``k = 16`` it took
211 s before this change); for ``c1``, the dense test alone (:func:`~symdecomp.verify.c1_sector_matrix.c1_sharp_test`, the
only route before this change, now reading the sector's sparse rows, which made it faster too) at ``k = 1..8``.

``check --k`` (:func:`check_targets`): the certificate of a vertex of 10,000 faces by the structural route (the
refined matrix's rows against the mirror model, O(k)), a range of sectors on the pool, and numeric mode's polylines at
10,000 faces, each beside the dense route at k = 64 (``check --k 64 --route charpoly``, 13 s before this change; numeric:
the dense eigenvalues at 64 faces), the largest vertex that route reads. Measured in one run (``--check``, 2 cores, load
average 0.2 to 0.8, fresh processes, start-up included): ``check --k 10000 --boundary --certify`` 9.4 s (BLZ's rules
9.7 s; ``--k 9997 --crease 3 --scheme loop-blz`` 5.9 s), ``--k 1:200 --corner --certify --scheme catmull-clark-blz``
7.1 s, beside the dense route at k = 64, 7.7 s; numeric ``check --k 10000 --boundary`` (polylines) 16.3 s beside the
dense eigenvalues at 64 faces, 2.9 s. (Before this change ``--k 1:50 --corner --certify --scheme catmull-clark-blz`` with
its 16 smallest vertices on the dense route took 368 s on a loaded machine.)

    python benchmarks/bench_sharp.py            # every target
    python benchmarks/bench_sharp.py --quick    # k = 200 and the dense route at k = 6
    python benchmarks/bench_sharp.py --check    # only check --k's rows (--quick: k = 1000, the dense route at k = 24)
    python benchmarks/bench_sharp.py --c1       # only c1 --k's rows (--quick: K = 100, BLZ's 1:24)
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def _seconds(*argv: str, codes: tuple[int, ...] = (0,)) -> float:
    """Wall-clock seconds of ``python -m symdecomp ...`` in a fresh process (its exit code must be one of ``codes``)."""
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "symdecomp", *argv], cwd=ROOT, capture_output=True, text=True)
    if done.returncode not in codes:
        raise RuntimeError(f"{' '.join(argv)} failed: {done.stdout[-300:]} {done.stderr[-300:]}")
    return time.perf_counter() - start


def _dense_seconds(scheme: str, vertex: str, k: int) -> float:
    """Seconds of the dense route (:func:`symdecomp.analysis.spectrum.sharp_spectrum`, ``route="dense"``) in a
    fresh process: the command line takes the structural route from 9 faces on, so this is the dense route's figure."""
    code = ("import symdecomp as sd; from symdecomp.schemes.files import load_scheme; "
            "from symdecomp.analysis.spectrum import sharp_spectrum; "
            f"s = load_scheme({scheme!r}); v = sd.SharpVertex.{vertex}({k}, s.lattice); "
            "sharp_spectrum(s, v, route='dense')")
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], cwd=ROOT, check=True, capture_output=True)
    return time.perf_counter() - start


def targets(quick: bool = False) -> list[dict]:
    """Issue 33's targets, each beside its baseline in this run (``quick``: k = 200, dense baseline at k = 6)."""
    k, small = (200, 6) if quick else (1000, 8)
    limit = None if quick else 5.0
    rows = []
    for scheme, vertex, option in (("catmull-clark-blz", "boundary", ["--boundary"]),
                                   ("catmull-clark-blz", "corner", ["--corner"]),
                                   ("catmull-clark-blz", "crease", ["--crease", str(k)]),
                                   ("loop-blz", "boundary", ["--boundary"]),
                                   ("catmull-clark", "crease", ["--crease", str(k)])):
        dense_vertex = "boundary" if vertex == "crease" else vertex
        rows.append({"target": f"spectrum {k} {' '.join(option)} --scheme {scheme}", "limit_seconds": limit,
                     "seconds": _seconds("spectrum", str(k), *option, "--scheme", scheme),
                     "baseline": f"dense route, {dense_vertex} k = {small}",
                     "baseline_seconds": _dense_seconds(scheme, dense_vertex, small)})
    return rows + c1_targets(quick) + check_targets(quick)


def _dense_c1_seconds(scheme: str, vertex: str, faces: range) -> float:
    """Seconds of the dense test alone at each ``k`` of ``faces`` in a fresh process (the route before the blocks)."""
    code = ("import symdecomp as sd; from symdecomp.schemes.files import load_scheme; "
            "from symdecomp.verify.c1_sector_matrix import c1_sharp_test; "
            f"s = load_scheme({scheme!r}); "
            f"[c1_sharp_test(s, sd.SharpVertex.{vertex}(k, s.lattice)) for k in range({faces.start}, {faces.stop})]")
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], cwd=ROOT, check=True, capture_output=True)
    return time.perf_counter() - start


def c1_targets(quick: bool = False) -> list[dict]:
    """``c1 --k 1:K`` at boundary and corner vertices (``K = 1000``; ``quick``: 100, BLZ's 1:24), beside the dense test at
    k = 1..8."""
    top, limit, small = (100, None, range(1, 7)) if quick else (1000, 60.0, range(1, 9))
    blz = 24 if quick else top
    rows = []
    for scheme, vertex, last in (("catmull-clark", "boundary", top), ("catmull-clark", "corner", top), ("loop", "boundary", top),
                                 ("loop", "corner", top), ("catmull-clark-blz", "boundary", blz),
                                 ("catmull-clark-blz", "corner", blz), ("loop-blz", "boundary", blz)):
        rows.append({"target": f"c1 --{vertex} --k 1:{last} --scheme {scheme}", "limit_seconds": limit,
                     "seconds": _seconds("c1", f"--{vertex}", "--k", f"1:{last}", "--scheme", scheme, "--quiet",
                                         codes=(0, 1)),
                     "baseline": f"dense test, {vertex} k = {small.start}..{small.stop - 1}",
                     "baseline_seconds": _dense_c1_seconds(scheme, vertex, small)})
    return rows


def check_targets(quick: bool = False) -> list[dict]:
    """``check --k`` past the dense route's 64 faces, beside the dense route at its largest vertex (``quick``: k = 1000,
    the range 1:50, the dense route at k = 24)."""
    top, span, small = (1000, 50, 24) if quick else (10_000, 200, 64)
    dense = _seconds("check", "--k", str(small), "--boundary", "--certify", "--route", "charpoly", "--quiet")
    dense_numeric = _seconds("check", "--k", str(small), "--boundary", "--quiet", "--jobs", "1")
    rows = []
    for argv, baseline in (
            (["--k", str(top), "--boundary", "--certify"], dense),
            (["--k", str(top), "--boundary", "--certify", "--scheme", "catmull-clark-blz"], dense),
            (["--k", str(top - 3), "--crease", "3", "--certify", "--scheme", "loop-blz"], dense),  # K + K2 = top faces
            (["--k", f"1:{span}", "--corner", "--certify", "--scheme", "catmull-clark-blz"], dense),
            (["--k", str(top), "--boundary"], dense_numeric)):
        numeric = "--certify" not in argv
        rows.append({"target": "check " + " ".join(argv), "limit_seconds": None, "seconds": _seconds("check", *argv, "--quiet"),
                     "baseline": f"check --k {small} --boundary" + ("" if numeric else " --certify --route charpoly")
                     + (" (dense eigenvalues)" if numeric else " (dense route)"), "baseline_seconds": baseline})
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="k = 200 and the dense route at k = 6, for a smoke run")
    parser.add_argument("--check", action="store_true", help="only check --k's rows")
    parser.add_argument("--c1", action="store_true", help="only c1 --k's rows")
    args = parser.parse_args(argv)
    if args.check and args.c1:
        parser.error("--check and --c1 cannot be used together: give one part, or neither for every target")
    part = check_targets if args.check else c1_targets if args.c1 else targets
    for row in part(args.quick):
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main())
