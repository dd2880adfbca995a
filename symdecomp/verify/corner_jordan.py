"""The eigenvalue ``1/2`` at a corner vertex with BLZ's rules: a triple root with a Jordan block, computed exactly.

At a corner ``O`` (interpolated) each boundary curve is a cubic B-spline ending at ``O`` and has its own tangent
eigenvalue ``1/2``; with Biermann-Levin-Zorin's near-edge weight at ``theta_k = pi/k`` the sine block ``j = 1`` has
the eigenvalue ``1/2`` as well, so ``1/2`` is a triple root of the sector's characteristic polynomial (the blocks
count it exactly, :mod:`.c1_mirror_blocks`). Its eigenvectors are not three: with ``A = S - I/2`` (``S`` the sector's
exact 2-ring matrix, entries in ``Q(cos(pi/k))``) this module computes, over that field,

* ``dim ker A`` (the geometric multiplicity) and ``dim ker A^2``: ``2`` and ``3`` at every corner tried, i.e. one
  Jordan block of size 2 (:attr:`CornerJordan.block`);
* the chain ``A g = e != 0``, ``A e = 0`` (checked exactly) and the labels where ``e`` is not zero: never a point on a
  sharp ray, nor ``O`` (:attr:`CornerJordan.chain_on_rays`). It must be so: the boundary curves read only their own
  points and have a simple ``1/2`` each, so no ``m 2^-m`` term can reach them.

The block comes with BLZ's weight at ``theta_k = pi/k``, a corner of angle ``pi`` (what ``SharpVertex.corner`` takes
without an angle): at a convex angle such as ``pi/2`` or ``3 pi/4`` the sine mode's eigenvalue is not ``1/2``, the
two boundary tangents are the only eigenvectors, and Zorin's test decides (C1 at 2 and 3 faces).

What it means for the limit surface: ``S^m g = 2^-m g + m 2^(1-m) e``, so for data with a component ``c_g`` along ``g``
the level-``m`` net near ``O`` is ``m 2^(1-m) c_g e`` plus ``2^-m`` terms: the limit is dominated by the chain's
eigenfunction ``f_e``, which vanishes on both boundary curves. Zorin's sufficient conditions (a strictly dominant
``lambda_1 = lambda_2`` with two eigenvectors and a regular injective characteristic map) do not apply. Expanding the
normal, ``N_m = 2 m (c_e' x c_g) J(f_e', f_e) + O(1)`` (``e'`` the other eigenvector, ``J`` the Jacobian determinant of
the pair): :mod:`.c1_corner_jordan` certifies that pair's map and decides C1 from it (:class:`JordanChain` holds the
exact vectors it reads).

>>> from symdecomp.schemes.files import load_scheme
>>> j = corner_jordan(load_scheme("catmull-clark-blz"), 2)
>>> j.eigenvectors, j.generalized, j.block, j.chain_on_rays
(2, 3, 2, False)
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.algebra.cos_field import FieldMatrix, field_name, field_of, rational_left_eigenspace
from symdecomp.algebra.number_field import FieldElement
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.verify.mirror_parts import NEAR, SectorMatrices, sector_matrices

__all__ = ["HALF", "JORDAN_FACES", "CornerJordan", "JordanChain", "corner_jordan", "jordan_chain", "kernel", "shifted_rows",
           "constant", "times", "square", "Rows", "chain_structure"]

#: Sparse rows ``{i: {j: entry}}`` of a matrix over the field.
Rows = dict[int, dict[int, FieldElement]]
#: The eigenvalue of the boundary curves' tangents at a corner.
HALF = Fraction(1, 2)
#: The most faces whose Jordan structure the C1 test computes on the whole matrix (the exact kernels cost about ``k^3``: 2 s
#: at 8 faces); past it, from the sector's blocks (:mod:`.corner_jordan_blocks`).
JORDAN_FACES = 12


@dataclass(frozen=True)
class CornerJordan:
    """The eigenvalue ``1/2`` of a corner sector: its eigenvectors, generalized eigenvectors and the chain's support."""

    #: Faces of the sector.
    k: int
    #: The entries' field: ``"Q"`` or ``"Q(cos(pi/k))"`` (the near-edge weight's).
    field: str
    #: ``dim ker(S - I/2)``, exact over :attr:`field`.
    eigenvectors: int
    #: ``dim ker(S - I/2)^2``, exact over :attr:`field`.
    generalized: int
    #: Whether the chain's eigenvector ``e = (S - I/2) g`` is nonzero on a sharp ray or ``O`` (``None``: no chain).
    chain_on_rays: bool | None

    @property
    def block(self) -> int:
        """The size of the largest Jordan block read (``1``: none; ``2``: ``ker A^2`` is larger than ``ker A``)."""
        return 2 if self.generalized > self.eigenvectors else 1

    def reason(self) -> str:
        """The computed structure of ``1/2``, in one sentence (module docstring)."""
        if self.block == 1:
            return f"lambda = 1/2 has {self.eigenvectors} eigenvectors (ker(S - I/2) over {self.field}, exact)"
        where = "off both sharp rays and O" if not self.chain_on_rays else "on a sharp ray"
        return (f"lambda = 1/2 is defective: dim ker(S - I/2) = {self.eigenvectors}, dim ker(S - I/2)^2 = "
                f"{self.generalized} (exact over {self.field}), a Jordan block of size 2 whose eigenvector e = (S - I/2) g "
                f"is nonzero only {where}; S^m g = 2^-m g + m 2^(1-m) e, so the limit at O is dominated by m 2^-m times "
                "the chain's eigenfunction, which vanishes on both boundary curves: Zorin's conditions do not cover a "
                "Jordan block; the map (f_e', f_e) decides the tangent plane (c1_corner_jordan, not run here)")


