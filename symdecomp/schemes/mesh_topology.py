"""The checks of a polygon mesh's faces, in linear (or ``n log n``) time on numpy arrays, strict or lenient.

A mesh's faces are two arrays: ``corners`` (every face's vertex indices, one face after the other)
and ``offsets`` (face ``i`` is ``corners[offsets[i]:offsets[i + 1]]``). :func:`check_faces` runs the
checks of :mod:`symdecomp.schemes.meshfile` in its documented order. Strict, the first problem is
refused in one line (:class:`~symdecomp.errors.InvalidMeshError`); lenient, the faces a scheme
cannot take are dropped by fixed rules and listed in a :class:`~symdecomp.schemes.mesh_tags.MeshDefects`:

1. a face of fewer than 3 corners, with a repeated corner, or of zero area (degenerate);
2. a face on the same corners as an earlier kept face (repeated: the later one is dropped);
3. at every edge, the first face (in file order) is kept, and the first later face that runs
   along the edge the other way; every other face at the edge is dropped (an edge of three or
   more faces is listed as non-manifold, two faces running the same way as misoriented);
4. at a vertex where the kept faces form two or more fans, the fan of its first face is kept and
   the faces of the other fans are dropped; repeated until every vertex has one fan;
5. the vertices left in no kept face are listed as isolated (they keep their index).

The rest is a consistently oriented manifold mesh. A zero area is decided in float64 with an error
bound, and exactly (``fractions.Fraction``) only for the faces the bound cannot decide.

>>> import numpy as np
>>> pts = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1)], dtype=float)
>>> kept, defects, _ = check_faces(pts, np.array([0, 4, 7]), np.array([0, 1, 2, 3, 0, 1, 2]), strict=False)
>>> kept.tolist(), defects.misoriented_edges, defects.isolated_vertices
([0], ((0, 1), (1, 2)), (4,))
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction

import numpy as np

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_tags import MeshDefects

__all__ = ["LegacyTopology", "Topology", "check_faces", "closed_fans", "face_ids", "next_corners"]

_EPS = float(np.finfo(float).eps)


def face_ids(offsets: np.ndarray) -> np.ndarray:
    """The face of every corner."""
    return np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))


def next_corners(offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(next, prev)``: the position of the following and of the preceding corner of every corner in its face."""
    total = int(offsets[-1])
    face = face_ids(offsets)
    pos = np.arange(total)
    start, end = offsets[:-1][face], offsets[1:][face]
    nxt = np.where(pos + 1 == end, start, pos + 1)
    prv = np.where(pos == start, end - 1, pos - 1)
    return nxt, prv


