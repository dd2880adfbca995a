"""Designing 1-rings with prescribed limit properties, from the polygonal decomposition (issue 22).

A 1-ring ``P`` (rows ``O, a_0.., b_0..`` as in Eq. 10; ``O, a_0..`` on triangles) is a sum of
components in the eigenvector basis of the 1-ring subdivision matrix, frequency by frequency
(Eq. 12-13): a right eigenvector ``X`` of the frequency matrix ``E(omega^j)`` gives the ring
vector ``X_q omega^(j s)`` on the vertex of class ``q`` in sector ``s``; a left eigenvector ``Y`` the
functional ``Y_q omega^(-j s)``. In a frame ``(u, v, N)`` (``N`` the prescribed normal, ``u`` the
prescribed first tangent direction projected off ``N``, ``v = N x u``):

* **position** ``p``: ``O`` and the class means of the in-plane and frequency-0 parts are chosen so
  that the position mask (the left eigenvector of ``E_0`` for 1) returns ``p``;
* **tangent plane**: the in-plane coordinates are the frequency-1 eigenvector (the characteristic
  map's 1-ring), rounded to doubles **with the ring's mirror symmetry kept** (``x`` even, ``y`` odd under
  ``a_s <-> a_(-s)``, ``b_s <-> b_(-1-s)``) and zero class means; the tangent masks of a mirror-symmetric
  scheme are even (first) and odd (second), so ``t_1`` is exactly along ``u`` and ``t_2`` along ``v``;
* **heights** along ``N``: ``elliptic`` times the frequency-0 eigenvector of the second largest
  eigenvalue of ``E_0`` (the Eq. 43 matrix on quads; scaled so that its largest class component, the
  height of the ``a_i`` or of the ``b_i``, is 1), which the position mask does not see, plus
  ``Re(B e^(-2iT) X_q omega^(2s))``, ``X`` the dominant eigenvector of ``E(omega^2)`` with ``X_a = 1`` (the
  hyperbolic component, amount ``B``, angle ``T``; none at ``n = 3`` and not separable at ``n = 4``).
  Heights of frequency 0 and 2 are invisible to the tangent masks, so the normal is ``N``; rounded, the
  saddle keeps that exactly at even ``n`` only (:func:`_rational_saddle`).

Each point is ``p + x u + y v + h N`` with the scalars ``x, y, h`` rounded to doubles and ``u, v, N`` made
primitive integer vectors (so the coordinates are terminating decimals when ``p`` is, and an OBJ or OFF file
holds the net exactly). What rounding cannot spoil is kept exact: class-constant heights stay constant, the
symmetry and the means are exact, and one vertex group (``O``, or one class by a constant) is moved by exactly
what the position mask needs, a group whose move is a terminating decimal when the weights are rational
(Catmull-Clark at every valence, Loop at 3, 4, 6); with irrational weights the move is rounded.
The achieved values are then **measured on the rational net**
(:func:`limit_frame`): the position exactly (:func:`~symdecomp.analysis.inspection.position_weights`),
the tangents' components along ``N`` and across ``u`` exactly in ``Q(zeta_4n)`` (each class's frequency-1
Fourier sum; a class weight of a mirror-symmetric scheme is real up to the phase of its class's angle),
the amounts from the left eigenvectors in 40-digit arithmetic.

The outer ring (the 2-ring a patch needs) continues the design on the regular sector lattice: the vertex
``(s, u, v)`` of :meth:`~symdecomp.schemes.lattice.Lattice.ring_mesh` is at ``z = u e^(i theta_s) + v
e^(i theta_(s+1))`` in the plane, with height ``elliptic |z|^2 + Re(B e^(-2iT) z^2)``. It does not change
the limit point, tangents or normal (the masks see the 1-ring only).

:func:`~symdecomp.analysis.redesign.redesign_vertex` takes a measured 1-ring and makes the smallest change (Euclidean norm on the
ring's points, along ``N``) that makes the limit normal parallel to ``N`` and/or removes the
hyperbolic heights: the heights are projected orthogonally off the span of the tangent masks (and of each
class's frequency-2 Fourier coefficient), which in the orthogonal Fourier basis is a change of the
frequencies 1, 2, n-2, n-1 only.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> d = design_ring(catmull_clark(), 5, normal=(0, 0, 1), position=(1, 2, 3))
>>> d.achieved.position, d.achieved.normal_exact, [round(x, 12) + 0.0 for x in d.achieved.normal]
((1, 2, 3), True, [0.0, 0.0, 1.0])
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField
from symdecomp.analysis.design_input import amount, dot, frame, vector
from symdecomp.analysis.frequency import ring_blocks
from symdecomp.analysis.inspection import position_weights
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import INPUT_LIMITS

__all__ = ["LimitFrame", "RingDesign", "design_ring", "limit_frame", "ring_amounts", "frame"]

#: The largest valence designed (40-digit eigenvectors per frequency and exact sums in Q(zeta_4n) per class).
MAX_VALENCE = INPUT_LIMITS["design_ring(n)"][0]

_DPS = 40


@dataclass(frozen=True)
class LimitFrame:
    """The limit properties of a 1-ring, measured (see the module docstring)."""

    #: The limit position, exact (sympy numbers).
    position: tuple
    #: The two tangents (tangent masks applied), doubles.
    tangents: tuple
    #: The unit normal ``t_1 x t_2/|t_1 x t_2|``, doubles.
    normal: tuple
    #: Whether ``t_1`` and ``t_2`` are exactly perpendicular to the target normal (decided in ``Q(zeta_4n)``).
    normal_exact: bool
    #: Whether ``t_1`` is exactly along the target tangent ``u`` (``t_1 . v = 0`` exactly); ``None`` without a target.
    tangent_exact: bool | None
    #: The coefficient of the heights on the elliptic eigenvector (frequency 0, second eigenvalue of ``E_0``).
    elliptic: float
    #: The hyperbolic amount ``B`` (frequency 2 heights ``Re(B e^(-2iT) X_q omega^(2s))``); ``None`` at ``n <= 4``.
    hyperbolic: float | None
    #: The hyperbolic angle ``T`` in radians (``None`` with ``hyperbolic``).
    angle: float | None


@dataclass(frozen=True)
class RingDesign:
    """A designed (or redesigned) control net and its measured limit properties."""

    #: The scheme's name.
    scheme: str
    #: The valence.
    n: int
    #: The control net (the 2-ring of the vertex for a new design; the whole mesh for a redesign).
    mesh: PolygonMesh
    #: The vertex designed.
    vertex: int
    #: Its 1-ring's vertex ids, ``O, a_0.., b_0..``.
    ring: tuple[int, ...]
    #: What the net achieves.
    achieved: LimitFrame
    #: For a redesign: the Euclidean norm of the change of the 1-ring (0 for a new design).
    change: float = 0.0


def _frequency_matrix(scheme: Scheme, n: int, j: int) -> mpmath.matrix:
    E = ring_blocks(scheme, 1).frequency_matrix().subs(N, n)  # an edge rule in n: at this valence
    with mpmath.workdps(_DPS):
        w = mpmath.expjpi(mpmath.mpf(2 * j) / n)
        return mpmath.matrix([[_mp_eval(E[r, c], w) for c in range(E.shape[1])] for r in range(E.shape[0])])


def _mp_eval(expr, w):
    f = sp.lambdify(OMEGA, expr, "mpmath")
    return mpmath.mpc(f(w))


def _dominant(M: mpmath.matrix, skip_one: bool = False):
    """``(lambda, left Y, right X)`` of the eigenvalue of largest modulus (below 1 if ``skip_one``)."""
    with mpmath.workdps(_DPS):
        values, left, right = mpmath.eig(M, left=True, right=True)
        order = sorted(range(len(values)), key=lambda k: -abs(values[k]))
        if skip_one:
            order = [k for k in order if abs(values[k] - 1) > mpmath.mpf(10) ** (-20)]
        k = order[0]
        return values[k], [left[k, c] for c in range(M.cols)], [right[r, k] for r in range(M.rows)]


def _elliptic(scheme: Scheme, n: int):
    """Right and left eigenvectors of ``E_0`` (rows ``O, classes``; acting on class means) for its second eigenvalue,
    the right one scaled so that its largest class component is 1."""
    E0 = ring_blocks(scheme, 1).frequency_zero_matrix(n)
    with mpmath.workdps(_DPS):
        M = mpmath.matrix([[mpmath.mpmathify(sp.N(E0[r, c], _DPS)) for c in range(E0.shape[1])] for r in range(E0.shape[0])])
        _, Y, X = _dominant(M, skip_one=True)
        top = max(range(1, len(X)), key=lambda k: abs(X[k]))  # Catmull-Clark at n = 3: the a_i stay (x_a = 0)
        return [mpmath.re(x / X[top]) for x in X], [mpmath.re(y) for y in Y]


def _hyperbolic(scheme: Scheme, n: int):
    if n <= 4:
        return None
    _, Y, X = _dominant(_frequency_matrix(scheme, n, 2))
    with mpmath.workdps(_DPS):
        return [x / X[0] for x in X], Y


def _layout(scheme: Scheme, n: int) -> list[tuple[int, int]]:
    """``(class, sector)`` of the 1-ring's vertices after ``O``, in matrix order."""
    K = ring_blocks(scheme, 1).class_count
    return [(q, s) for q in range(K) for s in range(n)]


