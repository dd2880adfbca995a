"""Stam's eigen-data file for Catmull-Clark: the binary layout and a high-precision JSON form.

Binary (little-endian, no padding; a drop-in replacement for the published ``ccdata50NT.dat``)::

    int32 Nmax
    for N = 3 .. Nmax (K = 2N + 8):
        float64 val[K]; float64 vecI[K*K]  (element (i, j) at i + K*j)
        float64 Phi0[K*16], Phi1[K*16], Phi2[K*16]  (element (i, l) at i + K*l)

JSON: ``{"format": "stam-catmull-clark", "nmax", "digits", "valences": [{"n", "values",
"inverse", "phi": [Phi0, Phi1, Phi2]}]}``, arrays flattened in the binary file's element order,
every number a decimal string. ``"digits": 17`` (the default): each number is the correctly
rounded float64 of the exact value (one rounding, from the certified ball), written as the
shortest decimal that reads back as that float64 (Python's ``repr``; at most 17 significant
digits), so ``float(text)`` is the correctly rounded value and the binary file's number.
``"digits": D > 17``: each number is the exact value correctly rounded to ``D`` significant
digits (one rounding, from the ball), ``d.ddd...e+XX``; ``float()`` of it rounds a second time
and may then differ from the correctly rounded float64 (by one ulp, where the exact value is
within ``10^-D`` of a float64 rounding boundary). Exact zeros of the symmetries are ``"0"``.

Loop (JSON only; the binary layout is Catmull-Clark's): ``{"format": "stam-loop", "scheme",
"nmax", "digits", "layout", "valences": [{"n", "values", "inverse", "phi": [Phi0, Phi1, Phi2],
"jordan": [{"row", "column", "value"}]}]}`` with ``K = N + 6``: ``values[K]``; ``inverse[K*K]``
(``V^-1``, element ``(i, j)`` at ``i + K*j``); ``Phi_k[K*12]`` (element ``(i, l)`` at ``i + K*l``:
box-spline coefficient ``l`` of eigenfunction ``i`` on sub-patch ``k``, ``l`` in the order of
:data:`symdecomp.schemes.box_spline.BOX_POINTS`); ``jordan`` lists the
entries ``N[row, column] = value`` of ``V^-1 A V = diag(values) + N`` (empty unless ``A`` is
not diagonalizable: Loop at ``N = 3``). Control points, sub-patches and the evaluation formula:
:mod:`symdecomp.schemes.patch` and :mod:`symdecomp.analysis.evaluation`; the
``layout`` string says the same in one line. :func:`read_binary` and :func:`read_json` read the
files back.

Boundary and corner patches (JSON only, every number an exact rational ``"p"`` or ``"p/q"``):
``{"format": "sharp-patches", "scheme", "lattice", "layout", "vertices": [{"kind", "k", "size",
"labels", "matrix", "limit", "patches", "spectrum", "diagonalizable"}]}``, one vertex per line: ``kind`` ``"boundary"`` or
``"corner"``, ``k`` the faces of the open fan, ``labels[size]`` the ``(s, u, v)`` labels of the
closed 2-ring (the control points, in :meth:`~symdecomp.schemes.sector.SharpVertex.ring_labels`
order), ``matrix[size]`` the sparse rows ``[[column, weight], ...]`` of the 2-ring's subdivision
matrix ``A``, ``limit[size]`` the limit position mask, ``patches[s][j]`` (face ``s = 0..k-1``,
sub-patch ``j = 0, 1, 2``) the sparse rows of the sub-patch's 16 (quads) or 12 (triangles) control
points over the coarse 2-ring, ``spectrum`` the characteristic polynomial of ``A`` factored over Q,
``[{"factor", "multiplicity", "eigenvectors"}]`` (integer coefficients, constant term first; the
eigenvectors per root), and ``diagonalizable`` whether every factor has as many eigenvectors as its
multiplicity. The evaluation (powers of ``A``, not eigenvectors: ``A`` may be
defective) is :mod:`symdecomp.analysis.subpatch_data`'s; the ``layout`` string says it in one
line. :func:`sharp_json_chunks` writes, :func:`read_sharp_json` reads back.

The files are streamed valence by valence (:func:`binary_chunks`, :func:`json_chunks`: nothing
holds the whole file) through :mod:`symdecomp.cli.files` (checked first, replaced atomically,
devices and FIFOs written in place).
"""

