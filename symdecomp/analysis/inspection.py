"""The extraordinary vertices of a modeller's mesh: limit point and frame, and the 1-ring's polygonal decomposition.

For each interior extraordinary vertex ``O`` of a :class:`~symdecomp.schemes.meshfile.PolygonMesh` under a
scheme (:func:`inspect_mesh`, :func:`inspect_vertex`):

* **limit position**, exactly: the position mask (the left eigenvector of ``E_0`` for the eigenvalue 1,
  solved exactly; the paper's Eq. 43 matrix on quads) applied to the exact coordinates of the file. For
  Catmull-Clark it is rational, ``(n O + 4 sum a_i + sum b_i)/(n (n + 5))``-style; for Loop it has the
  square roots of ``cos(2 pi/n)``. Also as doubles.
* **tangents and normal**: the two tangent masks (:func:`~symdecomp.analysis.masks.ring_masks`,
  certified balls printed to 20 digits, then doubles; scaling as there: weight ``cos(2 pi i/n)``,
  ``sin(2 pi i/n)`` on ``a_i``) applied to the 1-ring, and the unit normal ``t_1 x t_2/|t_1 x t_2|``,
  which points to the side the faces are counter-clockwise from.
* **decomposition** (Eq. 5 on triangles, Eq. 10-11 on quads): the 1-ring relative to ``O`` read as one
  polygon with ``N`` vertices (the 2n-gon ``a_0, b_0, a_1, ..`` on quads, the n-gon of the ``a_i`` on
  triangles) is the sum of ``N`` regular polygons ``z_j v_j``; the pairs ``{j, N - j}`` are planar and each is
  two coplanar regular polygons (Eq. 6; their radii are :attr:`RingComponent.radii`). The component ``j``
  moves with the n-gon frequency ``k = j mod n`` (Eq. 12-13), and its **size** is its RMS radius
  ``sqrt(sum |z_j|^2)`` (Parseval: the sizes of all frequencies add up in squares to the mean squared
  distance of the 1-ring from ``O``). Grouped as the paper's Section 5 reads them:

  - *tangent plane*, ``k = 1, n - 1`` (Section 5.1): its size, and how much of it leaves the limit tangent
    plane (the RMS of the normal components);
  - *elliptic*, ``k = 0`` (Section 5.2): the signed heights above the tangent plane through ``O`` of the
    centroids of the ``a_i`` and (quads) of the ``b_i``, the planes of ``A^0`` and ``B^0`` of Eq. 43;
  - *hyperbolic*, ``k = 2, n - 2`` (Section 5.3): its size and its part off the tangent plane (the saddle);
    none at ``n = 3``, where ``k = 2`` is ``n - 1``, a tangent-plane frequency;
  - the rest (``3 <= k <= n - 3``).

The tangent masks are those of the dominant eigenvalue of frequency 1; a scheme where that is not the
subdominant eigenvalue has no tangent plane there (``symdecomp masks N`` says whether it is).

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> cube = PolygonMesh.from_arrays([(x, y, z) for z in (0, 2) for y in (0, 2) for x in (0, 2)],
...     [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])
>>> r = inspect_vertex(cube, 0, catmull_clark())
>>> r.limit_exact, [round(c, 12) for c in r.normal]      # the corner's limit, and the outward normal
((1/2, 1/2, 1/2), [-0.57735026919, -0.57735026919, -0.57735026919])
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp

from symdecomp.algebra.polygons import coplanar_pairs, decompose
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.frequency import ring_blocks
from symdecomp.analysis.masks import ring_masks
from symdecomp.errors import InternalError, InvalidMeshError, NotApplicableError
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached, check_valence

__all__ = ["RingComponent", "VertexInspection", "MeshInspection", "inspect_vertex", "inspect_mesh", "position_weights"]


@dataclass(frozen=True)
class RingComponent:
    """A planar component of the 1-ring polygon: the frequencies ``(j, N - j)`` (or a single ``j = 0``, ``N/2``), Eq. 6."""

    #: The polygon frequencies, ``(j, N - j)`` or ``(j,)``.
    frequencies: tuple[int, ...]
    #: The n-gon frequency ``k = j mod n`` that the scheme moves it with (``min(k, n - k)``).
    ngon_frequency: int
    #: The circumradii of the coplanar regular polygons (Eq. 6), one per frequency.
    radii: tuple[float, ...]
    #: The RMS radius of the component (``sqrt`` of the sum of ``|z_j|^2``).
    size: float
    #: The RMS of its components along the limit normal (0 when it lies in the tangent plane).
    off_plane: float


@dataclass(frozen=True)
class VertexInspection:
    """What :func:`inspect_vertex` finds at one extraordinary vertex (see the module docstring)."""

    #: The vertex index in the mesh.
    vertex: int
    #: Its valence ``n``.
    valence: int
    #: The 1-ring's vertex indices in the subdivision matrix's order: ``O, a_0..a_{n-1}`` (then ``b_0..b_{n-1}`` on quads).
    ring: tuple[int, ...]
    #: The limit position, exact (sympy numbers).
    limit_exact: tuple
    #: The limit position as doubles.
    limit: tuple[float, float, float]
    #: The tangent masks applied to the 1-ring (doubles; the masks' scaling).
    tangents: tuple[tuple[float, float, float], tuple[float, float, float]]
    #: The unit normal ``t_1 x t_2/|t_1 x t_2|`` (``None`` if the tangents are parallel: no tangent plane).
    normal: tuple[float, float, float] | None
    #: Size of the tangent-plane part (n-gon frequencies 1 and n - 1).
    tangent_size: float
    #: Its RMS along the normal.
    tangent_off_plane: float
    #: Signed heights above the tangent plane at ``O`` of the centroid of the ``a_i`` and (quads) of the ``b_i``.
    elliptic_heights: tuple[float, ...]
    #: Size of the hyperbolic part (n-gon frequencies 2 and n - 2); ``None`` at ``n = 3``.
    hyperbolic_size: float | None
    #: Its RMS along the normal (the saddle); ``None`` at ``n = 3``.
    hyperbolic_off_plane: float | None
    #: Size of the other frequencies (3 <= k <= n - 3).
    rest_size: float
    #: The planar components (Eq. 6), by frequency.
    components: tuple[RingComponent, ...]


@dataclass(frozen=True)
class MeshInspection(NotebookDisplay):
    """All extraordinary vertices of a mesh under one scheme."""

    #: The scheme's name.
    scheme: str
    #: One report per interior extraordinary vertex, in index order.
    vertices: tuple[VertexInspection, ...]
    #: Boundary vertices (not analysed: boundary rules are not part of the paper).
    skipped_boundary: tuple[int, ...]


@cached(scheme=check_scheme, n=check_valence)
def position_weights(scheme: Scheme, n: int) -> tuple[sp.Expr, ...]:
    """The exact limit-position weights ``(w_O, w_class...)``: each vertex of class ``q`` of the 1-ring gets ``w_q``.

    From ``y E_0 = y`` (``E_0`` the frequency-0 matrix of the 1-ring, exact), ``y_O = 1``, solved exactly;
    ``w_O = y_O/s`` and ``w_q = y_q/(n s)`` with ``s = sum y``, so that the ``1 + n (classes)`` weights sum to 1.
    """
    E0 = sp.Matrix(ring_blocks(scheme, 1).frequency_zero_matrix(n)) - sp.eye(1 + len(ring_blocks(scheme, 1).classes))
    K = E0.shape[0]
    # columns 1..K-1 of y (E0 - I) = 0 with y_0 = 1; column 0 then holds too (the rows of E0 sum to 1)
    system = sp.Matrix([[E0[r, c] for r in range(1, K)] for c in range(1, K)])
    rhs = sp.Matrix([-E0[0, c] for c in range(1, K)])
    if sp.simplify(system.det()) == 0:
        raise NotApplicableError(f"{scheme.name} at valence {n}: the eigenvalue 1 is not simple, so no limit position mask is defined")
    y = [sp.Integer(1)] + [sp.radsimp(sp.simplify(x)) for x in system.LUsolve(rhs)]
    if sp.simplify(sum((y[r] * E0[r, 0] for r in range(K)), sp.Integer(0))) != 0:
        raise InternalError(f"{scheme.name}, n = {n}: the position mask does not solve y E_0 = y")
    total = sp.radsimp(sp.simplify(sum(y, sp.Integer(0))))
    return (sp.radsimp(sp.simplify(y[0] / total)),) + tuple(sp.radsimp(sp.simplify(x / (n * total))) for x in y[1:])


@cached(scheme=check_scheme, n=check_valence)
def _tangent_weights(scheme: Scheme, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The two tangent masks at valence ``n`` as doubles, in the order ``O, a_0.., b_0..`` (from certified balls)."""
    masks = ring_masks(scheme, n, 1, digits=20)["tangents"]
    out = []
    for mask in masks:
        weights = [mask["O"]] + [w for key in sorted(mask["classes"]) for w in mask["classes"][key]]
        out.append(np.array([float(w) for w in weights]))
    return out[0], out[1]


