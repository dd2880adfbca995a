"""The characteristic map's control nets as exact functions of ``t = cos(2 pi/n)``: one formula for every valence.

:mod:`symdecomp.analysis.characteristic` builds the frequency-1 eigenvector of the 2-ring matrix at one valence in
Arb balls. Here the same eigenvector is built once, exactly, for every ``n`` at once. Its entries are polynomials in
``omega = e^{2 pi i/n} = t + i s`` (``s = sin(2 pi/n)``) and the eigenvalue ``L = lambda_1``; they are reduced in the
ring ``Q[L, s, t] / (s^2 - 1 + t^2, L^2 - tr(t) L + det(t))`` (``tr``, ``det``: the trace and determinant of the
1-ring block ``M(omega)`` at frequency 1, polynomials in ``t`` for mirror-symmetric rules).

* The null vector of ``M - L`` on the 1-ring is ``(m_01, L - m_00)`` (quads; ``1`` on triangles); the outer part is
  ``adj(L I - S) C c_1`` with ``S`` the outer block and ``C`` the block between them, so the eigenvector is scaled by
  ``det(L I - S)``, the outer characteristic polynomial at ``L`` (the same at every frequency and valence,
  :func:`~symdecomp.analysis.characteristic.outer_charpoly`), positive once ``L`` exceeds the outer eigenvalues.
* It is multiplied by ``conj(m_01)`` so that its value at ``a_0`` is ``|m_01|^2 det(L I - S) > 0``: the map is a
  positive multiple (depending on ``n`` only) of the one :func:`~symdecomp.analysis.characteristic.frequency_eigenvector`
  normalises to 1 at ``a_0``, which has the same Jacobian sign and winding number.
* Mirror-symmetric rules make every value ``x + i s y`` with ``x``, ``y`` free of ``s``: the image of sector 0 is a
  wedge of angle ``2 pi/n`` that collapses as ``n`` grows, and ``(x, y)`` is that image stretched by ``1/s`` across
  the ray of ``a_0``. Its Jacobian is ``J/s``, which has a positive limit as ``n -> oo`` (the convergence the proof for
  every ``n`` needs: :mod:`symdecomp.verify.c1_uniform`); a value that is not of that form is refused.

The nets are those of :func:`~symdecomp.analysis.characteristic.subpatch_nets` (quads: three ``4 x 4`` B-spline
nets; triangles: ``{lattice point: value}`` on the 12 points of each of the three box-spline patches), with values
:class:`UniformValue` (``x``, ``y`` exact polynomials in ``L`` and ``t``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp
from sympy.polys.rings import PolyElement, ring

from symdecomp.analysis.characteristic import SUBPATCH_FACES, TRIANGLES, ring_layout, triangle_patch_points
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.scheme import Scheme
from symdecomp.symbols import n as N

__all__ = ["RING", "UniformValue", "UniformNets", "uniform_nets", "reduce_element"]

#: ``Q[L, s, t]`` in lex order ``L > s > t``: the leading terms of ``s^2 + t^2 - 1`` and of ``L^2 - tr L + det`` are
#: ``s^2`` and ``L^2``, so reducing by both (a Groebner basis: coprime leading terms) is well defined.
RING, L, S, T = ring("L,s,t", sp.QQ, sp.lex)


def reduce_element(p: PolyElement, quadratic: PolyElement) -> PolyElement:
    """``p`` reduced by ``s^2 + t^2 - 1`` and ``quadratic`` (``L^2 - tr L + det``, or ``L - lambda`` on a 1 x 1 block)."""
    return p.rem([S**2 + T**2 - 1] + ([quadratic] if quadratic else []))


@dataclass(frozen=True)
class UniformValue:
    """A value ``x + i s y`` of the eigenvector (``x``, ``y`` reduced polynomials in ``L``, ``t``); arithmetic as needed
    by the net conversions (sums and rational multiples)."""

    #: The real part.
    x: PolyElement
    #: The imaginary part divided by ``s = sin(2 pi/n)``.
    y: PolyElement

    def __add__(self, other):
        return UniformValue(self.x + other.x, self.y + other.y)

    def __sub__(self, other):
        return UniformValue(self.x - other.x, self.y - other.y)

    def __mul__(self, w):  # a rational weight
        return UniformValue(self.x * w, self.y * w)

    __rmul__ = __mul__

    def __truediv__(self, w):
        return UniformValue(self.x * sp.QQ(1, w), self.y * sp.QQ(1, w))

    @property
    def real(self) -> PolyElement:
        return self.x

    @property
    def imag(self) -> PolyElement:
        return self.y


@dataclass(frozen=True)
class UniformNets:
    """Sector 0's characteristic nets for every ``n`` (module docstring)."""

    #: The nets as :func:`~symdecomp.analysis.characteristic.subpatch_nets` lays them out, of :class:`UniformValue`.
    nets: tuple
    #: ``L^2 - tr(t) L + det(t)`` (quads) or ``L - lambda(t)`` (triangles), in :data:`RING`.
    quadratic: PolyElement
    #: ``tr(t)`` and ``disc(t) = tr^2 - 4 det`` as sympy polynomials in the symbol ``t`` (``disc = 0`` on triangles).
    trace: sp.Expr
    discriminant: sp.Expr
    #: ``det(L I - S)``, the positive scale of the eigenvector, reduced.
    scale: PolyElement


