"""OpenSubdiv with boundaries, creases and corners through the bridge (``osd_bridge.cpp``).

OpenSubdiv's options (``Sdc::Options``) and tags (``Far::TopologyDescriptor``'s crease and corner
arrays) as an :class:`OsdOptions` and two mappings:

* :func:`osd_sharp_ring` -- the one-step matrix of a vertex's ring ``(O, a_0.., b_0..)`` at a
  refinement level (``Far::PrimvarRefiner`` applied to unit vectors; semi-sharp sharpness decays
  level by level as OpenSubdiv decays it) and the vertex's limit masks at that level (position
  and the two first derivatives, ``PrimvarRefiner::Limit``, the masks ``Far::LimitStencilTable``
  uses);
* :func:`osd_patch_limits` -- limit positions and first derivatives at ``(face, u, v)``
  parameters (``Far::PatchTable`` after feature-adaptive refinement, ``Far::PatchMap``);
* :func:`fan_topology` -- the fan of faces around one vertex in the ring order above.

Sharpness is a non-negative number or ``math.inf``; OpenSubdiv stores it as a float and treats
10 and above as infinite, so a finite sharpness must be below 10 and exact in a float.
OpenSubdiv's limit mask at a level is the mask of the rule its tags give at that level: with a
semi-sharp feature not yet decayed it is the crease mask, not the limit of the surface.
"""

from __future__ import annotations

import ctypes
import math
from dataclasses import dataclass
from fractions import Fraction
from itertools import accumulate

import numpy as np

from symdecomp.errors import BridgeUnavailableError, InternalError, InvalidInputError
from symdecomp.verify.opensubdiv import build as _build
from symdecomp.verify.opensubdiv import load_bridge

__all__ = ["OsdFan", "OsdOptions", "OsdSharpRing", "fan_topology", "tagged_fan", "osd_sharp_ring", "osd_patch_limits"]

_SCHEMES = {"catmull-clark": 0, "loop": 1}
_BOUNDARIES = {"none": 0, "edge-only": 1, "edge-and-corner": 2}
_CREASING = {"uniform": 0, "chaikin": 1}
#: OpenSubdiv's infinite sharpness (``Sdc::Crease::SHARPNESS_INFINITE``).
OSD_INFINITE = 10.0


@dataclass(frozen=True)
class OsdOptions:
    """OpenSubdiv's scheme and ``Sdc::Options``: ``scheme`` ``catmull-clark`` or ``loop``, ``boundary``
    ``edge-only``, ``edge-and-corner`` or ``none``, ``creasing`` ``uniform`` or ``chaikin``."""

    scheme: str = "catmull-clark"
    boundary: str = "edge-only"
    creasing: str = "uniform"

    def __post_init__(self):
        for name, table in (("scheme", _SCHEMES), ("boundary", _BOUNDARIES), ("creasing", _CREASING)):
            value = getattr(self, name)
            if not isinstance(value, str) or value not in table:
                raise InvalidInputError(f"{name} must be one of {', '.join(table)}, got {value!r}")

    @property
    def sides(self) -> int:
        """Vertices per face: 4 for Catmull-Clark, 3 for Loop."""
        return 3 if self.scheme == "loop" else 4

    def codes(self):
        return (ctypes.c_int * 3)(_SCHEMES[self.scheme], _BOUNDARIES[self.boundary], _CREASING[self.creasing])


@dataclass(frozen=True)
class OsdSharpRing:
    """OpenSubdiv's one-step matrix of a ring and the centre's limit masks (doubles)."""

    #: ``(r, r)``: row i is ring point i one level finer, in weights of the ring points.
    matrix: np.ndarray
    #: ``(r,)``: each new ring point's total weight on vertices outside the ring (zero: the ring is closed).
    leak: np.ndarray
    #: ``(3, r)``: limit position mask and OpenSubdiv's two first-derivative masks of the centre.
    masks: np.ndarray
    #: ``(3,)``: the masks' total weight outside the ring.
    masks_leak: np.ndarray


