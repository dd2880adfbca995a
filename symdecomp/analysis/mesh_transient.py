"""Limit points of transient vertices: exact refinement of the vertex's neighbourhood until its tags have decayed.

A transient vertex (:mod:`symdecomp.analysis.mesh_outcomes`: a semi-sharp vertex tag, sharp edges of different
sharpness) is refined by the rules its tags give for :attr:`~symdecomp.analysis.mesh_outcomes.Outcome.levels` levels,
and is of its eventual kind from then on. :func:`transient_frame` cuts the vertex's 2-ring out of the mesh (the
faces at its 1-ring's vertices: every point of the child's 2-ring is computed from it, Chaikin's edge rule included,
which looks at both ends of an edge), refines it exactly with OpenSubdiv's semantics
(:func:`~symdecomp.schemes.tagged_refinement.refine_tagged`), cuts the child's 2-ring out again, level by level, and
applies the eventual kind's masks (:func:`~symdecomp.analysis.mesh_limits.kind_masks`) to the child's ordered 1-ring.
The kind found at the last level is checked to be the eventual kind the decay predicted.

>>> from symdecomp.schemes.meshformats import decode_mesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.analysis.mesh_kinds import classify_vertices
>>> cube = decode_mesh(b"v 0 0 0\\nv 2 0 0\\nv 0 2 0\\nv 2 2 0\\nv 0 0 2\\nv 2 0 2\\nv 0 2 2\\nv 2 2 2\\n"
...     b"f 1 3 4 2\\nf 5 6 8 7\\nf 1 2 6 5\\nf 3 7 8 4\\nf 1 5 7 3\\nf 2 4 8 6\\nt corner 1/1/0 0 1.5\\n", "obj")
>>> outcome = classify_vertices(cube, catmull_clark().lattice).outcomes[0]
>>> str(outcome.eventual), outcome.levels
('smooth n = 3', 2)
>>> frame = transient_frame(cube, catmull_clark(), 0, outcome)
>>> [round(float(x), 12) for x in frame[0]]
[0.276041666667, 0.276041666667, 0.276041666667]
"""

from __future__ import annotations

import math

import numpy as np

from symdecomp.errors import InvalidMeshError

__all__ = ["transient_frame"]


def _options(mesh):
    from symdecomp.schemes.sharp import SharpOptions

    boundary = mesh.tags.interpolate_boundary
    return SharpOptions("edge-and-corner" if boundary == "edge-and-corner" else "edge-only", mesh.tags.crease_method)


def _piece(source, v: int, real_boundary: frozenset, edge_sharpness, vertex_sharpness):
    """The 2-ring of ``v`` in ``source`` (a local mesh) as a :class:`~symdecomp.schemes.tagged_refinement.TaggedMesh`."""
    from symdecomp.schemes.tagged_refinement import TaggedMesh

    ring = {x for fi in source.faces_of(v) for x in source.faces[fi]}
    faces = {fi for x in ring for fi in source.faces_of(x)}
    while True:  # a small closed mesh can pinch the piece at an outer vertex: take that vertex's whole fan too
        rows = tuple(source.faces[fi] for fi in sorted(faces))
        corners = {x for f in rows for x in f}
        mesh = type(source)(rows, {x: source.values[x] for x in corners})
        pinched = [x for x in corners if _pinched(mesh, x)]
        if not pinched:
            break
        faces |= {fi for x in pinched for fi in source.faces_of(x)}
    edges = {frozenset(p) for f in rows for p in zip(f, f[1:] + f[:1])}
    sharp = {e: s for e in edges if (s := edge_sharpness(e)) > 0}
    cut = frozenset(e for e in TaggedMesh(mesh).boundary_edges(all_edges=True) if e not in real_boundary)
    return TaggedMesh(mesh, sharp, {x: s for x in corners if (s := vertex_sharpness(x)) > 0}, cut)


def _pinched(mesh, x: int) -> bool:
    """Whether the faces at ``x`` in ``mesh`` make more than one fan."""
    nxt = {}
    for fi in mesh.faces_of(x):
        f = mesh.faces[fi]
        k = f.index(x)
        nxt[f[(k + 1) % len(f)]] = f[k - 1]
    return len(set(nxt) - set(nxt.values())) > 1


def _level0(mesh, lattice, v: int):
    """The 2-ring of ``v`` in the file's mesh, with the file's tags."""
    from symdecomp.schemes.sharp import check_sharpness

    local = mesh.local_mesh(lattice)
    t = mesh._topo
    rim = np.flatnonzero(t.opposite < 0)
    real = frozenset(frozenset(p) for p in zip(t.corners[rim].tolist(), t.corners[t.next[rim]].tolist()))
    return _piece(local, v, real, lambda e: check_sharpness(mesh.tags.sharpness_of_edge(*e)),
                  lambda x: check_sharpness(mesh.tags.corners.get(x, 0)))


def _ordered_ring(tagged, v: int, boundary: str):
    """The child's kind (as :mod:`~symdecomp.analysis.mesh_kinds` names it) and its 1-ring in the masks' order."""
    from symdecomp.analysis.mesh_kinds import _kind_of
    from symdecomp.schemes.tagged_refinement import vertex_fan

    fan = vertex_fan(tagged, v)
    sharp = [tagged.sharpness(v, a) for a in fan.edges]
    faces = len(fan.between)
    kind = _kind_of(boundary, faces, sharp, tagged.vertex_sharpness.get(v, 0), fan.closed)
    if not isinstance(kind, tuple):
        raise InvalidMeshError(f"vertex {v} after refinement: {kind}")  # pragma: no cover - the decay predicts a kind
    kind, start = kind
    edges, between = list(fan.edges), list(fan.between)
    if fan.closed and start:
        edges, between = edges[start:] + edges[:start], between[start:] + between[:start]
    return kind, [v] + edges + [x for rest in between for x in rest]


def transient_frame(mesh, scheme, v: int, outcome) -> tuple[np.ndarray, np.ndarray, np.ndarray] | str:
    """``(limit, unit normal, the two tangents)`` of the transient vertex ``v`` (module docstring), or why not."""
    from symdecomp.analysis.mesh_limits import apply_masks, kind_masks
    from symdecomp.errors import NotApplicableError
    from symdecomp.schemes.tagged_refinement import refine_tagged

    options = _options(mesh)
    tagged = _level0(mesh, scheme.lattice, v)
    for level in range(outcome.levels):
        refined, _, ids = refine_tagged(tagged, scheme, options)
        v = ids[("vertex", v)]
        if level + 1 < outcome.levels:
            edges, corners = refined.edge_sharpness, refined.vertex_sharpness
            tagged = _piece(refined.mesh, v, refined.boundary_edges(), lambda e, d=edges: d.get(e, 0),
                            lambda x, d=corners: d.get(x, 0))
        else:
            tagged = refined
    kind, ring = _ordered_ring(tagged, v, mesh.tags.interpolate_boundary)
    if kind != outcome.eventual:
        return f"after {outcome.levels} levels the vertex is a {kind}, not the {outcome.eventual} its decay predicts"
    try:
        masks = kind_masks(scheme, kind)
    except NotApplicableError as exc:
        return f"{kind}: {exc}"
    points = np.array([[float(c) for c in tagged.mesh.values[x]] for x in ring])
    edge_count = kind.faces + (0 if kind.closed else 1)
    limit, normal, tangents = apply_masks(points, np.arange(len(ring))[None, :], masks, edge_count)
    if not math.isfinite(float(limit[0].sum())):
        return "its 1-ring's coordinates overflow double precision in the masks"
    return limit[0], normal[0], tangents[0]
