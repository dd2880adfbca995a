"""Zorin's conditions at boundary, crease and corner vertices with many faces: the spectrum from the sector's blocks.

The dense test (:mod:`.c1_sector_matrix`) builds the sector's exact 2-ring matrix, whose size grows like ``k`` and whose
exact spectrum costs far more; it is capped (:data:`MAP_FACES`). Here conditions 1 and 2 of :mod:`.c1_sector_matrix` are read
from the blocks of the mirror decomposition, O(log k) per sector (:mod:`symdecomp.analysis.leading_values`):

* **the 1-ring**: the sector's 2-ring matrix is block lower triangular, the new 1-ring reading only the old one, and
  the 1-ring block is the one-step matrix of a boundary (or corner) vertex with the sector's ``k`` faces, whose
  leading eigenvalues and a bound of the others come from its blocks;
* **the outer block** (the 2-ring's points past the 1-ring) holds only the regular and crease rules, so each of its
  rows is one of the rows at ``WINDOW`` faces (a row reads its point's neighbours; from ``WINDOW`` faces on, every
  kind of neighbourhood, next to a ray or between the rays, is there). Its spectral radius is at most its largest
  absolute row sum, computed exactly on the dense matrices at ``1..WINDOW + 1`` faces (the same at ``WINDOW`` and
  ``WINDOW + 1``, as the argument says), and the largest of them bounds every ``k``;
* **the boundary curve** (its eigenvalues, for condition 2) is read by crease rules only, which do not depend on
  ``k`` (:func:`~symdecomp.analysis.mirror.crease_block` has no ``k``): it is taken from the window's matrix.

So ``lambda_1, lambda_2`` are the two largest of the 1-ring's leading values once both bounds are below
``|lambda_2|``; then the spectral and tangent conditions are decided as in :mod:`.c1_sector_matrix` (the same reasons). What
the blocks decide alone is a failure: a sector whose subdominant eigenvectors miss the tangent of a boundary curve,
at any ``k``. A double subdominant eigenvalue is accepted in one case, BLZ's: one crease-block eigenvalue on its
mirror-odd vector and one of a sine block ``j`` odd, whose mode is mirror-even, so one eigenvector in each part of the
mirror's direct sum (checked exactly on the crease block). Where conditions 1 and 2 hold, conditions 3-5 are
decided on the characteristic map: for that double ``1/2`` from :data:`~.fourier_modes.WINDOW` faces on, from the
eigenvectors in closed form on a few faces per sector (:mod:`.fourier_map`, any ``k``); otherwise (or where that
route does not decide) from the eigenvectors in the mirror parts the blocks name (:func:`map_from_blocks`: no
characteristic polynomial, the sector's matrix up to :data:`~symdecomp.schemes.sector.MAX_DENSE_FACES` faces). An exact
tie ``lambda_2 = lambda_3`` (one value of the blocks, its multiplicity exact; BLZ's corners) is final: the dense test
finds the same multiple root, and is not run. At a corner's ``1/2`` (BLZ's corners: two eigenvectors and a block of
size 2, :mod:`.corner_jordan`) the block's own test decides (:mod:`.c1_corner_jordan`: the map of the chain's
eigenvector and the other one): up to :data:`~.corner_jordan.JORDAN_FACES` faces from the whole matrix's kernels, past
it from the 1-ring block's (:mod:`.corner_jordan_blocks`) with the spectral part from the blocks' leading values and
bounds, up to :data:`~.corner_jordan_blocks.BLOCK_JORDAN_FACES` faces (past it: undecided, the structure not
computed); and so does it for the dense test's tie at a corner given the angle ``pi`` (whole matrix, up to that cap).
Everything else (other multiple subdominant eigenvalues, a map not certified) goes to the dense test up to
:data:`MAP_FACES` faces, and past it the verdict is *undecided* with the blocks' finding as its reason (for BLZ's
rules where no closed form is found past the map's faces: the spectral and tangent conditions hold).
Darts, corners given an angle and semi-sharp creases are the dense test's alone.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> from symdecomp.schemes.sector import SharpVertex
>>> r = c1_mirror_blocks(catmull_clark(), SharpVertex.boundary(1000, "quad"))
>>> str(r.verdict), r.lambdas[0] > 0.65
('not-c1', True)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from symdecomp.analysis.leading_values import leading_values
from symdecomp.analysis.mirror import crease_block
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import check_scheme
from symdecomp.schemes.sector import MAX_DENSE_FACES, SharpVertex
from symdecomp.validate import check_depth
from symdecomp.verify.boundary_tangent import curve_eigenvalues, tangent_condition
from symdecomp.verify.c1_corner_jordan import blocks_jordan_spectrum, jordan_sector
from symdecomp.verify.c1_sector_matrix import SharpC1Result, _describe, c1_sharp_test, deciding_sector, sector_map
from symdecomp.verify.c1_spectrum import SpectralResult, ball_text, block_root, float_down, round_down
from symdecomp.verify.corner_jordan import HALF, JORDAN_FACES, chain_structure, corner_jordan, jordan_chain
from symdecomp.verify.corner_jordan_blocks import BLOCK_JORDAN_FACES, block_jordan_chain
from symdecomp.verify.fourier_map import applies, fourier_map
from symdecomp.verify.mirror_parts import block_parts, sector_matrices, sector_parts
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_injectivity import SectorFinding

__all__ = ["c1_mirror_blocks", "MAP_FACES", "WINDOW", "BLOCKS_METHOD", "MAP_METHOD", "map_from_blocks"]

#: Most faces of a sector for which the dense test (:mod:`.c1_sector_matrix`) is run where the blocks do not decide.
MAP_FACES = 32
#: Faces of the windows on which the outer block's rows and the boundary curve are read.
WINDOW = 4
#: The method, as reported with each verdict the blocks decide.
BLOCKS_METHOD = ("Zorin's conditions 1-2 from the sector's blocks: exact crease block and sine blocks j <= 3, a certified bound "
                 "of the other sine blocks and of the 2-ring's outer block; tangent of the boundary curve among the "
                 "subdominant eigenvalues")
#: The method, as reported with each verdict whose map this route certified (:func:`map_from_blocks`).
MAP_METHOD = ("Zorin's conditions 1-2 from the sector's blocks (certified leading values, exact multiplicities); the "
              "subdominant eigenvectors as certified null vectors in the mirror parts the blocks name; Jacobian of the "
              "sector's spline ring in Bernstein-Bezier form (Arb, de Casteljau); argument swept between the two sharp rays")


@dataclass(frozen=True)
class _Window:
    """What the route reads once per scheme and kind of sector: the outer block's bound and a matrix with the curve."""

    #: The outer block's largest absolute row sum (exact), an upper bound of its eigenvalues' moduli.
    outer: Fraction
    #: ``(roots, problem)`` of the boundary curve block at ``1..WINDOW`` faces (the last is every larger ``k``'s).
    curves: tuple

    def curve(self, k: int) -> tuple:
        """The boundary curve's eigenvalues (or why they are not read) in a sector of ``k`` faces."""
        return self.curves[min(k, WINDOW) - 1]


