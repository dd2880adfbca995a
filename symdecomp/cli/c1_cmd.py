"""``symdecomp c1 --n 3:64``: Reif's sufficient test for C1 at an extraordinary vertex, certified, per valence.

``symdecomp c1 --every-n`` (or an open range ``--n 3:``): C1 for every valence as far as it is shown
(:mod:`symdecomp.verify.c1_every_n`): the spectral conditions proved for every n, Reif's test at n = 3..64, and the
characteristic map proved regular and injective for every n by exact signs in cos(2 pi/n) where that closes.

``symdecomp c1 --boundary --k 1:16`` (``--corner``, ``--crease K1,K2``): Zorin's conditions at boundary, corner and
crease vertices (:mod:`symdecomp.verify.c1_sector_matrix`), per number of faces ``k``, with the scheme's ``[sharp]`` rules.
"""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, NamedTuple

from symdecomp.cli.common import (
    LIMITS,
    Once,
    add_pool_options,
    add_scheme_option,
    flag,
    given,
    integer,
    print_json,
    progress,
    valence_range,
)
from symdecomp.cli.element import named_element, route, sector_vertex, sharpness
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError

if TYPE_CHECKING:
    from symdecomp.schemes.scheme import Scheme
    from symdecomp.verify.c1_zorin_every_n import FrequencyPolynomials
    from symdecomp.verify.result import C1Verdict

__all__ = ["register", "run"]

#: The valences Reif's test certifies one by one under --every-n (beyond them the characteristic map is proved in
#: cos(2 pi/n) where the exact signs close, else open).
EVERY_N_CERTIFIED = 64

#: The same for a dual scheme of the zoo (Doo-Sabin): its test at one valence costs more than O(n) (the engine's exact
#: spectrum of the ring around the n-gon); the proof for every n starts at n = 16 (the blocks' reading), the valences
#: above it are a cross-check.
ZOO_EVERY_N_CERTIFIED = 32

#: The same for a primal scheme of the zoo (the modified butterfly): Zorin's test per valence, up to the first valence
#: of the structural blocks its spectral conditions for every n are read from.
ZORIN_EVERY_N_CERTIFIED = 16

#: --every-n's help.
EVERY_N_HELP = (
    "C1 for every valence: the spectral conditions as statements in t = cos(2 pi j/n) decided for every n "
    f"(Sturm sequences, the exact tail bound of Proposition 5.1), Reif's test at n = 3..{EVERY_N_CERTIFIED}, the "
    "characteristic map regular and injective for every n by exact signs of its nets in cos(2 pi/n) (a dual scheme of "
    "the zoo with the biquadratic regular part, e.g. doo-sabin: the n-gon's weights' symbol for every n, the dual test "
    f"at n = 3..{ZOO_EVERY_N_CERTIFIED}; a primal one, e.g. modified-butterfly: the blocks' characteristic polynomials "
    f"by the Schur-Cohn test in cos(2 pi k/n), Zorin's test at n = 3..{ZORIN_EVERY_N_CERTIFIED}, the map not proved for "
    "every n); says which part is proved, verified or open, and the first valence where C1 "
    "fails (--json: the steps)"
)

#: How a verdict is printed (by its value, so that the table needs no import of the verify layer).
LABELS = {"c1": "C1 certified", "not-c1": "not C1", "undecided": "undecided"}


def _depth(text: str) -> int:
    """argparse type: a subdivision depth, 0 to 12."""
    return integer(text, "--depth", minimum=0, limit="c1 --depth")


