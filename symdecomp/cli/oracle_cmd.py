"""``symdecomp oracle --n 3:12 [--scheme loop]``: the toolkit's Catmull-Clark or Loop predictions checked against OpenSubdiv.

``symdecomp oracle --kind boundary,corner,crease,dart --k 1:12 --sharpness 0,1/2,1,5/2,inf``: the same at
boundary, corner, crease and dart vertices (:mod:`symdecomp.verify.oracle`).

``symdecomp oracle --mesh FILE``: the limit position and normal of every analysed vertex of a mesh file (with its
crease and corner tags), as ``symdecomp inspect`` computes them, against OpenSubdiv's limit masks, to 1e-12
(:mod:`symdecomp.verify.oracle_mesh`; darts apart: OpenSubdiv gives them the smooth limit mask). The scheme is the
mesh's (Catmull-Clark for quads and mixed meshes, after its first exact step; Loop for triangles) unless
``--scheme`` names one.

``--plot FILE`` (valences, not ``--kind`` nor ``--mesh``): the printed comparisons drawn
(:mod:`symdecomp.output.plotting.oracle_chart`): each limit row's disagreement level by level against its predicted
rate, and the exact rows against double precision's epsilon. The target is checked before any work, and the figure
written once the comparisons are done: without the OpenSubdiv bridge no file is written.
"""

from __future__ import annotations

import argparse
import math
import re
from fractions import Fraction

from symdecomp.cli.common import LIMITS, Once, add_scheme_option, flag, integer, print_json, progress, valence_range
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError, UnavailableError


def register(sub) -> None:
    p = sub.add_parser(
        "oracle",
        help="compare the toolkit's predictions with OpenSubdiv's Catmull-Clark or Loop refinement",
        description="For each valence, push a random 1-ring in R^3 through OpenSubdiv (uniform "
        "Catmull-Clark, double precision) and print the largest disagreement of each prediction: the "
        "one-step subdivision matrix, 1-ring locality, the limit mask, the limit position, the shrink "
        "rate of every frequency (Eq. 34; Eq. 43 for j = 0; j = 2 is the hyperbolic decay), the ratio "
        "B^1/A^1 (Eq. 39) and the elliptic ratio (Eq. 44). 'exact' rows should agree to double "
        "precision; 'limit' rows converge, the disagreement shrinking by the stated rate per level. "
        "With --scheme loop: OpenSubdiv's Loop scheme against the one-step matrix, the spectrum, the limit "
        "position and tangent masks and the shrink rate of every frequency. "
        "Needs the OpenSubdiv bridge (built on demand with g++ if libosd-dev is installed).",
    )
    add_scheme_option(p)
    p.add_argument("--n", type=valence_range("oracle"), action=Once, default=list(range(3, 13)), metavar="A:B",
                   help="valence or inclusive range of valences (default 3:12, at most 64)")
    p.add_argument("--levels", type=_levels, action=Once, default=20, metavar="K",
                   help=f"refinement levels run in OpenSubdiv (default 20; 2 <= K <= {LIMITS['levels'][0]})")
    p.add_argument("--seed", type=_seed, action=Once, default=0, help="seed of the random 1-rings (default 0; 0 <= seed < 2^32)")
    p.add_argument("--kind", type=_kinds, action=Once, default=None, metavar="LIST",
                   help="compare at sharp vertices instead: a comma list of boundary, corner, crease, dart (or all); "
                        "every boundary interpolation and creasing method where they differ")
    flag(p, "--boundary", help="short for --kind all")
    p.add_argument("--mesh", dest="mesh_file", action=Once, default=None, metavar="FILE",
                   help="compare the limit positions and normals of every analysed vertex of this mesh file (OBJ with "
                   "OpenSubdiv's tags, OFF, PLY) with OpenSubdiv's limit masks, to 1e-12")
    p.add_argument("--k", type=_k_range, action=Once, default=list(range(1, 13)), metavar="A:B",
                   help="with --kind: faces per sector, one or an inclusive range (default 1:12, at most 16)")
    p.add_argument("--sharpness", type=_sharpness_list, action=Once, default=None, metavar="LIST",
                   help="with --kind: crease and dart sharpness values, comma list of numbers (1/2, 2.5) and inf "
                        "(default 0,1/2,1,5/2,inf; finite values below 10)")
    p.add_argument("--creasing", choices=("uniform", "chaikin", "both"), action=Once, default="both",
                   help="with --kind: OpenSubdiv's creasing method for semi-sharp creases (default both)")
    flag(p, "--json",
                   help='print [{"n", "levels", "seed", "agrees", "predictions": [{"name", "kind", "predicted", '
                        '"observed", "disagreement", "rate", "observed_rate", "agrees", "per_level": [{"level", '
                        '"disagreement"}] (a limit row\'s disagreement at each level compared, as --plot draws it)}]}]; '
                        'with --kind '
                        '[{"scheme", "kind", "k", "sharpness", "boundary", "creasing", "level", "agrees", '
                        '"checks": [{"name", "disagreement", "comparable", "agrees", "note"}]}]')
    add_quiet_option(p)
    add_plot_option(p, "the comparisons of --n: for each 'limit' row its largest disagreement at every level on a log "
                    "axis, one line per valence, beside the predicted shrink rate as a dashed reference line; the 'exact' "
                    "rows as bars in units of double precision's epsilon, with their tolerance (not with --kind or --mesh)")
    p.set_defaults(func=run)