def _outer_norm(sm) -> Fraction:
    """The outer block's largest absolute row sum, after checking the new 1-ring reads only the old one (exactly)."""
    S = sm.matrix
    ring1 = {i for i, lab in enumerate(sm.labels) if sm.lattice.ring_of(lab[1], lab[2]) <= 1}
    outer = [i for i in range(S.rows) if i not in ring1]
    if any(S[i, j] != 0 for i in ring1 for j in outer):
        raise NotApplicableError("the sector's new 1-ring reads its outer points: the blocks route does not apply")
    entries = [[S[i, j] for j in outer] for i in outer]
    if not all(sp.sympify(e, strict=True).is_Rational for row in entries for e in row):
        raise NotApplicableError("the sector's outer rules are not rational: the blocks route does not apply")
    return max(sum((abs(Fraction(int(e.p), int(e.q))) for e in row), Fraction(0)) for row in entries)


@functools.lru_cache(maxsize=16)
def _window(scheme, lattice, corner: bool) -> _Window:
    def sector(k: int):
        return sector_matrices(scheme, SharpVertex.corner(k, lattice) if corner else SharpVertex.boundary(k, lattice))

    matrices = [sector(k) for k in range(1, WINDOW + 2)]
    norms = [_outer_norm(sm) for sm in matrices]
    if norms[-1] != norms[-2]:
        raise NotApplicableError(f"the outer block's row sums differ at {WINDOW} and {WINDOW + 1} faces ({norms[-2]}, {norms[-1]})")
    return _Window(max(norms), tuple(curve_eigenvalues(sm) for sm in matrices[:WINDOW]))


