"""``symdecomp artifacts --n 3:64``: the curvature regime and artifact indicators at an extraordinary vertex, per valence.

The table is a list of columns (:data:`symdecomp.output.artifact_table.COLUMNS`, shared with the report's section
"Curvature and shape"), each a header and a function of one valence's JSON object
(:meth:`~symdecomp.verify.artifacts.ArtifactIndicators.as_json`): a new indicator is one more entry.

``symdecomp artifacts --every-n``: the curvature regime of every valence (:mod:`symdecomp.verify.regime_every_n`).
"""

from __future__ import annotations

import argparse

from symdecomp.cli.common import (
    ARTIFACTS_COST,
    LIMITS,
    Once,
    add_pool_options,
    add_scheme_option,
    estimate_seconds,
    flag,
    print_json,
    progress,
    valence_range,
)
from symdecomp.cli.element import named_element, route, steps_note
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError
from symdecomp.parallel import ordered_map
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.stencils import StencilScheme

__all__ = ["register", "run"]


_LEGEND = (
    "regime: curvature at the vertex bounded (|mu| = lambda_1^2, exact), zero (flat spot, |mu| < lambda_1^2) or unbounded "
    "(|mu| > lambda_1^2); freq: frequency of mu (0 elliptic, 1 tangent, 2 hyperbolic, outer: the regular rules at every "
    "frequency), '?' after mu: eigenvalues not separated in modulus; density: lambda_1 against the regular 1/2 (dense "
    "below, sparse above); spacing: the characteristic map's second ring spacing over the first (1 on the regular mesh); "
    "shape: the certified class of the central surface for elliptic input (elliptic, hyperbolic, hybrid), and whether the "
    "hyperbolic part dominates on fine rings (then convex input does not stay convex)"
)


def register(sub) -> None:
    p = sub.add_parser(
        "artifacts",
        help="curvature regime and artifact indicators at an extraordinary vertex, certified, per valence",
        description="For each valence: the eigenvalues of the 2-ring subdivision matrix after 1 and lambda_1 by "
        "frequency (0 elliptic, 2 hyperbolic, and the regular rules' outer blocks), the largest of them, mu, with "
        "its frequency and multiplicity, and the curvature regime from |mu| against lambda_1^2 (Peters and Reif "
        "2004): bounded (equal, shown exactly in a cyclotomic field), zero (a flat spot) or unbounded; certified in "
        "interval arithmetic. Then the artifact indicators: density (lambda_1 against the regular 1/2), negative "
        "weights in the limit and tangent masks, the characteristic map's ring spacing, and the shape class of the "
        "central surface (elliptic, hyperbolic, hybrid). Needs Reif's spectral "
        "conditions (else 'not applicable') and Catmull-Clark or Loop regular rules. A scheme of the zoo (doo-sabin, "
        "sqrt3, ...) gets density and the curvature regime from its engine's certified spectrum by frequency (over the "
        "steps that return its lattice). Exit status 1 if a valence's regime is undecided.",
        epilog=_LEGEND,
    )
    p.add_argument("--n", dest="valences", type=valence_range("artifacts"), action=Once, metavar="A:B",
                   help=f"valences: an inclusive range A:B or a single N (at most {LIMITS['artifacts'][0]}); or --every-n")
    flag(p, "--every-n", dest="every_n",
         help="the curvature regime of every valence: certified at n = 3, 4, ... until the unbounded regime is proved for "
         "every larger n (lambda_2 > lambda_1^2 in s = cos(2 pi/n): Sturm sequences on triangles, Arb balls covering "
         "[s_0, 1] on quads); --json: the steps")
    flag(p, "--json", help='print the one JSON shape (docs: File formats, --json), one object per valence under "rows": '
         '{"n", "density", "negative_weights", '
         '"ring_spacing_ratio", "sector_angle_ratio", "curvature": {"regime", "reason", "cause", "lambda1", '
         '"lambda1_squared", "mu": [{"value", "frequency", "multiplicity", "kind", "comparison", "exact"}], ...}}')
    add_scheme_option(p, zoo=True)
    add_pool_options(p)
    add_quiet_option(p)
    add_plot_option(p, "the regime chart over n: lambda_1, lambda_1^2 and |mu|, and |mu| / lambda_1^2 against 1, coloured by "
                    "the certified regime")
    p.set_defaults(func=run)


def _one(n: int, scheme: Scheme) -> dict:
    from symdecomp.verify.artifacts import artifact_indicators  # imported when the command runs: --help stays cheap

    return artifact_indicators(scheme, n).as_json()


def _figure(scheme: str, rows: list[dict[str, object]]) -> object:
    from symdecomp.output.plotting.regime_chart import regime_figure

    return regime_figure(scheme, rows)