def inspect_vertex(mesh: PolygonMesh, vertex: int, scheme: Scheme) -> VertexInspection:
    """Inspect one interior vertex of ``mesh`` under ``scheme`` (its faces must fit the scheme's lattice)."""
    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    scheme = check_scheme(scheme)
    ring = mesh.one_ring(vertex, scheme.lattice)
    ids = (ring[0],) + tuple(x for part in ring[1:] for x in part)
    n = len(ring[1])
    scheme.fitting_valence(n)
    limit_exact = _exact_limit(mesh, ring, position_weights(scheme, n))
    points = np.array([[float(c) for c in mesh.points[v]] for v in ids])
    t1, t2 = (tuple(float(x) for x in w @ points) for w in _tangent_weights(scheme, n))
    cross = np.cross(t1, t2)
    norm = float(np.linalg.norm(cross))
    normal = tuple(float(x) for x in cross / norm) if norm > 1e-300 else None
    parts = _decomposition(points, n, np.array(normal) if normal else np.zeros(3))
    return VertexInspection(vertex=int(vertex), valence=n, ring=ids, limit_exact=limit_exact,
                            limit=tuple(float(sp.N(x, 20)) for x in limit_exact), tangents=(t1, t2), normal=normal, **parts)


def _exact_limit(mesh: PolygonMesh, ring: tuple, weights: tuple) -> tuple:
    """``w_O O + sum_q w_q (sum of the class-q points)``: the sums in exact rationals, one product per class."""
    def rational(x: Fraction) -> sp.Rational:
        return sp.Rational(x.numerator, x.denominator)

    groups = [(ring[0],)] + [tuple(part) for part in ring[1:]]
    sums = [[sum((mesh.points[v][c] for v in group), Fraction(0)) for c in range(3)] for group in groups]
    return exact_combination(weights, [[rational(x) for x in s] for s in sums])