_KINDS = ("boundary", "corner", "crease", "dart")


def _kinds(text: str) -> tuple[str, ...]:
    names = [t.strip() for t in text.split(",")]
    if names == ["all"]:
        return _KINDS
    bad = [n for n in names if n not in _KINDS]
    if bad or not names:
        raise argparse.ArgumentTypeError(f"--kind takes a comma list of {', '.join(_KINDS)} (or all), got {text!r}")
    return tuple(dict.fromkeys(names))


def _k_range(text: str) -> list[int]:
    lo, sep, hi = text.partition(":")
    a = integer(lo, "--k", minimum=1)
    b = integer(hi, "--k", minimum=1) if sep else a
    if b < a or b > 16:
        raise argparse.ArgumentTypeError(f"--k must be K or A:B with 1 <= A <= B <= 16, got {text!r}")
    return list(range(a, b + 1))


def _sharpness_list(text: str) -> tuple:
    values = []
    for item in text.split(","):
        item = item.strip()
        if item == "inf":
            values.append(math.inf)
        elif re.fullmatch(r"\d{1,6}(\.\d{1,6})?(/[1-9]\d{0,5})?", item) and Fraction(item) < 10:
            values.append(Fraction(item))
        else:
            raise argparse.ArgumentTypeError(f"--sharpness takes numbers in [0, 10) such as 1/2 or 2.5, and inf; got {item!r}")
    return tuple(dict.fromkeys(values))


def _levels(text: str) -> int:
    return integer(text, "--levels", minimum=2, limit="levels")


def _seed(text: str) -> int:
    value = integer(text, "--seed", minimum=0)
    if value >= 2**32:
        raise argparse.ArgumentTypeError(f"--seed must be below 2^32, got {value}")
    return value


def _comparison(scheme):
    """The comparison for ``scheme``: OpenSubdiv has Catmull-Clark and Loop with their standard weights only."""
    from symdecomp.schemes.loop import loop
    from symdecomp.schemes.scheme import catmull_clark

    def rules(s):
        return (s.lattice, s.edge_rule, s.face_rule, s.vertex_rule)

    if rules(scheme) in (rules(catmull_clark()), rules(loop())):
        from symdecomp.verify.oracle import comparison

        return comparison(scheme.lattice)
    raise InvalidInputError(f"--scheme {scheme.name}: OpenSubdiv implements Catmull-Clark and Loop with their standard "
                            "weights only; this scheme's rules are neither")


def run(args) -> int:
    from symdecomp.verify.opensubdiv import load_bridge

    kinds = _KINDS if args.boundary else args.kind
    if kinds is None and args.sharpness is not None:
        raise InvalidInputError("--sharpness: needs --kind or --boundary (it sets the sharpness of sharp vertices)")
    compare = _comparison(args.scheme)
    if args.plot is not None and (kinds is not None or args.mesh_file is not None):
        raise InvalidInputError(f"--plot: draws the comparisons of --n; not with {'--mesh' if args.mesh_file else '--kind'}")
    plot = check_plot(args)
    load_bridge()  # BridgeUnavailableError: main() prints the one error line and exits with 3
    if args.mesh_file is not None:
        return _run_mesh(args)
    if kinds is not None:
        return _run_sharp(args, kinds)
    results = [compare(n, args.levels, args.seed) for n in progress(args.n, len(args.n), "oracle", enabled=not args.quiet)]
    if args.json:
        print_json(args, [r.as_json() for r in results])
    else:
        for r in results:
            print(f"n = {r.n}  ({r.levels} levels, seed {r.seed}): {'all agree' if r.agrees else 'DISAGREEMENT'}")
            for p in r.predictions:
                rate = "" if p.rate is None else f"  rate {p.rate:.4f}"
                seen = "" if p.observed_rate is None else f" (seen {p.observed_rate:.4f})"
                flag = "" if p.agrees else "  <-- disagrees"
                print(f"  {p.name:<30} {p.kind:<5} {p.disagreement:9.2e}{rate}{seen}{flag}")
    write_plot(plot, lambda: _figure(args, results))
    return 0 if all(r.agrees for r in results) else 1