def _undecided(k: int, reason: str) -> SectorFinding:
    return SectorFinding(C1Verdict.UNDECIDED, reason, SpectralResult(k, C1Verdict.UNDECIDED, reason))


def _is_real(value, values) -> bool:
    """A simple value of a real block whose conjugate ball meets no other value of the head is real (its conjugate,
    an eigenvalue of the same block, is in the head)."""
    conj = value.ball.conjugate()
    return value.ball.imag.contains(0) and not any(w is not value and w.ball.overlaps(conj) for w in values)


def _in_two_parts(crease: sp.Matrix, value) -> bool:
    """Whether a double eigenvalue is one of the crease block's, on its mirror-odd vector, and one of a sine block ``j`` odd,
    whose mode is mirror-even (``sin(j pi (k - s)/k) = sin(j pi s/k)``): then it has an eigenvector in each part of the
    mirror's direct sum (as the dense test requires: each simple in its part), and no Jordan block joins them."""
    names = sorted(value.blocks, key=lambda name: name.block)
    if value.multiplicity != 2 or [n.block for n in names] != ["crease", "sine"] or names[1].j % 2 == 0:
        return False
    if value.key[0] != "q":
        return False
    return _odd_simple(sp.ImmutableMatrix(crease), value.key[1])


@functools.lru_cache(maxsize=64)
def _odd_simple(crease: sp.ImmutableMatrix, value: Fraction) -> bool:
    """Whether ``value`` is a simple eigenvalue of the crease block with the mirror-odd eigenvector (exact; decided once
    per block and value, not per sector)."""
    q = sp.Rational(value.numerator, value.denominator)
    odd = sp.Matrix([0, 1, -1])  # O and its two sharp neighbours: the mirror exchanges the neighbours
    shifted = crease - q * sp.eye(3)
    return shifted * odd == sp.zeros(3, 1) and shifted.rank() == 2


def _exact_tie(lead) -> bool:
    """Whether ``lambda_2 = lambda_3`` exactly: one value of the blocks holds both (its multiplicity is exact)."""
    values = list(lead.values)
    unit = [v for v in values if v.ball.overlaps(flint.acb(1))]
    if len(unit) != 1:
        return False
    rest = [v for v in values if v is not unit[0] for _ in range(v.multiplicity)]
    return len(rest) > 2 and rest[2] is rest[1]


