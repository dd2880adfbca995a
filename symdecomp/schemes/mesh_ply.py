"""PLY mesh files (ASCII and binary, either byte order) read with their header checked before anything is allocated.

The header (``ply``, ``format ascii|binary_little_endian|binary_big_endian 1.0``, ``element NAME COUNT``,
``property TYPE NAME``, ``property list COUNT_TYPE INDEX_TYPE NAME``, ``comment``/``obj_info`` lines,
``end_header``) is parsed here; the counts it announces are checked against the size of the data that
follows (every element takes at least its fixed-size properties in binary, two bytes per property in
ASCII) before any array is made, so a lying header is refused in one line, never allocated. The
``vertex`` element needs ``x``, ``y``, ``z``; the ``face`` element a list ``vertex_indices`` (or
``vertex_index``) of an integer type: a float index type, a float, ``nan`` or ``inf`` token in an ASCII
index list is refused, never truncated. Coordinates: finite, of magnitude at most
:data:`~symdecomp.validate.MAX_COORDINATE`; in ASCII, a decimal is the rational it spells, in binary a
float is its exact value. Other elements and properties are skipped. Truncated data is refused.

>>> text = (b"ply\\nformat ascii 1.0\\nelement vertex 3\\nproperty float x\\nproperty float y\\nproperty float z\\n"
...         b"element face 1\\nproperty list uchar int vertex_indices\\nend_header\\n0 0 0\\n1 0 0\\n0 1 0.5\\n3 0 1 2\\n")
>>> m = read_ply(text, "t.ply")
>>> m.corners.tolist(), m.exact_point(2)
([0, 1, 2], (Fraction(0, 1), Fraction(1, 1), Fraction(1, 2)))
>>> read_ply(text.replace(b"face 1", b"face 300000000"), "t.ply")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
symdecomp.errors.InvalidMeshError: t.ply: not a readable PLY file: the header announces 300000000 'face' elements, more ...
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from symdecomp.errors import InvalidMeshError
from symdecomp.schemes.mesh_obj import ParsedMesh, index, number, reading_progress
from symdecomp.validate import INPUT_LIMITS, MAX_COORDINATE, MESH_ADVICE, check_memory, mesh_memory

__all__ = ["read_ply"]

_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
          "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}
_FORMATS = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}
_MAX_HEADER = INPUT_LIMITS["mesh, PLY: bytes of the header"][0]


@dataclass
class _Property:
    name: str
    kind: str  # numpy type code, e.g. "f4"
    count: str | None = None  # the list's count type, None for a scalar


@dataclass
class _Element:
    name: str
    count: int
    properties: list


def read_ply(data: bytes, name: str, wrap=None) -> ParsedMesh:
    """Parse a PLY file's bytes (module docstring); ``wrap`` (:func:`~symdecomp.schemes.mesh_obj.reading_progress`)
    goes around the loop over an ASCII file's list elements (its faces), the one loop element by element."""
    fmt, elements, body = _header(data, name)
    _check_counts(elements, len(data) - body, fmt, name)
    counts = {e.name: e.count for e in elements}
    check_memory(len(data) + mesh_memory(corners=3 * counts.get("face", 0), faces=counts.get("face", 0), vertices=counts.get("vertex", 0)),
                 f"{name}: a PLY mesh of {counts.get('vertex', 0)} vertices and {counts.get('face', 0)} faces", MESH_ADVICE)
    reader = _Ascii(data, body, name, wrap or reading_progress()) if fmt is None else _Binary(data, body, fmt, name)
    found = {}
    for element in elements:
        found[element.name] = reader.element(element, keep=element.name in ("vertex", "face") and element.name not in found)
    reader.finish()
    if "vertex" not in found or "face" not in found:
        raise InvalidMeshError(f"{name}: a PLY mesh needs 'vertex' and 'face' elements, the file has {[e.name for e in elements]}")
    floats, exact = found["vertex"]
    offsets, corners = found["face"]
    bad = np.flatnonzero((corners < 0) | (corners >= len(floats)))
    if len(bad):
        i = int(np.searchsorted(offsets, bad[0], side="right") - 1)
        raise InvalidMeshError(f"{name}: face {i}: vertex index {int(corners[bad[0]])} is out of range (the file has {len(floats)} "
                               f"vertices, 0..{len(floats) - 1})")
    return ParsedMesh(floats, exact, offsets, corners)


