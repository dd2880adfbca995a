"""Limit position and tangent masks of a block lower-triangular matrix part by part, as exact left eigenvectors.

The one-step matrix ``S`` of a boundary, crease, corner or dart vertex's 1-ring
(:func:`~symdecomp.schemes.sector.exact_sharp_matrix`) is block lower-triangular: the crease block ``C`` (the vertex
and its neighbours on sharp edges), then one block ``Y_s`` per sector (:mod:`symdecomp.analysis.triangular_eigen`).
So a left eigenvector of an eigenvalue of ``C`` that no ``Y_s`` has vanishes off the crease points, and a left
eigenvector ``(u, w)`` of an eigenvalue ``mu`` of ``Y_s`` has ``w Y_s = mu w`` (a sine polyline of the mirror
decomposition) and ``u (mu I - C) = w X``: the 3 x 3 solve on the crease points. Every mask here is computed exactly
as a left eigenvector of ``S`` (or of ``C``, or of the piece ``C + Y_s`` of one side of a crease, extended by zeros,
which is a left eigenvector of ``S`` because no other row reads that piece's points) over ``Q(lambda)``
(:func:`~symdecomp.algebra.number_field.left_eigenspace`); for rules with ``cos(theta_k)`` weights (BLZ's) over
``Q(cos(pi/k))`` at a rational eigenvalue (:func:`~symdecomp.algebra.cos_field.rational_left_eigenspace`,
:attr:`SharpMask.generator`); a mask at an irrational eigenvalue there would lie in ``Q(cos(pi/k), lambda)``, out of
reach (:class:`~symdecomp.errors.NotApplicableError`). When the cross tangent shares the curve tangent's eigenvalue
(BLZ's ``1/2``) their eigenspace is the tangent plane and the cross tangent is given as its member with equal weights
on the two crease neighbours.

* **position** (:func:`position_mask`): the eigenvalue 1 (it must be simple), weights summing to 1;
* **boundary curve tangent** (:func:`creased_masks`): the crease block's largest eigenvalue after 1
  (``1 - crease_edge`` = 1/2 for the standard rules), weight 1 on ``a_0`` and -1 on the crease's other neighbour; at a
  **corner** it is double, and the two masks are the two boundary curves' tangents (weight 1 on ``a_0``, resp. ``a_k``);
* **cross tangent** (one per sector at a crease): the largest eigenvalue of the sector's block, the surface's
  tangent across the boundary curve, weight 1 on the first point of the sector where it is not zero;
* with no block structure (a dart, a semi-sharp crease: :func:`generic_masks`): the two largest eigenvalues after 1.

The masks are the tangent plane's only if their eigenvalues are *the two subdominant ones*: of every eigenvalue
of the piece (the whole vertex; one side of a crease: ``C`` and ``Y_s``) except 1, the two of largest modulus, real,
strictly larger in modulus than the rest (certified in Arb); each builder returns why not, if not. The question's
answer for a vertex is :func:`~symdecomp.analysis.masks.sharp_masks`.
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.cos_field import rational_left_eigenspace
from symdecomp.algebra.number_field import FieldElement, element_ball, left_eigenspace, reduced_basis, to_sympy_vector
from symdecomp.algebra.numbers import to_sympy
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.spectrum import acb_text
from symdecomp.analysis.triangular_eigen import ball_at, merge, separated, submatrix
from symdecomp.errors import NotApplicableError
from symdecomp.validate import INPUT_LIMITS

__all__ = ["SharpMask", "MAX_MASK_SYSTEM", "ONE", "expanded", "position_mask", "generic_masks", "creased_masks"]

#: The factor ``lambda - 1`` of the eigenvalue 1.
ONE = flint.fmpq_poly([-1, 1])


@dataclass(frozen=True)
class SharpMask:
    """One mask: a left eigenvector of the vertex's matrix, exact in ``Q(lambda)``."""

    #: ``"position"``, ``"boundary curve tangent"``, ``"cross tangent"``, ...
    name: str
    eigenvalue: Eigenvalue
    #: One weight per 1-ring point (in the vertex order), each a polynomial in the eigenvalue, or, for rules with
    #: ``cos(theta_k)`` weights (the eigenvalue rational), a polynomial in :attr:`generator`.
    weights: tuple[FieldElement, ...]
    #: ``None``, or the generator ``w`` of the entries' field ``Q(w) = Q(cos(pi/k))`` the weights are polynomials in.
    generator: sp.Expr | None = None

    def exact(self) -> list[sp.Expr] | None:
        """The weights as exact sympy numbers (closed forms), or ``None`` past degree 2 (see :attr:`weights`)."""
        if self.generator is not None:
            return [sp.radsimp(sp.expand(sum((to_sympy(c) * self.generator**t for t, c in enumerate(w.poly.coeffs())),
                                             sp.Integer(0)))) for w in self.weights]
        if self.eigenvalue.factor.degree() > 2:
            return None
        return to_sympy_vector(self.weights, self.eigenvalue.factor, self.eigenvalue.index)

    def texts(self, digits: int) -> list[str]:
        """The weights as decimal text with ``digits`` significant digits (certified balls' midpoints)."""
        prec = 4 * digits + 64
        with flint.ctx.workprec(prec):
            if self.generator is not None:
                root = compile_expression(self.generator, (), "arb")()
            else:
                root = ball_at(self.eigenvalue, prec)
            return [acb_text(element_ball(w, root), digits) for w in self.weights]

    def as_json(self, names, digits: int) -> dict:
        exact = self.exact()
        return {"name": self.name, "eigenvalue": acb_text(self.eigenvalue.ball, digits), "part": self.eigenvalue.part,
                "weights": dict(zip(names, self.texts(digits))),
                "exact": None if exact is None else dict(zip(names, map(sp.sstr, exact))),
                "in_lambda": None if exact is not None else dict(zip(names, map(str, self.weights)))}


