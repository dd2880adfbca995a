"""Stam's eigen-data file for Catmull-Clark: the binary layout and a high-precision JSON form.

Binary (little-endian, no padding; a drop-in replacement for the published ``ccdata50NT.dat``)::

    int32 Nmax
    for N = 3 .. Nmax (K = 2N + 8):
        float64 val[K]; float64 vecI[K*K]  (element (i, j) at i + K*j)
        float64 Phi0[K*16], Phi1[K*16], Phi2[K*16]  (element (i, l) at i + K*l)

JSON: ``{"format": "stam-catmull-clark", "nmax", "digits", "valences": [{"n", "values",
"inverse", "phi": [Phi0, Phi1, Phi2]}]}``, arrays flattened in the binary file's element order,
every number a decimal string of ``digits`` significant digits.

Loop (JSON only; the binary layout is Catmull-Clark's): ``{"format": "stam-loop", "scheme",
"nmax", "digits", "layout", "valences": [{"n", "values", "inverse", "phi": [Phi0, Phi1, Phi2],
"jordan": [{"row", "column", "value"}]}]}`` with ``K = N + 6``: ``values[K]``; ``inverse[K*K]``
(``V^-1``, element ``(i, j)`` at ``i + K*j``); ``Phi_k[K*12]`` (element ``(i, l)`` at ``i + K*l``:
box-spline coefficient ``l`` of eigenfunction ``i`` on sub-patch ``k``); ``jordan`` lists the
entries ``N[row, column] = value`` of ``V^-1 A V = diag(values) + N`` (empty unless ``A`` is
not diagonalizable: Loop at ``N = 3``). Control points, sub-patches and the evaluation formula:
:mod:`symdecomp.schemes.patch` and :mod:`symdecomp.analysis.evaluation`; the
``layout`` string says the same in one line.

The command line writes these files (``symdecomp.cli.files``: checked first, replaced atomically,
devices and FIFOs written in place).
"""

from __future__ import annotations

import json
import struct
from collections.abc import Iterable

import flint
import numpy as np

from symdecomp.analysis.eigendata import PatchEigenData, RoundedEigenData
from symdecomp.errors import EvalDataFileError

__all__ = ["EvalDataFileError", "binary_bytes", "read_binary", "json_document", "read_json", "dumps"]

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
    for d in data:
        if d.phi.shape[-1] != 16 or d.jordan:
            raise EvalDataFileError(f"valence {d.n}: not Catmull-Clark data of a diagonalizable matrix; the binary layout cannot hold it")
    parts = [struct.pack("<i", data[-1].n)]
    for d in data:
        parts.append(np.asarray(d.values, "<f8").tobytes())
        parts.append(np.asarray(d.inverse, "<f8").ravel(order="F").tobytes())
        for k in range(3):
            parts.append(np.asarray(d.phi[k], "<f8").ravel(order="F").tobytes())
    return b"".join(parts)


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
        k = 2 * n + 8

        offset = pos
        values = np.frombuffer(raw, "<f8", k, offset)
        offset += 8 * k
        inverse = np.frombuffer(raw, "<f8", k * k, offset).reshape((k, k), order="F")
        offset += 8 * k * k
        phi = np.stack([np.frombuffer(raw, "<f8", 16 * k, offset + 8 * 16 * k * i).reshape((k, 16), order="F") for i in range(3)])
        pos = offset + 8 * 48 * k
        out[n] = RoundedEigenData(n, values.astype(float), inverse.astype(float), phi.astype(float))
    return out


def json_document(data: Iterable[PatchEigenData], digits: int, scheme: str | None = None) -> dict:
    """The JSON form: the Arb balls' midpoints to ``digits`` significant digits (balls must be that narrow).

    A ball that contains 0 and is narrower than ``10^-(digits + 20)`` is written ``"0"`` (the
    entries are of order 1; the exact zeros come from symmetries).
    """
    tiny = flint.arb(10) ** (-(digits + 20))

    def dec(x) -> str:
        if x.contains(0) and x.rad() < tiny:
            return "0"
        if x.rel_accuracy_bits() < digits * 3.33 + 4:
            raise EvalDataFileError(f"a ball is too wide for {digits} digits; raise the working precision")
        return x.str(digits, radius=False)

    valences = []
    ns, loop = [], False
    for d in data:
        ns.append(d.n)
        k, width = d.size, d.phi[0].ncols()
        loop = width == 12
        entry = {
            "n": d.n,
            "values": [dec(x) for x in d.values],
            "inverse": [dec(d.inverse[i, j]) for j in range(k) for i in range(k)],
            "phi": [[dec(t[i, l]) for l in range(width) for i in range(k)] for t in d.phi],
        }
        if loop:
            entry["jordan"] = [{"row": i, "column": c, "value": dec(g)} for i, c, g in d.jordan]
        elif d.jordan:
            raise EvalDataFileError(f"valence {d.n}: the Catmull-Clark layout has no place for a Jordan block")
        valences.append(entry)
    _check_sequence(ns)
    if loop:
        return {"format": LOOP_FORMAT, "scheme": scheme, "nmax": ns[-1], "digits": digits, "layout": LOOP_LAYOUT, "valences": valences}
    return {"format": FORMAT, "nmax": ns[-1], "digits": digits, "valences": valences}


def read_json(path) -> dict[int, RoundedEigenData]:
    """Read a JSON eigen-data document (either format) back as float64 arrays: valence -> arrays."""
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError) as exc:
        raise EvalDataFileError(f"cannot read {path}: {exc}") from None
    if not isinstance(doc, dict) or doc.get("format") not in (FORMAT, LOOP_FORMAT):
        raise EvalDataFileError(f"{path}: not an eigen-data document (format {FORMAT!r} or {LOOP_FORMAT!r})")
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


def dumps(document: dict) -> str:
    return json.dumps(document, indent=1) + "\n"