from __future__ import annotations

import json
import re
import struct
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from fractions import Fraction

import flint
import numpy as np

from symdecomp.algebra.rounding import round_ball_decimal
from symdecomp.analysis.eigendata import ZERO_PREC, PatchEigenData, RoundedEigenData, patch_eigendata
from symdecomp.errors import EvalDataFileError, PrecisionError, SymdecompError
from symdecomp.validate import FLOAT_DIGITS

__all__ = [
    "EvalDataFileError", "FLOAT_DIGITS", "binary_bytes", "binary_chunks", "binary_valence", "BinaryValence", "read_binary",
    "read_binary_valence", "json_chunks",
    "json_valence", "json_valence_text", "EncodedValence",
    "decimal_valence", "read_json", "sharp_entry", "sharp_json_chunks", "read_sharp_json", "load_document",
    "document_chunks",
]


FORMAT = "stam-catmull-clark"
LOOP_FORMAT = "stam-loop"
#: The one-line layout note in a Loop document.
LOOP_LAYOUT = (
    "K = N+6 control points: O, a_0..a_{N-1} (ccw; the patch is (O, a_0, a_1)), then lattice points "
    "(2,-1), (2,0), (1,1), (0,2), (-1,2) in (u, v) with a_0 = (1,0), a_1 = (0,1); "
    "inverse[i + K*j] = (V^-1)[i][j]; phi[k][i + K*l] = box-spline coefficient l of eigenfunction i on sub-patch k "
    "(k = 0 at a_0, 1 middle (reversed), 2 at a_1); s = sum_i (J^(n-1) V^-1 C)_i sum_l phi[k][i, l] b_l(s, t), "
    "J = diag(values) + jordan"
)


def _check_sequence(ns: list[int]) -> None:
    if not ns or ns != list(range(3, 3 + len(ns))):
        raise EvalDataFileError(f"the file holds valences 3..Nmax in order, got {ns[:3]}...")


def binary_bytes(data: Iterable[RoundedEigenData]) -> bytes:
    """The binary file's content for the valences ``3..Nmax`` (in that order)."""
    data = list(data)
    _check_sequence([d.n for d in data])
    return b"".join(binary_chunks(data, data[-1].n))


@dataclass(frozen=True)
class BinaryValence:
    """One valence of the binary file already written as its bytes (:func:`binary_valence`)."""

    n: int
    """The valence."""
    data: bytes
    """The valence's piece of the file: eigenvalues, ``V^-1`` and the three sub-patch tables, little-endian."""
    jordan: bool = False
    """Always False: a valence with Jordan pairs has no binary layout (:func:`binary_valence` refuses it)."""


def binary_valence(d: RoundedEigenData) -> BinaryValence:
    """One valence's piece of the binary file (made where the valence is computed: a worker process, in parallel)."""
    if d.phi.shape[-1] != 16 or d.jordan:
        raise EvalDataFileError(f"valence {d.n}: not Catmull-Clark data of a diagonalizable matrix; the binary layout cannot hold it")
    return BinaryValence(int(d.n), b"".join([
        np.asarray(d.values, "<f8").tobytes(),
        np.asarray(d.inverse, "<f8").ravel(order="F").tobytes(),
        *(np.asarray(d.phi[k], "<f8").ravel(order="F").tobytes() for k in range(3)),
    ]))


def binary_chunks(data: Iterable[RoundedEigenData | BinaryValence], nmax: int) -> Iterator[bytes]:
    """The binary file piece by piece: ``Nmax``, then one piece per valence as ``data`` yields it (3..nmax in order;
    the arrays, or their bytes from :func:`binary_valence`)."""
    yield struct.pack("<i", nmax)
    ns = []
    for d in data:
        ns.append(d.n)
        if d.n != len(ns) + 2:
            _check_sequence(ns)
        yield (d if isinstance(d, BinaryValence) else binary_valence(d)).data
    if not ns or ns[-1] != nmax:
        _check_sequence(ns + [nmax + 1] if ns else [])


