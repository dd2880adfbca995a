"""``symdecomp inspect MESH``: the extraordinary vertices of a mesh file, their limit points and 1-ring components.

Reads an OBJ, OFF or PLY polygon mesh (:mod:`symdecomp.schemes.meshformats`; the extension names the
format, or ``--format``), checks that the scheme can take it (one line naming the element otherwise:
``model.obj: edge (3, 7) is shared by 3 faces [0, 2, 6] (non-manifold edge)``, exit status 2), and prints
one row per interior extraordinary vertex (:mod:`symdecomp.analysis.inspection`): the limit position
(exact from the position mask; the row shows it to 6 digits), the unit normal from the tangent masks,
the size of the tangent-plane part (n-gon frequency 1), the elliptic heights (frequency 0: the centroids
of the ``a_i`` and ``b_i`` above the tangent plane through ``O``) and the hyperbolic part (frequency 2)
with its share off the tangent plane. Boundary vertices are counted and skipped.

Exit status 1 (with a line on stderr) when at some valence of the mesh ``lambda_1`` is not certified to be the
subdominant eigenvalue of the 1-ring (as ``symdecomp masks N`` decides): the normals there are not a tangent
plane's. A scheme whose eigenvalue 1 is not simple at a valence of the mesh has no limit position there: exit 2.

The scheme: ``--scheme`` (a name or a TOML file), else Catmull-Clark for a mesh of quads and Loop for a mesh
of triangles; a mesh with other faces is refused with the reason (split it into quads first, e.g. with
:meth:`~symdecomp.schemes.meshfile.PolygonMesh.split_into_quads`).

JSON (``--json``): ``{"mesh", "scheme", "vertices": V, "faces": F, "skipped_boundary": [...], "extraordinary":
[{"vertex", "valence", "ring", "limit_exact": ["x", "y", "z"], "limit": [x, y, z], "normal", "tangents",
"tangent_size", "tangent_off_plane", "elliptic_heights", "hyperbolic_size", "hyperbolic_off_plane",
"rest_size", "components": [{"frequencies", "ngon_frequency", "radii", "size", "off_plane"}], "artifacts": {"regime",
"cause", "shape", "density"} or null}], "subdominance": {"N": {"certified", "why"}}, "artifacts_not_applicable": {"N":
reason}}``; numbers are doubles, ``limit_exact`` exact (sympy text).

The artifact indicators of each vertex's valence (:func:`~symdecomp.verify.artifacts.artifact_indicators`, as
``symdecomp artifacts --n N --scheme S`` prints them; computed once per valence, since they depend on the scheme
and the valence only): the curvature regime at the vertex (bounded, zero: a flat spot, unbounded) and the
frequency causing it, the certified shape class of the central surface for elliptic input, and the density
(``lambda_1`` against the regular 1/2). Where they do not apply (free parameters, regular rules that are not
Catmull-Clark's or Loop's) the columns say ``n/a`` and one line gives the reason.

``--figures DIR`` writes ``vertex-<index>.png`` per extraordinary vertex (the 1-ring in the tangent plane
with its tangent-plane and hyperbolic components, and the heights off the plane); the directory's other
files stay, its earlier ``vertex-*.png`` are replaced, all in one step.
"""

from __future__ import annotations

import re
import sys

from symdecomp.cli.common import Once, flag, print_json, progress, scheme_by_name
from symdecomp.cli.files import check_output_directory, replace_owned_files
from symdecomp.cli.masks_cmd import lambda_1_subdominance
from symdecomp.errors import NotApplicableError, UnavailableError
from symdecomp.schemes.meshfile import scheme_for_mesh
from symdecomp.schemes.meshformats import FORMATS, read_mesh

__all__ = ["register", "run"]

_OWNED = re.compile(r"vertex-[0-9]+\.png\Z")


