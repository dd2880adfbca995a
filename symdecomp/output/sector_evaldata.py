"""The evaluation data file of crease, boundary and corner vertices (standard and BLZ rules): JSON.

``{"format": "sector-evaldata", "scheme", "lattice", "layout", "cells", "vertices": [...]}``, one vertex per line;
``cells`` the corners ``[a, b]`` of the twelve cells of a face's wide ring
(:data:`~symdecomp.analysis.sector_evaldata.CELLS`). Each vertex: ``{"kind", "sectors", "size", "labels", "exact",
"matrix", "limit", "modified", "cells", "decomposition"}``:

* ``kind`` ``"crease"``, ``"boundary"`` or ``"corner"``; ``sectors`` the faces of each sector (``[k1, k2]`` at a
  crease, ``[k]`` otherwise); ``labels[size]`` the ``(s, u, v)`` labels of the closed 2-ring, the control points
  ``C`` in :meth:`~symdecomp.schemes.sector.SharpVertex.ring_labels` order;
* ``exact``: ``true`` when every number is an exact rational ``"p"`` or ``"p/q"``; ``false`` when the rules'
  weights are irrational (BLZ's ``cos(pi/k)``, ``k >= 4``) and every number is an Arb ball ``"[m +/- r]"`` that
  contains the exact value (written at 256 bits; read back at that precision it still contains it);
* ``matrix[size]``: the sparse rows ``[[column, number], ...]`` of ``A``, the 2-ring's one-step matrix;
  ``limit[size]`` the limit position mask;
* ``modified``: the labels whose refinement rule is not the regular one (BLZ's near-edge points ``(s, 1, 0)``);
  the cells of the file are splines either way (they never read those points), and with ``modified`` empty the
  cells nearer to ``O`` (Stam's sub-patches) are splines too;
* ``cells[s][c]``: face ``s``, cell ``c``: the 16 sparse rows (net point ``(a - 1 + i, b - 1 + j)`` at row
  ``i + 4 j``) of the cell's bicubic B-spline net at level ``n`` over the 2-ring at level ``n - 2``;
* ``decomposition``: ``null`` (balls), or the eigen-decomposition over ``Q`` as a list of blocks ``{"factor",
  "multiplicity", "eigenvectors", "values", "basis", "block", "left"}``: ``factor`` the irreducible factor's integer
  coefficients (constant term first), ``values`` its roots as complex balls ``"[re +/- r] + [im +/- r]j"``,
  ``basis`` the sparse rows (``size`` of them) of ``W_i``, ``block`` those of ``B_i``, ``left`` those of the rows
  of ``W^-1`` for the block, with ``A W_i = W_i B_i``.

Evaluation (:mod:`symdecomp.analysis.sector_evaldata`; the ``layout`` string says it in one line): at
``(u, v) != (0, 0)`` in face ``s``, ``n >= 2`` with ``2 < 2^n max(u, v) <= 4``, ``(x, y) = 2^n (u, v)``, cell
``(a, b) = (min(floor x, 3), min(floor y, 3))``, ``point = sum_{i,j} N_i(x - a) N_j(y - b) (cells[s][c] A^(n-2) C)_{i+4j}``
(``N`` the uniform cubic B-spline basis; ``A^(n-2) C = sum_i W_i B_i^(n-2) left_i C``); at ``(0, 0)``: ``limit . C``.
:func:`sector_json_chunks` writes (streamed, one vertex at a time), :func:`read_sector_json` reads back.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator

import flint

from symdecomp.algebra.primary_decomposition import PrimaryBlock
from symdecomp.analysis.sector_evaldata import CELLS, PREC, SectorEvalData
from symdecomp.errors import EvalDataFileError, SymdecompError
from symdecomp.output.evaldata import document_chunks, load_document

__all__ = ["SECTOR_FORMAT", "SECTOR_LAYOUT", "sector_entry", "sector_json_chunks", "read_sector_json", "blocks_entry",
           "sparse_rows", "number_text", "read_number", "read_matrix", "read_blocks"]

SECTOR_FORMAT = "sector-evaldata"
#: The one-line layout note of a document.
SECTOR_LAYOUT = (
    "control points C: the closed 2-ring in labels order; face s has u along O->a_s, v along O->a_{s+1}; (u, v) != (0, 0): "
    "n >= 2 with 2 < 2^n max(u, v) <= 4, (x, y) = 2^n (u, v), cell (a, b) = (min(floor x, 3), min(floor y, 3)), "
    "point = sum N_i(x-a) N_j(y-b) (cells[s][c] A^(n-2) C)[i+4j], A = matrix = sum_i W_i B_i left_i (decomposition); "
    "(0, 0): limit . C"
)
_RATIONAL = re.compile(r"-?[0-9]{1,4000}(/[0-9]{1,4000})?", re.ASCII)
_BALL = re.compile(r"\[[-+0-9.e]{1,200} \+/- [0-9.e+-]{1,40}\]|[-+0-9.e]{1,200}", re.ASCII)


def number_text(x) -> str:
    if isinstance(x, flint.arb):
        return x.str(80, radius=True, more=True)
    return str(x)


def sparse_rows(m) -> list:
    return [[[c, number_text(m[i, c])] for c in range(m.ncols()) if m[i, c] != 0] for i in range(m.nrows())]


def complex_text(z) -> str:
    return f"{number_text(z.real)} + {number_text(z.imag)}j"


def blocks_entry(decomposition) -> list | None:
    """The eigen-decomposition over ``Q`` as the document's list of blocks (``None`` stays ``None``)."""
    return None if decomposition is None else [
        {"factor": [str(c) for c in b.factor], "multiplicity": b.multiplicity, "eigenvectors": b.eigenvectors,
         "values": [complex_text(z) for z in b.values], "basis": sparse_rows(b.basis), "block": sparse_rows(b.block),
         "left": sparse_rows(b.left)} for b in decomposition]


