"""Schemes written in TOML files, and schemes looked up by name.

This docstring is the one description of the scheme-file format (the documentation's page on it
is this text, and ``tests/schemes/test_scheme_file_format.py`` reads its examples with the parser).
Every command that works on a scheme takes ``--scheme NAME|FILE``: a name of :data:`SCHEMES` or
such a file.

A scheme of the paper's shape (Eq. 14-16) is three affine rules on the 1-ring of a vertex of
valence ``n``, written as a TOML file. Standard Catmull-Clark::

    name = "catmull-clark"
    [edge]            # new a_i = O*w + sum_k a[k]*a_{i+k} + sum_k b[k]*b_{i+k}
    O = "3/8"
    a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }
    b = { "-1" = "1/16", "0" = "1/16" }
    [face]            # new b_i (b_i lies between a_i and a_{i+1})
    O = "1/4"
    a = { "0" = "1/4", "1" = "1/4" }
    b = { "0" = "1/4" }
    [vertex]          # new O; the weight of O is 1 - n*a - n*b
    a = "3/(2*n**2)"
    b = "1/(4*n**2)"

**One model: a scheme is rules for the whole mesh.** The edge rule makes every new edge point and
the face rule every new face point, anywhere in the mesh; the vertex rule makes the new point of
every vertex from that vertex's own valence: at the extraordinary vertex with its valence ``n``, at
every other vertex (all of the regular valence) with ``n = 4`` (quads) or ``n = 6`` (triangles). So
the scheme's regular rules are its rules at the regular valence, and every command reads the same
rules: the 1-ring commands at the extraordinary vertex, ``--rings 2/3``, ``evaldata`` and ``c1`` on
the whole neighbourhood. A scheme tuned at extraordinary vertices only writes a vertex weight that
is the standard one at the regular valence (e.g. ``a = "3/32 + (n - 4)*(...)"``); the rules must be
defined there, and real (checked when the file is read). An edge rule may depend on ``n`` too: an edge
at a vertex of valence ``n`` other than the regular one takes the rule read from that vertex at ``n`` (of
two such ends, the one of larger valence), and an edge between regular vertices the rule at the regular
valence, which must give the same point from either end; every command reads it so. The C1 test knows the regular patches of
Catmull-Clark and Loop: it applies when all the rules at the regular valence, the vertex rule
included, are theirs, and says why in one line otherwise.

Every weight is exact: an integer or a string read by
:func:`symdecomp.expressions.parse_expression` (rationals, ``n``, the names listed in an optional
``parameters = ["alpha", "beta"]``, ``pi``, ``sqrt``, ``cos``, ``sin``), within the expression budget
(:data:`symdecomp.expressions.BUDGET`); nothing is evaluated. A parameter lives in its own namespace
(a symbol of its own class, never equal to the toolkit's ``c = cos(j pi/n)`` or to any symbol of a
derivation); the names the derivations print for their own symbols are reserved and refused in one
line: ``n``, ``j``, ``c``, ``s``, ``omega``, ``lambda``, ``pi``, ``sqrt``, ``cos``, ``sin``, ``k``. ``alpha``
and ``beta`` are the paper's vertex weights (tuning reads them). Parameter names are letters and
digits (a letter first, at most 16). ``name`` is one line of printable text (at most 100 characters), shown literally wherever it
appears. Offsets are integers of magnitude at most :data:`~symdecomp.expressions.MAX_OFFSET`
(``"-2"``, ``"3"``: wider stencils than -1..1): a stencil wider than a valence a command uses is
refused at that valence (the valence must exceed the stencil's width). ``[vertex]`` may also give
``O``; it must then equal ``1 - n*a - n*b``.

``mesh = "quad"`` is the default. A scheme on triangle meshes (Loop's shape, see
:mod:`symdecomp.schemes.loop`) says ``mesh = "triangle"``; its 1-ring is ``(O, a_0..a_{n-1})``
with faces ``(O, a_i, a_{i+1})``, so there is no ``[face]`` section and no ``b`` weights, and
the vertex rule is one weight ``beta`` on each neighbour (``O`` gets ``1 - n*beta``; the key
``a`` is accepted for it too, as in quad files). Loop::

    name = "loop"
    mesh = "triangle"
    [edge]            # new a_i = O*w + sum_k a[k]*a_{i+k}
    O = "3/8"
    a = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }
    [vertex]          # new O = (1 - n*beta)*O + beta*sum_i a_i
    beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"

``beta`` may contain cosines and sines of rational multiples of ``pi`` (``cos(2*pi/n)``,
``cos(4*pi/n)``): at each valence they are exact algebraic numbers, computed with in a cyclotomic
field, never as floats (a weight outside cyclotomic fields, such as ``sqrt(2)``, is refused by the
spectra with one line). A file equal to Loop gives Loop's results in every command.

**Sharp features** (boundaries, creases, corners; :mod:`symdecomp.schemes.sharp`): an optional ``[sharp]``
section gives the scheme's rules there; a key left out keeps the standard rule (OpenSubdiv's, the same for
quads and triangles). ``crease_centre`` and ``crease_end`` are the crease and boundary vertex rule (weight on
the vertex and on each of its two crease neighbours; ``3/4`` and ``1/8``, their sum ``crease_centre +
2*crease_end`` must be 1), ``crease_edge`` the weight on each end of a crease or boundary edge (``1/2``);
corners interpolate. ``near_edge_centre`` and ``near_edge_end``, given together, replace the smooth edge
rule's weights on the two ends of a smooth edge at a crease, boundary or corner vertex (Biermann, Levin and
Zorin's modified rule): the weight on the sharp vertex and on the other end, the other weights staying the
smooth rule's, so the two must sum to twice the edge rule's ``O`` weight. These weights may use the sector
angle ``theta_k`` (``pi/k`` in a crease or boundary sector of ``k`` faces, the corner angle over ``k`` at a
corner; ``cos``/``sin`` of rational multiples of ``theta_k`` only: a bare ``theta_k`` is refused when the file is
read), ``k`` and the declared parameters, with the same budget and checks as every other weight. A weight undefined
at a sector's ``k`` (``1/(k - 2)`` at the regular quad boundary, next to every boundary vertex) and free parameters
are refused, in one line naming the weight, when a boundary, crease, corner or dart vertex is analysed.
Biermann, Levin and Zorin's rules ship as the files ``catmull-clark-blz`` and ``loop-blz`` (:data:`SHIPPED_FILES`, loaded by name); Loop's::

    name = "loop-blz"
    mesh = "triangle"
    [edge]
    O = "3/8"
    a = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }
    [vertex]
    beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"
    [sharp]           # at a crease vertex v: (3/4 - gamma) v + gamma w + (1/8)(x + y), gamma = 1/2 - cos(theta_k)/4
    near_edge_centre = "1/4 + cos(theta_k)/4"
    near_edge_end = "1/2 - cos(theta_k)/4"

A rule whose weights do not sum to 1, a float weight, an unknown name, a malformed offset, an
unknown key, a ``[face]`` or a ``b`` weight in a triangle file, or a triangle ``[vertex]`` without
``beta`` is refused: every problem is reported as one :class:`~symdecomp.errors.InvalidSchemeError`
(or :class:`~symdecomp.errors.NotAffineError`) naming the file and the key; on the command line it
is one line and exit status 2 (``symdecomp: error: argument --scheme: my.toml: [face] O:
0.25 is a float; give an exact rational such as "3/8" (see 'symdecomp claims --help')``). In Python: ``load_scheme("my.toml")``, then e.g.
``symdecomp.check_claim("Remark 5.1", scheme)``. A float weight:

>>> scheme_from_text('[edge]\\nO = 0.375', source="s.toml")
Traceback (most recent call last):
...
symdecomp.errors.InvalidSchemeError: s.toml: [edge] O: 0.375 is a float; give an exact rational such as "3/8"
"""

