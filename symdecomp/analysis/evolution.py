"""The 1-ring under repeated subdivision steps (Section 5: "Evolution of the eigencomponents").

A 1-ring is stored as one array of shape ``(2n+1, d)`` in the vertex order of the subdivision
matrix, ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` (:func:`symdecomp.schemes.scheme.vertex_order`), with ``d``
coordinates per point (``d = 3`` for R^3; complex entries are allowed, e.g. planar rings as
complex numbers). One subdivision step is the exact matrix of the scheme applied to it.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> ring = one_ring([0, 0, 1], [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]],
...                 [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0]])
>>> after = subdivide_ring(catmull_clark(), ring, steps=1)[-1]
>>> O, a, b = split_ring(after)
>>> float(O[2]), a[:, 2].tolist(), b[:, 2].tolist()   # heights: 9/16, 3/8 and 1/4 of O's
(0.5625, [0.375, 0.375, 0.375, 0.375], [0.25, 0.25, 0.25, 0.25])
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from symdecomp.algebra.circulant import fourier_row
from symdecomp.algebra.polygons import decompose
from symdecomp.errors import InvalidInputError, InvalidPolygonError, NotApplicableError
from symdecomp.schemes.ring import interleaved_polygon
from symdecomp.schemes.scheme import Scheme, check_scheme, subdivision_matrix
from symdecomp.validate import cached, check_valence

__all__ = [
    "as_ring_array",
    "one_ring",
    "split_ring",
    "subdivide_ring",
    "subdivision_matrix_numeric",
    "Ellipse",
    "inscribed_ellipse",
    "EllipticProfile",
    "elliptic_profile",
    "tangent_configuration",
    "ring_polygon",
    "ring_from_polygon",
    "quadric_ring_mesh",
    "refine_mesh",
]


def one_ring(center, a, b) -> np.ndarray:
    """Stack ``O``, the ``a_i`` and the ``b_i`` into the ``(2n+1, d)`` array of a 1-ring."""
    O = np.atleast_1d(np.asarray(center))
    a = np.asarray(a)
    b = np.asarray(b)
    if a.ndim == 1:
        a = a[:, None]
    if b.ndim == 1:
        b = b[:, None]
    if a.shape != b.shape or a.shape[1:] != O.shape:
        raise InvalidPolygonError(
            f"a 1-ring needs as many a's as b's, each with as many coordinates as O: got O {O.shape}, a {a.shape}, b {b.shape}"
        )
    check_valence(len(a))
    ring = np.vstack([O[None, :], a, b])
    if not np.all(np.isfinite(ring)):
        raise InvalidPolygonError("a 1-ring has non-finite coordinates")
    return ring


def as_ring_array(ring) -> np.ndarray:
    """A ring as a float (or complex) ``(2n+1, d)`` array.

    Accepts arrays, nested lists, sympy matrices in the vertex order (e.g.
    :func:`symdecomp.analysis.hyperbolic.hyperbolic_ring`) and :class:`symdecomp.schemes.ring.OneRing`.
    """
    from symdecomp.schemes.ring import OneRing

    if isinstance(ring, OneRing):
        ring = ring.rows()
    if isinstance(ring, sp.MatrixBase):
        ring = ring.evalf(20).tolist()
    values = np.array(ring, dtype=complex)
    if values.ndim == 1:
        values = values[:, None]
    if np.all(values.imag == 0):
        values = values.real.copy()
    split_ring(values)
    return values


def split_ring(ring) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(O, a, b)`` of a ``(2n+1, d)`` ring array: the centre, the ``a_i`` and the ``b_i``."""
    ring = np.asarray(ring)
    if ring.ndim == 1:
        ring = ring[:, None]
    if ring.shape[0] % 2 != 1 or ring.shape[0] < 7:
        raise InvalidPolygonError(f"a 1-ring array has 2n+1 >= 7 rows (O, a's, b's), got {ring.shape[0]}")
    n = (ring.shape[0] - 1) // 2
    return ring[0], ring[1 : n + 1], ring[n + 1 :]


@cached(64, scheme=check_scheme, n=check_valence)
def subdivision_matrix_numeric(scheme: Scheme, n: int) -> np.ndarray:
    """The exact subdivision matrix of ``scheme`` at valence ``n``, rounded once to double precision."""
    if scheme.parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters {list(map(str, scheme.parameters))}; substitute them first")
    return np.array(subdivision_matrix(scheme, check_valence(n)).evalf(20), dtype=float)


def subdivide_ring(scheme: Scheme, ring, steps: int = 1) -> list[np.ndarray]:
    """The ring and its images after ``1..steps`` subdivision steps (a list of ``steps + 1`` arrays).

    The floating-point, whole-history counterpart of :func:`symdecomp.schemes.ring.subdivide` (same
    exact matrix, rounded once), for figures that show every step. ``ring`` is anything
    :func:`as_ring_array` accepts.
    """
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
        raise InvalidInputError(f"steps must be a non-negative integer, got {steps!r}")
    ring = as_ring_array(ring)
    n = (ring.shape[0] - 1) // 2
    S = subdivision_matrix_numeric(scheme, n)
    out = [ring]
    for _ in range(steps):
        out.append(S @ out[-1])
    return out


