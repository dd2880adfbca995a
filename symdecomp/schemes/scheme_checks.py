"""The checks a :class:`~symdecomp.schemes.scheme.Scheme` passes once, when it is built: the door of every scheme.

A scheme reaches the toolkit only as a ``Scheme``, and a ``Scheme`` exists only once :func:`validate_scheme` has
passed it (its ``__post_init__`` calls it; ``dataclasses.replace`` and :meth:`~symdecomp.schemes.scheme.Scheme.substitute`
build a new one, which passes again). So the code that takes a scheme trusts it:
:func:`~symdecomp.schemes.scheme.check_scheme` at the API's entry points is a type test, O(1), and nothing checks
the rules again (the parts' types, the lattice and the rules it has, the expression budget, the parameters, the
sharp rules, the rules at the regular valence).

>>> from symdecomp.schemes.scheme import Scheme, catmull_clark
>>> cc = catmull_clark()
>>> Scheme("no face rule", cc.edge_rule, None, cc.vertex_rule)
Traceback (most recent call last):
...
symdecomp.errors.InvalidSchemeError: scheme 'no face rule': a quad scheme needs a face rule
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import sympy as sp

from symdecomp.errors import InvalidExpressionError, InvalidSchemeError, InvalidTypeError
from symdecomp.expressions import MAX_OFFSET, check_budget
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.sharp import SHARP_SYMBOLS, SharpRules
from symdecomp.symbols import Parameter
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import n as N
from symdecomp.validate import check_type

if TYPE_CHECKING:
    from symdecomp.schemes.scheme import Scheme

__all__ = ["validate_scheme"]


def validate_scheme(scheme: Scheme) -> None:
    """Check ``scheme`` (just built) and normalize it in place: the lattice from its name, user symbols as parameters.

    Raises :class:`~symdecomp.errors.InvalidTypeError` for parts of the wrong kind and
    :class:`~symdecomp.errors.InvalidSchemeError` for rules the toolkit cannot take, each naming the scheme.
    """
    _check_parts(scheme)
    if not scheme.name.strip() or not scheme.name.isprintable():  # a str: _check_parts
        # a name is shown in terminals and typeset in documents: one line of text, no control characters
        raise InvalidSchemeError(f"scheme name must be a non-empty line of printable text, got {scheme.name!r}")
    try:
        object.__setattr__(scheme, "lattice", lattice(scheme.lattice))
    except InvalidSchemeError as exc:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: {exc}") from None
    _check_rules_of_the_lattice(scheme)
    _within_budget(scheme)
    _to_parameters(scheme)
    scheme.sharp.check_edge_rule(scheme.edge_rule.center, f"scheme {scheme.name!r}")
    free = {s for w in scheme.weights() + scheme.sharp.weights() for s in w.free_symbols} - {N, *SHARP_SYMBOLS.values()}
    declared = set(scheme.parameters)
    if free - declared:
        object.__setattr__(scheme, "parameters", tuple(scheme.parameters) + tuple(sorted(free - declared, key=str)))
    offsets = tuple(k for rule in scheme.stencils() for k in rule.offsets()) + (0,)
    object.__setattr__(scheme, "_span", max(offsets) - min(offsets))
    # the whole-mesh model: every vertex of the regular valence uses these rules there, so they must be defined there
    _scheme_module()._check_defined(scheme, scheme.lattice.regular_valence,
                                    " (the regular valence: every vertex away from O uses the rules there)")


def _check_rules_of_the_lattice(scheme: Scheme) -> None:
    """The rules the lattice's 1-ring has: a face rule and ``b`` weights only with face neighbours ``b_i``."""
    lat = scheme.lattice
    needs_face = "face" in lat.stencil_sections
    if (scheme.face_rule is not None) != needs_face:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: a {lat} scheme " + ("needs a face rule" if needs_face else "has no face rule"))
    if "b" not in {name for name, _ in lat.one_ring_classes} and (scheme.edge_rule.b or scheme.vertex_rule.each_b != 0):
        raise InvalidSchemeError(f"scheme {scheme.name!r}: a {lat} 1-ring has no face neighbours b_i; give no b weights")


def _scheme_module():
    """:mod:`symdecomp.schemes.scheme`, which imports this module (its rule types are read when a scheme is checked)."""
    from symdecomp.schemes import scheme

    return scheme


