"""A StencilScheme's rules read on a halfedge mesh: each new point as an exact row of weights on old points.

The rules are the data of :mod:`symdecomp.schemes.stencils`; this module applies them at anchors
of an explicit mesh (:class:`~symdecomp.schemes.halfedge.HalfedgeMesh`): it chooses the rule by
the valences at the anchor, follows each term's walk, evaluates the weight exactly at the concrete
valence ``n``, face size ``m`` and index ``j``, and sums the terms into a *row*
(old vertex id -> exact weight; a term naming a new point made earlier in the step is replaced by
that point's row). A vertex or face rule must give the same row from every anchor of its vertex or
face (the scheme is rotation invariant there); a rule that does not is refused, naming the kind.

Near the edge of a local mesh a stencil may leave the mesh, or need the valence of a vertex the
mesh does not close: the new point is then *not computable* (``None``); the engine only reads
points whose stencils lie inside (:mod:`symdecomp.analysis.zoo_matrix`).

>>> import sympy as sp
>>> from symdecomp.schemes.halfedge import halfedge_mesh
>>> from symdecomp.schemes.stencils import Term, Rule, KindRules, M
>>> m = halfedge_mesh(((0, 1, 2, 3),))
>>> face = KindRules("face", (Rule((Term(1 / M, over="face"),)),))
>>> kind_row(m, face, ("face", 0), {}, regular=4)
{0: 1/4, 1: 1/4, 2: 1/4, 3: 1/4}
"""

from __future__ import annotations

import sympy as sp

from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.halfedge import HalfedgeMesh
from symdecomp.schemes.stencils import J, KindRules, M, N, Rule, Term

__all__ = ["Row", "PointKey", "is_zero", "same_row", "kind_row", "point_key"]

#: A new point as weights on old vertex ids.
Row = dict[int, sp.Expr]
#: A new point's key: its kind and the vertex, edge (smaller halfedge), face or corner (halfedge) it belongs to.
PointKey = tuple[str, int]

_X = sp.Dummy("x")


class _Unknown(Exception):
    """The stencil needs what the local mesh does not show (a point beyond it, the valence of a boundary vertex)."""


def is_zero(e: sp.Expr | int) -> bool:
    """Whether an exact algebraic number is zero (its minimal polynomial is ``x``; a clear nonzero value is decided numerically first)."""
    e = sp.sympify(e, strict=True)
    assert isinstance(e, sp.Expr)
    if e.is_Rational:
        return bool(e == 0)
    if abs(complex(e.evalf(30))) > 1e-20:
        return False
    return bool(sp.minimal_polynomial(e, _X) == _X)


def same_row(a: Row, b: Row) -> bool:
    """Whether two rows are the same exact combination."""
    return all(is_zero(a.get(v, 0) - b.get(v, 0)) for v in set(a) | set(b))


def point_key(mesh: HalfedgeMesh, kind: str, h: int) -> PointKey:
    """The key of the new point of ``kind`` at halfedge ``h``: its origin, its edge, its face or its corner."""
    if kind == "vertex":
        return ("vertex", mesh.origin[h])
    if kind == "edge":
        return ("edge", min(h, mesh.twin[h]))
    if kind == "face":
        f = mesh.face[h]
        if f is None:
            raise _Unknown
        return ("face", f)
    return ("corner", h)


def _weight(term: Term, mesh: HalfedgeMesh, h: int, j: int) -> sp.Expr:
    symbols = term.symbols()
    at = {J: sp.Integer(j)}
    if N in symbols:
        n = mesh.valence(mesh.origin[h])
        if n is None:
            raise _Unknown
        at[N] = sp.Integer(n)
    if M in symbols:
        f = mesh.face[h]
        if f is None:
            raise _Unknown
        at[M] = sp.Integer(mesh.face_size(f))
    w = sp.sympify(term.weight.xreplace(at).doit(), strict=True)
    if w.free_symbols:
        raise InvalidSchemeError(f"a weight uses parameter {sorted(map(str, w.free_symbols))[0]!r}, which has no value")
    return w


