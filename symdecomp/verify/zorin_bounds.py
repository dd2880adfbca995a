"""How far a limit's derivatives can be from its control net's differences: the regular rules' difference bounds.

The regular part of a scheme on triangles is read from the scheme itself (:func:`regular_mask`): the steps that return
the lattice to itself (one primal step; sqrt(3)'s two, :attr:`~symdecomp.schemes.stencils.StencilScheme.steps`) on a
regular patch of the engine (:func:`~symdecomp.schemes.topology.refine_step` at valence 6, every point regular),
each new point placed where its rule puts a linear function (a vertex point on its vertex, an edge point at its
edge's midpoint, a face point at the centroid) in the lattice coordinates ``x e_1 + y w`` (``w`` the unit at 60
degrees). The new points are the lattice refined by ``1/a`` (``a = 2`` for a primal step, ``3`` for sqrt(3)'s two:
triadic refinement; computed, and checked point by point), so that ``(S p)(y) = sum_x A[y - a x] p(x)``. The bounds
below are computed from ``A`` and ``a``, never typed in; written below for ``a = 2``, they hold with ``a`` for 2.

**Second differences.** A *rhombus* is two triangles sharing an edge; its difference is the sum of ``p`` at the
two tips minus the sum at the shared edge's ends (three types by direction, :data:`RHOMBI`). They vanish exactly on
linear functions, and every finitely supported functional that vanishes on linear functions is a combination of them
(:func:`decompose`: exact division by ``(1 - z_1)^2``, ``(1 - z_1)(1 - z_2)``, ``(1 - z_2)^2``, then
``(1 - z_1)^2 = R_1 + z_1 R_2``; SciPy's linear program finds a combination of smaller l1 norm,
rounded to rationals, its exact residual decomposed again). The l1 norm of any such combination bounds the functional
by the largest rhombus difference ``M`` in its support.

**Contraction.** ``nu_r`` bounds a rhombus difference ``r`` steps finer by the coarse ones (the worst of the
functionals ``p -> delta(S^r p)(y)`` over the ``4^r`` positions ``y`` and the three types). When ``2^L nu_L < 1`` the
scheme's derivatives converge (it is C1 on the regular lattice), and with ``M_k`` the largest rhombus difference
of level ``k`` near a triangle,

    sum over k >= m of 2^k M_k  <=  2^m M_m (sum over r < L of 2^r nu_r) / (1 - 2^L nu_L).

**Derivatives.** For a triangle ``T`` of level ``k``, one of its four children ``T'`` and an edge direction ``e``,
``2 D_e p^(k+1)(T') - D_e p^k(T)`` (the edges of ``T'`` and ``T`` in the direction ``e``) vanishes on linear
functions; ``K_1`` bounds it by the rhombi. Summed over the levels, for ``x`` in a level-``m`` triangle ``T``:
``|d_e f(x) - 2^m D_e p^m(T)| <= K_1 sum_(k >= m) 2^k M_k`` (parameters of level 0, edges of length ``2^-k``).
**Positions**: ``(S p)(2 i) - p(i)`` gives ``K_0`` the same way (``0`` for an interpolatory scheme), and
``|f(v) - p^m(v)| <= K_0 M_m (sum over r < L of nu_r) / (1 - nu_L)``.

These are the bounds of the limit against its control net under refinement that D. Zorin, *A method for analysis of
C1-continuity of subdivision surfaces*, SIAM J. Numer. Anal. 37(5) (2000), 1677-1708, rests on (its abstract:
regularity inferred from a sufficiently close linear approximation, injectivity from the index of a curve);
the constants here are derived by the linear programs above, not taken from the paper.

>>> sorted(RHOMBI[0].items())
[((0, 0), 1), ((0, 1), -1), ((1, 0), -1), ((1, 1), 1)]
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from itertools import product

import sympy as sp

from symdecomp.analysis.zoo_matrix import compose_rows
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.halfedge import HalfedgeMesh
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.neighbourhood import neighbourhood
from symdecomp.schemes.stencil_rows import Row
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.schemes.topology import refine_step

__all__ = ["RHOMBI", "EDGES", "DifferenceBounds", "Point", "hex_norm", "turn", "unfold", "regular_mask", "regular_reach", "decompose",
           "difference_bounds"]

Point = tuple[int, int]
Functional = dict[Point, Fraction]

#: The three rhombus differences (tips +1, the shared edge's ends -1), in the coordinates ``x e_1 + y w``.
RHOMBI: tuple[dict[Point, int], ...] = (
    {(0, 0): 1, (1, 1): 1, (1, 0): -1, (0, 1): -1},
    {(1, 0): 1, (-1, 1): 1, (0, 0): -1, (0, 1): -1},
    {(0, 1): 1, (1, -1): 1, (0, 0): -1, (1, 0): -1},
)
#: The edge directions of a triangle: ``e_1``, ``w`` and ``w - e_1``.
EDGES: tuple[Point, ...] = ((1, 0), (0, 1), (-1, 1))
#: A triangle of level ``k`` at ``q``: its corners' offsets (``up``: ``q, q + e_1, q + w``; ``down``: the other one).
TRIANGLES: dict[str, tuple[Point, Point, Point]] = {"up": ((0, 0), (1, 0), (0, 1)), "down": ((1, 0), (1, 1), (0, 1))}
#: The most fine positions (``a^(2r)``, each three linear programs) a contraction step ``r > 1`` is computed over.
_POSITIONS = 64
#: The largest denominator of the linear program's rounded coefficients.
_DENOMINATOR = 1 << 20


def hex_norm(p: Point) -> int:
    """The lattice's graph distance from the origin: ``max(|x|, |y|, |x + y|)``."""
    return max(abs(p[0]), abs(p[1]), abs(p[0] + p[1]))


