"""``symdecomp check --k A:B --boundary`` (and ``--corner``, ``--crease K2``, ``--dart``): the mirror decomposition's
blocks against the vertex's refined matrix, one row per vertex, on the shared pool (``--jobs``, ``--executor``), in order
(the first vertex is checked before the workers fork, so that the once-per-scheme sine identity is proved once).

Certified (``--certify``), by one of two routes (``--route``, named in each row as ``check --n`` names its own):
``charpoly``, the dense route (``chi_S`` of the refined matrix equals the blocks' product, exactly: cubic in the faces,
at most 64), the default for darts and, under rational rules, up to
:data:`~symdecomp.verify.sector_structural.DENSE_UP_TO` faces; and ``structural``, O(k)
(:mod:`symdecomp.verify.sector_structural`: the refined matrix is the mirror model row by row), the default otherwise,
to 10,000 faces. Numeric (without ``--certify``, :mod:`symdecomp.verify.sector_numeric`): the
blocks' values against the refined matrix's eigenvalues while the matrix is small enough to solve densely, else the
refined matrix applied to every sine polyline against its block, in double precision; each row says which.
"""

from __future__ import annotations

import math
import time

from symdecomp.cli.common import given, print_json, progress, refuse_together
from symdecomp.cli.plot_file import write_plot
from symdecomp.errors import InvalidInputError

__all__ = ["run_mirror", "refuse_semi_sharp"]


def refuse_semi_sharp(args) -> None:
    """Refuse a finite ``--sharpness`` at once, before the header: both modes check the mirror decomposition, which a
    semi-sharp vertex does not have (its matrix changes level by level; ``spectrum`` shows the levels)."""
    from symdecomp.cli.element import check_sharp_options

    check_sharp_options(args)  # --sharpness without --crease or --dart: that line first
    if args.sharpness != math.inf:
        kind = "--dart" if args.dart else "--crease"
        mode = "--certify" if args.certify else "numeric mode"
        raise InvalidInputError(f"--sharpness {args.sharpness} with check {kind} ({mode}): check reads infinitely sharp edges "
                                "only (the mirror decomposition it checks against needs them); spectrum and masks read a "
                                "semi-sharp vertex level by level")


def run_mirror(args, plot) -> int:
    """``check --k A:B`` with a sharp vertex's option: certified or numeric rows, exit 1 if any vertex is not proved."""
    from symdecomp.cli.element import refuse_sharp_options

    refuse_semi_sharp(args)
    refuse_sharp_options(args, "--rings")
    if given(args, "solver"):
        raise InvalidInputError("--k and --solver cannot be used together: --solver applies to interior valences (--n)")
    if args.certify:
        return _run_certified(args, plot)
    for option in ("--route", "--structural"):
        if given(args, option.lstrip("-")):
            raise InvalidInputError(f"{option}: give it with --certify (it chooses the certificate)")
    return _run_numeric(args)


def _routes(args, vertices) -> list[str]:
    """Each vertex's certificate (``--route`` or the default), a vertex out of the asked route's reach refused in one line."""
    from symdecomp.cli.element import describe
    from symdecomp.schemes.sector import MAX_DENSE_FACES
    from symdecomp.verify.sector_structural import applies, default_route

    refuse_together(args, "--certify", "--dps", "the certified check is exact and has no precision")
    refuse_together(args, "--route", "--structural", "--structural is --route structural")
    asked = args.route or ("structural" if args.structural else None)
    routes = []
    for vertex in vertices:
        if asked == "structural" and not applies(args.scheme, vertex):
            raise InvalidInputError(f"--route structural: {describe(vertex)}: the structural route reads boundary, crease and "
                                    "corner vertices (a dart's symmetric part is the whole fan); use --route charpoly")
        route = asked or default_route(args.scheme, vertex)
        if route == "charpoly" and vertex.faces > MAX_DENSE_FACES:
            raise InvalidInputError(f"--route charpoly: {describe(vertex)} has {vertex.faces} faces; the dense route reads at "
                                    f"most {MAX_DENSE_FACES} (its characteristic polynomial is cubic in the faces); the "
                                    "structural route reads up to 10000")
        routes.append(route)
    return routes


def _precheck(args, vertices, routes) -> None:
    """Rules out of a route's reach (irrational weights over two fields, a bare theta_k, ...): one line before the header."""
    from symdecomp.analysis.block_values import block_values, layout
    from symdecomp.analysis.triangular_eigen import sharp_matrix
    from symdecomp.cli.element import exact_only

    dense = [v for v, r in zip(vertices, routes) if r == "charpoly"]
    for vertex in dense:
        exact_only(args, vertex, lambda: sharp_matrix(args.scheme, vertex))  # noqa: B023 - called at once
    wide = [v for v, r in zip(vertices, routes) if r == "structural"]
    if wide:
        exact_only(args, wide[0], lambda: block_values(args.scheme, layout(args.scheme, wide[0]), 64, head=1))


