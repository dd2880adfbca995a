"""An independent reference for the zoo's families: each refined on an explicit mesh, written from the papers.

Nothing of the toolkit is imported: meshes are lists of faces (tuples of vertex labels, counter-clockwise), a
point is its coefficient vector over the points of the old mesh (numpy), and each family's rules are written
here as the papers state them (not as halfedge walks). The subdivision matrix of the neighbourhood of an
extraordinary element is read off with this module's own identification of the new neighbourhood with the old:

* the disk around a vertex of valence ``n`` is ``n`` sectors, each a piece of the regular lattice; sector ``s``
  holds the points ``(s, a, b)`` (``a`` along ray ``s``, ``b`` along ray ``s + 1``), ``(s, 0, b)`` is
  ``(s + 1, b, 0)``, the centre is ``"c"``;
* a dyadic step doubles the coordinates: the new point ``(s, A, B)`` is the old vertex ``(s, A/2, B/2)`` when both
  are even, else the point of the old edge whose midpoint ``(A/2, B/2)`` is; a dual step's new points are the
  corners of the old faces, labelled by the refined lattice's cells, which is how the new n-gon and its
  neighbours are identified with the old (a cell ``(s, a, b)`` is the face with lower corner ``(s, a, b)``);
* sqrt(3)'s two steps turn the lattice by a whole sector's half twice: after them the face point of the
  triangle made at the centre from the old edge towards ``p_s`` lies in ``p_s``'s direction and takes its label.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

CENTRE = "c"


def _canonical(n: int, label):
    if label == CENTRE:
        return label
    s, a, b = label
    if a == 0 and b == 0:
        return CENTRE
    if a == 0:
        return ((s + 1) % n, b, 0)
    return (s % n, a, b)


def quad_disk(n: int, cells: int) -> list[tuple]:
    """The faces of ``cells`` x ``cells`` quads in each of ``n`` sectors around a vertex of valence ``n``."""
    faces = []
    for s in range(n):
        for a in range(cells):
            for b in range(cells):
                corners = ((s, a, b), (s, a + 1, b), (s, a + 1, b + 1), (s, a, b + 1))
                faces.append(tuple(_canonical(n, p) for p in corners))
    return faces


def triangle_disk(n: int, rings: int) -> list[tuple]:
    """The faces of ``rings`` rings of triangles in each of ``n`` sectors around a vertex of valence ``n``."""
    faces = []
    for s in range(n):
        for a in range(rings):
            for b in range(rings - a):
                faces.append(tuple(_canonical(n, p) for p in ((s, a, b), (s, a + 1, b), (s, a, b + 1))))
                if a + b <= rings - 2:
                    faces.append(tuple(_canonical(n, p) for p in ((s, a + 1, b), (s, a + 1, b + 1), (s, a, b + 1))))
    return faces


class Mesh:
    """A polygon mesh as faces; its halfedges ``(u, v)`` found by dictionary, its rings ordered counter-clockwise."""

    def __init__(self, faces):
        self.faces = [tuple(f) for f in faces]
        self.left = {}
        for index, face in enumerate(self.faces):
            for i, u in enumerate(face):
                self.left[(u, face[(i + 1) % len(face)])] = index
        self.vertices = sorted({v for f in self.faces for v in f}, key=repr)

    def previous(self, face: int, v) -> object:
        f = self.faces[face]
        return f[f.index(v) - 1]

    def faces_around(self, v, start_face: int | None = None) -> list[int] | None:
        """The faces around ``v`` counter-clockwise, or None when ``v`` is on the boundary."""
        first = start_face if start_face is not None else next(i for i, f in enumerate(self.faces) if v in f)
        out, face = [], first
        while True:
            out.append(face)
            u = self.previous(face, v)
            face = self.left.get((v, u))  # the face across the edge v-u, counter-clockwise around v
            if face is None:
                return None
            if face == first:
                return out

    def ring(self, v, first) -> list | None:
        """The neighbours of ``v`` counter-clockwise from ``first``, or None on the boundary."""
        faces = self.faces_around(v, self.left[(v, first)])
        if faces is None:
            return None
        return [self.faces[f][(self.faces[f].index(v) + 1) % len(self.faces[f])] for f in faces]


def _unit(labels) -> dict:
    return {v: np.eye(len(labels))[i] for i, v in enumerate(labels)}


def doo_sabin_weights(m: int) -> list[float]:
    """Doo and Sabin's weights on an m-gon's corners for the new point at corner 0 (``j`` counted round the face)."""
    return [(j == 0) / 4 + (3 + 2 * math.cos(2 * math.pi * j / m)) / (4 * m) for j in range(m)]


def midedge_weights(m: int) -> list[float]:
    """Two mid-edge steps: the midpoint of the midpoints of a corner's two edges."""
    return [0.5 if j == 0 else 0.25 if j in (1, m - 1) else 0.0 for j in range(m)]


