"""``symdecomp inspect MESH --vertices``: one row per interior extraordinary vertex, its 1-ring decomposed.

The detailed view of :mod:`symdecomp.cli.inspect_cmd` (which by default prints one row per neighbourhood kind):
for each smooth interior extraordinary vertex (no sharp edge or tag at it) (:mod:`symdecomp.analysis.inspection`) the limit position (exact from the
position mask; the row shows it to 6 digits), the unit normal from the tangent masks, the size of the
tangent-plane part (n-gon frequency 1), the elliptic heights (frequency 0: the centroids of the ``a_i`` and
``b_i`` above the tangent plane through ``O``) and the hyperbolic part (frequency 2) with its share off the
tangent plane; and the artifact indicators of each vertex's valence
(:func:`~symdecomp.verify.artifacts.artifact_indicators`, computed once per valence): the curvature regime at
the vertex and its cause, the density and the shape class of the central surface for elliptic input, or
``n/a`` with the reason once. Exact per vertex, so meant for small meshes and chosen vertices.

JSON (``--vertices --json``), under ``"extraordinary_details"``: ``[{"vertex", "valence", "ring", "limit_exact":
["x", "y", "z"], "limit", "normal", "tangents", "tangent_size", "tangent_off_plane", "elliptic_heights",
"hyperbolic_size", "hyperbolic_off_plane", "rest_size", "components": [{"frequencies", "ngon_frequency", "radii",
"size", "off_plane"}], "artifacts": {"regime", "cause", "shape", "density"} or null}]``, and
``"artifacts_not_applicable": {"N": reason}``.

``--figures DIR`` writes ``vertex-<index>.png`` per extraordinary vertex (the 1-ring in the tangent plane
with its tangent-plane and hyperbolic components, and the heights off the plane); the directory's other
files stay, its earlier ``vertex-*.png`` are replaced, all in one step.
"""

from __future__ import annotations

import re

from symdecomp.cli.common import progress
from symdecomp.cli.files import replace_owned_files
from symdecomp.cli.masks_cmd import lambda_1_subdominance
from symdecomp.errors import NotApplicableError, UnavailableError

__all__ = ["vertex_details", "require_matplotlib", "subdominance"]

_OWNED = re.compile(r"vertex-[0-9]+\.png\Z")


def _g(x) -> str:
    return "-" if x is None else f"{x:.6g}"


def _triple(xs) -> str:
    return "-" if xs is None else " ".join(f"{round(x, 6) + 0.0:>10.6f}" for x in xs)  # no "-0.000000"


def _json(mesh, result, artifacts: dict[int, dict | str]) -> dict:
    def vertex(r) -> dict:
        return {"vertex": r.vertex, "valence": r.valence, "ring": list(r.ring), "limit_exact": [str(x) for x in r.limit_exact],
                "limit": list(r.limit), "normal": None if r.normal is None else list(r.normal), "tangents": [list(t) for t in r.tangents],
                "tangent_size": r.tangent_size, "tangent_off_plane": r.tangent_off_plane, "elliptic_heights": list(r.elliptic_heights),
                "hyperbolic_size": r.hyperbolic_size, "hyperbolic_off_plane": r.hyperbolic_off_plane, "rest_size": r.rest_size,
                "components": [{"frequencies": list(c.frequencies), "ngon_frequency": c.ngon_frequency, "radii": list(c.radii),
                                "size": c.size, "off_plane": c.off_plane} for c in r.components],
                "artifacts": _indicators_of(artifacts, r.valence)}

    return {"extraordinary_details": [vertex(r) for r in result.vertices],
            "artifacts_not_applicable": {str(n): v for n, v in artifacts.items() if isinstance(v, str)}}


def _artifact_cells(indicators: dict | None) -> str:
    if indicators is None:
        return f"{'n/a':<24}  {'n/a':<12}  n/a"
    regime = indicators["regime"] + ("" if indicators["cause"] is None else f" ({indicators['cause']})")
    return f"{regime:<24}  {indicators['density']:<12}  {indicators['shape']}"


