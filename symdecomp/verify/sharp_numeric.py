"""The numeric check of a boundary, crease or corner vertex: the blocks' spectrum against the refined matrix's, in Arb.

``check --k A:B --boundary`` without ``--certify`` (like ``check --n``'s numeric mode): the eigenvalues from the
mirror decomposition's blocks (:mod:`symdecomp.analysis.sharp_structural`, each with its exact multiplicity and a
certified ball) are compared with the eigenvalues of the vertex's matrix built by exact refinement
(:func:`~symdecomp.schemes.sector.sharp_subdivision_matrix`, its entries evaluated at ``dps`` digits, its eigenvalues
by Arb's approximate QR iteration, ``acb_mat.eig(algorithm="approx")``). The two computations share nothing but the
scheme. Each of the matrix's eigenvalues is assigned to the nearest block value; they ``agree`` when every distance
is below ``10^-(dps/2)`` (a multiple eigenvalue is only that accurate in floating point) and each block value gets
exactly its multiplicity, else ``disagree``, naming the value. Numeric, not a proof: ``--certify`` is the proof.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import flint

from symdecomp.schemes.scheme import check_scheme
from symdecomp.validate import check_precision
from symdecomp.verify.result import CrossCheckStatus

__all__ = ["SharpNumericRow", "numeric_sharp", "numeric_row"]


@dataclass(frozen=True)
class SharpNumericRow:
    """One vertex's numeric check."""

    #: Faces of the vertex's first sector (``K``).
    k: int
    #: The vertex, as printed (``boundary k=5``, ...).
    vertex: str
    status: CrossCheckStatus
    #: Eigenvalues (with multiplicity) and distinct values of the blocks.
    size: int
    distinct: int
    #: Digits the comparison was made at.
    dps: int
    #: What disagreed or could not be told apart (empty when they agree).
    message: str = ""

    @property
    def ok(self) -> bool:
        return self.status is CrossCheckStatus.AGREE

    def as_json(self) -> dict:
        return {"k": self.k, "vertex": self.vertex, "status": self.status.value, "size": self.size,
                "distinct": self.distinct, "dps": self.dps, "message": self.message}


def _matrix_values(scheme, vertex, prec: int) -> list:
    from symdecomp.schemes.sector import sharp_subdivision_matrix
    from symdecomp.verify.c1_sharp_spectrum import ball_matrix

    S = sharp_subdivision_matrix(scheme, vertex)
    with flint.ctx.workprec(prec):
        return list(ball_matrix(S.tolist()).eig(algorithm="approx"))


def numeric_sharp(scheme, vertex, *, dps: int = 50) -> SharpNumericRow:
    """Compare the blocks' spectrum of ``vertex`` with its refined matrix's eigenvalues at ``dps`` digits (module docstring)."""
    from symdecomp.analysis.sharp_structural import structural_values
    from symdecomp.verify.sharp_certify import describe_vertex

    scheme, dps = check_scheme(scheme), check_precision(dps)
    prec = math.ceil(dps * 3.33) + 32
    values, size = structural_values(scheme, vertex, prec=prec)
    name = describe_vertex(vertex)
    common = dict(k=vertex.sectors[0], vertex=name, size=size, distinct=len(values), dps=dps)
    with flint.ctx.workprec(prec):
        mids = [flint.acb(v.ball.real.mid(), v.ball.imag.mid()) for v in values]
        counts = [0] * len(values)
        tol = flint.arb(10) ** (-(dps // 2))
        for z in _matrix_values(scheme, vertex, prec):
            i = min(range(len(values)), key=lambda t: float(abs(z - mids[t]).mid()))
            if not abs(z - mids[i]) < tol:
                return SharpNumericRow(status=CrossCheckStatus.DISAGREE, message=f"{name}: the matrix's eigenvalue "
                                       f"{z.mid().str(12, radius=False)} is no block's value to {dps // 2} digits", **common)
            counts[i] += 1
    for v, count in zip(values, counts):
        if count != v.multiplicity:
            return SharpNumericRow(status=CrossCheckStatus.DISAGREE, message=f"{name}: the blocks' value {v.ball.mid().str(12, radius=False)} "
                                   f"has multiplicity {v.multiplicity}, the matrix {count} eigenvalues there", **common)
    return SharpNumericRow(status=CrossCheckStatus.AGREE, **common)


def numeric_row(vertex, *, scheme, dps: int) -> SharpNumericRow:
    """:func:`numeric_sharp` with the vertex first, for the shared pool (one vertex per item; a vertex that travelled to a
    worker is given the scheme's own lattice object again, which the matrix's assembly compares by identity)."""
    return numeric_sharp(scheme, dataclasses.replace(vertex, lattice=scheme.lattice.name), dps=dps)