def _classes(scheme: Scheme) -> tuple:
    return ring_blocks(scheme, 1).classes


def _mirror(s: int, offset: int, n: int) -> int:
    """The sector of the mirror image (angle ``-(2 s + offset) pi/n``) of the class vertex in sector ``s``."""
    return (-s - offset) % n


def _symmetric_plane(scheme: Scheme, n: int, X1, su, sv) -> dict:
    """In-plane ``(x, y)`` per ``(class, sector)``: ``X1_q omega^s`` in units of ``1/su``, ``1/sv``, rounded to doubles,
    mirror symmetric, zero class means."""
    out = {}
    for q, (_, offset) in enumerate(_classes(scheme)):
        xs, ys = {}, {}
        for s in range(n):
            m = _mirror(s, offset, n)
            if m < s:
                continue
            z = X1[q] * mpmath.expjpi(mpmath.mpf(2 * s) / n)
            xs[s] = xs[m] = Fraction(float(mpmath.re(z) * su))
            y = Fraction(float(mpmath.im(z) * sv))
            ys[s], ys[m] = (Fraction(0), Fraction(0)) if m == s else (y, -y)
        total = sum(xs.values(), Fraction(0))
        fixed = [s for s in range(n) if _mirror(s, offset, n) == s]
        if fixed:
            xs[fixed[0]] -= total
        else:
            xs[0] -= total / 2
            xs[_mirror(0, offset, n)] -= total / 2
        out.update({(q, s): (xs[s], ys[s]) for s in range(n)})
    return out