class _Complex:
    """``re + i im`` over :data:`RING`, reduced after every product."""

    def __init__(self, re, im, quadratic):
        self.re, self.im, self.q = re, im, quadratic

    def __add__(self, o):
        return _Complex(self.re + o.re, self.im + o.im, self.q)

    def __sub__(self, o):
        return _Complex(self.re - o.re, self.im - o.im, self.q)

    def __mul__(self, o):
        re, im = self.re * o.re - self.im * o.im, self.re * o.im + self.im * o.re
        return _Complex(reduce_element(re, self.q), reduce_element(im, self.q), self.q)

    def conjugate(self):
        return _Complex(self.re, -self.im, self.q)


def _laurent(weights, q) -> _Complex:
    """``sum w omega^k`` over ``((k, w), ...)`` with ``omega = t + i s``."""
    total = _Complex(RING(0), RING(0), q)
    for k, w in weights:
        w = sp.sympify(w, strict=True)
        if w.has(N) or not w.is_Rational:
            raise NotApplicableError(f"the 1-ring weight {w} is not a rational constant; the map is built valence by valence")
        power = _Complex(RING(1), RING(0), q)
        step = _Complex(T, S if k > 0 else -S, q)
        for _ in range(abs(k)):
            power = power * step
        total = total + power * _Complex(RING(sp.QQ(int(w.p), int(w.q))), RING(0), q)
    return total


def _det(rows, q) -> _Complex:
    """Laplace expansion along the first row (the blocks are at most 4 x 4)."""
    if len(rows) == 1:
        return rows[0][0]
    total = _Complex(RING(0), RING(0), q)
    for c, entry in enumerate(rows[0]):
        minor = _det([row[:c] + row[c + 1:] for row in rows[1:]], q)
        total = total + entry * minor if c % 2 == 0 else total - entry * minor
    return total


def _blocks(scheme: Scheme, q):
    """The level-1 rows ``B(omega)`` (1-ring rows by the scheme's rules, the rest by the regular rules) as :class:`_Complex`."""
    layout = ring_layout(scheme.lattice)
    rows = []
    for rule in scheme.stencils():
        row = [_laurent(pairs, q) for pairs in (rule.a, rule.b)[:layout.one_ring]]
        rows.append(row + [_Complex(RING(0), RING(0), q)] * (layout.two_ring - layout.one_ring))  # the 1-ring reads the 1-ring
    for r in range(layout.one_ring, len(layout.labels)):
        rows.append([_laurent([(lo, sp.Rational(int(w.p), int(w.q))) for lo, w in layout.offsets[r][c]], q)
                     for c in range(layout.two_ring)])
    return layout, rows


def _quadratic(M) -> tuple[PolyElement, sp.Expr, sp.Expr]:
    """``L^2 - tr L + det`` of the 1-ring block (its entries' imaginary parts cancel in trace and determinant)."""
    if len(M) == 1:
        lam = M[0][0]
        return L - lam.re, _to_sympy(lam.re), sp.Integer(0)
    tr = M[0][0] + M[1][1]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if tr.im or det.im or tr.re.degree(S) > 0 or det.re.degree(S) > 0:
        raise NotApplicableError("the rules are not mirror symmetric: M(omega) is not a function of cos(2 pi/n)")
    return L**2 - tr.re * L + det.re, _to_sympy(tr.re), sp.expand(_to_sympy(tr.re) ** 2 - 4 * _to_sympy(det.re))


