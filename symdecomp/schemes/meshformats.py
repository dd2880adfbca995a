"""Polygon mesh files: OBJ, OFF and PLY read into a :class:`~symdecomp.schemes.meshfile.PolygonMesh` and written back.

Faces keep their sides (a quad stays a quad, an n-gon an n-gon) and their order, in all three
formats; every problem is one line naming the file and the line or element.

**Why these readers.** OBJ and OFF are line-oriented text: they are parsed here by a strict
grammar (never evaluated), which reads a coordinate such as ``0.1`` as the exact rational it
spells (``1/10``), so that limit positions of a mesh with decimal coordinates come out exactly,
and names the line of a bad token. PLY, with its binary encodings and typed header, is read and
written by ``plyfile`` (a maintained library that keeps each face's list of indices as it is:
quads and n-gons survive, in order). The alternatives were tried: meshio 5.3 reads OFF files of
triangles only and silently drops the quads of a mixed mesh when writing OFF; trimesh
triangulates every face; openmesh (1.2, 2022) has no wheel for current Pythons and repairs
non-manifold input silently, which hides the elements this module must name.

Text grammar: OBJ lines ``v x y z`` (an optional fourth coordinate must be 1) and ``f i j k ...``
(``i``, ``i/t``, ``i/t/n`` or ``i//n``; 1-based, negative indices count back from the last
vertex), ``#`` comments, other keywords (``vt``, ``vn``, ``g``, ``o``, ``s``, ``usemtl``,
``mtllib``) ignored; OFF: the keyword ``OFF``, the counts ``V F E``, ``V`` lines ``x y z`` and
``F`` lines ``k i_1 .. i_k`` (0-based). A number is a decimal ``[+-]digits[.digits][e[+-]digits]``
(at most 4 exponent digits); ``nan``, ``inf`` and hexadecimal are refused.

Writing (:func:`encode_mesh`): coordinates that are terminating decimals (every double, every
decimal read from text) are written exactly in OBJ and OFF; any other rational is rounded to the
nearest double, as PLY (doubles) always does. Output is deterministic (no dates, no comments
beyond the format's own). The command line writes files through its atomic writer; this module
only encodes and decodes bytes.

>>> from symdecomp.schemes.meshfile import PolygonMesh
>>> m = PolygonMesh.from_arrays([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 2, 0)], [(0, 1, 2, 3), (3, 2, 4)])
>>> print(encode_mesh(m, "obj").decode())
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0.5 2 0
f 1 2 3 4
f 4 3 5
<BLANKLINE>
>>> all(decode_mesh(encode_mesh(m, f), f) .faces == m.faces for f in FORMATS)
True
"""

from __future__ import annotations

import io
import os
import re
from fractions import Fraction
from pathlib import Path

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.meshfile import PolygonMesh

__all__ = ["FORMATS", "mesh_format", "read_mesh", "decode_mesh", "encode_mesh"]

#: The file formats, by extension (lower case, without the dot).
FORMATS = ("obj", "off", "ply")
#: Largest mesh file read (bytes): the exact coordinates cost about a kilobyte per vertex.
MAX_FILE_BYTES = 64 * 2**20

_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]{1,4})?", re.ASCII)
_INDEX = re.compile(r"[+-]?[0-9]{1,10}", re.ASCII)
_IGNORED_OBJ = {"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p"}


def mesh_format(path, fmt: str | None = None) -> str:
    """The format of ``path``: ``fmt`` if given, else its extension; one of :data:`FORMATS`."""
    if fmt is None:
        fmt = Path(os.fspath(path)).suffix.lstrip(".").lower()
        if fmt not in FORMATS:
            raise InvalidMeshError(f"{os.fspath(path)}: unknown mesh format {fmt!r} (the extension must be one of {', '.join(FORMATS)})")
    if fmt not in FORMATS:
        raise InvalidMeshError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    return fmt


def read_mesh(path, fmt: str | None = None) -> PolygonMesh:
    """Read and validate a mesh file; errors name the file (its name as given) and the element."""
    if not isinstance(path, (str, os.PathLike)):
        raise InvalidMeshError(f"path must be a file name, got {type(path).__name__}")
    name = os.fspath(path)
    fmt = mesh_format(path, fmt)
    try:
        size = os.path.getsize(path)
        if size > MAX_FILE_BYTES:
            raise InvalidMeshError(f"{name}: the file has {size} bytes, more than the limit of {MAX_FILE_BYTES}")
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError as exc:
        raise InvalidMeshError(f"{name}: cannot read the file ({exc.strerror or exc})") from None
    return decode_mesh(data, fmt, name=Path(name).name)


