"""What ``symdecomp inspect`` prints and writes: the table by kind, its JSON, the coloured mesh and its picture.

The values ``--color-by`` colours by, per vertex: the C1 ``verdict`` and curvature ``regime`` of the vertex's kind
(words, coloured by :data:`~symdecomp.output.colored_mesh.CATEGORY_COLORS`), its ``kind`` (the index in the
table), ``valence`` (faces around it) and ``displacement`` (distance from the vertex to its limit point over the
mesh's bounding-box diagonal); numbers are coloured by a ramp and written as PLY ``quality``.
"""

from __future__ import annotations

import math
import os
import stat
import sys

import numpy as np

from symdecomp.cli.files import write_output_file
from symdecomp.validate import MAX_MESH_FILE_BYTES, MESH_ADVICE, check_memory

__all__ = ["memory_note", "verdicts", "json_report", "print_report", "write_pictures", "color_values", "row_of_vertex"]

#: Bytes of memory per byte of a mesh file, read and analysed (float coordinates, the topology, the 1-rings per kind),
#: on top of :data:`MEMORY_BASE`: measured 12.4 for a one-million-quad OBJ (66 MiB, 819 MB at its peak) and 18 for the
#: same mesh as a binary PLY (39 MiB, 710 MB); the estimate takes about a third more.
MEMORY_PER_FILE_BYTE = {"text": 16, "binary": 24}
#: What the command holds whatever the mesh (the interpreter, sympy, numpy, the kinds' exact work): about 130 MB.
MEMORY_BASE = 160 * 2**20


def memory_note(path) -> None:
    """Before reading: refuse a file whose estimated memory is past the limit, and say the estimate for a large one."""
    try:
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode):
            return  # a FIFO or a device is never opened here: the reader refuses it
        size = info.st_size
        with open(path, "rb") as fh:
            binary = b"binary" in fh.read(256)
    except (OSError, TypeError, ValueError):
        return  # the reader names the problem
    if size > MAX_MESH_FILE_BYTES:
        return  # the reader refuses it by the file bound, which is what the file is past
    estimate = MEMORY_BASE + MEMORY_PER_FILE_BYTE["binary" if binary else "text"] * size
    check_memory(estimate, f"reading {path} ({size / 2**20:.1f} MiB)", MESH_ADVICE)
    if size > 8 * 2**20:
        print(f"symdecomp inspect: reading {path} ({size / 2**20:.0f} MiB): about {estimate / 2**30:.1f} GiB of memory",
              file=sys.stderr)


def verdicts(scheme, result) -> list[dict]:
    """One row per kind: its count, C1 verdict, regime, and whether its tangents span the tangent plane."""
    from symdecomp.cli.inspect_vertices import subdominance
    from symdecomp.verify.mesh_verdicts import kind_verdict

    smooth = {k.faces for k in result.kinds.kinds if k.name == "smooth" and not k.is_regular(scheme.lattice)}
    certified = subdominance(scheme, smooth)
    rows = []
    for index, kind in enumerate(result.kinds.kinds):
        masks = result.masks[kind]
        verdict = kind_verdict(scheme, kind)
        if isinstance(masks, str):
            plane, reason = None, masks
        elif masks.tangent_plane is None:
            plane, reason = certified.get(kind.faces, (True, "the regular valence"))
        else:
            plane, reason = masks.tangent_plane, masks.reason
        rows.append({"index": index, "kind": str(kind), "name": kind.name, "faces": kind.faces, "sectors": list(kind.sectors),
                     "closed": kind.closed, "corner": kind.corner,
                     "sharpness": None if math.isinf(kind.sharpness) else str(kind.sharpness),
                     "count": int(len(result.kinds.rings[kind][0])), "c1": verdict.c1, "c1_reason": verdict.c1_reason,
                     "regime": verdict.regime, "tangent_plane": plane, "reason": reason,
                     "tangents": None if isinstance(masks, str) else list(masks.tangent_names),
                     "levels": None if isinstance(masks, str) else masks.levels, "eventual": None, "on_surface": True})
    return rows + _outcome_rows(scheme, result, len(rows))


