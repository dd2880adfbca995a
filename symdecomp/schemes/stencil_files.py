"""The zoo's scheme files: a :class:`~symdecomp.schemes.stencils.StencilScheme` written in TOML, and read back.

This docstring is the one description of the format of the zoo's scheme files (the documentation's page
on it is this text; ``tests/schemes/test_stencil_files.py`` reads its example with the parser). A file
with a ``topology`` key is such a file (:func:`symdecomp.schemes.files.load_scheme` reads it; without the
key, a file is of today's format, :mod:`symdecomp.schemes.files`). The four families ship as files
(:data:`ZOO_FILES`: ``doo-sabin``, ``midedge``, ``sqrt3``, ``modified-butterfly``; loaded by name), and
another family is one more such file, its name at the end of :data:`ZOO_FILES` (the guide page
``docs/guide/adding-a-scheme.md``). Doo and Sabin's scheme::

    name = "doo-sabin"
    mesh = "quad"            # the lattice of the regular part
    topology = "dual"        # how a step makes the new mesh: primal, dual or sqrt3
    steps = 1                # steps that return the lattice to itself (2 for sqrt3)
    source = "D. Doo and M. Sabin, 1978, Behaviour of recursive division surfaces near extraordinary points"
    interpolatory = false

    [[corner]]               # a new point per corner of an old face, anchored at the face's halfedge leaving it
    terms = [{walk = "", weight = "KroneckerDelta(j, 0)/4 + (3 + 2*cos(2*pi*j/m))/(4*m)", over = "face"}]

**Top-level keys.** ``name`` (one line of printable text, at most 100 characters; default: the file's
name), ``mesh`` (a lattice's name, ``"quad"`` or ``"triangle"``), ``topology`` (``"primal"``, ``"dual"``,
``"sqrt3"``), ``steps`` (1 or 2, default 1), ``parameters`` (names the weights may use besides ``n``,
``m``, ``j``, as in today's files; ``m`` is reserved too), ``source`` (the publication, as printed in
reports), ``interpolatory`` (default false; when true, every ``[[vertex]]`` rule must keep the old vertex:
one term, weight 1, on the empty walk). Then, per kind of new point (``vertex``, ``edge``, ``face``,
``corner``), an array of tables, one per rule, in the order the kinds are computed (a kind may use new
points of a kind written above it).

**A rule** (``[[edge]]``): ``origin`` and ``tip``, the conditions on the valences at the anchor (``"any"``,
the default, ``"regular"``, ``"irregular"`` or a valence 3..64; the first rule of the kind whose conditions
hold is used), ``terms`` (an array of inline tables) and, for ``[[edge]]`` only, ``ends``: how the two
orientations of an edge combine, ``"average"`` (the default) or ``"sum"``, the same in every ``[[edge]]``
table that gives it. **A term**: ``walk``, the moves ``next``, ``prev``, ``twin`` separated by spaces, from
the anchor halfedge (``""`` names the anchor's origin, ``"next"`` its tip); ``weight``, an exact weight
(an integer or a string read by :func:`symdecomp.expressions.parse_expression`, within the expression
budget, never evaluated: rationals, ``n`` the valence of the anchor's origin, ``m`` the size of its face,
``j`` the index of the family, the parameters, ``pi``, ``sqrt``, ``cos``/``sin`` of rational multiples of
``pi`` such as ``cos(2*pi*j/m)``, and ``KroneckerDelta(j, 0)``); ``over``, ``"one"`` (the default), ``"ring"``
(``j = 0..n-1`` over the outgoing halfedges of the anchor's origin, counter-clockwise from the anchor) or
``"face"`` (``j = 0..m-1`` over the halfedges of the anchor's face); ``source``, ``"old"`` (the default)
or a kind of new point made earlier in the step. The walks and families are those of
:mod:`symdecomp.schemes.stencils`.

**Affinity is checked where the scheme is built** (:mod:`symdecomp.schemes.stencil_affinity`): each rule's
weights sum to 1 at every valence and face size it can apply to, as an identity in ``n`` and ``m`` when the
sum has a closed form (Doo-Sabin's: a trigonometric polynomial in ``j``), exactly at each size 3..64
otherwise; a rule with ``origin`` a valence is checked at that valence, ``"regular"`` at the lattice's.

**Errors.** Every problem is one :class:`~symdecomp.errors.InvalidSchemeError` (or
:class:`~symdecomp.errors.NotAffineError`) naming the file, the rule (numbered from 1) and the key; on
the command line it is one line and exit status 2:

>>> text = 'mesh = "quad"\\ntopology = "primal"\\n[[edge]]\\nterms = [{walk = "nxt", weight = "1"}]'
>>> stencil_scheme_from_text(text, source="s.toml")
Traceback (most recent call last):
...
symdecomp.errors.InvalidSchemeError: s.toml: [[edge]] 1: terms 1: walk: unknown move 'nxt' (known: next, prev, twin)

**Round trip**: :func:`stencil_scheme_to_text` writes a scheme that :func:`stencil_scheme_from_text` reads
back to an equal scheme.
"""