def decode_mesh(data: bytes, fmt: str, *, name: str = "mesh") -> PolygonMesh:
    """Parse the bytes of a mesh file of format ``fmt`` and validate the mesh."""
    if not isinstance(data, (bytes, bytearray)):
        raise InvalidMeshError(f"{name}: the data must be bytes, got {type(data).__name__}")
    fmt = mesh_format(name, fmt)
    if fmt == "ply":
        points, faces = _read_ply(bytes(data), name)
    else:
        try:
            text = bytes(data).decode("utf-8")
        except UnicodeDecodeError as exc:
            raise InvalidMeshError(f"{name}: not a text file (byte {exc.start} is not UTF-8)") from None
        points, faces = (_read_obj if fmt == "obj" else _read_off)(text, name)
    return PolygonMesh.from_arrays(points, faces, name=name)


def _number(token: str, where: str) -> Fraction:
    if not _NUMBER.fullmatch(token):
        raise InvalidMeshError(f"{where}: {token[:30]!r} is not a finite decimal number")
    return Fraction(token)


def _index(token: str, where: str) -> int:
    if not _INDEX.fullmatch(token):
        raise InvalidMeshError(f"{where}: vertex index {token[:30]!r} is not an integer")
    return int(token)


def _read_obj(text: str, name: str) -> tuple[list, list]:
    points, faces = [], []
    for number, line in enumerate(text.splitlines(), 1):
        words = line.split("#", 1)[0].split()
        if not words or words[0] in _IGNORED_OBJ:
            continue
        where = f"{name}: line {number}"
        if words[0] == "v":
            if len(words) not in (4, 5):
                raise InvalidMeshError(f"{where}: a vertex needs 3 coordinates, got {len(words) - 1}")
            if len(words) == 5 and _number(words[4], where) != 1:
                raise InvalidMeshError(f"{where}: a vertex with weight w = {words[4]} (rational vertices) is not supported")
            points.append(tuple(_number(w, where) for w in words[1:4]))
        elif words[0] == "f":
            faces.append(_obj_face(words[1:], len(points), where))
        else:
            raise InvalidMeshError(f"{where}: unknown OBJ keyword {words[0][:20]!r} (expected v, f or one of {', '.join(sorted(_IGNORED_OBJ))})")
    if not points:
        raise InvalidMeshError(f"{name}: no vertices (no 'v' lines): not an OBJ mesh")
    return points, faces


def _obj_face(tokens: list[str], count: int, where: str) -> tuple[int, ...]:
    corners = []
    for token in tokens:
        i = _index(token.split("/", 1)[0], where)
        if i == 0:
            raise InvalidMeshError(f"{where}: vertex index 0 (OBJ indices start at 1)")
        k = i - 1 if i > 0 else count + i
        if not 0 <= k < count:
            raise InvalidMeshError(f"{where}: vertex index {i} is out of range ({count} vertices defined so far)")
        corners.append(k)
    return tuple(corners)


def _off_lines(text: str):
    for number, line in enumerate(text.splitlines(), 1):
        words = line.split("#", 1)[0].split()
        if words:
            yield number, words


def _read_off(text: str, name: str) -> tuple[list, list]:
    lines = _off_lines(text)
    number, words = next(lines, (0, []))
    if not words or words[0] != "OFF":
        raise InvalidMeshError(f"{name}: line {number or 1}: the file must start with the keyword OFF")
    words = words[1:] or next(lines, (number, []))[1]
    if len(words) != 3 or not all(_INDEX.fullmatch(w) and int(w) >= 0 for w in words):
        raise InvalidMeshError(f"{name}: after OFF the counts 'vertices faces edges' (three non-negative integers) are expected")
    nv, nf = int(words[0]), int(words[1])
    points, faces = [], []
    for number, words in lines:
        where = f"{name}: line {number}"
        if len(points) < nv:
            if len(words) != 3:
                raise InvalidMeshError(f"{where}: a vertex needs 3 coordinates, got {len(words)}")
            points.append(tuple(_number(w, where) for w in words))
        elif len(faces) < nf:
            k = _index(words[0], where)
            if k != len(words) - 1:
                raise InvalidMeshError(f"{where}: the face says it has {k} corners but lists {len(words) - 1}")
            faces.append(tuple(_index(w, where) for w in words[1:]))
        else:
            raise InvalidMeshError(f"{where}: more lines than the header's {nv} vertices and {nf} faces")
    if len(points) < nv or len(faces) < nf:
        raise InvalidMeshError(f"{name}: the header announces {nv} vertices and {nf} faces, the file has {len(points)} and {len(faces)} "
                               "(truncated file)")
    return points, faces


