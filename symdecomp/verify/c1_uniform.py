"""The characteristic map regular and injective for every ``n >= N0`` at once: exact signs in ``t = cos(2 pi/n)``.

Reif's test (:mod:`symdecomp.verify.c1`) decides at one valence that the characteristic map is regular (the
Bernstein-Bezier coefficients of its Jacobian on sector 0's sub-patches all of one sign) and injective (the inner
boundary winds once around the origin). Here the same certificate is proved for all valences ``n >= N0`` in one go,
from the nets of :mod:`symdecomp.analysis.characteristic_uniform`: exact polynomials in ``t`` and the eigenvalue ``L``,
with the image stretched by ``1/sin(2 pi/n)`` across the ray of ``a_0`` (so that it converges as ``n -> oo`` instead of
collapsing to a ray; the stretch has a positive determinant and keeps the wedge of sector 0).

* **Where.** Every ``n >= N0`` has ``t = cos(2 pi/n)`` in ``[t_0, 1]`` with the rational
  ``t_0 = 1 - (44/(7 N0))^2 / 2 <= cos(2 pi/N0)`` (``cos x >= 1 - x^2/2`` and ``pi < 22/7``), or ``t_0 = cos(2 pi/N0)``
  where that is rational (``N0 = 3, 4, 6``); the limit ``n -> oo`` is ``t = 1``, inside the interval.
* **Signs with a square root.** ``L = (tr + r)/2``, ``r = sqrt(disc)`` (the dominant root of ``L^2 - tr L + det``,
  steps S1-S3 of :mod:`symdecomp.verify.c1_every_n`). A reduced coefficient ``F0(t) + F1(t) L`` is ``U + V r`` with
  ``U = F0 + F1 tr/2``, ``V = F1/2``; it is positive on the interval when ``U > 0`` and ``V >= 0``, or ``U >= 0`` and
  ``V > 0``, or ``U > 0 >= V`` and ``U^2 - V^2 disc > 0``, or ``V > 0 >= U`` and ``V^2 disc - U^2 > 0``: each a sign of
  a polynomial in ``t`` on ``[t_0, 1]``, decided by Sturm sequences in FLINT
  (:func:`~symdecomp.algebra.interval_signs.positive_on`). Nonnegative likewise with weak inequalities.
* **Regularity.** The eigenvector's scale ``|m_01|^2 det(L I - S)`` is positive, and every Bezier coefficient of the
  stretched map's Jacobian on the three sub-patches is positive on ``[t_0, 1]`` (no subdivision).
* **Injectivity.** The control points of sector 0's inner boundary curve (stretched coordinates ``(x, y)``) lie in the
  closed wedge ``y >= 0``, ``x - t y >= 0`` between the rays of ``a_0`` and ``a_1`` (a convex cone of angle
  ``2 pi/n < pi``), none at the origin (``x + y > 0``): the curve stays in the wedge and sweeps exactly ``2 pi/n``, so
  the whole boundary winds once, as the positive Jacobian requires (Reif's test's injectivity criterion,
  :mod:`symdecomp.verify.c1`).
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.interval_signs import positive_on
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.triangle_bezier import bezier_indices
from symdecomp.analysis.characteristic_uniform import RING, UniformNets, reduce_element, uniform_nets
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.box_spline import DEGREE
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.scheme import Scheme
from symdecomp.verify.bezier import bspline_to_bezier, jacobian_net, triangle_jacobian_net

__all__ = ["UniformMapResult", "t_lower_bound", "sign_with_root", "uniform_map", "root_parts", "jacobian_coefficients"]

T = sp.Symbol("t", real=True)
_PI_ABOVE = sp.Rational(22, 7)


def t_lower_bound(first: int) -> sp.Rational:
    """A rational ``t_0 <= cos(2 pi/first)`` (module docstring): every ``n >= first`` has ``cos(2 pi/n)`` in ``[t_0, 1]``.

    ``cos(2 pi/first)`` itself where it is rational (``first = 3, 4, 6``).

    >>> t_lower_bound(3), t_lower_bound(5), t_lower_bound(5) <= sp.cos(2 * sp.pi / 5)
    (-1/2, 257/1225, True)
    """
    exact = sp.cos(2 * sp.pi / first)
    return exact if exact.is_Rational else 1 - (2 * _PI_ABOVE / first) ** 2 / 2


@dataclass(frozen=True)
class UniformMapResult:
    """The characteristic map for every ``n >= first``: regular and injective (``proved``) or not shown (``open``)."""

    #: ``proved`` or ``open``.
    status: str
    #: The first valence covered.
    first: int
    #: ``t_0``: the interval ``[t_0, 1]`` of ``t = cos(2 pi/n)`` the signs are proved on.
    t_low: sp.Rational
    #: What was shown, one sentence per part (or why it is open).
    facts: tuple[str, ...]
    #: The Jacobian's Bezier coefficients and boundary control points whose signs were decided.
    coefficients: int


def _t_poly(p) -> flint.fmpq_poly:
    """A polynomial in ``t`` (a sympy ``Poly`` or expression, or an ``fmpq_poly``) as an ``fmpq_poly``."""
    if isinstance(p, flint.fmpq_poly):
        return p
    poly = p if isinstance(p, sp.Poly) else sp.Poly(sp.sympify(p, strict=True), T, domain=sp.QQ)
    return flint.fmpq_poly([to_fmpq(c) for c in reversed(poly.all_coeffs())])


def _coefficient(c) -> flint.fmpq:
    """A coefficient of :data:`RING` (sympy's ``QQ``, whatever its ground type) as an ``fmpq``."""
    return c if isinstance(c, flint.fmpq) else flint.fmpq(int(c.numerator), int(c.denominator))


def _powers_of_L(p) -> dict[int, flint.fmpq_poly] | None:
    """An element of :data:`RING` free of ``s`` as ``{k: coefficient of L^k}``, polynomials in ``t``; ``None`` if it has
    ``s``."""
    coeffs: dict[int, list] = {}
    for (k, j, i), c in p.terms():
        if j:
            return None
        row = coeffs.setdefault(k, [])
        row.extend([0] * (i + 1 - len(row)))
        row[i] = _coefficient(c)
    return {k: flint.fmpq_poly(row) for k, row in coeffs.items()}


@dataclass(frozen=True)
class _Field:
    """The quadratic (or linear) relation of ``L`` over ``Q[t]`` and ``tr``, ``disc`` as ``fmpq_poly``."""

    relation: dict
    trace: flint.fmpq_poly
    discriminant: flint.fmpq_poly

    @classmethod
    def of(cls, nets: UniformNets) -> _Field:
        return cls(_powers_of_L(nets.quadratic), _t_poly(nets.trace), _t_poly(nets.discriminant))


def root_parts(p, nets: UniformNets, field: _Field | None = None) -> tuple[flint.fmpq_poly, flint.fmpq_poly]:
    """``p = F0 + F1 L`` (reduced) as ``(U, V)`` with ``p = U + V sqrt(disc)``.

    Free of ``s``, ``p`` is reduced by the monic relation of ``L`` alone (``L^d = -sum q_k L^k``, highest powers
    first), in FLINT: the same normal form as :func:`~symdecomp.analysis.characteristic_uniform.reduce_element`."""
    field = field or _Field.of(nets)
    powers = _powers_of_L(p)
    if powers is None:
        powers = _powers_of_L(reduce_element(p, nets.quadratic))
        if powers is None:
            raise NotApplicableError("a Jacobian coefficient still depends on sin(2 pi/n)")
    degree = max(field.relation)
    for k in range(max(powers, default=0), degree - 1, -1):
        if k not in powers:
            continue
        c = powers.pop(k)
        for i, q in field.relation.items():
            if i < degree:
                powers[k - degree + i] = powers.get(k - degree + i, flint.fmpq_poly([])) - c * q
    zero = flint.fmpq_poly([])
    f0, f1 = powers.get(0, zero), powers.get(1, zero)
    return f0 + f1 * field.trace / 2, f1 / 2


def sign_with_root(U, V, disc, low, high, *, strict: bool = True) -> bool:
    """Whether ``U + V sqrt(disc)`` is positive (``strict``) or nonnegative on ``[low, high]`` (module docstring), exactly;
    ``False`` where none of the sufficient sign patterns is shown. ``U``, ``V``, ``disc``: polynomials in ``t`` (sympy
    ``Poly`` or expression, or FLINT ``fmpq_poly``), decided in FLINT."""
    U, V, disc = _t_poly(U), _t_poly(V), _t_poly(disc)

    def sign(p, s=True):
        return positive_on(p, low, high, strict=s)

    if V.is_zero():
        return sign(U, strict)
    u_weak, v_weak = sign(U, False), sign(V, False)
    if u_weak and v_weak:
        return not strict or sign(U) or sign(V)
    square = U * U - V * V * disc
    if u_weak and sign(-V, False):
        return sign(square, strict) and (not strict or sign(U))
    if v_weak and sign(-U, False):
        return sign(-square, strict) and (not strict or sign(V))
    return False


def jacobian_coefficients(nets: UniformNets, lat) -> list:
    """The Bezier coefficients of the Jacobian of sector 0's sub-patches (stretched by ``1/s``), exact in ``L`` and ``t``."""
    return lat.select(_JACOBIANS, "the characteristic ring's Jacobian nets")(nets.nets)


def _quad_jacobians(nets) -> list:
    out = []
    for net in nets:
        x = bspline_to_bezier([[v.x for v in row] for row in net])
        y = bspline_to_bezier([[v.y for v in row] for row in net])
        out.extend(c for row in jacobian_net(x, y) for c in row)
    return out


def _triangle_nets(nets) -> list:
    from symdecomp.verify.c1 import box_nets

    return [([v.x for v in net], [v.y for v in net]) for net in box_nets(nets)]


def _triangle_jacobians(nets) -> list:
    return [c for x, y in _triangle_nets(nets) for c in triangle_jacobian_net(x, y)]


def _quad_boundary(nets) -> list:
    first, last = (bspline_to_bezier(nets[p]) for p in (0, 2))
    return [first[0][k] for k in range(4)] + [last[i][0] for i in range(3, -1, -1)]


def _triangle_boundary(nets) -> list:
    x, y = _triangle_nets(nets)[1]
    pos = {i: k for k, i in enumerate(bezier_indices(DEGREE))}
    return [_Point(x[pos[(DEGREE - k, 0, k)]], y[pos[(DEGREE - k, 0, k)]]) for k in range(DEGREE + 1)]


@dataclass(frozen=True)
class _Point:
    x: object
    y: object


_JACOBIANS = {BICUBIC: _quad_jacobians, BOX_SPLINE: _triangle_jacobians}
_BOUNDARIES = {BICUBIC: _quad_boundary, BOX_SPLINE: _triangle_boundary}


def uniform_map(scheme: Scheme, first: int) -> UniformMapResult:
    """Regularity and injectivity of the characteristic map for every ``n >= first`` (module docstring); ``open`` with
    the first part that is not shown."""
    from symdecomp.analysis.characteristic import check_applicable

    low = t_lower_bound(first)
    try:
        check_applicable(scheme)
        nets = uniform_nets(scheme)
    except NotApplicableError as exc:
        return UniformMapResult("open", first, low, (str(exc),), 0)
    field = _Field.of(nets)
    check = lambda p, strict=True: sign_with_root(*root_parts(p, nets, field), field.discriminant, low, 1, strict=strict)  # noqa: E731
    interval = f"t = cos(2 pi/n) in [{low}, 1] (every n >= {first}, and the limit n -> oo at t = 1)"
    if not check(nets.scale):
        return UniformMapResult("open", first, low, (f"det(L I - S) is not shown positive for {interval}",), 0)
    coeffs = jacobian_coefficients(nets, scheme.lattice)
    bad = next((k for k, c in enumerate(coeffs) if not check(c)), None)
    if bad is not None:
        return UniformMapResult("open", first, low, (f"Bezier coefficient {bad} of the Jacobian is not shown positive for "
                                                     f"{interval} (no subdivision is tried)",), bad)
    points = scheme.lattice.select(_BOUNDARIES, "the characteristic ring's inner boundary")(nets.nets)
    t = RING.gens[2]
    in_wedge = all(check(p.y, False) and check(p.x - t * p.y, False) and check(p.x + p.y) for p in points)
    facts = (
        f"the eigenvector's scale det(L I - S) (the outer characteristic polynomial at L) is positive for {interval}",
        f"all {len(coeffs)} Bezier coefficients of the Jacobian of sector 0's sub-patches (stretched by 1/sin(2 pi/n) "
        f"across the ray of a_0) are positive polynomials in t and L = (tr + sqrt(disc))/2 on [{low}, 1] (Sturm "
        "sequences): the characteristic map is regular for every n >= " + str(first),
        f"the {len(points)} control points of sector 0's inner boundary lie in the closed wedge between the rays of a_0 and "
        f"a_1, none at 0, for every t in [{low}, 1]: the boundary winds once, the map is injective"
        if in_wedge else "the inner boundary's control points are not shown to lie in sector 0's wedge: injectivity open",
    )
    return UniformMapResult("proved" if in_wedge else "open", first, low, facts, len(coeffs) + len(points))
