"""The mirror-symmetric decomposition of a boundary, crease or corner vertex (issue 20, item 2).

At a vertex with sharp edges there is no rotational symmetry, but each *sector* (the ``k`` faces between
two consecutive sharp edges) is mirror symmetric: ``a_{p+i} <-> a_{p+k-i}``. On quads the 1-ring of a
sector is ``O, a_p..a_{p+k}, b_p..b_{p+k-1}``; on triangles ``O, a_p..a_{p+k}``.

* **The crease block.** ``O`` and the edge neighbours on sharp edges move by the sharp rules only
  (:class:`~symdecomp.schemes.sharp.SharpRules`: the crease vertex rule ``crease_centre, crease_end``,
  or the corner's identity, and the crease edge rule ``crease_edge``), so they span a block ``C`` of their
  own and the matrix is block lower-triangular ``[[C, 0], [X, T]]``.
* **The sine blocks.** With a smooth edge stencil symmetric about its edge and a face stencil symmetric
  about its face (reaching no further than the neighbouring edge and faces), the discrete sine polylines
  ``a_{p+i} = A sin(theta i)``, ``b_{p+i} = B sin(theta (i + 1/2))`` with ``theta = pi j/k`` vanish on
  ``O`` and on the sharp edges and are mapped to themselves: ``(A, B) -> M(theta) (A, B)`` with

  ``M(theta) = [[sum_d e_d cos(d theta), sum_d f_d cos((d + 1/2) theta)], [sum_d g_d cos((d - 1/2) theta), h_0]]``

  (``e, f``: the edge rule's weights on ``a_{i+d}, b_{i+d}``; ``g, h``: the face rule's on ``a_{i+d}, b_{i+d}``).
  This is an identity in ``theta`` and in the index ``i`` (:func:`sine_identity`, reduced to 0 by sympy's
  trigonometric expansion), so it holds for every ``k``; ``j = 1..k-1`` give 2 x 2 blocks (1 x 1 on
  triangles) and ``j = k`` the face rule's own weight ``h_0`` (``a = 0``, ``b_i = (-1)^i``).
  Biermann-Levin-Zorin's modified rule for a smooth edge at a sharp vertex (weights ``near_edge_centre``,
  ``near_edge_end`` in the sector angle ``theta_k``) replaces ``e_0`` by ``near_edge_end``.
* **A dart** (one sharp edge in a closed ring of ``n`` faces) is mirror symmetric about its sharp edge: the
  antisymmetric part is the same sine blocks at ``theta = 2 pi j/n``, ``j = 1..floor((n-1)/2)`` (and ``h_0``
  for even ``n``); the symmetric (cosine) part, with ``O`` and the sharp edge, is the rest (``n + 2`` points).

The blocks are :func:`sine_block` (symbolic in ``theta``), :func:`sector_decomposition` (for one vertex, with
the similarity transform) and :func:`sector_spectrum` (the exact eigenvalues, each with its block). The
comparison with the boundary curve's eigenvalue for every ``k`` is :mod:`symdecomp.analysis.mirror_threshold`.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import numbers
from dataclasses import dataclass

import sympy as sp

from symdecomp import symbols
from symdecomp.algebra.trig_identity import reduced
from symdecomp.analysis.eigenvalue import Eigenvalue, MirrorBlock
from symdecomp.errors import InvalidInputError, InvalidSchemeError, InvalidTypeError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, Stencil, check_scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sharp import SharpRules
from symdecomp.symbols import n as N
from symdecomp.validate import check_int, check_type

__all__ = ["THETA", "THETA_K", "SineBlock", "SectorDecomposition", "sharp_weights", "with_near_edge",
           "mirror_stencils", "sine_block", "sine_identity", "crease_block", "sector_rows", "sector_matrix", "sector_decomposition",
           "sector_spectrum"]

#: The frequency of a sine polyline: ``theta = pi j/k`` in a sector of ``k`` faces.
THETA = sp.Symbol("theta", positive=True)
#: The sector angle of the sharp rules (pi/k in a crease or boundary sector, alpha/k in a corner sector).
THETA_K = symbols.theta_k
_I = sp.Symbol("i", integer=True)
_J = sp.Symbol("j", integer=True, positive=True)
_K = sp.Symbol("k", integer=True, positive=True)

_NAMES = ("crease_centre", "crease_end", "crease_edge", "near_edge_centre", "near_edge_end")


def sharp_weights(scheme: Scheme, rules=None) -> dict:
    """The sharp-rule weights this module reads, from ``rules`` (a :class:`~symdecomp.schemes.sharp.SharpRules`) or
    the scheme's own (``scheme.sharp``): the one place that reads them."""
    source = scheme.sharp if rules is None else check_type(rules, SharpRules, "rules")
    return {name: getattr(source, name) for name in _NAMES}