def _family(mesh: HalfedgeMesh, h: int, over: str) -> tuple[int, ...]:
    if over == "one":
        return (h,)
    family = mesh.ring(h) if over == "ring" else (mesh.around_face(h) if mesh.face[h] is not None else None)
    if family is None:
        raise _Unknown
    return family


def _rule_row(mesh: HalfedgeMesh, h: int, rule: Rule, made: dict[PointKey, Row]) -> Row:
    row: Row = {}
    for term in rule.terms:
        for j, hj in enumerate(_family(mesh, h, term.over)):
            g = mesh.walk(hj, term.walk)
            if g is None:
                raise _Unknown
            w = _weight(term, mesh, h, j)
            if term.source == "old":
                row[mesh.origin[g]] = row.get(mesh.origin[g], 0) + w
                continue
            source = made.get(point_key(mesh, term.source, g))
            if source is None:
                raise _Unknown
            for v, x in source.items():
                row[v] = row.get(v, 0) + w * x
    return row


def _select(rules: KindRules, mesh: HalfedgeMesh, h: int, regular: int) -> Rule | None:
    """The first rule whose conditions hold at ``h``."""
    valences = (mesh.valence(mesh.origin[h]), mesh.valence(mesh.tip(h)))
    for rule in rules.rules:
        conditions = (rule.origin, rule.tip)
        if any(c != "any" and v is None for c, v in zip(conditions, valences)):
            raise _Unknown
        known = [v if c != "any" and v is not None else regular for c, v in zip(conditions, valences)]
        if rule.applies(known[0], known[1], regular=regular):
            return rule
    return None


def _anchors(mesh: HalfedgeMesh, key: PointKey) -> tuple[int, ...]:
    kind, x = key
    if kind == "vertex":
        ring = mesh.outgoing(x)
        if ring is None:
            raise _Unknown
        return ring
    if kind == "face":
        return mesh.face_halfedges[x]
    if kind == "edge":
        return (x, mesh.twin[x])
    return (x,)


def _clean(row: Row) -> Row:
    out = {}
    for v in sorted(row):
        w = sp.expand(row[v])
        if not is_zero(w):
            out[v] = w
    return out


def kind_row(mesh: HalfedgeMesh, rules: KindRules, key: PointKey, made: dict[PointKey, Row], *, regular: int) -> Row | None:
    """The row of the new point ``key`` (``(kind, vertex | halfedge | face)``) by ``rules``; ``None`` if not computable.

    ``made`` holds the rows of the new points made earlier in the step (by key); ``regular`` is the
    regular valence of the mesh (for the rules' conditions).
    """
    try:
        rows = []
        for h in _anchors(mesh, key):
            rule = _select(rules, mesh, h, regular)
            if rule is not None:  # an anchor where no rule applies is skipped, as an edge's other end is
                rows.append(_clean(_rule_row(mesh, h, rule, made)))
    except _Unknown:
        return None
    if not rows:
        where = "either end of an edge" if key[0] == "edge" else f"any anchor of a {key[0]}"
        raise InvalidSchemeError(f"no [{rules.kind}] rule applies at {where}")
    if key[0] == "edge":
        scale = sp.Integer(1) if rules.ends == "sum" else sp.Rational(1, len(rows))
        if rules.ends == "sum" and len(rows) != 2:
            raise InvalidSchemeError(f"[{rules.kind}] sums both ends of an edge, but a rule applies at only one")
        total: Row = {}
        for r in rows:
            for v, w in r.items():
                total[v] = total.get(v, 0) + scale * w
        return _clean(total)
    if any(not same_row(rows[0], r) for r in rows[1:]):
        raise InvalidSchemeError(f"the [{rules.kind}] rule is not rotation-invariant: at a {key[0]} its result depends on "
                                 f"the anchor halfedge")
    return rows[0]
