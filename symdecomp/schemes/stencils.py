"""A scheme as stencils of any support: the one model of every scheme of the zoo.

A step of a subdivision scheme has a *topology* (how the new mesh is made from the old one:
a fact of the topology's own object, :mod:`symdecomp.schemes.topology`) and *rules* (how each
new point is made from old points, and from new points made earlier in the same step). This
module is the rules' data; it knows no lattice and no topology beyond their names.

Points are addressed by *walks* on the halfedges of the old mesh, so that a stencil may reach
as many rings as the scheme needs and means the same thing next to an extraordinary element as
in the regular lattice. A walk starts at the rule's *anchor* halfedge and applies moves:

* ``"next"``: the next halfedge of the same face (faces are counter-clockwise);
* ``"prev"``: the previous halfedge of the same face;
* ``"twin"``: the opposite halfedge (the same edge in the neighbouring face).

The point a walk names is the *origin* (tail) of the halfedge it ends on; ``("next",)`` names
the anchor's tip. The anchor of each kind of new point is:

* ``vertex`` (a new point per old vertex): an outgoing halfedge of the vertex;
* ``edge`` (per old edge): the edge's halfedge ``h``, and again ``twin(h)`` (see :attr:`KindRules.ends`);
* ``face`` (per old face): a halfedge of the face;
* ``corner`` (per corner of an old face, dual schemes): the face's halfedge leaving the corner.

A :class:`Term` is one point (``over="one"``) or a family of points indexed by ``j``:

* ``over="ring"``: ``j = 0..n-1`` over the outgoing halfedges of the anchor's origin, counter-
  clockwise from the anchor (``h_0 = h``, ``h_(j+1) = twin(prev(h_j))``), ``n`` that vertex's valence;
* ``over="face"``: ``j = 0..m-1`` over the halfedges of the anchor's face (``h_j = next^j(h)``),
  ``m`` the face's number of sides.

The walk is applied to ``h_j``. A weight is an exact sympy expression in :data:`N` (the valence of
the anchor's origin), :data:`M` (the size of the anchor's face), :data:`J` (the index of an ``over``
family) and the scheme's declared parameters; ``cos``/``sin`` of rational multiples of ``pi`` and
``KroneckerDelta`` are allowed (Doo-Sabin's weights are ``(3 + 2 cos(2 pi j/m))/(4 m)``).

A term's :attr:`~Term.source` says which point the walk names: the ``old`` vertex, or the new
point of kind ``vertex``/``edge``/``face`` at the walked halfedge's origin, edge or face (Kobbelt's
face points are the four-point rule applied to new edge points); a kind may only use kinds made
before it (:attr:`StencilScheme.kinds` is in the order of computation).

Which rule of a kind applies is decided by the valences at the anchor: the first :class:`Rule`
whose :attr:`~Rule.origin` and :attr:`~Rule.tip` conditions hold (``"any"``, ``"regular"``,
``"irregular"`` or a valence). A scheme of several steps that return the lattice to itself
(Kobbelt's sqrt(3): the lattice turns by half a sector and comes back after two) is analysed over
:attr:`StencilScheme.steps` steps, and says so.

>>> import sympy as sp
>>> corner = Term(weight=sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> corner.symbols() == {J, M}
True
>>> Rule((Term(sp.Rational(1, 2)), Term(sp.Rational(1, 2), ("next",)))).applies(6, 5, regular=6)
True
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from symdecomp.errors import InvalidSchemeError

__all__ = ["MOVES", "OVERS", "SOURCES", "KINDS", "CONDITIONS", "N", "M", "J", "Term", "Rule", "KindRules",
           "StencilScheme"]

#: The moves of a walk on halfedges.
MOVES = ("next", "prev", "twin")
#: A term's family: one point, the ring of the anchor's origin, the corners of the anchor's face.
OVERS = ("one", "ring", "face")
#: Kinds of new points a rule may make.
KINDS = ("vertex", "edge", "face", "corner")
#: What a walk names: the old vertex, or a new point of a kind made earlier in the step.
SOURCES = ("old",) + KINDS[:3]
#: The conditions a rule may put on the anchor's origin and tip (besides a valence, an integer >= 3).
CONDITIONS = ("any", "regular", "irregular")
#: How the two orientations of an edge combine.
ENDS = ("average", "sum")

#: The valence of the anchor's origin, in a weight.
N = sp.Symbol("n", positive=True, integer=True)
#: The number of sides of the anchor's face, in a weight.
M = sp.Symbol("m", positive=True, integer=True)
#: The index of a term's family (``over`` ring or face), in a weight.
J = sp.Symbol("j", nonnegative=True, integer=True)


def _condition(value, what: str) -> str | int:
    if isinstance(value, bool) or not (value in CONDITIONS or (isinstance(value, int) and 3 <= value <= 64)):
        raise InvalidSchemeError(f"{what} must be one of {', '.join(CONDITIONS)} or a valence 3..64, got {value!r:.40}")
    return value


@dataclass(frozen=True)
class Term:
    """A weight on one point named by a walk, or on each point of a family indexed by ``j``."""

    weight: sp.Expr
    walk: tuple[str, ...] = ()
    over: str = "one"
    source: str = "old"

    def __post_init__(self):
        bad = [m for m in self.walk if m not in MOVES]
        if bad:
            raise InvalidSchemeError(f"walk: unknown move {bad[0]!r:.20} (known: {', '.join(MOVES)})")
        if self.over not in OVERS:
            raise InvalidSchemeError(f"over must be one of {', '.join(OVERS)}, got {self.over!r:.20}")
        if self.source not in SOURCES:
            raise InvalidSchemeError(f"source must be one of {', '.join(SOURCES)}, got {self.source!r:.20}")
        if not isinstance(self.weight, sp.Expr):
            raise InvalidSchemeError(f"a weight must be a sympy expression, got {type(self.weight).__name__}")

    def symbols(self) -> set:
        """The symbols its weight uses."""
        return set(self.weight.free_symbols)


@dataclass(frozen=True)
class Rule:
    """The terms of one new point, and when they apply (conditions on the valences at the anchor)."""

    terms: tuple[Term, ...]
    origin: str | int = "any"
    tip: str | int = "any"

    def __post_init__(self):
        if not self.terms:
            raise InvalidSchemeError("a rule needs at least one term")
        _condition(self.origin, "origin")
        _condition(self.tip, "tip")

    def applies(self, origin_valence: int, tip_valence: int, *, regular: int) -> bool:
        """Whether the rule applies at an anchor whose origin and tip have these valences."""
        return all(_holds(c, v, regular) for c, v in ((self.origin, origin_valence), (self.tip, tip_valence)))


def _holds(condition, valence: int, regular: int) -> bool:
    if condition == "any":
        return True
    if condition == "regular":
        return valence == regular
    if condition == "irregular":
        return valence != regular
    return valence == condition


@dataclass(frozen=True)
class KindRules:
    """The rules that make one kind of new point, tried in order (the first that applies is used).

    For ``edge`` points the rule is applied at both orientations of the edge: ``ends="average"``
    averages the orientations at which a rule applies (the butterfly's rules: the regular stencil from
    both ends, the extraordinary one from the extraordinary end, both when both are); ``ends="sum"``
    adds the two halves (Kobbelt's four-point rule: each end contributes its half, a virtual point at
    an extraordinary end).
    """

    kind: str
    rules: tuple[Rule, ...]
    ends: str = "average"

    def __post_init__(self):
        if self.kind not in KINDS:
            raise InvalidSchemeError(f"unknown kind of new point {self.kind!r:.20} (known: {', '.join(KINDS)})")
        if not self.rules:
            raise InvalidSchemeError(f"[{self.kind}] needs at least one rule")
        if self.ends not in ENDS:
            raise InvalidSchemeError(f"ends must be one of {', '.join(ENDS)}, got {self.ends!r:.20}")


@dataclass(frozen=True)
class StencilScheme:
    """A scheme of the zoo: a lattice and a topology by name, and the rules of each kind of new point."""

    name: str
    #: The lattice's name (``"quad"``, ``"triangle"``).
    lattice: str
    #: The topology's name (``"primal"``, ``"dual"``, ``"sqrt3"``): how a step makes the new mesh.
    topology: str
    #: The rules, in the order their kinds are computed.
    kinds: tuple[KindRules, ...]
    #: The number of steps that return the lattice to itself; the analysis is of that many steps.
    steps: int = 1
    #: Free parameters the weights may use (besides ``n``, ``m``, ``j``).
    parameters: tuple[sp.Symbol, ...] = ()
    #: Where the weights come from (a publication), as printed in reports.
    source: str = ""
    #: Whether the scheme keeps the old vertices (interpolatory).
    interpolatory: bool = field(default=False)

    def __post_init__(self):
        if self.steps not in (1, 2):
            raise InvalidSchemeError(f"steps must be 1 or 2, got {self.steps!r:.20}")
        seen: list[str] = []
        for k in self.kinds:
            if k.kind in seen:
                raise InvalidSchemeError(f"[{k.kind}] is given twice")
            for rule in k.rules:
                for t in rule.terms:
                    if t.source != "old" and t.source not in seen:
                        raise InvalidSchemeError(f"[{k.kind}]: a term uses new {t.source} points, which are not made "
                                                 f"before it (the order: {', '.join(x.kind for x in self.kinds)})")
            seen.append(k.kind)
        allowed = {N, M, J, *self.parameters}
        for k in self.kinds:
            for rule in k.rules:
                for t in rule.terms:
                    extra = t.symbols() - allowed
                    if extra:
                        raise InvalidSchemeError(f"[{k.kind}]: a weight uses undeclared symbol {sorted(map(str, extra))[0]!r}")

    @property
    def own_valences(self) -> tuple[int, ...]:
        """The valences some rule names (``origin = 3``): where the scheme has rules of their own, in order."""
        return tuple(sorted({c for k in self.kinds for rule in k.rules for c in (rule.origin, rule.tip) if isinstance(c, int)}))

    def rules_of(self, kind: str) -> KindRules:
        """The rules of one kind of new point; an error naming the kind if the scheme has none."""
        for k in self.kinds:
            if k.kind == kind:
                return k
        raise InvalidSchemeError(f"scheme {self.name!r} has no [{kind}] rules (it has {', '.join(k.kind for k in self.kinds)})")