def osd_sharpness(value, what: str = "sharpness") -> float:
    """A sharpness as OpenSubdiv's float: ``math.inf`` -> 10; finite values in ``[0, 10)`` and exact in a float."""
    if isinstance(value, bool) or not isinstance(value, (int, float, Fraction)):
        raise InvalidInputError(f"{what}: the sharpness must be a number or inf, got {value!r}")
    if value == math.inf:
        return OSD_INFINITE
    if not value >= 0 or not value < OSD_INFINITE:
        raise InvalidInputError(f"{what}: the sharpness must be in [0, 10) or inf (OpenSubdiv treats 10 and above as infinite), got {value}")
    single = float(np.float32(float(value)))
    if Fraction(single) != Fraction(value):
        raise InvalidInputError(f"{what}: the sharpness {value} is not exact in OpenSubdiv's single-precision sharpness")
    return single


def _tags(creases, corners, n_vertices: int) -> list:
    """The four ctypes arrays of the crease and corner tags (vertex pairs, weights, vertices, weights)."""
    creases, corners = dict(creases or {}), dict(corners or {})
    pairs, weights = [], []
    for edge, s in creases.items():
        if not (isinstance(edge, tuple) and len(edge) == 2 and all(isinstance(v, int) and 0 <= v < n_vertices for v in edge)):
            raise InvalidInputError(f"creases: a key must be a pair of vertex indices below {n_vertices}, got {edge!r}")
        pairs += edge
        weights.append(osd_sharpness(s, f"creases[{edge}]"))
    for v in corners:
        if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v < n_vertices:
            raise InvalidInputError(f"corners: a key must be a vertex index below {n_vertices}, got {v!r}")
    corner_weights = [osd_sharpness(s, f"corners[{v}]") for v, s in corners.items()]
    return [len(weights), (ctypes.c_int * max(1, len(pairs)))(*pairs), (ctypes.c_float * max(1, len(weights)))(*weights),
            len(corners), (ctypes.c_int * max(1, len(corners)))(*corners), (ctypes.c_float * max(1, len(corners)))(*corner_weights)]


def _faces(faces, options: OsdOptions) -> tuple[int, ctypes.Array]:
    """``(number of vertices, flat face array)``, checked against the scheme's face size."""
    rows = [tuple(f) for f in faces]
    if not rows or any(len(f) != options.sides or not all(isinstance(v, (int, np.integer)) and v >= 0 for v in f) for f in rows):
        raise InvalidInputError(f"faces must be a non-empty list of {options.sides}-tuples of vertex indices for {options.scheme}")
    flat = [int(v) for f in rows for v in f]
    return max(flat) + 1, (ctypes.c_int * len(flat))(*flat)


def _entry(name: str):
    lib = load_bridge()
    try:
        return getattr(lib, name)
    except AttributeError:
        raise BridgeUnavailableError(f"the OpenSubdiv bridge has no {name}; run: {_build.REBUILD_COMMAND}") from None


def _level(level, what: str = "level") -> int:
    if isinstance(level, bool) or not isinstance(level, int) or level < 0:
        raise InvalidInputError(f"{what} must be a non-negative integer, got {level!r}")
    return level


