"""Bernstein-Bezier arithmetic in Arb: Jacobians of bicubic patches, their sign, and winding angles.

Everything is rigorous interval arithmetic (python-flint ``arb``): a ball holds the true
value, so a coefficient whose ball lies right of 0 *is* positive.

* A uniform bicubic B-spline patch ``P`` (``4 x 4`` control points) is a bicubic Bezier patch
  with control points ``M P M^T``, ``M = 1/6 [[1,4,1,0],[0,4,2,0],[0,2,4,0],[0,1,4,1]]``.
* For a planar bicubic map ``(x, y)`` the Jacobian determinant ``x_u y_v - x_v y_u`` is a
  polynomial of bidegree ``(5, 5)``: ``x_u`` has bidegree ``(2, 3)`` (Bezier points
  ``3 (b_{i+1,k} - b_{i,k})``), ``y_v`` bidegree ``(3, 2)``, and the product of Bernstein
  polynomials has the coefficients
  ``h_{ab} = sum f_{ik} g_{i'k'} C(2,i) C(3,i') / C(5,a) * C(3,k) C(2,k') / C(5,b)`` over
  ``i + i' = a``, ``k + k' = b``.
* A Bernstein polynomial lies in the convex hull of its coefficients, so if all coefficients
  are positive the polynomial is, and its smallest coefficient is a lower bound. Where a ball
  straddles 0 the patch is split at ``1/2`` in both directions (de Casteljau), up to a
  depth; a *corner* coefficient is the polynomial's value there, so corners of opposite sign
  prove a sign change.
* Over a triangle (Loop's quartic patches, nets in the order of
  :func:`~symdecomp.algebra.triangle_bezier.bezier_indices`) the Jacobian of a planar map of
  degree 4 has degree 6 (:func:`triangle_jacobian_net`, products of the degree-3 derivative
  nets). Subdivision is *bisection*: the edge opposite a corner is cut at its midpoint, and
  along each row of coefficients with a fixed power of that corner the univariate de Casteljau
  step at ``1/2`` gives the two halves (the blossom at the midpoint is the average of the
  blossoms at the edge's ends). The longest edge of a piece is cut, so pieces stay similar
  right isosceles triangles; two bisections halve every edge, as one tensor split does.
* The argument swept by a planar Bezier curve is the sum of ``arg(z_end / z_start)`` over pieces
  whose control points lie in an open half-plane through the origin (then the piece turns by
  less than ``pi``, and the principal argument is the true increment).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from math import comb

import flint

from symdecomp.algebra.triangle_bezier import bezier_derivative, bezier_indices, bezier_product

__all__ = [
    "triangle_jacobian_net",
    "bisect_triangle",
    "certify_sign_triangles",
    "bspline_to_bezier",
    "jacobian_net",
    "split_net",
    "SignCertificate",
    "certify_sign",
    "curve_angle",
]

_M = ((1, 4, 1, 0), (0, 4, 2, 0), (0, 2, 4, 0), (0, 1, 4, 1))


#: For each row ``i`` of ``M``, the ``(column, weight)`` of its nonzero entries, in order.
_M_TERMS = tuple(tuple((a, m) for a, m in enumerate(row) if m) for row in _M)


def _combine(terms, values):
    """``sum(weight * values[a])`` over ``terms``, added in their order (the zero entries of ``M`` add exact zeros: left out)."""
    a, m = terms[0]
    total = m * values[a]
    for a, m in terms[1:]:
        total = total + m * values[a]
    return total


def bspline_to_bezier(net):
    """``M P M^T / 36`` for a ``4 x 4`` net of balls (real or complex)."""
    cols = [[net[a][k] for a in range(4)] for k in range(4)]
    rows = [[_combine(terms, col) for col in cols] for terms in _M_TERMS]
    return [[_combine(terms, row) / 36 for terms in _M_TERMS] for row in rows]


#: For each of the ``6 x 6`` coefficients of :func:`jacobian_net` (row by row), the products that add up to it, in the
#: order of the sum over ``i, k, i2, k2``: ``(x_u index, y_v index, weight)`` with the exact degree-raising weights
#: ``C(2,i) C(3,i2) C(3,k) C(2,k2) / (C(5,i+i2) C(5,k+k2))``, computed once (every sector reads thousands of nets).
_JACOBIAN_TERMS = tuple(
    tuple((4 * i + k, 3 * i2 + k2, flint.fmpq(comb(2, i) * comb(3, i2) * comb(3, k) * comb(2, k2),
                                              comb(5, i + i2) * comb(5, k + k2)))
          for i in range(3) for k in range(4) for i2 in range(4) for k2 in range(3) if (i + i2, k + k2) == (a, b))
    for a in range(6) for b in range(6))


def jacobian_net(x, y):
    """The ``6 x 6`` Bernstein coefficients of ``x_u y_v - x_v y_u`` for bicubic Bezier nets ``x``, ``y``
    (Arb balls, or exact polynomials: :mod:`symdecomp.verify.c1_uniform`)."""
    xu = [3 * (x[i + 1][k] - x[i][k]) for i in range(3) for k in range(4)]
    yu = [3 * (y[i + 1][k] - y[i][k]) for i in range(3) for k in range(4)]
    xv = [3 * (x[i][k + 1] - x[i][k]) for i in range(4) for k in range(3)]
    yv = [3 * (y[i][k + 1] - y[i][k]) for i in range(4) for k in range(3)]
    flat = []
    for terms in _JACOBIAN_TERMS:
        total = None
        for p, q, w in terms:
            # f = x_u (2,3) times g = y_v (3,2), minus y_u (2,3) times x_v (3,2)
            term = w * (xu[p] * yv[q] - yu[p] * xv[q])
            total = term if total is None else total + term
        flat.append(total)
    return [flat[6 * a: 6 * a + 6] for a in range(6)]


def _split_1d(coeffs):
    """de Casteljau at 1/2: the coefficients of the two halves."""
    left, right = [coeffs[0]], [coeffs[-1]]
    row = list(coeffs)
    while len(row) > 1:
        row = [(row[t] + row[t + 1]) / 2 for t in range(len(row) - 1)]
        left.append(row[0])
        right.append(row[-1])
    return left, right[::-1]


def split_net(net):
    """The four quarter nets ``(u low/high) x (v low/high)`` of a tensor Bezier net."""
    halves_v = [_split_1d(row) for row in net]  # split each row (in v)
    out = []
    for side_v in (0, 1):
        part = [h[side_v] for h in halves_v]
        cols = [_split_1d([part[i][k] for i in range(len(part))]) for k in range(len(part[0]))]
        for side_u in (0, 1):
            out.append((side_u, side_v, [[cols[k][side_u][i] for k in range(len(cols))] for i in range(len(part))]))
    return out


@dataclass(frozen=True)
class SignCertificate:
    """The sign of a family of Bernstein nets: ``status`` is ``'positive'``, ``'negative'``, ``'changes'`` or ``'undecided'``."""

    status: str
    #: A rigorous lower bound of ``sign * J`` over all patches (when the sign is certified).
    lower_bound: float | None
    #: The deepest subdivision used (0: the coefficients of the whole patches sufficed).
    depth: int
    #: Nets examined in all.
    pieces: int
    #: Where it failed: ``(patch index, (u0, u1), (v0, v1))`` of a piece (for 'changes'/'undecided').
    where: tuple | None = None


def certify_sign(nets, max_depth: int = 6) -> SignCertificate:
    """Show all nets' polynomials have one strict sign, subdividing (de Casteljau) up to ``max_depth``."""
    corners = {1: None, -1: None}
    stack = [(p, net, (0.0, 1.0), (0.0, 1.0), 0) for p, net in enumerate(nets)]
    leaves, pieces, depth, undecided = [], 0, 0, None
    while stack:
        p, net, ur, vr, d = stack.pop()
        pieces += 1
        depth = max(depth, d)
        for i, k in ((0, 0), (0, -1), (-1, 0), (-1, -1)):
            c = net[i][k]
            for sign in (1, -1):
                if sign * c > 0 and corners[sign] is None:
                    corners[sign] = (p, ur, vr)
        if corners[1] is not None and corners[-1] is not None:
            return SignCertificate("changes", None, depth, pieces, corners[-1])
        flat = [c for row in net for c in row]
        if all(c > 0 for c in flat) or all(c < 0 for c in flat):
            leaves.append(flat)
            continue
        if d >= max_depth:
            undecided = undecided or (p, ur, vr)
            continue
        um, vm = (ur[0] + ur[1]) / 2, (vr[0] + vr[1]) / 2
        for side_u, side_v, sub in split_net(net):
            stack.append((p, sub, (ur[0], um) if side_u == 0 else (um, ur[1]), (vr[0], vm) if side_v == 0 else (vm, vr[1]), d + 1))
    return _certificate(leaves, undecided, depth, pieces)


