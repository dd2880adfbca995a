"""``symdecomp charpoly N``: the characteristic polynomial of the valence-N subdivision matrix, in closed form.

``--plot FILE`` draws the printed polynomial's roots, certified from its exact coefficients
(:mod:`symdecomp.analysis.polynomial_roots`, :mod:`symdecomp.output.plotting.charpoly_roots`); with ``--free-weights``
(coefficients in alpha, beta) it is refused before any work.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.cli.common import add_rings_option, add_scheme_option, flag, general_path, print_json, refuse_together, valence
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.errors import InvalidInputError, InvalidSchemeError
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import lam as LAM


def register(sub) -> None:
    p = sub.add_parser(
        "charpoly",
        help="closed-form characteristic polynomial of the valence-N subdivision matrix, checked exactly",
        description="Derive det(xI - S) of the (2N+1)x(2N+1) subdivision matrix in closed form (symbolic in n and "
        "the vertex-rule weights; Section 6: S -> S', Prop. 6.3), evaluate it exactly at valence N and compare "
        "with the characteristic polynomial of the exact rational matrix (FLINT). With --free-weights the vertex "
        "weights alpha, beta stay symbolic (Catmull-Clark edge and face rules) and the coefficients are "
        "polynomials in them.",
    )
    p.add_argument("n", type=valence("charpoly"), metavar="N", help="the valence (an integer, 3 <= N <= 300)")
    flag(p, "--free-weights", help="keep the vertex-rule weights alpha, beta symbolic (Catmull-Clark edge and face rules)")
    flag(
        p,
        "--json",
        help='print {"n", "scheme", "closed_form", "zero_frequency_factor", "coefficients" (highest degree first, '
        'exact strings), "matches_matrix"}',
    )
    add_scheme_option(p)
    add_rings_option(p)
    add_plot_option(p, "the roots of the polynomial at N in the complex plane (certified from its exact coefficients; "
                    "marker area: multiplicity), with the unit circle and the circle of radius lambda_1; not with "
                    "--free-weights")
    p.set_defaults(func=run)


def _draw(args, plot, coefficients, rings: int = 1) -> None:
    """``charpoly --plot``: the roots of the printed polynomial (:mod:`symdecomp.output.plotting.charpoly_roots`)."""
    from symdecomp.analysis.polynomial_roots import polynomial_roots
    from symdecomp.output.plotting.charpoly_roots import roots_figure

    if plot is None:
        return
    where = f", {rings}-ring" if rings != 1 else ""
    roots = polynomial_roots(coefficients)
    title = f"{args.scheme.name}, valence n = {args.n}{where}: the roots of det(x I - S), degree {roots.degree}"
    write_plot(plot, lambda: roots_figure(roots, title))


def _run_general(args, plot, why: str = "") -> int:
    from symdecomp.analysis.charpoly import ring_charpoly_exact

    if args.free_weights:
        raise InvalidInputError("--free-weights applies to the Catmull-Clark 1-ring only (not to triangle schemes or --rings > 1)")
    data, coefficients = ring_charpoly_exact(args.scheme, args.n, args.rings)
    if args.json:
        print_json(args, data)
        _draw(args, plot, coefficients, args.rings)
        return 0 if data["matches_matrix"] else 1
    print(f"{args.scheme.name}: det(x I - S), S the {args.rings}-ring matrix of size {data['size']}, x written as {LAM}")
    if why:
        print(f"(no closed form: {why}; the product form instead)")
    print(f"product form (all n): {data['product_form']}")
    print(f"  det(x I - E_0) = {' * '.join(data['frequency_zero_factors'])}   (w_O = 1 - n w_a - n w_b: the centre's weights)")
    print(f"  det(x I - E(omega)) = {' * '.join(data['frequency_factors'])}")
    print(f"at n = {args.n}: {data['polynomial']}")
    print(f"equals the characteristic polynomial of the full matrix: {'yes' if data['matches_matrix'] else 'NO'} ({data['method']})")
    _draw(args, plot, coefficients, args.rings)
    return 0 if data["matches_matrix"] else 1


def _coefficients(scheme, n, free: bool) -> tuple[list[sp.Expr], bool]:
    from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial
    from symdecomp.schemes.full_matrix import characteristic_polynomial

    cf = closed_form_characteristic_polynomial(scheme)
    if not free:
        poly = cf.at(n)
        matches = poly == characteristic_polynomial(scheme, n)
        return [sp.Rational(int(c.p), int(c.q)) for c in reversed(poly.coeffs())], matches
    # affine in (alpha, beta): interpolate from three exact evaluations, each checked against the matrix
    points = [(0, 0), (1, 0), (0, 1)]
    polys, matches = [], True
    for a, b in points:
        values = {ALPHA: a, BETA: b}
        poly = cf.at(n, values)
        matches &= poly == characteristic_polynomial(scheme, n, values)
        polys.append([sp.Rational(int(c.p), int(c.q)) for c in reversed(poly.coeffs())])
    p0, pa, pb = polys
    return [sp.expand(c0 + ALPHA * (ca - c0) + BETA * (cb - c0)) for c0, ca, cb in zip(p0, pa, pb)], matches


def run(args) -> int:
    from symdecomp.analysis.charpoly import closed_form_characteristic_polynomial
    from symdecomp.analysis.tuning import with_free_vertex_rule

    refuse_together(args, "--free-weights", "--plot", "the coefficients are polynomials in alpha, beta: no roots to draw")
    plot = check_plot(args)
    if general_path(args):
        return _run_general(args, plot)
    refuse_together(args, "--free-weights", "--scheme", "--free-weights uses the Catmull-Clark edge and face rules")
    scheme = with_free_vertex_rule(args.scheme) if args.free_weights else args.scheme
    try:
        cf = closed_form_characteristic_polynomial(scheme)
    except InvalidSchemeError as exc:  # wider stencils: Eq. 51 does not apply, the product form does
        if args.free_weights:
            raise
        return _run_general(args, plot, str(exc).split(";")[-1].strip())
    coefficients, matches = _coefficients(scheme, args.n, args.free_weights)
    if args.json:
        print_json(
            args,
            {
                "n": args.n,
                "scheme": scheme.name,
                "closed_form": str(cf.expression),
                "zero_frequency_factor": str(cf.zero_frequency_factor),
                "coefficients": [str(c) for c in coefficients],
                "matches_matrix": bool(matches),
            }
        )
        _draw(args, plot, coefficients)
        return 0 if matches else 1
    print(f"{scheme.name}: det(x I - S), S of size {2 * args.n + 1}, x written as {LAM}")
    print(f"closed form (all n): {cf.expression}")
    print(f"the vertex weights enter only: {cf.zero_frequency_factor}")
    poly = sp.Add(*[c * LAM ** (len(coefficients) - 1 - i) for i, c in enumerate(coefficients)])
    print(f"at n = {args.n}: {poly}")
    print(f"equals the characteristic polynomial of the exact matrix: {'yes' if matches else 'NO'}")
    _draw(args, plot, coefficients)
    return 0 if matches else 1