@dataclass(frozen=True)
class Ellipse:
    """The ellipse ``center + U cos t + V sin t`` in R^3 through an affine-regular n-gon (Section 5.2)."""

    #: Its centre (the centroid of the polygon).
    center: np.ndarray
    #: ``U = 2 Re z_1``: the point at ``t = 0`` minus the centre.
    u: np.ndarray
    #: ``V = -2 Im z_1``: the point at ``t = pi/2`` minus the centre.
    v: np.ndarray

    def points(self, samples: int = 200) -> np.ndarray:
        """``samples`` points of the ellipse, an ``(samples, 3)`` array (closed: first = last)."""
        t = np.linspace(0.0, 2.0 * np.pi, samples)
        return self.center + np.outer(np.cos(t), self.u) + np.outer(np.sin(t), self.v)

    def semi_axes(self) -> tuple[float, float]:
        """The two semi-axes, largest first (``l_1/2``, ``l_2/2`` of Eq. 40 for planar rings)."""
        s = np.linalg.svd(np.column_stack([self.u, self.v]), compute_uv=False)
        return float(s[0]), float(s[1])

    def normal(self) -> np.ndarray:
        """The unit normal ``U x V / |U x V|`` of its plane."""
        w = np.cross(self.u, self.v)
        return w / np.linalg.norm(w)

    def scale(self) -> float:
        """``sqrt(area / pi)``: the radius of the circle with the same area."""
        return float(np.sqrt(np.linalg.norm(np.cross(self.u, self.v))))


def inscribed_ellipse(polygon) -> Ellipse:
    """The ellipse through the frequency-1 part of an n-gon in R^3 (``A^1 + A^{n-1}``, Eq. 40-41).

    With ``p_i = sum_k z_k omega^(k i)`` (Eq. 5) and ``p`` real, ``z_0 + z_1 omega^i + z_{n-1} omega^{-i}
    = z_0 + 2 Re(z_1 omega^i)``: the vertices of the affine-regular polygon ``A^1 + A^{n-1}`` lie on
    ``z_0 + 2 Re(z_1 e^{it})``. Other frequencies of the polygon are ignored.
    """
    P = np.asarray(polygon, dtype=float)
    if P.ndim != 2 or P.shape[1] != 3:
        raise InvalidPolygonError(f"an n-gon in R^3 is an (n, 3) array, got shape {np.shape(polygon)}")
    z = np.array(decompose(P).amplitudes, dtype=complex)
    if np.linalg.norm(np.cross(z[1].real, z[1].imag)) < 1e-300:
        raise InvalidPolygonError("the polygon's frequency-1 part is degenerate (a segment or a point): no ellipse")
    return Ellipse(z[0].real, 2 * z[1].real, -2 * z[1].imag)


@dataclass(frozen=True)
class EllipticProfile:
    """Per step, the ellipses ``E_a``, ``E_b`` of a ring and where they sit relative to ``O`` (Section 5.2).

    ``kappa = d / scale^2`` is the curvature of the paraboloid of revolution (about the normal
    through ``O``) on which an ellipse of that scale and distance lies; the scheme has nice
    elliptic properties when ``kappa_a = kappa_b`` and both stay constant over the steps.
    """

    #: The rings, step 0 first (``(2n+1, 3)`` arrays).
    rings: tuple
    #: ``E_a`` at each step (through the ``a_i``).
    ellipses_a: tuple
    #: ``E_b`` at each step (through the ``b_i``).
    ellipses_b: tuple
    #: ``d_a``: signed distance from ``O`` to the plane of ``E_a``, along ``E_a``'s normal.
    distance_a: np.ndarray
    #: ``d_b``: the same for ``E_b`` (along ``E_a``'s normal; the planes are parallel, Prop. 4.1).
    distance_b: np.ndarray
    #: ``d_a / scale(E_a)^2``.
    kappa_a: np.ndarray
    #: ``d_b / scale(E_b)^2``.
    kappa_b: np.ndarray


def elliptic_profile(scheme: Scheme, ring, steps: int) -> EllipticProfile:
    """Iterate ``ring`` (``(2n+1, 3)``) and measure ``E_a``, ``E_b``, ``d_a``, ``d_b`` at every step."""
    rings = subdivide_ring(scheme, ring, steps)
    ea, eb, da, db = [], [], [], []
    for r in rings:
        O, a, b = split_ring(r)
        A, B = inscribed_ellipse(a), inscribed_ellipse(b)
        normal = A.normal()
        ea.append(A)
        eb.append(B)
        da.append(float((A.center - O) @ normal))
        db.append(float((B.center - O) @ normal))
    da, db = np.array(da), np.array(db)
    return EllipticProfile(
        rings=tuple(rings),
        ellipses_a=tuple(ea),
        ellipses_b=tuple(eb),
        distance_a=da,
        distance_b=db,
        kappa_a=da / np.array([e.scale() ** 2 for e in ea]),
        kappa_b=db / np.array([e.scale() ** 2 for e in eb]),
    )


