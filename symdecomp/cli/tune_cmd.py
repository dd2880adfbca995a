"""``symdecomp tune N``: vertex-rule weights for nice elliptic properties at valence N (Section 5.2).

Prints, for the valence N, each of the two conditions of Section 5.2 alone (the line of
``(alpha, beta)`` on which it holds, the point on it with the scheme's own ``beta``, and the
interval of ``beta`` where the target is the subdominant eigenvalue of Eq. 43), and whether
both can hold together. With ``--table`` it prints instead the distance of the scheme from
nice elliptic behaviour (both defects, from their closed forms in ``n``) for ``n = 3..N``.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.analysis.elliptic import MU, elliptic_defect_table, nice_elliptic_conditions
from symdecomp.analysis.tuning import tune
from symdecomp.cli.common import LIMITS, Once, add_scheme_option, closed_form_obstacle, digits, flag, print_json, progress, valence
from symdecomp.errors import InvalidInputError


def register(sub) -> None:
    p = sub.add_parser(
        "tune",
        help="tune the vertex rule (alpha, beta) for nice elliptic properties at valence N",
        description="Solve for the vertex-rule weights alpha, beta (weights of each a_i, b_i in the new O) for which "
        "(1) the subdominant eigenvalue of the Eq. 43 matrix equals lambda_1^2 and (2) the Eq. 44 ratio d_b/d_a "
        "equals |B^1/A^1|^2; each alone is a line in the (alpha, beta) plane; both together are possible only where "
        "an equation in n alone holds (for Catmull-Clark: n = 4), since the Eq. 44 ratio at a given eigenvalue "
        "does not depend on the vertex rule. --table prints both defects of the scheme for n = 3..N.",
    )
    p.add_argument("n", type=valence("tune"), metavar="N", help="the valence (an integer, 3 <= N <= 1000; with --table N <= 200)")
    p.add_argument("--digits", type=digits(), action=Once, default=20,
                   help="significant digits of printed values (default 20, at most 1000)")
    flag(p, "--table", help="print the defects of both conditions for n = 3..N instead")
    flag(p, "--json", help="print JSON")
    add_scheme_option(p)
    p.set_defaults(func=run)


def run(args) -> int:
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
        for n in progress(valences, len(valences), "defects", enabled=not args.json):
            rows.extend(elliptic_defect_table(args.scheme, [n], digits=args.digits))
        cond = nice_elliptic_conditions(args.scheme)
        if args.json:
            closed = {
                "subdominant": sp.sstr(cond.subdominant),
                "lambda1": sp.sstr(cond.lambda1),
                "eq44_ratio_of_mu": sp.sstr(cond.eq44_ratio_of_mu.subs(MU, sp.Symbol("mu"))),
                "scale_ratio_squared": sp.sstr(cond.scale_ratio_squared),
            }
            print_json({"scheme": args.scheme.name, "closed_forms": closed, "rows": [r.as_json() for r in rows]})
            return 0
        print(f"{args.scheme.name}: closed forms in n")
        print(f"  mu(n)            = {cond.subdominant}   (subdominant eigenvalue of Eq. 43)")
        print(f"  lambda_1(n)      = {cond.lambda1}")
        print(f"  d_b/d_a at mu    = {cond.eq44_ratio_of_mu.subs(MU, sp.Symbol('mu'))}   (Eq. 44)")
        print(f"  |B^1/A^1|^2(n)   = {cond.scale_ratio_squared}")
        print("  defects: mu - lambda_1^2 and d_b/d_a - |B^1/A^1|^2")
        head = ("n", "mu", "lambda1^2", "mu - lambda1^2", "d_b/d_a", "|B1/A1|^2", "ratio defect")
        width = args.digits + 8
        print("  ".join([f"{head[0]:>4}"] + [f"{h:<{width}}" for h in head[1:]]))
        for r in rows:
            print("  ".join([f"{r.n:>4}"] + [f"{t:<{width}}" for t in r.texts]))
        return 0
    result = tune(args.scheme, args.n)
    data = result.as_json(args.digits)
    if args.json:
        print_json({"scheme": args.scheme.name, **data})
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