def register(sub) -> None:
    p = sub.add_parser(
        "c1",
        help="certify C1 at an extraordinary vertex (Reif's test on the characteristic map)",
        description="For each valence: Reif's spectral conditions (eigenvalue 1 simple; the subdominant "
        "eigenvalue real, double, non-defective, strictly dominant), then regularity of the characteristic "
        "map (the Jacobian of its sub-patches, bicubic for Catmull-Clark-type and quartic box-spline for "
        "Loop-type schemes, in Bernstein-Bezier form, all coefficients of one sign, "
        "in interval arithmetic with de Casteljau subdivision) and injectivity (winding number 1 of the "
        "ring's inner boundary). Prints 'C1 certified', 'not C1' with the failing condition, or "
        "'undecided' with what would decide it. Exit status 1 unless every valence is certified C1. "
        "With --boundary or --corner (and --k A:B) or --crease K1,K2: Zorin's conditions at sharp vertices, per "
        "sector between sharp edges: the sector's exact 2-ring matrix (the scheme's [sharp] rules; e.g. --scheme "
        "catmull-clark-blz), the tangent of the boundary curve among the two subdominant eigenvectors, the sector's "
        "characteristic map regular (phantom points at the sharp rays; with a modified near-edge rule such as BLZ's, on "
        "the ring of spline patches past the modified edges) and injective (the argument it sweeps between "
        "the two rays, 0 to 2 pi in the Jacobian's orientation), and at a corner with --angle a convex or concave image. "
        "For a scheme of the zoo (stencils): where its model's regular part is the biquadratic B-spline (a dual quad scheme "
        "such as Doo-Sabin), the same test on the ring of biquadratic patches around the centre n-gon; otherwise "
        "'undecided' with the reason (no spline patch).",
    )
    p.add_argument("--n", dest="valences", type=_valences, action=_ValencesOnce, metavar="A:B",
                   help=f"valences to test: an inclusive range A:B or a single N (at most {LIMITS['c1'][0]}); an open "
                   "range A: is --every-n; or a sharp vertex with --boundary, --corner or --crease")
    flag(p, "--every-n", dest="every_n", help=EVERY_N_HELP)
    flag(p, "--boundary", help="test boundary vertices with K faces (--k): the crease rules on the boundary, the scheme's "
         "[sharp] rules (default: the cubic B-spline's 3/4, 1/8 and 1/2; a file may give Biermann-Levin-Zorin's near-edge "
         "rule in theta_k = pi/k)")
    flag(p, "--corner", help="test corner vertices (interpolated) with K faces (--k); --angle gives the corner's angle")
    flag(p, "--dart", help="test infinitely sharp darts of valence K (--k, K >= 3; one sharp edge ends at a smooth vertex): "
         "Reif's test on the closed fan, the faces next to the sharp edge with phantom points")
    p.add_argument("--k", dest="faces", type=_faces, action=Once, metavar="A:B",
                   help=f"faces of the boundary or corner sector: a range A:B or a single K (1 to {LIMITS['c1 --k'][0]})")
    p.add_argument("--crease", type=_crease, action=Once, metavar="K1,K2",
                   help="test a vertex on an infinitely sharp crease with K1 faces on one side and K2 on the other (both "
                   "sides must pass); with --sharpness S a semi-sharp crease (the interior test at valence K1 + K2)")
    p.add_argument("--angle", type=_angle, action=Once, metavar="EXPR",
                   help="the corner's angle for --corner, e.g. pi/2 (convex) or 3*pi/2 (concave): Biermann-Levin-Zorin's "
                   "theta_k = angle/k in the rules, and the characteristic map must open convex or concave to match")
    p.add_argument("--sharpness", type=sharpness, action=Once, metavar="S", default=math.inf,
                   help="sharpness of the crease for --crease (default inf; a finite S is semi-sharp)")
    p.add_argument("--depth", type=_depth, action=Once, default=6,
                   help="largest de Casteljau subdivision depth, 0 to 12 (default 6; a level splits a quad piece in "
                   "four, a triangle twice); for modified-butterfly and sqrt3, refinements of the net in Zorin's test, capped at 7 "
                   "(at 4 for sqrt3, whose levels have nine times the points of the one before)")
    flag(p, "--json",
                   help='print the one JSON shape (docs: File formats, --json), one object per valence under "rows": '
                   '{"n", "verdict" (c1/not-c1/undecided), "reason", '
                   '"lambda", "gap", "jacobian_lower_bound", "winding_number", "method", ...}; at sharp vertices also '
                   '"vertex", "lambdas" (lambda_1, lambda_2) and "opening_over_pi"')
    add_scheme_option(p, zoo=True)
    add_pool_options(p)
    add_quiet_option(p)
    add_plot_option(p, "the characteristic map at the first, the last and a middle vertex, over the certified bounds of its "
                    "Jacobian and of the spectral gap at every vertex, coloured by verdict (a scheme of the zoo: its spline "
                    "patches, or its control net refined by its own rules, the panel saying which); with --every-n the "
                    "proof's lambda_1(n) as a curve beside each certified valence's lambda_1, its bound on the other "
                    "eigenvalues and its Jacobian bound")
    p.set_defaults(func=run)