def _read_ply(data: bytes, name: str) -> tuple[list, list]:
    import plyfile

    try:
        ply = plyfile.PlyData.read(io.BytesIO(data))
    except Exception as exc:  # noqa: BLE001 - plyfile raises many kinds (PlyParseError, ValueError, struct errors) on bad input
        message = " ".join(str(exc).split()) or type(exc).__name__
        raise InvalidMeshError(f"{name}: not a readable PLY file ({message[:200]})") from None
    names = [e.name for e in ply.elements]
    if "vertex" not in names or "face" not in names:
        raise InvalidMeshError(f"{name}: a PLY mesh needs 'vertex' and 'face' elements, the file has {names}")
    vertex, face = ply["vertex"], ply["face"]
    missing = [c for c in "xyz" if c not in vertex.data.dtype.names]
    if missing:
        raise InvalidMeshError(f"{name}: the PLY vertex element has no property {missing[0]!r}")
    lists = [p for p in ("vertex_indices", "vertex_index") if p in face.data.dtype.names]
    if not lists:
        raise InvalidMeshError(f"{name}: the PLY face element has no 'vertex_indices' list")
    points = [tuple(row) for row in zip(*(vertex.data[c].tolist() for c in "xyz"))]
    faces = [tuple(int(v) for v in f) for f in face.data[lists[0]]]
    return points, faces


def _decimal(x: Fraction) -> str:
    """``x`` exactly as a decimal when it terminates (denominator 2^a 5^b), else the nearest double."""
    d = x.denominator
    twos = fives = 0
    while d % 2 == 0:
        d, twos = d // 2, twos + 1
    while d % 5 == 0:
        d, fives = d // 5, fives + 1
    if d != 1:
        return repr(float(x))
    places = max(twos, fives)
    digits = str(abs(x.numerator) * 10**places // x.denominator).rjust(places + 1, "0")
    whole, frac = digits[: len(digits) - places], digits[len(digits) - places :].rstrip("0")
    return ("-" if x < 0 else "") + whole + ("." + frac if frac else "")


def encode_mesh(mesh: PolygonMesh, fmt: str) -> bytes:
    """The bytes of ``mesh`` as an OBJ, OFF or (binary little-endian) PLY file."""
    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    fmt = mesh_format("", fmt)
    if fmt == "ply":
        return _ply_bytes(mesh)
    coords = ["%s %s %s" % tuple(_decimal(c) for c in p) for p in mesh.points]
    if fmt == "obj":
        lines = [f"v {c}" for c in coords] + ["f " + " ".join(str(v + 1) for v in f) for f in mesh.faces]
    else:
        lines = ["OFF", f"{len(mesh.points)} {len(mesh.faces)} 0"] + coords + [" ".join(map(str, (len(f),) + f)) for f in mesh.faces]
    return ("\n".join(lines) + "\n").encode("ascii")


def _ply_bytes(mesh: PolygonMesh) -> bytes:
    import numpy as np
    import plyfile

    vertices = np.array([tuple(float(c) for c in p) for p in mesh.points], dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8")])
    count = "u1" if max(len(f) for f in mesh.faces) < 256 else "u4"
    faces = np.empty(len(mesh.faces), dtype=[("vertex_indices", object)])
    faces["vertex_indices"] = [np.array(f, dtype="<i4") for f in mesh.faces]
    elements = [plyfile.PlyElement.describe(vertices, "vertex"),
                plyfile.PlyElement.describe(faces, "face", len_types={"vertex_indices": count}, val_types={"vertex_indices": "i4"})]
    out = io.BytesIO()
    plyfile.PlyData(elements, text=False, byte_order="<").write(out)
    return out.getvalue()