from __future__ import annotations

import json
import tomllib
from importlib import resources
from typing import Any

import sympy as sp

from symdecomp.errors import InvalidExpressionError, InvalidSchemeError, InvalidTypeError, NotAffineError
from symdecomp.expressions import parse_expression
from symdecomp.schemes.lattice import LATTICES, Lattice
from symdecomp.schemes.stencil_affinity import CHECKED_SIZES, check_affine
from symdecomp.schemes.stencils import CONDITIONS, ENDS, KINDS, MOVES, OVERS, SOURCES, J, KindRules, M, N, Rule, StencilScheme, Term

__all__ = ["TOPOLOGIES", "ZOO_FILES", "load_zoo", "stencil_scheme_from_text", "stencil_scheme_to_text", "is_stencil_text"]

#: The topologies a file may name (the steps that make a new mesh; :mod:`symdecomp.schemes.stencils`).
TOPOLOGIES = ("primal", "dual", "sqrt3")

#: The zoo's families shipped with the package (``symdecomp/schemes/zoo/``), loaded by name.
ZOO_FILES = {name: f"zoo/{name}.toml" for name in ("doo-sabin", "midedge", "sqrt3", "modified-butterfly")}

_TOP_KEYS = ("name", "mesh", "topology", "steps", "parameters", "source", "interpolatory")
_RULE_KEYS = ("origin", "tip", "terms", "ends")
_TERM_KEYS = ("walk", "weight", "over", "source")


def is_stencil_text(text: str) -> bool:
    """Whether the text of a scheme file is of the zoo's format (it has a top-level ``topology`` key)."""
    try:
        return "topology" in tomllib.loads(text)
    except (tomllib.TOMLDecodeError, RecursionError):
        return False  # today's reader reports it


def load_zoo(name: str) -> StencilScheme:
    """A family of the zoo by name (:data:`ZOO_FILES`)."""
    if name not in ZOO_FILES:
        raise InvalidSchemeError(f"unknown family of the zoo {name!r:.40} (known: {', '.join(ZOO_FILES)})")
    text = resources.files("symdecomp.schemes").joinpath(ZOO_FILES[name]).read_text(encoding="utf-8")
    return stencil_scheme_from_text(text, source=ZOO_FILES[name], default_name=name)


def stencil_scheme_from_text(text: str, *, source: str = "<scheme>", default_name: str = "scheme") -> StencilScheme:
    """Build a :class:`~symdecomp.schemes.stencils.StencilScheme` from the text of a zoo scheme file."""
    if not isinstance(text, str):
        raise InvalidTypeError(f"stencil_scheme_from_text takes the text of a scheme file, got {type(text).__name__}")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InvalidSchemeError(f"{source}: not valid TOML ({exc})") from None
    except RecursionError:
        raise InvalidSchemeError(f"{source}: arrays or tables nested too deeply; a scheme file is a few flat tables") from None
    try:
        return _scheme(data, default_name)
    except (InvalidSchemeError, NotAffineError) as exc:
        raise type(exc)(f"{source}: {exc}") from None


