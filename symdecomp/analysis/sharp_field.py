"""The sharp-vertex matrix of rules with ``cos(theta_k)`` weights (Biermann-Levin-Zorin's), exactly over ``Q(cos(pi/k))``.

BLZ's near-edge rule has the weight ``w = 3/8 - cos(theta_k)/4`` (Catmull-Clark) on the edge's other end, so the
one-step matrix of a boundary or corner vertex with ``k`` faces (or a crease with ``k`` faces on both sides) has
entries ``p + q w`` in the real cyclotomic field ``K = Q(cos(pi/k))``. :func:`sharp_matrix` returns the rational
matrix when it is rational (``k <= 3``), else the :class:`~symdecomp.algebra.cos_field.FieldMatrix` over ``K``;
:func:`sharp_values` its eigenvalues part by part (:mod:`symdecomp.analysis.sharp_eigen`), the same
:class:`~symdecomp.analysis.eigenvalue.Eigenvalue` objects as for rational rules
(:func:`~symdecomp.analysis.sharp_eigen.root_eigenvalue`): each is a root of an
irreducible rational factor of the norm of the part's characteristic polynomial (its minimal polynomial over
``Q``), picked out and counted exactly (:func:`~symdecomp.algebra.cos_field.field_roots`).

Out of reach (:class:`~symdecomp.errors.NotApplicableError`): a crease whose two sides have different face counts
``k1 != k2`` with both ``cos(pi/k_i)`` irrational (entries in ``Q(cos(pi/k1), cos(pi/k2))``), and corners given an
angle.
"""

from __future__ import annotations

import flint
import sympy as sp

from symdecomp.algebra.cos_field import FieldMatrix, field_charpoly, field_roots, norm_charpoly
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.sharp_eigen import _factor_roots, crease_points, matrix_parts, part_eigenvalues, root_eigenvalue
from symdecomp.errors import NotApplicableError

__all__ = ["near_weight", "sharp_matrix", "sharp_values", "field_part_eigenvalues"]


def near_weight(scheme, vertex, k: int):
    """The near-edge rule's weight on the edge's other end in a sector of ``k`` faces, when it is irrational (else ``None``).

    BLZ's ``theta_k = pi/k``, or ``angle/k`` at a corner given its angle (:mod:`symdecomp.schemes.sharp_refinement`).
    """
    rules = scheme.sharp
    if rules is None or rules.near_edge_centre is None:
        return None
    theta = (vertex.angle if getattr(vertex, "angle", None) is not None else sp.pi) / k
    weight = rules.near_edge(theta, k)[1]
    return None if weight.is_Rational else weight


def sharp_matrix(scheme, vertex, *, level: int = 0):
    """The vertex's 1-ring matrix: a FLINT rational matrix, or a :class:`FieldMatrix` over ``Q(cos(pi/k))``."""
    from symdecomp.schemes.sector import exact_sharp_matrix, sharp_subdivision_matrix

    try:
        return exact_sharp_matrix(scheme, vertex, level=level)
    except NotApplicableError as refused:
        irrational = sorted(k for k in set(vertex.sectors) if near_weight(scheme, vertex, k) is not None)
        weights = {near_weight(scheme, vertex, k) for k in irrational}
        if not weights:  # irrational for another reason (Loop's cos(2 pi/n) at a dart): out of this route's reach
            raise
        if len(weights) != 1:
            fields = ", ".join(f"cos(pi/{k})" for k in irrational)
            raise NotApplicableError(f"scheme {scheme.name!r}: the sharp matrix's entries lie in Q({fields}) (sectors of "
                                     f"{' and '.join(map(str, irrational))} faces), beyond one field Q(cos(pi/k))") from None
        S = sharp_subdivision_matrix(scheme, vertex, level=level)
        try:
            return FieldMatrix.from_sympy(S.tolist(), weights.pop())
        except NotApplicableError as exc:
            raise NotApplicableError(f"{str(refused).split('; use ')[0]}, and {exc}") from None


def field_part_eigenvalues(M: FieldMatrix, parts, *, prec: int = 256) -> list[Eigenvalue]:
    """:func:`~symdecomp.analysis.sharp_eigen.part_eigenvalues` for a matrix over ``Q(w)``: each eigenvalue a root of
    an irreducible rational factor of the norm, with its exact multiplicity in the part at ``w``'s real value."""
    out = []
    for part in parts:
        P = M.submatrix(part.indices)
        chi = field_charpoly(P)
        items = []
        for f, _ in norm_charpoly(P).factor()[1]:
            f = f / f.leading_coefficient()
            found = field_roots(chi, f, P, prec=prec)
            if not found:
                continue
            named = _factor_roots(f, prec)
            for _, ball, mult in found:
                index, exact, own = next(t for t in named if t[2].overlaps(ball))
                items.append(root_eigenvalue(f, index, exact, own, mult, part.label))
        out += sorted(items, key=lambda v: (-float(abs(v.ball).mid()), -float(v.ball.real.mid())))
    return out


def sharp_values(scheme, vertex, *, level: int = 0, prec: int = 256):
    """``(S, parts, eigenvalues by part)`` of the vertex at ``level``, over ``Q`` or ``Q(cos(pi/k))``."""
    S = sharp_matrix(scheme, vertex, level=level)
    parts = matrix_parts(S, crease_points(vertex))
    if isinstance(S, flint.fmpq_mat):
        return S, parts, part_eigenvalues(S, parts, prec=prec)
    return S, parts, field_part_eigenvalues(S, parts, prec=prec)