def _header(data: bytes, name: str) -> tuple[str | None, list[_Element], int]:
    end = data.find(b"end_header", 0, _MAX_HEADER)
    if not data.startswith(b"ply") or end < 0:
        raise InvalidMeshError(f"{name}: not a readable PLY file (it must start with 'ply' and have 'end_header' within {_MAX_HEADER} bytes)")
    body = data.find(b"\n", end) + 1 or len(data)
    lines = data[:end].decode("ascii", "replace").splitlines()[1:]
    fmt, elements = "missing", []
    for k, line in enumerate(lines, 2):
        words, where = line.split(), f"{name}: header line {k}"
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format" and len(words) == 3 and words[1] in _FORMATS and words[2] == "1.0":
            fmt = _FORMATS[words[1]]
        elif words[0] == "element" and len(words) == 3:
            elements.append(_Element(words[1], index(words[2], where, "element count"), []))
            if elements[-1].count < 0:
                raise InvalidMeshError(f"{where}: element count {elements[-1].count} is negative")
        elif words[0] == "property" and elements and len(words) == 3 and words[1] in _TYPES:
            elements[-1].properties.append(_Property(words[2], _TYPES[words[1]]))
        elif words[0] == "property" and elements and len(words) == 5 and words[1] == "list" and words[2] in _TYPES and words[3] in _TYPES:
            if _TYPES[words[2]][0] == "f":
                raise InvalidMeshError(f"{where}: a list's count type must be an integer type, got {words[2]}")
            elements[-1].properties.append(_Property(words[4], _TYPES[words[3]], _TYPES[words[2]]))
        else:
            raise InvalidMeshError(f"{where}: {line.strip()[:60]!r} is not a PLY header line this reader takes")
    if fmt == "missing":
        raise InvalidMeshError(f"{name}: the PLY header has no 'format ascii|binary_little_endian|binary_big_endian 1.0' line")
    return fmt, elements, body


def _check_counts(elements: list[_Element], size: int, fmt: str | None, name: str) -> None:
    """Refuse a header whose counts the data cannot hold, before anything is allocated."""
    need = 0
    for e in elements:
        per = sum(2 for _ in e.properties) if fmt is None else sum(np.dtype(p.count or p.kind).itemsize for p in e.properties)
        need += e.count * max(per, 1 if fmt is None else 0)
        if need > size:
            raise InvalidMeshError(f"{name}: not a readable PLY file: the header announces {e.count} {e.name!r} elements, more than "
                                   f"the {size} bytes of data after it can hold")


def _vertex_arrays(columns: dict, element: _Element, name: str, exact=None):
    missing = [c for c in "xyz" if c not in columns]
    if missing:
        raise InvalidMeshError(f"{name}: the PLY vertex element has no property {missing[0]!r}")
    floats = np.stack([np.asarray(columns[c], dtype=np.float64) for c in "xyz"], axis=1).reshape(-1, 3)
    bad = np.flatnonzero(~np.isfinite(floats).all(axis=1))
    if len(bad):
        raise InvalidMeshError(f"{name}: vertex {bad[0]}: coordinates {floats[bad[0]].tolist()} are not finite numbers of magnitude at "
                               f"most {MAX_COORDINATE:g}")
    return floats, exact


def _face_list(element: _Element, name: str) -> str:
    lists = [p.name for p in element.properties if p.count and p.name in ("vertex_indices", "vertex_index")]
    if not lists:
        raise InvalidMeshError(f"{name}: the PLY face element has no 'vertex_indices' list")
    prop = next(p for p in element.properties if p.name == lists[0])
    if prop.kind[0] == "f":
        raise InvalidMeshError(f"{name}: the face list {prop.name!r} has a float type; vertex indices must be integers")
    return lists[0]


