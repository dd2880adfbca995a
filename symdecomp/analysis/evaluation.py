"""Exact evaluation of the patches next to an extraordinary vertex (Stam's method): Catmull-Clark and Loop, at an
interior vertex and at a boundary or corner vertex.

One evaluator for every lattice (:mod:`symdecomp.schemes.lattice`): the lattice gives the
parameter domain, the level of a parameter and the sub-patch it falls in
(:meth:`~symdecomp.schemes.lattice.Lattice.locate`); this module gives each lattice's regular
basis and the limit masks at the centre (:data:`_BASES`).

**Quads** (Catmull-Clark). The patch ``(O, e_2, f_1, e_1)`` of a valence-``N`` vertex is evaluated from its ``K = 2N + 8``
control points (order: :mod:`symdecomp.schemes.patch`) and the eigen-data of the patch matrix
(:mod:`symdecomp.analysis.eigendata`): for ``(u, v)`` in ``[0, 1]^2`` other than ``(0, 0)``,

* ``n = floor(-log2 max(u, v)) + 1``, ``(u, v) <- 2^(n-1) (u, v)``;
* sub-patch ``k`` and local ``(s, t)``: ``v < 1/2``: ``k = 0``, ``(2u - 1, 2v)``; else ``u < 1/2``:
  ``k = 2``, ``(2u, 2v - 1)``; else ``k = 1``, ``(2u - 1, 2v - 1)``;
* ``s(u, v) = sum_i lam_i^(n-1) (sum_l Phi_k[i, l] b_l(s, t)) (V^-1 C)_i`` with the bicubic
  B-spline basis ``b_{a + 4b}(s, t) = N_a(s) N_b(t)``.

Derivatives follow by the chain rule (``d/du = 2^n d/ds``). At ``(0, 0)`` the point is the
limit position (the position mask) and the normal the cross product of the two tangent masks'
images; the derivatives there are not defined by the parametrization (NaN).

**Triangles** (Loop). The patch ``(O, a_0, a_1)`` next to a valence-``N`` vertex (order and
sub-patches: :mod:`symdecomp.schemes.patch`) for ``u, v >= 0``, ``u + v <= 1`` other
than ``(0, 0)``:

* ``n = floor(-log2(u + v)) + 1``, ``(x, y) = 2^n (u, v)`` (so ``1 < x + y <= 2``);
* sub-patch ``k`` and local ``(s, t)``: ``x >= 1``: ``k = 0``, ``(x - 1, y)``; else ``y >= 1``:
  ``k = 2``, ``(x, y - 1)``; else ``k = 1`` (upside down), ``(1 - x, 1 - y)``, and derivatives
  change sign once per order (``sigma = -1``);
* the same sum with the 12 quartic box-spline basis functions ``b_l``
  (:func:`~symdecomp.schemes.box_spline.regular_patch`, evaluated in Bernstein-Bezier form;
  derivatives from the derivative nets, :func:`~symdecomp.analysis.regular_basis.box_basis`).

At ``(0, 0)`` the limit point and the tangent plane come from the eigen-data itself
(:func:`eigen_masks`): the eigenvalue-1 eigenvector is constant (``Phi_0[0, l]``), so the limit
position mask is ``Phi_0[0, 0]`` times row 0 of ``V^-1``; rows 2 and 3 (frequency 1, the
``cos`` and ``sin`` patterns) are the two tangent masks, turning from ``a_0`` to ``a_1`` like
``(u, v)``, so their images' cross product points along ``du x dv``.

Two arithmetics, one formula: :class:`PatchEvaluator` holds numpy float64 arrays (from the data
file, vectorized over many parameters) or numpy object arrays of mpmath numbers at any
precision (from the Arb balls, :meth:`PatchEvaluator.exact`).

**A boundary or corner vertex** (:func:`evaluate`, exact with Fractions): patch ``s`` of its open fan, from the
closed 2-ring's ``K`` control points ``C`` and the exact data of :mod:`symdecomp.analysis.subpatch_data`. At
``(u, v) != (0, 0)``: the level ``n`` and the sub-patch ``j`` with local ``(s', t')`` as above, then
``point = b(s', t') . patches[s][j] . A^(n-1) C`` with the same regular basis ``b``. *Matrix powers, not
eigenvectors*: ``A`` need not be diagonalisable (it has Jordan blocks at some ``k``), and ``A^(n-1) C`` by ``n - 1``
exact products is exact for every ``A``; in float64 it costs ``n - 1`` products of a ``K x K`` matrix (``n = 60`` at
``u = 2^-60``). At ``(0, 0)`` the point is ``limit . C``. With :class:`~fractions.Fraction` control points and
parameters the result is exact; with floats it is float64 arithmetic on the rounded data.

Affine invariance as a check: equal control points give that point everywhere.

>>> import numpy as np
>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.analysis.eigendata import certified_eigendata
>>> cc = catmull_clark()
>>> ev = PatchEvaluator.from_rounded(cc, certified_eigendata(cc, 7)[1])
>>> out = ev.evaluate(np.ones((22, 1)), [0.3, 0.01], [0.7, 0.02])
>>> np.allclose(out["point"], 1), np.allclose(out["du"], 0)
(True, True)
>>> from fractions import Fraction
>>> from symdecomp.analysis.subpatch_data import sharp_patch_data
>>> from symdecomp.schemes.sector import SharpVertex
>>> d = sharp_patch_data(cc, SharpVertex.boundary(3, "quad"))
>>> evaluate(d, 1, Fraction(1, 2), Fraction(1, 4), [[1]] * d.size)["point"]
[Fraction(1, 1)]
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from symdecomp.analysis.eigendata import PatchEigenData, RoundedEigenData, patch_eigendata
from symdecomp.analysis.masks import INDEX, LAMBDA1, limit_masks
from symdecomp.analysis.regular_basis import bicubic_exact, box_basis, box_exact, bspline_basis
from symdecomp.analysis.subpatch_data import SharpPatchData
from symdecomp.errors import EvaluationError, InvalidInputError, InvalidSchemeError
from symdecomp.schemes.box_spline import regular_patch
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, QUAD, Lattice
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N
from symdecomp.validate import check_type, check_valence

__all__ = [
    "EvaluationError", "PatchEvaluator", "patch_order", "patch_masks", "curvatures",
    "eigen_masks", "check_regular_patch", "evaluate",
]


#: Output key -> order of the derivative in (u, v).
_DERIVATIVES = {"point": (0, 0), "du": (1, 0), "dv": (0, 1), "duu": (2, 0), "duv": (1, 1), "dvv": (0, 2)}


def patch_order(n: int) -> np.ndarray:
    """Index permutation from the masks' order ``(O, a_0.., b_0..)`` to the patch's ``(O, e_0, f_0, ..)``."""
    return np.array([0] + [x for i in range(n) for x in (1 + i, 1 + n + i)])


@dataclass(frozen=True)
class PatchEvaluator:
    """Evaluate the valence-``n`` patch; arrays float64 or objects (mpmath numbers)."""

    n: int
    values: np.ndarray  # (K,)
    inverse: np.ndarray  # (K, K)
    phi: np.ndarray  # (3, K, 16)
    position_mask: np.ndarray  # (K,) limit position, patch order
    tangent_masks: np.ndarray  # (2, K)
    #: Working precision (decimal digits) of the mpmath arithmetic; None for float64.
    dps: int | None = None
    #: The lattice: :data:`~symdecomp.schemes.lattice.QUAD` (Catmull-Clark: ``[0, 1]^2``, bicubic
    #: sub-patches) or :data:`~symdecomp.schemes.lattice.TRIANGLE` (Loop: ``u, v >= 0``, ``u + v <= 1``,
    #: quartic box-spline sub-patches).
    lattice: Lattice = QUAD
    #: Jordan pairs ``(i, c, gamma)`` of the eigen-data (:class:`~symdecomp.analysis.eigendata.PatchEigenData`):
    #: ``J^m`` adds ``m lam^(m-1) gamma x_c`` to component ``i``.
    jordan: tuple = ()

    @property
    def mesh(self) -> str:
        """The lattice's name."""
        return self.lattice.name

    @classmethod
    def from_rounded(cls, scheme: Scheme, data: RoundedEigenData) -> PatchEvaluator:
        return cls.from_file_arrays(scheme, data.n, data.values, data.inverse, data.phi, data.jordan)

    @classmethod
    def from_file_arrays(cls, scheme: Scheme, n: int, values, inverse, phi, jordan=()) -> PatchEvaluator:
        values, inverse, phi = np.asarray(values, float), np.asarray(inverse, float), np.asarray(phi, float)
        pos, tan = _basis(scheme.lattice).masks(scheme, n, values, inverse, phi, float)
        return cls(n, values, inverse, phi, pos, tan, None, scheme.lattice, tuple((i, c, float(g)) for i, c, g in jordan))

    @classmethod
    def exact(cls, scheme: Scheme, n: int, dps: int = 30) -> PatchEvaluator:
        """mpmath numbers good to about ``dps`` digits (Arb balls at ``3.4 dps + 64`` bits)."""
        n = check_valence(n)
        data: PatchEigenData = patch_eigendata(scheme, n, int(3.4 * dps) + 64)
        with mpmath.workdps(dps + 10):
            mp = lambda x: mpmath.mpf(x.mid().str(dps + 15, radius=False))  # noqa: E731
            size = data.size
            values = np.array([mp(x) for x in data.values], dtype=object)
            inverse = np.array([[mp(data.inverse[i, j]) for j in range(size)] for i in range(size)], dtype=object)
            phi = np.array([[[mp(t[i, l]) for l in range(t.ncols())] for i in range(size)] for t in data.phi], dtype=object)
            conv = lambda e: mpmath.mpf(sp.N(e, dps + 10)) if isinstance(e, sp.Basic) else mpmath.mpf(e)  # noqa: E731
            pos, tan = _basis(scheme.lattice).masks(scheme, n, values, inverse, phi, conv)
            jordan = tuple((i, c, mp(g)) for i, c, g in data.jordan)
        return cls(n, values, inverse, phi, pos, tan, dps + 10, scheme.lattice, jordan)

    def evaluate(self, control_points, u, v) -> dict:
        """Point, first and second derivatives and unit normal at the parameters ``(u, v)`` (arrays).

        Returns ``{"point", "du", "dv", "duu", "duv", "dvv", "normal"}``, each of shape
        ``u.shape + (d,)`` for ``d``-dimensional control points of shape ``(K, d)``.
        """
        if self.dps is not None:
            with mpmath.workdps(self.dps):
                return self._evaluate(control_points, u, v)
        return self._evaluate(control_points, u, v)

    def _evaluate(self, control_points, u, v) -> dict:
        c = np.asarray(control_points)
        if c.ndim != 2 or c.shape[0] != self.values.size:
            raise EvaluationError(f"control points must have shape ({self.values.size}, d), got {c.shape}")
        exact = self.values.dtype == object
        u = np.atleast_1d(np.asarray(u, dtype=object if exact else float))
        v = np.atleast_1d(np.asarray(v, dtype=object if exact else float))
        u, v = np.broadcast_arrays(u, v)
        if any(x < 0 or x > 1 for x in np.concatenate([u.ravel(), v.ravel()])):
            raise EvaluationError("parameters must lie in [0, 1]")
        if not all(self.lattice.in_domain(a, b) for a, b in zip(u.ravel(), v.ravel())):
            raise EvaluationError(f"parameters of a {self.lattice} patch must satisfy u + v <= 1")
        shape, u, v = u.shape, u.ravel(), v.ravel()
        proj = self.inverse.dot(c)  # (K, d): the control points in the eigenbasis
        if exact:
            out = {key: np.empty((u.size, c.shape[1]), dtype=object) for key in _DERIVATIVES}
            for p in range(u.size):
                self._one(proj, c, u[p], v[p], out, p)
        else:
            out = self._vectorized(proj, u, v)
        out["normal"] = _normals(out["du"], out["dv"])
        origin = np.flatnonzero([a == 0 and b == 0 for a, b in zip(u, v)])
        if origin.size:
            t1, t2 = self.tangent_masks.dot(c)
            # quads: (t1, t2) turn from e_0 to e_1, against (u, v); triangles: from a_0 to a_1, with it
            if not self.lattice.tangents_along_parameters:
                t1, t2 = t2, t1
            nrm = _normals(t1[None, :], t2[None, :])[0]
            for p in origin:
                out["point"][p] = self.position_mask.dot(c)
                out["normal"][p] = nrm
                for key in list(_DERIVATIVES)[1:]:
                    out[key][p] = mpmath.nan if exact else np.nan
        return {k: a.reshape(shape + (c.shape[1],)) for k, a in out.items()}

    def _vectorized(self, proj, u, v) -> dict:
        lat, basis_at = self.lattice, _basis(self.lattice).vector
        origin = (u == 0) & (v == 0)
        m, e = np.frexp(np.where(origin, 1.0, lat.level_measure(u, v, np)))
        level = 1 - e + (m == 0.5)
        us, vs = np.ldexp(u, level - 1), np.ldexp(v, level - 1)
        k, s, t, sign = lat.locate(2 * us, 2 * vs, np)
        weights = self.values[None, :] ** (level - 1)[:, None]
        scale = (np.ldexp(1.0, level) * sign)[:, None]
        out = {}
        for key, (ds, dt) in _DERIVATIVES.items():
            basis = basis_at(s, t, ds, dt)
            g = np.empty((u.size, self.values.size), dtype=np.result_type(self.phi, self.values))
            for kk in range(3):
                sel = k == kk
                g[sel] = basis[sel] @ self.phi[kk].T
            total = (g * weights) @ proj
            for i, c, gamma in self.jordan:
                m = level - 1
                total = total + (g[:, i] * m * self.values[i] ** np.maximum(m - 1, 0) * gamma)[:, None] * proj[c][None, :]
            out[key] = total * scale ** (ds + dt)
        return out

    def _one(self, proj, c, u, v, out, p):
        if u == 0 and v == 0:  # filled in by the caller from the masks
            for key in _DERIVATIVES:
                out[key][p] = mpmath.mpf(0)
            return
        lat, basis_at = self.lattice, _basis(self.lattice).scalar
        level = 1
        while lat.level_measure(u, v, None) <= 0.5:
            u, v, level = u * 2, v * 2, level + 1
        k, s, t, sign = lat.locate(2 * u, 2 * v)
        scale = 2**level * sign
        weights = self.values ** (level - 1)
        for key, (ds, dt) in _DERIVATIVES.items():
            g = self.phi[k].dot(basis_at(s, t, ds, dt))
            total = (weights * g).dot(proj)
            for i, c, gamma in self.jordan:
                total = total + g[i] * (level - 1) * self.values[i] ** max(level - 2, 0) * gamma * proj[c]
            out[key][p] = total * scale ** (ds + dt)