def _distance(p: Point, centre: tuple[Fraction, Fraction]) -> Fraction:
    """:func:`hex_norm` of ``p - centre`` for a centre between lattice points."""
    x, y = p[0] - centre[0], p[1] - centre[1]
    return max(abs(x), abs(y), abs(x + y))


def turn(p: Point) -> Point:
    """The rotation by one sixth of a turn (``e_1 -> w``, ``w -> w - e_1``)."""
    return (-p[1], p[0] + p[1])


def _add(a: Point, b: Point) -> Point:
    return (a[0] + b[0], a[1] + b[1])


def unfold(mesh: HalfedgeMesh, start: int) -> dict[int, Point]:
    """Lattice coordinates of a patch of triangles with every interior vertex regular: ``start`` runs from ``(0, 0)`` to
    ``(1, 0)``, and each triangle ``(a, b, c)`` counter-clockwise has ``c = a + turn(b - a)``."""
    pos = {mesh.origin[start]: (0, 0), mesh.tip(start): (1, 0)}
    changed = True
    while changed:
        changed = False
        for face in mesh.faces:
            if len(face) != 3:
                raise InvalidSchemeError(f"the difference bounds are for triangles; a face has {len(face)} sides")
            for k in range(3):
                a, b, c = face[k], face[(k + 1) % 3], face[(k + 2) % 3]
                if a in pos and b in pos and c not in pos:
                    d = turn((pos[b][0] - pos[a][0], pos[b][1] - pos[a][1]))
                    pos[c], changed = _add(pos[a], d), True
    return pos


def _weight(w: object) -> Fraction:
    value = sp.sympify(w, strict=True)
    if not value.is_Rational:
        raise InvalidSchemeError(f"a regular weight is not rational ({w}): the difference bounds are exact rational")
    return Fraction(int(value.p), int(value.q))


def _placed(rows: Mapping[int, Mapping[int, object]], pos: Mapping[int, tuple[Fraction, Fraction]]
            ) -> dict[int, tuple[Fraction, Fraction]]:
    """Each new point where its rule puts a linear function: the row's weights applied to the old points' places."""
    out = {}
    for i, row in rows.items():
        if all(v in pos for v in row):
            ws = [(_weight(w), pos[v]) for v, w in row.items()]
            out[i] = (sum((w * p[0] for w, p in ws), Fraction(0)), sum((w * p[1] for w, p in ws), Fraction(0)))
    return out


