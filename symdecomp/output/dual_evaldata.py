"""The evaluation data file of extraordinary faces of a dual quad scheme (Doo-Sabin's biquadratic B-spline): JSON.

``{"format": "dual-evaldata", "scheme", "lattice", "layout", "cells", "faces": [...]}``, one face per line; ``cells``
the corners ``[a, b]`` of the three cells of a sector's ring (:data:`~symdecomp.analysis.dual_evaldata.CELLS`).
Each face: ``{"n", "size", "exact", "matrix", "limit", "patches", "decomposition"}``:

* ``n`` the sides of the extraordinary face ``F``; ``size`` ``K = 9n``, the control points ``C``: the zoo engine's
  neighbourhood of depth 2 (``F`` and two rings of faces) in its orbit order
  (:func:`~symdecomp.analysis.zoo_matrix.zoo_matrix`);
* ``exact``: ``true`` when every number is an exact rational ``"p"`` or ``"p/q"``; ``false`` when the rules' weights
  at ``n`` are irrational (Doo-Sabin's ``cos(2 pi j/n)``, ``n`` other than 3, 4, 6) and every number is an Arb ball
  ``"[m +/- r]"`` that contains the exact value (written at 256 bits);
* ``matrix[size]``: the sparse rows ``[[column, number], ...]`` of ``A``, the one-step matrix; ``limit[size]`` the
  limit position mask (the limit point of ``F``);
* ``patches[s][c]``: sector ``s``, cell ``c``: the 9 sparse rows (grid point ``(a - 1/2 + i, b - 1/2 + j)`` of
  sector ``s``'s chart at row ``i + 3 j``) of the cell's biquadratic B-spline grid at level ``m`` over ``A^m C``;
* ``decomposition``: ``null`` (balls), or the eigen-decomposition over ``Q`` as in the sector data
  (:mod:`symdecomp.output.sector_evaldata`): blocks ``{"factor", "multiplicity", "eigenvectors", "values",
  "basis", "block", "left"}`` with ``A W_i = W_i B_i``; a block with fewer ``eigenvectors`` than its
  ``multiplicity`` is not diagonalizable (Doo-Sabin, ``n = 6``: the eigenvalue 1/4).

Evaluation (:mod:`symdecomp.analysis.dual_evaluation`; the ``layout`` string says it in one line): sector ``s`` is
the quadrant of ``F``'s corner ``P_s``, ``(u, v)`` in ``[0, 1]^2``; at ``(u, v) != (0, 0)``, ``m >= 1`` with
``1 < 2^m max(u, v) <= 2``, ``(x, y) = 2^m (u, v)``, cell ``(a, b) = (min(floor x, 1), min(floor y, 1))``,
``point = sum_{i,j} N_i(x - a) N_j(y - b) (patches[s][c] A^m C)_{i+3j}`` (``N`` the uniform quadratic B-spline
basis; ``A^m C = sum_i W_i B_i^m left_i C``); at ``(0, 0)``: ``limit . C``. :func:`dual_json_chunks` writes
(streamed, one face at a time), :func:`read_dual_json` reads back.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

import flint

from symdecomp.analysis.dual_evaldata import CELLS, DualEvalData
from symdecomp.analysis.sector_evaldata import PREC
from symdecomp.errors import EvalDataFileError, SymdecompError
from symdecomp.output.evaldata import document_chunks, load_document
from symdecomp.output.sector_evaldata import blocks_entry, number_text, read_blocks, read_matrix, read_number, sparse_rows

__all__ = ["DUAL_FORMAT", "DUAL_LAYOUT", "dual_entry", "dual_json_chunks", "read_dual_json"]

DUAL_FORMAT = "dual-evaldata"
#: The one-line layout note of a document.
DUAL_LAYOUT = (
    "control points C: the depth-2 neighbourhood of the n-gon F in its orbit order; sector s: the quadrant of F's corner "
    "P_s, (u, v) in [0, 1]^2; (u, v) != (0, 0): m >= 1 with 1 < 2^m max(u, v) <= 2, (x, y) = 2^m (u, v), cell (a, b) = "
    "(min(floor x, 1), min(floor y, 1)), point = sum N_i(x-a) N_j(y-b) (patches[s][c] A^m C)[i+3j], N quadratic B-spline, "
    "A = matrix = sum_i W_i B_i left_i (decomposition); (0, 0): limit . C"
)


def dual_entry(data: DualEvalData) -> dict:
    """One face of the document from :class:`~symdecomp.analysis.dual_evaldata.DualEvalData`."""
    with flint.ctx.workprec(PREC):
        return {
            "n": data.n, "size": data.size, "exact": data.exact, "matrix": sparse_rows(data.matrix),
            "limit": [number_text(x) for x in data.limit],
            "patches": [[sparse_rows(p) for p in sector] for sector in data.patches],
            "decomposition": blocks_entry(data.decomposition),
        }


def dual_json_chunks(entries: Iterable[dict], scheme: str, lattice: str) -> Iterator[str]:
    """The document piece by piece, one face per line (:func:`dual_entry` entries)."""
    head = {"format": DUAL_FORMAT, "scheme": scheme, "lattice": lattice, "layout": DUAL_LAYOUT,
            "cells": [list(c) for c in CELLS]}
    return document_chunks(head, "faces", entries)


def _data(entry, scheme: str) -> DualEvalData:
    n, size, exact = int(entry["n"]), int(entry["size"]), entry["exact"]
    if n < 3 or size != 9 * n or not isinstance(exact, bool):
        raise ValueError(f"n = {n} with size {size}: the control points are 9n")
    patches = tuple(tuple(read_matrix(p, size, exact) for p in sector) for sector in entry["patches"])
    if len(patches) != n or any(len(sector) != len(CELLS) or any(p.nrows() != 9 for p in sector) for sector in patches):
        raise ValueError(f"n = {n}: need {n} sectors of {len(CELLS)} cells of 9 rows")
    limit = tuple(read_number(x, exact) for x in entry["limit"])
    if len(limit) != size:
        raise ValueError(f"n = {n}: the limit mask has {len(limit)} entries, not {size}")
    matrix = read_matrix(entry["matrix"], size, exact)
    if matrix.nrows() != size:
        raise ValueError(f"n = {n}: the matrix has {matrix.nrows()} rows, not {size}")
    blocks = None if entry["decomposition"] is None else read_blocks(entry["decomposition"], size)
    phi = None if blocks is None else tuple(tuple(tuple(p * b.basis for b in blocks) for p in sector) for sector in patches)
    return DualEvalData(scheme, n, exact, matrix, patches, limit, blocks, phi)


def read_dual_json(path) -> dict[int, DualEvalData]:
    """Read a document back: ``n`` -> :class:`~symdecomp.analysis.dual_evaldata.DualEvalData`."""
    doc = load_document(path, (DUAL_FORMAT,), "a dual evaluation data document")
    out = {}
    try:
        if doc["cells"] != [list(c) for c in CELLS]:
            raise ValueError("the cells are not a sector ring's")
        with flint.ctx.workprec(PREC):
            for entry in doc["faces"]:
                data = _data(entry, doc["scheme"])
                out[data.n] = data
    except KeyError as exc:
        raise EvalDataFileError(f"{path}: malformed dual evaluation data document (no key {exc})") from None
    except (TypeError, ValueError, AttributeError, SymdecompError) as exc:
        raise EvalDataFileError(f"{path}: malformed dual evaluation data document ({exc})") from None
    return out