def corner_mean_weights(m: int) -> list[float]:
    """The guide's sixth family (``docs/guide/adding-a-scheme.md``): the new point at corner 0 is the mean of four
    points, the corner, the midpoints of its two edges and the face's centroid."""
    centroid = [1 / m] * m
    corner = [1.0 if j == 0 else 0.0 for j in range(m)]
    midpoints = [(j == 0) + 0.5 * (j in (1, m - 1)) for j in range(m)]  # (p_0 + p_1)/2 + (p_0 + p_(m-1))/2
    return [(corner[j] + midpoints[j] + centroid[j]) / 4 for j in range(m)]


def dual_matrix(n: int, weights) -> tuple[np.ndarray, list]:
    """The subdivision matrix of a dual scheme at an n-gon: old and new points are the cells ``(s, a, b)``,
    ``a, b`` in 0..1 (4n points), of the quad disk whose dual mesh the scheme refines.

    The dual mesh's vertices are the quad disk's cells and its faces are the quad disk's interior vertices; the
    new point at the corner (dual face = vertex V, dual vertex = cell C) is the weighted sum over the cells round
    V, counter-clockwise from C. The new cell ``(s, A, B)`` lies in old cell ``(s, A//2, B//2)`` at its corner
    ``(s, A//2 + A%2, B//2 + B%2)``.
    """
    quads = quad_disk(n, 3)
    primal = Mesh(quads)
    cell_of = {face: (s, a, b) for face, (s, a, b) in zip(quads, [(s, a, b) for s in range(n) for a in range(3) for b in range(3)])}
    labels = [(s, a, b) for s in range(n) for a in range(2) for b in range(2)]
    all_cells = [cell_of[f] for f in quads]
    unit = _unit(all_cells)
    rows = []
    for s, A, B in labels:
        cell = (s, A // 2, B // 2)
        corner = _canonical(n, (s, A // 2 + A % 2, B // 2 + B % 2))
        face_index = quads.index(next(f for f in quads if cell_of[f] == cell))
        around = primal.faces_around(corner, face_index)
        w = weights(len(around))
        # j counts the dual face's corners from C; around V the primal faces run counter-clockwise, as the dual face does
        rows.append(sum(w[j] * unit[cell_of[primal.faces[f]]] for j, f in enumerate(around)))
    full = np.array(rows)
    keep = [all_cells.index(c) for c in labels]
    outside = np.delete(full, keep, axis=1)
    assert np.abs(outside).max() == 0, "the n-gon's neighbourhood is not closed under the step"
    return full[:, keep], labels


def _sqrt3_step(mesh: Mesh, points: dict) -> tuple[Mesh, dict]:
    """One sqrt(3) step (Kobbelt 2000): a point at each triangle's centroid, each interior vertex relaxed with
    alpha_n = (4 - 2 cos(2 pi/n))/9, and the old edges flipped: one new triangle (u, c_right, c_left) per halfedge."""
    new_points = {}
    for index, face in enumerate(mesh.faces):
        if all(v in points for v in face):
            new_points[("f", index)] = sum(points[v] for v in face) / 3
    for v in mesh.vertices:
        first = next(f for f in mesh.faces if v in f)
        ring = mesh.ring(v, first[(first.index(v) + 1) % 3])
        if ring is None or not all(u in points for u in ring) or v not in points:
            continue
        n = len(ring)
        alpha = (4 - 2 * math.cos(2 * math.pi / n)) / 9
        new_points[("v", v)] = (1 - alpha) * points[v] + alpha / n * sum(points[u] for u in ring)
    faces = []
    for (u, v), left in mesh.left.items():
        right = mesh.left.get((v, u))
        if right is not None:
            faces.append((("v", u), ("f", right), ("f", left)))
    return Mesh(faces), new_points


def sqrt3_matrix(n: int) -> np.ndarray:
    """Two sqrt(3) steps on the 1-ring ``(c, p_0..p_(n-1))``, ``p_s = (s, 1, 0)``: new ``c`` and the face points
    of the first step's triangles at ``c`` made from the edges ``c-p_s`` (in ``p_s``'s direction)."""
    mesh = Mesh(triangle_disk(n, 3))
    points = _unit(mesh.vertices)
    once, points1 = _sqrt3_step(mesh, points)
    twice, points2 = _sqrt3_step(once, points1)
    ring = [(s, 1, 0) for s in range(n)]
    triangles = {f: i for i, f in enumerate(once.faces)}
    rows = [points2[("v", ("v", CENTRE))]]
    for p in ring:  # the triangle made at c from the halfedge c -> p: (c, the face right of it, the face left of it)
        made = (("v", CENTRE), ("f", mesh.left[(p, CENTRE)]), ("f", mesh.left[(CENTRE, p)]))
        rows.append(points2[("f", triangles[made])])
    full = np.array(rows)
    keep = [mesh.vertices.index(v) for v in [CENTRE, *ring]]
    assert np.abs(np.delete(full, keep, axis=1)).max() < 1e-15, "the 1-ring is not closed under two steps"
    return full[:, keep]


def sqrt3_two_ring_matrix(n: int) -> np.ndarray:
    """Two sqrt(3) steps on the 2-ring: the 1-ring of :func:`sqrt3_matrix`, then ``(s, 2, 0)`` (the neighbour of
    ``p_s`` opposite the centre, three places round its ring of six) and ``(s, 1, 1)`` (the neighbour ``p_s`` and
    ``p_(s+1)`` share besides the centre), found the same way round the new centre and its new ring."""
    mesh = Mesh(triangle_disk(n, 6))
    points = _unit(mesh.vertices)
    once, points1 = _sqrt3_step(mesh, points)
    twice, points2 = _sqrt3_step(once, points1)
    triangles = {f: i for i, f in enumerate(once.faces)}

    def two_ring(m: Mesh, centre, ring: list) -> list:
        beyond = [m.ring(p, centre)[3] for p in ring]
        shared = [next(u for u in m.ring(ring[s], centre) if u != centre and u not in ring and u in m.ring(ring[(s + 1) % n], centre))
                  for s in range(n)]
        return [centre, *ring, *beyond, *shared]

    old = two_ring(mesh, CENTRE, [(s, 1, 0) for s in range(n)])
    new_ring = [("f", triangles[(("v", CENTRE), ("f", mesh.left[((s, 1, 0), CENTRE)]), ("f", mesh.left[(CENTRE, (s, 1, 0))]))])
                for s in range(n)]
    new = two_ring(twice, ("v", ("v", CENTRE)), new_ring)
    assert old[1 + n:1 + 2 * n] == [(s, 2, 0) for s in range(n)] and old[1 + 2 * n:] == [(s, 1, 1) for s in range(n)]
    full = np.array([points2[v] for v in new])
    keep = [mesh.vertices.index(v) for v in old]
    assert np.abs(np.delete(full, keep, axis=1)).max() < 1e-15, "the 2-ring is not closed under two steps"
    return full[:, keep]


def _butterfly_weights(k: int) -> list[float]:
    """Zorin, Schroeder and Sweldens' weights s_j on the neighbours of an end of valence k != 6 (e_0 the other end)."""
    if k == 3:
        return [5 / 12, -1 / 12, -1 / 12]
    if k == 4:
        return [3 / 8, 0.0, -1 / 8, 0.0]
    return [(1 / 4 + math.cos(2 * math.pi * j / k) + math.cos(4 * math.pi * j / k) / 2) / k for j in range(k)]


def _opposite(mesh: Mesh, u, v):
    """The vertex of the triangle left of u -> v that is neither u nor v."""
    face = mesh.faces[mesh.left[(u, v)]]
    return next(w for w in face if w not in (u, v))


def butterfly_edge_point(mesh: Mesh, points: dict, u, v):
    """The modified butterfly's new point on the edge u-v (None when its stencil leaves the mesh)."""
    rings = {x: mesh.ring(x, y) for x, y in ((u, v), (v, u))}
    if any(r is None for r in rings.values()):
        return None
    ends = [x for x in (u, v) if len(rings[x]) != 6]
    if ends:  # from each extraordinary end: 3/4 on it and s_j on its ring from the other end; both: the average
        return sum(0.75 * points[x] + sum(w * points[y] for w, y in zip(_butterfly_weights(len(rings[x])), rings[x]))
                   for x in ends) / len(ends)
    a, b = _opposite(mesh, u, v), _opposite(mesh, v, u)
    wings = [_opposite(mesh, x, y) for x, y in ((a, v), (u, a), (b, u), (v, b))]  # across the four outer edges
    return (points[u] + points[v]) / 2 + (points[a] + points[b]) / 8 - sum(points[w] for w in wings) / 16


def _old_edge(n: int, s: int, A: int, B: int):
    """The old vertex or the ends of the old edge at the doubled coordinates (s, A, B) of the triangle disk."""
    if A % 2 == 0 and B % 2 == 0:
        return (_canonical(n, (s, A // 2, B // 2)),)
    if A % 2 and B % 2:
        ends = ((s, (A + 1) // 2, (B - 1) // 2), (s, (A - 1) // 2, (B + 1) // 2))
    elif A % 2:
        ends = ((s, (A - 1) // 2, B // 2), (s, (A + 1) // 2, B // 2))
    else:
        ends = ((s, A // 2, (B - 1) // 2), (s, A // 2, (B + 1) // 2))
    return tuple(_canonical(n, e) for e in ends)


def butterfly_matrix(n: int) -> np.ndarray:
    """The modified butterfly on the 2-ring ``(c; (s,1,0), (s,2,0), (s,1,1) for each s)``, new labels at doubled coordinates."""
    mesh = Mesh(triangle_disk(n, 5))
    points = _unit(mesh.vertices)
    labels = [CENTRE] + [(s, a, b) for s in range(n) for a, b in ((1, 0), (2, 0), (1, 1))]
    rows = []
    for label in labels:
        old = (CENTRE,) if label == CENTRE else _old_edge(n, *label)
        rows.append(points[old[0]] if len(old) == 1 else butterfly_edge_point(mesh, points, *old))
    full = np.array(rows)
    keep = [mesh.vertices.index(v) for v in labels]
    assert np.abs(np.delete(full, keep, axis=1)).max() < 1e-15, "the 2-ring is not closed under a step"
    return full[:, keep]


def four_point_line_matrix(k: int, w: Fraction = Fraction(1, 16)) -> list[list[Fraction]]:
    """The four-point scheme's step on the points ``-k..k`` of a line around a vertex, exactly.

    A new point at an even index ``2l`` is the old point ``l`` (the scheme interpolates), at ``2l + 1`` it is
    ``(1/2 + w)(p_l + p_(l+1)) - w (p_(l-1) + p_(l+2))``; the points ``-k..k`` are closed under a step for ``k >= 3``.
    """
    rows = [[Fraction(0)] * (2 * k + 1) for _ in range(2 * k + 1)]
    for i in range(-k, k + 1):
        if i % 2 == 0:
            rows[i + k][i // 2 + k] = Fraction(1)
            continue
        for d, weight in ((-1, -w), (0, Fraction(1, 2) + w), (1, Fraction(1, 2) + w), (2, -w)):
            rows[i + k][(i - 1) // 2 + d + k] += weight
    return rows


def tensor_product(a: list[list[Fraction]], b: list[list[Fraction]]) -> list[list[Fraction]]:
    """The Kronecker product: the step of the tensor-product scheme on the grid of the two lines' points."""
    return [[x * y for x in row_a for y in row_b] for row_a in a for row_b in b]


def spectrum(matrix: np.ndarray) -> list[complex]:
    """The eigenvalues, largest modulus first."""
    return sorted(np.linalg.eigvals(matrix), key=lambda z: (-abs(z), -z.real))
