"""The computed outcome of a vertex whose level-0 neighbourhood is none of the kinds of :mod:`~symdecomp.analysis.mesh_kinds`.

OpenSubdiv's tags reach further than one step's rules, and each such vertex gets an :class:`Outcome`, the verdict's
subject:

* **off the surface**: a vertex all of whose faces are holes: tagged ``t hole``, or, under ``interpolateboundary
  none``, the faces of a boundary vertex with a boundary edge that is not tagged infinitely sharp (OpenSubdiv's
  ``TopologyRefinerFactory`` makes them holes: they are refined but are no part of the limit surface); a vertex in
  no face at all. It has no point on the limit surface, so no C1 verdict (``n/a``, with why). A vertex with only
  some of its faces holes keeps its kind: holes change no rule, only which faces are drawn.
* **transient**: a semi-sharp vertex tag, or sharp edges of different sharpness at the vertex. OpenSubdiv's decay
  (``Sdc::Crease``: ``SubdivideVertexSharpness`` and ``SubdivideEdgeSharpnessesAroundVertex``, uniform or Chaikin,
  :func:`~symdecomp.schemes.sharp.child_edge_sharpnesses`) is applied exactly at the vertex, level by level (the
  child edges at a vertex take their sharpness from the edges at that vertex only), until no semi-sharp tag is left:
  after :attr:`Outcome.levels` steps the vertex is of its :attr:`Outcome.eventual` kind (infinitely sharp tags only)
  and stays so. C1 and the curvature regime are properties of the limit at the vertex, which the rules from that level
  on decide: the verdicts are the eventual kind's.
* **spectrum**: a neighbourhood the sector model does not take (an interior vertex of valence 2; under ``edge-only``
  a boundary vertex of one face, where OpenSubdiv applies the crease rule): the exact 1-ring matrix from OpenSubdiv's
  rules (:func:`~symdecomp.schemes.tagged_refinement.sharp_stencils` on the vertex's fan, cut out of the mesh) and
  its exact eigenvalues decide what they can: ``not-c1`` when 1 is not a simple dominant eigenvalue, else
  ``undecided`` with the spectrum (no characteristic map test here for these fans).

>>> from fractions import Fraction
>>> decay([Fraction(5, 2), Fraction(1, 2), math.inf], Fraction(0), "uniform")
(3, [0, 0, inf], 0)
>>> decay([Fraction(3), Fraction(1)], Fraction(0), "chaikin")
(3, [0, 0], 0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

__all__ = ["Outcome", "decay", "off_surface", "transient", "transition_weights", "fan_outcome", "spectrum_verdict"]


@dataclass(frozen=True)
class Outcome:
    """A vertex's computed outcome (module docstring); one row of ``inspect``'s table per distinct outcome."""

    #: The row's label (``"crease k = 2,2 after 3 levels"``, ``"off the surface"``, ...).
    label: str
    #: The kind the vertex becomes after :attr:`levels` steps (transient), else ``None``.
    eventual: object = None
    #: Steps until the vertex's semi-sharp tags have decayed (transient), else 0.
    levels: int = 0
    #: The C1 verdict where there is no eventual kind (``"n/a"`` off the surface, ``"not-c1"``, ``"undecided"``).
    c1: str = ""
    #: Why: what made the vertex transient, or the computed reason of :attr:`c1`.
    reason: str = ""
    #: Whether the vertex has a point on the limit surface.
    on_surface: bool = True
    #: A fan judged by its spectrum: ``(faces, closed, edge sharpness, vertex sharpness, boundary interpolation)``.
    fan: tuple | None = None
    #: Transient: the fractional weights where its rule changes (:func:`transition_weights`; not part of the row).
    weights: tuple = field(default=(), compare=False)

    @property
    def no_limit(self) -> str:
        """Why the vertex has no limit point here (off the surface; else not computed for such a vertex)."""
        if not self.on_surface:
            return self.reason
        if self.eventual is not None:
            return (f"its tags change the rules for {self.levels} level{'s' * (self.levels != 1)}: its limit point is "
                    "not computed here (its verdicts are)")
        return "a fan judged by its spectrum: no limit masks here"


def off_surface(reason: str) -> Outcome:
    """A vertex with no point on the limit surface, with why."""
    return Outcome("off the surface", c1="n/a", reason=f"no point on the limit surface: {reason}", on_surface=False)


def decay(edges: list, vertex, method: str) -> tuple[int, list, object]:
    """OpenSubdiv's sharpness decay at a vertex, exactly, until no semi-sharp tag is left: ``(levels, edges, vertex)``.

    ``edges``: the sharpness of the edges at the vertex (``Fraction``, ``math.inf`` when infinitely sharp), ``vertex``
    its own; ``method``: ``"uniform"`` or ``"chaikin"``. Each level is ``SubdivideEdgeSharpnessesAroundVertex`` on the
    edges and ``SubdivideVertexSharpness`` on the vertex (module docstring).
    """
    from symdecomp.schemes.sharp import SharpOptions, child_edge_sharpnesses, decrement, is_infinite

    options = SharpOptions(crease_method=method)
    edges = [math.inf if is_infinite(s) else s for s in edges]
    vertex = math.inf if is_infinite(vertex) else vertex
    levels = 0
    while any(0 < s < math.inf for s in edges + [vertex]):
        edges, vertex, levels = child_edge_sharpnesses(edges, options), decrement(vertex), levels + 1
    return levels, [s if s == math.inf else 0 for s in edges], vertex if vertex == math.inf else 0


def transition_weights(edges: list, vertex, method: str) -> tuple:
    """The fractional weights of the levels where the vertex's rule changes on the way of :func:`decay` and the two
    rules are blended (OpenSubdiv's ``ComputeVertexVertexMask`` with ``ComputeFractionalWeightAtVertex``,
    :func:`~symdecomp.schemes.sharp.fractional_weight`), exactly."""
    from symdecomp.schemes.sharp import (
        SharpOptions,
        VertexRuleKind,
        child_edge_sharpnesses,
        decrement,
        fractional_weight,
        vertex_rule_kind,
    )

    options = SharpOptions(crease_method=method)
    smooth = (VertexRuleKind.SMOOTH, VertexRuleKind.DART)  # a smooth or dart parent takes the smooth mask, unblended
    out = []
    while any(0 < s < math.inf for s in list(edges) + [vertex]):
        child, child_vertex = child_edge_sharpnesses(edges, options), decrement(vertex)
        parent = vertex_rule_kind(vertex, edges)
        if parent not in smooth and parent is not vertex_rule_kind(child_vertex, child):
            out.append(fractional_weight(vertex, child_vertex, edges, child, options))
        edges, vertex = child, child_vertex
    return tuple(out)


def transient(eventual, levels: int, cause: str, weights: tuple = ()) -> Outcome:
    """A vertex that is of kind ``eventual`` after ``levels`` steps (module docstring); ``cause``: its level-0 tags;
    ``weights``: :func:`transition_weights`."""
    after = f"after {levels} level{'s' * (levels != 1)}"
    return Outcome(f"{eventual} {after}", eventual, levels,
                   reason=f"{cause}: {after} (OpenSubdiv's sharpness decay) the vertex is a {eventual} and stays so; the "
                   "verdicts are that kind's", weights=weights)


def _fan_mesh(lattice, faces: int, closed: bool):
    """The vertex's fan as a local mesh: ring ``0 = O, 1.. = a_i, then b_i`` (quads), faces ``(O, a_i, [b_i,] a_{i+1})``;
    and the fan's outer edges (cut: the mesh goes on there)."""
    quads = "b" in dict(lattice.one_ring_classes)
    edges = faces if closed else faces + 1
    a = [1 + (i % edges) for i in range(faces + 1)]
    rows = [(0, a[i]) + ((1 + edges + i,) if quads else ()) + (a[i + 1],) for i in range(faces)]
    outer = {frozenset(p) for f in rows for p in zip(f[1:], f[2:])}
    mesh = lattice.mesh(tuple(rows), {v: (v,) for f in rows for v in f})
    return mesh, frozenset(outer), edges