def _scheme(data: dict[str, Any], default_name: str) -> StencilScheme:
    unknown = [k for k in data if k not in _TOP_KEYS and k not in KINDS]
    if unknown:
        raise InvalidSchemeError(f"unknown key {unknown[0]!r:.40} (known: {', '.join(_TOP_KEYS + KINDS)})")
    name = data.get("name", default_name)
    if not isinstance(name, str) or not name.strip() or len(name) > 100 or not name.isprintable():
        raise InvalidSchemeError("name must be a non-empty string of at most 100 printable characters")
    lattice = _choice(data, "mesh", tuple(LATTICES), None)
    topology = _choice(data, "topology", TOPOLOGIES, None)
    steps = data.get("steps", 1)
    if isinstance(steps, bool) or steps not in (1, 2):
        raise InvalidSchemeError(f"steps must be 1 or 2, got {steps!r:.20}")
    interpolatory = data.get("interpolatory", False)
    if not isinstance(interpolatory, bool):
        raise InvalidSchemeError(f"interpolatory must be true or false, got {interpolatory!r:.20}")
    source_text = data.get("source", "")
    if not isinstance(source_text, str) or len(source_text) > 300 or not source_text.isprintable():
        raise InvalidSchemeError("source must be one line of printable text (at most 300 characters)")
    symbols = _symbols(data.get("parameters", []))
    kinds = tuple(_kind(kind, data[kind], symbols, LATTICES[lattice]) for kind in data if kind in KINDS)
    if not kinds:
        raise InvalidSchemeError(f"no rules: give at least one of {', '.join(f'[[{k}]]' for k in KINDS)}")
    parameters = tuple(s for key, s in symbols.items() if key not in ("n", "m", "j"))
    scheme = StencilScheme(name.strip(), lattice, topology, kinds, steps, parameters, source_text, interpolatory)
    if interpolatory:
        _check_interpolatory(scheme)
    return scheme


def _choice(data: dict[str, Any], key: str, known: tuple[str, ...], default: str | None) -> str:
    value = data.get(key, default)
    if value is None:
        raise InvalidSchemeError(f"missing key {key!r} (one of {', '.join(known)})")
    if not isinstance(value, str) or value not in known:
        raise InvalidSchemeError(f"{key} {value!r:.40} is not supported (known: {', '.join(known)})")
    return value


def _symbols(value: object) -> dict[str, sp.Symbol]:
    from symdecomp.schemes.files import _parameters  # today's format's one reading of parameter names

    if isinstance(value, list) and "m" in value:
        raise InvalidSchemeError("parameters: 'm' is reserved (the size of the anchor's face)")
    try:
        symbols = _parameters(value, "<scheme>")
    except InvalidSchemeError as exc:
        raise InvalidSchemeError(str(exc).removeprefix("<scheme>: ")) from None
    return {**symbols, "n": N, "m": M, "j": J}


