"""The extraordinary element the user named on the command line, built and validated once, and each command's routes.

A command that analyses one element (``spectrum``, ``masks``, ``check``, ``c1``, ``artifacts``, ``evaldata``) asks
:func:`named_element` for it: the scheme and the *kind* of element, read once from the arguments. The kinds
(:data:`KINDS`):

* ``vertex``: an interior vertex of valence ``n`` of a scheme of edge, face and vertex rules (the paper's route, or the
  any-scheme route on triangles and ``--rings K``);
* ``sector``: a boundary, crease, corner or dart vertex of such a scheme, its fan of ``K`` faces cut by sharp edges;
* ``zoo``: the extraordinary vertex or ``n``-sided face of a scheme of the zoo (a StencilScheme), at its ring depth;
* ``zoo sector``: a sharp option given with a scheme of the zoo (whose engine reads interior elements only).

Each command keeps one table from kind to the function that answers it (its *routes*, data as symfem keeps its
reference cells), and :func:`route` looks the element up there: a command module has no if-chain over the kinds, and
a kind a command has no route for is refused in one line naming the command and the kind. A new kind is one entry in
:data:`KINDS` (and where :func:`named_element` recognises it); a command's new route is one entry in its table.

The sharp vertex is named by one option (why these names: a user says "a boundary vertex with 5 faces", so
``spectrum 5 --boundary``; ``--crease K2`` takes the second sector's faces because a crease vertex has two
sectors and the positional argument is the first; ``--corner`` and ``--dart`` are the tags OpenSubdiv and
modellers use):

* ``--boundary``: a boundary vertex with ``K`` faces (an open fan, the standard crease rule at the vertex);
* ``--corner``: the same fan with the vertex tagged as a corner (interpolated);
* ``--crease K2``: an interior vertex on a crease, ``K`` faces on one side and ``K2`` on the other;
* ``--dart``: an interior vertex of valence ``K`` where a crease ends (one sharp edge);
* ``--sharpness S`` (with ``--crease`` or ``--dart``): the crease edges' sharpness, an exact rational ``>= 0``
  or ``inf`` (the default); semi-sharp edges decay by 1 a level.

``K`` is the sector's face count (``spectrum K``, ``masks K``; ``check --k A:B``), from 1 (a dart or a
crease needs 2 faces around the vertex in all). The lattice is the scheme's: quads for Catmull-Clark and quad
scheme files, triangles for Loop. The scheme's ``[sharp]`` rules (a scheme file's section) are used where it
gives them, the standard ones otherwise.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from symdecomp.cli.common import LIMITS, SHARP_OPTIONS, Once, flag, given, integer, positive_int
from symdecomp.errors import InvalidInputError
from symdecomp.validate import check_memory

__all__ = ["KINDS", "Element", "named_element", "route", "ring_depth", "steps_note", "SECTOR_VERTICES", "sector_vertex",
           "sharpness", "add_sharp_options", "check_sharp_options", "sharp_vertex", "check_rules_at", "faces_or_valence",
           "sector_range", "refuse_sharp_options", "describe", "exact_only"]

#: Most faces around a sharp vertex on the command line (the matrices are dense and exact; a row of the limits table).
MAX_FACES = LIMITS["--boundary, --corner, --crease, --dart: faces"][0]
#: Bytes the exact analysis of a dart with 16 faces takes beyond start-up (measured: ``masks 16 --dart``; it grows like
#: the faces to the 4th power, 24 faces about 140 MB, 32 about 450 MB, 64 past 3.8 GB): the memory estimate of
#: :func:`sharp_vertex`, checked before FLINT allocates anything, since FLINT aborts the whole process when an
#: allocation fails. A dart has no mirror symmetry, so its matrix is analysed whole; the other vertices' sectors split
#: it into small blocks (32 faces in under 80 MB).
BYTES_AT_16_FACES = 28 << 20
#: Most faces where a command reads the vertex by the mirror decomposition's blocks (boundary, corner, crease).
MAX_STRUCTURAL_FACES = LIMITS["--boundary, --corner, --crease: faces by the blocks"][0]


#: The kinds of extraordinary element a command can be asked about, each with the words an error line names it by.
KINDS = {
    "vertex": "an interior vertex",
    "sector": "a boundary, crease, corner or dart vertex",
    "zoo": "the extraordinary vertex or face of a scheme of the zoo",
    "zoo sector": "a boundary, crease, corner or dart vertex of a scheme of the zoo",
}

#: A command's route: the function that answers one kind of element, given the arguments (and its ``--plot`` target).
Route = Callable[..., int]


@dataclass(frozen=True)
class Element:
    """The extraordinary element the user named: the scheme and the kind (:data:`KINDS`), read once from the arguments."""

    #: The scheme (a :class:`~symdecomp.schemes.scheme.Scheme` or a :class:`~symdecomp.schemes.stencils.StencilScheme`).
    scheme: Any
    #: The kind, a key of :data:`KINDS`.
    kind: str
    #: The sharp options given (``("--crease",)``; empty for an interior element).
    tags: tuple[str, ...]
    #: The centre: ``"vertex"``, or ``"face"`` for a dual scheme of the zoo (Doo-Sabin: an ``n``-sided face).
    centre: str = "vertex"
    #: The valences, sides or face counts named (``N``, ``--n A:B``, ``--k A:B``; empty for ``--every-n``).
    sizes: tuple[int, ...] = ()
    #: The ring depth asked (``--rings K``; 1: the 1-ring, or a zoo scheme's smallest invariant neighbourhood).
    depth: int = 1

    @property
    def words(self) -> str:
        """The kind in words, as an error line names it."""
        return KINDS[self.kind]


def named_element(args: argparse.Namespace) -> Element:
    """The :class:`Element` the arguments name (the one place that reads which kind of element a command is asked about)."""
    from symdecomp.schemes.stencils import StencilScheme
    from symdecomp.schemes.topology import topology_of

    scheme = args.scheme
    tags = tuple(option for dest, option in SHARP_OPTIONS.items() if given(args, dest))
    named = next((getattr(args, dest) for dest in ("n", "valences", "sectors", "faces")
                  if isinstance(getattr(args, dest, None), (int, list))), [])
    sizes = tuple(named) if isinstance(named, list) else (named,)
    depth = int(getattr(args, "rings", 1))
    if isinstance(scheme, StencilScheme):
        centre = "vertex" if tags else topology_of(scheme).centre
        return Element(scheme, "zoo sector" if tags else "zoo", tags, centre, sizes, depth)
    return Element(scheme, "sector" if tags else "vertex", tags, "vertex", sizes, depth)


def route(command: str, routes: Mapping[str, Route], element: Element) -> Route:
    """The function of ``routes`` (a command's table, kind -> function) that answers ``element``; a kind the table has no
    route for is refused in one line naming the command and the kind."""
    try:
        return routes[element.kind]
    except KeyError:
        where = f" ({', '.join(element.tags)})" if element.tags else ""
        answered = "; ".join(KINDS[kind] for kind in routes)
        raise InvalidInputError(f"{command}: {element.words}{where} is not answered by {command} (--scheme "
                                f"{element.scheme.name}); it answers {answered}") from None


def ring_depth(args: argparse.Namespace) -> int | None:
    """The ring depth of a scheme of the zoo's neighbourhood (``--rings K``; ``None``: the smallest invariant one); a sharp
    option is refused in one line (the zoo's engine reads interior vertices and faces)."""
    if any(given(args, dest) for dest in SHARP_OPTIONS):
        raise InvalidInputError(f"--scheme {args.scheme.name}: boundary, crease, corner and dart vertices are not analysed "
                                "for schemes of the zoo (interior vertices and faces only)")
    rings = int(getattr(args, "rings", 1))
    return None if rings == 1 else rings


def steps_note(scheme: Any) -> str:
    """``", over 2 steps (...)"`` for a scheme whose lattice returns after more than one step (sqrt(3)), else ``""``."""
    return f", over {scheme.steps} steps (the lattice returns after {scheme.steps})" if scheme.steps > 1 else ""


def sharpness(text: str):
    """argparse type of ``--sharpness``: a sharpness ``>= 0`` (exact) or ``inf``."""
    from symdecomp.schemes.sharp import check_sharpness

    try:
        return check_sharpness(text, "--sharpness")
    except InvalidInputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def add_sharp_options(parser, *, count: str = "N", sharpness_help: str | None = None) -> None:
    """The options of a boundary, crease, corner or dart vertex (module docstring); ``count``: the argument giving K;
    ``sharpness_help``: the command's own help of ``--sharpness`` (where it reads only some sharpnesses)."""
    g = parser.add_argument_group("boundary, crease, corner and dart vertices",
                                  f"with one of these, {count} is the faces K of the vertex's sector (1 <= K <= {MAX_FACES})")
    parser.set_defaults(_sharp_options=True)  # check_sharp_options: this command has the options below
    flag(g, "--boundary", help="a boundary vertex with K faces")
    flag(g, "--corner", help="a boundary vertex with K faces tagged as a corner (interpolated)")
    g.add_argument("--crease", type=positive_int("--crease"), action=Once, metavar="K2",
                   help="an interior vertex on a crease with K faces on one side and K2 on the other")
    flag(g, "--dart", help="an interior vertex of valence K where a crease ends (one sharp edge)")
    g.add_argument("--sharpness", type=sharpness, action=Once, metavar="S", default=math.inf,
                   help=sharpness_help or "with --crease or --dart: the crease's sharpness, an exact rational >= 0 or inf "
                   "(default); semi-sharp edges decay by 1 a level, and the output shows every level whose matrix differs")


def faces_or_valence(limit: str):
    """argparse type of ``N``: an integer ``>= 1`` (a valence ``>= 3`` is checked when no sharp option is given)."""

    def parse(text: str) -> int:
        return integer(text, "N", minimum=1, limit=limit, noun="a valence (or with --boundary, ... a face count): an integer")

    parse.__name__ = "valence"
    return parse


def sector_range(text: str) -> list[int]:
    """argparse type of ``check --k``: ``K`` or an inclusive range ``A:B`` of face counts, ``1 <= A <= B <=
    MAX_STRUCTURAL_FACES`` (the blocks' routes; darts and the dense route are held to ``MAX_FACES`` per vertex by
    :func:`sharp_vertex` and ``check``'s route)."""
    if text.count(":") > 1:
        raise argparse.ArgumentTypeError(f"expected K or A:B, got {text!r}")
    parts = text.split(":")
    lo, hi = (integer(p, "--k", minimum=1, noun="a face count: an integer") for p in (parts[0], parts[-1]))
    if hi > MAX_STRUCTURAL_FACES:
        raise argparse.ArgumentTypeError(f"expected face counts <= {MAX_STRUCTURAL_FACES}, got {hi} (the blocks are O(k); "
                                         f"darts at most {MAX_FACES})")
    if hi < lo:
        raise argparse.ArgumentTypeError(f"empty range {text!r}: {hi} < {lo}")
    return list(range(lo, hi + 1))


def check_sharp_options(args) -> None:
    """Refuse, before any work, a combination of the sharp options that names no vertex or two kinds of vertex.

    Called for every command (:func:`symdecomp.cli.common.check_scheme_valences`); a command without the options
    (``oracle``, whose ``--sharpness`` is a list of its own) is left alone.
    """
    if not getattr(args, "_sharp_options", False):
        return
    named = [option for dest, option in SHARP_OPTIONS.items() if given(args, dest)]
    if given(args, "sharpness") and not set(named) & {"--crease", "--dart"}:
        raise InvalidInputError("--sharpness: the sharpness of a crease's edges; give it with --crease K2 or --dart (boundary "
                                "edges are infinitely sharp)")
    if len(named) > 1:
        raise InvalidInputError(f"{named[0]} and {named[1]} cannot be used together: each names a different kind of vertex")


def check_rules_at(scheme, vertex) -> None:
    """Refuse, in one line naming the scheme, ``[sharp]`` rules that cannot be evaluated at ``vertex``: a free parameter
    in them (the sharp routes are exact in numbers; the smooth rules' parameters are refused where a matrix reads
    them), or a weight undefined at one of its sectors or at the regular boundary next to it
    (:meth:`~symdecomp.schemes.sharp.SharpRules.check_at`)."""
    from symdecomp.errors import SymdecompError

    regular = scheme.lattice.regular_valence // 2  # the faces of the regular boundary vertices next to the vertex
    try:
        scheme.sharp.check_at((*vertex.sectors, regular), vertex.angle)
    except SymdecompError as exc:
        raise InvalidInputError(f"--scheme {scheme.name}: {exc}") from None


def sharp_vertex(args, k: int, *, structural: bool = False):
    """The :class:`~symdecomp.schemes.sector.SharpVertex` the options name, with ``k`` faces; one line for a bad combination.

    ``structural``: the command reads boundary, corner and infinitely sharp crease vertices by the mirror decomposition's
    blocks (O(k)), so they may have up to :data:`MAX_STRUCTURAL_FACES` faces; darts and semi-sharp creases stay dense.
    """
    check_sharp_options(args)
    named = [option for dest, option in SHARP_OPTIONS.items() if given(args, dest)]
    wide = structural and named[0] != "--dart" and args.sharpness == math.inf
    limit = MAX_STRUCTURAL_FACES if wide else MAX_FACES
    if k > limit or getattr(args, "crease", None) and k + args.crease > limit:
        raise InvalidInputError(f"the vertex has more than {limit} faces " + ("(the blocks are O(k))" if wide else
                                "(the matrices are dense and exact)"))
    if named[0] == "--dart" and k < 3:
        raise InvalidInputError(f"--dart: a dart is an interior vertex of valence K >= 3, got K = {k}")
    faces = (k, args.crease) if named[0] == "--crease" else k
    vertex = sector_vertex(named[0], faces, args.scheme.lattice, sharpness=args.sharpness)
    check_rules_at(args.scheme, vertex)
    if named[0] == "--dart":
        check_memory(int(BYTES_AT_16_FACES * (vertex.faces / 16) ** 4), f"{describe(vertex)}: the exact analysis")
    return vertex


#: The sharp vertex each tag names (:class:`~symdecomp.schemes.sector.SharpVertex`'s constructors), from its faces
#: (``K``; a crease's ``(K1, K2)``), lattice, corner angle (``None``: BLZ's ``pi/k``) and sharpness.
SECTOR_VERTICES: dict[str, Callable[..., Any]] = {
    "boundary": lambda cls, faces, lat, angle, sharpness: cls.boundary(faces, lat),
    "corner": lambda cls, faces, lat, angle, sharpness: cls.corner(faces, lat, angle),
    "crease": lambda cls, faces, lat, angle, sharpness: cls.crease(faces[0], faces[1], lat, sharpness),
    "dart": lambda cls, faces, lat, angle, sharpness: cls.dart(faces, lat, sharpness),
}


def sector_vertex(tag: str, faces, lattice, *, angle=None, sharpness=math.inf):
    """The :class:`~symdecomp.schemes.sector.SharpVertex` the tag names (``boundary`` or ``--boundary``, ...;
    :data:`SECTOR_VERTICES`), the one place a command builds one."""
    from symdecomp.schemes.sector import SharpVertex

    return SECTOR_VERTICES[tag.lstrip("-")](SharpVertex, faces, lattice, angle, sharpness)


def refuse_sharp_options(args, *names: str) -> None:
    """Refuse options of the interior route that a sharp vertex does not have (``--rings`` > 1, ``--exact``, ...)."""
    for name in names:
        dest = name.lstrip("-").replace("-", "_")
        if given(args, dest) and (dest != "rings" or args.rings != 1):
            raise InvalidInputError(f"{name}: not available for boundary, crease, corner and dart vertices (their 1-ring "
                                    "matrix is analysed exactly)")


def describe(vertex) -> str:
    """The vertex's short name (:func:`symdecomp.verify.certify.describe_vertex`)."""
    from symdecomp.verify.certify import describe_vertex

    return describe_vertex(vertex)


def exact_only(args, vertex, compute):
    """``compute()``, with a vertex out of the sharp routes' reach refused in one line (they are exact over ``Q``, and
    over one field ``Q(cos(pi/k))`` for Biermann-Levin-Zorin's ``cos(theta_k)`` weights: not over two such fields)."""
    from symdecomp.errors import NotApplicableError

    try:
        return compute()
    except NotApplicableError as exc:
        why = str(exc).split("; use ")[0]
        raise InvalidInputError(f"--scheme {args.scheme.name}, {describe(vertex)}: {why}; spectrum, masks and check of "
                                "boundary, crease, corner and dart vertices work exactly over Q, and over one field "
                                "Q(cos(pi/k)) for rules with cos(theta_k) weights") from None