def with_near_edge(scheme: Scheme, centre, end, rules=None) -> SharpRules:
    """The scheme's sharp rules (or ``rules``) with BLZ's modified smooth edge rule at a sharp vertex."""
    source = scheme.sharp if rules is None else check_type(rules, SharpRules, "rules")
    return dataclasses.replace(source, near_edge_centre=centre, near_edge_end=end)


def _weights(stencil: Stencil, part: str) -> dict[int, sp.Expr]:
    return dict(getattr(stencil, part))


def _require(condition: bool, scheme: Scheme, what: str) -> None:
    if not condition:
        raise NotApplicableError(f"scheme {scheme.name!r}: {what}, so its sectors have no mirror decomposition")


def mirror_stencils(scheme) -> tuple[dict, dict | None]:
    """The smooth stencils as ``{offset: weight}`` maps, checked mirror symmetric and reaching only the neighbours.

    Returns ``(edge, face)`` with ``edge = {"O": w, "a": {...}, "b": {...}}`` (``face`` is ``None`` on triangles).
    Refuses (:class:`~symdecomp.errors.NotApplicableError`, naming the weight) a stencil that is not symmetric
    about its edge or face, that reaches past the neighbouring edge or face, or that depends on the valence.
    """
    scheme = check_scheme(scheme)
    e, quad = scheme.edge_rule, scheme.face_rule is not None
    ea, eb = _weights(e, "a"), _weights(e, "b")
    _require(set(ea) <= {-1, 0, 1}, scheme, f"the edge rule's weight on a_(i{max(ea, key=abs):+d}) reaches past the neighbouring edge")
    _require(sp.simplify(ea.get(1, 0) - ea.get(-1, 0)) == 0, scheme,
             f"the edge rule's weights on a_(i+1) ({ea.get(1, 0)}) and a_(i-1) ({ea.get(-1, 0)}) differ")
    _require(set(eb) <= {-1, 0}, scheme, "the edge rule's b weights reach past the two faces of the edge")
    _require(sp.simplify(eb.get(0, 0) - eb.get(-1, 0)) == 0, scheme,
             f"the edge rule's weights on b_i ({eb.get(0, 0)}) and b_(i-1) ({eb.get(-1, 0)}) differ")
    edge = {"O": e.center, "a": ea, "b": eb}
    face = None
    if quad:
        f = scheme.face_rule
        fa, fb = _weights(f, "a"), _weights(f, "b")
        _require(set(fa) <= {0, 1} and set(fb) <= {0}, scheme, "the face rule reaches past its face (O, a_i, b_i, a_(i+1))")
        _require(sp.simplify(fa.get(0, 0) - fa.get(1, 0)) == 0, scheme,
                 f"the face rule's weights on a_i ({fa.get(0, 0)}) and a_(i+1) ({fa.get(1, 0)}) differ")
        face = {"O": f.center, "a": fa, "b": fb}
    for rule in (edge, face):
        if rule is not None:
            weights = [rule["O"], *rule["a"].values(), *rule["b"].values()]
            _require(not any(N in sp.sympify(w, strict=True).free_symbols for w in weights), scheme,
                     "a smooth edge or face weight depends on the valence n, which a sector does not have")
    return edge, face