def _spectral(k: int, lead, outer: Fraction, crease: sp.Matrix) -> tuple[SpectralResult, list]:
    """Condition 1 from the leading values: ``(result, picks)`` with ``picks`` the two subdominant values (balls)."""
    values = list(lead.values)
    unit = [v for v in values if v.ball.overlaps(flint.acb(1))]
    if len(unit) != 1 or unit[0].multiplicity != 1:
        return SpectralResult(k, C1Verdict.UNDECIDED, "1 is not shown to be a simple eigenvalue", one_simple=False), []
    rest = [v for v in values if v is not unit[0] for _ in range(v.multiplicity)]
    if len(rest) < 2:
        return SpectralResult(k, C1Verdict.UNDECIDED, "fewer than two eigenvalues after 1 in the blocks read"), []
    bounds = [flint.arb(outer.numerator) / outer.denominator] + ([lead.tail] if lead.tail is not None else [])
    second = abs(rest[1].ball)
    if not all(b < second for b in bounds):
        return SpectralResult(k, C1Verdict.UNDECIDED, f"lambda_2 = {ball_text(rest[1].ball)} is not shown larger than the "
                              "bound of the other blocks"), []
    top, picks = rest[:2], [(v.ball, v, None) for v in rest[:2]]
    lam = [ball_text(v.ball) for v in top]
    uppers = [b.upper() for b in bounds] + ([abs(rest[2].ball).upper()] if len(rest) > 2 else [])
    third = functools.reduce(lambda a, b: a if a > b else b, uppers)
    if len(rest) > 2 and not abs(rest[2].ball) < second:
        how = ("equal (one exact value of the blocks, counted with its multiplicity): lambda_2 is not strictly dominant, "
               "which Zorin's sufficient conditions need" if rest[2] is rest[1] else "not separated")
        return SpectralResult(k, C1Verdict.UNDECIDED, f"lambda_2 = {lam[1]} and lambda_3 = {ball_text(rest[2].ball)} are "
                              f"{how}"), picks
    if top[0] is top[1] and not _in_two_parts(crease, top[0]):
        return SpectralResult(k, C1Verdict.UNDECIDED, f"lambda_1 = lambda_2 = {lam[0]} (a double eigenvalue of the blocks: "
                              "its eigenvectors are the dense route's, by the mirror's parts)"), picks
    for v in top:
        if not _is_real(v, values) or not v.ball.real > 0:
            return SpectralResult(k, C1Verdict.UNDECIDED, f"the subdominant eigenvalue {ball_text(v.ball)} is not shown real "
                                  "and positive"), picks
    gap = float_down(second.lower() - third)
    return SpectralResult(k, C1Verdict.C1, f"lambda_1 = {lam[0]}, lambda_2 = {lam[1]}, real, gap >= {round_down(gap)}",
                          block_root(top[0].ball, 0, 1), gap, float(third)), picks


def _tie_finding(scheme, vertex: SharpVertex, k: int, spectral: SpectralResult, picks: list, max_depth: int | None,
                 lead, outer: Fraction) -> SectorFinding:
    """An exact tie (final): at a corner's ``1/2`` (BLZ's corners) the Jordan block's own verdict (:mod:`.c1_corner_jordan`;
    with ``max_depth=None``, its structure in the reason only): up to :data:`~.corner_jordan.JORDAN_FACES` faces from the
    whole matrix, past it from the blocks (the chain from the 1-ring block, :mod:`.corner_jordan_blocks`, and the spectral
    part from ``lead``, the blocks' leading values, and ``outer``, the outer block's bound)."""
    lambdas = tuple(float(p[0].real.mid()) for p in picks) or None
    reason = spectral.reason
    if vertex.corner and len(picks) >= 2 and picks[1][0].contains(flint.acb(HALF.numerator) / HALF.denominator):
        corner = SharpVertex.corner(k, vertex.lattice)
        if k <= JORDAN_FACES:
            if max_depth is None:
                return SectorFinding(spectral.status, f"{reason}; {corner_jordan(scheme, k).reason()}", spectral, lambdas, final=True)
            return jordan_sector(scheme, corner, max_depth)
        if k > BLOCK_JORDAN_FACES:
            return SectorFinding(spectral.status, f"{reason}; the Jordan structure of 1/2 is computed for at most "
                                 f"{BLOCK_JORDAN_FACES} faces", spectral, lambdas, final=True)
        found = block_jordan_chain(scheme, k)
        if max_depth is None:
            return SectorFinding(spectral.status, f"{reason}; {chain_structure(found).reason()}", spectral, lambdas, final=True)
        bounds = [flint.arb(outer.numerator) / outer.denominator] + ([lead.tail] if lead.tail is not None else [])
        return jordan_sector(scheme, corner, max_depth, found, blocks_jordan_spectrum(found, lead.values, bounds))
    return SectorFinding(spectral.status, reason, spectral, lambdas, final=True)