def _eigenvector(S: flint.fmpq_mat, rows: tuple[int, ...], value: Eigenvalue, order_first: tuple[int, ...]) -> list:
    """Left eigenvectors of ``S[rows]`` at ``value`` extended by zeros to all of ``S``, pivots first in ``order_first``."""
    local = {r: i for i, r in enumerate(rows)}
    order = [local[r] for r in order_first if r in local] + [i for r, i in local.items() if r not in order_first]
    if isinstance(S, flint.fmpq_mat):
        _check_system(len(rows), value)
        space = left_eigenspace(submatrix(S, rows), value.factor, order)
        zero = FieldElement(flint.fmpq_poly([]), value.factor)
    else:
        if value.factor.degree() != 1:
            raise NotApplicableError(f"the eigenvalue {acb_text(value.ball, 8)} is irrational and the rules' weights lie in "
                                     "Q(cos(pi/k)): its mask lies in Q(cos(pi/k), lambda), which is out of reach")
        space = reduced_basis(rational_left_eigenspace(S.submatrix(rows), -value.factor[0], order), order)
        zero = FieldElement(flint.fmpq_poly([]), S.modulus)
    out = []
    for v in space:
        full = [zero] * S.nrows()
        for r, i in local.items():
            full[r] = v[i]
        out.append(full)
    return out


#: Largest rational system ``m d`` (``m`` points, the eigenvalue of degree ``d``) solved for an exact mask: its dense
#: elimination grows as ``(m d)^3`` with growing rationals (``masks 64 --dart`` asked for one of about 8,000 unknowns and
#: ended in an allocation failure after minutes); checked before any work. A row of the limits table.
MAX_MASK_SYSTEM = INPUT_LIMITS["masks --boundary, ... (sharp_masks): unknowns of a mask's system"][0]


def _check_system(points: int, value: Eigenvalue) -> None:
    size = points * value.factor.degree()
    if size > MAX_MASK_SYSTEM:
        raise NotApplicableError(f"the mask at the eigenvalue {acb_text(value.ball, 8)} (degree {value.factor.degree()} over Q) "
                                 f"is the null space of a rational system of {points} x {value.factor.degree()} = {size} "
                                 f"unknowns, more than the {MAX_MASK_SYSTEM} solved exactly here")


def expanded(values) -> list[Eigenvalue]:
    """Each value repeated by its multiplicity."""
    return [v for v in values for _ in range(v.multiplicity)]


def _top_two(values: list[Eigenvalue]) -> tuple[list[Eigenvalue], str]:
    """The two eigenvalues of largest modulus after a simple 1, and why they are (not) certified the two largest."""
    rest = expanded([v for v in merge(values) if v.factor != ONE])
    if len(rest) < 2:
        return rest, f"only {len(rest)} eigenvalue(s) besides 1"
    top = rest[:2]
    if any(not v.is_real for v in top):
        return top, "a subdominant eigenvalue is not real"
    if len(rest) > 2 and not separated(rest[1], rest[2]):
        return top, f"the second eigenvalue {acb_text(rest[1].ball, 8)} is not larger in modulus than the next, {acb_text(rest[2].ball, 8)}"
    return top, ""


def position_mask(S, values) -> SharpMask:
    values = [v for v in merge(values) if v.factor == ONE]
    if not values or values[0].multiplicity != 1:
        raise NotApplicableError(f"1 is not a simple eigenvalue (multiplicity {values[0].multiplicity if values else 0}): "
                                 "no limit position mask is defined")
    (w,) = _eigenvector(S, tuple(range(S.nrows())), values[0], tuple(range(S.nrows())))
    total = w[0]
    for x in w[1:]:
        total = total + x
    scale = total.inverse()
    return SharpMask("position", values[0], tuple(x * scale for x in w))