def _outcome_rows(scheme, result, start: int) -> list[dict]:
    """One row per distinct computed outcome of the vertices of no kind (:mod:`symdecomp.analysis.mesh_outcomes`)."""
    from symdecomp.verify.mesh_verdicts import outcome_verdict

    counts: dict = {}
    for outcome in result.kinds.outcomes.values():
        counts[outcome] = counts.get(outcome, 0) + 1
    rows = []
    for index, (outcome, count) in enumerate(sorted(counts.items(), key=lambda oc: oc[0].label), start):
        verdict, kind = outcome_verdict(scheme, outcome), outcome.eventual
        fan = outcome.fan or (None, None)
        rows.append({"index": index, "kind": outcome.label, "name": kind.name if kind else "spectrum" if outcome.fan else
                     "off-surface", "faces": kind.faces if kind else fan[0], "sectors": list(kind.sectors) if kind else None,
                     "closed": kind.closed if kind else fan[1], "corner": kind.corner if kind else None, "sharpness": None,
                     "count": count, "c1": verdict.c1, "c1_reason": verdict.c1_reason, "regime": verdict.regime,
                     "tangent_plane": None, "reason": outcome.no_limit, "tangents": None, "levels": outcome.levels,
                     "eventual": None if kind is None else str(kind), "on_surface": outcome.on_surface, "outcome": outcome})
    return rows


def row_of_vertex(result, table: list[dict]) -> np.ndarray:
    """Per vertex, its row in ``table`` (``len(table)``: none, not analysed)."""
    row = np.where(result.kinds.kind_of >= 0, result.kinds.kind_of, len(table))
    index = {r["outcome"]: r["index"] for r in table if "outcome" in r}
    for v, outcome in result.kinds.outcomes.items():
        row[v] = index[outcome]
    return row


def _numbers(rows: np.ndarray) -> list[list]:
    """Rows of floats as lists, a value that is not finite as ``None``."""
    out = rows.tolist()
    for i, j in zip(*np.nonzero(~np.isfinite(rows))):
        out[i][j] = None
    return out


def json_report(original, mesh, result, table: list[dict], from_faces, status: int, lattice) -> dict:
    kinds = result.kinds
    extraordinary = []
    regular = [i for i, k in enumerate(kinds.kinds) if k.is_regular(lattice)]
    rows = row_of_vertex(result, table)
    ids = np.flatnonzero((rows < len(table)) & ~np.isin(rows, regular))
    names = [row["kind"] for row in table]
    limits, normals = _numbers(result.limits[ids]), _numbers(result.normals[ids])
    for v, k, limit, normal in zip(ids.tolist(), rows[ids].tolist(), limits, normals):
        item = {"vertex": v, "kind": names[k], "limit": limit, "normal": normal}
        if v in result.exact:
            item["limit_exact"] = [str(x) for x in result.exact[v]]
        extraordinary.append(item)
    return {"mesh": original.name, "scheme": result.scheme, "vertices": len(mesh.points), "faces": mesh.face_count,
            "refined_first": from_faces is not None,
            "from_faces": {str(v): f for v, f in (from_faces or {}).items()},
            "kinds": [{k: x for k, x in row.items() if k != "outcome"} for row in table],
            "not_analysed": {str(v): why for v, why in result.not_analysed().items()},
            "no_limit": {str(v): why for v, why in result.no_limit().items()},
            "defects": original.defects.as_dict(), "extraordinary": extraordinary, "exit_status": status}