def _normals(du, dv):
    n = np.cross(du, dv) if du.shape[-1] == 3 else np.zeros_like(du)
    if du.dtype == object:
        norms = np.array([mpmath.sqrt(sum(x * x for x in row)) or mpmath.nan for row in n], dtype=object)
    else:
        norms = np.sqrt((n * n).sum(axis=-1))
    with np.errstate(invalid="ignore", divide="ignore"):
        return n / norms[:, None]


def patch_masks(scheme: Scheme, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The limit-position mask and the two tangent masks in the patch's order (float64, K entries)."""
    return _masks(scheme, n, float)


def curvatures(result: dict) -> tuple[np.ndarray, np.ndarray]:
    """Gaussian and mean curvature from :meth:`PatchEvaluator.evaluate`'s derivatives (3D points)."""
    du, dv, nrm = result["du"], result["dv"], result["normal"]
    e, f, g = (du * du).sum(-1), (du * dv).sum(-1), (dv * dv).sum(-1)
    l_, m, n_ = ((result[k] * nrm).sum(-1) for k in ("duu", "duv", "dvv"))
    det = e * g - f * f
    return (l_ * n_ - m * m) / det, (e * n_ - 2 * f * m + g * l_) / (2 * det)


def _masks(scheme: Scheme, n: int, conv):
    """The masks of :mod:`symdecomp.analysis.masks` at valence ``n`` in patch order, through ``conv``.

    The closed forms are evaluated with mpmath (one compiled function per weight) rather than
    by substituting every index: the exact masks at ``n = 128`` would take seconds.
    """
    m = limit_masks(scheme)
    order = patch_order(n)
    with mpmath.workdps(max(mpmath.mp.dps, 30)):
        lam1 = mpmath.mpf(sp.N(m.subdominant.subs(N, n), mpmath.mp.dps + 5))
        position = [m.position[0].subs(N, n)] + [m.position[1].subs(N, n)] * n + [m.position[2].subs(N, n)] * n
        pos = [conv(position[i]) for i in order]
        tangents = []
        for a_w, b_w in zip(m.tangent_a, m.tangent_b):
            fa, fb = (sp.lambdify((N, INDEX, LAMBDA1), w, "mpmath") for w in (a_w, b_w))
            mask = [0] + [fa(n, i, lam1) for i in range(n)] + [fb(n, i, lam1) for i in range(n)]
            tangents.append([conv(mask[i]) for i in order])
    pos = np.array(pos + [conv(0)] * 7, dtype=object)
    tan = np.array([t + [conv(0)] * 7 for t in tangents], dtype=object)
    if conv is float:
        pos, tan = pos.astype(float), tan.astype(float)
    return pos, tan


def eigen_masks(values, inverse, phi) -> tuple[np.ndarray, np.ndarray]:
    """``(position mask, (cos, sin) tangent masks)`` of the centre from Loop eigen-data (any number type)."""
    if not (abs(values[0] - 1) < 1e-9 and abs(values[2] - values[3]) < 1e-9 * (1 + abs(values[2]))):
        raise InvalidSchemeError("the eigen-data is not in the triangle patch's order (1 first, then the frequency-1 pair)")
    return phi[0][0, 0] * inverse[0], np.array([inverse[2], inverse[3]])


def check_regular_patch(scheme: Scheme) -> None:
    """Raise unless the scheme's regular patch is the one the evaluator uses (Loop's quartic box spline)."""
    if regular_patch(scheme).coefficients != regular_patch().coefficients:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: its regular patch is not Loop's box spline; the evaluator does not support it")


@dataclass(frozen=True)
class _PatchBasis:
    """A lattice's regular patch basis and its centre masks, as the evaluator uses them."""

    #: ``(s, t, ds, dt) -> (P, m)``: the basis (or a derivative) at float64 arrays of local parameters.
    vector: Callable
    #: ``(s, t, ds, dt) -> (m,)``: the same at one point, mpmath numbers.
    scalar: Callable
    #: ``(scheme, n, values, inverse, phi, conv) -> (position mask, tangent masks)`` in the patch's order.
    masks: Callable
    #: ``(s, t, ds, dt) -> [m values]``: the same at one point in the arithmetic of ``s`` and ``t`` (exact with Fractions).
    exact: Callable


def _triangle_masks(scheme: Scheme, n: int, values, inverse, phi, conv):
    check_regular_patch(scheme)
    return eigen_masks(values, inverse, phi)


_BASES = {
    BICUBIC: _PatchBasis(
        lambda s, t, ds, dt: np.einsum("bp,ap->pba", bspline_basis(t, dt), bspline_basis(s, ds)).reshape(s.size, 16),
        lambda s, t, ds, dt: np.outer(bspline_basis(t, dt), bspline_basis(s, ds)).ravel(),  # index a + 4 b
        lambda scheme, n, values, inverse, phi, conv: _masks(scheme, n, conv),
        bicubic_exact,
    ),
    BOX_SPLINE: _PatchBasis(
        lambda s, t, ds, dt: box_basis(s, t, ds, dt, float),
        lambda s, t, ds, dt: box_basis(np.array([s], dtype=object), np.array([t], dtype=object), ds, dt, mpmath.mpf)[0],
        _triangle_masks,
        box_exact,
    ),
}


def _basis(lat: Lattice) -> _PatchBasis:
    return lat.select(_BASES, "the patch evaluator's regular basis")


def _apply(rows, points: list) -> list:
    d = len(points[0])
    return [[sum((w * points[c][i] for c, w in row.items()), 0 * points[0][i]) for i in range(d)] for row in rows]


def _check_parameters(data: SharpPatchData, face, u, v, points) -> list:
    if isinstance(face, bool) or not isinstance(face, int) or not 0 <= face < data.faces:
        raise InvalidInputError(f"face must be an integer from 0 to {data.faces - 1}, got {face!r:.40}")
    for name, x in (("u", u), ("v", v)):
        if isinstance(x, bool) or not isinstance(x, (int, float, Fraction)) or not 0 <= x <= 1:
            raise EvaluationError(f"{name} must be a number in [0, 1], got {x!r:.40}")
    if not data.lattice.in_domain(u, v):
        raise EvaluationError(f"parameters of a {data.lattice} patch must satisfy u + v <= 1, got ({u}, {v})")
    points = [list(p) for p in points] if hasattr(points, "__iter__") else None
    if not points or len(points) != data.size or len({len(p) for p in points}) != 1 or not points[0]:
        raise InvalidInputError(f"control points: need {data.size} points of one dimension d >= 1 (the closed 2-ring)")
    return points


def evaluate(data: SharpPatchData, face: int, u, v, points) -> dict:
    """``{"point", "du", "dv"}`` of patch ``face`` of a boundary or corner vertex at ``(u, v)`` from the ``K`` control
    ``points`` (each a sequence) and the vertex's :class:`~symdecomp.analysis.subpatch_data.SharpPatchData`.

    Exact with Fractions (data, points and parameters), float64 with floats. At ``(0, 0)`` the point is the
    limit position and the derivatives are ``None`` (the parametrization does not define them there).
    """
    check_type(data, SharpPatchData, "data")
    points = _check_parameters(data, face, u, v, points)
    if u == 0 and v == 0:
        return {"point": _apply([dict(enumerate(data.limit))], points)[0], "du": None, "dv": None}
    lat, level = data.lattice, 1
    while lat.level_measure(u, v, None) * 2 <= 1:
        u, v, level = u * 2, v * 2, level + 1
    for _ in range(level - 1):
        points = _apply(data.matrix, points)
    j, s, t, sign = lat.locate(2 * u, 2 * v)
    net = _apply(data.patches[face][j], points)
    out = {}
    for key, (ds, dt) in (("point", (0, 0)), ("du", (1, 0)), ("dv", (0, 1))):
        b = _basis(lat).exact(s, t, ds, dt)
        scale = (2**level * sign) ** (ds + dt)
        out[key] = [sum((bl * p[i] for bl, p in zip(b, net)), 0 * net[0][i]) * scale for i in range(len(net[0]))]
    return out
