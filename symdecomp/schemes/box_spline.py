"""The regular Loop patch: the 12 quartic box-spline basis functions over one triangle, in Bezier form.

Over a triangle of a regular triangle mesh (every vertex of valence 6) Loop's limit surface is
a quartic polynomial (the three-direction quartic box spline) depending on the 12 control
points within one edge of the triangle's corners. This module *derives* its Bernstein-Bezier
coefficients from the scheme's rules; nothing is typed in:

1. a regular hexagonal mesh (:func:`~symdecomp.schemes.mesh.triangle_ring_mesh` at valence
   6) carries, at each vertex, its lattice position and the unit vector of its index among the
   12 control points (zero elsewhere);
2. it is refined exactly by the scheme's mesh rules
   (:func:`~symdecomp.schemes.refinement.refine_triangles`); the refined positions land on the
   finer lattice because the rules reproduce linear functions (checked: a point off the lattice
   is an error), which is how refined vertices are found;
3. the limit value of a refined vertex is the regular limit mask (the left eigenvector, for
   eigenvalue 1, of the exact 1-ring matrix :func:`~symdecomp.schemes.rings.ring_subdivision_matrix`
   at valence 6) on its 1-ring;
4. after two refinements the 15 vertices at ``(b/4, c/4)`` of the triangle are the quartic's
   domain points; the Bernstein coefficients solve the exact 15 x 15 collocation system;
5. after three refinements the quartic must reproduce all 45 limit values at ``(b/8, c/8)``
   exactly, or the scheme's regular patch is not a quartic (an error).

Layout (the API for evaluation and for the characteristic map's Jacobian):

* the triangle is ``(0, 0), (1, 0), (0, 1)`` on the lattice of the ``(u, v)`` plane (edges along
  ``(1, 0)``, ``(0, 1)`` and ``(1, -1)``); the surface point at parameter ``(u, v)`` is
  ``sum_i P_i b_i(u, v)`` for the control points ``P_i`` at :data:`BOX_POINTS` ``[i]``;
* :data:`BOX_POINTS`: the 12 lattice points, row by row (``v = -1, 0, 1, 2``), ``u`` increasing;
* the 15 coefficients of ``b_i`` are in :func:`~symdecomp.algebra.triangle_bezier.bezier_indices`
  ``(4)`` order (domain points ``(b/4, c/4)`` by ``c``, then ``b``).

>>> patch = regular_patch()
>>> patch.coefficients[BOX_POINTS.index((0, 0))][0], patch.mask
(Fraction(1, 2), (Fraction(1, 2), Fraction(1, 12)))
>>> [sum(col) for col in zip(*patch.coefficients)] == [1] * 15
True
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq, to_fraction, to_mpf, to_sympy
from symdecomp.algebra.triangle_bezier import bernstein, bezier_indices
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import TriangleMesh, triangle_ring_mesh
from symdecomp.schemes.refinement import refine_triangles, triangle_mesh_rules
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached

__all__ = ["BOX_POINTS", "DEGREE", "LATTICE_RAYS", "RegularPatch", "regular_patch", "regular_limit_mask", "refined_limits"]

#: Total degree of the regular patch.
DEGREE = 4
#: The 12 control points of the regular patch over the triangle (0,0), (1,0), (0,1), as lattice points.
BOX_POINTS = (
    (0, -1), (1, -1), (2, -1),
    (-1, 0), (0, 0), (1, 0), (2, 0),
    (-1, 1), (0, 1), (1, 1),
    (-1, 2), (0, 2),
)  # fmt: skip
#: Lattice direction of the edge ray ``s`` of :func:`~symdecomp.schemes.mesh.triangle_ring_mesh` at valence 6.
LATTICE_RAYS = ((1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1))


@dataclass(frozen=True)
class RegularPatch:
    """The regular patch of a triangle scheme: 12 basis functions, 15 exact Bezier coefficients each."""

    scheme: str
    #: ``coefficients[i][k]``: coefficient ``k`` (``bezier_indices(4)`` order) of the basis function of ``BOX_POINTS[i]``.
    coefficients: tuple[tuple[Fraction, ...], ...]
    #: The regular limit mask ``(on the vertex, on each of its 6 neighbours)``.
    mask: tuple[Fraction, Fraction]

    def matrix(self) -> flint.fmpq_mat:
        """The 12 x 15 matrix of :attr:`coefficients` (rows: control points)."""
        return flint.fmpq_mat([[to_fmpq(c) for c in row] for row in self.coefficients])

    def bezier_net(self, control) -> list:
        """The 15 Bezier coefficients of the patch with control values ``control[i]`` at ``BOX_POINTS[i]``.

        Generic: ``control`` may hold numbers, balls or numpy arrays (points); the result is
        ``[sum_i coefficients[i][k] * control[i] for k in range(15)]``.
        """
        if len(control) != len(BOX_POINTS):
            raise ValueError(f"the regular patch has {len(BOX_POINTS)} control points, got {len(control)}")
        out = []
        for k in range(len(self.coefficients[0])):
            terms = [(row[k], p) for row, p in zip(self.coefficients, control) if row[k]]
            total = terms[0][1] * _scalar(terms[0][0], terms[0][1])
            for c, p in terms[1:]:
                total = total + p * _scalar(c, p)
            out.append(total)
        return out

    def basis(self, u, v) -> list:
        """The 12 basis functions at ``(u, v)`` (floats, mpmath, numpy arrays, Fractions)."""
        bern = bernstein(DEGREE, u, v)
        out = []
        for row in self.coefficients:
            total = 0 * bern[0]
            for c, b in zip(row, bern):
                if c:
                    total = total + _scalar(c, b) * b
            out.append(total)
        return out


def _scalar(c: Fraction, like):
    """``c`` in a number type that multiplies ``like`` exactly where possible (float for numpy)."""
    mod = type(like).__module__
    if mod.startswith("numpy") or isinstance(like, float):
        return c.numerator / c.denominator
    if mod.startswith("mpmath"):

        return to_mpf(c)
    if mod.startswith("flint"):
        return to_fmpq(c)
    return c


@cached(8, scheme=check_scheme)
def regular_limit_mask(scheme: Scheme) -> tuple[Fraction, Fraction]:
    """``(on the vertex, on each neighbour)``: the left eigenvector for 1 of the regular 1-ring matrix, summing to 1."""
    ring = ring_subdivision_matrix(scheme, 6, 1)
    S = sp.zeros(ring.size, ring.size)
    for (r, c), x in ring.entries().items():
        S[r, c] = to_sympy(x)
    null = (S.T - sp.eye(ring.size)).nullspace()
    if len(null) != 1 or sum(null[0]) == 0:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: eigenvalue 1 of the regular 1-ring matrix is not simple, no limit mask")
    mask = [x / sum(null[0]) for x in null[0]]
    if len(set(mask[1:])) != 1:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the regular limit mask is not symmetric")
    return to_fraction(mask[0]), to_fraction(mask[1])


def _lattice_values(s: int, u: int, v: int) -> tuple:
    """Lattice position and unit vector (over :data:`BOX_POINTS`) of a vertex of the valence-6 ring mesh."""
    (x0, y0), (x1, y1) = LATTICE_RAYS[s % 6], LATTICE_RAYS[(s + 1) % 6]
    p = (u * x0 + v * x1, u * y0 + v * y1)
    unit = [Fraction(0)] * len(BOX_POINTS)
    if p in BOX_POINTS:
        unit[BOX_POINTS.index(p)] = Fraction(1)
    return (Fraction(p[0]), Fraction(p[1]), *unit)


def refined_limits(scheme: Scheme, level: int, mesh: TriangleMesh | None = None) -> dict:
    """``{(i, j): limit value}`` at the vertices ``(i/2^L, j/2^L)``, ``i + j <= 2^L``, of the triangle.

    ``mesh``: a valence-6 ring mesh whose values start with the two lattice coordinates (the
    default carries the 12 unit vectors of :data:`BOX_POINTS`); the limit values are the rest.
    """
    rules = triangle_mesh_rules(scheme)
    centre, each = (to_fmpq(w) for w in regular_limit_mask(scheme))
    mesh = triangle_ring_mesh(6, 3, _lattice_values) if mesh is None else mesh
    # refined in FLINT's rationals (the rules' weights at the regular valence, and the values, as fmpq): the same
    # numbers as Fractions, a fifth of the time; the limits are returned as Fractions
    mesh = TriangleMesh(mesh.faces, {v: tuple(to_fmpq(x) for x in val) for v, val in mesh.values.items()})

    def vertex_weights(valence: int) -> tuple:
        return tuple(to_fmpq(w) for w in rules.vertex_weights(valence))

    def edge_weights(valence: int) -> tuple:
        return tuple(to_fmpq(w) for w in rules.edge_weights(valence))

    for _ in range(level):
        mesh = refine_triangles(mesh, rules, vertex_weights=vertex_weights, edge_weights=edge_weights).mesh
    scale = 2**level
    at = {}
    for vid, val in mesh.values.items():
        x, y = val[0] * scale, val[1] * scale
        if x.denominator != 1 or y.denominator != 1:
            raise InvalidSchemeError(f"scheme {scheme.name!r} does not reproduce linear functions on the regular mesh")
        at[(int(x), int(y))] = vid
    out = {}
    for i in range(scale + 1):
        for j in range(scale + 1 - i):
            _, ring = mesh.one_ring(at[(i, j)])
            vals = [mesh.values[at[(i, j)]]] + [mesh.values[r] for r in ring]
            out[(i, j)] = tuple(to_fraction(centre * vals[0][k] + each * sum(p[k] for p in vals[1:])) for k in range(2, len(vals[0])))
    return out


@cached(8, scheme=lambda scheme: scheme if scheme is None else check_scheme(scheme))
def regular_patch(scheme: Scheme | None = None) -> RegularPatch:
    """The regular patch of ``scheme`` (default Loop's) over one triangle, derived by exact refinement."""
    if scheme is None:
        from symdecomp.schemes.loop import loop

        scheme = loop()
    idx = bezier_indices(DEGREE)
    limits = refined_limits(scheme, 2)
    points = [(b, c) for _, b, c in idx]
    A = flint.fmpq_mat([[to_fmpq(x) for x in bernstein(DEGREE, Fraction(b, 4), Fraction(c, 4))] for b, c in points])
    B = flint.fmpq_mat([[to_fmpq(x) for x in limits[p]] for p in points])
    X = A.solve(B)  # 15 x 12: column i holds the coefficients of basis function i
    coefficients = tuple(tuple(to_fraction(X[k, i]) for k in range(len(idx))) for i in range(len(BOX_POINTS)))
    patch = RegularPatch(scheme.name, coefficients, regular_limit_mask(scheme))
    for (i, j), want in refined_limits(scheme, 3).items():
        if patch.basis(Fraction(i, 8), Fraction(j, 8)) != list(want):
            raise InvalidSchemeError(f"scheme {scheme.name!r}: the regular limit surface is not a quartic polynomial over a triangle")
    return patch