def _edge_weights(scheme: Scheme, edge: dict, rules=None, *, modified: bool = True) -> dict:
    """The smooth edge rule at a sharp vertex: BLZ's ``near_edge_centre``/``near_edge_end`` where the rules give them."""
    w = sharp_weights(scheme, rules)
    out = {"O": edge["O"], "a": dict(edge["a"]), "b": dict(edge["b"])}
    if modified and w["near_edge_centre"] is not None:
        out["O"], out["a"][0] = w["near_edge_centre"], w["near_edge_end"]
    return out


def sine_block(scheme, rules=None, *, modified: bool = True) -> sp.Matrix:
    """``M(theta)``: the sine polylines' block, symbolic in :data:`THETA` (and :data:`THETA_K` for BLZ's rules).

    2 x 2 on quads (amplitudes ``A`` on the ``a_i``, ``B`` on the ``b_i``), 1 x 1 on triangles. ``modified=False``
    reads the plain smooth edge rule (a dart's sectors, where the vertex is smooth).
    """
    edge, face = mirror_stencils(scheme)
    e = _edge_weights(scheme, edge, rules, modified=modified)
    aa = sum((w * sp.cos(d * THETA) for d, w in e["a"].items()), sp.Integer(0))
    if face is None:
        return sp.Matrix([[aa]])
    ab = sum((w * sp.cos((d + sp.Rational(1, 2)) * THETA) for d, w in e["b"].items()), sp.Integer(0))
    ba = sum((w * sp.cos((d - sp.Rational(1, 2)) * THETA) for d, w in face["a"].items()), sp.Integer(0))
    return sp.Matrix([[aa, ab], [ba, face["b"].get(0, sp.Integer(0))]])


def sine_identity(scheme, rules=None, *, modified: bool = True) -> tuple[sp.Matrix, sp.Matrix]:
    """The proof that the sine polylines are invariant for every ``k`` (:func:`_sine_identity`), once per scheme and rules."""
    scheme = check_scheme(scheme)
    rules = None if rules is None else check_type(rules, SharpRules, "rules")
    return _sine_identity(scheme, rules, bool(modified))


@functools.lru_cache(maxsize=64)
def _sine_identity(scheme, rules, modified: bool) -> tuple[sp.ImmutableMatrix, sp.ImmutableMatrix]:
    """The proof that the sine polylines are invariant for every ``k``: ``(residual, boundary values)``.

    ``residual``: each interior stencil applied to ``a_m = A sin(theta m)``, ``b_m = B sin(theta (m + 1/2))``
    at a symbolic index ``i``, minus ``M(theta) (A, B)`` times ``sin(theta i)`` (resp. ``sin(theta (i + 1/2))``),
    reduced by sympy's trigonometric expansion; it is 0 identically in ``i`` and ``theta``. ``boundary``: the
    polylines on the sharp edges ``a_0`` and ``a_k`` at ``theta = pi j/k`` (``sin(0)``, ``sin(pi j)``), 0 for integer j.
    """
    edge, face = mirror_stencils(scheme)
    e, M = _edge_weights(scheme, edge, rules, modified=modified), sine_block(scheme, rules, modified=modified)
    A, B = sp.symbols("A B")

    def a(m):
        return A * sp.sin(THETA * m)

    def b(m):
        return B * sp.sin(THETA * (m + sp.Rational(1, 2)))

    new_a = sum((w * a(_I + d) for d, w in e["a"].items()), sp.Integer(0))
    new_a += sum((w * b(_I + d) for d, w in e["b"].items()), sp.Integer(0))
    rows = [new_a - (M[0, 0] * A + (M[0, 1] * B if face else 0)) * sp.sin(THETA * _I)]
    if face is not None:
        new_b = sum((w * a(_I + d) for d, w in face["a"].items()), sp.Integer(0)) + face["b"].get(0, 0) * b(_I)
        rows.append(new_b - (M[1, 0] * A + M[1, 1] * B) * sp.sin(THETA * (_I + sp.Rational(1, 2))))
    residual = sp.ImmutableMatrix([reduced(sp.expand(sp.expand_trig(r))) for r in rows])
    boundary = sp.ImmutableMatrix([sp.sin(THETA * 0), sp.sin(THETA * _K).subs(THETA, sp.pi * _J / _K)])
    return residual, boundary