def _dilation(places: Mapping[int, tuple[Fraction, Fraction]], near: int) -> int:
    """``a``: the new points near the centre are exactly the lattice scaled by ``1/a`` (else the reason why not)."""
    a = 1
    for p in places.values():
        a = math.lcm(a, p[0].denominator, p[1].denominator)
    fine = {(int(p[0] * a), int(p[1] * a)) for p in places.values()}
    wanted = {(x, y) for x in range(-near, near + 1) for y in range(-near, near + 1) if hex_norm((x, y)) <= near}
    if a < 2 or not wanted <= fine:
        missing = sorted(wanted - fine)[:1]
        raise InvalidSchemeError(f"the new points are not the triangle lattice refined by an integer factor (factor {a}"
                                 f"{', no point at ' + str(missing[0]) + '/' + str(a) if missing else ''})")
    return a


@lru_cache(maxsize=16)
def _regular_rows(scheme: StencilScheme) -> tuple[int, dict[int, tuple[Fraction, Fraction]], dict[int, tuple[Fraction, Fraction]],
                                                  dict[int, Row]]:
    """``(a, pos0, pos, rows)``: the scheme's steps composed on a regular neighbourhood, the old points' and the new
    points' places, and the new points' rows on the old ones (entries that cancel to 0 kept: a row's keys are every
    old point some path of the steps reads)."""
    lat = lattice(scheme.lattice)
    nb = neighbourhood(lat, lat.regular_valence, 3 + scheme.steps)
    pos0 = {v: (Fraction(p[0]), Fraction(p[1])) for v, p in unfold(nb.mesh, nb.start).items()}
    mesh, pos, rows = nb.mesh, pos0, None
    for _ in range(scheme.steps):  # the steps that return the lattice to itself
        step = refine_step(scheme, mesh, regular=lat.regular_valence)
        pos, rows, mesh = _placed(step.rows, pos), compose_rows(step.rows, rows), step.mesh
    assert rows is not None  # a scheme has at least one step
    a = _dilation({i: p for i, p in pos.items() if _distance_q(p) <= 1}, 2)
    return a, pos0, pos, rows


def _near_rows(scheme: StencilScheme) -> Iterator[tuple[int, Point, Row, dict[int, tuple[Fraction, Fraction]]]]:
    """``(a, y, row, pos0)`` for each new point ``y`` within one coarse cell of the centre (every kind of new point, its
    rule clear of the neighbourhood's edge)."""
    a, pos0, pos, rows = _regular_rows(scheme)
    for i, p in pos.items():
        y = (int(p[0] * a), int(p[1] * a))
        if hex_norm(y) <= a:
            yield a, y, rows[i], pos0


def regular_mask(scheme: StencilScheme) -> tuple[int, dict[Point, Fraction]]:
    """``(a, A)`` with ``(S p)(y) = sum_x A[y - a x] p(x)``, ``S`` the scheme's steps (module docstring)."""
    a = _regular_rows(scheme)[0]
    mask: dict[Point, Fraction] = {}
    for _, y, row, pos0 in _near_rows(scheme):
        for v, w in row.items():
            u = (y[0] - a * int(pos0[v][0]), y[1] - a * int(pos0[v][1]))
            value = _weight(w)
            if value and mask.setdefault(u, value) != value:
                raise InvalidSchemeError(f"scheme {scheme.name!r}: its regular rules are not the same at every point")
    return a, mask


def regular_reach(scheme: StencilScheme) -> int:
    """The largest ``|y - a x|`` over every old point ``x`` a new point ``y`` reads through some path of the steps, its
    composed weight 0 or not: a new point farther than this from the centre reads no rule of the centre, even where
    a two-step scheme's weights cancel (the nonzero mask alone would not show that)."""
    return max(hex_norm((y[0] - a * int(pos0[v][0]), y[1] - a * int(pos0[v][1])))
               for a, y, row, pos0 in _near_rows(scheme) for v in row)


def _distance_q(p: tuple[Fraction, Fraction]) -> Fraction:
    return max(abs(p[0]), abs(p[1]), abs(p[0] + p[1]))