def run(args) -> int:
    """``artifacts``: the route of the element the arguments name (:data:`ROUTES_BY_KIND`)."""
    return route("artifacts", ROUTES_BY_KIND, named_element(args))(args)


def _run_vertex(args) -> int:
    """``artifacts --n A:B`` (or ``--every-n``) at an interior vertex: the indicators per valence."""
    from symdecomp.output.artifact_table import table

    if args.every_n and args.valences is not None:
        raise InvalidInputError("--every-n and --n cannot be used together: --every-n covers every valence")
    if args.every_n:
        return _run_every_n(args)
    if args.valences is None:
        raise InvalidInputError("give --n A:B (the valences) or --every-n")
    valences = args.valences
    plot = check_plot(args)
    estimate_seconds(ARTIFACTS_COST * sum(valences), "artifacts --n A:B", f"--n {valences[0]}:{valences[-1]}")
    rows = ordered_map(_one, valences, shared={"scheme": args.scheme}, jobs=args.jobs, executor=args.executor, warm_up=True)
    results = list(progress(rows, len(valences), "artifacts", enabled=not args.quiet))
    if args.json:
        print_json(args, results)
    else:
        print(f"{args.scheme.name}: curvature and artifacts at the extraordinary vertex, valences {valences[0]}..{valences[-1]}")
        print(table(results))
        print(_LEGEND)
    write_plot(plot, lambda: _figure(args.scheme.name, results))
    return 1 if any(r["curvature"]["regime"] == "undecided" for r in results) else 0


def _run_every_n(args) -> int:
    from symdecomp.verify.regime_every_n import regime_every_n

    result = regime_every_n(args.scheme)
    if args.json:
        print_json(args, {**result.as_json(), "rows": []})  # a proof for every valence: its steps, no rows of valences
    else:
        print(f"{args.scheme.name}: the curvature regime at the extraordinary vertex, every valence")
        for step in result.steps:
            first, last = step.valences
            where = f"n >= {first}" if last is None else f"n = {first}..{last}"
            print(f"  [{step.status}] {where}: {step.text}")
    return 0 if result.first_proved is not None else 1


def _zoo_one(n: int, scheme: StencilScheme) -> dict[str, object]:
    from symdecomp.verify.zoo_artifacts import zoo_artifacts

    return zoo_artifacts(scheme, n).as_json()


#: An exact form longer than this is shown by its decimal value in the text (``--json`` has both).
_SHORT = 40


def _short(exact: object, value: object) -> str:
    return str(exact) if exact is not None and len(str(exact)) <= _SHORT else str(value or "-")


def _mu_text(curvature: dict[str, object]) -> str:
    mu = curvature["mu"]
    assert isinstance(mu, list)
    return "; ".join(f"{_short(m['exact'], m['value'])} ({m['kind']})" for m in mu) or "-"


def _print_zoo(name: str, scheme: StencilScheme, rows: list[dict[str, object]]) -> None:
    print(f"{name}: curvature regime and density at the extraordinary element, valences {rows[0]['n']}..{rows[-1]['n']}"
          f"{steps_note(scheme)}")
    for r in rows:
        c = r["curvature"]
        assert isinstance(c, dict)
        lam, square = _short(c["lambda1_exact"], c["lambda1"]), _short(c["lambda1_squared"], c["lambda1_squared_value"])
        print(f"n = {r['n']:>3}: {c['regime']}; lambda_1 = {lam}, lambda_1^2 = {square}, "
              f"mu = {_mu_text(c)}; density {r['density']} (regular lambda_1 {r['regular_lambda1'] or '-'}); {c['reason']}")
    print(str(rows[0]["not_computed"]))


def _run_zoo(args: argparse.Namespace) -> int:
    """``artifacts --n A:B --scheme <zoo scheme>`` on the smallest invariant neighbourhood. Exit 1 if a regime is undecided."""
    plot = check_plot(args)
    name = args.scheme.name
    if args.every_n:
        raise InvalidInputError(f"--every-n: the curvature regime for every n is not derived for {name!r} (a scheme of the zoo); "
                                "give --n A:B")
    if args.valences is None:
        raise InvalidInputError("give --n A:B (the valences)")
    rows = ordered_map(_zoo_one, args.valences, shared={"scheme": args.scheme}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    results: list[dict[str, object]] = list(progress(rows, len(args.valences), "artifacts", enabled=not args.quiet))
    write_plot(plot, lambda: _figure(name, results))
    if args.json:
        print_json(args, results)
    else:
        _print_zoo(name, args.scheme, results)
    undecided = [r for r in results if isinstance(r["curvature"], dict) and r["curvature"]["regime"] == "undecided"]
    return 1 if undecided else 0


#: The route of each kind of element (:mod:`symdecomp.cli.element`).
ROUTES_BY_KIND = {"vertex": _run_vertex, "zoo": _run_zoo}
