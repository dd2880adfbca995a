"""``evaldata --crease --k A:B``, and ``--boundary``/``--corner`` under rules with a modified near-edge rule (BLZ's).

Writes the sector evaluation data (:mod:`symdecomp.output.sector_evaldata`, format ``sector-evaldata``): for each
``K`` in the range, the crease vertex with ``K`` faces on each side, or the boundary or corner vertex with ``K``
faces; exact rationals where the rules are rational there, else Arb balls. The file is checked before the work
and replaced atomically (:mod:`symdecomp.cli.files`). ``--json``: ``{"out", "format", "scheme", "kind", "k",
"bytes", "sizes", "exact"}``.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterator

from symdecomp.cli.common import print_json, progress
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.errors import InvalidInputError

__all__ = ["run_sector", "MAX_CREASE_FACES"]

#: Most faces on each side of a crease: its 2-ring has 12K + 1 points and the exact decomposition grows like their
#: cube (K = 12: 7 s, K = 32: minutes).
MAX_CREASE_FACES = 32


def run_sector(args: argparse.Namespace, kind: str) -> int:
    """Write the sector evaluation data of the vertices ``kind`` with ``args.faces`` faces (module docstring)."""
    from symdecomp.analysis.sector_evaldata import sector_evaldata
    from symdecomp.output.sector_evaldata import SECTOR_FORMAT, sector_entry, sector_json_chunks
    from symdecomp.schemes.sector import SharpVertex

    scheme, ks, lat = args.scheme, args.faces, args.scheme.lattice
    if kind == "crease" and ks[0] < 2:
        raise InvalidInputError(f"--k {ks[0]}: a crease vertex with K faces on each side needs K >= 2 (3 or more faces "
                                "around an interior vertex)")
    if kind == "crease" and ks[-1] > MAX_CREASE_FACES:
        raise InvalidInputError(f"--k {ks[-1]}: --crease takes at most {MAX_CREASE_FACES} faces on each side (the exact "
                                "eigen-decomposition of its 2-ring of 12K + 1 points grows like the cube of K)")
    vertices = [SharpVertex.crease(k, k, lat) if kind == "crease" else getattr(SharpVertex, kind)(k, lat) for k in ks]
    check_output_file(args.out)
    sizes: list[int] = []
    exact: list[bool] = []

    def entries() -> Iterator[dict[str, object]]:
        for vertex in progress(vertices, len(vertices), "evaldata", enabled=not args.quiet):
            data = sector_evaldata(scheme, vertex)
            sizes.append(data.size)
            exact.append(data.exact)
            yield sector_entry(data)

    size = write_output_file(args.out, sector_json_chunks(entries(), scheme.name, lat.name))
    if args.json:
        print_json(args, {"out": args.out, "format": SECTOR_FORMAT, "scheme": scheme.name, "kind": kind, "k": ks,
                          "bytes": size, "sizes": sizes, "exact": exact})
    else:
        numbers = "exact rationals" if all(exact) else ("Arb balls" if not any(exact) else "exact rationals and Arb balls")
        print(f"wrote {args.out}: {SECTOR_FORMAT} ({scheme.name}), {kind} vertices with K = {ks[0]}..{ks[-1]} faces"
              f"{' on each side' if kind == 'crease' else ''}, {size} bytes ({numbers}; control points: the closed "
              f"2-ring, {sizes[0]}..{sizes[-1]} points)")
    return 0