def _same(top: list[Eigenvalue], wanted: list[Eigenvalue]) -> bool:
    return sorted(v.key for v in top) == sorted(v.key for v in wanted)


def _verdict(values, wanted: list[Eigenvalue], where: str) -> str:
    """``""`` when ``wanted`` are certified the two subdominant eigenvalues among ``values``, else why not."""
    top, why = _top_two(values)
    if not _same(top, wanted):
        got = ", ".join(acb_text(v.ball, 8) for v in top)
        return f"{where}: the two subdominant eigenvalues are {got}, not the tangents' {', '.join(acb_text(v.ball, 8) for v in wanted)}"
    return f"{where}: {why}" if why else ""


def generic_masks(S, values, names) -> tuple[list[SharpMask], list[str]]:
    top, _ = _top_two(values)
    everything = tuple(range(S.nrows()))
    order = everything[1:] + (0,)
    if len(top) == 2 and top[0].key == top[1].key:
        vectors = _eigenvector(S, everything, top[0], order)
        if len(vectors) < 2:
            return [], [f"the double eigenvalue {acb_text(top[0].ball, 8)} is defective: one eigenvector"]
        pairs = [(top[0], vectors[0]), (top[0], vectors[1])]
    else:
        pairs = [(v, _eigenvector(S, everything, v, order)[0]) for v in top]
    masks = [SharpMask(f"tangent {i + 1}", v, tuple(w)) for i, (v, w) in enumerate(pairs)]
    return masks, [r for r in [_verdict(values, top, "the vertex")] if r]


def _symmetric(vector: list, curve: list) -> list:
    """``vector`` minus the multiple of the curve tangent ``curve`` that gives it equal weights on the curve tangent's two
    points (its entries 1 and -1): when the cross tangent shares the curve tangent's eigenvalue (BLZ's 1/2) the
    eigenspace holds both, and the cross tangent is the mirror-symmetric one of them."""
    ends = [i for i, x in enumerate(curve) if x]
    if len(ends) != 2:  # pragma: no cover - the curve tangent is 1 on one crease neighbour and -1 on the other
        return vector
    i, j = ends
    t = (vector[i] - vector[j]) * (curve[i] - curve[j]).inverse()
    return [v - t * u for v, u in zip(vector, curve)]


def _cross(S, crease, sector, values, c1, many: bool, curve=None) -> tuple[SharpMask | None, str]:
    own = [v for v in values if v.part == sector.label]
    where = f"sector {sector.label.split()[-1]}" if many else "the sector"
    if not own:
        return None, f"{where} has no points off the crease: no cross tangent"
    mu = own[0]
    rows = tuple(sorted(crease.indices + sector.indices))
    vectors = _eigenvector(S, rows, mu, sector.indices)
    vector = next((v for v in vectors if any(v[i] for i in sector.indices)), None)
    if vector is None:  # pragma: no cover - needs a defective eigenvalue shared by C and Y_s
        return None, f"{where}: the eigenvalue {acb_text(mu.ball, 8)} has no eigenvector off the crease (defective)"
    if mu.key == c1.key and curve is not None:
        vector = _symmetric(vector, curve)
    name = "cross tangent" + (f", {sector.label}" if many else "")
    mask = SharpMask(name, mu, tuple(vector))
    piece = [v for v in values if v.part in ("crease", sector.label)]
    return mask, _verdict(piece, [c1, mu], f"the surface on {where}" if many else "the vertex")


def creased_masks(S, parts, values, names) -> tuple[list[SharpMask], list[str]]:
    crease, sectors = parts[0], parts[1:]
    own = [v for v in values if v.part == "crease" and v.factor != ONE]
    order = tuple(i for i in crease.indices if i != 0) + (0,)
    c1 = own[0]
    vectors = _eigenvector(S, crease.indices, c1, order)
    if c1.multiplicity >= 2 and len(vectors) >= 2:  # a corner: the two boundary curves
        masks = [SharpMask(f"boundary curve tangent along O-{names[order[i]]}", c1, tuple(v)) for i, v in enumerate(vectors[:2])]
        return masks, [r for r in [_verdict(values, [c1, c1], "the vertex")] if r]
    curve = "crease curve tangent" if len(sectors) > 1 else "boundary curve tangent"
    masks, reasons = [SharpMask(curve, c1, tuple(vectors[0]))], []
    for sector in sectors:
        mask, why = _cross(S, crease, sector, values, c1, len(sectors) > 1, list(vectors[0]))
        masks += [mask] if mask is not None else []
        reasons += [why] if why else []
    return masks, reasons