def read_binary(path) -> dict[int, RoundedEigenData]:
    """Read a binary eigen-data file back: valence -> arrays (``inverse[i, j]``, ``phi[k, i, l]``)."""
    try:
        with open(path, "rb") as fh:
            raw = fh.read()
    except OSError as exc:
        raise EvalDataFileError(f"cannot read {path}: {exc.strerror}") from None
    if len(raw) < 4:
        raise EvalDataFileError(f"{path}: too short for an eigen-data file")
    (nmax,) = struct.unpack_from("<i", raw, 0)
    expected = 4 + 8 * sum((2 * n + 8) * (1 + (2 * n + 8) + 48) for n in range(3, nmax + 1)) if nmax >= 3 else -1
    if len(raw) != expected:
        raise EvalDataFileError(f"{path}: {len(raw)} bytes, but Nmax = {nmax} needs {expected}")
    out, pos = {}, 4
    for n in range(3, nmax + 1):
        out[n], pos = read_binary_valence(n, raw, pos)
    return out


def read_binary_valence(n: int, raw: bytes, offset: int = 0) -> tuple[RoundedEigenData, int]:
    """Valence ``n``'s piece of the binary file (module docstring) read from ``raw`` at ``offset``: its arrays, and the
    offset where the next piece starts. The one decoder of the layout :func:`binary_valence` writes."""
    k = 2 * n + 8
    if len(raw) < offset + 8 * k * (1 + k + 48):
        raise EvalDataFileError(f"valence {n}: {len(raw) - offset} bytes, but its piece needs {8 * k * (1 + k + 48)}")
    values = np.frombuffer(raw, "<f8", k, offset)
    offset += 8 * k
    inverse = np.frombuffer(raw, "<f8", k * k, offset).reshape((k, k), order="F")
    offset += 8 * k * k
    phi = np.stack([np.frombuffer(raw, "<f8", 16 * k, offset + 8 * 16 * k * i).reshape((k, 16), order="F") for i in range(3)])
    return RoundedEigenData(n, values.astype(float), inverse.astype(float), phi.astype(float)), offset + 8 * 48 * k


def json_valence(d: RoundedEigenData) -> dict:
    """One valence of the JSON form from the correctly rounded float64 arrays (``"digits": 17``): shortest round-trip text."""
    width = d.phi.shape[-1]
    entry = {
        "n": d.n,
        "values": list(map(repr, d.values.tolist())),
        "inverse": list(map(repr, d.inverse.ravel(order="F").tolist())),
        "phi": [list(map(repr, d.phi[k].ravel(order="F").tolist())) for k in range(3)],
    }
    if width == 12:
        entry["jordan"] = [{"row": i, "column": c, "value": repr(float(g))} for i, c, g in d.jordan]
    elif d.jordan:
        raise EvalDataFileError(f"valence {d.n}: the Catmull-Clark layout has no place for a Jordan block")
    return entry


@dataclass(frozen=True)
class EncodedValence:
    """One valence of the JSON form already written as text (:func:`json_valence_text`)."""

    n: int
    """The valence."""
    loop: bool
    """Whether it has Loop's layout (a ``"jordan"`` list)."""
    text: str
    """``json.dumps(json_valence(d), separators=(",", ":"))``, character for character."""
    jordan: bool = False
    """Whether the valence carries Jordan pairs (its matrix is not diagonalizable)."""