def _divide(c: Functional, var: int) -> tuple[Functional, Functional]:
    """``c = (z_var - 1) q + r`` with ``r`` free of ``z_var`` (exponents >= 0)."""
    q: Functional = {}
    r: Functional = {}
    columns: dict[int, dict[int, Fraction]] = defaultdict(dict)
    for key, value in c.items():
        columns[key[1 - var]][key[var]] = value
    for other, column in columns.items():
        carry = Fraction(0)
        for k in range(max(column), 0, -1):
            carry += column.get(k, Fraction(0))
            if carry:
                q[(k - 1, other) if var == 0 else (other, k - 1)] = carry
        rest = column.get(0, Fraction(0)) + carry
        if rest:
            r[(0, other) if var == 0 else (other, 0)] = rest
    return q, r


def _shift(c: Mapping[Point, Fraction], t: Point) -> Functional:
    return {_add(k, t): v for k, v in c.items()}


def _combine(*parts: Mapping[Point, Fraction]) -> Functional:
    out: Functional = defaultdict(Fraction)
    for part in parts:
        for k, v in part.items():
            out[k] += v
    return {k: v for k, v in out.items() if v}


def _division(c: Functional) -> list[Functional]:
    """Rhombus coefficients ``g_r`` with ``c = sum_r sum_t g_r[t] R_r(. - t)``, by exact division (module docstring)."""
    low = (min(k[0] for k in c), min(k[1] for k in c))
    c = _shift(c, (-low[0], -low[1]))
    q, r = _divide(c, 0)
    q2, r1 = _divide(q, 0)
    s, rest1 = _divide(r1, 1)
    t1, rest2 = _divide(r, 1)
    t, rest3 = _divide(t1, 1)
    if rest1 or rest2 or rest3:
        raise InvalidSchemeError("a functional that should vanish on linear functions does not: the regular rules do "
                                 "not reproduce linear functions")
    parts = [_combine(q2, s, t), _shift(q2, (1, 0)), _shift(t, (0, 1))]
    return [_shift(g, low) for g in parts]


def _expand(g: list[Functional]) -> Functional:
    return _combine(*(_shift({k: Fraction(v) * x for k, v in RHOMBI[r].items()}, t) for r, gr in enumerate(g)
                      for t, x in gr.items()))


def _linear_program(c: Functional) -> list[Functional] | None:
    """A combination of small l1 norm by SciPy's linear program (rounded to rationals; ``None`` if it finds none)."""
    import numpy as np
    from scipy.optimize import linprog  # type: ignore[import-untyped]  # SciPy ships no annotations; loaded when used
    xs, ys = [k[0] for k in c], [k[1] for k in c]
    cand = [(t, r) for t in product(range(min(xs) - 2, max(xs) + 2), range(min(ys) - 2, max(ys) + 2)) for r in range(3)]
    keys = sorted({_add(k, t) for t, r in cand for k in RHOMBI[r]} | set(c))
    row = {k: i for i, k in enumerate(keys)}
    m = len(cand)
    a_eq, b_eq = np.zeros((len(keys), 2 * m)), np.zeros(len(keys))
    for j, (t, r) in enumerate(cand):
        for k, v in RHOMBI[r].items():
            a_eq[row[_add(k, t)], j], a_eq[row[_add(k, t)], m + j] = float(v), float(-v)
    for key, value in c.items():
        b_eq[row[key]] = float(value)
    res = linprog(np.ones(2 * m), A_eq=a_eq, b_eq=b_eq, bounds=(0, None), method="highs")
    if res.status != 0:  # pragma: no cover - the division's combination is feasible, so the program is
        return None
    g: list[Functional] = [{}, {}, {}]
    for j, (t, r) in enumerate(cand):
        x = Fraction(float(res.x[j] - res.x[m + j])).limit_denominator(_DENOMINATOR)
        if x:
            g[r][t] = x
    return g


def decompose(c: Mapping[Point, Fraction]) -> list[Functional]:
    """Rhombus coefficients of a functional vanishing on linear functions, exact, of small l1 norm (module docstring)."""
    c = {k: Fraction(v) for k, v in c.items() if v}
    if not c:
        return [{}, {}, {}]
    best = _division(c)
    program = _linear_program(c)
    if program is not None:
        residual = _combine(c, {k: -v for k, v in _expand(program).items()})
        fixed = [_combine(a, b) for a, b in zip(program, _division(residual) if residual else [{}, {}, {}])]
        if _norm(fixed) < _norm(best):
            best = fixed
    assert _expand(best) == c
    return best