class _Binary:
    """Elements of a binary PLY body: scalar elements and uniform face lists as numpy views, others face by face."""

    def __init__(self, data: bytes, pos: int, order: str, name: str):
        self.data, self.pos, self.order, self.name = data, pos, order, name

    def _take(self, dtype, count: int, what: str) -> np.ndarray:
        dtype = np.dtype(dtype)
        if self.pos + dtype.itemsize * count > len(self.data):
            raise InvalidMeshError(f"{self.name}: not a readable PLY file: the binary data ends inside the {what} (truncated file)")
        out = np.frombuffer(self.data, dtype=dtype, count=count, offset=self.pos)
        self.pos += dtype.itemsize * count
        return out

    def element(self, e: _Element, keep: bool):
        if all(p.count is None for p in e.properties):
            block = self._take([(f"p{i}", self.order + p.kind) for i, p in enumerate(e.properties)], e.count, f"{e.name!r} elements")
            if keep and e.name == "vertex":
                return _vertex_arrays({p.name: block[f"p{i}"] for i, p in enumerate(e.properties)}, e, self.name)
            if keep:
                _face_list(e, self.name)
            return None
        listed = _face_list(e, self.name) if keep and e.name == "face" else None
        if keep and e.name == "vertex":
            raise InvalidMeshError(f"{self.name}: the PLY vertex element has a list property; x, y, z must be scalars")
        if listed and len(e.properties) == 1 and e.count:
            uniform = self._uniform(e.properties[0], e.count)
            return uniform if uniform is not None else self._scan(e.properties[0], e.count)
        return self._loop(e, listed)

    def _scan(self, p: _Property, count: int):
        """Faces of several sizes: the counts read in one pass, the indices gathered by numpy."""
        csize, isize = np.dtype(p.count).itemsize, np.dtype(p.kind).itemsize
        code = {"u1": "B", "i1": "b", "u2": "H", "i2": "h", "u4": "I", "i4": "i"}[p.count]
        unpack, data, pos, end = struct.Struct(self.order + code).unpack_from, self.data, self.pos, len(self.data)
        sizes = np.empty(count, dtype=np.int64)
        for i in range(count):
            if pos + csize > end:
                break
            k = data[pos] if code == "B" else unpack(data, pos)[0]
            if k < 0:
                raise InvalidMeshError(f"{self.name}: face {i}: the list {p.name!r} has {k} entries")
            sizes[i] = k
            pos += csize + k * isize
            if pos > end:
                break
        else:
            i = count
        if i < count:
            raise InvalidMeshError(f"{self.name}: not a readable PLY file: the binary data ends inside the face {i} (truncated file)")
        offsets = np.zeros(count + 1, dtype=np.int64)
        np.cumsum(sizes, out=offsets[1:])
        first = self.pos + csize * np.arange(1, count + 1) + isize * offsets[:-1]  # each face's first index
        at = np.repeat(first - isize * offsets[:-1], sizes) + isize * np.arange(int(offsets[-1]))
        raw = np.frombuffer(data, dtype=np.uint8)
        values = raw[at[:, None] + np.arange(isize)].copy().view(self.order + p.kind).reshape(-1)
        self.pos = pos
        return offsets, values.astype(np.int64)

    def _uniform(self, p: _Property, count: int):
        csize, isize = np.dtype(p.count).itemsize, np.dtype(p.kind).itemsize
        if self.pos + csize > len(self.data):
            return None
        k = int(np.frombuffer(self.data, dtype=self.order + p.count, count=1, offset=self.pos)[0])
        if k < 0 or self.pos + (csize + k * isize) * count > len(self.data):
            return None  # the face by face scan names what is wrong
        dtype = np.dtype([("n", self.order + p.count), ("v", self.order + p.kind, (k,))])
        block = np.frombuffer(self.data, dtype=dtype, count=count, offset=self.pos)
        if not (block["n"] == k).all():
            return None
        self.pos += dtype.itemsize * count
        return np.arange(0, k * count + 1, max(k, 1), dtype=np.int64)[: count + 1], block["v"].astype(np.int64).reshape(-1)

    def _loop(self, e: _Element, listed: str | None):
        sizes, values = [], []
        for i in range(e.count):
            for p in e.properties:
                if p.count is None:
                    self._take(self.order + p.kind, 1, f"{e.name} {i}")
                    continue
                k = int(self._take(self.order + p.count, 1, f"{e.name} {i}")[0])
                if k < 0:
                    raise InvalidMeshError(f"{self.name}: {e.name} {i}: the list {p.name!r} has {k} entries")
                entries = self._take(self.order + p.kind, k, f"{e.name} {i}")
                if p.name == listed:
                    sizes.append(k)
                    values.append(entries.astype(np.int64))
        if listed is None:
            return None
        offsets = np.zeros(len(sizes) + 1, dtype=np.int64)
        np.cumsum(sizes, out=offsets[1:])
        return offsets, np.concatenate(values) if values else np.zeros(0, dtype=np.int64)

    def finish(self) -> None:
        """Trailing bytes after the last element are allowed (some writers pad)."""


