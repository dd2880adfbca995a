"""The 1-ring of a vertex as a 2n-gon and its decomposition (Section 4: Eq. 10-13, 24).

The 1-ring of a valence-``n`` vertex ``O``: edge neighbours ``a_0..a_{n-1}`` and face
neighbours ``b_0..b_{n-1}``, read as the 2n-gon ``P = (a_0, b_0, ..., a_{n-1}, b_{n-1})``
(Eq. 10). Its decomposition ``P = sum_j z_j v_j`` into regular 2n-gons (Eq. 11) splits each
component into the n-gons ``A^j = (a_i^j)`` and ``B^j = (b_i^j)`` (Eq. 12-13), and
``B^j = omega_2n^j A^j`` (Eq. 24). After subdivision the ``a``'s and ``b``'s are no longer one
2n-gon; what the scheme moves is the pair of n-gon amplitudes ``(X_k, Y_k)`` of the ``a``'s
and ``b``'s at n-gon frequency ``k`` (:func:`ngon_amplitudes`), by ``M_k`` (Eq. 33).

>>> import sympy as sp
>>> ring = OneRing.from_points((0, 0, 1), [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)],
...                            [(1, 1, 0), (-1, 1, 0), (-1, -1, 0), (1, -1, 0)])
>>> ring.n
4
>>> from symdecomp.schemes.scheme import catmull_clark
>>> subdivide(catmull_clark(), ring).center
(0, 0, 9/16)
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from symdecomp.algebra.numbers import to_mpf
from symdecomp.algebra.polygons import PolygonDecomposition, as_vertex_rows, decompose
from symdecomp.errors import FrequencyOutOfRangeError, InvalidInputError, InvalidPolygonError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, subdivision_matrix

__all__ = ["interleaved_polygon", "OneRing", "subdivide", "one_ring_decomposition", "OneRingDecomposition", "ngon_amplitudes"]


def interleaved_polygon(a, b) -> list:
    """The 2n-gon ``P = (a_0, b_0, a_1, b_1, ..., a_{n-1}, b_{n-1})`` of a 1-ring (Eq. 10).

    ``a`` and ``b`` are the ``n`` edge and face neighbours (any sequences of points); the
    result lists the points themselves, interleaved.

    >>> interleaved_polygon(["a0", "a1"], ["b0", "b1"])
    ['a0', 'b0', 'a1', 'b1']
    """
    a, b = list(a), list(b)
    if len(a) != len(b):
        raise InvalidPolygonError(f"a 1-ring needs as many face neighbours as edge neighbours, got {len(a)} and {len(b)}")
    return [p for pair in zip(a, b) for p in pair]


@dataclass(frozen=True)
class OneRing:
    """A 1-ring: the centre ``O`` and its neighbours ``a_i`` (edge) and ``b_i`` (face)."""

    #: The central vertex ``O`` (a point of R^3, or a 1-tuple holding a complex number).
    center: tuple
    #: The edge neighbours ``a_0..a_{n-1}``.
    a: tuple
    #: The face neighbours ``b_0..b_{n-1}``; the faces are ``(O, a_i, b_i, a_{i+1})``.
    b: tuple
    #: ``"exact"``, ``"numpy"`` or ``"mpmath"``.
    arithmetic: str

    @classmethod
    def from_points(cls, center, a, b) -> OneRing:
        """Build and validate a 1-ring (same rules as polygons: exact, numpy or mpmath)."""
        a_rows, kind_a, dim_a = as_vertex_rows(a, name="edge neighbours a")
        b_rows, kind_b, dim_b = as_vertex_rows(b, name="face neighbours b")
        if len(a_rows) != len(b_rows):
            raise InvalidPolygonError(f"a 1-ring needs as many face neighbours as edge neighbours, got {len(a_rows)} and {len(b_rows)}")
        if dim_a != dim_b:
            raise InvalidPolygonError("edge and face neighbours have different numbers of coordinates")
        center_in = [center] if dim_a == 1 and not isinstance(center, (list, tuple, np.ndarray)) else list(center)
        c_rows, kind_c, dim_c = as_vertex_rows([center_in] * 3, name="centre O")
        if dim_c != dim_a:
            raise InvalidPolygonError(f"the centre O has {dim_c} coordinates, the neighbours {dim_a}")
        kinds = {kind_a, kind_b, kind_c}
        kind = "mpmath" if "mpmath" in kinds else "numpy" if "numpy" in kinds else "exact"
        conv = {"exact": lambda x: x, "numpy": lambda x: complex(x) if dim_a == 1 else float(x), "mpmath": mpmath.mpmathify}[kind]
        return cls(
            center=tuple(conv(x) for x in c_rows[0]),
            a=tuple(tuple(conv(x) for x in r) for r in a_rows),
            b=tuple(tuple(conv(x) for x in r) for r in b_rows),
            arithmetic=kind,
        )

    @property
    def n(self) -> int:
        return len(self.a)

    def polygon(self) -> list:
        """The 2n-gon ``(a_0, b_0, a_1, b_1, ..., a_{n-1}, b_{n-1})`` of Eq. 10, as lists."""
        return [list(p) for p in interleaved_polygon(self.a, self.b)]

    def rows(self) -> list:
        """The points in the order of the subdivision matrix: ``O, a_0..a_{n-1}, b_0..b_{n-1}``."""
        return [list(self.center)] + [list(p) for p in self.a] + [list(q) for q in self.b]

    @classmethod
    def from_rows(cls, rows, arithmetic: str) -> OneRing:
        n = (len(rows) - 1) // 2
        return cls(tuple(rows[0]), tuple(tuple(r) for r in rows[1 : 1 + n]), tuple(tuple(r) for r in rows[1 + n :]), arithmetic)


def subdivide(scheme: Scheme, ring: OneRing, steps: int = 1) -> OneRing:
    """Apply ``steps`` subdivision steps of ``scheme`` to a 1-ring (through the exact matrix)."""
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
        raise InvalidInputError(f"steps must be a non-negative integer, got {steps!r}")
    S = subdivision_matrix(scheme, ring.n)
    if scheme.parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters {scheme.parameters}; substitute values first")
    rows = ring.rows()
    if ring.arithmetic == "exact":
        X = sp.Matrix(rows)
        for _ in range(steps):
            X = S * X
        return OneRing.from_rows([tuple(sp.expand(x) for x in X.row(i)) for i in range(X.rows)], "exact")
    if ring.arithmetic == "numpy":
        A = np.array(S.tolist(), dtype=float)
        X = np.array(rows)
        for _ in range(steps):
            X = A @ X
        return OneRing.from_rows([tuple(r) for r in X.tolist()], "numpy")
    A = mpmath.matrix([[to_mpf(x) for x in row] for row in S.tolist()])
    X = mpmath.matrix(rows)
    for _ in range(steps):
        X = A * X
    return OneRing.from_rows([tuple(X[i, k] for k in range(X.cols)) for i in range(X.rows)], "mpmath")


@dataclass(frozen=True)
class OneRingDecomposition:
    """The decomposition of a 1-ring 2n-gon into regular 2n-gons and their n-gon halves."""

    #: The valence.
    n: int
    #: The decomposition of the 2n-gon of Eq. 10 (Eq. 11): ``2n`` components ``z_j v_j``.
    polygon: PolygonDecomposition

    def components(self, j: int) -> tuple[list, list]:
        """``(A^j, B^j)`` of Eq. 12-13: the even and odd vertices of ``z_j v_j``.

        Each is a list of ``n`` vertices (one complex number per coordinate); ``A^j`` is the
        regular n-gon ``z_j v_{j mod n}`` and ``B^j = omega_2n^j A^j`` (Eq. 24).
        """
        if isinstance(j, bool) or not isinstance(j, int) or not 0 <= j < 2 * self.n:
            raise FrequencyOutOfRangeError(f"component j must be an integer with 0 <= j < {2 * self.n}, got {j!r}")
        verts = self.polygon.component(j)
        return verts[0::2], verts[1::2]


def one_ring_decomposition(ring: OneRing) -> OneRingDecomposition:
    """Decompose the 1-ring's 2n-gon (Eq. 10-11)."""
    return OneRingDecomposition(ring.n, decompose(_typed(ring.polygon(), ring)))


def _typed(rows, ring: OneRing):
    if ring.arithmetic == "exact":
        return sp.Matrix(rows)
    if ring.arithmetic == "numpy":
        arr = np.array(rows)
        return arr[:, 0] if arr.shape[1] == 1 else arr
    return mpmath.matrix(rows)


def ngon_amplitudes(ring: OneRing) -> list[tuple[tuple, tuple]]:
    """``(X_k, Y_k)`` for ``k = 0..n-1``: the n-gon amplitudes of the ``a``'s and the ``b``'s.

    ``a = sum_k X_k v_k`` and ``b = sum_k Y_k v_k`` (each amplitude one complex number per
    coordinate). For ``k != 0`` one subdivision step maps ``(X_k, Y_k)`` to ``M_k (X_k, Y_k)``.
    """
    da = decompose(_typed([list(p) for p in ring.a], ring))
    db = decompose(_typed([list(q) for q in ring.b], ring))
    return [(da.amplitudes[k], db.amplitudes[k]) for k in range(ring.n)]