def _header(args, routes) -> None:
    used = sorted(set(routes))
    texts = {"charpoly": "dense route: chi_S of the refined 1-ring matrix = det(l - C) prod det(l - M(theta_j)) in Q[l] "
                         "(Q(cos(pi/K))[l] for cos(theta_k) weights)",
             "structural": "structural route, O(K): the refined matrix = the mirror model row by row, exactly; the spectrum "
                           "is the blocks' (no characteristic polynomial)"}
    print(f"{args.scheme.name}: mirror decomposition vs full matrix, certified (exact), "
          + "; ".join(texts[r] for r in used))
    print(f"{'K':>5}  {'status':<9} {'distinct':>8}  {'mult.':<9} {'route':<10} {'vertex':<16} {'chi_S bits':>10}  certificate")


def _run_certified(args, plot) -> int:
    from symdecomp.cli.element import describe, sharp_vertex
    from symdecomp.parallel import ordered_map
    from symdecomp.verify.sector_structural import certify_vertex

    vertices = [sharp_vertex(args, k, structural=True) for k in args.sectors]  # every bad combination refused first
    routes = _routes(args, vertices)
    _precheck(args, vertices, routes)
    start, rows = time.perf_counter(), []
    if not args.json:
        _header(args, routes)
    asked = args.route or ("structural" if args.structural else None)
    results = ordered_map(certify_vertex, vertices, shared={"scheme": args.scheme, "route": asked}, jobs=args.jobs,
                          executor=args.executor, warm_up=True, cost=lambda v: v.faces)
    for r in progress(results, len(vertices), "certify", enabled=not args.quiet):
        rows.append(r)
        if not args.json:
            bits = r.height_bits if r.route == "charpoly" else "-"
            line = (f"{r.n:>5}  {r.status.value:<9} {r.distinct:>8}  {'exact':<9} {r.route:<10} {r.vertex:<16} {bits:>10}  "
                    f"{r.method}")
            print(line if r.ok else f"{line}\n      {r.message}", flush=True)
    elapsed = time.perf_counter() - start
    failed = [r for r in rows if not r.ok]
    counts = {st: sum(1 for r in rows if r.status.value == st) for st in ("agree", "disagree", "undecided")}
    used = {route: routes.count(route) for route in sorted(set(routes))}
    if args.json:
        print_json(args, {"scheme": args.scheme.name, "vertex": describe(vertices[0]).split()[0], "rows": [r.as_json() for r in rows],
                    "summary": {"mode": "certified", "route": next(iter(used)) if len(used) == 1 else "mixed", "routes": used,
                                "sectors": len(rows), **counts, "seconds": round(elapsed, 3), "ok": not failed}})
    else:
        tally = ", ".join(f"{v} {k}" for k, v in counts.items() if v)
        print(f"{len(rows)} vertices: {tally} ({elapsed:.2f} s; " + ", ".join(f"{n} {r}" for r, n in used.items()) + ")")
        for r in failed:
            print(f"FAILED {r.message}")
    write_plot(plot, lambda: _figure(args.scheme.name, rows))
    return 1 if failed else 0


def _figure(scheme: str, rows: list):
    from symdecomp.output.plotting.check_chart import check_figure

    return check_figure(scheme, [r.as_json() for r in rows])


def _run_numeric(args) -> int:
    """The blocks against the refined matrix, numerically, on the pool (:mod:`symdecomp.verify.sector_numeric`)."""
    from symdecomp.analysis.block_values import structural_values
    from symdecomp.cli.element import describe, exact_only, sharp_vertex
    from symdecomp.parallel import ordered_map
    from symdecomp.verify.sector_numeric import DENSE_FACES, numeric_sector_row

    vertices = [sharp_vertex(args, k, structural=True) for k in args.sectors]
    exact_only(args, vertices[0], lambda: structural_values(args.scheme, vertices[0]))  # darts, rules: refused here
    start, rows = time.perf_counter(), []
    if not args.json:
        print(f"{args.scheme.name}: mirror decomposition's blocks vs the refined 1-ring matrix, numeric (--certify proves it): "
              f"up to {DENSE_FACES} faces its eigenvalues at {args.dps} digits against the blocks' to {args.dps // 2}; past "
              "them the matrix applied to every sine polyline against its block, in double precision")
        print(f"{'K':>5}  {'status':<13} {'size':>5} {'distinct':>8}  {'compared':<10} {'vertex':<16} deviation")
    results = ordered_map(numeric_sector_row, vertices, shared={"scheme": args.scheme, "dps": args.dps}, jobs=args.jobs,
                          executor=args.executor, warm_up=True, cost=lambda v: v.faces)
    for r in progress(results, len(vertices), "check", enabled=not args.quiet):
        rows.append(r)
        if not args.json:
            line = f"{r.k:>5}  {r.status.value:<13} {r.size:>5} {r.distinct:>8}  {r.compared:<10} {r.vertex:<16} {r.deviation}"
            print(line if r.ok else f"{line}\n      {r.message}", flush=True)
    failed = [r for r in rows if not r.ok]
    if args.json:
        print_json(args, {"scheme": args.scheme.name, "vertex": describe(vertices[0]).split()[0], "rows": [r.as_json() for r in rows],
                    "summary": {"mode": "numeric", "route": "mirror", "sectors": len(rows), "dps": args.dps,
                                "seconds": round(time.perf_counter() - start, 3), "ok": not failed}})
    else:
        print(f"{len(rows)} vertices: {len(rows) - len(failed)} agree ({time.perf_counter() - start:.2f} s)")
    return 1 if failed else 0
