"""The evaluation-data files beyond Stam's: a sector's (``sector-evaldata``) and a dual scheme's faces' (``dual-evaldata``).

``evaldata --crease --k A:B``, and ``--boundary``/``--corner`` under rules with a modified near-edge rule (BLZ's),
write the sector evaluation data (:mod:`symdecomp.output.sector_evaldata`, format ``sector-evaldata``): for each
``K`` in the range, the crease vertex with ``K`` faces on each side, or the boundary or corner vertex with ``K``
faces; exact rationals where the rules are rational there, else Arb balls. ``--json``: ``{"out", "format",
"scheme", "kind", "k", "bytes", "sizes", "exact"}``.

``evaldata --n A:B --scheme doo-sabin``: a dual quad scheme of the zoo whose regular part is the biquadratic B-spline
(Doo-Sabin, a user's variant as a file) gets, for each ``n`` in the range, the data of its extraordinary faces,
:mod:`symdecomp.analysis.dual_evaldata`, as JSON (format ``dual-evaldata``, :mod:`symdecomp.output.dual_evaldata`):
exact rationals where the rules are rational at ``n``, else Arb balls. Any other scheme of the zoo gets one line
saying why the data do not apply (:func:`~symdecomp.analysis.dual_evaldata.spline_reason`), exit code 2.
``--json``: ``{"out", "format", "scheme", "n", "bytes", "sizes", "exact", "jordan"}`` (``jordan``: the ``n`` whose
matrix is not diagonalizable).

Either file is checked before the work and replaced atomically (:mod:`symdecomp.cli.files`).
"""

from __future__ import annotations

import argparse
from collections.abc import Iterator

from symdecomp.cli.common import given, print_json, progress
from symdecomp.cli.element import sector_vertex
from symdecomp.cli.evaldata_plot import EigenvaluesDrawn, block_values
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.cli.plot_file import PlotTarget
from symdecomp.errors import EvalDataFileError, InvalidInputError, NotApplicableError

__all__ = ["run_sector", "run_dual", "MAX_CREASE_FACES", "MAX_DUAL_SIDES"]

#: Most faces on each side of a crease: its 2-ring has 12K + 1 points and the exact decomposition grows like their
#: cube (K = 12: 7 s, K = 32: minutes).
MAX_CREASE_FACES = 32

#: Most sides of the extraordinary face: its control points are 9n (n = 32: a few seconds per face with balls).
MAX_DUAL_SIDES = 32


def _numbers(exact: list[bool]) -> str:
    """Whether the file holds exact rationals, Arb balls or both, in words."""
    return "exact rationals" if all(exact) else ("Arb balls" if not any(exact) else "exact rationals and Arb balls")


def run_sector(args: argparse.Namespace, kind: str, plot: PlotTarget | None = None) -> int:
    """Write the sector evaluation data of the vertices ``kind`` with ``args.faces`` faces (module docstring)."""
    from symdecomp.analysis.sector_evaldata import sector_evaldata
    from symdecomp.output.sector_evaldata import SECTOR_FORMAT, sector_entry, sector_json_chunks

    scheme, ks, lat = args.scheme, args.faces, args.scheme.lattice
    if kind == "crease" and ks[0] < 2:
        raise InvalidInputError(f"--k {ks[0]}: a crease vertex with K faces on each side needs K >= 2 (3 or more faces "
                                "around an interior vertex)")
    if kind == "crease" and ks[-1] > MAX_CREASE_FACES:
        raise InvalidInputError(f"--k {ks[-1]}: --crease takes at most {MAX_CREASE_FACES} faces on each side (the exact "
                                "eigen-decomposition of its 2-ring of 12K + 1 points grows like the cube of K)")
    vertices = [sector_vertex(kind, (k, k) if kind == "crease" else k, lat) for k in ks]  # a crease: K faces on each side
    check_output_file(args.out)
    sizes: list[int] = []
    exact: list[bool] = []
    drawn = EigenvaluesDrawn(plot)

    def entries() -> Iterator[dict[str, object]]:
        for k, vertex in zip(ks, progress(vertices, len(vertices), "evaldata", enabled=not args.quiet)):
            data = sector_evaldata(scheme, vertex)
            sizes.append(data.size)
            exact.append(data.exact)
            drawn.add(k, block_values, data.decomposition)
            yield sector_entry(data)

    size = write_output_file(args.out, sector_json_chunks(entries(), scheme.name, lat.name))
    drawn.write("K (faces" + (" on each side)" if kind == "crease" else ")"),
                f"{scheme.name}, {kind} vertices: eigenvalues of the decomposition written")
    if args.json:
        print_json(args, {"out": args.out, "format": SECTOR_FORMAT, "scheme": scheme.name, "kind": kind, "k": ks,
                          "bytes": size, "sizes": sizes, "exact": exact})
    else:
        print(f"wrote {args.out}: {SECTOR_FORMAT} ({scheme.name}), {kind} vertices with K = {ks[0]}..{ks[-1]} faces"
              f"{' on each side' if kind == 'crease' else ''}, {size} bytes ({_numbers(exact)}; control points: the closed "
              f"2-ring, {sizes[0]}..{sizes[-1]} points)")
    return 0


