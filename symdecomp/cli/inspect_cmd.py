"""``symdecomp inspect MESH``: every vertex of a mesh file classified, its limit point and normal, verdicts by kind.

Reads an OBJ, OFF or PLY polygon mesh (:mod:`symdecomp.schemes.meshformats`; the extension names the format,
or ``--format``; OpenSubdiv's ``t crease``/``t corner`` tags with it), classifies every vertex by its
neighbourhood kind as OpenSubdiv tags it (:mod:`symdecomp.analysis.mesh_kinds`: smooth valence ``n``; boundary,
crease, corner, dart with their sectors' face counts and sharpness), computes each kind's exact masks and
verdicts once (:mod:`symdecomp.analysis.mesh_limits`; C1 and the curvature regime,
:mod:`symdecomp.verify.mesh_verdicts`) and applies the masks to every vertex of the kind with numpy. It prints
one row per kind: how many vertices, the C1 verdict, the curvature regime, whether the tangents span the
tangent plane; then the vertices not analysed, with why.

A mesh with faces other than the scheme's (a quad mesh with triangles, n-gons): for Catmull-Clark its first
step is taken exactly (:mod:`symdecomp.schemes.polygon_step`) and the refined mesh is analysed; the report
names the extraordinary points that came from faces (the centres of the n-gons).

A vertex of no kind gets its computed outcome (:mod:`symdecomp.analysis.mesh_outcomes`), one row per distinct
outcome: off the limit surface (every face of it a hole, or under ``interpolateboundary none``), transient (semi-sharp
vertex tags, sharp edges of different sharpness: the verdicts of the kind it becomes once its tags have decayed, and
after how many levels), or a fan judged by its exact spectrum (valence 2; one face under ``edge-only``).

Exit status: 0 when every vertex was analysed, 1 when something was left out (vertices not analysed, a limit point not
computed, elements of the file left out of the mesh, or a valence where ``lambda_1`` is not certified subdominant),
2 for a file that cannot be read or a mesh the scheme cannot take; ``--strict`` makes anything left out an
error (exit 2, one line naming it).

``--out FILE.ply|FILE.obj`` writes the (analysed) mesh with a colour per vertex by ``--color-by``: ``verdict``
(C1: green c1, red not-c1, amber undecided, grey not analysed or n/a), ``regime`` (green bounded, blue zero, red
unbounded), ``kind``, ``valence``, ``displacement`` (distance of the vertex from its limit point, scaled by the
mesh's size; a ramp blue-white-red), and the value as PLY ``quality``. ``--plot FILE.png`` draws the mesh
coloured the same way. ``--exact`` adds the exact limit positions (slow: vertex by vertex). ``--vertices``
adds the detailed per-vertex table of the extraordinary vertices (:mod:`symdecomp.cli.inspect_vertices`).

JSON (``--json``): ``{"mesh", "scheme", "vertices", "faces", "refined_first": bool, "from_faces": {"new vertex":
old face}, "kinds": [{"kind", "name", "faces", "sectors", "closed", "corner", "sharpness", "count", "c1",
"c1_reason", "regime", "tangent_plane", "tangents", "levels", "eventual", "on_surface"}], "not_analysed": {"vertex":
reason}, "no_limit": {"vertex": reason},
"defects": {...}, "extraordinary": [{"vertex", "kind", "limit", "normal"} (and "limit_exact")], "exit_status"}``.
"""

from __future__ import annotations

import sys

from symdecomp.cli.common import Once, flag, print_json, progress, scheme_by_name
from symdecomp.cli.files import check_output_directory, check_output_file
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError, InvalidMeshError
from symdecomp.validate import MESH_FORMATS as FORMATS

__all__ = ["register", "run", "prepare_mesh", "COLOR_BY"]

#: What ``--color-by`` can colour by.
COLOR_BY = ("verdict", "regime", "kind", "valence", "displacement")


def register(sub) -> None:
    p = sub.add_parser(
        "inspect",
        help="every vertex of a mesh file (OBJ, OFF, PLY) classified: limit points, normals, C1 and curvature by kind",
        description="Classify every vertex of the mesh by its neighbourhood kind (smooth valence n; boundary, crease, "
        "corner, dart, as OpenSubdiv tags it), compute each kind's exact limit masks, C1 verdict and curvature regime "
        "once, and apply the masks to all vertices of the kind. Prints one row per kind and the vertices not analysed "
        "with why; exit status 0 when everything was analysed, 1 when something was left out, 2 for an unreadable file.",
    )
    p.add_argument("mesh", metavar="MESH", help="the mesh file: .obj, .off or .ply (faces counter-clockwise from outside)")
    p.add_argument("--scheme", type=scheme_by_name, action=Once, default=None, metavar="NAME|FILE",
                   help="subdivision scheme: a known name or a TOML scheme file (default: catmull-clark for quads or a "
                   "mixed mesh, loop for a triangle mesh)")
    p.add_argument("--format", choices=FORMATS, action=Once, default=None, help="the file format, if not its extension")
    p.add_argument("--out", action=Once, default=None, metavar="FILE",
                   help="write the mesh with per-vertex colours (.ply: red green blue and quality; .obj: v x y z r g b)")
    p.add_argument("--color-by", choices=COLOR_BY, action=Once, default="verdict", help="what --out and --plot colour by "
                   "(default: verdict)")
    p.add_argument("--plot", action=Once, default=None, metavar="FILE.png", help="draw the mesh coloured by --color-by")
    p.add_argument("--figures", action=Once, default=None, metavar="DIR",
                   help="write one figure per extraordinary vertex, DIR/vertex-<index>.png (needs matplotlib)")
    flag(p, "--vertices", help="also print the detailed table of each interior extraordinary vertex (exact; small meshes)")
    flag(p, "--exact", help="also compute every limit position exactly (vertex by vertex: slow)")
    flag(p, "--strict", help="refuse (exit 2) instead of leaving a vertex or an element of the file out")
    flag(p, "--json", help='print {"mesh", "scheme", "kinds", "not_analysed", "defects", "extraordinary", ...}')
    add_quiet_option(p)
    p.set_defaults(func=run)