def _with_jordan(scheme, vertex: SharpVertex, result: SharpC1Result, max_depth: int) -> SharpC1Result:
    """The dense test's undecided verdict at a corner given an angle: where ``1/2`` has a Jordan block there (at most
    :data:`~.corner_jordan.JORDAN_FACES` faces), the block's own verdict (:mod:`.c1_corner_jordan`)."""
    if not vertex.corner or result.verdict is not C1Verdict.UNDECIDED or vertex.faces > JORDAN_FACES:
        return result
    chain = jordan_chain(scheme, vertex.faces, vertex.angle)
    if len(chain.general) < 3:
        return result
    with flint.ctx.workprec(64):
        found = jordan_sector(scheme, vertex, max_depth, chain)
    return _blocks_result(scheme, vertex, [found], max_depth)


def _sector(scheme, vertex: SharpVertex, sector: int, max_depth: int | None) -> SectorFinding:
    """Conditions 1 and 2 in one sector of ``k`` faces (module docstring), then 3-5 by :func:`map_from_blocks` (``max_depth``:
    its deepest subdivision; ``None``: the blocks alone)."""
    lattice, k, corner = scheme.lattice, vertex.sectors[sector], vertex.corner
    window = _window(scheme, lattice, corner)
    lead = leading_values(scheme, SharpVertex.corner(k, lattice) if corner else SharpVertex.boundary(k, lattice))
    crease = crease_block(scheme, 2, corner=corner)
    spectral, picks = _spectral(k, lead, window.outer, crease)
    lambdas = tuple(float(p[0].real.mid()) for p in picks) or None
    tangent = tangent_condition(*window.curve(k), picks) if picks else None
    if tangent and tangent[0] is C1Verdict.NOT_C1:
        return SectorFinding(C1Verdict.NOT_C1, tangent[1], spectral, lambdas)
    if spectral.status is not C1Verdict.C1:  # an exact tie is final: the dense test finds the same multiple eigenvalue
        if _exact_tie(lead):
            return _tie_finding(scheme, vertex, k, spectral, picks, max_depth, lead, window.outer)
        return SectorFinding(spectral.status, spectral.reason, spectral, lambdas)
    if tangent:
        return SectorFinding(tangent[0], tangent[1], spectral, lambdas)
    if max_depth is None:
        return SectorFinding(C1Verdict.UNDECIDED, f"{spectral.reason}; the spectral and tangent conditions hold (blocks), the "
                             "characteristic map is not built (the blocks alone)", spectral, lambdas)
    if applies(vertex, k, picks, crease):
        try:
            found = fourier_map(scheme, vertex, k, spectral, picks, max_depth)
        except NotApplicableError as exc:
            found = SectorFinding(C1Verdict.UNDECIDED, f"{spectral.reason}; no closed-form modes: {exc}", spectral, lambdas)
        if found.verdict is not C1Verdict.UNDECIDED or k > MAX_DENSE_FACES:
            return found
    found = map_from_blocks(scheme, vertex, sector, spectral, picks, crease, max_depth)
    if found.verdict is C1Verdict.UNDECIDED and vertex.faces <= MAX_DENSE_FACES:
        with flint.ctx.workprec(2 * flint.ctx.prec):  # the balls of the eigenvectors' solves, as the dense test retries
            found = map_from_blocks(scheme, vertex, sector, spectral, picks, crease, max_depth)
    return found