def sector_entry(data: SectorEvalData) -> dict:
    """One vertex of the document from :class:`~symdecomp.analysis.sector_evaldata.SectorEvalData`."""
    with flint.ctx.workprec(PREC):
        blocks = blocks_entry(data.decomposition)
        return {
            "kind": data.kind, "sectors": list(data.vertex.sectors), "size": data.size,
            "labels": [list(lab) for lab in data.vertex.ring_labels(2)], "exact": data.exact,
            "matrix": sparse_rows(data.matrix), "limit": [number_text(x) for x in data.limit],
            "modified": [list(lab) for lab in data.modified],
            "cells": [[sparse_rows(p) for p in face] for face in data.cells], "decomposition": blocks,
        }


def sector_json_chunks(entries: Iterable[dict], scheme: str, lattice: str) -> Iterator[str]:
    """The document piece by piece, one vertex per line (:func:`sector_entry` entries)."""
    head = {"format": SECTOR_FORMAT, "scheme": scheme, "lattice": lattice, "layout": SECTOR_LAYOUT,
            "cells": [list(c) for c in CELLS]}
    return document_chunks(head, "vertices", entries)


def read_number(text, exact: bool):
    if not isinstance(text, str) or not (_RATIONAL if exact else _BALL).fullmatch(text):
        raise ValueError(f"{str(text)[:40]!r} is not an {'exact rational p or p/q' if exact else 'Arb ball [m +/- r]'}")
    return flint.fmpq(*map(int, text.split("/"))) if exact else flint.arb(text)


def read_matrix(rows, ncols: int, exact: bool):
    out = (flint.fmpq_mat if exact else flint.arb_mat)(len(rows), ncols)
    for i, row in enumerate(rows):
        for c, w in row:
            if isinstance(c, bool) or not isinstance(c, int) or not 0 <= c < ncols:
                raise ValueError(f"column {str(c)[:20]} outside 0..{ncols - 1}")
            out[i, c] = read_number(w, exact)
    return out


def read_blocks(entry, size: int) -> tuple[PrimaryBlock, ...]:
    out = []
    for b in entry:
        factor = tuple(int(c) for c in b["factor"])
        d = (len(factor) - 1) * int(b["multiplicity"])
        values = tuple(flint.acb(*(flint.arb(t.strip()) for t in z[:-1].split(" + ", 1))) for z in b["values"])
        out.append(PrimaryBlock(factor, int(b["multiplicity"]), int(b["eigenvectors"]), read_matrix(b["basis"], d, True),
                                read_matrix(b["block"], d, True), read_matrix(b["left"], size, True), values))
    if sum(b.block.nrows() for b in out) != size:
        raise ValueError("the decomposition's blocks do not add up to the 2-ring")
    return tuple(out)


def _vertex(entry, lattice: str):
    from symdecomp.schemes.sector import SharpVertex

    kind, sectors = entry["kind"], [int(k) for k in entry["sectors"]]
    if kind == "crease" and len(sectors) == 2:
        return SharpVertex.crease(*sectors, lattice)
    if kind in ("boundary", "corner") and len(sectors) == 1:
        return getattr(SharpVertex, kind)(sectors[0], lattice)
    raise ValueError(f"kind {str(kind)[:20]!r} with sectors {sectors[:3]}")


def _data(entry, scheme: str, lattice: str) -> SectorEvalData:
    vertex, size, exact = _vertex(entry, lattice), int(entry["size"]), entry["exact"]
    if [tuple(lab) for lab in entry["labels"]] != list(vertex.ring_labels(2)) or not isinstance(exact, bool):
        raise ValueError(f"{vertex!r}: the labels do not match the 2-ring")
    cells = tuple(tuple(read_matrix(p, size, exact) for p in face) for face in entry["cells"])
    if len(cells) != vertex.faces or any(len(face) != len(CELLS) for face in cells):
        raise ValueError(f"{vertex!r}: need {vertex.faces} faces of {len(CELLS)} cells")
    limit = tuple(read_number(x, exact) for x in entry["limit"])
    blocks = None if entry["decomposition"] is None else read_blocks(entry["decomposition"], size)
    phi = None if blocks is None else tuple(tuple(tuple(p * b.basis for b in blocks) for p in face) for face in cells)
    modified = tuple(tuple(int(x) for x in lab) for lab in entry["modified"])
    return SectorEvalData(scheme, vertex, exact, read_matrix(entry["matrix"], size, exact), None, cells, limit, modified,
                          blocks, phi)


def read_sector_json(path) -> dict:
    """Read a document back: ``(kind, sectors)`` -> :class:`~symdecomp.analysis.sector_evaldata.SectorEvalData`."""
    doc = load_document(path, (SECTOR_FORMAT,), "a sector evaluation data document")
    out = {}
    try:
        if doc["cells"] != [list(c) for c in CELLS]:
            raise ValueError("the cells are not the wide ring's")
        with flint.ctx.workprec(PREC):
            for entry in doc["vertices"]:
                data = _data(entry, doc["scheme"], doc["lattice"])
                out[(data.kind, data.vertex.sectors)] = data
    except (KeyError, TypeError, ValueError, AttributeError, SymdecompError) as exc:
        raise EvalDataFileError(f"{path}: malformed sector evaluation data document ({exc})") from None
    return out