class _ValencesOnce(Once):
    """--n, given once; the open range ``3:`` is stored as --every-n (no list of valences)."""

    def __call__(self, parser, namespace, values, option_string=None):
        super().__call__(parser, namespace, None if values == "every" else values, option_string)
        if values == "every":
            namespace.open_range = True


def _valences(text: str):
    """argparse type: :func:`valence_range`, or an open range ``A:`` (every valence from ``A``: --every-n)."""
    if text.endswith(":") and text.count(":") == 1:
        first = valence_range("c1")(text[:-1])[0]
        if first != 3:
            raise argparse.ArgumentTypeError(f"an open range starts at 3 (every valence), got {text!r}")
        return "every"
    return valence_range("c1")(text)


def _faces(text: str) -> list[int]:
    """argparse type: ``K`` or ``A:B``, faces of a sector, ``1 <= A <= B <= LIMITS['c1 --k']``."""
    parts = text.split(":")
    if len(parts) > 2:
        raise argparse.ArgumentTypeError(f"expected K or A:B, got {text[:40]!r}")
    a, b = (integer(x, "--k", minimum=1, limit="c1 --k") for x in (parts[0], parts[-1]))
    if b < a:
        raise argparse.ArgumentTypeError(f"empty range {text!r}: {b} < {a}")
    return list(range(a, b + 1))


def _crease(text: str) -> tuple[int, int]:
    """argparse type: ``K1,K2``, faces on the two sides of a crease."""
    parts = text.split(",")
    if len(parts) != 2:
        raise argparse.ArgumentTypeError(f"expected K1,K2 (faces on each side), got {text[:40]!r}")
    return tuple(integer(x.strip(), "--crease", minimum=1, limit="c1 --k") for x in parts)


def _angle(text: str):
    """argparse type: a corner angle in (0, 2 pi), an exact expression such as ``3*pi/2``."""
    import sympy as sp

    from symdecomp.expressions import exact_value

    try:
        value = exact_value(text, {"pi": sp.pi}, argument="--angle")
    except Exception as exc:  # the package's one-line errors
        raise argparse.ArgumentTypeError(str(exc)) from None
    if not (value.is_positive and (value - 2 * sp.pi).is_negative):
        raise argparse.ArgumentTypeError(f"expected an angle in (0, 2*pi) such as pi/2 or 3*pi/2, got {value}")
    return value


class _Row(NamedTuple):
    """What the command prints of one valence's :class:`~symdecomp.verify.c1.C1Result` (its Arb balls stay in the worker)."""

    n: int
    verdict: C1Verdict
    reason: str
    json: dict
    #: The sharp vertex in words (``""`` for an interior vertex).
    vertex: str = ""


def _one(n: int, scheme: Scheme, max_depth: int) -> _Row:
    from symdecomp.verify.c1 import c1_test

    r = c1_test(scheme, n, max_depth=max_depth)
    return _Row(r.n, r.verdict, r.reason, r.as_json())


def _zoo_one(n: int, scheme, max_depth: int) -> _Row:
    from symdecomp.verify.c1_zoo import c1_zoo
    from symdecomp.verify.zoo_characteristic import engine_neighbourhood

    r = c1_zoo(scheme, n, neighbourhood=engine_neighbourhood, max_depth=max_depth)
    return _Row(r.n, r.verdict, r.reason, r.as_json())


def _run_zoo(args, items: None, plot) -> int:
    """A scheme of the zoo (stencils): :func:`~symdecomp.verify.c1_zoo.c1_zoo` per valence (the route its model allows)."""
    from symdecomp.verify.result import C1Verdict

    if getattr(args, "every_n", False) or getattr(args, "open_range", False):
        from symdecomp.verify.c1_zoo import four_direction_every_n_gap, spline_route, zorin_route

        zorin = zorin_route(args.scheme)
        polys, reason = _zorin_polynomials(args.scheme) if zorin else (None, spline_route(args.scheme))
        if reason is not None and not zorin:
            reason = four_direction_every_n_gap(args.scheme) or reason
        if reason is not None:
            raise InvalidInputError(f"--every-n: the spectral conditions for every n are not derived for {args.scheme.name!r} "
                                    f"(a scheme of the zoo: {reason.split('; ')[0]}); give --n A:B")
        return _run_every_n(args, _zoo_one, ZORIN_EVERY_N_CERTIFIED if zorin else ZOO_EVERY_N_CERTIFIED, plot, polys)
    results = _run_valences(args, _zoo_one, _zoo_methods, title="C1 by the test its model allows")
    write_plot(plot, lambda: _zoo_figure(args.scheme, results))
    return 0 if all(r.verdict is C1Verdict.C1 for r in results) else 1