def _array_texts(arrays: list[np.ndarray]) -> list[str]:
    """Each array's float64s as a JSON array of their shortest round-trip strings (``repr``), the arrays in turn.

    Each distinct float64 (by its bits: ``-0.0`` is not ``0.0``) is formatted once; the tables repeat few values
    (a mirror's and the rotations' copies), about one in ten is distinct. The strings need no escaping, so each
    array is joined at once instead of each string quoted by the JSON encoder.
    """
    flat = [np.ascontiguousarray(a, dtype="<f8").ravel() for a in arrays]
    bits, where = np.unique(np.concatenate(flat).view("<i8"), return_inverse=True)
    texts = np.array(list(map(float.__repr__, bits.view("<f8").tolist())), dtype=object)[where.ravel()].tolist()
    out, start = [], 0
    for a in flat:
        out.append('["' + '","'.join(texts[start:start + a.size]) + '"]' if a.size else "[]")
        start += a.size
    return out


def json_valence_text(d: RoundedEigenData) -> EncodedValence:
    """:func:`json_valence` as its compact JSON text, written in bulk (the same characters as ``json.dumps`` of it)."""
    width = d.phi.shape[-1]
    if width != 12 and d.jordan:
        raise EvalDataFileError(f"valence {d.n}: the Catmull-Clark layout has no place for a Jordan block")
    values, inverse, *phi = _array_texts([d.values, np.asarray(d.inverse).T, *(np.asarray(d.phi[k]).T for k in range(3))])
    parts = [f'{{"n":{int(d.n)},"values":', values, ',"inverse":', inverse, f',"phi":[{",".join(phi)}]']
    if width == 12:
        pairs = ",".join(f'{{"row":{int(i)},"column":{int(c)},"value":"{float(g)!r}"}}' for i, c, g in d.jordan)
        parts.append(f',"jordan":[{pairs}]')
    parts.append("}")
    return EncodedValence(int(d.n), width == 12, "".join(parts), bool(d.jordan))


def decimal_valence(scheme, n: int, digits: int, max_prec: int = 1 << 14) -> tuple[int, dict]:
    """``(precision, entry)``: one valence of the JSON form at ``digits > 17`` significant digits.

    Every number is the exact value correctly rounded to ``digits`` digits in one step from its
    Arb ball (:func:`~symdecomp.algebra.rounding.round_ball_decimal`), at the lowest precision
    from ``max(1200, 3.33 digits + 64)`` bits (doubling) where every ball rounds; exact zeros of
    the symmetries (balls inside ``(-2^-1075, 2^-1075)``) are ``"0"``.
    """
    prec = max(ZERO_PREC, int(3.33 * digits) + 64)
    while True:
        try:
            data = patch_eigendata(scheme, n, prec)
            with flint.ctx.workprec(prec):
                entry = _decimal_entry(data, digits)
        except PrecisionError:
            entry = None
        if entry is not None:
            return prec, entry
        if prec >= max_prec:
            raise PrecisionError(f"valence {n}: the eigen-data did not round to {digits} digits at {prec} bits")
        prec *= 2


def _decimal_entry(d: PatchEigenData, digits: int) -> dict | None:
    width = d.phi[0].ncols()
    order = lambda m: [m[i, j] for j in range(m.ncols()) for i in range(m.nrows())]  # noqa: E731 - column-major
    groups = [list(d.values), order(d.inverse), *(order(t) for t in d.phi), [g for *_, g in d.jordan]]
    texts = []
    for balls in groups:
        texts.append([round_ball_decimal(x, digits) for x in balls])
        if None in texts[-1]:
            return None
    entry = {"n": d.n, "values": texts[0], "inverse": texts[1], "phi": texts[2:5]}
    if width == 12:
        entry["jordan"] = [{"row": i, "column": c, "value": v} for (i, c, _), v in zip(d.jordan, texts[5])]
    elif d.jordan:
        raise EvalDataFileError(f"valence {d.n}: the Catmull-Clark layout has no place for a Jordan block")
    return entry