def fan_outcome(faces: int, closed: bool, edge_sharpness: list, vertex_sharpness, boundary: str) -> Outcome:
    """A fan the sector model does not take (module docstring), judged per scheme by :func:`spectrum_verdict`.
    ``edge_sharpness``: per edge ``(O, a_i)``; ``boundary``: the boundary interpolation."""
    where = f"{'interior vertex of valence' if closed else 'boundary vertex of'} {faces}{'' if closed else ' face' + 's' * (faces > 1)}"
    inner = edge_sharpness if closed else edge_sharpness[1:-1]  # a boundary fan's end edges are sharp anyway
    tags = [str(s) for s in inner if s > 0] + ([f"vertex {vertex_sharpness}"] if vertex_sharpness else [])
    label = f"{where}{', sharpness ' + ', '.join(tags) if tags else ''} (spectrum)"
    return Outcome(label, fan=(faces, closed, tuple(edge_sharpness), vertex_sharpness, boundary))


def spectrum_verdict(scheme, outcome: Outcome) -> tuple[str, str]:
    """The exact 1-ring matrix of ``outcome``'s fan under OpenSubdiv's rules and what its spectrum decides (module
    docstring): ``(verdict, reason)``."""
    import sympy as sp

    from symdecomp.algebra.numbers import to_sympy
    from symdecomp.errors import InvalidSchemeError, InvalidValenceError
    from symdecomp.schemes.sharp import SharpOptions
    from symdecomp.schemes.tagged_refinement import TaggedMesh, sharp_stencils

    faces, closed, edge_sharpness, vertex_sharpness, boundary = outcome.fan
    mesh, outer, edges = _fan_mesh(scheme.lattice, faces, closed)
    sharp = {frozenset((0, 1 + i)): s for i, s in enumerate(edge_sharpness) if s > 0 and (closed or 0 < i < edges - 1)}
    tagged = TaggedMesh(mesh, sharp, {0: vertex_sharpness} if vertex_sharpness else {}, outer)
    options = SharpOptions("edge-and-corner" if boundary == "edge-and-corner" else "edge-only")
    try:
        st = sharp_stencils(tagged, scheme, options)
    except (InvalidValenceError, InvalidSchemeError) as exc:  # a rule read at a valence the scheme does not define
        return "undecided", f"the 1-ring matrix of {outcome.label[:-len(' (spectrum)')]} is not built here: {exc}"
    stencils = [st.vertex[0]] + [st.edge[frozenset((0, 1 + i))] for i in range(edges)] + [st.face[i] for i in range(len(st.face))]
    size = len(stencils)
    matrix = sp.Matrix(size, size, lambda r, c: to_sympy(stencils[r].get(int(c), 0)))
    values = sorted(matrix.eigenvals().items(), key=lambda vm: -abs(complex(vm[0])))
    spectrum = ", ".join(f"{v}" + (" (twice)" if m == 2 else f" ({m} times)" if m > 2 else "") for v, m in values)
    head = f"the exact 1-ring matrix of {outcome.label[:-len(' (spectrum)')]} under OpenSubdiv's rules has the eigenvalues {spectrum}"
    if values[0][0] != 1 or values[0][1] != 1 or (len(values) > 1 and abs(complex(values[1][0])) >= 1):
        return "not-c1", f"{head}: 1 is not a simple dominant eigenvalue"
    return "undecided", f"{head}; the sector and Reif tests here take no such fan, so its characteristic map is not tested"
