"""Time the zoo at large n: ``spectrum 64`` and ``check --certify`` at n = 10,000, beside the explicit route.

The targets (issue 30): ``spectrum 64 --scheme S`` in a few seconds for each family of the zoo, and
``check --n 10000 --certify`` per scheme. Measured: the whole command as a user runs it (start-up included),
wall-clock, which takes the structural route (the blocks read once, ``analysis/zoo_structure``). Beside it, the
baseline measured in the same run: the explicit route (the matrix built by refinement at that valence, its blocks
read and factored there), forced by giving the neighbourhood's depth. The explicit route cannot reach n = 10,000
(``O(n^2)`` entries), so the certificate's baseline is the explicit certificate at n = 64.

    python benchmarks/bench_zoo.py            # n = 64 (the explicit baseline takes minutes for Doo-Sabin)
    python benchmarks/bench_zoo.py --quick    # n = 32, and the certificate at n = 1000
"""

from __future__ import annotations

from _targets import main_with_quick, timed

#: The issue's targets, seconds per scheme.
SPECTRUM_SECONDS = 10.0
CERTIFY_SECONDS = 10.0
SCHEMES = ("doo-sabin", "midedge", "sqrt3", "modified-butterfly")

_EXPLICIT = """
import sys
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.schemes.stencil_files import load_zoo
scheme, n, what = load_zoo(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
depth = zoo_matrix(scheme, n).depth
if what == "spectrum":
    from symdecomp.analysis.zoo_spectrum import zoo_spectrum
    zoo_spectrum(scheme, n, depth)
else:
    from symdecomp.verify.certify import certify_zoo
    assert certify_zoo(scheme, n, depth).status.value == "agree"
"""


def targets(quick: bool = False) -> list[dict]:
    """``spectrum N`` and ``check --n M --certify`` per scheme, beside the explicit route."""
    n, big = (32, 1000) if quick else (64, 10_000)
    out = []
    for name in SCHEMES:
        seconds = timed("-m", "symdecomp", "spectrum", str(n), "--scheme", name, "--json")
        baseline = timed("-c", _EXPLICIT, name, str(n), "spectrum")
        out.append({"target": f"spectrum {n} --scheme {name}", "limit_seconds": SPECTRUM_SECONDS if not quick else None,
                    "seconds": seconds, "baseline": f"the explicit route at n = {n}", "baseline_seconds": baseline})
        seconds = timed("-m", "symdecomp", "check", "--n", str(big), "--certify", "--scheme", name, "--json")
        baseline = timed("-c", _EXPLICIT, name, str(n), "certify")
        out.append({"target": f"check --n {big} --certify --scheme {name}", "limit_seconds": CERTIFY_SECONDS if not quick else None,
                    "seconds": seconds, "baseline": f"the explicit certificate at n = {n}", "baseline_seconds": baseline})
    return out


def main() -> None:
    main_with_quick(__doc__, targets, "n = 32 and the certificate at n = 1000")


if __name__ == "__main__":
    main()