def print_report(original, mesh, result, table: list[dict], from_faces) -> None:
    analysed = int(result.analysed().sum())
    print(f"{original.name}: {len(original.points)} vertices, {original.face_count} faces; scheme {result.scheme}; "
          f"{analysed} of {len(mesh.points)} vertices analysed in {len(result.kinds.kinds)} kinds"
          + (f", {len(result.kinds.outcomes)} with computed outcomes" if result.kinds.outcomes else ""))
    if from_faces is not None:
        print(f"faces other than quads: Catmull-Clark's first step taken exactly ({mesh.face_count} quads); "
              f"{len(from_faces)} extraordinary points came from faces: "
              + ", ".join(f"vertex {v} (face {f}, {len(original.faces[f])} sides)" for v, f in list(from_faces.items())[:8])
              + (" ..." if len(from_faces) > 8 else ""))
    print(f"{'#':>3}  {'kind':<34} {'vertices':>9}  {'C1':<10} {'curvature':<10} tangent plane")
    for row in table:
        plane = {True: "yes", False: "not certified", None: "-"}[row["tangent_plane"]]
        print(f"{row['index']:>3}  {row['kind']:<34} {row['count']:>9}  {row['c1']:<10} {row['regime']:<10} {plane}")
    no_limit = result.no_limit()
    if no_limit:
        lacking: dict[str, list[int]] = {}
        for v, why in no_limit.items():
            lacking.setdefault(why, []).append(v)
        for why, vs in lacking.items():
            print(f"no limit point: {len(vs)} vertices ({', '.join(map(str, vs[:10]))}{' ...' if len(vs) > 10 else ''}): {why}")
    left = result.not_analysed()
    if left:
        reasons: dict[str, list[int]] = {}
        for v, why in left.items():
            reasons.setdefault(why, []).append(v)
        for why, vs in reasons.items():
            print(f"not analysed: {len(vs)} vertices ({', '.join(map(str, vs[:10]))}{' ...' if len(vs) > 10 else ''}): {why}")
    if not original.defects.is_empty():
        parts = [f"{len(v)} {k.replace('_', ' ')}" for k, v in original.defects.as_dict().items() if v]
        print(f"left out of the file: {', '.join(parts)}")
    edits = original.defects.hierarchical_edits
    if edits:
        print(f"hierarchical edits left out (lines {', '.join(str(line) for line, _ in edits)}; acting from level "
              f"{min(level for _, level in edits)} on): the analysis is of the unedited surface of the control mesh")


def color_values(result, table: list[dict], what: str, points: np.ndarray) -> np.ndarray:
    """Per vertex, the value ``--color-by what`` colours by (words or numbers; see the module docstring)."""
    row = row_of_vertex(result, table)
    if what in ("verdict", "regime"):
        key = "c1" if what == "verdict" else "regime"
        words = np.array([r[key] for r in table] + ["not analysed"], dtype=object)
        return words[row]
    if what == "kind":
        return np.where(row < len(table), row, np.nan).astype(np.float64)
    if what == "valence":
        faces = np.array([np.nan if r["faces"] is None else r["faces"] for r in table] + [np.nan], dtype=np.float64)
        return faces[row]
    size = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))) or 1.0
    return np.linalg.norm(result.limits - points, axis=1) / size


def write_pictures(args, mesh, result, table: list[dict]) -> None:
    """``--out`` (coloured PLY or OBJ, written whole) and ``--plot`` (PNG)."""
    if args.out is None and args.plot is None:
        return
    from symdecomp.analysis.mesh_limits import float_points
    from symdecomp.output.colored_mesh import colored_obj, colored_ply, vertex_colors

    points = float_points(mesh)
    values = color_values(result, table, args.color_by, points)
    colors = vertex_colors(values)
    if args.out is not None:
        quality = values if values.dtype.kind == "f" else np.array([{"c1": 1.0, "bounded": 1.0, "zero": 0.5}.get(v, 0.0)
                                                                    for v in values])
        content = colored_obj(points, mesh.faces, colors) if str(args.out).lower().endswith(".obj") else \
            colored_ply(points, mesh.faces, colors, quality)
        write_output_file(args.out, content, "--out")
    if args.plot is not None:
        from symdecomp.output.plotting.meshes import colored_mesh_figure, png_bytes

        figure = colored_mesh_figure(points, mesh.faces, colors, f"{mesh.name}: coloured by {args.color_by}")
        write_output_file(args.plot, png_bytes(figure), "--plot")