def _zoo_methods(results: list) -> str:
    """The method line: one method, or each with the valences it decided (Midedge: the Jordan chains at 3, Reif's from 4)."""
    by_method: dict[str, list[int]] = {}
    for r in results:
        by_method.setdefault(r.json["method"], []).append(r.n)
    if len(by_method) == 1:
        return next(iter(by_method))
    return "; ".join(f"{m} (n = {', '.join(map(str, ns))})" for m, ns in by_method.items())


def _zorin_polynomials(scheme) -> tuple[FrequencyPolynomials | None, str | None]:
    """``(polys, None)``: the blocks' characteristic polynomials of a primal scheme of the zoo for every n
    (:func:`~symdecomp.verify.c1_zorin_every_n.frequency_polynomials`), read once here, before any valence is tested,
    and handed to the proof and the plot; ``(None, why not)`` where they are not read."""
    from symdecomp.errors import InvalidSchemeError, NotApplicableError
    from symdecomp.verify.c1_zorin_every_n import frequency_polynomials

    try:
        return frequency_polynomials(scheme), None
    except (NotApplicableError, InvalidSchemeError) as exc:
        return None, f"its blocks for every n are not read: {exc}"


def _zoo_figure(scheme, results: list[_Row]):
    """``c1 --plot`` for a scheme of the zoo: its patches or its refined control net (:mod:`symdecomp.output.plotting.zoo_maps`)."""
    from symdecomp.output.plotting.c1_figures import c1_figure
    from symdecomp.output.plotting.zoo_maps import zoo_map_curves

    return c1_figure(scheme, [r.json for r in results], maps=lambda n: zoo_map_curves(scheme, n))


