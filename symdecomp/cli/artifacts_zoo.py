"""``symdecomp artifacts --n A:B --scheme <zoo scheme>``: density and the curvature regime from the zoo's engine.

:func:`symdecomp.verify.zoo_artifacts.zoo_artifacts` per valence; the options about what a zoo scheme does not have
(``--every-n``'s proof in ``n``) are refused in one line, and what is not computed is said in one line.
"""

from __future__ import annotations

import argparse

from symdecomp.cli.common import print_json
from symdecomp.cli.plot_file import PlotTarget, write_plot
from symdecomp.cli.progress import progress
from symdecomp.errors import InvalidInputError
from symdecomp.parallel import ordered_map
from symdecomp.schemes.stencils import StencilScheme

__all__ = ["run_zoo_artifacts"]


def _one(n: int, scheme: StencilScheme) -> dict[str, object]:
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


def _print(name: str, steps: int, rows: list[dict[str, object]]) -> None:
    over = f", over {steps} steps (the lattice returns after {steps})" if steps > 1 else ""
    print(f"{name}: curvature regime and density at the extraordinary element, valences {rows[0]['n']}..{rows[-1]['n']}{over}")
    for r in rows:
        c = r["curvature"]
        assert isinstance(c, dict)
        lam, square = _short(c["lambda1_exact"], c["lambda1"]), _short(c["lambda1_squared"], None)
        print(f"n = {r['n']:>3}: {c['regime']}; lambda_1 = {lam}, lambda_1^2 = {square}, "
              f"mu = {_mu_text(c)}; density {r['density']} (regular lambda_1 {r['regular_lambda1'] or '-'}); {c['reason']}")
    print(str(rows[0]["not_computed"]))


def _figure(name: str, rows: list[dict[str, object]]) -> object:
    from symdecomp.output.plotting.regime_chart import regime_figure

    return regime_figure(name, rows)


def run_zoo_artifacts(args: argparse.Namespace, plot: PlotTarget | None) -> int:
    """``artifacts --n A:B --scheme <zoo scheme>`` on the smallest invariant neighbourhood. Exit 1 if a regime is undecided."""
    name = args.scheme.name
    if args.every_n:
        raise InvalidInputError(f"--every-n: the curvature regime for every n is not derived for {name!r} (a scheme of the zoo); "
                                "give --n A:B")
    if args.valences is None:
        raise InvalidInputError("give --n A:B (the valences)")
    rows = ordered_map(_one, args.valences, shared={"scheme": args.scheme}, jobs=args.jobs,
                       executor=args.executor, warm_up=True)
    results: list[dict[str, object]] = list(progress(rows, len(args.valences), "artifacts", enabled=not args.quiet))
    write_plot(plot, lambda: _figure(name, results))
    if args.json:
        print_json(args, results)
    else:
        _print(name, args.scheme.steps, results)
    undecided = [r for r in results if isinstance(r["curvature"], dict) and r["curvature"]["regime"] == "undecided"]
    return 1 if undecided else 0
