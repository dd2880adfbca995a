"""``symdecomp tune N``: vertex-rule weights for nice elliptic properties at valence N (Section 5.2).

Prints, for the valence N, each of the two conditions of Section 5.2 alone (the line of
``(alpha, beta)`` on which it holds, the point on it with the scheme's own ``beta``, and the
interval of ``beta`` where the target is the subdominant eigenvalue of Eq. 43), and whether
both can hold together. With ``--table`` it prints instead the distance of the scheme from
nice elliptic behaviour (both defects, from their closed forms in ``n``) for ``n = 3..N``.

With ``--region`` (a scheme file with free vertex weights, ``parameters = ["alpha", "beta"]`` or one
parameter) it prints instead the exact region of those weights at valence N by curvature regime
(:mod:`symdecomp.analysis.tuning_region`, certified by :mod:`symdecomp.verify.tuning_c1`): the
quadratic ``Q`` of the frequency-0 eigenvalues, ``lambda_1``, the defining linear conditions of the
sets where the scheme is C1 and the curvature regime (:mod:`symdecomp.analysis.curvature_regime`, its names)
is zero (``|mu| < lambda_1^2``), bounded (``=``) or unbounded (``>``, or ``=`` with a Jordan block), each a union
of conjunctions; points outside C1 are "not applicable", for one parameter the exact intervals, and where the published and the paper's
weights lie (Catmull-Clark's, the paper's Section 5.2 tuning; Loop's and Warren's on triangles).
``--plot FILE.png|FILE.pdf`` draws the region (each cell coloured only where certified signs decide
it; :mod:`symdecomp.output.plotting.tuning`).
"""

from __future__ import annotations

import math

import sympy as sp

from symdecomp.cli.common import LIMITS, Once, add_scheme_option, closed_form_obstacle, digits, flag, print_json, progress, valence
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError

_PHI = LIMITS["tune --region, interval_region, placed_points: phi(n)"][0]


def _region_valences() -> str:
    """The valences ``tune N --region`` answers at (Euler's ``phi(N)`` within the bound), for the help."""
    return ", ".join(str(m) for m in range(3, 64) if sum(math.gcd(i, m) == 1 for i in range(1, m + 1)) <= _PHI)


def register(sub) -> None:
    p = sub.add_parser(
        "tune",
        help="tune the vertex rule (alpha, beta) for nice elliptic properties at valence N",
        description="Solve for the vertex-rule weights alpha, beta (weights of each a_i, b_i in the new O) for which "
        "(1) the subdominant eigenvalue of the Eq. 43 matrix equals lambda_1^2 and (2) the Eq. 44 ratio d_b/d_a "
        "equals |B^1/A^1|^2; each alone is a line in the (alpha, beta) plane; both together are possible only where "
        "an equation in n alone holds (for Catmull-Clark: n = 4), since the Eq. 44 ratio at a given eigenvalue "
        "does not depend on the vertex rule. --table prints both defects of the scheme for n = 3..N. --region (a scheme "
        "file with parameters = [\"alpha\", \"beta\"] or one parameter in its vertex rule) prints instead the exact region "
        "of those weights at valence N where the scheme is C1 with curvature regime zero (|mu| < lambda_1^2, "
        "curvature tends to 0), bounded (|mu| = lambda_1^2) or unbounded (|mu| > lambda_1^2, or = with a Jordan block), "
        "mu the largest eigenvalue modulus after 1 and lambda_1 over all "
        "frequencies: linear inequalities in the weights with exact algebraic coefficients, exact intervals for one "
        "parameter, and where published weights lie; --plot draws it, cells coloured only where certified signs decide.",
    )
    p.add_argument("n", type=valence("tune"), metavar="N", help="the valence (an integer, 3 <= N <= 1000; with --table N <= 200)")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of printed values (default 20, at most 1000)")
    flag(p, "--table", help="print the defects of both conditions for n = 3..N instead")
    flag(p, "--region", help="print the exact region of the scheme's free vertex weights (parameters in its file) at valence N "
         "by curvature regime: zero (|mu| < lambda_1^2, a flat spot), bounded (|mu| = lambda_1^2), unbounded (|mu| > lambda_1^2 "
         "or a Jordan block), not applicable (not C1), with "
         "Catmull-Clark's, the paper's Section 5.2 and (triangles) Loop's and Warren's weights placed in it; at the valences "
         f"whose exact signs are within reach, Euler's phi(N) <= {_PHI}: N = {_region_valences()} (the limits table)")
    p.add_argument("--plot", action=Once, metavar="FILE.png|FILE.pdf",
                   help="with --region: draw the region in the parameter plane (or line) to this file, coloured by regime")
    flag(p, "--json", help="print JSON")
    add_scheme_option(p)
    add_quiet_option(p)
    p.set_defaults(func=run)