def _run_valences(args, one, method, title: str = "Reif's test") -> list:
    """``one(n, scheme, max_depth)`` for each valence on the pool, printed (or ``--json``); ``method(results)`` its line."""
    from symdecomp.parallel import ordered_map

    valences = args.valences
    rows = ordered_map(one, valences, shared={"scheme": args.scheme, "max_depth": args.depth}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    results = list(progress(rows, len(valences), "c1", enabled=not args.quiet))
    if args.json:
        print_json(args, [r.json for r in results])
    else:
        print(f"{args.scheme.name}: {title}, valences {valences[0]}..{valences[-1]}")
        print(f"method: {method(results)}")
        for r in results:
            print(f"n = {r.n:>3}: {LABELS[r.verdict.value]}: {r.reason}")
    return results


def _vertex(item: tuple, scheme: Scheme):
    """The :class:`~symdecomp.schemes.sector.SharpVertex` of one item of :func:`_sharp_items`
    (:func:`symdecomp.cli.element.sector_vertex`)."""
    kind, faces, angle, sharpness = item
    return sector_vertex(kind, faces, scheme.lattice, angle=angle, sharpness=math.inf if sharpness is None else sharpness)


def _closed_fan(item: tuple, scheme: Scheme, max_depth: int):
    from symdecomp.verify.c1_closed_fan import c1_dart_test

    return c1_dart_test(scheme, item[1], max_depth=max_depth)


def _mirror_blocks(item: tuple, scheme: Scheme, max_depth: int):
    from symdecomp.verify.c1_mirror_blocks import c1_mirror_blocks

    return c1_mirror_blocks(scheme, _vertex(item, scheme), max_depth=max_depth)


#: The test of each sharp vertex, named by the symmetry it reads: a dart's closed fan (Reif's test), else the sector's
#: mirror blocks (Zorin's conditions).
SECTOR_TESTS = {"boundary": _mirror_blocks, "corner": _mirror_blocks, "crease": _mirror_blocks, "dart": _closed_fan}


def _sharp_one(item: tuple, scheme: Scheme, max_depth: int) -> _Row:
    r = SECTOR_TESTS[item[0]](item, scheme, max_depth)
    return _Row(r.n, r.verdict, r.reason, r.as_json(), r.vertex)


def _sharp_items(args) -> list[tuple] | None:
    """What to test at sharp vertices (``None``: the interior test of --n), or a one-line error."""
    kinds = [name for name in ("boundary", "corner", "crease", "dart") if given(args, name)]
    if given(args, "every_n") and (kinds or given(args, "valences")):
        other = "--n" if given(args, "valences") else f"--{kinds[0]}"
        raise InvalidInputError(f"--every-n and {other} cannot be used together: --every-n tests every interior valence")
    if given(args, "valences") and kinds:
        raise InvalidInputError(f"--n (interior vertices) and --{kinds[0]} cannot be used together: give one kind of vertex")
    if len(kinds) > 1:
        raise InvalidInputError(f"--{kinds[0]} and --{kinds[1]} cannot be used together: give one kind of vertex")
    if not kinds:
        for name in ("faces", "angle", "sharpness"):
            if given(args, name):
                raise InvalidInputError(f"--{'k' if name == 'faces' else name} needs --boundary, --corner or --crease")
        if not given(args, "valences") and not given(args, "every_n"):
            raise InvalidInputError("give --n A:B (interior vertices) or --every-n, or --boundary/--corner with --k A:B, or --crease K1,K2")
        return None
    kind = kinds[0]
    if given(args, "angle") and kind != "corner":
        raise InvalidInputError("--angle is the angle of a corner: it needs --corner")
    if given(args, "sharpness") and kind != "crease":
        raise InvalidInputError("--sharpness is the sharpness of a crease: it needs --crease")
    if kind == "crease":
        if given(args, "faces"):
            raise InvalidInputError("--k and --crease cannot be used together: --crease K1,K2 gives the faces")
        _refuse_dense_past_map_faces(args, max(args.crease))
        return [("crease", args.crease, None, args.sharpness)]
    if not given(args, "faces"):
        raise InvalidInputError(f"--{kind} needs --k A:B, the faces of the sector")
    _refuse_dense_past_map_faces(args, max(args.faces))
    if kind == "dart":
        _check_dart_faces(args)
    return [(kind, k, args.angle, None) for k in args.faces]


def _check_dart_faces(args) -> None:
    """A dart's matrix is dense (no mirror blocks): valences 3 to :data:`MAP_FACES`; its map is not drawn."""
    from symdecomp.verify.c1_mirror_blocks import MAP_FACES

    if min(args.faces) < 3 or max(args.faces) > MAP_FACES:
        raise InvalidInputError(f"--k: a dart's valence is 3 to {MAP_FACES}, got {args.faces[0]}:{args.faces[-1]}")
    if given(args, "plot"):
        raise InvalidInputError("--plot: a dart's characteristic map is not drawn")


def _refuse_dense_past_map_faces(args, faces: int) -> None:
    """What only the dense matrices give (a corner's --angle, the map --plot draws) is refused past their faces."""
    from symdecomp.verify.c1_mirror_blocks import MAP_FACES

    if faces <= MAP_FACES:
        return
    if given(args, "angle"):
        raise InvalidInputError(f"--k: a corner given an --angle is tested on its dense matrices, faces <= {MAP_FACES} (got {faces})")
    if given(args, "plot"):
        raise InvalidInputError(f"--plot: the characteristic map is drawn from the dense matrices, faces <= {MAP_FACES} (got {faces})")


def run(args) -> int:
    """``c1``: the route of the element the arguments name (:data:`ROUTES_BY_KIND`), after c1's own sector options (``--k``,
    ``--crease K1,K2``, ``--angle``) are read and checked."""
    items = _sharp_items(args)
    plot = check_plot(args)
    return route("c1", ROUTES_BY_KIND, named_element(args))(args, items, plot)


def _refuse_zoo_sector(args, items: list[tuple], plot) -> int:
    raise InvalidInputError(f"--{items[0][0]}: sharp vertices are not tested for {args.scheme.name!r} (a scheme of the zoo)")


def _run_vertex(args, items: None, plot) -> int:
    """Reif's test at interior valences (--n), or C1 for every valence (--every-n)."""
    from symdecomp.verify.result import C1Verdict

    if getattr(args, "every_n", False) or getattr(args, "open_range", False):
        return _run_every_n(args, plot=plot)

    results = _run_valences(args, _one, lambda results: args.scheme.lattice.c1_method)
    write_plot(plot, lambda: _figure(args.scheme, results))
    return 0 if all(r.verdict is C1Verdict.C1 for r in results) else 1


def _figure(scheme: Scheme, results: list[_Row], vertices: list | None = None):
    from symdecomp.output.plotting.c1_figures import c1_figure

    return c1_figure(scheme, [{**r.json, "vertex": r.vertex} for r in results], vertices)


def _run_sharp(args, items: list[tuple], plot) -> int:
    from symdecomp.parallel import ordered_map
    from symdecomp.verify.result import C1Verdict

    rows = ordered_map(_sharp_one, items, shared={"scheme": args.scheme, "max_depth": args.depth}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    results = list(progress(rows, len(items), "c1", enabled=not args.quiet))
    if args.json:
        print_json(args, [r.json for r in results])
    else:
        test = "Reif's test" if items[0][0] == "dart" else "Zorin's conditions"
        print(f"{args.scheme.name}: {test} at {items[0][0]} vertices")
        for method in dict.fromkeys(r.json["method"] for r in results):
            print(f"method: {method}")
        width = max(len(r.vertex) for r in results)
        for r in results:
            print(f"{r.vertex:<{width}}: {LABELS[r.verdict.value]}: {r.reason}")
    write_plot(plot, lambda: _figure(args.scheme, results, [_vertex(item, args.scheme) for item in items]))
    return 0 if all(r.verdict is C1Verdict.C1 for r in results) else 1


def _run_every_n(args, one=_one, last: int = EVERY_N_CERTIFIED, plot=None, polys: FrequencyPolynomials | None = None) -> int:
    """``--every-n``: :func:`~symdecomp.verify.c1_every_n.c1_every_n`, or for a dual scheme of the zoo (``one`` is
    :func:`_zoo_one`) :func:`~symdecomp.verify.c1_dual_every_n.c1_dual_every_n`, for a primal one
    :func:`~symdecomp.verify.c1_zorin_every_n.c1_zorin_every_n`; ``one(n)`` at ``3..last`` on the pool.
    ``--plot``: the proof's ``lambda_1(n)`` beside the certified valences (:mod:`symdecomp.output.plotting.every_n_chart`).
    ``polys``: a primal zoo scheme's blocks' polynomials, read once by :func:`_zorin_polynomials`."""
    from symdecomp.parallel import ordered_map
    from symdecomp.verify.c1_dual_every_n import c1_dual_every_n, ngon_spectrum
    from symdecomp.verify.c1_every_n import c1_every_n, lambda_one
    from symdecomp.verify.c1_zoo import zorin_route
    from symdecomp.verify.c1_zorin_every_n import c1_zorin_every_n, zorin_lambda_one

    scheme = args.scheme
    valences = list(range(3 if one is _zoo_one else max(3, scheme.minimum_valence()), last + 1))
    rows = ordered_map(one, valences, shared={"scheme": scheme, "max_depth": args.depth}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    by_n = {r.n: r for r in progress(rows, len(valences), "c1", enabled=not args.quiet)}
    zorin = one is _zoo_one and zorin_route(scheme)  # a primal scheme of the zoo: Zorin's test per valence
    certify = lambda k: by_n[k] if k in by_n else one(k, scheme, args.depth)  # noqa: E731
    result = (c1_zorin_every_n(scheme, last, certify=certify, polys=polys) if zorin else
              (c1_dual_every_n if one is _zoo_one else c1_every_n)(scheme, last, certify=certify))
    if args.json:
        print_json(args, {**result.as_json(), "rows": [by_n[k].json for k in sorted(by_n) if k <= result.certified[1] + 1]})
    else:
        print(f"{scheme.name}: C1 for every valence? {result.status}")  # the question and the verdict, never the claim
        for step in result.steps:
            first, last = step.valences
            where = f"n >= {first}" if last is None else f"n = {first}..{last}" if last > first else f"n = {first}"
            print(f"  [{step.status}] {where}: {step.text}")
        print(f"{result.status}: {result.summary}")
    write_plot(plot, lambda: _every_n_figure(result, [by_n[k].json for k in sorted(by_n)],
                                             zorin_lambda_one(scheme, polys) if zorin else
                                             ngon_spectrum(scheme).first if one is _zoo_one else lambda_one(scheme)))
    return 0 if result.status in ("proved", "verified") else 1


def _every_n_figure(result, rows: list[dict], lam):
    from symdecomp.output.plotting.every_n_chart import every_n_figure

    return every_n_figure(result, rows, lam)


#: The route of each kind of element (:mod:`symdecomp.cli.element`), each given the arguments, c1's sector items and --plot.
ROUTES_BY_KIND = {"vertex": _run_vertex, "sector": _run_sharp, "zoo": _run_zoo, "zoo sector": _refuse_zoo_sector}
