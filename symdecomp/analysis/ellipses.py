"""The ellipses ``E_a``, ``E_b`` of a 1-ring's tangent-plane components (Eq. 40-41).

A 1-ring, written as the 2n-gon ``P = (a_0, b_0, ..., a_{n-1}, b_{n-1})`` (Eq. 10), decomposes
into regular 2n-gons ``z_j v_j`` (Eq. 11) with ``z_j`` in ``C^3``; for a real ring
``z_{2n-j} = conj(z_j)``. The a-part of the pair ``j, 2n - j`` is the planar polygon
``A^j + A^{2n-j}``: vertex ``i`` is ``U cos(2 pi i j/n) + W sin(2 pi i j/n)`` with
``U = 2 Re z_j``, ``W = -2 Im z_j``. In a complex coordinate of its plane it is
``w_j v_j + w_{2n-j} v_{n-j}`` (Eq. 41; the amplitudes of the coplanar pair of Eq. 6 of the
2n-gon, :meth:`symdecomp.algebra.polygons.PolygonDecomposition.planar_pair`), and it lies on the ellipse with semi-axes
``|w_j| + |w_{2n-j}|`` and ``| |w_j| - |w_{2n-j}| |`` (Eq. 40), which are also the singular
values of the ``3 x 2`` matrix ``[U W]``.

>>> import sympy as sp
>>> ring = sp.Matrix([[0, 0, 0], [2, 0, 0], [0, 1, 0], [-2, 0, 0], [0, -1, 0],
...                   [1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0]])
>>> e = ellipse_axes(ring, 1, digits=20)
>>> e.semi_axes
(1.7071067811865475244, 1.2071067811865475244)
>>> e.singular_values
(1.7071067811865475244, 1.2071067811865475244)
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.polygons import decompose
from symdecomp.errors import InvalidInputError, InvalidPolygonError
from symdecomp.schemes.ring import interleaved_polygon
from symdecomp.validate import check_digits, check_frequency

__all__ = ["ring_components", "EllipseAxes", "ellipse_axes"]


def _check_ring(ring) -> tuple[sp.Matrix, int]:
    M = sp.Matrix(ring)
    rows, cols = M.shape
    if cols != 3 or rows < 7 or rows % 2 == 0:
        raise InvalidPolygonError(
            f"a 1-ring is a (2n+1) x 3 matrix (O, a_0..a_{{n-1}}, b_0..b_{{n-1}}) with n >= 3, got {rows} x {cols}"
        )
    if any(not x.is_real for x in M if x.is_number) or any(x.has(sp.nan, sp.oo, sp.zoo) for x in M):
        raise InvalidPolygonError("1-ring coordinates must be finite real numbers")
    return M, (rows - 1) // 2


def _ring_polygon(M: sp.Matrix, n: int) -> sp.Matrix:
    """The 1-ring as the 2n-gon ``P = (a_0, b_0, a_1, b_1, ...)`` of Eq. 10, one row per vertex."""
    a = [list(M.row(1 + i)) for i in range(n)]
    b = [list(M.row(1 + n + i)) for i in range(n)]
    return sp.Matrix(interleaved_polygon(a, b))


def ring_components(ring) -> list[sp.Matrix]:
    """The amplitudes ``z_0..z_{2n-1}`` (complex 3-vectors) of Eq. 11 for a 1-ring.

    ``ring`` is ``(2n+1) x 3`` in the order ``(O, a_0..a_{n-1}, b_0..b_{n-1})``; then
    ``P_k = sum_j z_j omega_2n^(jk)`` with ``P = (a_0, b_0, a_1, b_1, ...)``
    (:func:`symdecomp.algebra.polygons.decompose` of the 2n-gon).
    """
    M, n = _check_ring(ring)
    return [sp.Matrix(z) for z in decompose(_ring_polygon(M, n)).amplitudes]


@dataclass(frozen=True)
class EllipseAxes:
    """The ellipse of ``A^j + A^{2n-j}`` (or of the b-part) of a 1-ring (Eq. 40-41)."""

    #: ``w_j``: the amplitude of ``v_j`` in a complex coordinate of the pair's plane (Eq. 41).
    w_j: sp.Expr
    #: ``w_{2n-j}``: the amplitude of ``v_{n-j}`` (swaps with ``w_j`` if the plane's orientation is flipped).
    w_conj: sp.Expr
    #: ``(|w_j| + |w_{2n-j}|, ||w_j| - |w_{2n-j}||)``: the semi-axes by Eq. 40.
    semi_axes: tuple[sp.Expr, sp.Expr]
    #: The singular values of ``[U W]``: the semi-axes of the ellipse through the polygon, computed directly.
    singular_values: tuple[sp.Expr, sp.Expr]
    #: ``(U, W)``: the real conjugate semi-diameters (vertex ``i`` is ``U cos + W sin``).
    diameters: tuple[sp.Matrix, sp.Matrix]


def ellipse_axes(ring, j: int = 1, part: str = "a", *, digits: int | None = 30) -> EllipseAxes:
    """Eq. 40-41 for the pair ``j, 2n - j`` of a 1-ring's decomposition (``part`` ``"a"`` or ``"b"``).

    The decomposition of the 2n-gon and its coplanar pair (Eq. 6) come from
    :mod:`symdecomp.algebra.polygons`, exactly; with ``digits`` (default 30) the amplitudes and axes are
    then evaluated to that many significant digits (``digits=None``: exact sympy numbers with
    square roots, unsimplified).
    """
    M, n = _check_ring(ring)
    j = check_frequency(j, n)
    digits = None if digits is None else check_digits(digits)
    if part not in ("a", "b"):
        raise InvalidInputError(f"part must be 'a' or 'b', got {part!r:.40}")
    if part not in ("a", "b"):
        raise InvalidInputError(f"part must be 'a' or 'b', got {part!r}")
    d = decompose(_ring_polygon(M, n))
    first, second = d.planar_pair(j)
    w_j, w_conj = first.amplitude, second.amplitude
    z = sp.Matrix(d.amplitudes[j])
    if part == "b":  # b_i is vertex 2i + 1 of the 2n-gon: B^j = omega_2n^j A^j (Eq. 24)
        turn = sp.exp(sp.pi * sp.I * sp.Rational(j, n))
        w_j, w_conj, z = w_j * turn, w_conj / turn, z * turn
    evaluate = (lambda e: sp.N(e, digits)) if digits is not None else (lambda e: e)  # noqa: E731
    w_j, w_conj = evaluate(w_j), evaluate(w_conj)
    U = (2 * z).applyfunc(lambda e: evaluate(sp.re(sp.expand_complex(e))))
    W = (-2 * z).applyfunc(lambda e: evaluate(sp.im(sp.expand_complex(e))))
    a1, a2 = sp.Abs(w_j), sp.Abs(w_conj)
    G = sp.Matrix.hstack(U, W)
    gram = G.T * G
    tr, det = gram.trace(), gram.det()
    disc = sp.sqrt(sp.Max(tr**2 - 4 * det, 0))
    singular = (sp.sqrt((tr + disc) / 2), sp.sqrt(sp.Max((tr - disc) / 2, 0)))
    return EllipseAxes(w_j, w_conj, (a1 + a2, sp.Abs(a1 - a2)), singular, (U, W))