def run(args) -> int:
    if args.region or args.plot is not None:
        return run_region(args)
    from symdecomp.analysis import elliptic, tuning
    obstacle = closed_form_obstacle(args.scheme)
    if obstacle:
        raise InvalidInputError(f"--scheme {args.scheme.name}: tune solves the paper's quad 1-ring conditions (Section 5.2) "
                                f"in closed form, which do not apply: {obstacle}")
    bound, why = LIMITS["tune --table"]
    if args.table and args.n > bound:
        raise InvalidInputError(f"tune --table: N must be at most {bound}, got {args.n} ({why})")
    if args.table:
        valences = list(range(3, args.n + 1))
        rows = []
        for n in progress(valences, len(valences), "defects", enabled=not args.quiet):
            rows.extend(elliptic.elliptic_defect_table(args.scheme, [n], digits=args.digits))
        cond = elliptic.nice_elliptic_conditions(args.scheme)
        if args.json:
            closed = {
                "subdominant": sp.sstr(cond.subdominant),
                "lambda1": sp.sstr(cond.lambda1),
                "eq44_ratio_of_mu": sp.sstr(cond.eq44_ratio_of_mu.subs(elliptic.MU, sp.Symbol("mu"))),
                "scale_ratio_squared": sp.sstr(cond.scale_ratio_squared),
            }
            print_json(args, {"scheme": args.scheme.name, "closed_forms": closed, "rows": [r.as_json() for r in rows]})
            return 0
        print(f"{args.scheme.name}: closed forms in n")
        print(f"  mu(n)            = {cond.subdominant}   (subdominant eigenvalue of Eq. 43)")
        print(f"  lambda_1(n)      = {cond.lambda1}")
        print(f"  d_b/d_a at mu    = {cond.eq44_ratio_of_mu.subs(elliptic.MU, sp.Symbol('mu'))}   (Eq. 44)")
        print(f"  |B^1/A^1|^2(n)   = {cond.scale_ratio_squared}")
        print("  defects: mu - lambda_1^2 and d_b/d_a - |B^1/A^1|^2")
        head = ("n", "mu", "lambda1^2", "mu - lambda1^2", "d_b/d_a", "|B1/A1|^2", "ratio defect")
        width = args.digits + 8
        print("  ".join([f"{head[0]:>4}"] + [f"{h:<{width}}" for h in head[1:]]))
        for r in rows:
            print("  ".join([f"{r.n:>4}"] + [f"{t:<{width}}" for t in r.texts]))
        return 0
    result = tuning.tune(args.scheme, args.n)
    data = result.as_json(args.digits)
    if args.json:
        print_json(args, {"scheme": args.scheme.name, **data})
        return 0
    print(f"{args.scheme.name}, valence n = {args.n}")
    print(f"  lambda_1 = {data['lambda1']}, lambda_1^2 = {data['lambda1_squared']}, |B^1/A^1|^2 = {data['scale_ratio_squared']}")
    print(f"  scheme's own weights: alpha = {data['standard']['alpha']}, beta = {data['standard']['beta']}")
    for key, title in (("eigenvalue_condition", "condition 1: subdominant eigenvalue of Eq. 43 = lambda_1^2"),
                       ("ratio_condition", "condition 2: Eq. 44 ratio d_b/d_a = |B^1/A^1|^2")):
        c = data[key]
        print(f"{title}")
        print(f"  target eigenvalue mu = {c['target']}")
        print(f"  line: {c['line']}")
        print(f"  with the scheme's beta: alpha = {c['alpha']}, beta = {c['beta']}")
        print(f"  mu is the simple subdominant eigenvalue for beta in ({c['beta_interval'][0]}, {c['beta_interval'][1]})"
              f" [scheme's beta inside: {'yes' if c['standard_beta_admissible'] else 'no'}; mu < lambda_1: "
              f"{'yes' if c['target_below_lambda1'] else 'no'}]")
    print("both conditions together: " + ("possible" if data["jointly_possible"] else "impossible"))
    print(f"  ratio(lambda_1^2) - |B^1/A^1|^2 = {data['joint_defect']} (no vertex-rule weight enters it); "
          "only the edge and face rules can change it")
    return 0


def _num(e, digits: int) -> str:
    from symdecomp.algebra.algebraic_sign import real_ball

    return real_ball(e, 4 * digits + 64).str(digits, radius=False)


def _ball(e, digits: int) -> str:
    """A certified enclosure of an algebraic end, as text ``[mid +/- radius]``."""
    from symdecomp.algebra.algebraic_sign import real_ball

    return real_ball(e, 4 * digits + 64).str(digits)


