"""The characteristic map of a sharp sector whose spectral conditions the blocks decided: no characteristic polynomial.

The dense test (:mod:`.c1_sharp`) finds the sector's subdominant eigenvalues from the exact characteristic polynomials of
the mirror parts of its 2-ring matrix; with BLZ's rules (weights in ``cos(pi/k)``) that polynomial is what costs minutes
from about 30 faces on. The blocks (:mod:`.c1_sharp_blocks`) already give ``lambda_1, lambda_2`` certified, each with the
block it comes from and its exact multiplicity, and prove that they are separated from every other eigenvalue. What the
map needs from them is which mirror part holds each eigenvector (:func:`block_parts`):

* a sine block ``j`` has the mode ``sin(pi j s/k)`` on the rays ``s``, and the mirror ``s -> k - s`` multiplies it by
  ``(-1)^(j + 1)``: even for ``j`` odd, odd for ``j`` even;
* an eigenvalue ``q`` (rational) of the crease block has an odd eigenvector when ``(C - q) (0, 1, -1) = 0`` exactly and
  ``C - q`` has rank 2, an even one when ``C - q`` has rank 2 and the odd vector is not in its kernel.

An eigenvalue the blocks count once in the whole matrix is simple in its part. A double one (BLZ's ``1/2``: the crease
block's, odd, and sine block 1's, even) has one eigenvector in each part. So each eigenvector is the certified null vector
of its part's 1-ring block at the blocks' ball (:func:`~symdecomp.algebra.null_vector.null_vector`: the square solve
proves the kernel has dimension at most 1), lifted to the outer points by a certified solve
(:func:`~symdecomp.verify.c1_sharp_spectrum.sector_eigenvector`). Conditions 3-5 are then decided by the dense test's own
routine (:func:`~symdecomp.verify.c1_sharp.sector_map`: Bezier nets of the spline ring, or of the wide ring past BLZ's
modified edges, the Jacobian's sign by de Casteljau subdivision, the argument swept between the sharp rays). The sector's
exact matrix is built from the refinement's sparse rows, so it is capped by
:data:`~symdecomp.schemes.sector.MAX_DENSE_FACES` faces; the linear algebra in Arb is cubic in ``k``.
"""

from __future__ import annotations

import sympy as sp

from symdecomp.schemes.sector import MAX_DENSE_FACES, SharpVertex
from symdecomp.verify.c1_sharp import sector_map
from symdecomp.verify.c1_sharp_spectrum import sector_matrices, sector_parts
from symdecomp.verify.c1_spectrum import SpectralResult
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_injectivity import SectorFinding

__all__ = ["block_parts", "map_from_blocks", "MAP_METHOD"]

#: The method, as reported with each verdict whose map this route certified.
MAP_METHOD = ("Zorin's conditions 1-2 from the sector's blocks (certified leading values, exact multiplicities); the "
              "subdominant eigenvectors as certified null vectors in the mirror parts the blocks name; Jacobian of the "
              "sector's spline ring in Bernstein-Bezier form (Arb, de Casteljau); argument swept between the two sharp rays")


def _crease_parity(crease: sp.Matrix, value) -> str | None:
    """The mirror part (``"even"``, ``"odd"``) of the crease block's eigenvector for ``value`` (``None``: not decided)."""
    if value.key[0] != "q":
        return None
    q = sp.Rational(value.key[1].numerator, value.key[1].denominator)
    shifted = crease - q * sp.eye(crease.rows)
    if shifted.rank() != crease.rows - 1:
        return None
    odd = sp.Matrix([0, 1, -1])  # O and its two sharp neighbours: the mirror exchanges the neighbours
    return "odd" if shifted * odd == sp.zeros(3, 1) else "even"


def _parity(crease: sp.Matrix, value, block) -> str | None:
    if block.block == "crease":
        return _crease_parity(crease, value)
    if block.block == "sine":
        return "even" if block.j % 2 == 1 else "odd"
    return None


def block_parts(crease: sp.Matrix, picks: list) -> list[str] | None:
    """The mirror part of each subdominant eigenvector (module docstring), ``picks`` holding ``(ball, Eigenvalue, _)``.

    ``None`` where the blocks do not name one part per eigenvector (a value of several blocks of one part, a face mode).
    """
    first, second = picks[0][1], picks[1][1]
    if first is second:
        if first.multiplicity != 2 or len(first.blocks) != 2:
            return None
        names = [_parity(crease, first, b) for b in first.blocks]
        return names if None not in names and names[0] != names[1] else None
    if any(v.multiplicity != 1 or len(v.blocks) != 1 for v in (first, second)):
        return None
    names = [_parity(crease, v, v.blocks[0]) for v in (first, second)]
    return None if None in names else names


def map_from_blocks(scheme, vertex: SharpVertex, sector: int, spectral: SpectralResult, picks: list, crease: sp.Matrix,
                    max_depth: int) -> SectorFinding:
    """Conditions 3-5 in sector ``sector`` of ``vertex``, the spectral conditions holding by the blocks (module docstring)."""
    lambdas = tuple(float(p[0].real.mid()) for p in picks)
    if vertex.faces > MAX_DENSE_FACES:
        return SectorFinding(C1Verdict.UNDECIDED, f"{spectral.reason}; the spectral and tangent conditions hold (blocks), the "
                             f"characteristic map is built for at most {MAX_DENSE_FACES} faces", spectral, lambdas)
    names = block_parts(crease, picks)
    sm = sector_matrices(scheme, vertex, sector)
    parts = {p.name: p for p in sector_parts(sm)}
    if names is None or not all(name in parts for name in names):
        return SectorFinding(C1Verdict.UNDECIDED, f"{spectral.reason}; the blocks do not name the mirror part of each "
                             "subdominant eigenvector", spectral, lambdas)
    return sector_map(scheme, vertex, sm, spectral, [(p[0], parts[name], True) for p, name in zip(picks, names)], max_depth)