def _to_sympy(p: PolyElement) -> sp.Expr:
    return p.as_expr().subs(sp.Symbol("t"), sp.Symbol("t", real=True))


def uniform_nets(scheme: Scheme) -> UniformNets:
    """The characteristic nets of ``scheme`` for every ``n`` (module docstring); :class:`NotApplicableError` (one line) where
    a 1-ring weight depends on ``n`` or the rules are not mirror symmetric."""
    return _uniform_nets(scheme)


@lru_cache(maxsize=8)
def _uniform_nets(scheme: Scheme) -> UniformNets:
    layout, rows = _blocks(scheme, None)  # no reduction by the eigenvalue until its quadratic is known
    k1, k2 = layout.one_ring, layout.two_ring
    quadratic, trace, disc = _quadratic([row[:k1] for row in rows[:k1]])
    layout, rows = _blocks(scheme, quadratic)
    lam = _Complex(L, RING(0), quadratic)
    one = [rows[0][1], lam - rows[0][0]] if k1 == 2 else [_Complex(RING(1), RING(0), quadratic)]
    if k1 == 2 and not (one[0].re or one[0].im):
        raise NotApplicableError("m_01 vanishes: the eigenvector is not normalised at a_0 (the map is built valence by valence)")
    shifted = [[(lam if r == c else _Complex(RING(0), RING(0), quadratic)) - rows[k1 + r][k1 + c] for c in range(k2 - k1)]
               for r in range(k2 - k1)]
    scale = _det(shifted, quadratic)
    rhs = [sum((rows[k1 + r][m] * one[m] for m in range(k1)), _Complex(RING(0), RING(0), quadratic)) for r in range(k2 - k1)]
    outer = []
    for r in range(k2 - k1):  # Cramer's rule: det(L I - S) times the solution
        replaced = [row[:r] + [rhs[i]] + row[r + 1:] for i, row in enumerate(shifted)]
        outer.append(_det(replaced, quadratic))
    coeffs = [c * scale for c in one] + outer
    norm = one[0].conjugate() if k1 == 2 else _Complex(RING(1), RING(0), quadratic)
    values = {}
    for r, label in enumerate(layout.labels):
        value = sum((rows[r][m] * coeffs[m] for m in range(k2)), _Complex(RING(0), RING(0), quadratic)) * norm
        values[label] = value
    return UniformNets(_nets(scheme, values, quadratic), quadratic, trace, disc, scale.re)


def _scaled(value: _Complex) -> UniformValue:
    """``re + i s y`` as ``(re, y)``; refused unless ``re`` is free of ``s`` and ``im`` is ``s`` times a polynomial free of it."""
    if value.re.degree(S) > 0 or any(m[1] != 1 for m in value.im.monoms()):
        raise NotApplicableError("the eigenvector is not mirror symmetric about the ray of a_0")
    y = RING({(m[0], 0, m[2]): c for m, c in value.im.terms()}) if value.im else RING(0)
    return UniformValue(value.re, y)


def _nets(scheme: Scheme, values: dict, quadratic) -> tuple:
    lat = scheme.lattice
    cache: dict = {}

    def value(u: int, v: int) -> UniformValue:
        if (u, v) not in cache:
            label = lat.canonical(0, u, v)
            if label is None:
                cache[(u, v)] = UniformValue(RING(0), RING(0))
            else:
                s, uu, vv = label
                rot = _laurent([(s, 1)], quadratic) if s else _Complex(RING(1), RING(0), quadratic)
                cache[(u, v)] = _scaled(values[(uu, vv)] * rot)
        return cache[(u, v)]

    return lat.select(_LAYOUTS, "the characteristic ring's sub-patch nets")(value)


def _quad_layout(value):
    return tuple([[value(a - 1 + i, b - 1 + k) for k in range(4)] for i in range(4)] for a, b in SUBPATCH_FACES)


def _triangle_layout(value):
    return tuple({p: value(*p) for p in triangle_patch_points(t)} for t in TRIANGLES)


#: How the nets are laid out on each kind of regular patch (as :func:`~symdecomp.analysis.characteristic.subpatch_nets`).
_LAYOUTS = {BICUBIC: _quad_layout, BOX_SPLINE: _triangle_layout}