def run_region(args) -> int:
    """``tune N --region [--plot FILE]``: the region of free vertex weights at valence N (module docstring)."""
    from symdecomp.analysis.tuning_region import check_region_valence, interval_region, placed_points
    from symdecomp.verify.tuning_c1 import certified_tuning_region

    if not args.region:
        raise InvalidInputError("tune --plot: draws the region; give --region too")
    if args.table:
        raise InvalidInputError("tune --region: cannot be combined with --table (the region is at one valence N)")
    plot, fmt = None, None
    if args.plot is not None:
        fmt = str(args.plot).rsplit(".", 1)[-1].lower() if "." in str(args.plot) else ""
        if fmt not in ("png", "pdf"):
            raise InvalidInputError(f"--plot {args.plot}: the file name must end in .png or .pdf")
        plot = check_output_file(args.plot, "--plot")
    if args.scheme.parameters:  # (without parameters the region refuses the scheme first, at once)
        check_region_valence(args.n)  # refused before any work: the exact signs' cost grows with phi(N)
    region = certified_tuning_region(args.scheme, args.n)
    points = placed_points(args.scheme, args.n)
    data = _region_data(region, points, interval_region(region) if len(region.parameters) == 1 else None, args.digits)
    if plot is not None:
        from symdecomp.output.plotting.tuning import figure_bytes, tuning_region_figure

        write_output_file(plot, figure_bytes(tuning_region_figure([region], {region.n: points}), fmt), "--plot")
    if args.json:
        print_json(args, data)
        return 0
    _print_region(data)
    return 0


def _region_data(region, points, intervals, digits: int) -> dict:
    relation = {-1: "<", 0: "=", 1: ">"}[region.fixed_vs_square]
    return {
        "scheme": region.scheme,
        "n": region.n,
        "parameters": [str(p) for p in region.parameters],
        "Q": sp.sstr(region.quadratic).replace("lambda", "x"),
        "lambda1": sp.sstr(region.lambda1),
        "lambda1_value": _num(region.lambda1, digits),
        "lambda1_squared_value": _num(region.lambda1**2, digits),
        "fixed_modulus": region.fixed_text,
        "fixed_vs_lambda1_squared": relation,
        "c1_test": {"verdict": region.witness_verdict, "reason": region.witness_reason},
        "c1": [f.text(">") for f in region.c1_forms],
        "regions": {str(k): v for k, v in region.conditions().items()},
        "jordan_corners": [{"double_root": name, "values": [sp.sstr(v) for v in p]} for name, p, jordan in region.corners() if jordan],
        "intervals": None if intervals is None else [
            {"regime": str(i.regime), "interval": i.text(), "ends": [None if e is None else _ball(e, digits) for e in (i.lo, i.hi)]}
            for i in intervals],
        "points": [{"name": name, "values": [sp.sstr(v) for v in p], "approx": [_num(v, digits) for v in p],
                    "regime": str(region.classify(p)), "on": [f.name for f, s in zip(region.square_forms, region.signs(p)[1]) if s == 0]}
                   for name, p in points],
    }


def _label(regime: str) -> str:
    """A regime's name as printed: outside the C1 set the regime is not applicable, and the line says why."""
    from symdecomp.analysis.curvature_regime import CurvatureRegime

    return regime + (" (not C1)" if regime == CurvatureRegime.NOT_APPLICABLE.value else "")


def _print_region(data: dict) -> None:
    from symdecomp.analysis.curvature_regime import REGIME_TEXT, CurvatureRegime

    params = ", ".join(data["parameters"])
    print(f"{data['scheme']}, valence n = {data['n']}: free vertex weights ({params}) at O")
    print(f"  Q(x) = {data['Q']}   (det(x - T)/(x - 1), T the frequency-0 block, Eq. 43)")
    print(f"  lambda_1 = {data['lambda1']} = {data['lambda1_value']}, lambda_1^2 = {data['lambda1_squared_value']}")
    print(f"  weight-independent eigenvalues: largest modulus m = {data['fixed_modulus']} ({data['fixed_vs_lambda1_squared']} "
          "lambda_1^2, exactly)")
    print(f"  Reif's weight-independent conditions: {data['c1_test']['verdict']} ({data['c1_test']['reason']})")
    print("  C1 (weight-dependent part): " + " and ".join(data["c1"]))
    for name, alternatives in data["regions"].items():
        print(f"  C1 and {REGIME_TEXT[CurvatureRegime(name)]}:" + ("" if alternatives else " empty"))
        for conj in alternatives:
            print("    " + " and ".join(conj))
    for corner in data["jordan_corners"]:
        print(f"  except ({', '.join(corner['values'])}): Q has the double root {corner['double_root']} with a Jordan block "
              "in T, so the curvature is unbounded there")
    if data["intervals"] is not None:
        print(f"  {params} by regime:")
        for piece in data["intervals"]:
            ends = ", ".join(inf if e is None else e for e, inf in zip(piece["ends"], ("-oo", "oo")))
            print(f"    {piece['interval']}: {_label(piece['regime'])}   (ends in {ends})")
    for point in data["points"]:
        on = f" (on {', '.join(point['on'])} = 0)" if point["on"] else ""
        print(f"  {point['name']}: ({', '.join(point['values'])}) ~ ({', '.join(point['approx'])}): {_label(point['regime'])}{on}")
