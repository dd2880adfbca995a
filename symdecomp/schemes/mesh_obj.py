"""OBJ mesh text with OpenSubdiv's tags, read fast and exactly; the numbers of mesh text files.

Lines: ``v x y z`` (an optional fourth coordinate must be 1), ``f i j k ...`` (``i``, ``i/t``, ``i/t/n`` or
``i//n``; 1-based; a negative index counts back from the last vertex defined before the face, as the
OBJ standard says), ``#`` comments, and lines that do not change the surface, ignored: ``vt``, ``vn``,
``vp``, ``g``, ``o``, ``s``, ``usemtl``, ``mtllib``, ``l``, ``p`` and the other display attributes
(:data:`IGNORED`). Any other keyword (free-form curves and surfaces: ``cstype``, ``curv``, ``surf``, ...)
is refused with its line number.

OpenSubdiv's tags (``regression/common/shape_utils.cpp``: ``t NAME I/F/S`` then ``I`` integers, ``F``
numbers, ``S`` words) fill a :class:`~symdecomp.schemes.mesh_tags.MeshTags`; vertex and face numbers in
tags are 0-based, as OpenSubdiv reads them:

* ``t crease 2k/1/0 u1 v1 .. uk vk s`` or ``2k/k/0 .. s1 .. sk``: edges ``{u, v}`` of the mesh with sharpness
  ``s >= 0`` (an exact rational; 10 or more is infinitely sharp);
* ``t corner k/1/0 v1 .. vk s`` or ``k/k/0``: sharp vertices; ``t hole k/0/0 f1 .. fk``: faces that are holes;
* ``t interpolateboundary 1/0/0 m``: ``m`` = 0, 1, 2 is none, edge-and-corner, edge-only (without the tag:
  edge-and-corner; OpenSubdiv's shape loader takes edge-only then, so write the tag to compare with it);
* ``t creasemethod 0/0/1 normal|chaikin``, ``t smoothtriangles 0/0/1 catmark|smooth``;
* ``t facevaryinginterpolateboundary``, ``t facevaryingpropagatecorners``: face-varying data only, ignored;
* hierarchical edits (``t vertexedit``, ``t edgeedit``, ``t faceedit``): read (their paths checked: ``length, face,
  subface.., [vertex or edge]``) and left out of the mesh, listed with their line and the first level they act at
  (:attr:`ParsedMesh.edits`, then the mesh's defects). They override points, sharpness or holes at refined levels, so
  the edited surface is not the subdivision surface of the control mesh, which is what every verdict is about: the
  analysis is of the unedited surface, and says what it left out. OpenSubdiv's 3.0 release removed them too ("support
  for hierarchical features has been removed from the 3.0 release", its page *Hierarchical Edits*). Any other tag:
  refused.

A number is a decimal ``[+-]digits[.digits][e[+-]digits]`` of at most
:data:`~symdecomp.validate.MAX_NUMBER_CHARS` characters whose value has magnitude at most
:data:`~symdecomp.validate.MAX_COORDINATE` (its nearest double is finite); ``nan``, ``inf`` and hexadecimal are refused. A line is at
most :data:`MAX_LINE_BYTES` bytes. Every refusal is one line naming the file and the line.

>>> m = read_obj(b"v 0 0 0\\nv 1 0 0\\nv 1 1 0\\nv 0 1 0.1\\nf 1 2 3 4\\nt crease 2/1/0 0 1 2.5\\n", "sq.obj")
>>> m.corners.tolist(), m.tags.creases[(0, 1)], m.exact_point(3)[2]
([0, 1, 2, 3], Fraction(5, 2), Fraction(1, 10))
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_tags import MeshTags
from symdecomp.validate import INPUT_LIMITS, MAX_COORDINATE, MAX_NUMBER_CHARS, finite_double

__all__ = ["IGNORED", "MAX_LINE_BYTES", "ParsedMesh", "number", "index", "read_obj", "reading_progress"]

#: Keywords of OBJ lines that do not change the surface (texture, normals, groups, materials, display).
IGNORED = frozenset({"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p", "mg", "lod", "bevel", "c_interp", "d_interp",
                     "shadow_obj", "trace_obj", "maplib", "usemap"})
#: The longest line of a mesh text file (bytes): a face of about a million corners.
MAX_LINE_BYTES = INPUT_LIMITS["mesh, OBJ: bytes of a line"][0]

_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)
_INDEX = re.compile(r"[+-]?[0-9]{1,12}", re.ASCII)
_NUMBER_BYTES = b"0123456789+-.eE"
_BOUNDARY = {0: "none", 1: "edge-and-corner", 2: "edge-only"}
_OPTIONS = {"creasemethod": ("crease_method", {"normal": "uniform", "chaikin": "chaikin"}),
            "smoothtriangles": ("triangle_subdivision", {"catmark": "catmark", "smooth": "smooth"})}


@dataclass
class ParsedMesh:
    """What a reader hands to :meth:`~symdecomp.schemes.meshfile.PolygonMesh.from_parsed`."""

    #: ``(V, 3)`` float64, finite and within the bound.
    floats: np.ndarray
    #: ``exact_point(i)``: vertex ``i``'s exact coordinates.
    exact_point: object
    #: Face ``i`` is ``corners[offsets[i]:offsets[i + 1]]``.
    offsets: np.ndarray
    #: 0-based vertex indices, in range.
    corners: np.ndarray
    #: The tags read (OBJ only).
    tags: MeshTags | None = None
    #: ``(line, level)`` of each hierarchical edit read (OBJ only): left out of the mesh.
    edits: tuple[tuple[int, int], ...] = ()


class _Irregular(Exception):
    """The fast path met a line it does not take: the line-by-line reader decides."""


def number(token: str, where: str) -> Fraction:
    """A decimal token as the exact rational it spells, within the bounds (module docstring); else one line."""
    if len(token) > MAX_NUMBER_CHARS:
        raise InvalidMeshError(f"{where}: a number of {len(token)} characters (at most {MAX_NUMBER_CHARS})")
    if not _NUMBER.fullmatch(token):
        raise InvalidMeshError(f"{where}: {token[:30]!r} is not a finite decimal number")
    value = Fraction(token)
    if finite_double(value) is None:
        raise InvalidMeshError(f"{where}: {token[:30]} is beyond the range of doubles (a mesh coordinate is at most {MAX_COORDINATE:.4g} "
                               "in magnitude)")
    return value


def index(token: str, where: str, what: str = "vertex index") -> int:
    """An integer token (at most 12 digits); else one line (``1.7``, ``nan``, ``inf`` are not integers)."""
    if not _INDEX.fullmatch(token):
        raise InvalidMeshError(f"{where}: {what} {token[:30]!r} is not an integer")
    return int(token)


def _lines(data: bytes, name: str) -> list[bytes]:
    lines = data.split(b"\n")
    if len(data) > MAX_LINE_BYTES and max(map(len, lines)) > MAX_LINE_BYTES:
        k = next(i for i, line in enumerate(lines) if len(line) > MAX_LINE_BYTES)
        raise InvalidMeshError(f"{name}: line {k + 1} has more than {MAX_LINE_BYTES} bytes")
    return lines


def reading_progress(progress=None):
    """``wrap(iterable, total, what)`` for the line-by-line loops of the readers: ``progress`` with ``what`` as
    ``"reading lines"`` (``"reading faces"``), or the iterable itself when ``progress`` is None."""
    if progress is None:
        return lambda items, total, what: items
    return lambda items, total, what: progress(items, total, f"reading {what}")


def read_obj(data: bytes, name: str, wrap=None) -> ParsedMesh:
    """Parse an OBJ file's bytes (module docstring): fast on plain ``v`` and ``f`` lines, line by line otherwise
    (``wrap``: :func:`reading_progress`, around that loop)."""
    lines = _lines(data, name)
    try:
        return _fast(lines, name)
    except _Irregular:
        return _slow(lines, name, wrap)


def _fast(lines: list[bytes], name: str) -> ParsedMesh:
    vlines = [line for line in lines if line[:2] == b"v "]
    flines = [line for line in lines if line[:2] == b"f "]
    if not vlines:
        raise _Irregular  # the line reader says what is missing
    others = [(k, line) for k, line in enumerate(lines, 1) if not line.startswith((b"v ", b"f "))] if len(vlines) + len(flines) < len(lines) else []
    tags = _TagReader(name)
    for number_, line in others:
        words = line.split(b"#", 1)[0].decode("utf-8", "replace").split()
        if words and words[0] in ("v", "f"):
            raise _Irregular
        _other(words, f"{name}: line {number_}", tags)
    floats = _fast_vertices(vlines)
    offsets, corners = _fast_faces(flines, len(floats))
    return ParsedMesh(floats, _TextPoints(vlines), offsets, corners, tags.finish(len(floats), offsets, corners),
                      tuple(tags.edits))


def _fast_vertices(vlines: list[bytes]) -> np.ndarray:
    """``v x y z`` lines as a ``(V, 3)`` array: every line exactly 4 tokens, the numbers of the grammar, in the bound."""
    blob = b"\n".join(vlines)
    tokens = blob.split()
    count = len(vlines)
    if len(tokens) != 4 * count or tokens[::4].count(b"v") != count or tokens.count(b"v") != count:
        raise _Irregular
    if blob.translate(None, _NUMBER_BYTES + b"v \t\r\n\x0b\x0c") or (tokens and max(map(len, tokens)) > 40):
        raise _Irregular  # long numbers (up to the bound) and other characters: the line-by-line reader decides
    floats = np.empty((count, 3))
    for k in range(3):
        column = _numbers(b" ".join(tokens[k + 1::4]), np.float64)
        if len(column) != count:
            raise _Irregular
        floats[:, k] = column
    if not np.isfinite(floats).all():
        raise _Irregular
    return floats


def _numbers(text: bytes, dtype) -> np.ndarray:
    """The numbers of a checked text, parsed in C; any token it cannot read sends the file to the line reader."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            return np.fromstring(text, dtype=dtype, sep=" ")
        except (ValueError, DeprecationWarning):
            raise _Irregular from None