def register(sub) -> None:
    p = sub.add_parser(
        "inspect",
        help="the extraordinary vertices of a mesh file (OBJ, OFF, PLY): limit points, normals, 1-ring components",
        description="For every interior extraordinary vertex of the mesh: the limit position (exact position mask), "
        "the limit normal and tangents (tangent masks), and the 1-ring decomposed into planar regular polygons "
        "(Eq. 5, 6, 11): sizes of the tangent-plane (frequency 1), elliptic (frequency 0) and hyperbolic "
        "(frequency 2) parts; and its valence's artifact indicators (as symdecomp artifacts computes them, once per "
        "valence): the curvature regime at the vertex and its cause, the density and the shape class of the central "
        "surface for elliptic input, or n/a with the reason once. A mesh the scheme cannot take (non-manifold edge or vertex, inconsistent "
        "orientation, degenerate face, a face of the wrong kind) is refused in one line naming the element.",
    )
    p.add_argument("mesh", metavar="MESH", help="the mesh file: .obj, .off or .ply (faces counter-clockwise from outside)")
    p.add_argument("--scheme", type=scheme_by_name, action=Once, default=None, metavar="NAME|FILE",
                   help="subdivision scheme: a known name or a TOML scheme file (default: catmull-clark for a quad mesh, "
                   "loop for a triangle mesh)")
    p.add_argument("--format", choices=FORMATS, action=Once, default=None, help="the file format, if not its extension")
    p.add_argument("--figures", action=Once, default=None, metavar="DIR",
                   help="write one figure per extraordinary vertex, DIR/vertex-<index>.png (needs matplotlib)")
    flag(p, "--json", help='print {"mesh", "scheme", "skipped_boundary", "extraordinary": [one object per vertex]}')
    p.set_defaults(func=run)


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

    return {"mesh": mesh.name, "scheme": result.scheme, "vertices": len(mesh.points), "faces": len(mesh.faces),
            "skipped_boundary": list(result.skipped_boundary), "extraordinary": [vertex(r) for r in result.vertices],
            "artifacts_not_applicable": {str(n): v for n, v in artifacts.items() if isinstance(v, str)}}


def _artifact_cells(indicators: dict | None) -> str:
    if indicators is None:
        return f"{'n/a':<24}  {'n/a':<12}  n/a"
    regime = indicators["regime"] + ("" if indicators["cause"] is None else f" ({indicators['cause']})")
    return f"{regime:<24}  {indicators['density']:<12}  {indicators['shape']}"


def _print_table(mesh, result, artifacts: dict[int, dict | str]) -> None:
    print(f"{mesh.name}: {len(mesh.points)} vertices, {len(mesh.faces)} faces; scheme {result.scheme}; "
          f"{len(result.vertices)} extraordinary vertices; {len(result.skipped_boundary)} boundary vertices skipped")
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
    for r in progress(result.vertices, len(result.vertices), "figures"):
        files[f"vertex-{r.vertex}.png"] = png_bytes(vertex_figure(r, [[float(c) for c in mesh.points[v]] for v in r.ring]))
    replace_owned_files(args.figures, files, _OWNED, "--figures")


def _require_matplotlib() -> None:
    """--figures needs matplotlib: say so before the work starts (exit 3), not after."""
    from symdecomp.output.plotting._mpl import require_matplotlib

    try:
        require_matplotlib()
    except ImportError as exc:
        raise UnavailableError(f"--figures: {exc}") from None


def _subdominance(mesh, scheme) -> dict[int, tuple[bool, str]]:
    """Per valence of an extraordinary vertex: whether ``lambda_1`` is certified subdominant (the normal is a tangent plane's)."""
    out = {}
    for n in sorted({mesh.valence(v) for v in mesh.extraordinary_vertices(scheme.lattice)}):
        certified, why, one_simple = lambda_1_subdominance(scheme, n)
        if not one_simple:
            raise NotApplicableError(f"{mesh.name}: {scheme.name} at valence {n}: {why}; no limit position is defined there")
        out[n] = (certified, why)
    return out


def run(args) -> int:
    from symdecomp.analysis.inspection import inspect_mesh

    if args.figures is not None:
        check_output_directory(args.figures, "--figures")
        _require_matplotlib()
    mesh = read_mesh(args.mesh, args.format)
    scheme = args.scheme if args.scheme is not None else scheme_for_mesh(mesh)
    mesh.require_lattice(scheme.lattice, scheme.name)
    subdominant = _subdominance(mesh, scheme)
    result = inspect_mesh(mesh, scheme, progress=lambda xs, total: progress(xs, total, "inspect"))
    artifacts = _artifacts(result, scheme)
    if args.figures is not None:
        _figures(args, mesh, result)
    if args.json:
        data = _json(mesh, result, artifacts)
        data["subdominance"] = {str(n): {"certified": c, "why": why} for n, (c, why) in subdominant.items()}
        print_json(args, data)
    else:
        _print_table(mesh, result, artifacts)
    if result.skipped_boundary and not args.json:
        print(f"note: boundary vertices are not analysed (boundary rules are a later issue): {len(result.skipped_boundary)} skipped",
              file=sys.stderr)
    for n, (certified, why) in subdominant.items():
        if not certified:
            print(f"symdecomp inspect: at valence {n} lambda_1 is not certified the subdominant eigenvalue ({why}); the normals "
                  "there are the tangent masks' cross product, not a tangent plane's", file=sys.stderr)
    return 0 if all(c for c, _ in subdominant.values()) else 1