def _norm(g: list[Functional]) -> Fraction:
    return sum((abs(v) for gr in g for v in gr.values()), Fraction(0))


def _reach(g: list[Functional], centre: tuple[Fraction, Fraction]) -> Fraction:
    """The farthest rhombus corner from ``centre`` (graph distance)."""
    pts = [_add(k, t) for r, gr in enumerate(g) for t in gr for k in RHOMBI[r]]
    return max((_distance(p, centre) for p in pts), default=Fraction(0))


@dataclass(frozen=True)
class DifferenceBounds:
    """The regular rules' bounds (module docstring), exact rationals."""

    #: ``a``: the scheme's steps refine the lattice by ``1/a`` (2 for one primal step, 3 for sqrt(3)'s two).
    dilation: int
    #: ``A``: ``(S p)(y) = sum_x A[y - a x] p(x)``.
    mask: dict[Point, Fraction]
    #: ``L``: the number of steps of the contraction.
    steps: int
    #: ``nu_r`` for ``r = 0..L``.
    contraction: tuple[Fraction, ...]
    #: ``K_1``: the derivative functionals' bound.
    derivative: Fraction
    #: ``K_0``: the position functionals' bound (0 for an interpolatory scheme).
    position: Fraction
    #: How far (in coarse edges) the combinations reach: a margin that keeps every level's rhombi in one region.
    margin: int
    #: The largest ``|y - 2x|`` in the mask: a new point needs the old ones that close.
    reach: int

    @property
    def clear_radius(self) -> int:
        """The smallest radius (fine graph distance) where a new point's rule is the regular one: its stencil reaches no
        coarse point nearer the centre than one coarse edge (``reach + a``)."""
        return self.reach + self.dilation

    @property
    def closes(self) -> bool:
        """``a^L nu_L < 1``: the derivatives converge (C1 on the regular lattice)."""
        return bool(self.dilation ** self.steps * self.contraction[-1] < 1)

    def derivative_factor(self) -> Fraction:
        """``sum_(r < L) a^r nu_r / (1 - a^L nu_L)``: ``sum_(k >= m) a^k M_k <= a^m M_m`` times this."""
        a = self.dilation
        top = Fraction(a ** self.steps) * self.contraction[-1]
        return sum((Fraction(a ** r) * self.contraction[r] for r in range(self.steps)), Fraction(0)) / (1 - top)

    def position_factor(self) -> Fraction:
        """``sum_(r < L) nu_r / (1 - nu_L)``: ``sum_(k >= m) M_k <= M_m`` times this."""
        return sum(self.contraction[: self.steps], Fraction(0)) / (1 - self.contraction[-1])


def _power(mask: Mapping[Point, Fraction], previous: Mapping[Point, Fraction], a: int) -> dict[Point, Fraction]:
    """The mask of ``S^(r+1)`` from that of ``S^r``: ``A_(r+1)[u] = sum_v A[u - a v] A_r[v]``."""
    out: dict[Point, Fraction] = defaultdict(Fraction)
    for u, x in mask.items():
        for v, w in previous.items():
            out[(u[0] + a * v[0], u[1] + a * v[1])] += x * w
    return {k: v for k, v in out.items() if v}


