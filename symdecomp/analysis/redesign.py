"""The least change of a measured 1-ring that gives its limit a prescribed normal and/or no hyperbolic part.

Given the 1-ring ``P`` of a vertex of a mesh (:func:`redesign_vertex`), the constraints are linear in the heights
``h = P . N`` along the target normal ``N``: the limit normal is parallel to ``N`` when both tangent masks
(the real and imaginary parts of the frequency-1 left eigenvector ``Y_q omega^(-s)``) give ``t . N = 0``; the
hyperbolic part vanishes when the frequency-2 functionals ``omega^(-2s)`` on each class give 0 (all of the
heights' n-gon frequency 2 and n - 2: the dominant eigencomponent of ``M_2``, whose coefficient is the limit's
hyperbolic amount, and the faster-decaying one, so that ``symdecomp inspect`` sees no saddle either). Moving the points along
``N`` changes nothing else those functionals see, so the least change in the Euclidean norm of the ring's points is
``dh = -G^T (G G^T)^(-1) G h`` along ``N`` (``G`` the constraint rows): an orthogonal projection, which in the
orthogonal Fourier basis of each class changes only the frequencies 1, 2, n - 2, n - 1. The eigenvectors are
the ones :mod:`symdecomp.analysis.design` builds with (40 digits); the new points are rounded to doubles, so the
normal is met to double precision (exactly would need the points in ``Q(zeta_n, lambda_1)``).

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> from symdecomp.schemes.scheme import catmull_clark
>>> cube = PolygonMesh.from_arrays([(x, y, z) for z in (0, 2) for y in (0, 2) for x in (0, 2)],
...     [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])
>>> d = redesign_vertex(catmull_clark(), cube, 0, normal=(-1, -1, -2))
>>> [round(x, 12) for x in d.achieved.normal], round(d.change, 6)
([-0.408248290464, -0.408248290464, -0.816496580928], 0.863461)
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath

from symdecomp.analysis.design import _DPS, RingDesign, _classes, _dominant, _frequency_matrix, limit_frame
from symdecomp.analysis.design_input import check_ring_scale, dot, frame
from symdecomp.errors import InvalidInputError, InvalidMeshError, NotApplicableError
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import Scheme, check_scheme

__all__ = ["redesign_vertex"]


def _functionals(scheme: Scheme, n: int, j: int, Y) -> list[list]:
    """The real and imaginary parts of the ring functional ``Y_q omega^(-j s)`` (0 on ``O``), 40 digits."""
    with mpmath.workdps(_DPS):
        K = len(_classes(scheme))
        values = [Y[q] * mpmath.expjpi(mpmath.mpf(-2 * j * s) / n) for q in range(K) for s in range(n)]
        return [[mpmath.mpf(0)] + [mpmath.re(x) for x in values], [mpmath.mpf(0)] + [mpmath.im(x) for x in values]]


def redesign_vertex(scheme: Scheme, mesh: PolygonMesh, vertex: int, *, normal=None, flatten_hyperbolic: bool = False) -> RingDesign:
    """The smallest change of the 1-ring of ``vertex`` giving limit normal ``normal`` and/or no hyperbolic heights.

    The change is along the target normal (``normal``, else the measured one): the heights ``h`` of the ring
    are replaced by their orthogonal projection off the span of the constraint functionals (the two tangent
    masks when ``normal`` is given; each class's frequency-2 Fourier coefficient when ``flatten_hyperbolic``), the
    least-squares solution; the new points are rounded to doubles. Refused when the projected normal would
    point away from ``normal`` (the tangent plane would have to turn over).
    """
    from symdecomp.analysis.inspection import inspect_vertex

    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    scheme = check_scheme(scheme)
    if normal is None and not flatten_hyperbolic:
        raise InvalidInputError("redesign needs a normal or flatten_hyperbolic=True")
    ring = mesh.one_ring(vertex, scheme.lattice)
    check_ring_scale(mesh, (ring[0],) + tuple(x for part in ring[1:] for x in part), vertex)
    before = inspect_vertex(mesh, vertex, scheme)
    n, ring = before.valence, before.ring
    if normal is not None:
        N = frame(normal)[2]
        unit = [float(x) / math.sqrt(float(dot(N, N))) for x in N]
    elif before.normal is None:
        raise NotApplicableError(f"{mesh.name}: vertex {vertex} has no tangent plane (parallel tangents); give a normal")
    else:
        unit = list(before.normal)
    rows = []
    if normal is not None:
        rows += _functionals(scheme, n, 1, _dominant(_frequency_matrix(scheme, n, 1))[1])
    if flatten_hyperbolic:
        if n <= 4:
            raise NotApplicableError(f"at valence {n} there is no separate hyperbolic component (frequency 2 is not apart "
                                     "from its conjugate and the tangent frequencies); it needs n >= 5")
        K = len(_classes(scheme))
        for q in range(K):  # the class indicator: the Fourier coefficient of class q alone
            rows += _functionals(scheme, n, 2, [int(r == q) for r in range(K)])
    with mpmath.workdps(_DPS):
        h = mpmath.matrix([mpmath.fsum(mpmath.mpf(float(c)) * w for c, w in zip(mesh.points[v], unit)) for v in ring])
        G = mpmath.matrix(rows)
        dh = -(G.T * mpmath.lu_solve(G * G.T, G * h))
        points = list(mesh.points)
        for k, v in enumerate(ring):
            points[v] = tuple(Fraction(float(mpmath.mpf(float(c)) + dh[k] * w)) for c, w in zip(mesh.points[v], unit))
        change = float(mpmath.norm(dh))
    new = PolygonMesh.from_arrays(points, mesh.faces, name=mesh.name)
    achieved = limit_frame(scheme, new, vertex, normal=normal)
    if normal is not None and sum(a * b for a, b in zip(achieved.normal, unit)) < 0:
        raise NotApplicableError(f"{mesh.name}: vertex {vertex}: the least-squares change turns the tangent plane over (its normal "
                                 "would point away from the given normal); give the normal on the side the faces face")
    return RingDesign(scheme.name, n, new, int(vertex), ring, achieved, change)