def _heights(scheme: Scheme, n: int, elliptic, hyperbolic, angle) -> tuple:
    """``(h_O, {(class, sector): h})``: the elliptic and hyperbolic heights (doubles), then one class moved by a
    constant so that the position mask sees no height (exactly when its weights are rational)."""
    Xe, _ = _elliptic(scheme, n)
    K = len(_classes(scheme))
    e = mpmath.mpf(float(elliptic))
    c = None
    if hyperbolic != 0:
        hyper = _hyperbolic(scheme, n)
        if hyper is None:
            raise NotApplicableError(f"at valence {n} there is no separate hyperbolic component (frequency 2 is "
                                     f"{'n - 1, a tangent-plane frequency' if n == 3 else 'its own conjugate n - 2'}); use n >= 5")
        c = mpmath.mpf(float(hyperbolic)) * mpmath.expj(-2 * mpmath.mpf(float(angle)))
    h = {}
    for q in range(K):
        saddle = [mpmath.re(c * hyper[0][q] * mpmath.expjpi(mpmath.mpf(4 * s) / n)) for s in range(n)] if c is not None else [0] * n
        for s, value in enumerate(_rational_saddle(saddle, n)):
            h[(q, s)] = Fraction(float(e * Xe[1 + q])) + value
    h_O = Fraction(float(e * Xe[0]))
    w = position_weights(scheme, n)
    means = [sum((h[(q, s)] for s in range(n)), Fraction(0)) / n for q in range(K)]
    # the heights the position mask sees, sum over O and the classes of weight * mean height: made zero by moving one
    # vertex group (O, or every vertex of one class by a constant); the first whose move is a terminating decimal
    parts = [w[0] * _q(h_O)] + [n * w[1 + q] * _q(means[q]) for q in range(K)]
    total = sum(parts, sp.Integer(0))
    moves = []
    for g in [K] + list(range(K)):  # group 0 is O, group 1 + q the class q
        move = -total / (w[0] if g == 0 else n * w[g])
        if move.is_Rational and _terminates(move):
            moves.append((g, Fraction(int(move.p), int(move.q))))
            break
    if not moves:  # irrational weights (Loop at most valences): the last class, rounded to a double
        moves.append((K, Fraction(float(sp.N(-total / (n * w[K]), _DPS)))))
    g, move = moves[0]
    if g == 0:
        h_O += move
    for s in range(n if g else 0):
        h[(g - 1, s)] += move
    return h_O, h