def _refined(power: Mapping[Point, Fraction], size: int, terms: Mapping[Point, Fraction]) -> Functional:
    """The functional ``p -> sum_y terms[y] (S^r p)(y)`` on the coarse points (``size = a^r``)."""
    c: Functional = defaultdict(Fraction)
    for y, s in terms.items():
        for u, a in power.items():
            d = (y[0] - u[0], y[1] - u[1])
            if d[0] % size == 0 and d[1] % size == 0:
                c[(d[0] // size, d[1] // size)] += s * a
    return {k: v for k, v in c.items() if v}


def _contraction(power: Mapping[Point, Fraction], size: int) -> tuple[Fraction, Fraction]:
    """``(nu_r, reach)`` over the ``size^2`` positions and three types of a fine rhombus."""
    worst, reach = Fraction(0), Fraction(0)
    for y0, y1 in product(range(size), repeat=2):
        y = (y0, y1)
        for rh in RHOMBI:
            g = decompose(_refined(power, size, {_add(y, k): Fraction(v) for k, v in rh.items()}))
            worst = max(worst, _norm(g))
            reach = max(reach, _reach(g, (Fraction(y[0], size), Fraction(y[1], size))) + 1)
    return worst, reach


def _children(corners: tuple[Point, ...], a: int) -> list[tuple[Point, ...]]:
    """The ``a^2`` triangles one level finer inside a triangle (its corners scaled by ``a``)."""
    big = [(a * c[0], a * c[1]) for c in corners]

    def inside(p: Point) -> bool:
        return all((q[0] - o[0]) * (p[1] - o[1]) - (q[1] - o[1]) * (p[0] - o[0]) >= 0
                   for o, q in zip(big, big[1:] + big[:1]))

    low = (min(c[0] for c in big), min(c[1] for c in big))
    out = []
    for x, y in product(range(low[0] - 1, low[0] + a + 1), range(low[1] - 1, low[1] + a + 1)):
        for shape in TRIANGLES.values():
            pts = tuple((x + c[0], y + c[1]) for c in shape)
            if all(inside(p) for p in pts):
                out.append(pts)
    assert len(out) == a * a  # a triangle refined by 1/a is a^2 triangles
    return out


def _derivative_bound(mask: Mapping[Point, Fraction], a: int) -> tuple[Fraction, Fraction]:
    """``(K_1, reach)``: the worst ``a D_e p^(k+1)(T') - D_e p^k(T)`` over triangles, children and directions."""
    worst, reach = Fraction(0), Fraction(0)
    for corners in TRIANGLES.values():
        for e in EDGES:
            parent = _edge(corners, e)
            for child in _children(corners, a):
                fine = _edge(child, e)
                terms = {fine[1]: Fraction(a), fine[0]: Fraction(-a)}
                c = _combine(_refined(mask, a, terms), {parent[1]: Fraction(-1), parent[0]: Fraction(1)})
                g = decompose(c)
                worst, reach = max(worst, _norm(g)), max(reach, _reach(g, (Fraction(0), Fraction(0))) + 1)
    return worst, reach


def _edge(corners: tuple[Point, ...], e: Point) -> tuple[Point, Point]:
    """The edge of a triangle in the direction ``e``, as ``(tail, head)`` with ``head - tail`` a positive multiple of ``e``."""
    for a in corners:
        for b in corners:
            d = (b[0] - a[0], b[1] - a[1])
            if d != (0, 0) and d[0] * e[1] == d[1] * e[0] and d[0] * e[0] + d[1] * e[1] > 0:
                return a, b
    raise AssertionError("a lattice triangle has an edge in each direction")  # pragma: no cover


@lru_cache(maxsize=16)
def _bounds(key: str, scheme: StencilScheme, max_steps: int) -> DifferenceBounds:
    a, mask = regular_mask(scheme)
    power: dict[Point, Fraction] = {(0, 0): Fraction(1)}
    contraction, margin = [Fraction(1)], Fraction(0)
    k1, k1_reach = _derivative_bound(mask, a)
    k0 = _norm(decompose(_combine(_refined(mask, a, {(0, 0): Fraction(1)}), {(0, 0): Fraction(-1)})))
    reach = max(max(hex_norm(u) for u in mask), regular_reach(scheme))
    best = None
    for r in range(1, max_steps + 1):
        if r > 1 and a ** (2 * r) > _POSITIONS:
            break  # the next step's fine positions would cost more than the factor it saves
        power = _power(mask, power, a)
        nu, fine_reach = _contraction(power, a ** r)
        contraction.append(nu)
        margin = max(margin, fine_reach / (1 - Fraction(1, a ** r)), k1_reach)
        found = DifferenceBounds(a, mask, r, tuple(contraction), k1, k0, int(-(-margin // 1)), reach)
        if found.closes and (best is None or found.derivative_factor() < best.derivative_factor()):
            best = found  # more steps: a smaller factor, a wider margin
    return best if best is not None else found


def difference_bounds(scheme: StencilScheme, max_steps: int = 3) -> DifferenceBounds:
    """The scheme's regular difference bounds (module docstring): of ``L = 1..max_steps`` (those over at most 64 fine
    positions), the one whose derivative factor is smallest among those that close."""
    return _bounds(repr(scheme), scheme, max_steps)
