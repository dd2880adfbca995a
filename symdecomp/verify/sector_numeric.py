"""``check --k`` without ``--certify`` at any size: the mirror decomposition's blocks against the refined matrix, numerically.

Up to :data:`DENSE_FACES` faces the refined 1-ring matrix is small enough to solve: its eigenvalues (Arb, at ``dps``
digits) are matched with the blocks' values and their multiplicities (:func:`~symdecomp.verify.numeric.numeric_sharp`).
Past them a dense eigen-solve is cubic in the faces (20,002 x 20,002 at k = 10,000), so what is compared is what the
decomposition says of the matrix: ``S`` (built by exact refinement, :func:`~symdecomp.schemes.sector.sharp_matrix_rows`,
read as a sparse matrix of doubles) applied to every sine polyline ``a_(p+i) = sin(theta i)``,
``b_(p+i) = sin(theta (i + 1/2))``, ``theta = pi j/k``, ``j = 1..k`` (``1..k-1`` on triangles), against the polylines
times the block ``M(theta)`` (:func:`~symdecomp.analysis.mirror.sine_block`, evaluated in doubles at that ``theta``);
and ``S``'s rows of ``O`` and the sharp points against the crease block ``C`` (they must read nothing else). The
deviation is the largest entry of ``S V - V B`` (``V``'s entries are at most 1 in modulus); it passes below
:data:`TOLERANCE`. The blocks' values themselves are the exact ones of
:func:`~symdecomp.analysis.block_values.structural_values`, not solved from ``S``: this is a numeric check that
``S`` has the blocks; ``--certify`` proves it exactly. Work: ``O(k^2)`` double operations in numpy, in chunks of
:data:`CHUNK` frequencies (memory ``O(k)``).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import sympy as sp

from symdecomp import symbols
from symdecomp.algebra.numbers import to_sympy
from symdecomp.analysis.block_values import structural_values
from symdecomp.analysis.mirror import THETA, THETA_K, crease_block, sine_block, vertex_layout, vertex_of
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.schemes.sector import MAX_DENSE_FACES, sharp_matrix_rows
from symdecomp.verify.certify import describe_vertex
from symdecomp.verify.numeric import SharpNumericRow, numeric_sharp
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["DENSE_FACES", "TOLERANCE", "CHUNK", "polyline_deviation", "numeric_sector", "numeric_sector_row"]

#: Most faces whose refined matrix is solved densely (Arb eigenvalues: about 5 s at 64 faces).
DENSE_FACES = MAX_DENSE_FACES
#: Largest deviation of ``S V - V B`` that passes: double rounding of ``sin`` at arguments up to ``pi k`` is about
#: ``1e-16 pi k`` (3e-12 at k = 10,000); a weight moved by 1/1024 shows as about 1e-3.
TOLERANCE = 1e-9
#: Frequencies applied at once (two arrays of ``size x CHUNK`` doubles).
CHUNK = 256


def _float_matrix(rows: tuple):
    """The sparse rows as a scipy CSR matrix of doubles (each distinct exact weight converted once)."""
    from scipy.sparse import csr_matrix  # type: ignore[import-untyped]  # SciPy ships no annotations

    cache: dict = {}
    data, cols, ptr = [], [], [0]
    for row in rows:
        for c, w in row.items():
            if w not in cache:
                cache[w] = float(to_sympy(w))
            data.append(cache[w])
            cols.append(c)
        ptr.append(len(data))
    return csr_matrix((np.array(data), np.array(cols), np.array(ptr)), shape=(len(rows), len(rows)))


@functools.lru_cache(maxsize=16)
def _block_function(scheme: Scheme, modified: bool):
    """``M(theta)`` as a numpy function of ``theta``, ``theta_k`` and ``k`` (the block's entries, each an array)."""
    M = sine_block(scheme, modified=modified)
    return sp.lambdify((THETA, THETA_K, symbols.sector_faces), [M[i, j] for i in range(M.rows) for j in range(M.cols)],
                       "numpy")


def _crease_deviation(S, scheme: Scheme, lay) -> float:
    idx = [0] + [lay.a(m) for m in lay.sharp]
    C = np.array(crease_block(scheme, len(lay.sharp), corner=lay.corner).tolist(), dtype=float)
    rows = S[idx].toarray()
    expected = np.zeros_like(rows)
    expected[:, idx] = C
    return float(np.abs(rows - expected).max())


def _sector_deviation(S, scheme: Scheme, lay, p: int, k: int) -> float:
    """The largest entry of ``S V - V B`` over the sector's polylines (module docstring), ``CHUNK`` frequencies at once."""
    block = _block_function(scheme, True)
    top = k if lay.quad else k - 1
    a_rows = np.array([lay.a(p + i) for i in range(1, k)], dtype=int)
    b_rows = np.array([lay.b(p + i) for i in range(k)], dtype=int) if lay.quad else None
    worst = 0.0
    for j0 in range(1, top + 1, CHUNK):
        theta = np.pi * np.arange(j0, min(top, j0 + CHUNK - 1) + 1) / k
        entries = [np.broadcast_to(np.asarray(e, dtype=float), theta.shape) for e in block(theta, float(lay.angle) / k, k)]
        Va = np.zeros((S.shape[0], theta.size))
        Va[a_rows] = np.sin(np.outer(np.arange(1, k), theta))
        if b_rows is None:
            worst = max(worst, float(np.abs(S @ Va - Va * entries[0]).max(initial=0.0)))
            continue
        Vb = np.zeros_like(Va)
        Vb[b_rows] = np.sin(np.outer(np.arange(k) + 0.5, theta))
        m00, m01, m10, m11 = entries
        worst = max(worst, float(np.abs(S @ Va - (Va * m00 + Vb * m10)).max(initial=0.0)),
                    float(np.abs(S @ Vb - (Va * m01 + Vb * m11)).max(initial=0.0)))
    return worst


def polyline_deviation(scheme: Scheme, vertex) -> float:
    """The largest deviation of the refined matrix from the mirror decomposition: its crease rows against ``C`` and its
    action on every sine polyline against the polyline's block (module docstring), in doubles."""
    scheme = check_scheme(scheme)
    lay = vertex_layout(scheme, vertex)
    S = _float_matrix(sharp_matrix_rows(scheme, vertex))
    worst = _crease_deviation(S, scheme, lay)
    for p, k in zip(lay.starts, lay.sectors):
        worst = max(worst, _sector_deviation(S, scheme, lay, p, k))
    return worst


def numeric_sector(scheme: Scheme, vertex, *, dps: int = 50) -> SharpNumericRow:
    """The numeric check of ``vertex``: its eigenvalues up to :data:`DENSE_FACES` faces, else its polylines."""
    scheme = check_scheme(scheme)
    vertex = vertex_of(scheme, vertex)
    if vertex.faces <= DENSE_FACES:
        return numeric_sharp(scheme, vertex, dps=dps)
    values, size = structural_values(scheme, vertex)
    deviation, name = polyline_deviation(scheme, vertex), describe_vertex(vertex)
    common = dict(k=vertex.sectors[0], vertex=name, size=size, distinct=len(values), dps=dps, compared="polylines",
                  deviation=f"{deviation:.1e}")
    if not deviation < TOLERANCE:  # a NaN fails too
        return SharpNumericRow(status=CrossCheckStatus.DISAGREE, **common,
                               message=f"{name}: the refined matrix is not the blocks' (S V - V B has an entry of "
                               f"{deviation:.3g}, above {TOLERANCE:g}, in double precision)")
    return SharpNumericRow(status=CrossCheckStatus.AGREE, **common)


def numeric_sector_row(vertex, *, scheme: Scheme, dps: int) -> SharpNumericRow:
    """:func:`numeric_sector` with the vertex first, for the shared pool (the vertex given the scheme's own lattice
    object again, which the refinement compares by identity)."""
    return numeric_sector(scheme, dataclasses.replace(vertex, lattice=scheme.lattice.name), dps=dps)