def _select(offsets: np.ndarray, corners: np.ndarray, keep: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The ``(offsets, corners)`` of the faces ``keep`` (a sorted index array)."""
    sizes = np.diff(offsets)[keep]
    new_offsets = np.zeros(len(keep) + 1, dtype=np.int64)
    np.cumsum(sizes, out=new_offsets[1:])
    take = np.repeat(offsets[:-1][keep] - new_offsets[:-1], sizes) + np.arange(int(new_offsets[-1]))
    return new_offsets, corners[take]


def _fail(name: str, message: str):
    raise InvalidMeshError(f"{name}: {message}")


def _groups(offsets: np.ndarray, corners: np.ndarray, chunk: int = 1 << 18):
    """``(k, ids, rows)`` for the faces of each size ``k``, in chunks: ``rows[i]`` is face ``ids[i]``'s corners."""
    sizes = np.diff(offsets)
    for k in np.unique(sizes).tolist():
        every = np.flatnonzero(sizes == k)
        for at in range(0, len(every), max(chunk // max(k, 1), 1)):
            ids = every[at:at + max(chunk // max(k, 1), 1)]
            yield k, ids, corners[offsets[ids][:, None] + np.arange(k)]


def _degenerate(points, offsets, corners, exact_point) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(small, repeated, flat, key)`` per face: fewer than 3 corners, a repeated corner, zero area, and a hash of
    its sorted corners (equal for faces on the same corners)."""
    count = len(offsets) - 1
    small, repeated, flat = np.zeros(count, dtype=bool), np.zeros(count, dtype=bool), np.zeros(count, dtype=bool)
    key = np.zeros(count, dtype=np.uint64)
    for k, ids, rows in _groups(offsets, corners):
        if k < 3:
            small[ids] = True
            continue
        srt = np.sort(rows, axis=1)
        repeated[ids] = (srt[:, 1:] == srt[:, :-1]).any(axis=1)
        mix = np.uint64(k)
        for i in range(k):
            mix = (mix ^ srt[:, i].astype(np.uint64)) * np.uint64(0x100000001B3)
        key[ids] = mix
        p = points[rows]
        q = np.roll(p, -1, axis=1)
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):  # overflow (near 1e308) is undecided: exact
            area = np.cross(p, q).sum(axis=1)
            scale = (np.abs(p).sum(axis=2) * np.abs(q).sum(axis=2)).sum(axis=1)
            undecided = (~(np.abs(area).max(axis=1) > (k + 8) * _EPS * scale) | ~np.isfinite(scale)) & ~repeated[ids]
        for i in ids[undecided].tolist():
            flat[i] = _exactly_flat([exact_point(int(v)) for v in corners[offsets[i]:offsets[i + 1]]])
    return small, repeated, flat, key


def _exactly_flat(pts: list) -> bool:
    """Whether the vector area ``sum p_k x p_{k+1}`` is exactly zero (corners collinear, or folded flat)."""
    area = [Fraction(0)] * 3
    for p, q in zip(pts, pts[1:] + pts[:1]):
        area[0] += p[1] * q[2] - p[2] * q[1]
        area[1] += p[2] * q[0] - p[0] * q[2]
        area[2] += p[0] * q[1] - p[1] * q[0]
    return not any(area)


def _repeated_faces(offsets, corners, alive: np.ndarray, key: np.ndarray) -> np.ndarray:
    """Per face: whether it has the same corners as an earlier face among ``alive`` (hash candidates, checked exactly)."""
    out = np.zeros(len(offsets) - 1, dtype=bool)
    ids = np.flatnonzero(alive)
    order = ids[np.argsort(key[ids], kind="stable")]
    skey = key[order]
    same = np.flatnonzero(skey[1:] == skey[:-1])
    candidates = np.unique(np.concatenate((order[same], order[same + 1])))
    seen: dict = {}
    for i in candidates.tolist():
        corners_i = tuple(sorted(corners[offsets[i]:offsets[i + 1]].tolist()))
        if corners_i in seen:
            out[i] = True
        else:
            seen[corners_i] = i
    return out


def _edges(count: int, offsets, corners) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(order, group, u, w)``: the corners sorted by undirected edge (stable, so in face order within an
    edge), the edge group of each sorted corner, and every corner's directed edge ``u -> w``."""
    nxt, _ = next_corners(offsets)
    u, w = corners, corners[nxt]
    key = np.minimum(u, w) * np.int64(count) + np.maximum(u, w)
    order = np.argsort(key, kind="stable")
    skey = key[order]
    group = np.concatenate(([0], np.cumsum(skey[1:] != skey[:-1]))) if len(skey) else skey
    return order, group, u, w


def _edge_rule(count: int, offsets, corners, name: str, strict: bool):
    """Rule 3: ``(dropped faces mask, non-manifold edges, misoriented edges)`` (strict: the first one refused)."""
    faces = len(offsets) - 1
    order, group, u, w = _edges(count, offsets, corners)
    face = face_ids(offsets)[order]
    forward = (u < w)[order]
    starts = np.flatnonzero(np.concatenate(([True], group[1:] != group[:-1]))) if len(group) else group
    sizes = np.diff(np.append(starts, len(group)))
    rank = np.arange(len(group)) - starts[group]
    opposite = forward != forward[starts][group]
    first_opposite = np.full(len(starts), len(group))
    np.minimum.at(first_opposite, group[opposite], rank[opposite])
    keep = (rank == 0) | (rank == first_opposite[group])
    drop = np.zeros(faces, dtype=bool)
    drop[face[~keep]] = True
    crowded, same = sizes > 2, (sizes == 2) & (first_opposite > 1)
    pair = lambda g: (int(min(u[order][starts[g]], w[order][starts[g]])), int(max(u[order][starts[g]], w[order][starts[g]])))  # noqa: E731
    if strict and (crowded.any() or same.any()):
        _strict_edge(name, crowded, same, starts, sizes, face, order, u[order], w[order], pair)
    return drop, tuple(pair(g) for g in np.flatnonzero(crowded)), tuple(pair(g) for g in np.flatnonzero(same))


def _strict_edge(name, crowded, same, starts, sizes, face, order, u, w, pair):
    """Refuse the first non-manifold edge (by its first corner), else the misoriented edge met first (by its second face)."""
    if crowded.any():
        g = int(np.flatnonzero(crowded)[np.argmin(order[starts[crowded]])])
        fs = face[starts[g]:starts[g] + sizes[g]].tolist()
        _fail(name, f"edge {pair(g)} is shared by {len(fs)} faces {fs} (non-manifold edge)")
    g = int(np.flatnonzero(same)[np.argmin(order[starts[same] + 1])])
    a, b = starts[g], starts[g] + 1
    _fail(name, f"faces {face[a]} and {face[b]} both run along edge {u[a]} -> {w[a]} (inconsistent orientation)")


class Topology:
    """The incidences of a manifold, consistently oriented mesh, as arrays over its corners and vertices.

    ``succ[c]``: the corner at the same vertex in the next face counter-clockwise (``c`` itself where the fan
    ends at the boundary); ``by_vertex``/``vertex_start``: the corners of each vertex (CSR); ``faces_at``:
    faces per vertex; ``boundary``: whether the vertex is on a boundary edge.
    """

    def __init__(self, count: int, offsets: np.ndarray, corners: np.ndarray):
        self.offsets, self.corners = offsets, corners
        self.next, self.prev = next_corners(offsets)
        u, w = corners, corners[self.next]
        # the two corners of an edge are neighbours once sorted by the undirected edge (one sort; a search of each
        # reversed edge among the sorted directed ones cost four times as much on a million faces)
        order = np.argsort(np.minimum(u, w) * np.int64(count) + np.maximum(u, w), kind="stable")
        first, second = order[:-1], order[1:]
        pair = (u[first] == w[second]) & (w[first] == u[second])
        #: The corner starting the opposite directed edge of each corner's edge (-1 on the boundary).
        self.opposite = np.full(len(corners), -1, dtype=np.int64)
        self.opposite[first[pair]], self.opposite[second[pair]] = second[pair], first[pair]
        before = self.opposite[self.prev]
        self.succ = np.where(before >= 0, before, np.arange(len(corners)))
        self.faces_at = np.bincount(corners, minlength=count)
        self.boundary = np.zeros(count, dtype=bool)
        self.boundary[corners[self.opposite < 0]] = True
        self.boundary[corners[self.next][self.opposite < 0]] = True
        self.by_vertex = np.argsort(corners, kind="stable")
        self.vertex_start = np.zeros(count + 1, dtype=np.int64)
        np.cumsum(self.faces_at, out=self.vertex_start[1:])

    def fans(self) -> np.ndarray:
        """A label per corner, equal for the corners of one fan of faces at a vertex (pointer doubling)."""
        n = len(self.succ)
        jump, label = self.succ.copy(), np.arange(n)
        tail = self.succ == np.arange(n)
        for _ in range(max(int(np.max(self.faces_at, initial=1)), 1).bit_length() + 1):
            label = np.minimum(label, label[jump])
            jump = jump[jump]
        return np.where(tail[jump], jump, label)


def closed_fans(topo: Topology, vertices: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The corners of interior vertices of ``n`` faces each, counter-clockwise, for all of them at once.

    Row ``i`` starts at the corner of ``vertices[i]`` whose next vertex in its face is the smallest (where the
    dict-shaped walk of :class:`LegacyTopology` starts) and follows :attr:`Topology.succ`; the mask says which rows
    are one closed fan of exactly ``n`` faces (the others, on a boundary or not a single fan, are for the caller's
    vertex-by-vertex route). ``topo.corners[topo.next[rows]]`` are the edge neighbours ``a_i``.
    """
    vertices = np.asarray(vertices, dtype=np.int64)
    at = topo.by_vertex[topo.vertex_start[vertices][:, None] + np.arange(n)]  # (m, n): each vertex's corners
    start = at[np.arange(len(vertices)), np.argmin(topo.corners[topo.next[at]], axis=1)]
    rows = np.empty((len(vertices), n), dtype=np.int64)
    rows[:, 0] = start
    closes = topo.faces_at[vertices] == n
    for i in range(1, n):
        rows[:, i] = topo.succ[rows[:, i - 1]]
        closes &= rows[:, i] != start  # back at the start early: not one fan of n faces
    closes &= topo.succ[rows[:, -1]] == start
    return rows, closes


def _fan_rule(count: int, offsets, corners, name: str, strict: bool) -> tuple[np.ndarray, tuple[int, ...], Topology]:
    """Rule 4 once: ``(dropped faces mask, non-manifold vertices, the topology it was found on)``."""
    topo = Topology(count, offsets, corners)
    label = topo.fans()
    per_vertex = np.bincount(corners[label == np.arange(len(label))], minlength=count)  # one root corner per fan
    bad = np.flatnonzero(per_vertex > 1)
    if strict and len(bad):
        _fail(name, f"vertex {bad[0]} joins {per_vertex[bad[0]]} separate fans of faces (non-manifold vertex)")
    face = face_ids(offsets)
    first = topo.by_vertex[topo.vertex_start[:-1][bad]]  # each bad vertex's corner in its first face
    keep_label = np.full(count, -1)
    keep_label[bad] = label[first]
    at_bad = keep_label[corners] >= 0
    drop = np.zeros(len(offsets) - 1, dtype=bool)
    drop[face[at_bad & (label != keep_label[corners])]] = True
    return drop, tuple(int(v) for v in bad), topo


def _strict_degenerate(name, offsets, corners, small, repeated, flat) -> None:
    bad = np.flatnonzero(small | repeated | flat)
    if not len(bad):
        return
    i = int(bad[0])
    f = corners[offsets[i]:offsets[i + 1]].tolist()
    if small[i]:
        _fail(name, f"face {i} has {len(f)} corner{'s' * (len(f) != 1)}; a face needs at least 3 (degenerate face)")
    if repeated[i]:
        seen: set = set()
        _fail(name, f"face {i} repeats vertex {next(v for v in f if v in seen or seen.add(v))} (degenerate face)")
    _fail(name, f"face {i} {tuple(f)} has zero area (degenerate face)")


def check_faces(points: np.ndarray, offsets: np.ndarray, corners: np.ndarray, *, name: str = "mesh", strict: bool = True,
                exact_point=None) -> tuple[np.ndarray, MeshDefects, Topology]:
    """``(kept, defects, topology)``: the indices of the faces kept (all when ``strict``), what was left out, the
    :class:`Topology` of the kept faces.

    ``points`` is the ``(V, 3)`` float64 array, ``exact_point(v)`` the exact coordinates of vertex ``v`` (for
    the faces whose zero area floats cannot decide). Indices must already be integers in ``0..V-1``.
    """
    count = len(points)
    if len(offsets) < 2:
        _fail(name, "the mesh has no faces")
    exact_point = exact_point or (lambda v: tuple(Fraction(float(x)) for x in points[v]))
    small, repeated, flat, key = _degenerate(points, offsets, corners, exact_point)
    alive = ~(small | repeated | flat)
    if strict:
        _strict_degenerate(name, offsets, corners, small, repeated, flat)
        isolated = np.flatnonzero(np.bincount(corners, minlength=count) == 0)
        if len(isolated):
            _fail(name, f"vertex {isolated[0]} is in no face (isolated vertex)")
    twice = _repeated_faces(offsets, corners, alive, key)
    if strict and twice.any():
        i = int(np.flatnonzero(twice)[0])
        f = np.sort(corners[offsets[i]:offsets[i + 1]])
        first = next(int(j) for j in np.flatnonzero(key == key[i]) if np.array_equal(np.sort(corners[offsets[j]:offsets[j + 1]]), f))
        _fail(name, f"faces {first} and {i} have the same corners {f.tolist()} (duplicate face)")
    kept = np.flatnonzero(alive & ~twice)
    sub_offsets, sub_corners = _select(offsets, corners, kept)
    drop, crowded, same = _edge_rule(count, sub_offsets, sub_corners, name, strict)
    kept, nonmanifold = kept[~drop], []
    while True:
        sub_offsets, sub_corners = _select(offsets, corners, kept)
        drop, bad, topo = _fan_rule(count, sub_offsets, sub_corners, name, strict)
        if not bad:
            break
        nonmanifold += bad
        kept = kept[~drop]
    if not len(kept):
        _fail(name, f"no face can be kept ({_first_reason(points, offsets, corners, name, exact_point)})")
    used = np.bincount(sub_corners, minlength=count) > 0
    defects = MeshDefects(
        non_manifold_edges=crowded, misoriented_edges=same, non_manifold_vertices=tuple(sorted(set(nonmanifold))),
        degenerate_faces=tuple(np.flatnonzero(~alive).tolist()), repeated_faces=tuple(np.flatnonzero(twice).tolist()),
        isolated_vertices=tuple(np.flatnonzero(~used).tolist()),
        dropped_faces=tuple(np.flatnonzero(~np.isin(np.arange(len(offsets) - 1), kept, assume_unique=True)).tolist())
        if len(kept) < len(offsets) - 1 else ())
    return kept, defects, topo


def _first_reason(points, offsets, corners, name: str, exact_point) -> str:
    """Why the first face was left out: the strict check's line without the name."""
    try:
        check_faces(points, offsets, corners, name=name, strict=True, exact_point=exact_point)
    except InvalidMeshError as exc:
        return str(exc).removeprefix(f"{name}: ")
    return "every face was left out"  # pragma: no cover - a strict check refuses what lenient drops


class LegacyTopology(dict):
    """The incidences as the first mesh model had them (``"next"``, ``"boundary"``, ``"directed"``), each made on first
    use (:attr:`~symdecomp.schemes.meshfile.PolygonMesh._topology`); other keys are a cache of the caller's."""

    def __init__(self, topo: Topology):
        super().__init__()
        self._topo = topo

    def __missing__(self, key):
        t = self._topo
        if key == "boundary":
            value = frozenset(np.flatnonzero(t.boundary).tolist())
        elif key == "next":
            value = _NextMap(t)
        elif key == "directed":
            face = np.searchsorted(t.offsets, np.arange(len(t.corners)), side="right") - 1
            value = dict(zip(zip(t.corners.tolist(), t.corners[t.next].tolist()), face.tolist()))
        else:
            raise KeyError(key)
        self[key] = value
        return value


class _NextMap(Mapping):
    """Vertex ``v`` -> ``{a: a'}``: the next edge neighbour counter-clockwise (face ``(v, a, .., a')``); on the boundary
    the neighbour ending the fan maps to ``None``."""

    def __init__(self, topo):
        self._t = topo

    def __len__(self) -> int:
        return len(self._t.faces_at)

    def __iter__(self):
        return iter(range(len(self)))

    def __getitem__(self, v: int) -> dict:
        t = self._t
        at = t.by_vertex[t.vertex_start[v]:t.vertex_start[v + 1]]
        step = dict(zip(t.corners[t.next[at]].tolist(), t.corners[t.prev[at]].tolist()))
        if t.boundary[v]:
            step.update({b: None for b in set(step.values()) - set(step)})
        return step