def json_chunks(entries: Iterable[dict | EncodedValence], nmax: int, digits: int, scheme: str | None = None) -> Iterator[str]:
    """The JSON document piece by piece, one valence per line, from :func:`json_valence` entries (or their text,
    :func:`json_valence_text`, or the decimal ones of :func:`decimal_valence`) for ``3..nmax`` in order.

    The format (Catmull-Clark or Loop) follows from the first valence: 12 box-spline coefficients
    per sub-patch (Loop, with ``"jordan"``) or 16 (Catmull-Clark).
    """
    ns = []
    for entry in entries:
        encoded = isinstance(entry, EncodedValence)
        ns.append(entry.n if encoded else entry["n"])
        if ns[-1] != len(ns) + 2:
            _check_sequence(ns)
        if len(ns) == 1:
            loop = entry.loop if encoded else "jordan" in entry
            head = {"format": LOOP_FORMAT, "scheme": scheme} if loop else {"format": FORMAT}
            head.update({"nmax": nmax, "digits": digits})
            if loop:
                head["layout"] = LOOP_LAYOUT
            yield json.dumps(head)[:-1] + ', "valences": [\n'
        yield ("" if len(ns) == 1 else ",\n") + (entry.text if encoded else json.dumps(entry, separators=(",", ":")))
    if not ns or ns[-1] != nmax:
        _check_sequence(ns + [nmax + 1] if ns else [])
    yield "\n]}\n"


def load_document(path, formats: tuple[str, ...], what: str) -> dict:
    """The JSON object in ``path`` whose ``format`` is one of ``formats``; else one line naming the file (``what``: the kind)."""
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError) as exc:
        raise EvalDataFileError(f"cannot read {path}: {exc}") from None
    if not isinstance(doc, dict) or doc.get("format") not in formats:
        raise EvalDataFileError(f"{path}: not {what} (format {' or '.join(map(repr, formats))})")
    return doc


def read_json(path) -> dict[int, RoundedEigenData]:
    """Read a JSON eigen-data document (either format) back as float64 arrays: valence -> arrays."""
    doc = load_document(path, (FORMAT, LOOP_FORMAT), "an eigen-data document")
    width = 12 if doc["format"] == LOOP_FORMAT else 16
    out = {}
    try:
        for v in doc["valences"]:
            values = np.array([float(x) for x in v["values"]])
            k = values.size
            inverse = np.array([float(x) for x in v["inverse"]]).reshape((k, k), order="F")
            phi = np.stack([np.array([float(x) for x in t]).reshape((k, width), order="F") for t in v["phi"]])
            jordan = tuple((int(j["row"]), int(j["column"]), float(j["value"])) for j in v.get("jordan", ()))
            out[int(v["n"])] = RoundedEigenData(int(v["n"]), values, inverse, phi, jordan)
    except (KeyError, TypeError, ValueError) as exc:
        raise EvalDataFileError(f"{path}: malformed eigen-data document ({exc})") from None
    return out




SHARP_FORMAT = "sharp-patches"
#: The one-line layout note in a boundary/corner document.
SHARP_LAYOUT = (
    "control points C: the closed 2-ring in labels order (O, a_0..a_k, [b_0..b_{k-1}], then (s, u, v) ring 2); "
    "face s has u along O->a_s, v along O->a_{s+1}; (u, v) != (0, 0): n = level, (x, y) = 2^n (u, v), sub-patch j "
    "and local (s', t') as the interior patch; point = b(s', t') . patches[s][j] . A^(n-1) C with A = matrix "
    "(b: bicubic B-spline l = a + 4 b, or the 12 box-spline functions); (0, 0): limit . C"
)
_RATIONAL = re.compile(r"-?[0-9]{1,4000}(/[0-9]{1,4000})?", re.ASCII)


def _text(x) -> str:
    return str(x)


def _sparse(rows) -> list:
    return [[[c, _text(w)] for c, w in sorted(row.items())] for row in rows]


def sharp_entry(data) -> dict:
    """One vertex of the boundary/corner document from :class:`~symdecomp.analysis.subpatch_data.SharpPatchData`."""
    return {
        "kind": data.kind, "k": data.faces, "size": data.size,
        "labels": [list(lab) for lab in data.vertex.ring_labels(2)],
        "matrix": _sparse(data.matrix), "limit": [_text(x) for x in data.limit],
        "patches": [[_sparse(sub) for sub in face] for face in data.patches],
        "spectrum": [{"factor": [str(c) for c in q], "multiplicity": e, "eigenvectors": g} for q, e, g in data.spectrum],
        "diagonalizable": data.diagonalizable,
    }


