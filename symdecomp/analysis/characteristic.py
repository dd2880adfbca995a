"""The 2-ring subdivision matrix by frequency, its eigen-data in Arb, and the characteristic map's control nets.

Reif's test (Reif 1995; Peters and Reif, *Subdivision Surfaces*, Springer 2008, Chapters 4-5)
looks at the *characteristic map*: the spline ring that the two real subdominant eigenvectors
generate. It applies where the regular part of the scheme is a known spline: the rules of a
:class:`~symdecomp.schemes.scheme.Scheme` act on the 1-ring of the extraordinary vertex ``O``
and every other point is refined by the regular rules, which must be Catmull-Clark's (quad
meshes: bicubic B-spline patches) or Loop's (triangle meshes: quartic box-spline patches);
:func:`check_applicable` says in one line why the test does not apply otherwise.

**Which control points, and why (quads).** Label the vertices of sector ``s`` by ``(s, u, v)`` as in
:func:`~symdecomp.schemes.mesh.ring_mesh` (``u`` steps along edge ray ``s``, ``v`` along ray
``s + 1``). After one refinement the *ring* of sector ``s`` is the L-shaped region
``[0, 2]^2 \\ [0, 1)^2`` of level-1 parameters, the union of the three level-1 faces with lower
corners ``(1, 0)``, ``(1, 1)``, ``(0, 1)``. None of them has ``O`` as a corner, so each is a
regular bicubic B-spline patch, evaluated from the ``4 x 4`` level-1 control points
``(a - 1 .. a + 2) x (b - 1 .. b + 2)`` around its face ``(a, b)``: these points lie in
``-1 <= u, v <= 3``, i.e. in the 3-ring of ``O`` at level 1 (points with ``u = -1`` or ``v = -1``
belong to the neighbouring sectors; ``O`` itself is a corner of the nets of the faces ``(1, 1)``
and of the row ``v = 0`` of ``(0, 1)``, always on the boundary of the net, so every net is a
regular grid). The level-1 3-ring is computed from the level-0 2-ring by one refinement (new
1-ring points by the scheme's rules, all others by the B-spline rules), which is why the
eigenvectors are those of the ``(6n + 1) x (6n + 1)`` 2-ring subdivision matrix. These are the
same three sub-patches Stam's exact evaluation uses at each level (Stam 1998; Peters and Reif
2008, Section 6.1, for the Catmull-Clark ring).

**Triangles (Loop).** Sector ``s`` is the wedge between edge rays ``s`` and ``s + 1``
(:func:`~symdecomp.schemes.mesh.triangle_ring_labels`); its ring at level 1 is the
triangle ``u, v >= 0, u + v <= 2`` minus the corner ``u + v < 1``: the three level-1 triangles
:data:`TRIANGLES` ``(1,0),(2,0),(1,1)``, ``(1,0),(1,1),(0,1)`` and ``(0,1),(1,1),(0,2)``. Their three
corners are regular (valence 6), so each is a regular quartic box-spline patch whose 12 control
points are the corners' 1-rings (:func:`triangle_patch_points`); those lie in the level-1
3-ring, which one refinement computes from the level-0 2-ring (``3n + 1`` points). These are the
sub-patches of Stam's evaluation of Loop surfaces (Stam 1998, *Evaluation of Loop subdivision
surfaces*).

**By frequency.** The ring matrix is block-circulant (the rules do not depend on the sector):
a vector with sector values ``omega^s c`` (``omega = e^{2 pi i j / n}``, ``c`` the values of
sector 0 on the 2-ring classes) maps to one with sector values ``omega^s B_j c``. ``B_j`` is
block lower triangular: its upper left block is the 1-ring matrix ``M_j`` (``2 x 2`` on
quads, ``1 x 1`` on triangles: the new 1-ring depends only on the old one), the lower right
block ``S_j`` belongs to the outer points, which the regular rules move. The regular rows are
the scheme-independent block form of :func:`~symdecomp.analysis.frequency.ring_blocks` (the
3-ring matrix of the reference scheme, whose level-1 ring-3 rows read only the level-0
2-ring); the 1-ring rows are the scheme's own rules at valence ``n``.

The eigen-data are Arb balls (python-flint), so every number here is a rigorous enclosure.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.frequency import ring_blocks
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, QUAD, Lattice, lattice
from symdecomp.schemes.scheme import Scheme, subdivision_matrix
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_valence

__all__ = [
    "RING2_LABELS",
    "LEVEL1_LABELS",
    "SUBPATCH_FACES",
    "TRIANGLES",
    "RingLayout",
    "ring_layout",
    "outer_charpoly",
    "outer_radius",
    "outer_norm_bound",
    "outer_bounds",
    "outer_row_sum",
    "check_applicable",
    "frequency_block",
    "frequency_blocks",
    "omega_ball",
    "FrequencyEigenvector",
    "frequency_eigenvector",
    "subpatch_nets",
    "inner_boundary_nets",
    "triangle_patch_points",
]

#: The six per-sector points of the quad 2-ring, in the order of ``c`` (canonical labels ``u >= 1``).
RING2_LABELS = ((1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (2, 2))
#: The twelve per-sector points of the quad 3-ring at level 1: the 2-ring first, then ring 3.
LEVEL1_LABELS = RING2_LABELS + ((1, 3), (2, 3), (3, 0), (3, 1), (3, 2), (3, 3))
#: Lower corners of the three level-1 faces of sector 0 that make up the quad characteristic ring.
SUBPATCH_FACES = ((1, 0), (1, 1), (0, 1))
#: The three level-1 triangles of sector 0 that make up Loop's characteristic ring, counter-clockwise.
TRIANGLES = (((1, 0), (2, 0), (1, 1)), ((1, 0), (1, 1), (0, 1)), ((0, 1), (1, 1), (0, 2)))


def triangle_patch_points(corners) -> tuple[tuple[int, int], ...]:
    """The 12 lattice points of a regular Loop patch: the union of its three corners' 1-rings, sorted."""
    steps = ((1, 0), (-1, 0), (0, 1), (0, -1), (1, -1), (-1, 1))
    points = {(u + du, v + dv) for u, v in corners for du, dv in steps} | set(corners)
    return tuple(sorted(points))