_SPACE = np.zeros(256, dtype=bool)
_SPACE[list(b" \t\r\n\x0b\x0c")] = True


def _fast_faces(flines: list[bytes], count: int) -> tuple[np.ndarray, np.ndarray]:
    """``f i j k ..`` lines (positive indices, ``i/t/n`` forms) as ``(offsets, corners)``."""
    blob = b"\n".join(flines)
    if blob.translate(None, b"0123456789/ \t\r\n\x0b\x0c") != b"f" * len(flines):
        raise _Irregular
    blob = blob.replace(b"f", b" ")
    if b"/" in blob:
        blob = re.sub(rb"/[0-9/]*", b"", blob)
    raw = np.frombuffer(blob, dtype=np.uint8)
    space = _SPACE[raw]
    starts = ~space & np.concatenate(([True], space[:-1]))
    line = np.searchsorted(np.flatnonzero(raw == 10), np.flatnonzero(starts))
    sizes = np.bincount(line, minlength=len(flines))
    offsets = np.zeros(len(flines) + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    corners = _numbers(blob, np.int64) - 1 if offsets[-1] else np.zeros(0, dtype=np.int64)
    if len(corners) != offsets[-1] or (len(corners) and (corners.min() < 0 or corners.max() >= count)):
        raise _Irregular
    return offsets, corners


class _TextPoints:
    """Exact coordinates of vertex ``i`` from its ``v`` line, on request."""

    def __init__(self, vlines: list[bytes]):
        self.vlines = vlines

    def __call__(self, i: int) -> tuple[Fraction, Fraction, Fraction]:
        return tuple(Fraction(t.decode("ascii")) for t in self.vlines[i].split(b"#", 1)[0].split()[1:4])


def _slow(lines: list[bytes], name: str, wrap=None) -> ParsedMesh:
    exact, faces, tags = [], [], _TagReader(name)
    for number_, raw in (wrap or reading_progress())(enumerate(lines, 1), len(lines), "lines"):
        line = raw.decode("utf-8", "replace")
        words = line.split("#", 1)[0].split()
        where = f"{name}: line {number_}"
        if words and words[0] == "v":
            if len(words) not in (4, 5):
                raise InvalidMeshError(f"{where}: a vertex needs 3 coordinates, got {len(words) - 1}")
            if len(words) == 5 and number(words[4], where) != 1:
                raise InvalidMeshError(f"{where}: a vertex with weight w = {words[4][:30]} (rational vertices) is not supported")
            exact.append(tuple(number(w, where) for w in words[1:4]))
        elif words and words[0] == "f":
            faces.append(_face(words[1:], len(exact), where))
        else:
            _other(words, where, tags)
    if not exact:
        raise InvalidMeshError(f"{name}: no vertices (no 'v' lines): not an OBJ mesh")
    for where, face in faces:
        bad = [i for i in face if i >= len(exact)]
        if bad:
            raise InvalidMeshError(f"{where}: vertex index {bad[0] + 1} is out of range (the file has {len(exact)} vertices)")
    floats = np.array([[float(c) for c in p] for p in exact], dtype=np.float64)
    offsets = np.zeros(len(faces) + 1, dtype=np.int64)
    np.cumsum([len(f) for _, f in faces], out=offsets[1:])
    corners = np.array([i for _, f in faces for i in f], dtype=np.int64)
    return ParsedMesh(floats, exact.__getitem__, offsets, corners, tags.finish(len(exact), offsets, corners),
                      tuple(tags.edits))


def _face(tokens: list[str], count: int, where: str) -> tuple[str, tuple[int, ...]]:
    corners = []
    for token in tokens:
        i = index(token.split("/", 1)[0], where)
        if i == 0:
            raise InvalidMeshError(f"{where}: vertex index 0 (OBJ indices start at 1)")
        if i < 0 and count + i < 0:
            raise InvalidMeshError(f"{where}: vertex index {i} is out of range ({count} vertices defined before this face)")
        corners.append(i - 1 if i > 0 else count + i)
    return where, tuple(corners)


def _other(words: list[str], where: str, tags: _TagReader) -> None:
    if not words or words[0] in IGNORED:
        return
    if words[0] == "t":
        tags.read(words[1:], where)
        return
    raise InvalidMeshError(f"{where}: unknown OBJ keyword {words[0][:20]!r} (it could change the surface; known: v, f, t and "
                           f"the ignored {', '.join(sorted(IGNORED))})")


def _edit_level(tag: str, ints: list[int], where: str) -> int:
    """The first refined level a hierarchical edit acts at: its paths are ``length, face, subface.., [vertex or edge]``
    (OpenSubdiv 2's ``shape_utils``), a face edit's path ending at a face, a vertex or edge edit's one element further."""
    levels, k = [], 0
    while k < len(ints):
        length = ints[k]
        if length < 1 + (tag != "faceedit") or k + 1 + length > len(ints):
            raise InvalidMeshError(f"{where}: tag {tag!r}: the path at integer {k + 1} does not fit its length {length}")
        levels.append(length - 1 - (tag != "faceedit"))
        k += 1 + length
    if not levels:
        raise InvalidMeshError(f"{where}: tag {tag!r} names no path")
    return min(levels)


class _TagReader:
    """OpenSubdiv's ``t`` lines, checked as read and, for the elements they name, once the faces are known."""

    def __init__(self, name: str):
        self.name = name
        self.creases: dict = {}
        self.corners: dict = {}
        self.holes: dict = {}
        self.options: dict = {}
        #: ``(line, level)`` of each hierarchical edit: left out of the mesh (module docstring).
        self.edits: list[tuple[int, int]] = []

    def read(self, words: list[str], where: str) -> None:
        if len(words) < 2:
            raise InvalidMeshError(f"{where}: a tag is 't NAME INTS/NUMBERS/WORDS ...'")
        tag, counts, args = words[0], words[1], words[2:]
        parts = counts.split("/")
        if len(parts) != 3 or not all(_INDEX.fullmatch(p) and int(p) >= 0 for p in parts):
            raise InvalidMeshError(f"{where}: tag {tag[:30]!r}: the counts {counts[:30]!r} are not INTS/NUMBERS/WORDS")
        ni, nf, ns = map(int, parts)
        if ni + nf + ns != len(args):
            raise InvalidMeshError(f"{where}: tag {tag[:30]!r} announces {ni + nf + ns} arguments and has {len(args)}")
        ints = [index(a, where, "tag argument") for a in args[:ni]]
        numbers = [number(a, where) for a in args[ni:ni + nf]]
        strings = args[ni + nf:]
        if tag in ("crease", "corner"):
            self._sharp(tag, ints, numbers, strings, where)
        elif tag == "hole" and ints and not numbers and not strings:
            self.holes.update((f, where) for f in ints)
        elif tag == "interpolateboundary" and len(ints) == 1 and ints[0] in _BOUNDARY and not numbers and not strings:
            self.options["interpolate_boundary"] = _BOUNDARY[ints[0]]
        elif tag in _OPTIONS and not ints and not numbers and len(strings) == 1 and strings[0] in _OPTIONS[tag][1]:
            self.options[_OPTIONS[tag][0]] = _OPTIONS[tag][1][strings[0]]
        elif tag in ("facevaryinginterpolateboundary", "facevaryingpropagatecorners") and len(ints) == 1 and not numbers:
            pass  # face-varying data (texture coordinates) only: the surface is the same
        elif tag in ("vertexedit", "edgeedit", "faceedit"):
            self.edits.append((int(where.rsplit(" ", 1)[1]), _edit_level(tag, ints, where)))
        elif tag in ("crease", "corner", "hole", "interpolateboundary", "creasemethod", "smoothtriangles",
                     "facevaryinginterpolateboundary", "facevaryingpropagatecorners"):
            raise InvalidMeshError(f"{where}: tag {tag!r} with arguments {counts} {' '.join(args)[:60]!r} is malformed "
                                   "(see the OBJ format page)")
        else:
            raise InvalidMeshError(f"{where}: unknown tag {tag[:30]!r} (known: crease, corner, hole, interpolateboundary, "
                                   "creasemethod, smoothtriangles, facevaryinginterpolateboundary, facevaryingpropagatecorners)")

    def _sharp(self, tag: str, ints: list[int], numbers: list[Fraction], strings: list[str], where: str) -> None:
        per = 2 if tag == "crease" else 1
        items = len(ints) // per
        if strings or not items or len(ints) % per or len(numbers) not in (1, items):
            raise InvalidMeshError(f"{where}: tag {tag!r} takes {'pairs of vertices' if per == 2 else 'vertices'} and one "
                                   f"sharpness, or one sharpness each; got {len(ints)} integers and {len(numbers)} numbers")
        negative = [s for s in numbers if s < 0]
        if negative:
            raise InvalidMeshError(f"{where}: tag {tag!r}: sharpness {float(negative[0]):g} is negative")
        for k in range(items):
            sharpness = numbers[k if len(numbers) > 1 else 0]
            if per == 2:
                u, v = ints[2 * k], ints[2 * k + 1]
                self.creases[(min(u, v), max(u, v))] = (sharpness, where)
            else:
                self.corners[ints[k]] = (sharpness, where)

    def finish(self, count: int, offsets: np.ndarray, corners: np.ndarray) -> MeshTags:
        """The tags, each element checked against the file's vertices and faces (one line naming the tag's line)."""
        for v, (_, where) in self.corners.items():
            if not 0 <= v < count:
                raise InvalidMeshError(f"{where}: tag 'corner': vertex {v} is out of range (the file has {count} vertices, 0..{count - 1})")
        faces = len(offsets) - 1
        for f, where in self.holes.items():
            if not 0 <= f < faces:
                raise InvalidMeshError(f"{where}: tag 'hole': face {f} is out of range (the file has {faces} faces, 0..{faces - 1})")
        if self.creases:
            self._check_edges(count, offsets, corners)
        return MeshTags(creases={e: s for e, (s, _) in self.creases.items()}, corners={v: s for v, (s, _) in self.corners.items()},
                        holes=frozenset(self.holes), **self.options)

    def _check_edges(self, count: int, offsets: np.ndarray, corners: np.ndarray) -> None:
        from symdecomp.schemes.mesh_topology import next_corners

        u, w = corners, corners[next_corners(offsets)[0]] if len(corners) else corners
        # sorted, not np.unique: numpy's hashing unique took 19 s on the 6.4 million edges of a 1.6 million-quad mesh
        edges = np.sort(np.minimum(u, w) * np.int64(count) + np.maximum(u, w))
        tagged = list(self.creases.items())
        keys = np.array([a * count + b if 0 <= a < count and 0 <= b < count else -1 for (a, b), _ in tagged], dtype=np.int64)
        found = edges[np.minimum(np.searchsorted(edges, keys), len(edges) - 1)] == keys if len(edges) else keys < -1
        if not found.all():
            (a, b), (_, where) = tagged[int(np.flatnonzero(~found)[0])]
            raise InvalidMeshError(f"{where}: tag 'crease': ({a}, {b}) is not an edge of a face of the file")