def osd_sharp_ring(faces, center: int, ring_a, ring_faces, *, options: OsdOptions = OsdOptions(), creases=None,
                   corners=None, level: int = 0) -> OsdSharpRing:
    """OpenSubdiv's one-step matrix of the ring of ``center`` at refinement ``level``, and its limit masks.

    ``faces``: the mesh (quads for Catmull-Clark, triangles for Loop, counter-clockwise, vertices
    ``0..V-1``); ``ring_a`` the edge neighbours ``a_0..`` of ``center`` in rotational order and
    ``ring_faces`` the indices of its faces ``(O, a_j, [b_j,] a_{j+1})`` (indices of ``a`` mod its
    length; an open fan on a boundary has one face fewer than edge neighbours). ``creases`` maps
    vertex pairs to edge sharpness, ``corners`` vertices to vertex sharpness. The ring at every level
    is followed through OpenSubdiv's refinement (O's child vertex, the edge children, the child faces).
    """
    if not isinstance(options, OsdOptions):
        raise InvalidInputError(f"options must be an OsdOptions, got {type(options).__name__}")
    level = _level(level)
    n_vertices, flat = _faces(faces, options)
    ring_a, ring_faces = [int(x) for x in ring_a], [int(x) for x in ring_faces]
    if not 0 <= center < n_vertices or not ring_a or not ring_faces:
        raise InvalidInputError("center must be a vertex of the mesh with a non-empty ring")
    r = 1 + len(ring_a) + (len(ring_faces) if options.sides == 4 else 0)
    if r + 1 > 64:
        raise InvalidInputError(f"the ring has {r} points; the bridge handles at most 63")
    fn = _entry("symdecomp_osd_sharp_ring")
    ip, fp, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_float), ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ip, ctypes.c_int, ctypes.c_int, ctypes.c_int, ip, ctypes.c_int, ip, fp, ctypes.c_int, ip, fp,
                   ctypes.c_int, ctypes.c_int, ip, ctypes.c_int, ip, ctypes.c_int, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    matrix, masks = np.zeros((r, r + 1)), np.zeros((3, r + 1))
    err = ctypes.create_string_buffer(512)
    rc = fn(options.codes(), options.sides, n_vertices, len(flat) // options.sides, flat,
            *_tags(creases, corners, n_vertices), center, len(ring_a), (ctypes.c_int * len(ring_a))(*ring_a),
            len(ring_faces), (ctypes.c_int * len(ring_faces))(*ring_faces), level,
            matrix.ctypes.data_as(dp), masks.ctypes.data_as(dp), err, len(err))
    if rc != 0:
        raise InternalError(f"OpenSubdiv bridge failed (code {rc}): {err.value.decode(errors='replace')}")
    return OsdSharpRing(matrix[:, :r], matrix[:, r], masks[:, :r], masks[:, r])