@dataclass(frozen=True)
class RingLayout:
    """The regular part of the ring on one lattice: its spline, classes and block rows."""

    lattice: Lattice
    #: The reference scheme whose regular rules the scheme must have, and their spline.
    reference: str
    spline: str
    #: Per-sector classes of the level-1 3-ring (2-ring classes first, 1-ring classes first of all).
    labels: tuple[tuple[int, int], ...]
    #: Number of 1-ring and 2-ring classes.
    one_ring: int
    two_ring: int
    #: ``offsets[p][q] = ((l, weight), ...)`` (``q`` below ``two_ring``): block ``C_pq`` of the level-1 3-ring rows.
    offsets: tuple


def ring_layout(mesh: Lattice | str) -> RingLayout:
    """The layout of a lattice's ring (quads: Catmull-Clark, triangles: Loop), read off :func:`ring_blocks`."""
    return _ring_layout(lattice(mesh))


@lru_cache(maxsize=4)
def _ring_layout(lat: Lattice) -> RingLayout:
    reference = lat.reference()
    blocks = ring_blocks(reference, 3)
    classes = blocks.classes
    one = sum(1 for u, v in classes if lat.ring_of(u, v) == 1)
    two = sum(1 for u, v in classes if lat.ring_of(u, v) <= 2)
    offsets = []
    for p in range(len(classes)):
        if any(blocks.offsets[p][q] for q in range(two, len(classes))):  # pragma: no cover - a property of the rules
            raise InvalidSchemeError(f"level-1 point {classes[p]} reads beyond the level-0 2-ring")
        offsets.append(tuple(tuple((l, to_fmpq(c)) for l, c in blocks.offsets[p][q]) for q in range(two)))
    return RingLayout(lat, _display_name(reference.name), lat.spline, classes, one, two, tuple(offsets))