class _Ascii:
    """Elements of an ASCII PLY body, token by token (numbers checked as in OBJ, indices integers only)."""

    def __init__(self, data: bytes, pos: int, name: str, wrap):
        self.tokens, self.pos, self.name, self.wrap = data[pos:].split(), 0, name, wrap

    def _take(self, count: int, what: str) -> list[bytes]:
        if self.pos + count > len(self.tokens):
            raise InvalidMeshError(f"{self.name}: not a readable PLY file: the data ends inside the {what} (truncated file)")
        out = self.tokens[self.pos:self.pos + count]
        self.pos += count
        return out

    def element(self, e: _Element, keep: bool):
        if all(p.count is None for p in e.properties):
            width = len(e.properties)
            block = self._take(width * e.count, f"{e.name!r} elements")
            if keep and e.name == "vertex":
                columns = {p.name: block[i::width] for i, p in enumerate(e.properties)}
                return self._vertices(columns, e)
            if keep:
                _face_list(e, self.name)
            return None
        listed = _face_list(e, self.name) if keep and e.name == "face" else None
        if keep and e.name == "vertex":
            raise InvalidMeshError(f"{self.name}: the PLY vertex element has a list property; x, y, z must be scalars")
        sizes, values = [], []
        for i in self.wrap(range(e.count), e.count, f"{e.name}s"):
            where = f"{self.name}: {e.name} {i}"
            for p in e.properties:
                k = 1 if p.count is None else index(self._take(1, f"{e.name} {i}")[0].decode("ascii", "replace"), where, "list length")
                if k < 0:
                    raise InvalidMeshError(f"{where}: the list {p.name!r} has {k} entries")
                entries = self._take(k, f"{e.name} {i}")
                if p.name == listed:
                    sizes.append(k)
                    values.extend(index(t.decode("ascii", "replace"), where) for t in entries)
        if listed is None:
            return None
        offsets = np.zeros(len(sizes) + 1, dtype=np.int64)
        np.cumsum(sizes, out=offsets[1:])
        return offsets, np.array(values, dtype=object if any(abs(v) >= 2**62 for v in values) else np.int64).astype(np.int64)

    def _vertices(self, columns: dict, e: _Element):
        missing = [c for c in "xyz" if c not in columns]
        if missing:
            raise InvalidMeshError(f"{self.name}: the PLY vertex element has no property {missing[0]!r}")
        xyz = [columns[c] for c in "xyz"]
        exact = _TokenPoints(xyz)
        try:
            if b"".join(b"".join(c) for c in xyz).translate(None, b"0123456789+-.eE"):
                raise ValueError
            floats = np.stack([np.array(c, dtype=np.float64) for c in xyz], axis=1).reshape(-1, 3)
        except ValueError:
            for i in range(len(xyz[0])):
                exact.checked(i, f"{self.name}: vertex {i}")
            raise  # pragma: no cover - the loop above names the bad token
        return _vertex_arrays({c: floats[:, k] for k, c in enumerate("xyz")}, e, self.name, exact)

    def finish(self) -> None:
        if self.pos < len(self.tokens):
            raise InvalidMeshError(f"{self.name}: {len(self.tokens) - self.pos} tokens after the last element announced by the header")


class _TokenPoints:
    """Exact coordinates of vertex ``i`` from its ASCII tokens, on request."""

    def __init__(self, columns: list):
        self.columns = columns

    def checked(self, i: int, where: str) -> tuple[Fraction, Fraction, Fraction]:
        return tuple(number(c[i].decode("ascii", "replace"), where) for c in self.columns)

    def __call__(self, i: int) -> tuple[Fraction, Fraction, Fraction]:
        return tuple(Fraction(c[i].decode("ascii")) for c in self.columns)