from __future__ import annotations

import os
import re
import tomllib
from collections.abc import Callable, Mapping
from importlib import resources

import sympy as sp

from symdecomp.errors import InvalidExpressionError, InvalidSchemeError, InvalidTypeError, NotAffineError, SymdecompError
from symdecomp.expressions import identically_zero, parse_expression
from symdecomp.schemes.lattice import LATTICES, QUAD
from symdecomp.schemes.loop import loop, loop_warren
from symdecomp.schemes.scheme import Scheme, Stencil, VertexRule, catmull_clark
from symdecomp.schemes.sharp import SHARP_SYMBOLS, SharpRules, standard_sharp_rules
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import RESERVED_NAMES, Parameter
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import n as N
from symdecomp.validate import INPUT_LIMITS

__all__ = ["SCHEMES", "SHIPPED_FILES", "load_scheme", "scheme_from_text", "scheme_to_text"]

#: Schemes known by name (``--scheme NAME``).
SCHEMES: dict[str, Callable[[], Scheme]] = {"catmull-clark": catmull_clark, "loop": loop, "loop-warren": loop_warren}

#: Mesh types a file may name (the lattices' names); ``"quad"`` is the default.
MESHES = tuple(LATTICES)
#: The mesh of a file that names none (and that a written file leaves out).
DEFAULT_MESH = QUAD.name

