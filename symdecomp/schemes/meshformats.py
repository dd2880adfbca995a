"""Polygon mesh files: OBJ, OFF and PLY read into a :class:`~symdecomp.schemes.meshfile.PolygonMesh` and written back.

Faces keep their sides (a quad stays a quad, an n-gon an n-gon) and their order, in all three
formats; every problem is one line naming the file and the line or element
(:class:`~symdecomp.errors.InvalidMeshError`; exit status 2 on the command line).

**Reading discipline.** :func:`read_mesh` takes a regular file only (a FIFO, device or directory is
refused from its status, before it is opened for reading; the file is then opened without blocking
and checked again), or ``-`` for standard input (give ``fmt``). At most
:data:`~symdecomp.validate.MAX_MESH_FILE_BYTES` bytes are read, whatever size the file system reports
(a device reports 0), and the memory that reading will take is estimated from the size
(:func:`~symdecomp.validate.mesh_memory`) and refused before it is allocated when it does not fit.
``progress(iterable, total, what)``, when given, wraps the loops that read a text file element by element or line
by line (an ASCII PLY's faces, an OFF file, an OBJ that its fast path does not take: negative indices, vertex
weights; the command line's progress display); the rest (binary PLY, the OBJ fast path) is read with numpy in one pass.

**Lenient by default.** ``read_mesh(path, strict=False)`` and ``decode_mesh(..., strict=False)`` keep
the valid rest of a mesh with non-manifold edges or vertices, degenerate or repeated faces and
isolated vertices, and list them in :attr:`~symdecomp.schemes.meshfile.PolygonMesh.defects` (in the
file's numbering: vertex ``i`` of the file is vertex ``i`` of the mesh); ``strict=True`` refuses the
first one (the rules: :mod:`symdecomp.schemes.mesh_topology`). A file that cannot be read (bad
syntax, indices out of range, numbers beyond the bounds, a lying PLY header, truncated data) is
refused in both modes.

**Why these readers.** OBJ (:mod:`symdecomp.schemes.mesh_obj`, with OpenSubdiv's ``t`` tags) and OFF
are line-oriented text, parsed by a strict grammar (never evaluated) that reads a coordinate such as
``0.1`` as the exact rational it spells (``1/10``) and names the line of a bad token. PLY
(:mod:`symdecomp.schemes.mesh_ply`) is read by this package so that its header's counts are checked
against the file's size before anything is allocated, and written by ``plyfile``. The alternatives
were tried: meshio 5.3 reads OFF files of triangles only and silently drops the quads of a mixed mesh
when writing OFF; trimesh triangulates every face; openmesh (1.2, 2022) has no wheel for current
Pythons and repairs non-manifold input silently, which hides the elements this module must name.

OFF: the keyword ``OFF``, the counts ``V F E``, ``V`` lines ``x y z`` and ``F`` lines ``k i_1 .. i_k``
(0-based), ``#`` comments. Numbers as in OBJ (:mod:`symdecomp.schemes.mesh_obj`): decimals of at most
:data:`~symdecomp.validate.MAX_NUMBER_CHARS` characters and magnitude at most
:data:`~symdecomp.validate.MAX_COORDINATE`.

Writing (:func:`encode_mesh`): coordinates that are terminating decimals of at most
:data:`~symdecomp.validate.MAX_NUMBER_CHARS` characters (every double of the mesh bound, every decimal
read from text) are written exactly in OBJ and OFF; any other rational is rounded to the nearest double,
as PLY (doubles) always does, so that what is written is read back. Output is deterministic (no dates,
no comments beyond the format's own). The command line writes files through its atomic writer; this
module only encodes and decodes bytes. Tags are not written.

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
>>> raw = b"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nv 0 0 1\\nf 1 2 3\\nf 1 2 4\\nf 2 1 3\\n"
>>> m = decode_mesh(raw, "obj")   # face 2 repeats face 0; faces 0 and 1 both run 0 -> 1
>>> m.defects.repeated_faces, m.defects.misoriented_edges, m.defects.isolated_vertices, m.faces
((2,), ((0, 1),), (3,), ((0, 1, 2),))
"""

from __future__ import annotations

import io
import os
import stat
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_obj import ParsedMesh, _lines, index, number, read_obj, reading_progress
from symdecomp.schemes.mesh_ply import read_ply
from symdecomp.schemes.meshfile import PolygonMesh
from symdecomp.validate import MAX_MESH_FILE_BYTES, MAX_NUMBER_CHARS, MESH_ADVICE, MESH_FORMATS, check_memory, mesh_memory

__all__ = ["FORMATS", "mesh_format", "read_mesh", "decode_mesh", "encode_mesh"]

#: The file formats, by extension (lower case, without the dot).
FORMATS = MESH_FORMATS
#: Largest mesh file read (bytes); the same as :data:`~symdecomp.validate.MAX_MESH_FILE_BYTES`.
MAX_FILE_BYTES = MAX_MESH_FILE_BYTES