def _read(args):
    """The mesh, read leniently unless ``--strict``."""
    from symdecomp.cli.inspect_outputs import memory_note
    from symdecomp.schemes.meshformats import read_mesh

    memory_note(args.mesh)
    mesh = read_mesh(args.mesh, args.format, strict=args.strict, progress=None if args.quiet else progress_lines)
    if args.strict and not mesh.defects.is_empty():
        raise InvalidMeshError(f"{mesh.name}: --strict: the file has elements a scheme cannot take: {_first_defect(mesh.defects)}")
    return mesh


def _first_defect(defects) -> str:
    for name, items in defects.as_dict().items():
        if items:
            return f"{name.replace('_', ' ')} {items[0]}"
    return "none"


def prepare_mesh(scheme, mesh):
    """The scheme (``None``: the mesh's) and the mesh it analyses: a mixed mesh takes Catmull-Clark's first step exactly;
    also the new vertices that came from faces other than quads (``None`` when no step was taken)."""
    from symdecomp.schemes.meshfile import scheme_for_mesh
    from symdecomp.schemes.scheme import catmull_clark

    if scheme is None:
        sizes = mesh.face_sizes()
        scheme = scheme_for_mesh(mesh) if len(sizes) == 1 and sizes[0] in (3, 4) else catmull_clark()
    if mesh.face_sizes() != (scheme.lattice.face_sides,):  # Catmull-Clark takes any polygons by its first step
        if scheme.name != "catmull-clark":
            mesh.require_lattice(scheme.lattice, scheme.name)
        from symdecomp.schemes.polygon_step import catmull_clark_polygon_step

        step = catmull_clark_polygon_step(mesh)
        from_faces = {step.face_point[i]: i for i, f in enumerate(mesh.faces) if len(f) != 4}
        return scheme, step.mesh, from_faces
    mesh.require_lattice(scheme.lattice, scheme.name)
    return scheme, mesh, None


def _check_outputs(args) -> None:
    if args.out is not None:
        check_output_file(args.out, "--out")
        if not str(args.out).lower().endswith((".ply", ".obj")):
            raise InvalidInputError(f"--out {args.out}: give a .ply or .obj file name (the format follows the extension)")
    if args.plot is not None:
        check_output_file(args.plot, "--plot")
    if args.figures is not None:
        check_output_directory(args.figures, "--figures")
    if args.figures is not None or args.plot is not None:
        from symdecomp.cli.inspect_vertices import require_matplotlib

        require_matplotlib()


def run(args) -> int:
    from symdecomp.analysis.mesh_limits import mesh_limits
    from symdecomp.cli.inspect_outputs import json_report, print_report, verdicts, write_pictures

    _check_outputs(args)
    original = _read(args)
    scheme, mesh, from_faces = prepare_mesh(args.scheme, original)
    result = mesh_limits(mesh, scheme, exact=args.exact, progress=None if args.quiet else progress_lines)
    left_out = result.not_analysed()
    off = {v for v, o in result.kinds.outcomes.items() if not o.on_surface}  # no limit point is their computed outcome
    left_out.update({v: f"no limit point: {why}" for v, why in result.no_limit().items() if v not in off})
    if args.strict and left_out:
        v, why = next(iter(sorted(left_out.items())))
        raise InvalidMeshError(f"{mesh.name}: --strict: vertex {v} is not analysed: {why}")
    table = verdicts(scheme, result)
    status = 0 if not left_out and original.defects.is_empty() and all(
        row["tangent_plane"] is not False for row in table) else 1
    write_pictures(args, mesh, result, table)
    if not args.json:
        print_report(original, mesh, result, table, from_faces)
    details = None
    if args.vertices or args.figures is not None:
        from symdecomp.cli.inspect_vertices import vertex_details

        smooth = [int(v) for k in result.kinds.kinds if k.name == "smooth" and not k.is_regular(scheme.lattice)
                  for v in result.kinds.rings[k][0]]
        details = vertex_details(args, mesh, scheme, sorted(smooth))
    if args.json:
        data = json_report(original, mesh, result, table, from_faces, status, scheme.lattice)
        data.update(details or {})
        print_json(args, data)
    for row in table:
        if row["tangent_plane"] is False:
            print(f"symdecomp inspect: {row['kind']}: the tangents are not certified the tangent plane's ({row['reason']})",
                  file=sys.stderr)
    return status


def progress_lines(items, total: int, what: str):
    """The one place this command reports progress (a bar on a terminal; plain lines otherwise,
    :data:`symdecomp.cli.progress.PLAIN_LINE`: the label holds no colon, so a program tells them from an error)."""
    return progress(items, total, f"inspect {what}")