def _print_table(mesh, result, artifacts: dict[int, dict | str]) -> None:
    print(f"{'vertex':>6} {'n':>3}  {'limit position':^32}  {'normal':^32}  {'tangent':>9}  {'elliptic heights':^21}  "
          f"{'hyperbolic (off plane)':>22}  {'curvature regime (cause)':<24}  {'density':<12}  shape")
    for r in result.vertices:
        heights = " ".join(f"{h:>10.3g}" for h in r.elliptic_heights)
        hyper = "-" if r.hyperbolic_size is None else f"{_g(r.hyperbolic_size)} ({_g(r.hyperbolic_off_plane)})"
        cells = _artifact_cells(_indicators_of(artifacts, r.valence))
        print(f"{r.vertex:>6} {r.valence:>3}  {_triple(r.limit)}  {_triple(r.normal)}  {_g(r.tangent_size):>9}  {heights:<21}  "
              f"{hyper:>22}  {cells}".rstrip())
    for reason, valences in _not_applicable(artifacts).items():
        print(f"artifact indicators n/a at valence {', '.join(map(str, valences))}: {reason}")


def _artifacts(result, scheme) -> dict[int, dict | str]:
    """Per valence of an extraordinary vertex: its artifact indicators (regime, cause, shape, density), or why they do not apply."""
    from symdecomp.verify.artifacts import artifact_indicators

    out: dict[int, dict | str] = {}
    for n in sorted({r.valence for r in result.vertices}):
        try:
            a = artifact_indicators(scheme, n).as_json()
        except NotApplicableError as exc:
            out[n] = str(exc)
            continue
        out[n] = {"regime": a["curvature"]["regime"], "cause": a["curvature"]["cause"], "shape": a["shape"]["text"],
                  "density": a["density"]}
    return out


def _indicators_of(artifacts: dict[int, dict | str], n: int) -> dict | None:
    value = artifacts[n]
    return value if isinstance(value, dict) else None


def _not_applicable(artifacts: dict[int, dict | str]) -> dict[str, list[int]]:
    """Each reason the indicators do not apply, once, with its valences."""
    out: dict[str, list[int]] = {}
    for n, value in artifacts.items():
        if isinstance(value, str):
            out.setdefault(value, []).append(n)
    return out


def _figures(args, mesh, result) -> None:
    from symdecomp.output.plotting.meshes import png_bytes, vertex_figure

    files = {}
    for r in progress(result.vertices, len(result.vertices), "figures", enabled=not args.quiet):
        files[f"vertex-{r.vertex}.png"] = png_bytes(vertex_figure(r, [[float(c) for c in mesh.points[v]] for v in r.ring]))
    replace_owned_files(args.figures, files, _OWNED, "--figures")


def require_matplotlib() -> None:
    """--figures needs matplotlib: say so before the work starts (exit 3), not after."""
    from symdecomp.output.plotting._mpl import require_matplotlib

    try:
        require_matplotlib()
    except ImportError as exc:
        raise UnavailableError(f"--figures: {exc}") from None


def subdominance(scheme, valences) -> dict[int, tuple[bool, str]]:
    """Per smooth valence: whether ``lambda_1`` is certified subdominant (the normal is a tangent plane's)."""
    out = {}
    for n in sorted(valences):
        certified, why, one_simple = lambda_1_subdominance(scheme, n)
        if not one_simple:
            raise NotApplicableError(f"{scheme.name} at valence {n}: {why}; no limit position is defined there")
        out[n] = (certified, why)
    return out


def vertex_details(args, mesh, scheme, vertices) -> dict | None:
    """Print the per-vertex table of ``vertices`` (the smooth extraordinary ones; or return its JSON part) and write
    ``--figures``; the exact route, vertex by vertex."""
    from symdecomp.analysis.inspection import MeshInspection, inspect_vertex

    shown = progress(vertices, len(vertices), "vertices", enabled=not args.quiet)
    result = MeshInspection(scheme.name, tuple(inspect_vertex(mesh, v, scheme) for v in shown), ())
    artifacts = _artifacts(result, scheme)
    if args.figures is not None:
        _figures(args, mesh, result)
    if not args.vertices:
        return None
    if args.json:
        return _json(mesh, result, artifacts)
    _print_table(mesh, result, artifacts)
    return None