def triangle_jacobian_net(x, y, degree: int = 4) -> list:
    """The Bernstein coefficients (degree ``2 degree - 2``) of ``x_u y_v - x_v y_u`` for triangular nets ``x``, ``y``."""
    xu, xv = bezier_derivative(x, degree, "u"), bezier_derivative(x, degree, "v")
    yu, yv = bezier_derivative(y, degree, "u"), bezier_derivative(y, degree, "v")
    first, second = bezier_product(xu, yv, degree - 1, degree - 1), bezier_product(xv, yu, degree - 1, degree - 1)
    return [a - b for a, b in zip(first, second)]


def bisect_triangle(net, degree: int, corners):
    """The two halves of a triangular net whose domain has ``corners`` (for ``w``, ``u``, ``v``), split at its longest edge.

    Returns ``[(net, corners), (net, corners)]``; a corner is a pair of floats.
    """
    d2 = lambda p, q: (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2  # noqa: E731
    apex = max(range(3), key=lambda k: d2(corners[(k + 1) % 3], corners[(k + 2) % 3]))
    e1, e2 = (apex + 1) % 3, (apex + 2) % 3
    idx = bezier_indices(degree)
    pos = {i: k for k, i in enumerate(idx)}
    near_e2, near_e1 = [None] * len(idx), [None] * len(idx)
    for i in range(degree + 1):
        def index(t, i=i):
            out = [0, 0, 0]
            out[apex], out[e1], out[e2] = i, t, degree - i - t
            return tuple(out)

        left, right = _split_1d([net[pos[index(t)]] for t in range(degree - i + 1)])
        for t in range(degree - i + 1):
            near_e2[pos[index(t)]], near_e1[pos[index(t)]] = left[t], right[t]
    mid = ((corners[e1][0] + corners[e2][0]) / 2, (corners[e1][1] + corners[e2][1]) / 2)
    c2, c1 = list(corners), list(corners)
    c2[e1], c1[e2] = mid, mid
    return [(near_e2, tuple(c2)), (near_e1, tuple(c1))]


def certify_sign_triangles(nets, degree: int, max_depth: int = 12) -> SignCertificate:
    """:func:`certify_sign` for triangular nets, bisecting (:func:`bisect_triangle`) up to ``max_depth`` times.

    ``where`` is ``(patch index, corners)`` of a piece; the corners are in the patch's own
    ``(u, v)`` parameters (the triangle ``(0, 0), (1, 0), (0, 1)``).
    """
    tips = [pos for pos, i in enumerate(bezier_indices(degree)) if max(i) == degree]
    corners = {1: None, -1: None}
    stack = [(p, net, ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0)), 0) for p, net in enumerate(nets)]
    leaves, pieces, depth, undecided = [], 0, 0, None
    while stack:
        p, net, domain, d = stack.pop()
        pieces, depth = pieces + 1, max(depth, d)
        for k in tips:
            for sign in (1, -1):
                if sign * net[k] > 0 and corners[sign] is None:
                    corners[sign] = (p, domain)
        if corners[1] is not None and corners[-1] is not None:
            return SignCertificate("changes", None, depth, pieces, corners[-1])
        if all(c > 0 for c in net) or all(c < 0 for c in net):
            leaves.append(net)
        elif d >= max_depth:
            undecided = undecided or (p, domain)
        else:
            stack += [(p, half, dom, d + 1) for half, dom in bisect_triangle(net, degree, domain)]
    return _certificate(leaves, undecided, depth, pieces)