def crease_block(scheme, count: int = 2, *, corner: bool = False, rules=None) -> sp.Matrix:
    """``C``: ``O`` and its ``count`` sharp-edge neighbours, moved by the sharp rules only.

    A crease or boundary vertex (``count = 2``, not a corner) takes ``crease_centre`` on itself and ``crease_end``
    on each sharp neighbour; a corner (or ``count >= 3`` sharp edges) interpolates; each sharp edge point takes
    ``crease_edge`` on each end.
    """
    scheme = check_scheme(scheme)
    count = check_int(count, "count", minimum=2)
    w = sharp_weights(scheme, rules)
    C = sp.zeros(count + 1, count + 1)
    if corner or count > 2:
        C[0, 0] = 1
    else:
        C[0, 0], C[0, 1], C[0, 2] = w["crease_centre"], w["crease_end"], w["crease_end"]
    for r in range(1, count + 1):
        C[r, 0], C[r, r] = w["crease_edge"], 1 - w["crease_edge"]
    return C


@dataclass(frozen=True)
class _Layout:
    """Where the points of a vertex with sharp edges sit in its 1-ring ``O, a_0.., b_0..``."""

    sectors: tuple[int, ...]
    closed: bool
    corner: bool
    quad: bool
    angle: sp.Expr

    @property
    def faces(self) -> int:
        return sum(self.sectors)

    @property
    def a_count(self) -> int:
        return self.faces if self.closed else self.faces + 1

    @property
    def size(self) -> int:
        return 1 + self.a_count + (self.faces if self.quad else 0)

    @property
    def starts(self) -> tuple[int, ...]:
        return tuple(sum(self.sectors[:s]) for s in range(len(self.sectors)))

    @property
    def sharp(self) -> tuple[int, ...]:
        """The positions ``m`` of the edge neighbours ``a_m`` on sharp edges."""
        return self.starts + (() if self.closed else (self.faces,))

    def a(self, m: int) -> int:
        return 1 + (m % self.faces if self.closed else m)

    def b(self, m: int) -> int:
        return 1 + self.a_count + m % self.faces


def vertex_of(scheme: Scheme, vertex) -> SharpVertex:
    """``vertex`` as a :class:`~symdecomp.schemes.sector.SharpVertex` (``k``: a boundary vertex with k faces)."""
    scheme = check_scheme(scheme)
    if isinstance(vertex, SharpVertex):
        return vertex
    if isinstance(vertex, bool) or not isinstance(vertex, numbers.Integral):
        raise InvalidTypeError(f"vertex: expected a SharpVertex or the faces k of a boundary sector, got {type(vertex).__name__}")
    return SharpVertex.boundary(check_int(vertex, "vertex (the faces k of a boundary sector)", minimum=1), scheme.lattice)


def vertex_layout(scheme: Scheme, vertex) -> _Layout:
    """Where the points of ``vertex`` sit: a :class:`~symdecomp.schemes.sector.SharpVertex`, or ``k`` for
    ``SharpVertex.boundary(k, scheme.lattice)``. A boundary vertex with one face is a corner (OpenSubdiv's default
    boundary interpolation, edge and corner), as in :func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`."""
    scheme = check_scheme(scheme)
    vertex = vertex_of(scheme, vertex)
    if vertex.lattice != scheme.lattice:
        raise InvalidSchemeError(f"vertex: a {vertex.lattice.name} vertex, but scheme {scheme.name!r} lives on {scheme.lattice.name}")
    if vertex.sharpness != math.inf:
        raise NotApplicableError("vertex: semi-sharp edges (finite sharpness) have no mirror decomposition here; "
                                 "it reads infinitely sharp ones")
    corner = vertex.corner or (not vertex.closed and vertex.faces == 1)
    angle = sp.pi if vertex.angle is None or not corner else vertex.angle
    return _Layout(vertex.sectors, vertex.closed, corner, scheme.face_rule is not None, angle)