def sharp_json_chunks(entries: Iterable[dict], scheme: str, lattice: str) -> Iterator[str]:
    """The boundary/corner JSON document piece by piece, one vertex per line (:func:`sharp_entry` entries)."""
    head = {"format": SHARP_FORMAT, "scheme": scheme, "lattice": lattice, "layout": SHARP_LAYOUT}
    return document_chunks(head, "vertices", entries)


def document_chunks(head: dict, key: str, entries: Iterable[dict]) -> Iterator[str]:
    """A JSON document ``head`` plus the list ``key`` of ``entries``, streamed piece by piece, one entry per line (the
    sharp, sector and dual evaluation data files: nothing holds the whole document)."""
    yield json.dumps(head)[:-1] + f', "{key}": [\n'
    for i, entry in enumerate(entries):
        yield ("" if i == 0 else ",\n") + json.dumps(entry, separators=(",", ":"))
    yield "\n]}\n"


def _fraction(text) -> Fraction:
    if not isinstance(text, str) or not _RATIONAL.fullmatch(text):
        raise ValueError(f"{str(text)[:40]!r} is not an exact rational p or p/q")
    return Fraction(text)


def _integer(text) -> int:
    x = _fraction(text)
    if x.denominator != 1:
        raise ValueError(f"{text!r} is not an integer")
    return int(x)


def _rows(rows, size: int) -> tuple[dict, ...]:
    out = []
    for row in rows:
        entry = {}
        for c, w in row:
            if isinstance(c, bool) or not isinstance(c, int) or not 0 <= c < size:
                raise ValueError(f"column {str(c)[:20]} outside 0..{size - 1}")
            entry[c] = _fraction(w)
        out.append(entry)
    return tuple(out)


def read_sharp_json(path) -> dict:
    """Read a boundary/corner document back: ``(kind, k)`` -> :class:`~symdecomp.analysis.subpatch_data.SharpPatchData`."""
    from symdecomp.analysis.subpatch_data import SharpPatchData
    from symdecomp.schemes.sector import SharpVertex

    doc = load_document(path, (SHARP_FORMAT,), "a boundary/corner eigen-data document")
    out = {}
    try:
        for v in doc["vertices"]:
            kind, k, size = v["kind"], int(v["k"]), int(v["size"])
            if kind not in ("boundary", "corner"):
                raise ValueError(f"kind {str(kind)[:20]!r}")
            vertex = getattr(SharpVertex, kind)(k, doc["lattice"])
            if [tuple(lab) for lab in v["labels"]] != list(vertex.ring_labels(2)) or len(v["matrix"]) != size:
                raise ValueError(f"{kind} k = {k}: labels or matrix do not match the 2-ring")
            patches = tuple(tuple(_rows(sub, size) for sub in face) for face in v["patches"])
            limit = tuple(_fraction(x) for x in v["limit"])
            if len(patches) != k or any(len(face) != 3 for face in patches) or len(limit) != size:
                raise ValueError(f"{kind} k = {k}: need {k} faces of 3 sub-patches and {size} mask weights")
            spectrum = tuple((tuple(_integer(c) for c in f["factor"]), int(f["multiplicity"]), int(f["eigenvectors"]))
                             for f in v["spectrum"])
            data = SharpPatchData(doc["scheme"], vertex, _rows(v["matrix"], size), patches, limit, spectrum)
            if sum((len(q) - 1) * e for q, e, _ in spectrum) != size or data.diagonalizable is not v["diagonalizable"]:
                raise ValueError(f"{kind} k = {k}: the spectrum's degrees or diagonalizable do not match")
            out[(kind, k)] = data
    except (KeyError, TypeError, ValueError, SymdecompError) as exc:
        raise EvalDataFileError(f"{path}: malformed boundary/corner document ({exc})") from None
    return out