def mesh_format(path, fmt: str | None = None) -> str:
    """The format of ``path``: ``fmt`` if given, else its extension; one of :data:`FORMATS`."""
    if fmt is None:
        fmt = Path(os.fspath(path)).suffix.lstrip(".").lower()
        if fmt not in FORMATS:
            raise InvalidMeshError(f"{os.fspath(path)}: unknown mesh format {fmt!r} (the extension must be one of {', '.join(FORMATS)})")
    if fmt not in FORMATS:
        raise InvalidMeshError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r:.40}")
    return fmt


def read_mesh(path, fmt: str | None = None, *, strict: bool = False, progress=None) -> PolygonMesh:
    """Read and check a mesh file (a regular file, or ``-`` for standard input with ``fmt``); errors name the file
    (its name as given) and the element. ``strict=False`` keeps the valid rest (module docstring)."""
    if not isinstance(path, (str, os.PathLike)):
        raise InvalidMeshError(f"path must be a file name, got {type(path).__name__}")
    name = os.fspath(path)
    if not isinstance(name, str):
        raise InvalidMeshError(f"path must be a file name as text, got {name!r:.60}")
    if name == "-":
        if fmt is None:
            raise InvalidMeshError("-: give the format (obj, off or ply) to read a mesh from standard input")
        data = _capped(sys.stdin.buffer, "-")
        return decode_mesh(data, mesh_format(name, fmt), name="<stdin>", strict=strict, progress=progress)
    fmt = mesh_format(path, fmt)
    return decode_mesh(_read_regular(name), fmt, name=Path(name).name, strict=strict, progress=progress)


