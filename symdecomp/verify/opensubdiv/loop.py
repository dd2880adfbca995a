"""OpenSubdiv's Loop scheme through the bridge: one refinement step and limit positions of a triangle mesh.

:func:`osd_loop_step` hands a :class:`~symdecomp.schemes.mesh.TriangleMesh` with 3-D values to
``symdecomp_osd_loop_step`` (``osd_bridge.cpp``). :func:`osd_loop_one_ring_matrix` and
:func:`osd_loop_position_mask` read OpenSubdiv's one-step matrix of the 1-ring and its limit
position mask column by column (unit vectors as positions, three columns per call), to be
compared with :func:`~symdecomp.schemes.rings.ring_subdivision_matrix` and
:func:`~symdecomp.analysis.masks.ring_masks`.
"""

from __future__ import annotations

import ctypes

from symdecomp.errors import BridgeUnavailableError
from symdecomp.schemes.mesh import TriangleMesh, triangle_ring_mesh
from symdecomp.verify.opensubdiv import load_bridge

__all__ = ["osd_loop_step", "osd_loop_one_ring_matrix", "osd_loop_position_mask", "osd_loop_tangent_masks"]


def _function(build: bool = True):
    lib = load_bridge(build)
    try:
        fn = lib.symdecomp_osd_loop_step
    except AttributeError as exc:  # an old build without the Loop entry point
        raise BridgeUnavailableError("the OpenSubdiv bridge has no Loop entry point; rebuild it") from exc
    ip, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ctypes.c_int, ctypes.c_int, ip, dp, ctypes.c_int, ip, dp, dp, dp, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    return fn


def osd_loop_step(mesh: TriangleMesh, edges, *, tangents: bool = False) -> tuple:
    """``(vertex points, edge points, limit positions)`` of one OpenSubdiv Loop step (3-D values).

    With ``tangents`` also the two limit tangents of every vertex (two more dictionaries).
    """
    fn = _function()
    ids = mesh.vertices()
    index = {v: i for i, v in enumerate(ids)}
    faces = [index[v] for f in mesh.faces for v in f]
    positions = [float(x) for v in ids for x in mesh.values[v]]
    edges = list(edges)
    flat_edges = [index[v] for e in edges for v in e]
    out_v = (ctypes.c_double * (3 * len(ids)))()
    out_l = (ctypes.c_double * (3 * len(ids)))()
    out_t1 = (ctypes.c_double * (3 * len(ids)))()
    out_t2 = (ctypes.c_double * (3 * len(ids)))()
    out_e = (ctypes.c_double * max(1, 3 * len(edges)))()
    error = ctypes.create_string_buffer(512)
    code = fn(len(ids), len(mesh.faces), (ctypes.c_int * len(faces))(*faces), (ctypes.c_double * len(positions))(*positions),
              len(edges), (ctypes.c_int * max(1, len(flat_edges)))(*flat_edges), out_v, out_e, out_l, out_t1, out_t2, error, 512)
    if code:
        raise BridgeUnavailableError(f"OpenSubdiv Loop step failed ({code}): {error.value.decode()}")
    vertex = {v: tuple(out_v[3 * i:3 * i + 3]) for i, v in enumerate(ids)}
    limit = {v: tuple(out_l[3 * i:3 * i + 3]) for i, v in enumerate(ids)}
    edge = [tuple(out_e[3 * i:3 * i + 3]) for i in range(len(edges))]
    if not tangents:
        return vertex, edge, limit
    t1 = {v: tuple(out_t1[3 * i:3 * i + 3]) for i, v in enumerate(ids)}
    t2 = {v: tuple(out_t2[3 * i:3 * i + 3]) for i, v in enumerate(ids)}
    return vertex, edge, limit, t1, t2


def _columns(n: int):
    """Batches of three 1-ring columns (O, a_0..a_{n-1}) and a 2-ring mesh putting unit vectors there."""
    size = n + 1
    for start in range(0, size, 3):
        cols = list(range(start, min(start + 3, size)))

        def value(s, u, v, cols=cols):
            j = 0 if (u, v) == (0, 0) else (1 + s if (u, v) == (1, 0) else None)
            return tuple(1.0 if j == c else 0.0 for c in cols) + (0.0,) * (3 - len(cols))

        yield cols, triangle_ring_mesh(n, 2, value)


def osd_loop_one_ring_matrix(n: int) -> list[list[float]]:
    """OpenSubdiv's one-step Loop matrix of the 1-ring ``(O, a_0..a_{n-1})`` (rows: new points)."""
    size = n + 1
    M = [[0.0] * size for _ in range(size)]
    for cols, mesh in _columns(n):
        vertex, edge, _ = osd_loop_step(mesh, [(0, 1 + i) for i in range(n)])
        for t, c in enumerate(cols):
            M[0][c] = vertex[0][t]
            for i in range(n):
                M[1 + i][c] = edge[i][t]
    return M


def osd_loop_tangent_masks(n: int) -> tuple[list[float], list[float]]:
    """OpenSubdiv's two Loop limit-tangent masks of the centre (weights of ``O, a_0..a_{n-1}``).

    OpenSubdiv's tangents are some basis of the tangent plane, so they equal the toolkit's two
    masks only up to a 2 x 2 change of basis: compare spans.
    """
    first, second = [0.0] * (n + 1), [0.0] * (n + 1)
    for cols, mesh in _columns(n):
        _, _, _, t1, t2 = osd_loop_step(mesh, [], tangents=True)
        for t, c in enumerate(cols):
            first[c], second[c] = t1[0][t], t2[0][t]
    return first, second


def osd_loop_position_mask(n: int) -> list[float]:
    """OpenSubdiv's Loop limit-position mask of the centre: weights of ``(O, a_0..a_{n-1})``."""
    mask = [0.0] * (n + 1)
    for cols, mesh in _columns(n):
        _, _, limit = osd_loop_step(mesh, [])
        for t, c in enumerate(cols):
            mask[c] = limit[0][t]
    return mask
