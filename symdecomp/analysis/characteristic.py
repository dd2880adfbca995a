"""The 2-ring subdivision matrix by frequency, its eigen-data in Arb, and the characteristic map's control nets.

Reif's test (Reif 1995; Peters and Reif, *Subdivision Surfaces*, Springer 2008, Chapters 4-5)
looks at the *characteristic map*: the spline ring that the two real subdominant eigenvectors
generate. For a scheme of Catmull-Clark type (the rules of a
:class:`~symdecomp.schemes.scheme.Scheme` around the extraordinary vertex ``O``, the bicubic
B-spline rules of Catmull-Clark everywhere else) the ring is made of bicubic patches, and which
control points they need is read off the quad grid of one sector.

**Which control points, and why.** Label the vertices of sector ``s`` by ``(s, u, v)`` as in
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

**By frequency.** The 2-ring matrix is block-circulant (the rules do not depend on the
sector). For a frequency ``j`` a vector with sector values ``omega^s c`` (``omega = e^{2 pi i j / n}``,
``c`` the six values of sector 0 at ``(1,0), (1,1), (1,2), (2,0), (2,1), (2,2)``) maps to one
with sector values ``omega^s B_j c``. ``B_j`` is ``6 x 6`` and block lower triangular: its upper
left ``2 x 2`` block is the 1-ring matrix ``M_j`` (the new ``a_i``, ``b_i`` depend only on the old
1-ring), the lower right ``4 x 4`` block ``S_j`` belongs to the outer points, which the regular
rules move. The stencils are read once, exactly, from :func:`~symdecomp.schemes.mesh.refine`
applied to unit vectors.

The eigen-data are Arb balls (python-flint), so every number here is a rigorous enclosure.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import flint
import sympy as sp

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.mesh import mesh_rules, refine, ring_mesh, ring_mesh_labels
from symdecomp.schemes.scheme import Scheme, catmull_clark, subdivision_matrix
from symdecomp.symbols import n as N
from symdecomp.validate import check_valence

__all__ = [
    "RING2_LABELS",
    "LEVEL1_LABELS",
    "SUBPATCH_FACES",
    "RingStencils",
    "ring_stencils",
    "check_applicable",
    "frequency_block",
    "omega_ball",
    "FrequencyEigenvector",
    "frequency_eigenvector",
    "subpatch_nets",
    "inner_boundary_nets",
]

#: The six per-sector points of the 2-ring, in the order of ``c`` (canonical labels ``u >= 1``).
RING2_LABELS = ((1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (2, 2))
#: The twelve per-sector points of the 3-ring at level 1: the 2-ring first, then ring 3.
LEVEL1_LABELS = RING2_LABELS + ((1, 3), (2, 3), (3, 0), (3, 1), (3, 2), (3, 3))
#: Lower corners of the three level-1 faces of sector 0 that make up the characteristic ring.
SUBPATCH_FACES = ((1, 0), (1, 1), (0, 1))

_PROBE_VALENCE = 7  # stencils reach one sector either side; 7 sectors keep the offsets apart


def canonical(s: int, u: int, v: int) -> tuple[int, int, int] | None:
    """The label ``(sector, u, v)`` with ``u >= 1`` of a grid point of sector ``s`` (``None``: ``O``).

    Points just outside the sector (``u = -1`` or ``v = -1``) are named in the neighbouring
    sector: ``(s, u, -1) = (s - 1, 1, u)`` and ``(s, -1, v) = (s + 1, v, 1)``.
    """
    if u == -1:
        s, u, v = s + 1, v, 1
    elif v == -1:
        s, u, v = s - 1, 1, u
    if u == 0 and v == 0:
        return None
    if u == 0:
        s, u, v = s + 1, v, 0
    return s, u, v


@dataclass(frozen=True)
class RingStencils:
    """Rows of the refinement from the level-0 2-ring to the level-1 3-ring, for sector 0.

    ``rows[label] = (weight on O, {(sector offset d, index m into RING2_LABELS): weight})`` for
    the labels of :data:`LEVEL1_LABELS` other than the 1-ring ones, which come from the scheme.
    """

    rows: dict


@lru_cache(maxsize=1)
def ring_stencils() -> RingStencils:
    """The bicubic B-spline (Catmull-Clark) rows, read exactly off one refinement of unit vectors."""
    n0, rings = _PROBE_VALENCE, 2
    labels = ring_mesh_labels(n0, rings)
    ident = {lab: i for i, lab in enumerate(labels)}
    size = len(labels)
    mesh = ring_mesh(n0, rings, lambda s, u, v: tuple(Fraction(int(ident[(s, u, v)] == k)) for k in range(size)))
    step = refine(mesh, mesh_rules(catmull_clark()))

    def old_id(s, u, v):
        lab = canonical(s % n0, u, v)
        return 0 if lab is None else ident[(lab[0] % n0, lab[1], lab[2])]

    rows = {}
    for u, v in LEVEL1_LABELS[2:]:
        if u % 2 == 0 and v % 2 == 0:
            new = step.vertex_point[old_id(0, u // 2, v // 2)]
        elif u % 2 == 1 and v % 2 == 1:
            a, b = (u - 1) // 2, (v - 1) // 2
            new = step.face_point[a * rings + b]  # faces of sector 0 come first, (u, v) row-major
        elif u % 2 == 1:
            new = step.edge_point[frozenset((old_id(0, (u - 1) // 2, v // 2), old_id(0, (u + 1) // 2, v // 2)))]
        else:
            new = step.edge_point[frozenset((old_id(0, u // 2, (v - 1) // 2), old_id(0, u // 2, (v + 1) // 2)))]
        value = step.mesh.values[new]
        center, weights = value[0], {}
        for k in range(1, size):
            if value[k]:
                s, uu, vv = labels[k]
                d = s if s <= n0 // 2 else s - n0
                weights[(d, RING2_LABELS.index((uu, vv)))] = value[k]
        rows[(u, v)] = (center, weights)
    return RingStencils(rows)


def check_applicable(scheme: Scheme) -> None:
    """Raise :class:`~symdecomp.errors.InvalidSchemeError` (one line) if the bicubic ring does not apply.

    The scheme's rules act on the 1-ring of ``O``; every other point is refined by the
    bicubic B-spline rules (Catmull-Clark's at valence 4). So that this is one scheme, its edge
    and face rules at ``n = 4`` must be Catmull-Clark's (they are the rules of the regular
    mesh); its vertex rule is used at ``O`` only (tuned weights are a change at ``O``).
    """
    if scheme.parameters:
        raise InvalidSchemeError(
            f"scheme {scheme.name!r} has free parameters {', '.join(map(str, scheme.parameters))}; give them values first"
        )
    try:
        same = subdivision_matrix(scheme, 4)[1:, :] == subdivision_matrix(catmull_clark(), 4)[1:, :]
    except InvalidSchemeError as exc:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the C1 test does not apply ({exc})") from None
    if not same:
        raise InvalidSchemeError(
            f"the C1 test does not apply to scheme {scheme.name!r}: its edge and face rules at valence 4 are not "
            "Catmull-Clark's, so its regular patches are not bicubic B-splines"
        )


def omega_ball(n: int, j: int) -> flint.acb:
    """``e^{2 pi i j / n}`` as an Arb ball."""
    return flint.acb(flint.fmpq(2 * j, n)).exp_pi_i()


def _ball(w) -> flint.acb:
    if isinstance(w, (Fraction, int)):
        w = Fraction(w)
        return flint.acb(flint.fmpq(w.numerator, w.denominator))
    w = sp.sympify(w)
    if not w.is_Rational:
        raise InvalidSchemeError(f"weight {w} is not an exact rational at this valence")
    return flint.acb(flint.fmpq(int(w.p), int(w.q)))


def one_ring_rows(scheme: Scheme, n: int) -> dict:
    """The rows of the new ``a_0`` and ``b_0`` (scheme rules at valence ``n``) in the form of :class:`RingStencils`."""
    rows = {}
    for label, rule in (((1, 0), scheme.edge_rule), ((1, 1), scheme.face_rule)):
        weights: dict = {}
        for m, pairs in ((0, rule.a), (1, rule.b)):
            for k, w in pairs:
                key = (k, m)
                weights[key] = weights.get(key, 0) + sp.sympify(w).subs(N, n)
        rows[label] = (sp.sympify(rule.center).subs(N, n), weights)
    return rows


def frequency_block(scheme: Scheme, n: int, j: int, *, rows: int = 6) -> flint.acb_mat:
    """``B_j`` (``rows x 6``): the first ``rows`` labels of :data:`LEVEL1_LABELS` from the 2-ring at frequency ``j``.

    ``rows = 6`` gives the 2-ring block (``M_j`` upper left, ``S_j`` lower right); ``rows = 12``
    also the new ring 3, which the sub-patches need. The ``O`` column is left out: for ``j != 0``
    ``O`` is 0 in every eigenvector.
    """
    n = check_valence(n)
    omega = omega_ball(n, j)
    table = {**ring_stencils().rows, **one_ring_rows(scheme, n)}
    B = flint.acb_mat(rows, 6)
    for r, label in enumerate(LEVEL1_LABELS[:rows]):
        _, weights = table[label]
        for (d, m), w in weights.items():
            B[r, m] += _ball(w) * omega ** (d % n)
    return B


@dataclass(frozen=True)
class FrequencyEigenvector:
    """An eigenvector of the 2-ring matrix at frequency ``j``, extended to the level-1 3-ring."""

    n: int
    j: int
    #: The eigenvalue (an Arb ball).
    eigenvalue: flint.acb
    #: ``{(u, v): value}`` on :data:`LEVEL1_LABELS` of sector 0 (sector ``s``: times ``omega^s``).
    values: dict


def frequency_eigenvector(scheme: Scheme, n: int, j: int, eigenvalue: flint.acb) -> FrequencyEigenvector:
    """The eigenvector of ``M_j`` for ``eigenvalue`` (a ball around a simple root), lifted to the 2-ring and refined once.

    Normalised to the value 1 at ``a_0`` (level 0), so ``a_s`` is ``omega^s``; to 1 at ``b_0`` when ``a_0``
    is 0 (``M_j`` triangular).

    The outer part solves ``(lambda I - S_j) c_out = (lower left block) c_1ring`` (Arb's certified
    solve); ``lambda`` must not be an eigenvalue of ``S_j``, which the spectral test has shown.
    """
    B = frequency_block(scheme, n, j, rows=12)
    lam = eigenvalue
    m00, m01, m10, m11 = B[0, 0], B[0, 1], B[1, 0], B[1, 1]
    # a null vector of M_j - lambda: [m01, lambda - m00] or [lambda - m11, m10]; for a simple root one of them
    # is not 0 (m01 = 0: M_j is triangular and lambda is m00 or m11, not both), so take one with an entry that
    # is certainly not 0, the row with the larger off-diagonal entry first
    candidates = [[m01, lam - m00], [lam - m11, m10]]
    if abs(m01).mid() < abs(m10).mid():
        candidates.reverse()
    usable = [v for v in candidates if v[0] != 0 or v[1] != 0]
    if not usable:
        raise InvalidSchemeError(f"the frequency-{j} eigenvector for {lam} could not be separated from 0")
    c1 = usable[0]
    A = flint.acb_mat(4, 4)
    rhs = flint.acb_mat(4, 1)
    for r in range(4):
        for c in range(4):
            A[r, c] = (lam if r == c else 0) - B[2 + r, 2 + c]
        rhs[r, 0] = B[2 + r, 0] * c1[0] + B[2 + r, 1] * c1[1]
    out = A.solve(rhs)
    c = c1 + [out[r, 0] for r in range(4)]
    # normalised: 1 at a_0, so the map and its Jacobian are comparable across n; at b_0 if a_0 is 0 (an eigenvector
    # that vanishes on the a_i is still one: a complex factor only rotates and scales the map)
    scale = c[0] if c[0] != 0 else c[1]
    c = [x / scale for x in c]
    values = {}
    for r, label in enumerate(LEVEL1_LABELS):
        values[label] = sum((B[r, k] * c[k] for k in range(6)), flint.acb(0))
    return FrequencyEigenvector(n, j, lam, values)


def _value(vec: FrequencyEigenvector, u: int, v: int) -> flint.acb:
    lab = canonical(0, u, v)
    if lab is None:
        return flint.acb(0)
    s, uu, vv = lab
    return omega_ball(vec.n, vec.j * s % vec.n) * vec.values[(uu, vv)]


def subpatch_nets(vec: FrequencyEigenvector) -> tuple[list[list[flint.acb]], ...]:
    """The three ``4 x 4`` B-spline control nets (complex: ``x + i y``) of sector 0's ring.

    Net ``P[i][k]`` of face ``(a, b)`` is the level-1 point ``(a - 1 + i, b - 1 + k)``.
    """
    return tuple(
        [[_value(vec, a - 1 + i, b - 1 + k) for k in range(4)] for i in range(4)] for a, b in SUBPATCH_FACES
    )


def inner_boundary_nets(vec: FrequencyEigenvector) -> tuple[list[list[flint.acb]], list[list[flint.acb]]]:
    """The B-spline nets of faces ``(1, 0)`` and ``(0, 1)``, whose edges ``u = 1`` and ``v = 1`` form the inner boundary."""
    nets = subpatch_nets(vec)
    return nets[0], nets[2]