def _rational_saddle(values, n: int) -> list[Fraction]:
    """Heights of n-gon frequency 2 and n - 2 (``values``) as terminating decimals, without frequency 1 where possible.

    For even ``n`` the frequencies ``j`` with ``gcd(j, n) = 2`` (the Galois orbit of 2, which misses 1) span a rational
    space with integer columns ``b_t(s) = c_(n/2)(s - t)`` (Ramanujan sums): ``values = sum_t values_t/n b_t``, and
    rounding the coefficients keeps the result in that space, so the tangent masks see none of it. For odd ``n`` the
    orbit of 2 contains 1 (a rational sequence without frequency 1 has no frequency 2): the values are rounded, and
    the first moved so that they sum to exactly 0 (as the columns ``b_t`` do).
    """
    if n % 2:
        rounded = [Fraction(float(x)) for x in values]
        rounded[0] -= sum(rounded, Fraction(0))  # no frequency 0, exactly: the position mask needs no move for it
        return rounded
    columns = [_ramanujan_sum(n // 2, k) for k in range(n)]
    coefficients = [Fraction(float(x / n)) for x in values]
    return [sum((coefficients[t] * columns[(s - t) % n] for t in range(n)), Fraction(0)) for s in range(n)]


def _ramanujan_sum(m: int, k: int) -> int:
    """``c_m(k)``, the sum of the ``k``-th powers of the primitive ``m``-th roots of unity: ``sum_(d | gcd(m, k)) mu(m/d) d``."""
    def mobius(x: int) -> int:
        powers = sp.factorint(x).values()
        return 0 if any(p > 1 for p in powers) else (-1) ** len(powers)

    g = math.gcd(m, k)
    return sum(mobius(m // d) * d for d in sp.divisors(g))


def _terminates(x: sp.Rational) -> bool:
    d = int(x.q)
    for p in (2, 5):
        while d % p == 0:
            d //= p
    return d == 1


def _q(x: Fraction) -> sp.Rational:
    return sp.Rational(x.numerator, x.denominator)


def _fraction(x) -> Fraction:
    return Fraction(int(x.p), int(x.q))


def design_ring(scheme: Scheme, n: int, *, normal, position=(0, 0, 0), tangent=None, elliptic=0, hyperbolic=0, angle=0) -> RingDesign:
    """A control net (the 2-ring of a vertex of valence ``n``) whose limit at the centre has the prescribed properties.

    ``position``, ``normal``, ``tangent``: 3 rationals each (ints, Fractions, text such as ``"1/3"``); ``elliptic``,
    ``hyperbolic`` (amounts along the unit normal) and ``angle`` (radians): real numbers, exact or text.
    See the module docstring for the construction and what is exact.
    """
    scheme = check_scheme(scheme)
    n = scheme.fitting_valence(n)
    if n > MAX_VALENCE:
        raise InvalidInputError(f"valence n must be at most {MAX_VALENCE} for a design, got {n}")
    with mpmath.workdps(_DPS):
        return _design(scheme, n, normal, position, tangent, (elliptic, hyperbolic, angle))


def _design(scheme: Scheme, n: int, normal, position, tangent, amounts) -> RingDesign:
    u, v, N = frame(normal, tangent)
    p = vector(position, "position")
    amounts = [amount(x, name) for x, name in zip(amounts, ("elliptic", "hyperbolic", "angle"))]
    _, _, X1 = _dominant(_frequency_matrix(scheme, n, 1))
    X1 = [x / X1[0] for x in X1]
    su, sv = (1 / mpmath.sqrt(mpmath.mpf(sp.N(dot(w, w), _DPS))) for w in (u, v))
    plane = _symmetric_plane(scheme, n, X1, su, sv)
    scaled = [a / sp.sqrt(dot(N, N)) for a in amounts[:2]] + [amounts[2]]  # heights along N/|N| -> multiples of N
    h_O, h = _heights(scheme, n, *[sp.N(x, _DPS) for x in scaled])
    frac = [tuple(_fraction(x) for x in w) for w in (p, u, v, N)]

    def point(x, y, z):
        return tuple(frac[0][k] + x * frac[1][k] + y * frac[2][k] + z * frac[3][k] for k in range(3))

    ring = {(q, s): point(x, y, h[(q, s)]) for (q, s), (x, y) in plane.items()}
    e, b, t = (mpmath.mpmathify(sp.N(x, _DPS)) for x in scaled)

    def outer(s, a, c):  # the regular sector chart, and the quadric it continues
        z = a * mpmath.expjpi(mpmath.mpf(2 * s) / n) + c * mpmath.expjpi(mpmath.mpf(2 * (s + 1)) / n)
        height = e * abs(z) ** 2 + mpmath.re(b * mpmath.expj(-2 * t) * z**2)
        return point(*(Fraction(float(x)) for x in (mpmath.re(z) * su, mpmath.im(z) * sv, height)))

    mesh = _ring_net(scheme, n, point(0, 0, h_O), ring, outer)
    return RingDesign(scheme.name, n, mesh, 0, _ids(mesh, scheme), limit_frame(scheme, mesh, 0, normal=N, tangent=u))


def _ids(mesh: PolygonMesh, scheme: Scheme) -> tuple[int, ...]:
    ring = mesh.one_ring(0, scheme.lattice)
    return (ring[0],) + tuple(x for part in ring[1:] for x in part)


def _ring_net(scheme: Scheme, n: int, centre, ring: dict, outer) -> PolygonMesh:
    """The 2-ring mesh of the lattice with the designed 1-ring and the outer vertices from ``outer(s, u, v)``."""
    classes = _classes(scheme)

    def value(s, a, c):
        if (a, c) == (0, 0):
            return centre
        if (a, c) in classes:
            return ring[(classes.index((a, c)), s % n)]
        if a == 0:  # (s, 0, c) is (s + 1, c, 0)
            return value(s + 1, c, 0)
        return outer(s, a, c)

    local = scheme.lattice.ring_mesh(n, 2, lambda s, a, c: tuple(sp.Rational(x.numerator, x.denominator) for x in value(s, a, c)))
    points = [tuple(_fraction(x) for x in local.values[i]) for i in range(len(local.values))]
    return PolygonMesh.from_arrays(points, [tuple(f) for f in local.faces], name="design")


def _class_sums(K: CyclotomicField, points: dict, n: int, direction) -> list:
    """Per class: ``sum_s omega^(-s) (P_(q,s) . direction)``, exact in ``K = Q(zeta_4n)``."""
    d = [Fraction(int(x.p), int(x.q)) if isinstance(x, sp.Rational) else Fraction(x) for x in direction]
    out = []
    for q in sorted({q for q, _ in points}):
        total = K(0)
        for s in range(n):
            height = sum((c * w for c, w in zip(points[(q, s)], d)), Fraction(0))
            if height:
                total = total + K(height) * K.zeta(-4 * s)
        out.append(total)
    return out


def _amounts(scheme: Scheme, n: int, centre, points: dict, unit) -> tuple:
    """``(elliptic, hyperbolic, angle)`` of the heights ``P . unit`` (40 digits)."""
    with mpmath.workdps(_DPS):
        def height(x):
            return mpmath.fsum(mpmath.mpf(float(c)) * w for c, w in zip(x, unit))

        Xe, Ye = _elliptic(scheme, n)
        K = len(_classes(scheme))
        top = Ye[0] * height(centre) + mpmath.fsum(Ye[1 + q] / n * height(points[(q, s)]) for q in range(K) for s in range(n))
        elliptic = top / mpmath.fsum(y * x for y, x in zip(Ye, Xe))
        hyper = _hyperbolic(scheme, n)
        if hyper is None:
            return float(elliptic), None, None
        X2, Y2 = hyper
        L = mpmath.fsum(Y2[q] * mpmath.expjpi(mpmath.mpf(-4 * s) / n) * height(points[(q, s)]) for q in range(K) for s in range(n))
        A = 2 * L / (n * mpmath.fsum(y * x for y, x in zip(Y2, X2)))
        angle = float((-mpmath.arg(A) / 2) % mpmath.pi) if abs(A) > mpmath.mpf(10) ** -30 else 0.0
        return float(elliptic), float(abs(A)), angle


def ring_amounts(scheme: Scheme, points, unit) -> tuple:
    """``(elliptic, hyperbolic, angle)`` of a 1-ring given as points ``O, a_0.., b_0..`` (doubles suffice), along ``unit``.

    The coefficients of the heights ``P . unit`` on the elliptic eigenvector (frequency 0) and on the dominant
    frequency-2 eigenvectors (``Re(B e^(-2iT) X_q omega^(2s))``); the hyperbolic pair is ``None`` at ``n <= 4``.
    """
    scheme = check_scheme(scheme)
    K = len(_classes(scheme))
    if (len(points) - 1) % K or len(points) < 1 + 3 * K:
        raise InvalidInputError(f"points must be a 1-ring O, then {K} classes of n >= 3 points each; got {len(points)} points")
    n = (len(points) - 1) // K
    return _amounts(scheme, n, points[0], {(q, s): points[1 + q * n + s] for q in range(K) for s in range(n)}, unit)


def limit_frame(scheme: Scheme, mesh: PolygonMesh, vertex: int, *, normal=None, tangent=None) -> LimitFrame:
    """The limit properties at ``vertex`` of ``mesh``, checked against the target ``normal`` (and ``tangent``) exactly.

    Position exact, tangents and normal as doubles (:func:`~symdecomp.analysis.inspection.inspect_vertex`); whether
    ``t_1, t_2`` are exactly perpendicular to ``normal`` and ``t_1`` exactly along the projected ``tangent`` (the class
    sums of the frequency-1 Fourier transform, exact in ``Q(zeta_4n)``); the amounts along the target normal (or the
    measured one).
    """
    from symdecomp.analysis.inspection import inspect_vertex

    scheme = check_scheme(scheme)
    r = inspect_vertex(mesh, vertex, scheme)
    n = r.valence
    ring = r.ring
    classes = _classes(scheme)
    points = {(q, s): mesh.points[ring[1 + q * n + s]] for q in range(len(classes)) for s in range(n)}
    normal_exact = tangent_exact = None
    if normal is not None:
        u, v, N = frame(normal, tangent)
        K = CyclotomicField(4 * n)
        normal_exact = all(x == 0 for x in _class_sums(K, points, n, N))
        if tangent is not None:
            phases = [K.zeta(-2 * offset) for _, offset in classes]
            across_u = _class_sums(K, points, n, v)
            across_v = _class_sums(K, points, n, u)
            tangent_exact = all((p * a).real() == 0 for p, a in zip(phases, across_u)) and all(
                (p * a).imag() == 0 for p, a in zip(phases, across_v))
        unit = [float(x) / math.sqrt(float(dot(N, N))) for x in N]
    else:
        unit = list(r.normal) if r.normal is not None else [0.0, 0.0, 1.0]
    amounts = _amounts(scheme, n, mesh.points[ring[0]], points, unit)
    return LimitFrame(tuple(r.limit_exact), tuple(r.tangents), tuple(r.normal) if r.normal else None, normal_exact,
                      tangent_exact, *amounts)

