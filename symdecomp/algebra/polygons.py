"""Decomposition of polygons into planar regular polygons (Section 2: Eq. 1, 4, 5, 6).

An n-gon is an n-tuple of points of R^3 (Eq. 1), given as an ``n x 3`` array, or a planar
one as an n-tuple of complex numbers (a vector of C^n). Every n-gon is a sum of ``n`` regular
n-gons ``z_j v_j`` (Eq. 5), ``v_j`` the rows of the Fourier matrix; the amplitudes are
``z_j = (1/n) sum_m p_m omega^(-jm)``, one complex number per coordinate. For a polygon in
R^3 the pair ``{j, n-j}`` sums to the real planar polygon ``2 Re(z_j v_j)`` which is the sum
of two coplanar planar regular polygons (Eq. 6): see :meth:`PolygonDecomposition.planar_pair`.

Three arithmetics, chosen from the input:

* exact: sympy Matrices or lists of ints, Fractions, sympy Rationals (Gaussian rationals
  ``a + b*I`` for C^n). Computed in the cyclotomic field Q(zeta_N) (:mod:`symdecomp.algebra.cyclotomic`),
  so equalities are exact; results are returned as sympy numbers.
* numpy (fast): a numpy array of floats (R^3) or complex numbers (C^n).
* mpmath (high precision): an ``mpmath.matrix`` or lists of ``mpf``/``mpc``; computed at the
  caller's working precision (scope it with ``mpmath.workdps``).

>>> import sympy as sp
>>> square = sp.Matrix([[2, 0, 0], [0, 2, 0], [-2, 0, 0], [0, -2, 0]])
>>> d = decompose(square)
>>> d.amplitudes[1]
(1, -I, 0)
>>> d.reconstruct() == square
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField
from symdecomp.algebra.numbers import to_sympy
from symdecomp.errors import FrequencyOutOfRangeError, InvalidPolygonError

__all__ = [
    "PlanarRegularComponent",
    "PolygonDecomposition",
    "decompose",
    "coplanar_pairs",
    "as_vertex_rows",
]


def _is_exact_scalar(x) -> bool:
    if isinstance(x, bool):
        return False
    if isinstance(x, (int, Fraction)):
        return True
    if isinstance(x, sp.Basic):
        re, im = sp.sympify(x, strict=True).as_real_imag()
        return bool(re.is_Rational and im.is_Rational)
    return False


def as_vertex_rows(polygon, *, name: str = "polygon"):
    """Validate a polygon; return ``(rows, kind, dim)`` with ``kind`` in exact/numpy/mpmath.

    ``dim`` is 3 for points of R^3 and 1 for complex numbers (C^n).
    """
    rows, kind = _rows_and_kind(polygon, name)
    if len(rows) < 3:
        raise InvalidPolygonError(f"{name}: a polygon needs at least 3 vertices, got {len(rows)}")
    dims = {len(r) for r in rows}
    if len(dims) != 1:
        raise InvalidPolygonError(f"{name}: vertices have different numbers of coordinates {sorted(dims)}")
    dim = dims.pop()
    if dim not in (1, 3):
        raise InvalidPolygonError(
            f"{name}: vertices must be points of R^3 (3 coordinates) or complex numbers (1), got {dim} coordinates"
        )
    out = [[_coordinate(x, kind, dim, f"{name}: vertex {i}") for x in r] for i, r in enumerate(rows)]
    return out, kind, dim


def _rows_and_kind(polygon, name: str) -> tuple[list[list], str]:
    """The vertices as lists of coordinates, and the arithmetic the input asks for."""
    if isinstance(polygon, sp.MatrixBase):
        rows = [list(polygon.row(i)) for i in range(polygon.rows)] if polygon.cols > 1 else [[x] for x in polygon]
        return rows, "exact"
    if isinstance(polygon, np.ndarray):
        if polygon.dtype == object or not np.issubdtype(polygon.dtype, np.number):
            raise InvalidPolygonError(f"{name}: a numpy polygon must have a float or complex dtype, not {polygon.dtype}")
        if polygon.ndim not in (1, 2):
            raise InvalidPolygonError(f"{name}: expected an n x 3 array or a vector of C^n, got shape {polygon.shape}")
        arr = polygon if polygon.ndim == 2 else polygon.reshape(-1, 1)
        return [list(r) for r in arr], "numpy"
    if isinstance(polygon, mpmath.matrix):
        return [[polygon[i, k] for k in range(polygon.cols)] for i in range(polygon.rows)], "mpmath"
    if isinstance(polygon, (list, tuple)):
        rows = [list(p) if isinstance(p, (list, tuple, np.ndarray)) else [p] for p in polygon]
        flat = [x for r in rows for x in r]
        if any(isinstance(x, (mpmath.mpf, mpmath.mpc)) for x in flat):
            return rows, "mpmath"
        if any(isinstance(x, (float, complex, np.floating, np.complexfloating)) for x in flat):
            return rows, "numpy"
        return rows, "exact"
    raise InvalidPolygonError(f"{name}: expected an n x 3 array or a vector of C^n, got {type(polygon).__name__}")


def _coordinate(x, kind: str, dim: int, where: str):
    """One coordinate, checked and converted to the arithmetic ``kind`` (real if ``dim == 3``)."""
    not_real = f"{where}: coordinate {x!r} of a point of R^3 is not real"
    if kind == "exact":
        if not _is_exact_scalar(x):
            raise InvalidPolygonError(
                f"{where} has coordinate {x!r}, which is not a (Gaussian) rational; "
                "use floats (numpy) or mpmath numbers for other values"
            )
        v = sp.sympify(x, strict=True) if not isinstance(x, Fraction) else to_sympy(x)
        if dim == 3 and not v.is_real:
            raise InvalidPolygonError(not_real)
        return v
    if kind == "numpy":
        v = complex(x)
        if not (math.isfinite(v.real) and math.isfinite(v.imag)):
            raise InvalidPolygonError(f"{where} has a coordinate that is not finite ({x!r})")
        if dim == 3:
            if v.imag != 0:
                raise InvalidPolygonError(not_real)
            return v.real
        return v
    v = mpmath.mpmathify(x)
    if not mpmath.isfinite(v):
        raise InvalidPolygonError(f"{where} has a coordinate that is not finite ({x!r})")
    if dim == 3 and isinstance(v, mpmath.mpc):
        if v.imag != 0:
            raise InvalidPolygonError(not_real)
        return v.real
    return v


# ------------------------------------------------------------------------- arithmetics
class _Exact:
    def __init__(self, n: int):
        self.K = CyclotomicField(4 * n // math.gcd(4, n))
        self.n = n

    def lift(self, x):
        return self.K(x)

    def root(self, k):
        return self.K.root(self.n, k)

    def out(self, x: Cyclotomic):
        return x.to_sympy()

    re = staticmethod(lambda z: z.real())
    im = staticmethod(lambda z: z.imag())


class _Numpy:
    def __init__(self, n: int):
        self.n = n

    lift = staticmethod(complex)
    root = lambda self, k: complex(np.exp(2j * np.pi * (k % self.n) / self.n))  # noqa: E731
    out = staticmethod(lambda x: x)
    re = staticmethod(lambda z: z.real)
    im = staticmethod(lambda z: z.imag)


class _Mpmath:
    def __init__(self, n: int):
        self.n = n

    lift = staticmethod(mpmath.mpmathify)
    root = lambda self, k: mpmath.expjpi(mpmath.mpf(2 * (k % self.n)) / self.n)  # noqa: E731
    out = staticmethod(lambda x: x)
    re = staticmethod(mpmath.re)
    im = staticmethod(mpmath.im)


_ARITH = {"exact": _Exact, "numpy": _Numpy, "mpmath": _Mpmath}


def coplanar_pairs(n: int) -> tuple[tuple[int, int], ...]:
    """The index pairs ``(j, n - j)``, ``j = 1..floor((n-1)/2)``, of Eq. 6."""
    return tuple((j, n - j) for j in range(1, (n - 1) // 2 + 1))


@dataclass(frozen=True)
class PlanarRegularComponent:
    """A planar regular n-gon in R^3: ``p_m = f1 Re(u omega_n^(jm)) + f2 Im(u omega_n^(jm))``.

    ``(f1, f2)`` is an orthonormal basis of its plane (through the origin), ``u`` its complex
    amplitude in that basis (circumradius ``|u|``).
    """

    #: The frequency ``j``.
    frequency: int
    #: The complex amplitude ``u``.
    amplitude: object
    #: First unit vector of the plane.
    f1: tuple
    #: Second unit vector of the plane.
    f2: tuple
    #: Number of vertices.
    n: int

    def vertices(self):
        """The ``n`` vertices (sympy numbers if the amplitude is exact, else floats/mpf)."""
        exact = isinstance(self.amplitude, sp.Basic)
        pts = []
        for m in range(self.n):
            if exact:
                w = sp.expand_complex(self.amplitude * sp.exp(2 * sp.pi * sp.I * sp.Rational(self.frequency * m % self.n, self.n)))
                x, y = sp.re(w), sp.im(w)
            elif isinstance(self.amplitude, (mpmath.mpc, mpmath.mpf)):
                w = self.amplitude * mpmath.expjpi(mpmath.mpf(2 * (self.frequency * m % self.n)) / self.n)
                x, y = mpmath.re(w), mpmath.im(w)
            else:
                w = complex(self.amplitude) * np.exp(2j * np.pi * (self.frequency * m % self.n) / self.n)
                x, y = w.real, w.imag
            pts.append(tuple(self.f1[k] * x + self.f2[k] * y for k in range(3)))
        return pts


@dataclass(frozen=True)
class PolygonDecomposition:
    """An n-gon as the sum of ``n`` regular n-gons ``z_j v_j`` (Eq. 5)."""

    #: The number of vertices.
    n: int
    #: ``"exact"``, ``"numpy"`` or ``"mpmath"``.
    arithmetic: str
    #: 3 for a polygon in R^3, 1 for a polygon in C^n.
    dim: int
    #: ``z_j`` for ``j = 0..n-1``: a tuple with one complex number per coordinate
    #: (sympy numbers in exact arithmetic).
    amplitudes: tuple
    _internal: tuple = field(repr=False, compare=False, default=())

    def _arith(self):
        return _ARITH[self.arithmetic](self.n)

    def component(self, j: int) -> list:
        """The vertices of ``z_j v_j`` (complex per coordinate): ``z_j omega_n^(jm)``."""
        self._check_j(j)
        a = self._arith()
        return [tuple(a.out(z * a.root(j * m)) for z in self._internal[j]) for m in range(self.n)]

    def _check_j(self, j):
        if isinstance(j, bool) or not isinstance(j, int) or not 0 <= j < self.n:
            raise FrequencyOutOfRangeError(f"frequency j must be an integer with 0 <= j < {self.n}, got {j!r}")

    def _sum(self, frequencies):
        a = self._arith()
        rows = []
        for m in range(self.n):
            row = []
            for k in range(self.dim):
                total = a.lift(0)
                for j in frequencies:
                    total = total + self._internal[j][k] * a.root(j * m)
                row.append(total)
            rows.append(row)
        return rows

    def _output(self, rows, real: bool):
        a = self._arith()
        if self.arithmetic == "exact":
            out = [[a.out(a.re(x) if real else x) for x in r] for r in rows]
            return sp.Matrix(out)
        if self.arithmetic == "numpy":
            arr = np.array(rows, dtype=complex)
            arr = arr.real if real else arr
            return arr[:, 0] if self.dim == 1 else arr
        return mpmath.matrix([[mpmath.re(x) if real else x for x in r] for r in rows])

    def reconstruct(self):
        """``sum_j z_j v_j``: the polygon back (exactly, in exact arithmetic)."""
        return self._output(self._sum(range(self.n)), real=self.dim == 3)

    def pair_polygon(self, j: int):
        """The real polygon ``z_j v_j + z_{n-j} v_{n-j}`` (Eq. 6); for R^3 input it is planar."""
        self._check_j(j)
        freqs = sorted({j, (self.n - j) % self.n})
        return self._output(self._sum(freqs), real=self.dim == 3)

    def planar_pair(self, j: int) -> tuple[PlanarRegularComponent, PlanarRegularComponent]:
        """The coplanar regular polygons of frequencies ``j`` and ``n - j`` (Eq. 6).

        With ``(f1, f2)`` an orthonormal basis of the pair's plane and ``r``, ``s`` the
        coordinates of ``R = 2 Re z_j``, ``I = 2 Im z_j`` in it read as complex numbers, the pair
        polygon ``R cos(phi) - I sin(phi)`` equals ``e^(i phi)(r + i s)/2 + e^(-i phi)(r - i s)/2``:
        regular polygons of frequencies ``j`` (amplitude ``(r + i s)/2``) and ``n - j``
        (amplitude ``(r - i s)/2``) in the same plane. For ``j = 0`` and ``j = n/2`` the pair is a
        single frequency (``j = n - j`` mod ``n``) and a single degenerate regular polygon (a point;
        a segment traversed back and forth): the first component carries all of it (amplitude
        ``(r + i s)/2``, with ``s = 0``) and the second has amplitude 0. In every case the two
        components sum to :meth:`pair_polygon`.
        Exact input gives exact sympy amplitudes and frames with square roots, unsimplified.
        """
        if self.dim != 3:
            raise InvalidPolygonError("planar pairs are defined for polygons in R^3")
        self._check_j(j)
        a = self._arith()
        k = (self.n - j) % self.n
        R = [2 * a.re(z) for z in self._internal[j]]
        I = [2 * a.im(z) for z in self._internal[j]]
        if self.arithmetic == "exact":
            f1, f2, r, s = _exact_frame(R, I)
            imag_unit = sp.I
        else:
            mp = self.arithmetic == "mpmath"
            f1, f2 = _numeric_frame(R, I, mp)
            dot = (lambda u, v: mpmath.fsum(x * y for x, y in zip(u, v))) if mp else (lambda u, v: sum(x * y for x, y in zip(u, v)))
            imag_unit = mpmath.mpc(0, 1) if mp else 1j
            r = dot(R, f1) + imag_unit * dot(R, f2)
            s = dot(I, f1) + imag_unit * dot(I, f2)
        if k == j:  # z_j v_j alone is the pair polygon (z_j real, R = 2 z_j): count it once, not twice
            first = PlanarRegularComponent(j, (r + imag_unit * s) / 2, tuple(f1), tuple(f2), self.n)
            second = PlanarRegularComponent(k, 0 * r, tuple(f1), tuple(f2), self.n)
            return first, second
        first = PlanarRegularComponent(j, (r + imag_unit * s) / 2, tuple(f1), tuple(f2), self.n)
        second = PlanarRegularComponent(k, (r - imag_unit * s) / 2, tuple(f1), tuple(f2), self.n)
        return first, second


def _field_dot(u, v):
    total = u[0] * v[0]
    for x, y in zip(u[1:], v[1:]):
        total = total + x * y
    return total


def _exact_frame(R, I):
    """Orthonormal frame of span(R, I) and the complex coordinates r, s of R, I, exactly.

    Dot products are taken in the cyclotomic field (exact zero tests); square roots only
    appear in the returned sympy numbers.
    """
    K = R[0].field
    RR = _field_dot(R, R)
    if RR == 0:
        R, I = I, [K(0)] * 3
        RR = _field_dot(R, R)
        swap = True
    else:
        swap = False
    if RR == 0:  # both zero: any plane
        one, zero = sp.Integer(1), sp.Integer(0)
        return (one, zero, zero), (zero, one, zero), sp.Integer(0), sp.Integer(0)
    IR = _field_dot(I, R)
    g = [I[k] - IR / RR * R[k] for k in range(3)]
    gg = _field_dot(g, g)
    if gg == 0:
        # span(R, I) is a line: complete by the coordinate axis least parallel to R.
        Rf = [complex(sp.N(x.to_sympy())).real for x in R]
        axis = min(range(3), key=lambda t: abs(Rf[t]))
        e = [K(1 if t == axis else 0) for t in range(3)]
        g = [e[t] - R[axis] / RR * R[t] for t in range(3)]
        gg = _field_dot(g, g)
        Ig = K(0)
    else:
        Ig = _field_dot(I, g)
    nR, ng = sp.sqrt(RR.to_sympy()), sp.sqrt(gg.to_sympy())
    f1 = tuple(x.to_sympy() / nR for x in R)
    f2 = tuple(x.to_sympy() / ng for x in g)
    r = nR  # R = |R| f1
    s = IR.to_sympy() / nR + sp.I * Ig.to_sympy() / ng
    if swap:  # we framed I instead of R (R = 0): r is 0 and s is |I|
        r, s = sp.Integer(0), nR
    return f1, f2, r, s


def _numeric_frame(R, I, mp):
    dot = (lambda u, v: mpmath.fsum(x * y for x, y in zip(u, v))) if mp else (lambda u, v: float(sum(x * y for x, y in zip(u, v))))
    sqrt = mpmath.sqrt if mp else math.sqrt
    eps = (mpmath.mpf(10) ** (-mpmath.mp.dps + 5)) if mp else 1e-13
    scale = max(1, dot(R, R), dot(I, I))
    if dot(R, R) > eps * scale:
        base, other = R, I
    elif dot(I, I) > eps * scale:
        base, other = I, [0 * x for x in I]
    else:
        one = mpmath.mpf(1) if mp else 1.0
        return [one, 0 * one, 0 * one], [0 * one, one, 0 * one]
    nb = sqrt(dot(base, base))
    f1 = [x / nb for x in base]
    g = [other[k] - dot(other, f1) * f1[k] for k in range(3)]
    if dot(g, g) <= eps * scale:
        axis = min(range(3), key=lambda t: abs(f1[t]))
        e = [1 if t == axis else 0 for t in range(3)]
        g = [e[t] - f1[axis] * f1[t] for t in range(3)]
    ng = sqrt(dot(g, g))
    return f1, [x / ng for x in g]


def decompose(polygon) -> PolygonDecomposition:
    """Decompose an n-gon into the regular n-gons ``z_j v_j`` of Eq. 5.

    >>> d = decompose([1, 1j, -1, -1j])        # a regular square in C^4: all in v_1
    >>> [abs(z[0]) > 1e-12 for z in d.amplitudes]
    [False, True, False, False]
    """
    rows, kind, dim = as_vertex_rows(polygon)
    n = len(rows)
    a = _ARITH[kind](n)
    if kind == "numpy":
        arr = np.array(rows, dtype=complex)
        internal = tuple(tuple(complex(x) for x in r) for r in np.fft.fft(arr, axis=0) / n)
    else:
        lifted = [[a.lift(x) for x in r] for r in rows]
        internal = []
        for j in range(n):
            z = []
            for k in range(dim):
                total = a.lift(0)
                for m in range(n):
                    total = total + lifted[m][k] * a.root(-j * m)
                z.append(total / n)
            internal.append(tuple(z))
        internal = tuple(internal)
    amplitudes = tuple(tuple(a.out(z) for z in zs) for zs in internal)
    return PolygonDecomposition(n=n, arithmetic=kind, dim=dim, amplitudes=amplitudes, _internal=internal)