def exact_combination(weights, points) -> tuple:
    """``sum_k w_k p_k`` coordinate by coordinate, exactly: rational points, weights exact numbers (a rational sum is
    returned as it is, an algebraic one with its denominators made rational by ``radsimp``)."""
    limit = []
    for c in range(3):
        total = sum((w * p[c] for w, p in zip(weights, points) if w != 0), sp.Integer(0))
        limit.append(total if total.is_Rational else sp.radsimp(total))
    return tuple(limit)


def _decomposition(points: np.ndarray, n: int, normal: np.ndarray) -> dict:
    """The sizes of :class:`VertexInspection` from the 1-ring ``points`` (``O, a.., b..``) and the unit ``normal``."""
    centre, a, b = points[0], points[1 : n + 1], points[n + 1 :]
    polygon = (np.stack([a, b], axis=1).reshape(-1, 3) if len(b) else a) - centre  # Eq. 10: a_0, b_0, a_1, ...
    N = len(polygon)
    d = decompose(polygon)
    z = [np.array(d.amplitudes[j], dtype=complex) for j in range(N)]
    pairs = [(0,)] + [p for p in coplanar_pairs(N)] + ([(N // 2,)] if N % 2 == 0 else [])
    components = []
    for freq in pairs:
        radii = tuple(float(abs(c.amplitude)) for c in d.planar_pair(freq[0])[: len(freq)])
        size = math.sqrt(sum(float(np.vdot(z[j], z[j]).real) for j in freq))
        off = math.sqrt(sum(abs(complex(z[j] @ normal)) ** 2 for j in freq))
        k = freq[0] % n
        components.append(RingComponent(freq, min(k, n - k), radii, size, off))

    def total(ks, attr):
        chosen = [getattr(c, attr) for c in components if c.ngon_frequency in ks]
        return math.sqrt(sum(x * x for x in chosen))

    hyperbolic = {2} if n > 3 else set()
    heights = (float((a.mean(axis=0) - centre) @ normal),) + ((float((b.mean(axis=0) - centre) @ normal),) if len(b) else ())
    return dict(tangent_size=total({1}, "size"), tangent_off_plane=total({1}, "off_plane"), elliptic_heights=heights,
                hyperbolic_size=total(hyperbolic, "size") if hyperbolic else None,
                hyperbolic_off_plane=total(hyperbolic, "off_plane") if hyperbolic else None,
                rest_size=total(set(range(3, n // 2 + 1)), "size"), components=tuple(components))


def inspect_mesh(mesh: PolygonMesh, scheme: Scheme, *, progress=None) -> MeshInspection:
    """Inspect every interior extraordinary vertex of ``mesh`` under ``scheme``; boundary vertices are listed as skipped.

    ``progress(iterable, total)``, when given, wraps the loop over the vertices (the command line's progress bar).
    """
    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    scheme = check_scheme(scheme)
    mesh.require_lattice(scheme.lattice, scheme.name)
    chosen = mesh.extraordinary_vertices(scheme.lattice)
    loop = progress(chosen, len(chosen)) if progress is not None else chosen
    reports = tuple(inspect_vertex(mesh, v, scheme) for v in loop)
    return MeshInspection(scheme.name, reports, mesh.boundary_vertices())