def _add_interior(row: dict, lay: _Layout, centre, stencil: dict, m: int) -> None:
    row[0] = row.get(0, 0) + centre
    for d, w in stencil["a"].items():
        row[lay.a(m + d)] = row.get(lay.a(m + d), 0) + w
    for d, w in stencil["b"].items():
        row[lay.b(m + d)] = row.get(lay.b(m + d), 0) + w


def _centre_row(scheme: Scheme, lay: _Layout, rules) -> dict:
    """Row ``O``: the crease block's first row, or at a dart the smooth vertex rule at valence ``n``."""
    if len(lay.sharp) == 1:
        v, n = scheme.vertex_rule, check_int(lay.faces, "faces around a dart", minimum=3)
        row = {0: v.center.subs(N, n)}
        for m in range(n):
            row[lay.a(m)] = row.get(lay.a(m), 0) + v.each_a.subs(N, n)
            if lay.quad:
                row[lay.b(m)] = row.get(lay.b(m), 0) + v.each_b.subs(N, n)
        return row
    C = crease_block(scheme, len(lay.sharp), corner=lay.corner, rules=rules)
    row = {0: C[0, 0]}
    for r, m in enumerate(lay.sharp, 1):
        row[lay.a(m)] = row.get(lay.a(m), 0) + C[0, r]
    return row


def sector_rows(scheme, vertex, rules=None) -> tuple[dict, ...]:
    """The one-step matrix of the 1-ring of ``vertex`` assembled from the stencils, sparse: ``{column: weight}`` per row.

    The model the blocks describe (:func:`sector_matrix` is it, dense). Order ``O, a_0..a_m, b_0..b_{f-1}`` (``a_0`` on
    the first sharp edge). Interior points use the smooth stencils (BLZ's modified edge rule next to a sharp vertex
    where the rules give it), with ``theta_k`` the sector angle over the sector's faces, evaluated once per sector; a
    dart's ``O`` uses the smooth vertex rule at valence ``n``. O(faces) work and entries.
    """
    scheme = check_scheme(scheme)
    lay = vertex_layout(scheme, vertex)
    edge, face = mirror_stencils(scheme)
    w = sharp_weights(scheme, rules)
    rows: list[dict] = [{} for _ in range(lay.size)]
    rows[0] = _centre_row(scheme, lay, rules)
    for m in lay.sharp:
        rows[lay.a(m)] = {0: w["crease_edge"], lay.a(m): 1 - w["crease_edge"]}
    e = _edge_weights(scheme, edge, rules, modified=len(lay.sharp) > 1)
    for p, k in zip(lay.starts, lay.sectors):
        at = {THETA_K: lay.angle / k, symbols.sector_faces: k}
        stencil = {"a": {d: sp.sympify(x, strict=True).subs(at) for d, x in e["a"].items()}, "b": e["b"]}
        centre = sp.sympify(e["O"], strict=True).subs(at)
        for i in range(1, k):
            _add_interior(rows[lay.a(p + i)], lay, centre, stencil, p + i)
        for i in range(k if lay.quad else 0):
            _add_interior(rows[lay.b(p + i)], lay, face["O"], face, p + i)
    return tuple(rows)