def osd_patch_limits(faces, positions, queries, *, options: OsdOptions = OsdOptions(), creases=None, corners=None,
                     isolation: int = 6) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(limits, du, dv)``, each ``(Q, 3)``: OpenSubdiv's limit surface at ``queries`` ``(face, u, v)``.

    Evaluated on ``Far::PatchTable`` (feature-adaptive refinement to ``isolation`` levels,
    infinitely sharp patches, Gregory end caps, double precision) found by ``Far::PatchMap``.
    Exact (a polynomial patch of the limit) wherever the parameter's patch is regular, i.e. away
    from the ``2**-isolation`` neighbourhood of extraordinary and semi-sharp features.
    """
    if not isinstance(options, OsdOptions):
        raise InvalidInputError(f"options must be an OsdOptions, got {type(options).__name__}")
    if isinstance(isolation, bool) or not isinstance(isolation, int) or not 1 <= isolation <= 10:
        raise InvalidInputError(f"isolation must be an integer in 1..10, got {isolation!r}")
    n_vertices, flat = _faces(faces, options)
    pos = np.ascontiguousarray(positions, dtype=np.float64)
    if pos.shape != (n_vertices, 3) or not np.all(np.isfinite(pos)):
        raise InvalidInputError(f"positions must be {n_vertices} finite 3-vectors, got shape {pos.shape}")
    queries = [tuple(q) for q in queries]
    n_faces = len(flat) // options.sides
    if any(len(q) != 3 or not 0 <= int(q[0]) < n_faces or not (0 <= q[1] <= 1 and 0 <= q[2] <= 1) for q in queries):
        raise InvalidInputError(f"queries must be (face < {n_faces}, u, v) with u and v in [0, 1]")
    fn = _entry("symdecomp_osd_sharp_patch_points")
    ip, fp, dp = ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_float), ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ip, ctypes.c_int, ctypes.c_int, ctypes.c_int, ip, dp, ctypes.c_int, ip, fp, ctypes.c_int, ip, fp,
                   ctypes.c_int, ctypes.c_int, ip, dp, dp, ctypes.c_char_p, ctypes.c_int]
    fn.restype = ctypes.c_int
    q_faces = (ctypes.c_int * max(1, len(queries)))(*[int(q[0]) for q in queries])
    uv = np.ascontiguousarray([[float(q[1]), float(q[2])] for q in queries] or [[0.0, 0.0]])
    out = np.zeros((max(1, len(queries)), 9))
    err = ctypes.create_string_buffer(512)
    rc = fn(options.codes(), options.sides, n_vertices, n_faces, flat, pos.ctypes.data_as(dp),
            *_tags(creases, corners, n_vertices), isolation, len(queries), q_faces, uv.ctypes.data_as(dp),
            out.ctypes.data_as(dp), err, len(err))
    if rc != 0:
        raise InternalError(f"OpenSubdiv bridge failed (code {rc}): {err.value.decode(errors='replace')}")
    out = out[: len(queries)]
    return out[:, 0:3], out[:, 3:6], out[:, 6:9]


def fan_topology(n_faces: int, *, closed: bool, quad: bool = True):
    """``(faces, center, ring_a, ring_faces)`` of the fan of ``n_faces`` faces around vertex 0.

    Vertices: ``0`` the centre, ``1..`` the edge neighbours ``a_0..`` in counter-clockwise order,
    then (quads) the face neighbours ``b_j``; face j is ``(0, a_j, b_j, a_{j+1})`` or ``(0, a_j, a_{j+1})``.
    ``closed``: the fan goes all round (an interior, dart or crease vertex, ``n_faces`` edge
    neighbours); otherwise it is open (a boundary or corner vertex, ``n_faces + 1`` edge neighbours).
    """
    if isinstance(n_faces, bool) or not isinstance(n_faces, int) or n_faces < (2 if closed else 1):
        raise InvalidInputError(f"n_faces must be an integer >= {2 if closed else 1}, got {n_faces!r}")
    n_a = n_faces if closed else n_faces + 1
    a = list(range(1, n_a + 1))
    faces = []
    for j in range(n_faces):
        nxt = a[(j + 1) % n_a]
        faces.append((0, a[j], n_a + 1 + j, nxt) if quad else (0, a[j], nxt))
    return faces, 0, a, list(range(n_faces))


@dataclass(frozen=True)
class OsdFan:
    """A fan of faces around vertex 0 with its tags, ready for :func:`osd_sharp_ring` and :func:`osd_patch_limits`.

    Vertex ``i`` is point ``i`` of the ring order ``O, a_0.., b_0..`` (see :func:`fan_topology`).
    """

    faces: tuple
    center: int
    ring_a: tuple
    ring_faces: tuple
    creases: dict
    corners: dict

    def ring(self, options: OsdOptions, level: int = 0) -> OsdSharpRing:
        """:func:`osd_sharp_ring` of the centre at ``level``."""
        return osd_sharp_ring(self.faces, self.center, self.ring_a, self.ring_faces, options=options,
                              creases=self.creases, corners=self.corners, level=level)

    def limits(self, positions, queries, options: OsdOptions, isolation: int = 6):
        """:func:`osd_patch_limits` of the fan with ``positions`` in ring order."""
        return osd_patch_limits(self.faces, positions, queries, options=options, creases=self.creases,
                                corners=self.corners, isolation=isolation)


def tagged_fan(sectors, *, closed: bool, quad: bool = True, corner: bool = False, sharpness=math.inf) -> OsdFan:
    """The fan of a vertex whose faces are split into ``sectors`` (faces per sector, rotational order) by sharp edges.

    The sharp edges are ``(O, a_0)`` and the edge at every sector's end; on an open fan the first
    and last are the boundary edges (sharp by boundary interpolation, not tagged), the others are
    tagged with ``sharpness``. ``corner`` tags ``O`` as an infinitely sharp vertex.
    """
    sectors = tuple(sectors)
    if not sectors or any(isinstance(k, bool) or not isinstance(k, int) or k < 1 for k in sectors):
        raise InvalidInputError(f"sectors must be positive face counts, got {sectors!r}")
    faces, center, a, ring_faces = fan_topology(sum(sectors), closed=closed, quad=quad)
    ends = {0} | {total % len(a) for total in accumulate(sectors)}
    if not closed:
        ends -= {0, len(a) - 1}
    creases = {(center, a[i]): sharpness for i in sorted(ends)}
    for value in creases.values():
        osd_sharpness(value)
    return OsdFan(tuple(faces), center, tuple(a), tuple(ring_faces), creases, {center: math.inf} if corner else {})