def _check_parts(scheme: Scheme) -> None:
    """Refuse parts of the wrong kind (a dict for a rule, a number for the name) with :class:`InvalidTypeError`."""
    rules = _scheme_module()
    check_type(scheme.name, str, "scheme name")
    for part, kind in (("edge_rule", rules.Stencil), ("face_rule", (rules.Stencil, type(None))), ("vertex_rule", rules.VertexRule)):
        check_type(getattr(scheme, part), kind, f"scheme {scheme.name!r}: {part}", hint="see Stencil.from_weights, VertexRule.affine")
    if not isinstance(scheme.parameters, (tuple, list)) or not all(isinstance(p, sp.Symbol) for p in scheme.parameters):
        raise InvalidTypeError(f"scheme {scheme.name!r}: parameters must be a tuple of sympy symbols, got {scheme.parameters!r}")
    object.__setattr__(scheme, "parameters", tuple(scheme.parameters))
    check_type(scheme.sharp, SharpRules, f"scheme {scheme.name!r}: sharp", hint="see symdecomp.schemes.sharp.SharpRules")


def _within_budget(scheme: Scheme) -> None:
    """Refuse a scheme whose weights or offsets are beyond the expression budget (:data:`symdecomp.expressions.BUDGET`),
    before anything is computed with them: the API's door, for rules built without :meth:`Stencil.from_weights`."""
    for label, rule in zip(("edge rule", "face rule"), scheme.stencils()):
        wide = [k for k in rule.offsets() if abs(k) > MAX_OFFSET]
        if wide:
            raise InvalidSchemeError(
                f"scheme {scheme.name!r}: {label}: offset {wide[0]} is beyond the budget's {MAX_OFFSET} in magnitude (the "
                f"closed forms are Laurent polynomials in omega of degree 2*offset, and every valence below the stencil's "
                "width is refused)")
    try:
        for w in scheme.weights() + scheme.sharp.weights():
            check_budget(sp.sympify(w, strict=True), "weight")
    except InvalidExpressionError as exc:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: {exc}") from None


def _to_parameters(scheme: Scheme) -> None:
    """Move every user symbol of ``scheme`` into the users' namespace (:class:`~symdecomp.symbols.Parameter`).

    A weight given to the API may hold any sympy symbol, e.g. ``Symbol("c", real=True)``, which is the
    toolkit's ``c = cos(j pi/n)`` by sympy's equality; replaced by a parameter of the same name and
    assumptions it can no longer meet the toolkit's symbols. ``n`` stays the valence, and ``alpha``,
    ``beta`` stay the paper's vertex weights.
    """
    own = {N, ALPHA, BETA, *SHARP_SYMBOLS.values()}
    stray = {s for w in (*scheme.weights(), *scheme.sharp.weights(), *scheme.parameters) for s in w.free_symbols
             if s not in own and not isinstance(s, Parameter)}
    if not stray:
        return
    for s in sorted(stray, key=str):  # printed by sympy in every derivation: a name, never markup
        if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", s.name):
            raise InvalidSchemeError(f"scheme {scheme.name!r}: the parameter name {s.name!r} is not an identifier (letters, "
                                     "digits and _, starting with a letter)")
    move = {s: Parameter(s.name, **s.assumptions0) for s in stray}

    rules = _scheme_module()

    def stencil(rule):
        return rules.Stencil(rule.center.xreplace(move), tuple((k, w.xreplace(move)) for k, w in rule.a),
                       tuple((k, w.xreplace(move)) for k, w in rule.b))

    v = scheme.vertex_rule
    object.__setattr__(scheme, "edge_rule", stencil(scheme.edge_rule))
    if scheme.face_rule is not None:
        object.__setattr__(scheme, "face_rule", stencil(scheme.face_rule))
    object.__setattr__(scheme, "vertex_rule", rules.VertexRule(v.center.xreplace(move), v.each_a.xreplace(move),
                                                         v.each_b.xreplace(move)))
    object.__setattr__(scheme, "parameters", tuple(p.xreplace(move) for p in scheme.parameters))
    object.__setattr__(scheme, "sharp", scheme.sharp.xreplace(move))