def _element(e: object, modulus: flint.fmpq_poly) -> FieldElement:
    """An entry ``p + q NEAR`` of the sector's matrices as an element of ``Q[w]/(modulus)``."""
    coeffs = sp.Poly(sp.sympify(e, strict=True), NEAR).all_coeffs()[::-1]
    if len(coeffs) > 2:
        raise NotApplicableError(f"an entry {e} is not affine in the near-edge weight")
    return FieldElement(flint.fmpq_poly([to_fmpq(sp.Rational(c)) for c in coeffs]) % modulus, modulus)


def constant(q: Fraction | int, modulus: flint.fmpq_poly) -> FieldElement:
    return FieldElement(flint.fmpq_poly([to_fmpq(q)]) % modulus, modulus)


def shifted_rows(sm: SectorMatrices, value: Fraction) -> tuple[Rows, flint.fmpq_poly]:
    """``(rows, modulus)``: ``S - value I`` as sparse rows ``{i: {j: entry}}`` over ``Q[w]/(modulus)``."""
    mod = flint.fmpq_poly([0, 1]) if sm.weight is None else field_of(sm.weight)
    rows: Rows = {i: {} for i in range(len(sm.labels))}
    for (i, j), e in sm.matrix.todok().items():
        rows[i][j] = _element(e, mod)
    for i in rows:
        rows[i][i] = rows[i].get(i, constant(0, mod)) - constant(value, mod)
    return rows, mod


def times(rows: Rows, vector: list[FieldElement], mod: flint.fmpq_poly) -> list[FieldElement]:
    out = []
    for i in range(len(rows)):
        total = constant(0, mod)
        for j, x in rows[i].items():
            total = total + x * vector[j]
        out.append(total)
    return out


def square(rows: Rows, mod: flint.fmpq_poly) -> Rows:
    out: Rows = {}
    for i, row in rows.items():
        acc: dict[int, FieldElement] = {}
        for j, x in row.items():
            for c, y in rows[j].items():
                acc[c] = acc.get(c, constant(0, mod)) + x * y
        out[i] = {c: v for c, v in acc.items() if v}
    return out