def _kind(kind: str, tables: object, symbols: dict[str, sp.Symbol], lattice: Lattice) -> KindRules:
    if not isinstance(tables, list) or not tables or not all(isinstance(t, dict) for t in tables):
        raise InvalidSchemeError(f"{kind} must be an array of tables [[{kind}]], one per rule")
    rules, ends = [], set()
    for number, table in enumerate(tables, 1):
        where = f"[[{kind}]] {number}"
        unknown = [k for k in table if k not in _RULE_KEYS]
        if unknown:
            raise InvalidSchemeError(f"{where}: unknown key {unknown[0]!r:.40} (known: {', '.join(_RULE_KEYS)})")
        if "ends" in table:
            if kind != "edge":
                raise InvalidSchemeError(f"{where}: ends: only [[edge]] rules have two ends")
            if table["ends"] not in ENDS:
                raise InvalidSchemeError(f"{where}: ends must be one of {', '.join(ENDS)}, got {table['ends']!r:.20}")
            ends.add(table["ends"])
        rule = _rule(table, where, symbols)
        check_affine(rule, where=where, valences=_valences(rule.origin, lattice), face_sizes=_face_sizes(lattice))
        rules.append(rule)
    if len(ends) > 1:
        raise InvalidSchemeError(f"[[{kind}]]: ends is given as both {' and '.join(sorted(ends))}; one kind has one way")
    return KindRules(kind, tuple(rules), ends.pop() if ends else "average")


def _valences(condition: str | int, lattice: Lattice) -> list[int]:
    """The valences of the anchor's origin a rule can meet, its usual one first."""
    if isinstance(condition, int):
        return [condition]
    regular = lattice.regular_valence
    if condition == "regular":
        return [regular]
    others = [n for n in CHECKED_SIZES if n != regular]
    return others if condition == "irregular" else [regular] + others


def _face_sizes(lattice: Lattice) -> list[int]:
    """The sizes of the anchor's face a rule can meet (the lattice's first; an n-gon at a dual scheme's centre)."""
    usual = len(lattice.cell_faces(0, 1, 2, 3)[0])
    return [usual] + [m for m in CHECKED_SIZES if m != usual]


def _rule(table: dict[str, Any], where: str, symbols: dict[str, sp.Symbol]) -> Rule:
    conditions = {}
    for key in ("origin", "tip"):
        value = table.get(key, "any")
        if isinstance(value, bool) or not (value in CONDITIONS or (isinstance(value, int) and 3 <= value <= 64)):
            raise InvalidSchemeError(f"{where}: {key} must be one of {', '.join(CONDITIONS)} or a valence 3..64, got {value!r:.40}")
        conditions[key] = value
    terms = table.get("terms")
    if not isinstance(terms, list) or not terms:
        raise InvalidSchemeError(f"{where}: terms must be a non-empty array of inline tables such as "
                                 '[{walk = "next", weight = "1/2"}]')
    return Rule(tuple(_term(t, f"{where}: terms {i}", symbols) for i, t in enumerate(terms, 1)), **conditions)


def _term(table: object, where: str, symbols: dict[str, sp.Symbol]) -> Term:
    if not isinstance(table, dict):
        raise InvalidSchemeError(f"{where}: a term is an inline table such as {{walk = \"next\", weight = \"1/2\"}}")
    unknown = [k for k in table if k not in _TERM_KEYS]
    if unknown:
        raise InvalidSchemeError(f"{where}: unknown key {unknown[0]!r:.40} (known: {', '.join(_TERM_KEYS)})")
    walk = table.get("walk", "")
    if not isinstance(walk, str):
        raise InvalidSchemeError(f"{where}: walk must be a string of moves such as \"next twin\", got {walk!r:.40}")
    moves = tuple(walk.split())
    bad = [m for m in moves if m not in MOVES]
    if bad:
        raise InvalidSchemeError(f"{where}: walk: unknown move {bad[0]!r:.20} (known: {', '.join(MOVES)})")
    over, source = table.get("over", "one"), table.get("source", "old")
    if over not in OVERS:
        raise InvalidSchemeError(f"{where}: over must be one of {', '.join(OVERS)}, got {over!r:.20}")
    if source not in SOURCES:
        raise InvalidSchemeError(f"{where}: source must be one of {', '.join(SOURCES)}, got {source!r:.20}")
    if "weight" not in table:
        raise InvalidSchemeError(f"{where}: weight is missing")
    weight = _weight(table["weight"], f"{where}: weight", symbols)
    if over == "one" and weight.has(J):
        raise InvalidSchemeError(f"{where}: weight uses j, but the term is over one point (give over = \"ring\" or \"face\")")
    return Term(weight, moves, over, source)