#: Scheme files shipped with the package, loaded by name (``--scheme catmull-clark-blz``): BLZ's rules at sharp features.
SHIPPED_FILES = {"catmull-clark-blz": "catmull-clark-blz.toml", "loop-blz": "loop-blz.toml"}

_TOP_KEYS = {"name", "mesh", "parameters", "edge", "face", "vertex", "sharp"}
_SHARP_KEYS = ("crease_centre", "crease_end", "crease_edge", "near_edge_centre", "near_edge_end")
_RULE_KEYS = {"O", "a", "b"}
_OFFSET = re.compile(r"^[+-]?[0-9]{1,4}$")
_IDENTIFIER = re.compile(r"^[A-Za-z][A-Za-z0-9]{0,15}$")
_KNOWN_SYMBOLS = {"alpha": ALPHA, "beta": BETA}
MAX_FILE_BYTES = INPUT_LIMITS["scheme file: bytes"][0]


def load_scheme(name_or_path: str | os.PathLike) -> Scheme | StencilScheme:
    """A scheme by name (``"catmull-clark"``) or from a TOML file (see the module docstring).

    The zoo's families by name (``"doo-sabin"``) and files with a ``topology`` key are read as
    :class:`~symdecomp.schemes.stencils.StencilScheme` (:mod:`symdecomp.schemes.stencil_files`).
    """
    from symdecomp.schemes import stencil_files  # the zoo's format (it reads parameter names with this module)

    if not isinstance(name_or_path, (str, os.PathLike)):
        raise InvalidTypeError(f"load_scheme takes a scheme name or a file path, got {name_or_path!r:.60} "
                               f"({type(name_or_path).__name__})")
    text_name = os.fspath(name_or_path)
    if not isinstance(text_name, str):
        raise InvalidTypeError(f"load_scheme takes a scheme name or a file path as text, got {text_name!r:.60}")
    if text_name in SCHEMES:
        return SCHEMES[text_name]()
    if text_name in stencil_files.ZOO_FILES:
        return stencil_files.load_zoo(text_name)
    if text_name in SHIPPED_FILES:
        text = resources.files("symdecomp.schemes").joinpath(SHIPPED_FILES[text_name]).read_text(encoding="utf-8")
        return scheme_from_text(text, source=SHIPPED_FILES[text_name], default_name=text_name)
    if not os.path.isfile(text_name):
        from symdecomp.schemes.zoo_literature import NOT_SHIPPED

        if text_name in NOT_SHIPPED:
            raise InvalidSchemeError(f"{text_name!r} is not shipped: {NOT_SHIPPED[text_name].summary}")
        raise InvalidSchemeError(
            f"unknown scheme {text_name!r}: neither a known name ({', '.join([*SCHEMES, *stencil_files.ZOO_FILES])}) nor a readable file"
        )
    try:
        with open(text_name, "rb") as handle:
            raw = handle.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise InvalidSchemeError(f"{text_name}: cannot read the file ({exc.strerror})") from None
    if len(raw) > MAX_FILE_BYTES:
        raise InvalidSchemeError(f"{text_name}: larger than {MAX_FILE_BYTES} bytes; a scheme file is a few lines")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise InvalidSchemeError(f"{text_name}: not UTF-8 text") from None
    default_name = os.path.splitext(os.path.basename(text_name))[0]
    if stencil_files.is_stencil_text(text):
        return stencil_files.stencil_scheme_from_text(text, source=text_name, default_name=default_name)
    return scheme_from_text(text, source=text_name, default_name=default_name)