def _blocks_result(scheme, vertex: SharpVertex, found: list[SectorFinding], max_depth: int) -> SharpC1Result:
    key, reason = deciding_sector(vertex, found)
    verdict = key.verdict
    if verdict is C1Verdict.UNDECIDED and not all(f.final or f.verdict is C1Verdict.C1 for f in found):
        reason += f" (the dense test reads sectors of at most {MAP_FACES} faces)"
    mapped = key.sign is not None or key.depth is not None
    return SharpC1Result(n=vertex.faces, scheme=scheme.name, verdict=verdict, reason=reason, spectral=key.spectral,
                         jacobian_sign=key.sign, jacobian_lower_bound=key.bound, subdivision_depth=key.depth,
                         max_depth=max_depth, lattice=vertex.lattice, vertex=_describe(vertex), lambdas=key.lambdas,
                         opening=key.opening, winding_number=1 if verdict is C1Verdict.C1 else None,
                         method=key.method or (MAP_METHOD if mapped else BLOCKS_METHOD))


def map_from_blocks(scheme, vertex: SharpVertex, sector: int, spectral: SpectralResult, picks: list, crease: sp.Matrix,
                    max_depth: int) -> SectorFinding:
    """Conditions 3-5 in sector ``sector`` of ``vertex``, the spectral conditions holding by the blocks: each subdominant
    eigenvector is the certified null vector of its mirror part's 1-ring block at the blocks' ball (the part the blocks
    name, :func:`~.mirror_parts.block_parts`; the square solve proves the kernel has dimension at most 1), lifted to the
    outer points by a certified solve (:func:`~.mirror_parts.sector_eigenvector`); then the dense test's own routine
    (:func:`~.c1_sector_matrix.sector_map`). No characteristic polynomial (with BLZ's weights in ``cos(pi/k)`` the dense test's
    costs minutes from about 30 faces on), but the sector's exact matrix: at most
    :data:`~symdecomp.schemes.sector.MAX_DENSE_FACES` faces, the linear algebra in Arb cubic in ``k``."""
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


def c1_mirror_blocks(scheme, vertex: SharpVertex, *, max_depth: int = 6, map_faces: int = MAP_FACES,
                    certify_map: bool = True) -> SharpC1Result:
    """Zorin's test at a boundary, crease or corner vertex: the blocks first, then the characteristic map from the
    eigenvectors they name (:func:`map_from_blocks`; not with ``certify_map=False``), the dense test where these do not
    decide and every sector has at most ``map_faces`` faces (module docstring)."""
    scheme, max_depth = check_scheme(scheme), check_depth(max_depth)
    sharp_sectors = not vertex.closed or (math.isinf(vertex.sharpness) and len(vertex.sectors) == 2)
    if not sharp_sectors or vertex.angle is not None or vertex.lattice is not scheme.lattice:
        if vertex.angle is not None and max(vertex.sectors) > map_faces:
            raise NotApplicableError(f"a corner given an angle is tested on its dense matrices, at most {map_faces} faces")
        return _with_jordan(scheme, vertex, c1_sharp_test(scheme, vertex, max_depth=max_depth), max_depth)
    try:
        with flint.ctx.workprec(64):
            found = [_sector(scheme, vertex, i, max_depth if certify_map else None) for i in range(len(vertex.sectors))]
    except NotApplicableError as exc:
        if max(vertex.sectors) <= map_faces:
            return c1_sharp_test(scheme, vertex, max_depth=max_depth)
        found = [_undecided(k, f"the blocks route does not apply ({exc})") for k in vertex.sectors]
    decided = any(f.verdict is C1Verdict.NOT_C1 for f in found) or all(f.verdict is C1Verdict.C1 or f.final for f in found)
    if decided or max(vertex.sectors) > map_faces:
        return _blocks_result(scheme, vertex, found, max_depth)
    return c1_sharp_test(scheme, vertex, max_depth=max_depth)