def _figure(args, results):
    """``oracle --plot``: the comparisons as printed (:mod:`symdecomp.output.plotting.oracle_chart`)."""
    from symdecomp.output.plotting.oracle_chart import oracle_figure

    ns = f"{results[0].n}" if len(results) == 1 else f"{results[0].n}..{results[-1].n}"
    return oracle_figure(results, f"{args.scheme.name} against OpenSubdiv, n = {ns} (seed {args.seed}, {args.levels} levels)")


def _run_mesh(args) -> int:
    from symdecomp.cli.common import given
    from symdecomp.cli.inspect_cmd import prepare_mesh
    from symdecomp.schemes.meshformats import read_mesh
    from symdecomp.verify.oracle_mesh import compare_mesh

    if args.kind is not None or args.boundary:
        raise InvalidInputError("--mesh: not with --kind or --boundary (the mesh's own vertices are compared)")
    original = read_mesh(args.mesh_file)
    scheme, mesh, _ = prepare_mesh(args.scheme if given(args, "scheme") else None, original)
    r = compare_mesh(mesh, scheme)
    if args.json:
        print_json(args, r.as_json())
    else:
        print(f"{original.name}: {scheme.name}, {r.compared} vertices compared with OpenSubdiv's limit masks "
              f"({r.levels} levels first): {'all agree' if r.agrees else 'DISAGREEMENT'} (tolerance {r.tolerance:.0e})")
        print(f"  {'limit position':<16} {r.position_disagreement:9.2e}  (relative to the mesh's size; worst at vertex "
              f"{r.worst_position_vertex})")
        print(f"  {'unit normal':<16} {r.normal_disagreement:9.2e}  (worst at vertex {r.worst_normal_vertex}; "
              f"{r.normals_skipped} vertices not compared: a crease's two sides, or no certified tangent plane)")
        if r.biermann:
            print(f"  {r.biermann} boundary vertices of more faces than a regular one: normals apart, OpenSubdiv's cross tangent there is "
                  f"Biermann et al.'s, not its surface's (they differ by {r.biermann_normal_disagreement:.2e})")
        if r.rounded_tags:
            print(f"  {r.rounded_tags} sharpness tags not exact in single precision: both sides given OpenSubdiv's float")
        if r.single_precision:
            print(f"  {r.single_precision} vertices whose rule changes with a weight not exact in single precision: positions "
                  f"apart, to 1e-6 (they differ by {r.single_precision_disagreement:.2e})")
        if r.darts:
            print(f"  {r.darts} dart vertices apart: OpenSubdiv's limit mask there is the smooth one, not the dart's "
                  f"eigenvector (they differ by {r.dart_position_disagreement:.2e})")
    return 0 if r.agrees else 1


def _run_sharp(args, kinds) -> int:
    from symdecomp.verify.oracle import SHARPNESS, compare_sharp_case, sharp_cases

    try:
        import symdecomp.schemes.sector  # noqa: F401  (the toolkit's side of the comparison)
    except ModuleNotFoundError:  # main() prints the one error line and exits with 3
        raise UnavailableError("--kind needs the sharp vertex model (symdecomp.schemes.sector), not in this build") from None

    scheme = args.scheme.lattice.reference().name  # _comparison checked the rules
    cases = [c for c in sharp_cases(scheme, kinds, args.k, args.sharpness or SHARPNESS)
             if args.creasing in ("both", c.creasing)]
    results = [r for case in progress(cases, len(cases), "oracle", enabled=not args.quiet) for r in compare_sharp_case(case, seed=args.seed)]
    if args.json:
        print_json(args, [r.as_json() for r in results])
    else:
        for r in results:
            worst = max((c for c in r.checks if c.comparable), key=lambda c: c.disagreement)
            bad = [c.name for c in r.checks if not c.agrees]
            verdict = "agrees" if r.agrees else "DISAGREES: " + ", ".join(f"{c.name} {c.disagreement:.2e}" for c in r.checks if not c.agrees)
            print(f"{r.case.label()} level {r.level}: {verdict if bad else f'{verdict} (largest {worst.name} {worst.disagreement:.1e})'}")
    return 0 if all(r.agrees for r in results) else 1