def scheme_from_text(text: str, *, source: str = "<scheme>", default_name: str = "scheme") -> Scheme:
    """Build a :class:`~symdecomp.schemes.scheme.Scheme` from the text of a scheme file."""
    if not isinstance(text, str):
        raise InvalidTypeError(f"scheme_from_text takes the text of a scheme file, got {type(text).__name__}")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InvalidSchemeError(f"{source}: not valid TOML ({exc})") from None
    except RecursionError:  # tomllib parses nested arrays and tables recursively
        raise InvalidSchemeError(f"{source}: arrays or tables nested too deeply; a scheme file is a few flat tables") from None
    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        raise InvalidSchemeError(f"{source}: unknown key {unknown[0]!r} (known: {', '.join(sorted(_TOP_KEYS))})")
    name = data.get("name", default_name)
    if not isinstance(name, str) or not name.strip() or len(name) > 100 or not name.isprintable():
        raise InvalidSchemeError(f"{source}: name must be a non-empty string of at most 100 printable characters (no line "
                                 "breaks or control characters)")
    mesh = data.get("mesh", DEFAULT_MESH)
    if not isinstance(mesh, str) or mesh not in LATTICES:
        raise InvalidSchemeError(f"{source}: mesh {mesh!r} is not supported (known: {', '.join(MESHES)})")
    mesh = LATTICES[mesh]
    symbols = _parameters(data.get("parameters", []), source)
    sections = mesh.stencil_sections + ("vertex",)
    kinds = {name for name, _ in mesh.one_ring_classes}  # the 1-ring's neighbours: a_i, and b_i with face neighbours
    if "face" in data and "face" not in sections:
        raise InvalidSchemeError(f"{source}: [face]: a {mesh} mesh has no face rule (its 1-ring has no face neighbours b_i)")
    rules = {}
    for section in sections:
        if section not in data:
            raise InvalidSchemeError(f"{source}: missing section [{section}]")
        if not isinstance(data[section], dict):
            raise InvalidSchemeError(f"{source}: {section} must be a table [{section}]")
        if section == "vertex":
            rules[section] = (_vertex if "b" in kinds else _triangle_vertex)(data[section], source, symbols)
        else:
            rules[section] = _stencil(data[section], section, source, symbols, keys={"O", *kinds})
    edge, face, vertex = rules["edge"], rules.get("face"), rules["vertex"]
    declared = tuple(s for key, s in symbols.items() if key != "n")
    sharp = _sharp(data.get("sharp", {}), source, symbols)
    try:
        scheme = Scheme(name.strip(), edge, face, vertex, declared, mesh, sharp)
        scheme.check_values_at(mesh.regular_valence, real=True, note=" (the regular valence: every vertex away from O uses "
                               "the rules there)")
    except SymdecompError as exc:
        raise InvalidSchemeError(f"{source}: {exc}") from None
    undeclared = set(scheme.parameters) - set(declared)
    if undeclared:  # pragma: no cover - the parser only knows declared names
        raise InvalidSchemeError(f"{source}: undeclared symbols {sorted(map(str, undeclared))}")
    return scheme


def _parameters(value, source: str) -> dict[str, sp.Symbol]:
    if not isinstance(value, list) or not all(isinstance(p, str) for p in value):
        raise InvalidSchemeError(f"{source}: parameters must be a list of names, e.g. [\"alpha\", \"beta\"]")
    symbols = {"n": N}
    for p in value:
        if not _IDENTIFIER.match(p) or p in RESERVED_NAMES:
            raise InvalidSchemeError(
                f"{source}: parameters: {p!r} is not a usable name (letters and digits, at most 16; reserved: "
                f"{', '.join(RESERVED_NAMES)})"
            )
        if p in symbols:
            raise InvalidSchemeError(f"{source}: parameters: {p!r} is declared twice")
        symbols[p] = _KNOWN_SYMBOLS.get(p) or Parameter(p, real=True)
    return symbols


