"""C1 at a corner whose subdominant eigenvalue ``1/2`` has a Jordan block: the map of the chain decides.

At BLZ's corners with ``theta_k = pi/k`` (a corner of angle ``pi``) the eigenvalue ``1/2`` of the sector's matrix ``S``
is a triple root with two eigenvectors (:mod:`.corner_jordan`): ``A = S - I/2``, ``A e = 0``, ``A e' = 0``, ``A g = e``,
``e`` zero on both sharp rays and at ``O``, ``e'`` not. Zorin's sufficient conditions (:mod:`.c1_sector_matrix`) ask for
two subdominant eigenvectors and do not cover this; the condition used here is derived below, not copied from a paper.

*What was checked in the literature*: the abstract of D. Zorin, *Smoothness of stationary subdivision on irregular
meshes* (Constr. Approx. 16, 2000) says it derives necessary and sufficient conditions for tangent plane and ``C^k``
continuity near extraordinary vertices and generalizes most earlier conditions; the paper's text, and J. Peters and
U. Reif's treatment of Jordan blocks (*Subdivision Surfaces*, Springer 2008), could not be read here, so the argument
below is this module's own and is not claimed to be theirs.

**The expansion.** Write the control net as ``p = c_0 1 + c_e' e' + c_g g + c_e e + r`` (``c`` in ``R^3``, ``r`` in the
span of the eigenvalues ``|lambda| < 1/2``). Then ``S^m p = c_0 + 2^-m (c_e' e' + c_g g + (c_e + 2 m c_g) e) + o(2^-m)``,
and on the ring of patches ``R`` at level ``m`` the surface is ``c_0 + 2^-m (c_e' f_e' + c_g f_g + (c_e + 2 m c_g) f_e)``
plus smaller terms, ``f_v`` the ring's spline of ``v``. Its normal (the cross product of the partial derivatives) is

    ``N_m = 2 m (c_e' x c_g) J(f_e', f_e) + O(1)``,

``J`` the Jacobian determinant of the pair ``chi_J = (f_e', f_e)`` (the ``O(1)`` terms pair ``f_g`` or ``c_e`` with the
others). Both ``e'`` and ``e`` are eigenvectors of ``1/2``, so ``chi_J(x / 2) = chi_J(x) / 2``: it is a characteristic map
of two equal eigenvalues, certified on the same ring and with the same tools as Zorin's (:func:`.c1_sector_matrix.vector_map`:
Jacobian in Bernstein-Bezier form, Arb, de Casteljau; the open sector's injectivity argument of
:mod:`.sector_injectivity`). Since ``J(f_e' + t f_e, f_e) = J(f_e', f_e)``, the choice of ``e'`` in ``ker A`` does not matter.

* ``J`` changes sign on the ring: for every net with ``c_e' x c_g != 0`` the normals at the two places point to opposite
  sides at every level: the surface turns over at ``O``, *not C1* (the reading the sector test gives a characteristic
  map whose Jacobian changes sign).
* ``J`` has one strict sign and ``chi_J`` is injective: the normal converges to ``c_e' x c_g`` (up to ``O(1/m)``), the
  tangent plane is spanned by ``c_e'`` and ``c_g``; ``f_e`` vanishes on both rays, so ``chi_J`` maps them to opposite
  directions of one line and the sector onto a half-plane. In the tangent plane's coordinates the projection is
  ``(f_e' + a f_e, f_g + (2 m + b) f_e) + o(1)`` on the level-``m`` ring (``a, b`` the in-plane parts of ``c_e``): its
  Jacobian is ``2 m J(f_e', f_e) + O(1)``, one sign near ``O``; its boundary near ``O`` (the two rays' images, straight
  segments in the directions ``(e'_0, g_0)`` and ``(e'_k, g_k)``, and one ring's outer arc, which the ``2 m f_e`` term
  stretches away from the line of the rays) is a simple closed curve, so the projection is injective there, and the
  height over the plane, ``c_e . n f_e + o(2^-m)``, has a gradient ``O(1/m)``: *C1 for almost every control net*
  (every net with ``c_e' x c_g != 0``), the normal converging only like ``1/m``, i.e. like ``1 / log(1/|x|)``.
* ``J`` of one sign but ``chi_J`` not shown injective: undecided (the consequence is not worked out).

The spectral part is certified too: 1 is simple, ``1/2`` has multiplicity exactly 3 (three eigenvalue balls of the
sector's mirror parts meet it, and ``dim ker A^2 = 3`` is exact), every other eigenvalue is below ``1/2`` in modulus.

>>> from symdecomp.schemes.files import load_scheme
>>> from symdecomp.schemes.sector import SharpVertex
>>> found = jordan_sector(load_scheme("catmull-clark-blz"), SharpVertex.corner(2, "quad"))
>>> str(found.verdict), found.sign is not None, round(found.opening, 6)
('c1', True, 1.0)
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import cast

import flint

from symdecomp.algebra.cos_field import FieldMatrix
from symdecomp.algebra.number_field import FieldElement, element_ball
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.schemes.scheme import Scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.c1_sector_matrix import vector_map
from symdecomp.verify.c1_spectrum import SpectralResult, ball_text, block_root, float_down, round_down
from symdecomp.verify.corner_jordan import HALF, JordanChain, jordan_chain
from symdecomp.verify.mirror_parts import sector_eigenvalues
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_injectivity import SectorFinding

__all__ = ["JORDAN_METHOD", "jordan_sector", "jordan_spectrum", "blocks_jordan_spectrum", "chain_vectors"]

#: The method, as reported with each verdict of this route.
JORDAN_METHOD = ("Jordan block of the subdominant 1/2 at a corner: exact kernels of (S - I/2) and (S - I/2)^2 over the "
                 "near-edge weight's field (past 12 faces: of the 1-ring block, lifted by rational solves), certified "
                 "eigenvalue balls of the mirror parts (past 12 faces: the blocks' leading values and bounds); the Jacobian of the map "
                 "(f_e', f_e) of the eigenvector e' and the chain's e = (S - I/2) g in Bernstein-Bezier form (Arb, de "
                 "Casteljau) and the argument swept between the two sharp rays")


def jordan_spectrum(found: JordanChain) -> SpectralResult:
    """The spectral part (module docstring): ``C1`` when 1 is simple, ``1/2`` has multiplicity 3 with one block of size 2,
    and every other eigenvalue is certified below ``1/2`` in modulus."""
    k = found.sm.k
    wrong = _chain_structure(found)
    if wrong is not None:
        return wrong
    values = [v[0] for v in sector_eigenvalues(found.sm)]
    half = flint.acb(HALF.numerator) / HALF.denominator
    one = [i for i, v in enumerate(values) if v.overlaps(flint.acb(1))]
    at_half = [i for i, v in enumerate(values) if v.overlaps(half)]
    if len(one) != 1 or set(one) & set(at_half):
        return SpectralResult(k, C1Verdict.UNDECIDED, "1 is not shown to be a simple eigenvalue", one_simple=False)
    if len(at_half) != 3:  # with dim ker A^2 = 3 exact, three balls meeting 1/2 hold its three copies and no other root
        return SpectralResult(k, C1Verdict.UNDECIDED, f"{len(at_half)} eigenvalue balls meet 1/2 (its multiplicity is at "
                              "least 3): the other eigenvalues are not separated from it at this precision")
    rest = [abs(v).upper() for i, v in enumerate(values) if i not in one and i not in at_half]
    top = max(rest, key=lambda x: float(x.mid())) if rest else flint.arb(0)
    if not top < flint.arb(half.real):
        return SpectralResult(k, C1Verdict.UNDECIDED, f"an eigenvalue other than 1 and 1/2 is not shown below 1/2 in modulus "
                              f"(up to {ball_text(top)})")
    gap = float_down(half.real - top)
    return SpectralResult(k, C1Verdict.C1, f"{corner_jordan_text(found)}; 1 simple, every other |lambda| <= "
                          f"{ball_text(top)}, gap >= {round_down(gap)}", block_root(half, 0, 3, defective=True), gap,
                          float(top))


def _chain_structure(found: JordanChain) -> SpectralResult | None:
    """An undecided result where the exact kernels are not the structure this route reads (``None``: they are)."""
    k = found.sm.k
    if (len(found.eigen), len(found.general)) != (2, 3) or found.chain is None:
        return SpectralResult(k, C1Verdict.UNDECIDED, f"not the Jordan structure this route reads: dim ker(S - I/2) = "
                              f"{len(found.eigen)}, dim ker(S - I/2)^2 = {len(found.general)}")
    if found.on_rays(found.chain[1]) or found.partner() is None:  # the half-plane argument needs f_e = 0 on both rays
        return SpectralResult(k, C1Verdict.UNDECIDED, "the chain's eigenvector e is nonzero on a sharp ray (or no other "
                              "eigenvector is): not the structure this route reads")
    return None


def blocks_jordan_spectrum(found: JordanChain, values: Sequence[Eigenvalue], bounds: Sequence[flint.arb]) -> SpectralResult:
    """The spectral part from the sector's blocks (no eigenvalue of the whole matrix computed): ``values`` the blocks'
    leading eigenvalues with their exact multiplicities (:func:`~symdecomp.analysis.leading_values.leading_values`),
    ``bounds`` exact upper bounds of the modulus of every eigenvalue not among them (the other sine blocks, the 2-ring's
    outer block). ``C1`` when 1 is one simple value, ``1/2`` one value of multiplicity 3 (with ``dim ker(S - I/2)^2 = 3``
    exact: one Jordan block of size 2), and every other value and bound is below ``1/2``."""
    k = found.sm.k
    wrong = _chain_structure(found)
    if wrong is not None:
        return wrong
    half = flint.acb(HALF.numerator) / HALF.denominator
    balls = {id(v): cast(flint.acb, v.ball) for v in values}  # the leading values are balls (acb)
    one = [v for v in values if balls[id(v)].overlaps(flint.acb(1))]
    if len(one) != 1 or one[0].multiplicity != 1:
        return SpectralResult(k, C1Verdict.UNDECIDED, "1 is not shown to be a simple eigenvalue", one_simple=False)
    at_half = [v for v in values if balls[id(v)].overlaps(half)]
    if len(at_half) != 1 or at_half[0].multiplicity != 3:
        return SpectralResult(k, C1Verdict.UNDECIDED, "1/2 is not one value of the blocks with multiplicity 3")
    rest = [abs(balls[id(v)]).upper() for v in values if v is not one[0] and v is not at_half[0]] + [b.upper() for b in bounds]
    top = functools.reduce(lambda a, b: a if a > b else b, rest, flint.arb(0))
    if not top < flint.arb(half.real):
        return SpectralResult(k, C1Verdict.UNDECIDED, f"an eigenvalue other than 1 and 1/2 is not shown below 1/2 in modulus "
                              f"(up to {ball_text(top)}, blocks)")
    gap = float_down(half.real - top)
    return SpectralResult(k, C1Verdict.C1, f"{corner_jordan_text(found)}; 1 simple, every other |lambda| <= "
                          f"{ball_text(top)} (blocks), gap >= {round_down(gap)}", block_root(half, 0, 3, defective=True), gap,
                          float(top))


def corner_jordan_text(found: JordanChain) -> str:
    """The structure of ``1/2`` in a few words."""
    return (f"lambda = 1/2 is a triple root with dim ker(S - I/2) = {len(found.eigen)}, dim ker(S - I/2)^2 = "
            f"{len(found.general)} (exact): a Jordan block of size 2 whose eigenvector e = (S - I/2) g vanishes on both "
            "sharp rays and O")


def _ball_vector(found: JordanChain, vector: list[FieldElement]) -> list[flint.arb] | None:
    """An exact vector over the field as real balls at the working precision, scaled to 1 at its largest entry (``None``:
    zero not excluded). The entries are polynomials of degree up to ``phi(2k)/2 - 1`` in the weight with large rational
    coefficients, whose evaluation cancels: it is done at up to 16 times the working precision, raised until every entry's
    radius is below ``2^-(prec - 8)`` relative to the largest (then rounded)."""
    weight, prec = found.sm.weight, flint.ctx.prec
    vec: list[flint.arb] = []
    for scale in (1, 2, 4, 8, 16):
        with flint.ctx.workprec(scale * prec):
            root = flint.acb(0) if weight is None else flint.acb(FieldMatrix((), found.modulus, weight).weight_ball(scale * prec))
            vec = [element_ball(x, root).real for x in vector]
            big = max(vec, key=lambda x: abs(x).mid())
            if big.contains(0):
                continue
            vec = [x / big for x in vec]
            if all(x.rad() < flint.arb(2) ** (8 - prec) for x in vec):
                break
    else:
        return None
    return [+x for x in vec]  # rounded to the working precision


def chain_vectors(found: JordanChain) -> tuple[list[flint.arb] | None, list[flint.arb] | None]:
    """``(e', e)`` as real balls (matrix order): an eigenvector nonzero on a sharp ray, and the chain's ``e``."""
    partner = found.partner()
    if partner is None or found.chain is None:
        return None, None
    return _ball_vector(found, partner), _ball_vector(found, found.chain[1])


def jordan_sector(scheme: Scheme, vertex: SharpVertex, max_depth: int = 6, found: JordanChain | None = None,
                  spectral: SpectralResult | None = None) -> SectorFinding:
    """The verdict at a corner ``vertex`` whose ``1/2`` has a Jordan block (module docstring), as a final finding;
    ``found``: the vertex's :func:`~.corner_jordan.jordan_chain` (or :func:`~.corner_jordan_blocks.block_jordan_chain`), if
    computed already; ``spectral``: its spectral part, if computed already (:func:`blocks_jordan_spectrum`)."""
    found = jordan_chain(scheme, vertex.faces, vertex.angle) if found is None else found
    spectral = jordan_spectrum(found) if spectral is None else spectral
    if spectral.status is not C1Verdict.C1:
        return SectorFinding(C1Verdict.UNDECIDED, spectral.reason, spectral, final=True, method=JORDAN_METHOD)
    half = flint.arb(HALF.numerator) / HALF.denominator
    mapped = vector_map(scheme, vertex, found.sm, spectral, list(chain_vectors(found)), (half, half), max_depth)
    return _verdict(mapped, spectral)


def _verdict(mapped: SectorFinding, spectral: SpectralResult) -> SectorFinding:
    """The chain's map's finding (:func:`~.c1_sector_matrix.vector_map`) read as the Jordan case's verdict."""
    found = mapped.reason.replace("the characteristic map", "the map (f_e', f_e)")
    if not found.startswith(spectral.reason):
        found = f"{spectral.reason}; {found}"
    normal = "the normal at level m is 2 m (c_e' x c_g) J(f_e', f_e) + O(1)"
    verdict = mapped.verdict
    if verdict is C1Verdict.C1:
        found += (f": {normal}, so the tangent plane (c_e', c_g) is reached like 1/m and the projection onto it is injective "
                  "near O: C1 for every net with c_e' x c_g != 0")
    elif verdict is C1Verdict.NOT_C1 and mapped.sign is None:
        found += f": {normal}, so the normals at the two signs of J point to opposite sides at every level: the surface turns over"
    elif verdict is C1Verdict.NOT_C1:
        verdict = C1Verdict.UNDECIDED
        found += ": the map (f_e', f_e) is regular but not injective, a case whose consequence this route does not work out"
    else:
        found += " (the map (f_e', f_e) decides the tangent plane)"
    return SectorFinding(verdict, found, spectral, mapped.lambdas, mapped.sign, mapped.bound, mapped.depth, mapped.opening,
                         final=True, method=JORDAN_METHOD)