def kernel(rows: Rows, mod: flint.fmpq_poly, weight: sp.Expr) -> list[list[FieldElement]]:
    """A basis over the field of ``{x : A x = 0}`` for sparse rows ``A`` (the left kernel of ``A^T``, exact)."""
    n = len(rows)
    zero = constant(0, mod)
    transposed = [[zero] * n for _ in range(n)]
    for i, row in rows.items():
        for j, x in row.items():
            transposed[j][i] = x
    M = FieldMatrix(tuple(tuple(r) for r in transposed), mod, weight)
    return rational_left_eigenspace(M, 0, range(n))


@dataclass(frozen=True)
class JordanChain:
    """The generalized eigenspace of ``1/2`` at a corner sector, exact over the near-edge weight's field (matrix order)."""

    #: The sector's exact matrices.
    sm: SectorMatrices
    #: ``Q[w]/(modulus)``, ``w`` the near-edge weight (``x`` when the matrix is rational).
    modulus: flint.fmpq_poly
    #: A basis of ``ker(S - I/2)``.
    eigen: list[list[FieldElement]]
    #: A basis of ``ker(S - I/2)^2``.
    general: list[list[FieldElement]]
    #: ``(g, e)`` with ``(S - I/2) g = e != 0`` (checked exactly; ``None``: no chain).
    chain: tuple[list[FieldElement], list[FieldElement]] | None

    def on_rays(self, vector: list[FieldElement]) -> bool:
        """Whether ``vector`` is nonzero at ``O`` or at a point of a sharp ray."""
        k = self.sm.k
        return any(x for x, lab in zip(vector, self.sm.labels) if lab == ORIGIN or (lab[2] == 0 and lab[0] in (0, k)))

    def partner(self) -> list[FieldElement] | None:
        """An eigenvector ``e'`` of ``1/2`` independent of the chain's ``e``: one nonzero on a sharp ray (``e`` is not)."""
        return next((x for x in self.eigen if self.on_rays(x)), None)


def jordan_chain(scheme: Scheme, k: int, angle: sp.Expr | None = None) -> JordanChain:
    """The eigenvalue ``1/2`` of a corner sector of ``k`` faces, its kernels and chain computed and checked exactly (module
    docstring); ``angle``: the corner's, for BLZ's ``theta_k = angle/k`` (``None``: ``pi``)."""
    vertex = SharpVertex.corner(k, scheme.lattice, angle)  # type: ignore[operator]  # corner: a property and a constructor
    sm = sector_matrices(scheme, vertex)
    A, mod = shifted_rows(sm, HALF)
    weight = sp.Integer(0) if sm.weight is None else sm.weight
    eigen = kernel(A, mod, weight)
    for x in eigen:  # the identity the count rests on
        if any(times(A, x, mod)):
            raise NotApplicableError("a computed eigenvector for 1/2 does not satisfy (S - I/2) x = 0")
    general = kernel(square(A, mod), mod, weight)
    chain = next(((g, e) for g, e in ((g, times(A, g, mod)) for g in general) if any(e)), None)
    if chain is not None and any(times(A, chain[1], mod)):
        raise NotApplicableError("(S - I/2)^2 g = 0 does not hold for a computed generalized eigenvector")
    return JordanChain(sm, mod, eigen, general, chain)


def corner_jordan(scheme: Scheme, k: int, angle: sp.Expr | None = None) -> CornerJordan:
    """The structure of the eigenvalue ``1/2`` of a corner sector of ``k`` faces (module docstring); ``angle``: the
    corner's, for BLZ's ``theta_k = angle/k`` (``None``: ``pi``)."""
    return chain_structure(jordan_chain(scheme, k, angle))


def chain_structure(found: JordanChain) -> CornerJordan:
    """The structure of ``1/2`` that a computed chain shows (the whole matrix's, or the blocks' of :mod:`.corner_jordan_blocks`)."""
    k = found.sm.k
    weight = sp.Integer(0) if found.sm.weight is None else found.sm.weight
    field = field_name(FieldMatrix((), found.modulus, weight))
    on_rays = None if found.chain is None else found.on_rays(found.chain[1])
    return CornerJordan(k, field, len(found.eigen), len(found.general), on_rays)
