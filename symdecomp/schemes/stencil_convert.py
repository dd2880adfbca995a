"""Today's schemes as the zoo's stencils: a :class:`~symdecomp.schemes.scheme.Scheme` as a
:class:`~symdecomp.schemes.stencils.StencilScheme`, so that the one engine analyses Catmull-Clark and Loop too.

A :class:`~symdecomp.schemes.scheme.Scheme` gives its rules on the 1-ring of a vertex ``O``: the new ``a_i``
is ``center*O + sum_k a[k]*a_(i+k) + sum_k b[k]*b_(i+k)`` (Eq. 14), the new ``b_i`` likewise (Eq. 15), the new
``O`` is ``center*O + each_a*sum a_i + each_b*sum b_i`` (Eq. 16). On halfedges, with the anchor ``h_i`` leaving
``O`` towards ``a_i`` and ``h_(i+1) = twin(prev(h_i))`` (counter-clockwise, as in
:mod:`symdecomp.schemes.stencils`):

* ``O`` is the anchor's origin (the empty walk);
* ``a_(i+k)`` is the tip of ``h_(i+k)``: the walk to ``h_(i+k)`` (``prev twin`` ``k`` times, or ``twin next``
  ``-k`` times), then ``next``;
* ``b_(i+k)`` (between ``a_(i+k)`` and ``a_(i+k+1)``, in the face of ``h_(i+k)``): that walk, then ``next next``.

The edge rule is read from an end of valence other than the regular one (the first rule, ``origin =
"irregular"``) and between two regular vertices at the regular valence (the second, ``origin = tip =
"regular"``, the same point from either end, as today's model requires); both rules have the same terms,
their weights in ``n``, the valence of the anchor's origin. (Today's model takes, at an edge with two ends of
other valences, the end of larger valence; the zoo's ``ends = "average"`` averages them. A neighbourhood of one
extraordinary vertex has no such edge.) The face rule is read the same way from the face's corners, the vertex
rule at every vertex. The rules at sharp features (``[sharp]``) are not stencils of the zoo and are not
converted.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> cc = as_stencils(catmull_clark())
>>> cc.topology, cc.lattice, [k.kind for k in cc.kinds]
('primal', 'quad', ['vertex', 'edge', 'face'])
>>> [t.walk for t in cc.rules_of("face").rules[0].terms]
[(), ('next',), ('prev', 'twin', 'next'), ('next', 'next')]
"""

from __future__ import annotations

import sympy as sp

from symdecomp.errors import InvalidTypeError
from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule
from symdecomp.schemes.stencils import KindRules, Rule, StencilScheme, Term

__all__ = ["as_stencils", "ring_walk"]


def ring_walk(k: int) -> tuple[str, ...]:
    """The walk from the anchor ``h_i`` to ``h_(i+k)``, the ``k``-th outgoing halfedge of its origin counter-clockwise."""
    return ("prev", "twin") * k if k >= 0 else ("twin", "next") * (-k)


def _stencil_terms(rule: Stencil) -> tuple[Term, ...]:
    terms = [Term(sp.sympify(rule.center, strict=True))]
    terms += [Term(sp.sympify(w, strict=True), ring_walk(k) + ("next",)) for k, w in rule.a]
    terms += [Term(sp.sympify(w, strict=True), ring_walk(k) + ("next", "next")) for k, w in rule.b]
    return tuple(t for t in terms if t.weight != 0)


def _by_valence(kind: str, terms: tuple[Term, ...]) -> KindRules:
    return KindRules(kind, (Rule(terms, origin="irregular"), Rule(terms, origin="regular", tip="regular")))


def _vertex_terms(rule: VertexRule) -> tuple[Term, ...]:
    terms = (Term(sp.sympify(rule.center, strict=True)), Term(sp.sympify(rule.each_a, strict=True), ("next",), over="ring"),
             Term(sp.sympify(rule.each_b, strict=True), ("next", "next"), over="ring"))
    return tuple(t for t in terms if t.weight != 0)


def as_stencils(scheme: Scheme) -> StencilScheme:
    """``scheme`` (today's 1-ring rules, Eq. 14-16) as a primal :class:`~symdecomp.schemes.stencils.StencilScheme`."""
    if not isinstance(scheme, Scheme):
        raise InvalidTypeError(f"as_stencils takes a Scheme (catmull_clark(), loop(), load_scheme(...)), got {type(scheme).__name__}")
    kinds = [KindRules("vertex", (Rule(_vertex_terms(scheme.vertex_rule)),)), _by_valence("edge", _stencil_terms(scheme.edge_rule))]
    if scheme.face_rule is not None:
        kinds.append(_by_valence("face", _stencil_terms(scheme.face_rule)))
    return StencilScheme(scheme.name, scheme.lattice.name, "primal", tuple(kinds), 1, tuple(scheme.parameters),
                         f"{scheme.name}'s rules on the 1-ring (Eq. 14-16), as stencils", False)