def _read_regular(name: str) -> bytes:
    """The bytes of the regular file ``name``, at most the limit; a FIFO or device is refused without blocking."""
    try:
        kind = os.stat(name).st_mode
        if not stat.S_ISREG(kind):
            raise InvalidMeshError(f"{name}: not a regular file ({_kind(kind)}); a mesh is read from a regular file or '-'")
        fd = os.open(name, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise InvalidMeshError(f"{name}: cannot read the file ({exc.strerror or exc})") from None
    with os.fdopen(fd, "rb") as handle:
        status = os.fstat(handle.fileno())
        if not stat.S_ISREG(status.st_mode):  # replaced between the two looks
            raise InvalidMeshError(f"{name}: not a regular file ({_kind(status.st_mode)})")
        if status.st_size > MAX_MESH_FILE_BYTES:  # the file bound first: it, not the memory, is what the file is past
            raise InvalidMeshError(f"{name}: more than {MAX_MESH_FILE_BYTES} bytes, the limit of a mesh file")
        check_memory(mesh_memory(file_bytes=min(status.st_size, MAX_MESH_FILE_BYTES)), f"{name}: reading a mesh file of {status.st_size} "
                     "bytes", MESH_ADVICE)  # PLY: checked again from its header's counts
        return _capped(handle, name)


def _kind(mode: int) -> str:
    for test, what in ((stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISDIR, "a directory"), (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return what
    return "not a regular file"


def _capped(handle, name: str) -> bytes:
    try:
        data = handle.read(MAX_MESH_FILE_BYTES + 1)
    except OSError as exc:
        raise InvalidMeshError(f"{name}: cannot read the file ({exc.strerror or exc})") from None
    if len(data) > MAX_MESH_FILE_BYTES:
        raise InvalidMeshError(f"{name}: more than {MAX_MESH_FILE_BYTES} bytes, the limit of a mesh file")
    return data


def decode_mesh(data: bytes, fmt: str, *, name: str = "mesh", strict: bool = False, progress=None) -> PolygonMesh:
    """Parse the bytes of a mesh file of format ``fmt`` and check the mesh (``strict``, ``progress``: module docstring)."""
    if not isinstance(data, (bytes, bytearray)):
        raise InvalidMeshError(f"{name}: the data must be bytes, got {type(data).__name__}")
    if not isinstance(name, str):
        raise InvalidMeshError(f"name must be a string, got {type(name).__name__}")
    if len(data) > MAX_MESH_FILE_BYTES:
        raise InvalidMeshError(f"{name}: more than {MAX_MESH_FILE_BYTES} bytes, the limit of a mesh file")
    fmt = mesh_format(name, fmt)
    if fmt != "ply":  # PLY: from its header's counts (mesh_ply)
        check_memory(mesh_memory(file_bytes=len(data)), f"{name}: reading a mesh file of {len(data)} bytes", MESH_ADVICE)
    data = bytes(data)
    if fmt != "ply" and not data.isascii():
        try:
            data.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise InvalidMeshError(f"{name}: not a text file (byte {exc.start} is not UTF-8)") from None
    wrap = reading_progress(progress)
    parsed = read_ply(data, name, wrap) if fmt == "ply" else read_obj(data, name, wrap) if fmt == "obj" else _read_off(data, name, wrap)
    return PolygonMesh.from_parsed(parsed.floats, parsed.exact_point, parsed.offsets, parsed.corners, name=name, tags=parsed.tags,
                                   strict=strict, edits=parsed.edits)


def _off_lines(lines: list[bytes]):
    for number_, line in enumerate(lines, 1):
        words = line.decode("utf-8", "replace").split("#", 1)[0].split()
        if words:
            yield number_, words


def _read_off(data: bytes, name: str, wrap) -> ParsedMesh:
    raw = _lines(data, name)
    lines = _off_lines(wrap(raw, len(raw), "lines"))
    number_, words = next(lines, (0, []))
    if not words or words[0] != "OFF":
        raise InvalidMeshError(f"{name}: line {number_ or 1}: the file must start with the keyword OFF")
    words = words[1:] or next(lines, (number_, []))[1]
    if len(words) != 3 or not all(w.isdigit() and len(w) <= 12 for w in words):
        raise InvalidMeshError(f"{name}: after OFF the counts 'vertices faces edges' (three non-negative integers) are expected")
    nv, nf = int(words[0]), int(words[1])
    points, sizes, corners = [], [], []
    for number_, words in lines:
        where = f"{name}: line {number_}"
        if len(points) < nv:
            if len(words) != 3:
                raise InvalidMeshError(f"{where}: a vertex needs 3 coordinates, got {len(words)}")
            points.append(tuple(number(w, where) for w in words))
        elif len(sizes) < nf:
            k = index(words[0], where, "corner count")
            if k != len(words) - 1:
                raise InvalidMeshError(f"{where}: the face says it has {k} corners but lists {len(words) - 1}")
            face = [index(w, where) for w in words[1:]]
            bad = [i for i in face if not 0 <= i < nv]
            if bad:
                raise InvalidMeshError(f"{where}: vertex index {bad[0]} is out of range (the file has {nv} vertices, 0..{nv - 1})")
            sizes.append(k)
            corners += face
        else:
            raise InvalidMeshError(f"{where}: more lines than the header's {nv} vertices and {nf} faces")
    if len(points) < nv or len(sizes) < nf:
        raise InvalidMeshError(f"{name}: the header announces {nv} vertices and {nf} faces, the file has {len(points)} and {len(sizes)} "
                               "(truncated file)")
    offsets = np.zeros(len(sizes) + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    floats = np.array([[float(c) for c in p] for p in points], dtype=np.float64).reshape(-1, 3)
    return ParsedMesh(floats, points.__getitem__, offsets, np.array(corners, dtype=np.int64))


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
    if twos + fives > MAX_NUMBER_CHARS or abs(x.numerator).bit_length() > 4 * MAX_NUMBER_CHARS:
        return repr(float(x))
    places = max(twos, fives)
    digits = str(abs(x.numerator) * 10**places // x.denominator).rjust(places + 1, "0")
    whole, frac = digits[: len(digits) - places], digits[len(digits) - places :].rstrip("0")
    text = ("-" if x < 0 else "") + whole + ("." + frac if frac else "")
    return text if len(text) <= MAX_NUMBER_CHARS else repr(float(x))


def encode_mesh(mesh: PolygonMesh, fmt: str) -> bytes:
    """The bytes of ``mesh`` as an OBJ, OFF or (binary little-endian) PLY file."""
    if not isinstance(mesh, PolygonMesh):
        raise InvalidMeshError(f"mesh must be a PolygonMesh, got {type(mesh).__name__}")
    fmt = mesh_format("", fmt)
    if fmt == "ply":
        return _ply_bytes(mesh)
    coords = ["%s %s %s" % tuple(_decimal(c) for c in mesh.exact_point(v)) for v in range(len(mesh.points_array))]
    if fmt == "obj":
        lines = [f"v {c}" for c in coords] + ["f " + " ".join(str(v + 1) for v in f) for f in mesh.faces]
    else:
        lines = ["OFF", f"{len(mesh.points_array)} {len(mesh.faces)} 0"] + coords + [" ".join(map(str, (len(f),) + f)) for f in mesh.faces]
    return ("\n".join(lines) + "\n").encode("ascii")


def _ply_bytes(mesh: PolygonMesh) -> bytes:
    import plyfile

    vertices = np.empty(len(mesh.points_array), dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8")])
    for k, c in enumerate("xyz"):
        vertices[c] = mesh.points_array[:, k]
    count = "u1" if max(len(f) for f in mesh.faces) < 256 else "u4"
    faces = np.empty(len(mesh.faces), dtype=[("vertex_indices", object)])
    faces["vertex_indices"] = [np.array(f, dtype="<i4") for f in mesh.faces]
    elements = [plyfile.PlyElement.describe(vertices, "vertex"),
                plyfile.PlyElement.describe(faces, "face", len_types={"vertex_indices": count}, val_types={"vertex_indices": "i4"})]
    out = io.BytesIO()
    plyfile.PlyData(elements, text=False, byte_order="<").write(out)
    return out.getvalue()