def _regular_2n_gon(n: int, j: int) -> np.ndarray:
    """The regular 2n-gon ``v_j`` of Eq. 11 (row ``j`` of ``F_{2n}``), as complex floats."""
    return np.array([complex(w) for w in fourier_row(2 * n, j)])


def tangent_configuration(n: int, heights=(0.0, 0.0, 0.0), *, radius: float = 1.0, stretch: float = 0.0) -> np.ndarray:
    """A 1-ring in R^3 made of the tangent-plane components and the heights of Remark 5.2.

    In the plane (as complex numbers): ``radius * (v_1 + stretch * v_{2n-1})`` of Eq. 11, the
    components ``A^1 + A^{2n-1}``, ``B^1 + B^{2n-1}``: a regular 2n-gon for ``stretch = 0``, an
    affine image of one (inscribed in an ellipse with semi-axes ``radius * (1 +- stretch)``,
    Eq. 40) otherwise; ``O`` at the centre. Heights (z): ``heights = (h_O, h_a, h_b)`` for ``O``,
    every ``a_i`` and every ``b_i``. Remark 5.2's two cases are ``(1, 1, 1)`` (no elliptic
    component) and ``(0, 1, 1)``.
    """
    n = check_valence(n)
    h_O, h_a, h_b = (float(h) for h in heights)
    p = radius * (_regular_2n_gon(n, 1) + float(stretch) * _regular_2n_gon(n, 2 * n - 1))
    a, b = p[0::2], p[1::2]
    return one_ring(
        [0.0, 0.0, h_O],
        np.column_stack([a.real, a.imag, np.full(n, h_a)]),
        np.column_stack([b.real, b.imag, np.full(n, h_b)]),
    )


def ring_polygon(ring) -> np.ndarray:
    """The 2n-gon ``P = (a_0, b_0, a_1, b_1, ..., a_{n-1}, b_{n-1})`` of a 1-ring (Eq. 10)."""
    _, a, b = split_ring(ring)
    return np.array(interleaved_polygon(a, b), dtype=np.result_type(a, b))


def ring_from_polygon(center, polygon) -> np.ndarray:
    """The 1-ring with centre ``center`` whose 2n-gon is ``polygon`` (Eq. 10, split as in Eq. 12)."""
    P = np.asarray(polygon)
    if len(P) % 2:
        raise InvalidPolygonError(f"the polygon of a 1-ring has 2n vertices, got {len(P)}")
    return one_ring(center, P[0::2], P[1::2])


def quadric_ring_mesh(n: int, rings: int = 3, kind: str = "hyperbolic", height: float = 0.3):
    """A quad mesh of ``rings`` rings around a valence-``n`` vertex on a quadric (Sections 5.2-5.3).

    Vertex ``(s, u, v)`` of :func:`symdecomp.schemes.mesh.ring_mesh` sits at ``p = u e_s + v e_{s+1}`` in the
    plane (``e_s`` the unit vector at angle ``2 pi s/n``), lifted by ``height * Re(p^2)``
    (``kind="hyperbolic"``: out of the plane only frequency 2, the components ``A^2, A^{2n-2},
    B^2, B^{2n-2}``, and no elliptic component) or by ``height * |p|^2`` (``kind="elliptic"``:
    only frequency 0, the heights of ``O``, the ``a``'s and the ``b``'s of Eq. 43).
    """
    from symdecomp.schemes.mesh import ring_mesh

    n = check_valence(n)
    if kind not in ("hyperbolic", "elliptic"):
        raise InvalidInputError(f"kind must be 'hyperbolic' or 'elliptic', got {kind!r}")
    h = float(height)

    def value(s, u, v):
        p = u * np.exp(2j * np.pi * s / n) + v * np.exp(2j * np.pi * (s + 1) / n)
        z = h * (p * p).real if kind == "hyperbolic" else h * abs(p) ** 2
        return (float(p.real), float(p.imag), float(z))

    return ring_mesh(n, rings, value)


def refine_mesh(scheme: Scheme, mesh, levels: int):
    """``levels`` refinement steps of a :class:`symdecomp.schemes.mesh.QuadMesh` by the scheme's mesh rules."""
    from symdecomp.schemes.refinement import refine

    if isinstance(levels, bool) or not isinstance(levels, int) or levels < 0:
        raise InvalidInputError(f"levels must be a non-negative integer, got {levels!r}")
    for _ in range(levels):
        mesh = refine(mesh, scheme).mesh
    return mesh