def _check_options(args: argparse.Namespace) -> list[int]:
    """The faces' sizes; an option that does not apply is refused in one line."""
    name = args.scheme.name
    for option in ("boundary", "corner", "crease", "faces"):
        if given(args, option):
            flag = "--k" if option == "faces" else f"--{option}"
            raise InvalidInputError(f"{flag}: the evaluation data of --scheme {name} (a scheme of the zoo) are for its "
                                    "extraordinary faces, --n A:B")
    if not given(args, "n"):
        raise InvalidInputError(f"--scheme {name}: give --n A:B, the sides of the extraordinary faces")
    for option in ("digits", "jobs", "executor"):
        if given(args, option):
            raise InvalidInputError(f"--{option} does not apply to --scheme {name}: its data are exact rationals or Arb "
                                    "balls, computed in this process")
    if args.format == "binary" and given(args, "format"):
        raise EvalDataFileError(f"--format binary: the binary layout is Stam's Catmull-Clark file; --scheme {name} writes json")
    if args.n[-1] > MAX_DUAL_SIDES:
        raise InvalidInputError(f"--n {args.n[-1]}: --scheme {name} takes faces of at most {MAX_DUAL_SIDES} sides (9n control "
                                "points each)")
    return list(args.n)


def run_dual(args: argparse.Namespace, plot: PlotTarget | None = None) -> int:
    """Write the evaluation data of the zoo scheme ``args.scheme``'s faces of ``args.n`` sides (module docstring)."""
    from symdecomp.analysis.dual_evaldata import dual_evaldata, spline_reason
    from symdecomp.output.dual_evaldata import DUAL_FORMAT, dual_entry, dual_json_chunks

    scheme = args.scheme
    ns = _check_options(args)
    reason = spline_reason(scheme)
    if reason is not None:
        raise NotApplicableError(f"evaldata: {reason}")
    check_output_file(args.out)
    sizes: list[int] = []
    exact: list[bool] = []
    jordan: list[int] = []
    drawn = EigenvaluesDrawn(plot)

    def entries() -> Iterator[dict[str, object]]:
        for n in progress(ns, len(ns), "evaldata", enabled=not args.quiet):
            data = dual_evaldata(scheme, n)
            sizes.append(data.size)
            exact.append(data.exact)
            drawn.add(n, block_values, data.decomposition)
            if data.decomposition is not None and any(b.eigenvectors < b.multiplicity for b in data.decomposition):
                jordan.append(n)
            yield dual_entry(data)

    size = write_output_file(args.out, dual_json_chunks(entries(), scheme.name, scheme.lattice))
    drawn.write("n (sides of the face)", f"{scheme.name}: eigenvalues of the decomposition written, faces of n sides")
    if args.json:
        print_json(args, {"out": args.out, "format": DUAL_FORMAT, "scheme": scheme.name, "n": ns, "bytes": size,
                          "sizes": sizes, "exact": exact, "jordan": jordan})
        return 0
    print(f"wrote {args.out}: {DUAL_FORMAT} ({scheme.name}), faces with n = {ns[0]}..{ns[-1]} sides, {size} bytes ({_numbers(exact)}; "
          f"control points: the face and two rings of faces, {sizes[0]}..{sizes[-1]} points)")
    if jordan:
        print(f"not diagonalizable at n = {', '.join(map(str, jordan))}: the decomposition over Q holds their Jordan blocks")
    return 0