def outer_charpoly(mesh: Lattice | str) -> tuple[flint.fmpq, ...] | None:
    """``det(x I - S(omega))`` of the outer block when it is the same at every frequency: its coefficients, else ``None``.

    ``S(omega)`` (the lower right block of :func:`frequency_block`) holds only the regular rules of
    :func:`ring_layout`, the same for every scheme the C1 test applies to, and ``S_j = S(omega_n^j)``
    for every ``n`` and ``j`` (its entries are Laurent polynomials in ``omega``). Its characteristic
    polynomial is expanded once in symbolic ``omega``; when no coefficient depends on ``omega`` (both
    lattices: Catmull-Clark ``(8x - 1)(16x - 1)(32x - 1)(64x - 1)/2^18``, Loop ``(8x - 1)(16x - 1)/2^7``),
    the outer eigenvalues are its roots at every frequency of every valence. Coefficients from
    ``x^k`` (monic) down to ``x^0``.
    """
    return _outer_charpoly(lattice(mesh))


@lru_cache(maxsize=4)
def _outer_charpoly(lat: Lattice) -> tuple[flint.fmpq, ...] | None:
    layout = ring_layout(lat)
    k1, k2 = layout.one_ring, layout.two_ring
    x = sp.Symbol("x")
    S = sp.Matrix(k2 - k1, k2 - k1, lambda r, c: sum(
        (sp.Rational(int(w.p), int(w.q)) * OMEGA**l for l, w in layout.offsets[k1 + r][k1 + c]), sp.Integer(0)))
    poly = sp.Poly(sp.expand((x * sp.eye(k2 - k1) - S).det()), x)
    coeffs = [sp.expand(c) for c in poly.all_coeffs()]
    if any(c.has(OMEGA) for c in coeffs):  # pragma: no cover - not so for Catmull-Clark's or Loop's rules
        return None
    return tuple(to_fmpq(c) for c in coeffs)


def outer_radius(mesh: Lattice | str) -> flint.arb | None:
    """The largest modulus of the outer block's eigenvalues, the same at every frequency of every valence, or ``None``.

    The roots of :func:`outer_charpoly` (certified complex roots of a rational polynomial, FLINT,
    at the working precision); ``None`` when that polynomial depends on ``omega`` (then each
    frequency needs its own bound).
    """
    coeffs = outer_charpoly(mesh)
    if coeffs is None:  # pragma: no cover - not so for the regular rules the C1 test knows
        return None
    roots = flint.fmpq_poly(list(reversed(coeffs))).complex_roots()
    return max((abs(r) for r, _ in roots), key=lambda x: x.upper())


def outer_norm_bound(S: flint.acb_mat) -> flint.arb:
    """``min_k ||S^k||_inf^{1/k}`` for ``k = 1, 2, 4``: an upper bound of the spectral radius of ``S``."""
    best, power = None, S
    for k in (1, 2, 4):
        if k > 1:
            power = power * power
        norm = max(sum((abs(power[r, c]) for c in range(power.ncols())), flint.arb(0)) for r in range(power.nrows()))
        bound = norm if k == 1 else norm.root(k)
        best = bound if best is None or bound.upper() < best.upper() else best
    return best