def _weight(value, where: str, source: str, symbols: Mapping[str, sp.Symbol]) -> sp.Expr:
    if isinstance(value, bool):
        raise InvalidSchemeError(f"{source}: {where}: {value!r} is a boolean, not a weight")
    if isinstance(value, float):
        raise InvalidSchemeError(f"{source}: {where}: {value!r} is a float; give an exact rational such as \"3/8\"")
    if isinstance(value, int):
        return sp.Integer(value)
    if not isinstance(value, str):
        raise InvalidSchemeError(f"{source}: {where}: expected a weight such as \"3/8\", got a {type(value).__name__}")
    try:
        expr = parse_expression(value, symbols, argument="weight")
    except InvalidExpressionError as exc:
        raise InvalidSchemeError(f"{source}: {where}: {exc}") from None
    if expr.has(sp.I) or expr.is_real is False:
        raise InvalidSchemeError(f"{source}: {where}: {value!r} is not real")
    return expr


def _sharp(table, source: str, symbols) -> SharpRules:
    """The ``[sharp]`` section: the standard rules, with the weights it gives (``theta_k`` and ``k`` allowed)."""
    if not isinstance(table, dict):
        raise InvalidSchemeError(f"{source}: sharp must be a table [sharp]")
    _check_keys(table, set(_SHARP_KEYS), "sharp", source)
    names = {key: s for key, s in symbols.items() if key != "n"} | SHARP_SYMBOLS
    standard = standard_sharp_rules()
    weights = {key: _weight(table[key], f"[sharp] {key}", source, names) if key in table else getattr(standard, key)
               for key in _SHARP_KEYS}
    try:
        return SharpRules(**weights)
    except SymdecompError as exc:
        raise InvalidSchemeError(f"{source}: [sharp]: {str(exc).removeprefix('sharp rules: ')}") from None


def _offsets(value, where: str, source: str, symbols) -> dict[int, sp.Expr]:
    if not isinstance(value, dict):
        raise InvalidSchemeError(f"{source}: {where}: expected a table of offsets, e.g. {{ \"-1\" = \"1/16\", \"0\" = \"3/8\" }}")
    out: dict[int, sp.Expr] = {}
    for key, weight in value.items():
        if not _OFFSET.match(key):
            raise InvalidSchemeError(f"{source}: {where}.{key!r}: an offset must be an integer such as \"-1\", \"0\" or \"2\"")
        k = int(key)
        if k in out:
            raise InvalidSchemeError(f"{source}: {where}.{key!r}: offset {k} is given twice")
        out[k] = _weight(weight, f"{where}.{key!r}", source, symbols)
    return out


def _check_keys(table: dict, allowed: set, section: str, source: str) -> None:
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise InvalidSchemeError(f"{source}: [{section}] unknown key {unknown[0]!r} (known: {', '.join(sorted(allowed))})")


def _stencil(table: dict, section: str, source: str, symbols, *, keys=_RULE_KEYS) -> Stencil:
    if "b" in table and "b" not in keys:
        raise InvalidSchemeError(f"{source}: [{section}] b: a triangle mesh has no face neighbours b_i; give only O and a")
    _check_keys(table, keys, section, source)
    center = _weight(table.get("O", 0), f"[{section}] O", source, symbols)
    a = _offsets(table.get("a", {}), f"[{section}] a", source, symbols)
    b = _offsets(table.get("b", {}), f"[{section}] b", source, symbols)
    total = center + sum(a.values(), sp.Integer(0)) + sum(b.values(), sp.Integer(0))
    if not identically_zero(total - 1):
        total = sp.cancel(total)
        raise NotAffineError(f"{source}: [{section}] is not affine: O + sum of a + sum of b = {total}, not 1")
    return Stencil.from_weights(center, a, b, name=f"{section} rule")


