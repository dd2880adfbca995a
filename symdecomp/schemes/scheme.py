"""A subdivision scheme as data: the stencils of its 1-ring rules (Eq. 14-16).

A scheme of the shape the paper studies moves the 1-ring of a valence-``n`` vertex ``O``
(edge neighbours ``a_i``, face neighbours ``b_i``, indices mod ``n``) by three affine rules:

* the edge rule, for the new ``a_i``: a weight on ``O`` and weights on ``a_{i+k}``, ``b_{i+k}``
  for a few offsets ``k``;
* the face rule, for the new ``b_i``: the same shape;
* the vertex rule, for the new ``O``: a weight on ``O`` and one weight shared by all ``a_i``
  and one shared by all ``b_i``.

Weights are sympy expressions: exact rationals, or expressions in the valence symbol
``symdecomp.symbols.n`` and in free parameters (such as ``alpha``, ``beta``). Every rule is
checked to be affine (its weights sum to 1, identically in ``n`` and the parameters) when
the scheme is built.

>>> cc = catmull_clark()
>>> cc.vertex_rule.center
1 - 7/(4*n)
>>> subdivision_matrix(cc, 4)[0, :]
Matrix([[9/16, 3/32, 3/32, 3/32, 3/32, 1/64, 1/64, 1/64, 1/64]])
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import flint
import sympy as sp

from symdecomp.errors import InvalidExpressionError, InvalidSchemeError, NotAffineError
from symdecomp.expressions import exact_value, identically_zero
from symdecomp.schemes.lattice import LATTICES, QUAD, Lattice, lattice
from symdecomp.schemes.scheme_checks import validate_scheme
from symdecomp.schemes.sharp import SharpRules, standard_sharp_rules
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import n as N
from symdecomp.validate import check_memory, check_type, check_valence, parameter_values

__all__ = [
    "Stencil",
    "VertexRule",
    "MESH_TYPES",
    "Scheme",
    "check_scheme",
    "catmull_clark",
    "subdivision_entries",
    "subdivision_matrix",
    "vertex_order",
]


#: Names a weight given as text may use: the valence and the vertex-rule weights of Eq. 16.
WEIGHT_SYMBOLS = {"n": N, "alpha": ALPHA, "beta": BETA}


def _sympify_weight(value, where: str) -> sp.Expr:
    """A weight as an exact expression (text is parsed, never evaluated; see :mod:`symdecomp.expressions`).

    A symbol named ``n`` is the valence, whatever its assumptions; other symbols are free parameters.
    """
    try:
        return exact_value(value, WEIGHT_SYMBOLS, argument=f"{where}: weight", other_symbols=True)
    except InvalidExpressionError as exc:
        raise InvalidSchemeError(str(exc)) from None


def _weights(mapping: Mapping[int, object], where: str) -> tuple[tuple[int, sp.Expr], ...]:
    out = []
    if not isinstance(mapping, Mapping):
        raise InvalidSchemeError(f"{where}: expected a mapping {{offset: weight}}, got {type(mapping).__name__}")
    keys = list(mapping)
    for k in keys:
        if isinstance(k, bool) or not isinstance(k, numbers.Integral):
            raise InvalidSchemeError(f"{where}: offset {k!r} is not an integer")
    for k, w in sorted((int(k), w) for k, w in mapping.items()):
        expr = _sympify_weight(w, f"{where}[{k}]")
        if expr != 0:
            out.append((k, expr))
    return tuple(out)


@dataclass(frozen=True)
class Stencil:
    """An affine rule for a new 1-ring point ``p_i`` (Eq. 14 or Eq. 15).

    ``p_i -> center*O + sum_k a[k]*a_{i+k} + sum_k b[k]*b_{i+k}``, indices mod ``n``.
    """

    #: Weight on the central vertex ``O``.
    center: sp.Expr
    #: Pairs ``(k, weight)``: the weight on ``a_{i+k}``, sorted by offset.
    a: tuple[tuple[int, sp.Expr], ...]
    #: Pairs ``(k, weight)``: the weight on ``b_{i+k}``, sorted by offset.
    b: tuple[tuple[int, sp.Expr], ...]

    @classmethod
    def from_weights(cls, center, a: Mapping[int, object], b: Mapping[int, object], *, name: str = "rule") -> Stencil:
        """Build a stencil and check that it is affine."""
        stencil = cls(_sympify_weight(center, f"{name}: center"), _weights(a, f"{name}: a"), _weights(b, f"{name}: b"))
        if not identically_zero(stencil.weight_sum() - 1):
            raise NotAffineError(
                f"{name} is not affine: its weights sum to {sp.cancel(stencil.weight_sum())}, not 1"
            )
        return stencil

    def weight_sum(self) -> sp.Expr:
        """The sum of all weights (1 for an affine rule)."""
        return self.center + sum((w for _, w in self.a), sp.Integer(0)) + sum((w for _, w in self.b), sp.Integer(0))

    def offsets(self) -> tuple[int, ...]:
        return tuple(sorted({k for k, _ in self.a} | {k for k, _ in self.b}))


@dataclass(frozen=True)
class VertexRule:
    """The rule for the new central vertex (Eq. 16, in affine form).

    ``O -> center*O + each_a * sum_i a_i + each_b * sum_i b_i``. Affine means
    ``center + n*each_a + n*each_b = 1`` identically.
    """

    #: Weight on ``O``.
    center: sp.Expr
    #: Weight on each edge neighbour ``a_i`` (the paper's ``alpha``).
    each_a: sp.Expr
    #: Weight on each face neighbour ``b_i`` (the paper's ``beta``).
    each_b: sp.Expr

    @classmethod
    def from_weights(cls, center, each_a, each_b, *, name: str = "vertex rule") -> VertexRule:
        rule = cls(
            _sympify_weight(center, f"{name}: center"),
            _sympify_weight(each_a, f"{name}: each_a"),
            _sympify_weight(each_b, f"{name}: each_b"),
        )
        if not identically_zero(rule.weight_sum() - 1):
            raise NotAffineError(
                f"{name} is not affine: center + n*each_a + n*each_b = {sp.cancel(rule.weight_sum())}, not 1"
            )
        return rule

    @classmethod
    def affine(cls, each_a, each_b, *, name: str = "vertex rule") -> VertexRule:
        """The affine vertex rule with the given weights: ``center = 1 - n*each_a - n*each_b``."""
        a = _sympify_weight(each_a, f"{name}: each_a")
        b = _sympify_weight(each_b, f"{name}: each_b")
        return cls.from_weights(sp.expand(1 - N * a - N * b), a, b, name=name)

    def weight_sum(self) -> sp.Expr:
        return self.center + N * self.each_a + N * self.each_b


#: The mesh types a scheme can live on (the names of the lattices).
MESH_TYPES = tuple(LATTICES)


@dataclass(frozen=True)
class Scheme:
    """A subdivision scheme on a quad or triangle mesh, given by its rules for the whole mesh.

    **The model** (one for every command): the edge rule makes every new edge point and the face rule
    every new face point, anywhere in the mesh; the vertex rule makes the new point of every vertex
    from that vertex's valence ``n``: at the extraordinary vertex ``O`` with its valence, and at every
    other vertex of a neighbourhood (all of the regular valence, 4 on quads, 6 on triangles) with
    ``n = 4`` or ``n = 6``. So the regular rules of the scheme are its rules at the regular valence;
    a scheme tuned at extraordinary vertices only keeps the standard weights at the regular valence
    (for instance a vertex weight that is a function of ``n`` equal to the standard one at ``n = 4``).
    The rules must be defined at the regular valence (checked here). **An edge rule in n** is read from the
    edge's extraordinary end ``O`` at its valence (of two, the larger valence), and at the regular valence
    (where it must give one point from either end) between regular vertices: the ``n`` edges at ``O`` use it at
    ``n``, as the 1-ring stencils say, every other edge the regular rule; every command reads it so
    (:mod:`symdecomp.schemes.refinement`). 1-ring commands read the rules at
    ``O``; K-ring matrices, evaluation and the C1 test read all of them; the C1 test and the evaluation
    know the regular patches of Catmull-Clark and Loop only, so they apply when the rules at the regular
    valence are those (they say so in one line otherwise).

    On a quad mesh (``lattice = QUAD``, the paper's shape) the 1-ring is ``(O, a_i, b_i)`` and
    the scheme has an edge, a face and a vertex rule. On a triangle mesh
    (``lattice = TRIANGLE``) the 1-ring is ``(O, a_0..a_{n-1})`` with faces ``(O, a_i, a_{i+1})``:
    there are no face neighbours, so ``face_rule`` is ``None``, the edge rule has no ``b``
    weights and the vertex rule's ``each_b`` is 0. The lattice may be given by its name
    (``lattice="triangle"``); :mod:`symdecomp.schemes.lattice`.
    """

    #: A short name, used in reports.
    name: str
    #: The rule for the new edge neighbours ``a_i`` (Eq. 14 for Catmull-Clark).
    edge_rule: Stencil
    #: The rule for the new face neighbours ``b_i`` (Eq. 15 for Catmull-Clark); ``None`` on triangles.
    face_rule: Stencil | None
    #: The rule for the new ``O`` (Eq. 16).
    vertex_rule: VertexRule
    #: Free parameters of the scheme (symbols other than ``n`` in its weights).
    parameters: tuple[sp.Symbol, ...] = field(default=())
    #: The lattice the scheme lives on: :data:`~symdecomp.schemes.lattice.QUAD` (the paper's shape)
    #: or :data:`~symdecomp.schemes.lattice.TRIANGLE` (e.g. Loop).
    lattice: Lattice = QUAD
    #: The rules at boundaries, creases and corners (:mod:`symdecomp.schemes.sharp`); the standard ones by default.
    sharp: SharpRules = field(default_factory=standard_sharp_rules)

    def __post_init__(self):
        # the door: every Scheme passes it once, when built, and the code that takes a Scheme trusts it
        validate_scheme(self)

    @property
    def mesh(self) -> str:
        """The lattice's name (``"quad"``, ``"triangle"``), as files, JSON and reports spell it."""
        return self.lattice.name

    def weights(self) -> tuple[sp.Expr, ...]:
        """Every weight of every rule: the stencils' (centre, ``a``, ``b``), then the vertex rule's."""
        v = self.vertex_rule
        return tuple(w for rule in self.stencils() for w in (rule.center, *(x for _, x in rule.a + rule.b))) + (
            v.center, v.each_a, v.each_b)

    def stencils(self) -> tuple[Stencil, ...]:
        """The 1-ring stencils: ``(edge rule, face rule)`` on quads, ``(edge rule,)`` on triangles."""
        return (self.edge_rule,) if self.face_rule is None else (self.edge_rule, self.face_rule)

    def ring_size(self, n: int) -> int:
        """Points of the 1-ring at valence ``n``: ``2n + 1`` on quads, ``n + 1`` on triangles."""
        return self.lattice.one_ring_size(n)

    def minimum_valence(self) -> int:
        """The smallest valence for which the stencil offsets are distinct mod ``n`` (at least 3)."""
        return max(3, self._span + 1)

    def fitting_valence(self, n, *, real: bool = False) -> int:
        """``n``, checked to be a valence at which the stencils fit and every weight is defined (else
        :class:`InvalidSchemeError`); with ``real``, every weight must also be real there (scheme files and the
        command line ask for real rules; in Python a scheme may have complex weights, e.g. to test a statement)."""
        n = check_valence(n)
        if n < self.minimum_valence():
            raise InvalidSchemeError(f"scheme {self.name!r} has stencils {self._span + 1} wide, wider than the valence n = {n}")
        _check_defined(self, n, real=real)
        return n

    def check_values_at(self, n: int, *, real: bool = False, note: str = "") -> None:
        """Refuse the valence ``n`` if a weight is undefined there (with ``real``: or not real); ``note`` ends the message."""
        _check_defined(self, check_valence(n), note, real=real)

    def substitute(self, values: Mapping[sp.Symbol, object], *, name: str | None = None) -> Scheme:
        """The scheme with some parameters replaced (e.g. tuned vertex weights)."""
        subs = parameter_values(self.parameters, values, owner=f"scheme {self.name!r}", symbols=WEIGHT_SYMBOLS,
                                require_all=False)

        def st(rule: Stencil, label: str) -> Stencil:
            return Stencil.from_weights(
                rule.center.subs(subs), {k: w.subs(subs) for k, w in rule.a}, {k: w.subs(subs) for k, w in rule.b}, name=label
            )

        v = self.vertex_rule
        return Scheme(
            name or self.name,
            st(self.edge_rule, "edge rule"),
            None if self.face_rule is None else st(self.face_rule, "face rule"),
            VertexRule.from_weights(v.center.subs(subs), v.each_a.subs(subs), v.each_b.subs(subs)),
            tuple(p for p in self.parameters if p not in subs),
            self.lattice,
            self.sharp.substitute(subs),
        )


def check_scheme(scheme, argument: str = "scheme") -> Scheme:
    """``scheme`` if it is a :class:`Scheme`, else :class:`~symdecomp.errors.InvalidTypeError` (the check of every
    public function that takes a scheme, run before any cache)."""
    return check_type(scheme, Scheme, argument, hint="catmull_clark(), loop(), load_scheme(NAME_OR_FILE)")


def catmull_clark(alpha=None, beta=None) -> Scheme:
    """Catmull-Clark on the 1-ring (Eq. 14-16), with the vertex-rule weights as parameters.

    With no arguments the standard weights ``alpha = 3/(2n^2)``, ``beta = 1/(4n^2)``; pass
    ``symdecomp.symbols.alpha, symdecomp.symbols.beta`` (or any expressions) to keep them free.
    The weight of ``O`` is ``1 - n*alpha - n*beta`` so that the rule is affine (Eq. 16 as printed
    has ``1 - alpha - beta``; see the claim "Eq. 16").

    >>> from symdecomp.symbols import alpha, beta
    >>> catmull_clark(alpha, beta).vertex_rule.center
    -alpha*n - beta*n + 1
    """
    if alpha is None and beta is None:
        return _standard_catmull_clark()
    return _catmull_clark(alpha, beta)


@lru_cache(maxsize=1)
def _standard_catmull_clark() -> Scheme:
    """The standard Catmull-Clark, built (and validated) once: the lattice's reference, the command line's name."""
    return _catmull_clark(None, None)


def _catmull_clark(alpha, beta) -> Scheme:
    standard = alpha is None and beta is None
    if alpha is None:
        alpha = sp.Rational(3, 2) / N**2
    if beta is None:
        beta = sp.Rational(1, 4) / N**2
    R = sp.Rational
    edge = Stencil.from_weights(R(3, 8), {-1: R(1, 16), 0: R(3, 8), 1: R(1, 16)}, {-1: R(1, 16), 0: R(1, 16)}, name="edge rule (Eq. 14)")
    face = Stencil.from_weights(R(1, 4), {0: R(1, 4), 1: R(1, 4)}, {0: R(1, 4)}, name="face rule (Eq. 15)")
    vertex = VertexRule.affine(alpha, beta, name="vertex rule (Eq. 16)")
    return Scheme("catmull-clark" if standard else "catmull-clark (tuned vertex rule)", edge, face, vertex)


def vertex_order(n: int, mesh: Lattice | str = QUAD) -> tuple[str, ...]:
    """Names of the rows/columns of the subdivision matrix: ``O, a_0..a_{n-1}, b_0..b_{n-1}``.

    On a triangle mesh (``mesh=TRIANGLE`` or ``"triangle"``) there are no ``b_i``.
    """
    return lattice(mesh).vertex_order(check_valence(n))


def subdivision_entries(scheme: Scheme, n: int, weight: Callable[[sp.Expr], Any]) -> dict[tuple[int, int], Any]:
    """The nonzero entries ``{(row, column): value}`` of the subdivision matrix at valence ``n``.

    The one assembly of the matrix from the rules (Eq. 14-16; Section 6), for any number type:
    ``weight`` turns a weight of a rule (a sympy expression in ``n`` and the parameters) into
    a number at this valence (a sympy expression for :func:`subdivision_matrix`, a FLINT
    rational for :mod:`symdecomp.schemes.full_matrix`). Rows and columns in the order
    ``(O, a_0..a_{n-1}, b_0..b_{n-1})``; ``O(n)`` entries, no circulant or block structure.
    Weights that land on the same entry (offsets equal mod ``n``) are added.
    """
    n = check_scheme(scheme).fitting_valence(n)
    entries: dict[tuple[int, int], Any] = {}

    def add(r: int, c: int, x) -> None:
        value = entries.get((r, c), 0) + x
        if value == 0:
            entries.pop((r, c), None)
        else:
            entries[(r, c)] = value

    v = scheme.vertex_rule
    add(0, 0, weight(v.center))
    each_a, each_b = weight(v.each_a), weight(v.each_b)
    for i in range(n):
        add(0, 1 + i, each_a)
        if scheme.face_rule is not None:
            add(0, 1 + n + i, each_b)
    for row_offset, rule in zip((1, 1 + n), scheme.stencils()):
        center = weight(rule.center)
        a = [(k, weight(x)) for k, x in rule.a]
        b = [(k, weight(x)) for k, x in rule.b]
        for i in range(n):
            r = row_offset + i
            add(r, 0, center)
            for k, x in a:
                add(r, 1 + (i + k) % n, x)
            for k, x in b:
                add(r, 1 + n + (i + k) % n, x)
    return entries



def _check_defined(scheme: Scheme, n: int, note: str = "", *, real: bool = False) -> None:
    """Refuse a valence at which a weight of the scheme is undefined (e.g. ``1/(n - 5)`` at ``n = 5``)."""
    for label, rule in zip(("edge rule", "face rule"), scheme.stencils()):
        for w in (rule.center, *(w for _, w in rule.a + rule.b)):
            _check_weight_at(w, n, f"{scheme.name!r} {label}", note, real)
    v = scheme.vertex_rule
    for w in (v.center, v.each_a, v.each_b):
        _check_weight_at(w, n, f"{scheme.name!r} vertex rule", note, real)


@lru_cache(maxsize=1024)
def _poles(weight: sp.Expr) -> frozenset | None:
    """The valences at which ``weight`` is undefined, when that is decided once for every ``n`` (else ``None``).

    A weight without radicals or ``I`` is real wherever it is defined (``cos``/``sin`` of rational multiples of
    ``pi`` included: their arguments have no pole at a valence, see :mod:`symdecomp.expressions`), and undefined
    exactly where its denominator, a polynomial in ``n`` alone, vanishes: at its positive integer roots, read off
    the linear factors of FLINT's factorization. Anything else is decided at each valence by substitution.
    """
    if (weight.has(sp.I, sp.Piecewise) or any(not p.exp.is_Integer for p in weight.atoms(sp.Pow))
            or any(not isinstance(f, (sp.cos, sp.sin)) for f in weight.atoms(sp.Function))):
        return None
    _, den = sp.fraction(sp.together(weight))
    if not den.free_symbols <= {N} or den.has(sp.Function) or not den.is_polynomial(N):
        return None
    poly = sp.Poly(den, N)
    scale = sp.ilcm(1, 1, *[sp.Rational(c).q for c in poly.all_coeffs()])
    integer = flint.fmpz_poly([int(c * scale) for c in reversed(poly.all_coeffs())])
    roots = set()
    for factor, _ in integer.factor()[1]:
        if factor.degree() == 1 and factor[0] % factor[1] == 0 and -factor[0] // factor[1] > 0:
            roots.add(int(-factor[0] // factor[1]))
    return frozenset(roots)


def _check_weight_at(weight: sp.Expr, n: int, where: str, note: str = "", real: bool = False) -> None:
    """Refuse a weight that is undefined (``zoo``, ``nan``) at the valence ``n``, or with ``real`` not real there."""
    poles = _poles(weight)
    if poles is not None:
        if n in poles:
            raise InvalidSchemeError(f"{where}: weight {weight} is undefined at valence n = {n}{note}")
        return
    value = weight.subs(N, n) if N in weight.free_symbols else weight
    if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise InvalidSchemeError(f"{where}: weight {weight} is undefined at valence n = {n}{note}")
    if real and (value.has(sp.I) or value.is_real is False):
        raise InvalidSchemeError(f"{where}: weight {weight} is not real at valence n = {n} (it is {value}){note}")


def subdivision_matrix(scheme: Scheme, n: int) -> sp.ImmutableMatrix:
    """The exact subdivision matrix of ``scheme`` at valence ``n``, in sympy: ``(2n+1)`` or ``(n+1)`` square.

    Rows and columns in the order ``(O, a_0..a_{n-1}, b_0..b_{n-1})`` (Section 6; no ``b_i`` on a
    triangle mesh), assembled by :func:`subdivision_entries`, without any circulant structure.
    """
    n = check_valence(n)
    size = check_scheme(scheme).ring_size(n)
    check_memory(size * size * 64, f"the sympy {size} x {size} subdivision matrix")
    entries = subdivision_entries(scheme, n, lambda w: w.subs(N, n))
    return sp.ImmutableMatrix(size, size, lambda r, c: entries.get((r, c), sp.Integer(0)))
