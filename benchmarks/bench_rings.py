"""Time the any-scheme route (Catmull-Clark and Loop) against the issue's targets, in one run.

For each scheme: the structural certificate for n = 3..256 (one process), the dense FLINT
characteristic polynomial of the *same* matrices (the certificate of ``check --certify``
without ``--structural``) over a shorter range, one valence n = 1000 certified (time and the
process's peak memory), and ``spectrum`` and ``masks`` at n = 1000 (for Catmull-Clark also by
the closed forms, the route ``symdecomp spectrum 1000`` and ``symdecomp masks 1000`` take). Times are CPU seconds of
this process (the machine may be shared) and wall seconds. Run from the repository root:

    python benchmarks/bench_rings.py            # dense comparison up to n = 96
    python benchmarks/bench_rings.py --quick    # a smoke run
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from symdecomp.analysis.masks import (
    limit_masks_at,  # noqa: E402
    ring_masks,  # noqa: E402
)
from symdecomp.analysis.spectrum import (
    closed_form_spectrum,  # noqa: E402
    ring_spectrum,  # noqa: E402
)
from symdecomp.schemes.full_matrix import entries_characteristic_polynomial  # noqa: E402
from symdecomp.schemes.loop import loop  # noqa: E402
from symdecomp.schemes.rings import ring_subdivision_matrix  # noqa: E402
from symdecomp.schemes.scheme import catmull_clark  # noqa: E402
from symdecomp.verify.certify import certify_ring  # noqa: E402

#: The issue's targets (seconds, megabytes).
TARGETS = {"certify 3..256": 60.0, "certify n=1000": 60.0, "memory n=1000 (MB)": 2048.0, "spectrum n=1000": 2.0, "masks n=1000": 2.0,
           "default spectrum n=1000": 2.0, "default masks n=1000": 2.0}


def timed(f, *args, **kwargs):
    wall, cpu = time.perf_counter(), time.process_time()
    out = f(*args, **kwargs)
    return time.process_time() - cpu, time.perf_counter() - wall, out


def dense(scheme, valences):
    """The dense FLINT characteristic polynomials of the refined matrices (rational centre weights at 0 if algebraic)."""
    for n in valences:
        S = ring_subdivision_matrix(scheme, n, 1)
        entries_characteristic_polynomial(S.entries({s: 0 for s in S.weights}), S.size)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small ranges (a smoke run)")
    parser.add_argument("--dense-max", type=int, default=96, help="largest n of the dense comparison (default 96)")
    args = parser.parse_args(argv)
    top, big, dense_max = (32, 200, 16) if args.quick else (256, 1000, args.dense_max)
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f}; "
          "times: CPU s (wall s)")
    ok = True
    for scheme in (catmull_clark(), loop()):
        certify_ring(scheme, 5, 1, method="structure")  # the one-time symbolic step
        rows = []
        cpu, wall, results = timed(lambda s=scheme: [certify_ring(s, n, 1, method="structure") for n in range(3, top + 1)])
        assert all(r.ok for r in results)
        rows.append((f"certify 3..{top}", cpu, wall))
        d_cpu, d_wall, _ = timed(dense, scheme, range(3, dense_max + 1))
        s_cpu, s_wall, _ = timed(lambda s=scheme: [certify_ring(s, n, 1, method="structure") for n in range(3, dense_max + 1)])
        cpu, wall, r = timed(certify_ring, scheme, big, 1, method="structure")
        assert r.ok
        rows.append((f"certify n={big}", cpu, wall))
        memory = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        cpu_s, wall_s, _ = timed(ring_spectrum, scheme, big, 1, digits=20, exact=False)
        rows.append((f"spectrum n={big}", cpu_s, wall_s))
        cpu_m, wall_m, _ = timed(ring_masks, scheme, big, 1, digits=20)
        rows.append((f"masks n={big}", cpu_m, wall_m))
        if scheme.mesh == "quad":  # the commands' default route for the paper's 1-ring: the closed forms
            rows.append((f"default spectrum n={big}", *timed(closed_form_spectrum, scheme, big, digits=20)[:2]))
            rows.append((f"default masks n={big}", *timed(lambda s=scheme: limit_masks_at(s, big).as_json(20))[:2]))
        print(f"\n{scheme.name} (1-ring)")
        for label, cpu, wall in rows:
            target = TARGETS.get(label.replace(str(top), "256").replace(str(big), "1000"))
            verdict = "" if args.quick or target is None else ("  ok" if cpu <= target else f"  OVER the {target:g} s target")
            ok &= not verdict.startswith("  OVER")
            print(f"  {label:<24} {cpu:8.2f} s ({wall:.2f} s){verdict}")
        print(f"  peak memory of the process: {memory:.0f} MB (target 2048 MB)")
        print(f"  n = 3..{dense_max}: dense FLINT charpoly of the same matrices {d_cpu:8.2f} s ({d_wall:.2f} s), "
              f"structural certificate {s_cpu:.2f} s ({s_wall:.2f} s): {d_cpu / s_cpu:.1f}x")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
