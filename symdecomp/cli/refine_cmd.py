"""``symdecomp refine MESH --steps K --out OUT``: the mesh after K exact steps of a scheme, written whole.

Reads an OBJ, OFF or PLY mesh (with OpenSubdiv's crease and corner tags), takes ``--steps`` exact steps of the
scheme (:func:`~symdecomp.schemes.mesh_refine.refine_mesh`: OpenSubdiv's rules at boundaries, creases and corners;
a mesh with faces other than quads takes Catmull-Clark's first step on its polygons) and writes the refined mesh to
``--out`` (format by extension: ``.obj`` with the creases still sharp as ``t crease`` lines, ``.ply`` binary)
atomically: a regular file is replaced in one step, a FIFO or device is written, never replaced. Coordinates are
computed exactly and written as doubles with ``repr`` precision (a double reads back unchanged).

The scheme: ``--scheme`` (a name or a TOML file), else Catmull-Clark for quads or a mixed mesh and Loop for
triangles. ``--json`` prints ``{"mesh", "scheme", "steps", "vertices", "faces", "creases", "out", "bytes"}``.

``--plot FILE`` also draws the refined mesh it writes, its faces shaded and the control mesh's edges light, from a
fixed view (:mod:`symdecomp.output.plotting.refine_figure`; at most
:data:`~symdecomp.validate.MAX_REFINED_FACES` faces, an even sample of a larger mesh, as the
title says). The target is checked before the mesh is read.
"""

from __future__ import annotations

import argparse
import sys

from symdecomp.cli.common import Once, flag, integer, print_json, progress, scheme_by_name
from symdecomp.cli.files import check_output_file, write_output_file
from symdecomp.cli.plot_file import add_plot_option, check_plot, write_plot
from symdecomp.cli.progress import add_quiet_option
from symdecomp.errors import InvalidInputError
from symdecomp.validate import MAX_REFINED_FACES
from symdecomp.validate import MESH_FORMATS as FORMATS

__all__ = ["register", "run"]


def _steps(text: str) -> int:
    from symdecomp.schemes.mesh_refine import MAX_STEPS

    value = integer(text, "--steps", minimum=0, noun="a number of steps")
    if value > MAX_STEPS:
        raise argparse.ArgumentTypeError(f"expected a number of steps <= {MAX_STEPS}, got {value} (each step multiplies the faces by 4)")
    return value


def register(sub) -> None:
    p = sub.add_parser(
        "refine",
        help="refine a mesh file (OBJ, OFF, PLY) exactly by K steps of a scheme and write it",
        description="Take K exact steps of the scheme on the mesh (OpenSubdiv's rules at boundaries, creases and corners; "
        "faces other than quads take Catmull-Clark's first step) and write the refined mesh, whole, with doubles in "
        "repr precision: the surface the analysis is about.",
    )
    p.add_argument("mesh", metavar="MESH", help="the mesh file: .obj, .off or .ply")
    p.add_argument("--steps", type=_steps, action=Once, default=1, metavar="K", help="refinement steps (default 1)")
    p.add_argument("--scheme", type=scheme_by_name, action=Once, default=None, metavar="NAME|FILE",
                   help="subdivision scheme (default: catmull-clark for quads or a mixed mesh, loop for triangles)")
    p.add_argument("--format", choices=FORMATS, action=Once, default=None, help="the input format, if not its extension")
    p.add_argument("--out", action=Once, required=True, metavar="FILE", help="the refined mesh: .obj or .ply")
    flag(p, "--json", help='print {"mesh", "scheme", "steps", "vertices", "faces", "creases", "out", "bytes"}')
    add_plot_option(p, f"the refined mesh (its faces shaded, the control mesh's edges light; at most {MAX_REFINED_FACES} faces: "
                    "an even sample of a larger mesh, as the title says)")
    add_quiet_option(p)
    p.set_defaults(func=run)


def _obj_tags(refined, tags) -> str:
    """OpenSubdiv's ``t corner`` lines of the corners still sharp and ``t interpolateboundary`` when not the default."""
    def value(s):
        return 10.0 if s == float("inf") else float(s)

    lines = [f"t corner 1/1/0 {v} {value(s)!r}" for v, s in refined.corners.items()]
    if tags.interpolate_boundary != "edge-and-corner":
        lines.append(f"t interpolateboundary 1/0/0 {('none', 'edge-and-corner', 'edge-only').index(tags.interpolate_boundary)}")
    return "".join(line + "\n" for line in lines)


def run(args) -> int:
    from symdecomp.output.colored_mesh import colored_obj, colored_ply
    from symdecomp.schemes.mesh_refine import refine_mesh
    from symdecomp.schemes.meshfile import scheme_for_mesh
    from symdecomp.schemes.scheme import catmull_clark

    check_output_file(args.out, "--out")
    if not str(args.out).lower().endswith((".obj", ".ply")):
        raise InvalidInputError(f"--out {args.out}: give a .obj or .ply file name (the format follows the extension)")
    plot = check_plot(args)
    from symdecomp.schemes.meshformats import read_mesh

    mesh = read_mesh(args.mesh, args.format, progress=None if args.quiet else lambda xs, total, what: progress(xs, total, f"refine {what}"))
    scheme = args.scheme
    if scheme is None:
        sizes = mesh.face_sizes()
        scheme = scheme_for_mesh(mesh) if len(sizes) == 1 and sizes[0] in (3, 4) else catmull_clark()
    refined = refine_mesh(mesh, scheme, args.steps, progress=lambda xs, total: progress(xs, total, "refine", enabled=not args.quiet))
    points = [[float(c) for c in p] for p in refined.points]
    if str(args.out).lower().endswith(".obj"):
        content = colored_obj(points, refined.faces, creases=refined.creases) + _obj_tags(refined, mesh.tags)
    else:
        content = colored_ply(points, refined.faces)
        if refined.creases or refined.corners or mesh.tags.interpolate_boundary != "edge-and-corner":
            print(f"symdecomp refine: {args.out}: PLY holds no sharpness tags: the {len(refined.creases)} crease edges, "
                  f"{len(refined.corners)} corners and the boundary interpolation ({mesh.tags.interpolate_boundary}) "
                  "are not in it (write .obj to keep them)", file=sys.stderr)
    written = write_output_file(args.out, content, "--out")
    write_plot(plot, lambda: _figure(mesh, scheme, args.steps, points, refined.faces))
    summary = {"mesh": mesh.name, "scheme": scheme.name, "steps": args.steps, "vertices": len(refined.points),
               "faces": len(refined.faces), "creases": len(refined.creases), "out": str(args.out), "bytes": written}
    if args.json:
        print_json(args, summary)
    else:
        print(f"{mesh.name}: {args.steps} step(s) of {scheme.name}: {len(refined.points)} vertices, {len(refined.faces)} faces"
              f"{f', {len(refined.creases)} crease edges' if refined.creases else ''} -> {args.out} ({written} bytes)")
    return 0


def _figure(mesh, scheme, steps: int, points, faces):
    """The refined mesh as written (``points``: its doubles) over the control mesh ``mesh``."""
    from symdecomp.output.plotting.refine_figure import refine_figure

    return refine_figure(points, faces, mesh.points_array, mesh.faces,
                         f"{mesh.name}: {steps} step(s) of {scheme.name}, {len(faces)} faces")