def _certificate(leaves, undecided, depth: int, pieces: int) -> SignCertificate:
    """The certificate once every piece is a leaf of one strict sign (or not)."""
    signs = {1 if leaf[0] > 0 else -1 for leaf in leaves}
    if undecided is not None or len(signs) != 1:
        return SignCertificate("undecided", None, depth, pieces, undecided)
    sign = signs.pop()
    bound = min(((sign * c).lower() for leaf in leaves for c in leaf), key=float)
    value = float(bound)
    if not flint.arb(value) <= bound:  # round down, so that the float is still a lower bound
        value = math.nextafter(value, -math.inf)
    return SignCertificate("positive" if sign > 0 else "negative", value, depth, pieces)


def curve_angle(points, max_depth: int = 12) -> flint.arb | None:
    """The argument swept by the planar Bezier curve with complex control ``points`` (``None``: not decided).

    Fails (``None``) when a piece at ``max_depth`` still has control points on both sides of
    every line through the origin that the test tries (the curve may pass through 0).
    """
    total = flint.arb(0)
    stack = [(list(points), 0)]
    while stack:
        pts, d = stack.pop()
        direction = pts[0] + pts[-1]
        if all((q * direction.conjugate()).real > 0 for q in pts):
            total += (pts[-1] * pts[0].conjugate()).arg()
            continue
        if d >= max_depth:
            return None
        left, right = _split_1d(pts)
        stack.append((right, d + 1))
        stack.append((left, d + 1))
    return total