def sector_matrix(scheme, vertex, rules=None) -> sp.Matrix:
    """The exact one-step matrix of the 1-ring of ``vertex`` assembled from the stencils (the model the blocks describe):
    :func:`sector_rows`, dense (for at most ``MAX_DENSE_FACES`` faces)."""
    from symdecomp.schemes.sector import MAX_DENSE_FACES

    scheme = check_scheme(scheme)
    lay = vertex_layout(scheme, vertex)
    if lay.faces > MAX_DENSE_FACES:
        raise InvalidInputError(f"vertex: {lay.faces} faces; the assembled matrix is built for at most {MAX_DENSE_FACES} faces")
    P = sp.zeros(lay.size, lay.size)
    for r, row in enumerate(sector_rows(scheme, vertex, rules)):
        for c, x in row.items():
            P[r, c] = x
    return P


@dataclass(frozen=True)
class SineBlock:
    """One block of the decomposition: sector ``sector`` (its index), frequency ``j``, ``theta = pi j/k``, the matrix."""

    sector: int
    j: int
    theta: sp.Expr
    matrix: sp.Matrix
    #: ``"sine"`` (the 2 x 2 or 1 x 1 block ``M(theta)``) or ``"face"`` (``j = k`` on quads: ``a = 0``, ``b_i = (-1)^i``).
    kind: str = "sine"


@dataclass(frozen=True)
class SectorDecomposition:
    """The blocks of a vertex with sharp edges (:func:`sector_decomposition`).

    ``transform`` is the similarity: its columns are ``O`` and the sharp-edge points (unit vectors), then each block's
    polylines in the order of ``blocks``; ``transform**-1 * matrix * transform`` is block lower-triangular with
    ``crease`` (or, at a dart, ``cosine``) first and the blocks on the diagonal.
    """

    matrix: sp.Matrix
    crease: sp.Matrix | None
    blocks: tuple[SineBlock, ...]
    transform: sp.Matrix
    #: A dart's mirror-symmetric part (``O``, the sharp edge and the symmetric pairs), else ``None``.
    cosine: sp.Matrix | None = None


def _sine_column(lay: _Layout, p: int, k: int, theta) -> tuple[sp.Matrix, sp.Matrix | None]:
    """The sine polyline of frequency ``theta`` on the sector starting at ``a_p``: its a-part and (quads) b-part."""
    a, b = sp.zeros(lay.size, 1), (sp.zeros(lay.size, 1) if lay.quad else None)
    for i in range(1, k):
        a[lay.a(p + i)] = sp.sin(theta * i)
    for i in range(k if lay.quad else 0):
        b[lay.b(p + i)] = sp.sin(theta * (2 * i + 1) / 2)
    return a, b