def _weight(value: object, where: str, symbols: dict[str, sp.Symbol]) -> sp.Expr:
    if isinstance(value, bool):
        raise InvalidSchemeError(f"{where}: {value!r} is a boolean, not a weight")
    if isinstance(value, float):
        raise InvalidSchemeError(f"{where}: {value!r} is a float; give an exact rational such as \"3/8\"")
    if isinstance(value, int):
        value = str(value)
    if not isinstance(value, str):
        raise InvalidSchemeError(f"{where}: expected a weight such as \"3/8\", got a {type(value).__name__}")
    try:
        expr = parse_expression(value, symbols, argument="weight", kronecker=True)
    except InvalidExpressionError as exc:
        raise InvalidSchemeError(f"{where}: {exc}") from None
    if expr.has(sp.I) or expr.is_real is False:
        raise InvalidSchemeError(f"{where}: {value!r:.60} is not real")
    return expr


def _check_interpolatory(scheme: StencilScheme) -> None:
    kept = Rule((Term(sp.Integer(1)),))
    vertex = next((k for k in scheme.kinds if k.kind == "vertex"), None)
    for number, rule in enumerate(vertex.rules if vertex else (), 1):
        if rule.terms != kept.terms:
            raise InvalidSchemeError(f"[[vertex]] {number}: interpolatory = true, but the rule moves the old vertex "
                                     '(an interpolatory scheme keeps it: terms = [{walk = "", weight = "1"}])')


def _string(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)  # a TOML basic string: JSON's escapes are TOML's


def _term_text(term: Term) -> str:
    parts = [f"walk = {_string(' '.join(term.walk))}", f"weight = {_string(sp.sstr(term.weight))}"]
    parts += [f"over = {_string(term.over)}"] if term.over != "one" else []
    parts += [f"source = {_string(term.source)}"] if term.source != "old" else []
    return "{" + ", ".join(parts) + "}"


def stencil_scheme_to_text(scheme: StencilScheme) -> str:
    """The zoo scheme file of ``scheme`` (read back by :func:`stencil_scheme_from_text` to an equal scheme).

    >>> ds = load_zoo("doo-sabin")
    >>> stencil_scheme_from_text(stencil_scheme_to_text(ds)) == ds
    True
    """
    if not isinstance(scheme, StencilScheme):
        raise InvalidTypeError(f"stencil_scheme_to_text takes a StencilScheme, got {type(scheme).__name__}")
    piecewise = next((t.weight for k in scheme.kinds for r in k.rules for t in r.terms if t.weight.has(sp.Piecewise)), None)
    if piecewise is not None:
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the weight {piecewise} is defined by cases, which a scheme file cannot write")
    lines = [f"name = {_string(scheme.name)}", f"mesh = {_string(scheme.lattice)}", f"topology = {_string(scheme.topology)}",
             f"steps = {scheme.steps}", f"interpolatory = {str(scheme.interpolatory).lower()}"]
    if scheme.source:
        lines.append(f"source = {_string(scheme.source)}")
    if scheme.parameters:
        lines.append("parameters = [" + ", ".join(_string(str(p)) for p in scheme.parameters) + "]")
    for kind in scheme.kinds:
        for number, rule in enumerate(kind.rules):
            lines += ["", f"[[{kind.kind}]]"]
            lines += [f"{key} = {json.dumps(getattr(rule, key))}" for key in ("origin", "tip") if getattr(rule, key) != "any"]
            if kind.ends != "average" and number == 0:
                lines.append(f"ends = {_string(kind.ends)}")
            lines.append("terms = [\n" + "".join(f"  {_term_text(t)},\n" for t in rule.terms) + "]")
    return "\n".join(lines) + "\n"