def _triangle_vertex(table: dict, source: str, symbols) -> VertexRule:
    if "b" in table:
        raise InvalidSchemeError(f"{source}: [vertex] b: on a triangle mesh the vertex rule is one weight, beta, on each neighbour")
    _check_keys(table, {"O", "a", "beta"}, "vertex", source)
    if "a" in table and "beta" in table:
        raise InvalidSchemeError(f"{source}: [vertex] a and beta are the same weight (beta on each neighbour a_i); give one")
    key = "a" if "a" in table else "beta"  # ``a`` as in quad files, ``beta`` as Loop's papers name it
    if key not in table:
        raise InvalidSchemeError(f"{source}: [vertex] beta is missing (the weight of each neighbour a_i in the new O)")
    beta = _weight(table[key], f"[vertex] {key}", source, symbols)
    rule = VertexRule.affine(beta, 0)
    if "O" in table:
        center = _weight(table["O"], "[vertex] O", source, symbols)
        if not identically_zero(center - rule.center):
            raise NotAffineError(f"{source}: [vertex] is not affine: O = {center}, but 1 - n*beta = {rule.center}")
    return rule


def _vertex(table: dict, source: str, symbols) -> VertexRule:
    _check_keys(table, _RULE_KEYS, "vertex", source)
    for key in ("a", "b"):
        if key not in table:
            raise InvalidSchemeError(f"{source}: [vertex] {key} is missing (the weight of each {key}_i in the new O)")
    a = _weight(table["a"], "[vertex] a", source, symbols)
    b = _weight(table["b"], "[vertex] b", source, symbols)
    rule = VertexRule.affine(a, b)
    if "O" in table:
        center = _weight(table["O"], "[vertex] O", source, symbols)
        if not identically_zero(center - rule.center):
            raise NotAffineError(f"{source}: [vertex] is not affine: O = {center}, but 1 - n*a - n*b = {rule.center}")
    return rule


def _text(expr: sp.Expr) -> str:
    return sp.sstr(expr)


def scheme_to_text(scheme: Scheme) -> str:
    """The scheme file of ``scheme`` (read back by :func:`scheme_from_text` to an equal scheme).

    >>> cc = catmull_clark()
    >>> scheme_from_text(scheme_to_text(cc)) == cc
    True
    """

    def offsets(pairs):
        return "{ " + ", ".join(f'"{k}" = "{_text(w)}"' for k, w in pairs) + " }"

    v = scheme.vertex_rule
    piecewise = next((w for w in scheme.weights() if sp.sympify(w, strict=True).has(sp.Piecewise)), None)
    if piecewise is not None:  # e.g. Warren's beta (3/16 at n = 3): the file grammar has no cases
        raise InvalidSchemeError(f"scheme {scheme.name!r}: the weight {piecewise} is defined by cases, which a scheme file cannot write")
    lines = [f'name = "{scheme.name}"']
    if scheme.lattice.name != DEFAULT_MESH:  # the default is not written
        lines.append(f'mesh = "{scheme.lattice.name}"')
    if scheme.parameters:
        lines.append("parameters = [" + ", ".join(f'"{p}"' for p in scheme.parameters) + "]")
    if "face" not in scheme.lattice.stencil_sections:
        rule = scheme.edge_rule
        lines += ["[edge]", f'O = "{_text(rule.center)}"', f"a = {offsets(rule.a)}", "[vertex]", f'beta = "{_text(v.each_a)}"']
        return "\n".join(lines + _sharp_lines(scheme)) + "\n"
    for section, rule in (("edge", scheme.edge_rule), ("face", scheme.face_rule)):
        lines += [f"[{section}]", f'O = "{_text(rule.center)}"', f"a = {offsets(rule.a)}", f"b = {offsets(rule.b)}"]
    lines += ["[vertex]", f'a = "{_text(v.each_a)}"', f'b = "{_text(v.each_b)}"']
    return "\n".join(lines + _sharp_lines(scheme)) + "\n"


def _sharp_lines(scheme: Scheme) -> list[str]:
    """The ``[sharp]`` section, when the rules are not the standard ones."""
    if scheme.sharp == standard_sharp_rules():
        return []
    return ["[sharp]"] + [f'{key} = "{_text(getattr(scheme.sharp, key))}"' for key in _SHARP_KEYS
                          if getattr(scheme.sharp, key) is not None]