def _sector_blocks(scheme: Scheme, lay: _Layout, rules, columns: list) -> list[SineBlock]:
    out, dart = [], len(lay.sharp) == 1
    M = sine_block(scheme, rules, modified=not dart)
    for s, (p, k) in enumerate(zip(lay.starts, lay.sectors)):
        period, top = (2, (k - 1) // 2) if dart else (1, k - 1)
        for j in range(1, top + 1):
            theta = period * sp.pi * j / k
            out.append(SineBlock(s, j, theta, M.subs({THETA: theta, THETA_K: lay.angle / k, symbols.sector_faces: k}).applyfunc(sp.simplify)))
            a, b = _sine_column(lay, p, k, theta)
            columns.extend([a] if b is None else [a, b])
        if lay.quad and (not dart or k % 2 == 0):
            j = k // 2 if dart else k
            out.append(SineBlock(s, j, sp.pi, sp.Matrix([[M[1, 1]]]), kind="face"))
            columns.append(_sine_column(lay, p, k, sp.pi)[1])
    return out


def _dart_symmetric(lay: _Layout) -> list[sp.Matrix]:
    """A dart's mirror-symmetric basis: ``O``, ``a_0``, the pairs ``a_m + a_(n-m)`` and ``b_m + b_(n-1-m)``."""
    n, cols = lay.faces, []
    pairs = [(0,), (lay.a(0),)] + [(lay.a(m), lay.a(n - m)) for m in range(1, n // 2 + 1)]
    pairs += [(lay.b(m), lay.b(n - 1 - m)) for m in range((n + 1) // 2)] if lay.quad else []
    for pair in pairs:
        v = sp.zeros(lay.size, 1)
        for r in set(pair):
            v[r] = 1
        cols.append(v)
    return cols


def sector_decomposition(scheme, vertex, rules=None) -> SectorDecomposition:
    """The mirror decomposition of the 1-ring matrix of ``vertex`` (a SharpVertex, or ``k`` for a boundary sector).

    The crease block ``C`` (``O`` and the sharp-edge points), then per sector of ``k`` faces the sine blocks
    ``M(pi j/k)``, ``j = 1..k-1``, and on quads the face block ``j = k``; at a dart the sine blocks at
    ``2 pi j/n`` and the symmetric (cosine) part. ``rules`` overrides the scheme's sharp rules.
    """
    lay = vertex_layout(scheme, vertex)
    P = sector_matrix(scheme, vertex, rules)
    if len(lay.sharp) == 1:
        columns = _dart_symmetric(lay)
        rep = [next(i for i in range(lay.size) if c[i]) for c in columns]  # each column's first point
        cosine = sp.Matrix([[(P * c)[r] for c in columns] for r in rep])
        crease = None
    else:
        crease = sp.Matrix(P.extract([0] + [lay.a(m) for m in lay.sharp], [0] + [lay.a(m) for m in lay.sharp]))
        columns, cosine = [sp.eye(lay.size)[:, i] for i in [0] + [lay.a(m) for m in lay.sharp]], None
    blocks = _sector_blocks(scheme, lay, rules, columns)
    return SectorDecomposition(P, crease, tuple(blocks), sp.Matrix.hstack(*columns), cosine)


def _block_eigenvalue(value: sp.Expr, block: str, sector: int | None = None, j: int | None = None) -> Eigenvalue:
    """One exact eigenvalue of a block (counted once: a repeated one is listed again) and the block it comes from."""
    return Eigenvalue(value, "", 1, exact=value, blocks=(MirrorBlock(block, sector, j),))


def _matrix_eigenvalues(M: sp.Matrix) -> list[sp.Expr]:
    x = sp.Symbol("x")
    out = []
    for factor, mult in sp.factor_list(M.charpoly(x).as_expr(), x)[1]:
        found = sp.roots(sp.Poly(factor, x))
        values = list(found) if sum(found.values()) == sp.degree(factor, x) else sp.Poly(factor, x).all_roots()
        out.extend(sp.simplify(v) for v in values for _ in range(mult))
    return out


def block_eigenvalues(M: sp.Matrix) -> tuple[sp.Expr, ...]:
    """The eigenvalues of a 1 x 1 or 2 x 2 block in closed form: ``(tr +- sqrt(tr^2 - 4 det))/2``."""
    if M.shape == (1, 1):
        return (M[0, 0],)
    tr, det = sp.simplify(M.trace()), sp.simplify(M.det())
    root = sp.sqrt(sp.simplify(tr**2 - 4 * det))
    return tuple(sp.simplify((tr + sign * root) / 2) for sign in (1, -1))


def sector_spectrum(scheme, vertex, rules=None) -> tuple[Eigenvalue, ...]:
    """The exact eigenvalues of the 1-ring matrix of ``vertex``, one item per unit of multiplicity, each with its block
    (crease, cosine, sine j, face) as its one :class:`~symdecomp.analysis.eigenvalue.MirrorBlock`."""
    d = sector_decomposition(scheme, vertex, rules)
    out = [_block_eigenvalue(v, "crease") for v in _matrix_eigenvalues(d.crease)] if d.crease is not None else []
    out += [_block_eigenvalue(v, "cosine") for v in _matrix_eigenvalues(d.cosine)] if d.cosine is not None else []
    for blk in d.blocks:
        out += [_block_eigenvalue(v, blk.kind, blk.sector, blk.j) for v in block_eigenvalues(blk.matrix)]
    return tuple(out)