def outer_bounds(scheme: Scheme, n: int) -> list[tuple[int, flint.arb]]:
    """``(j, bound)`` for ``0 <= j <= n/2``: :func:`outer_norm_bound` of each outer block ``S_j`` (the per-frequency route)."""
    layout = ring_layout(scheme.lattice)
    k1, k2 = layout.one_ring, layout.two_ring
    blocks = frequency_blocks(scheme, n)
    out = []
    for j in range(n // 2 + 1):
        B = blocks(j)
        out.append((j, outer_norm_bound(flint.acb_mat([[B[r, c] for c in range(k1, k2)] for r in range(k1, k2)]))))
    return out


def outer_row_sum(mesh: Lattice | str) -> flint.fmpq:
    """The largest row sum of ``|weights|`` of the outer block: ``||S(omega)||_inf`` for every ``|omega| = 1`` is at most this,
    so every :func:`outer_norm_bound` is (up to rounding)."""
    return _outer_row_sum(lattice(mesh))


@lru_cache(maxsize=4)
def _outer_row_sum(lat: Lattice) -> flint.fmpq:
    layout = ring_layout(lat)
    k1, k2 = layout.one_ring, layout.two_ring
    return max(sum((abs(w) for q in range(k1, k2) for _, w in layout.offsets[r][q]), flint.fmpq(0)) for r in range(k1, k2))


def _display_name(name: str) -> str:
    """``catmull-clark`` -> ``Catmull-Clark``."""
    return "-".join(part.capitalize() for part in name.split("-"))


def check_applicable(scheme: Scheme) -> None:
    """Raise :class:`~symdecomp.errors.InvalidSchemeError` (one line) if the characteristic ring is not a known spline.

    The scheme is one set of rules for the whole mesh (see :mod:`symdecomp.schemes.scheme`): its
    edge and face rules everywhere, its vertex rule at every vertex by that vertex's valence. Away
    from ``O`` every vertex has the regular valence (4 on quads, 6 on triangles), so the regular
    patches are the splines the test knows (bicubic B-splines, quartic box-splines) exactly when
    all its rules at the regular valence, the vertex rule included, are Catmull-Clark's or Loop's.
    The answer depends on the scheme alone, so it is worked out once per scheme (not per valence).
    """
    reason = _inapplicable(scheme)
    if reason is not None:
        raise NotApplicableError(reason)


#: How the vertex rule's weights on each kind of 1-ring neighbour are named in the refusal.
_WHO = {"a": "each neighbour", "b": "each face neighbour"}


@lru_cache(maxsize=32)
def _inapplicable(scheme: Scheme) -> str | None:
    """Why the C1 test does not apply to ``scheme`` (one line), or ``None``: :func:`check_applicable`'s reason."""
    if scheme.parameters:
        return f"scheme {scheme.name!r} has free parameters {', '.join(map(str, scheme.parameters))}; give them values first"
    lat = scheme.lattice
    regular, reference = lat.regular_valence, lat.reference()
    try:
        ours, theirs = subdivision_matrix(scheme, regular), subdivision_matrix(reference, regular)
    except InvalidSchemeError as exc:
        return f"scheme {scheme.name!r}: the C1 test does not apply ({exc})"
    layout = ring_layout(lat)
    if ours[1:, :] != theirs[1:, :]:
        kinds = ("edge", "face")[:len(lat.one_ring_classes)]
        rules, verb = (" and ".join(kinds) + " rules", "are") if len(kinds) > 1 else (f"{kinds[0]} rule", "is")
        return (
            f"the C1 test does not apply to scheme {scheme.name!r}: its {rules} at valence {regular} {verb} not "
            f"{layout.reference}'s, so its regular patches are not {layout.spline}s (the only regular splines it knows)"
        )
    if ours[0, :] != theirs[0, :]:
        mine = tuple(ours[0, k] for k in (0, 1, 1 + regular) if k < ours.cols)
        standard = tuple(theirs[0, k] for k in (0, 1, 1 + regular) if k < theirs.cols)
        return (
            f"the C1 test does not apply to scheme {scheme.name!r}: its vertex rule at the regular valence {regular} has the "
            f"weights {mine} ({', '.join(('centre', *(_WHO[name] for name, _ in lat.one_ring_classes)))}), not "
            f"{layout.reference}'s {standard}; every regular vertex of the mesh uses it, so its regular patches are not "
            f"{layout.spline}s (the only regular splines it knows)"
        )
    return None


def omega_ball(n: int, j: int) -> flint.acb:
    """``e^{2 pi i j / n}`` as an Arb ball."""
    return flint.acb(flint.fmpq(2 * j, n)).exp_pi_i()


def _rational(w) -> flint.fmpq:
    """A weight at one valence as an exact FLINT rational (one line if it is not rational)."""
    if isinstance(w, (Fraction, int)):
        return to_fmpq(w)
    w = sp.sympify(w, strict=True)
    if not w.is_Rational:
        raise InvalidSchemeError(f"weight {w} is not an exact rational at this valence")
    return to_fmpq(w)


def one_ring_rows(scheme: Scheme, n: int) -> list[dict]:
    """The rows of the new 1-ring classes (scheme rules at valence ``n``): ``{(sector offset, class): weight}``."""
    rows = []
    for rule in scheme.stencils():
        weights: dict = {}
        for m, pairs in ((0, rule.a), (1, rule.b)):
            for k, w in pairs:
                weights[(k, m)] = weights.get((k, m), 0) + sp.sympify(w, strict=True).subs(N, n)
        rows.append(weights)
    return rows


def _exact_rows(scheme: Scheme, n: int) -> tuple[tuple[tuple[int, int, flint.fmpq], ...], ...]:
    """:func:`one_ring_rows` as exact FLINT rationals ``((offset, class, weight), ...)`` per row."""
    return tuple(tuple((d, m, _rational(w)) for (d, m), w in weights.items()) for weights in one_ring_rows(scheme, n))


def frequency_blocks(scheme: Scheme, n: int):
    """``j, rows -> B_j``: :func:`frequency_block` for every frequency of one valence, the rules at ``n`` read once.

    The C1 test builds ``B_j`` for ``n / 2 + 1`` frequencies; sympy substitutes ``n`` into the
    rules once per valence (not once per frequency), and each block computes only the powers
    ``omega^(j d)`` of the stencils' offsets ``d`` (a few, not ``n``).
    """
    n = check_valence(n)
    layout = ring_layout(scheme.lattice)
    exact = _exact_rows(scheme, n)

    def block(j: int, rows: int | None = None) -> flint.acb_mat:
        rows = layout.two_ring if rows is None else rows
        powers: dict[int, flint.acb] = {}

        def power(d: int) -> flint.acb:
            k = j * d % n
            if k not in powers:
                powers[k] = omega_ball(n, k)
            return powers[k]

        B = flint.acb_mat(rows, layout.two_ring)
        for r, weights in enumerate(exact[:rows]):
            for d, m, w in weights:
                B[r, m] += w * power(d)
        for r in range(layout.one_ring, rows):
            for q, terms in enumerate(layout.offsets[r]):
                for l, w in terms:
                    B[r, q] += w * power(l)
        return B

    return block


def frequency_block(scheme: Scheme, n: int, j: int, *, rows: int | None = None) -> flint.acb_mat:
    """``B_j``: the first ``rows`` level-1 classes of :func:`ring_layout` from the 2-ring at frequency ``j``.

    ``rows = None`` gives the square 2-ring block (``M_j`` upper left, ``S_j`` lower right);
    ``rows = len(layout.labels)`` also the new ring 3, which the sub-patches need. The ``O``
    column is left out: for ``j != 0`` ``O`` is 0 in every eigenvector. Many frequencies of one
    valence: :func:`frequency_blocks`.
    """
    return frequency_blocks(scheme, n)(j, rows)


@dataclass(frozen=True)
class FrequencyEigenvector:
    """An eigenvector of the 2-ring matrix at frequency ``j``, extended to the level-1 3-ring."""

    n: int
    j: int
    #: The eigenvalue (an Arb ball).
    eigenvalue: flint.acb
    #: ``{(u, v): value}`` on the layout's classes of sector 0 (sector ``s``: times ``omega^s``).
    values: dict
    lattice: Lattice = QUAD

    @property
    def mesh(self) -> str:
        """The lattice's name."""
        return self.lattice.name


def _one_ring_null_vector(M: flint.acb_mat, lam: flint.acb, j: int) -> list:
    """A null vector of ``M - lambda`` (``1 x 1`` or ``2 x 2``) with an entry certainly not 0."""
    if M.nrows() == 1:
        return [flint.acb(1)]
    m00, m01, m10, m11 = M[0, 0], M[0, 1], M[1, 0], M[1, 1]
    # [m01, lambda - m00] or [lambda - m11, m10]; for a simple root one of them is not 0 (m01 = 0: M_j is triangular
    # and lambda is m00 or m11, not both), so take one with an entry that is certainly not 0, larger off-diagonal first
    candidates = [[m01, lam - m00], [lam - m11, m10]]
    if abs(m01).mid() < abs(m10).mid():
        candidates.reverse()
    usable = [v for v in candidates if v[0] != 0 or v[1] != 0]
    if not usable:
        raise InvalidSchemeError(f"the frequency-{j} eigenvector for {lam} could not be separated from 0")
    return usable[0]


def frequency_eigenvector(scheme: Scheme, n: int, j: int, eigenvalue: flint.acb) -> FrequencyEigenvector:
    """The eigenvector of ``M_j`` for ``eigenvalue`` (a ball around a simple root), lifted to the 2-ring and refined once.

    Normalised to the value 1 at ``a_0`` (level 0), so ``a_s`` is ``omega^s``; to 1 at ``b_0`` when ``a_0``
    is 0 (``M_j`` triangular).

    The outer part solves ``(lambda I - S_j) c_out = (lower left block) c_1ring`` (Arb's certified
    solve); ``lambda`` must not be an eigenvalue of ``S_j``, which the spectral test has shown.
    """
    layout = ring_layout(scheme.lattice)
    k1, k2 = layout.one_ring, layout.two_ring
    B = frequency_block(scheme, n, j, rows=len(layout.labels))
    lam = eigenvalue
    c1 = _one_ring_null_vector(flint.acb_mat([[B[r, c] for c in range(k1)] for r in range(k1)]), lam, j)
    k = k2 - k1
    A, rhs = flint.acb_mat(k, k), flint.acb_mat(k, 1)
    for r in range(k):
        for c in range(k):
            A[r, c] = (lam if r == c else 0) - B[k1 + r, k1 + c]
        rhs[r, 0] = sum((B[k1 + r, m] * c1[m] for m in range(k1)), flint.acb(0))
    out = A.solve(rhs)
    c = c1 + [out[r, 0] for r in range(k)]
    # normalised: 1 at a_0, so the map and its Jacobian are comparable across n; at b_0 if a_0 is 0 (an eigenvector
    # that vanishes on the a_i is still one: a complex factor only rotates and scales the map)
    scale = c[0] if c[0] != 0 else c[1]
    c = [x / scale for x in c]
    values = {label: sum((B[r, m] * c[m] for m in range(k2)), flint.acb(0)) for r, label in enumerate(layout.labels)}
    return FrequencyEigenvector(n, j, lam, values, scheme.lattice)


def _value(vec: FrequencyEigenvector, u: int, v: int) -> flint.acb:
    lab = vec.lattice.canonical(0, u, v)
    if lab is None:
        return flint.acb(0)
    s, uu, vv = lab
    return omega_ball(vec.n, vec.j * s % vec.n) * vec.values[(uu, vv)]


def subpatch_nets(vec: FrequencyEigenvector) -> tuple:
    """Sector 0's control nets (complex: ``x + i y``).

    Quads: three ``4 x 4`` B-spline nets, ``P[i][k]`` of face ``(a, b)`` the level-1 point
    ``(a - 1 + i, b - 1 + k)``. Triangles: for each of :data:`TRIANGLES` the dict
    ``{lattice point: value}`` on its 12 :func:`triangle_patch_points`.
    """
    return vec.lattice.select(_SUBPATCH_NETS, "the characteristic ring's sub-patch nets")(vec)


#: The characteristic ring's sub-patch nets on each lattice.
_SUBPATCH_NETS = {
    BICUBIC: lambda vec: tuple(
        [[_value(vec, a - 1 + i, b - 1 + k) for k in range(4)] for i in range(4)] for a, b in SUBPATCH_FACES
    ),
    BOX_SPLINE: lambda vec: tuple({p: _value(vec, *p) for p in triangle_patch_points(t)} for t in TRIANGLES),
}


def inner_boundary_nets(vec: FrequencyEigenvector) -> tuple[list[list[flint.acb]], list[list[flint.acb]]]:
    """The B-spline nets of faces ``(1, 0)`` and ``(0, 1)``, whose edges ``u = 1`` and ``v = 1`` form the inner boundary."""
    nets = subpatch_nets(vec)
    return nets[0], nets[2]
