"""The toolkit checked against OpenSubdiv (an outside oracle), at an interior vertex and at a sector.

OpenSubdiv implements Catmull-Clark and Loop with their standard weights; which comparison runs is the
lattice's (:func:`comparison`, read with :meth:`~symdecomp.schemes.lattice.Lattice.select` by the regular
patch). The measurements (single OpenSubdiv steps chained, renormalised, split by frequency) are
:mod:`symdecomp.verify.step_chains`; what a comparison reports, :mod:`symdecomp.verify.comparisons`.

*Catmull-Clark* (:func:`compare_with_opensubdiv`). For a valence ``n`` a random 1-ring in ``R^3`` (seeded) is
pushed through OpenSubdiv's uniform Catmull-Clark refinement (:mod:`symdecomp.verify.opensubdiv`), and what
OpenSubdiv computes is compared with what the toolkit predicts from the scheme's rules:

======================  =============================================  ============================
prediction              toolkit side                                   expected agreement
======================  =============================================  ============================
one-step matrix         ``subdivision_matrix`` (exact) times the       double precision
                        ring OpenSubdiv started the step from
1-ring locality         OpenSubdiv on the 1-ring alone vs on a         double precision
                        3-ring mesh containing it
limit mask              left eigenvector of eigenvalue 1 of the        double precision
                        exact matrix vs OpenSubdiv's ``Limit``
limit position          ``O_k -> l . ring_0``                          error ~ mu_2^k
shrink rate, freq. j    ``lambda_dom(j)`` (Eq. 34,                     ~ (lambda_sub/lambda_dom)^k
                        ``tangent_eigenvalues``); ``j = 0``: the
                        subdominant ``mu_2`` of Eq. 43
Eq. 39 ratio            ``B^1/A^1 -> invariant_ratio_at(n, 1)``        ~ (lambda_sub/lambda_dom)^k
elliptic ratio Eq. 44   ``(bbar-O)/(abar-O) -> (u_b-u_O)/(u_a-u_O)``   ~ (mu_3/mu_2)^k
hyperbolic decay        shrink rate of frequency 2                     as for frequency 2
======================  =============================================  ============================

Levels are chained one at a time: the 1-ring read back after a step is the next step's
input mesh (the new 1-ring of an interior vertex depends only on its old 1-ring, which the
"1-ring locality" row checks in OpenSubdiv itself). Between steps the ring is translated
to put ``O`` at the origin and scaled by a power of two, which keeps the shrinking
components at full relative precision; every compared quantity is invariant under that
(ratios, rates) or is computed in the original coordinates (limit position).

The Fourier components follow :func:`symdecomp.analysis.tangent.invariant_ratio`: ``a_i = sum_j
A^j omega^{ij}``, i.e. ``A^j = (1/n) sum_i a_i omega^{-ij}``, ``omega = exp(2 pi i/n)``.
OpenSubdiv implements the standard vertex rule, so everything is compared with
``catmull_clark()`` (standard weights).

*Loop* (:func:`compare_loop_with_opensubdiv`). OpenSubdiv's Loop refinement
(:mod:`symdecomp.verify.opensubdiv.loop`) is compared with what the toolkit derives from the rules of
:func:`~symdecomp.schemes.loop.loop`:

======================  ===========================================  ======================
prediction              toolkit side                                 expected agreement
======================  ===========================================  ======================
one-step matrix         ``ring_subdivision_matrix`` (exact), read    double precision
                        column by column from OpenSubdiv
spectrum                ``ring_spectrum`` (with multiplicities) vs   double precision
                        the eigenvalues of OpenSubdiv's matrix
limit mask              ``ring_masks`` position mask vs              double precision
                        OpenSubdiv's ``Limit``
tangent plane           ``ring_masks`` tangent masks span            double precision
                        OpenSubdiv's two limit tangents
limit position          ``O_k -> l . ring_0``                        error ~ mu^k, mu the
                                                                     value after 1 at j = 0
shrink rate, freq. j    the dominant eigenvalue of frequency ``j``   exact when frequency
                        (``j = 0``: the one after 1)                 ``j`` has one value
======================  ===========================================  ======================

The shrink rates are measured as for Catmull-Clark: a random 1-ring ``(O, a_0..a_{n-1})`` is
pushed through single OpenSubdiv steps, each fed the 1-ring the previous one returned
(renormalised by a translation and a power of two), and the part in frequencies ``j`` and
``n - j`` is followed alone (projected back after every step). Loop's 1-ring has one value
per frequency ``j != 0`` (``3/8 + cos(2 pi j/n)/4``) and one after 1 at ``j = 0``
(``5/8 - n beta(n)``), so each rate is the ratio of one step exactly, to rounding.

*Boundary, corner, crease and dart vertices* (:func:`compare_sharp_case`). For a :class:`SharpCase` (scheme,
kind of vertex, ``k`` faces per sector, sharpness, boundary interpolation, creasing method) the toolkit's exact
one-step matrix (:func:`symdecomp.schemes.sector.exact_sharp_matrix`) is compared at every refinement level until
a semi-sharp crease has decayed with OpenSubdiv's (:func:`symdecomp.verify.opensubdiv.sharp.osd_sharp_ring`
on the same tagged fan, doubles; the measures are :mod:`symdecomp.verify.matrix_measures`):

* ``matrix``: the largest entry of ``|ours - OpenSubdiv|`` (ours exact, the difference taken exactly);
* ``ring closed``: OpenSubdiv's new ring points have no weight outside the ring;
* ``spectrum``: for every eigenvalue of either matrix, the smallest singular value of the other
  matrix minus it (the distance to the nearest matrix with that eigenvalue: robust at Jordan blocks);
* ``limit mask``: ours is exact -- the left eigenvector of eigenvalue 1 at the first level where the
  vertex's rule no longer changes, pulled back through the exact matrices of the levels before;
  OpenSubdiv's is ``PrimvarRefiner::Limit`` at the level;
* ``curve tangent``: OpenSubdiv's first derivative mask at a boundary, corner or crease vertex must
  lie in the span of our left eigenvectors of eigenvalue 1/2 (the cubic B-spline crease curve);
* ``surface tangent 1`` and ``2``: OpenSubdiv's two derivative masks must lie in the span of our left
  eigenvectors of the largest eigenvalues below 1: two of them with their multiplicities (the tangent
  plane), three at a crease (each side's plane, sharing the crease direction);
* ``limit point`` (level 0): OpenSubdiv's patch table at the vertex's corner ``(u, v) = (0, 0)`` of
  every face, for a random fan, against our exact limit mask applied to it.

Every measure is absolute on weights of size at most 1 (relative to 1); all must be at most
:data:`~symdecomp.verify.comparisons.TOLERANCE` (1e-12). While a semi-sharp crease has not decayed, OpenSubdiv's limit and tangent
masks are those of the crease rule of that level (its ``Limit`` takes the level's rule), not the
limit of the surface: those rows are reported with their numbers and marked not comparable, and
the limit point (the patch table refines the crease away) is the check of the true limit there.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from symdecomp.analysis.masks import ring_masks
from symdecomp.analysis.spectrum import ring_spectrum
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice, lattice_of_reference
from symdecomp.schemes.loop import loop
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.validate import INPUT_LIMITS, check_int, check_levels, check_valence
from symdecomp.verify.comparisons import Prediction, SharpCheck, SharpResult, ValenceComparison, exact_row, limit_row
from symdecomp.verify.matrix_measures import (
    DIGITS,
    difference,
    floats,
    left_spans,
    limit_masks,
    spectrum_distance,
    tangent_residual,
)
from symdecomp.verify.opensubdiv.sharp import OsdFan, OsdOptions, tagged_fan
from symdecomp.verify.predictions import toolkit_predictions
from symdecomp.verify.step_chains import (
    loop_chain,
    lsq_ratio,
    quad_chain,
    random_ring,
    ring_as_mesh,
    ring_frequency_part,
    triangle_frequency_part,
)

__all__ = ["compare_with_opensubdiv", "compare_loop_with_opensubdiv", "comparison", "KINDS", "SHARPNESS", "SharpCase",
           "sharp_cases", "compare_sharp_case"]


#: Most refinement levels compared (double precision: beyond this the ring is below rounding).
MAX_LEVELS = INPUT_LIMITS["levels"][0]


def compare_with_opensubdiv(n: int, levels: int = 20, seed: int = 0) -> ValenceComparison:
    """Run the comparisons of this module at valence ``n`` (needs the OpenSubdiv bridge).

    ``"exact"`` rows agree when the disagreement is below ``EXACT_TOLERANCE`` (1e-13, on data
    of size about 1). ``"limit"`` rows agree when the disagreement at the last level is below
    ``100 * rate^levels + 1e-12`` (the constant absorbs the random data's eigen-coefficients).
    """
    from symdecomp.verify.opensubdiv import osd_central_rings

    n = check_valence(n)
    levels = check_levels(levels, minimum=2, maximum=MAX_LEVELS, reason="double precision: beyond this the ring is below rounding")
    seed = check_int(seed, "seed", minimum=0, maximum=2**32 - 1)
    pred = toolkit_predictions(n)
    ring0 = random_ring(n, seed)
    rows: list[Prediction] = []

    # 1-ring locality, inside OpenSubdiv: the 1-ring alone vs a 3-ring mesh containing it.
    alone = osd_central_rings(ring_as_mesh(ring0, n, 1, seed), 0, 3)
    larger = osd_central_rings(ring_as_mesh(ring0, n, 3, seed), 0, 3)
    rows.append(exact_row("1-ring locality", float(np.max(np.abs(alone.rings - larger.rings)))))

    # limit mask vs OpenSubdiv's limit positions
    limit = np.array([float(sum(w * Fraction(p[c]) for w, p in zip(pred.limit_mask, ring0))) for c in range(3)])
    rows.append(exact_row("limit mask", float(max(np.max(np.abs(alone.limit - limit)), np.max(np.abs(larger.limit - limit))))))

    # The whole random ring, chained: the one-step matrix and the limit position.
    chain = quad_chain(ring0, n, levels, pred.matrix, limit=limit)
    rows.insert(0, exact_row("one-step matrix", chain.one_step))
    mu2, mu3 = pred.mu
    floor = 1e-13
    rows.append(limit_row("limit position", None, None, chain.centre_errors, abs(mu2), floor, levels))

    # Per frequency: the ring's frequency-j part alone (j and n - j together, so it stays real),
    # projected back onto frequency j after every OpenSubdiv step so that rounding noise in the
    # other frequencies cannot outgrow it.
    leak = 0.0
    chains = {}
    for j in range(0, n // 2 + 1):
        part = ring_frequency_part(np.array(ring0), n, j)
        chains[j] = quad_chain(part, n, levels, pred.matrix, frequency=j)
        leak = max(leak, chains[j].leak)
    rows.append(exact_row("frequencies decouple", leak))

    rows.extend(_shrink_rates(n, chains, pred, floor, levels))

    # Eq. 39: B^1/A^1 on the frequency-1 chain
    q1 = abs(pred.tangent[1][1] / pred.tangent[1][0])
    ratios = [lsq_ratio(b[1], a[1]) for _, (o, a, b) in chains[1].steps]
    rows.append(limit_row("Eq. 39 ratio B1/A1", pred.eq39_ratio, ratios[-1], [abs(r - pred.eq39_ratio) for r in ratios], q1, floor, levels))

    # Eq. 44: (bbar - O)/(abar - O) on the frequency-0 chain
    ell = [lsq_ratio(b[0].real - o, a[0].real - o).real for _, (o, a, b) in chains[0].steps]
    q0 = abs(mu3 / mu2)
    rows.append(limit_row("Eq. 44 elliptic ratio", pred.elliptic_ratio, ell[-1], [abs(r - pred.elliptic_ratio) for r in ell], q0, floor, levels))
    return ValenceComparison(n, levels, seed, tuple(rows))


def _shrink_rates(n: int, chains: dict, pred, floor: float, levels: int) -> list:
    """The ``shrink rate j=..`` rows: each frequency's chain against its dominant eigenvalue.

    The shrink rate of frequency j is read as ell(Z_{k+1}) / ell(Z_k) for a fixed generic linear
    functional ell of Z = (A^j, B^j) (j = 0: (abar - O, bbar - O)); its error is exactly
    C (lambda_sub/lambda_dom)^k to first order (a norm ratio can have a vanishing first-order term).
    """
    rows = []
    mu2, mu3 = pred.mu
    ell = np.array([complex(*x) for x in np.random.default_rng(12345).uniform(-1, 1, (6, 2))])
    for j in range(0, n // 2 + 1):
        seq = []
        for (o0, a0, b0), (o1, a1, b1) in chains[j].steps:
            if j == 0:
                z0 = np.concatenate([a0[0].real - o0, b0[0].real - o0])
                z1 = np.concatenate([a1[0].real - o1, b1[0].real - o1])
            else:
                z0 = np.concatenate([a0[j], b0[j]])
                z1 = np.concatenate([a1[j], b1[j]])
            seq.append(complex(np.dot(ell, z1) / np.dot(ell, z0)))
        if j == 0:
            dom, q = abs(mu2), abs(mu3 / mu2)
        else:
            d, s_ = pred.tangent[j]
            dom, q = abs(d), abs(s_ / d)
        name = f"shrink rate j={j}" + (" (hyperbolic)" if j == 2 else "")
        errs = [abs(x - dom) for x in seq]
        seen = abs(seq[-1])
        if q >= 1 - 1e-12:  # a double eigenvalue (M_j = I/4 at j = n/2): the rate is exact
            rows.append(exact_row(name, max(errs), predicted=dom, observed=seen))
        else:
            rows.append(limit_row(name, dom, seen, errs, q, floor, levels))
    return rows


def _frequency_values(spectrum, n: int) -> dict[int, list[complex]]:
    """The distinct eigenvalues of each frequency ``j`` (1 left out at ``j = 0``), largest first."""
    out: dict[int, list[complex]] = {j: [] for j in range(n // 2 + 1)}
    for e in spectrum.eigenvalues:
        value = complex(float(e.value.real.mid()), float(e.value.imag.mid()))
        for j in e.frequencies:
            if j in out and not (j == 0 and abs(value - 1) < 1e-12):
                out[j].append(value)
    return {j: sorted(v, key=abs, reverse=True) for j, v in out.items()}


def compare_loop_with_opensubdiv(n: int, levels: int = 20, seed: int = 0) -> ValenceComparison:
    """Run the comparisons of this module at valence ``n`` (needs the OpenSubdiv bridge).

    Tolerances as in :func:`~symdecomp.verify.oracle.compare_with_opensubdiv`.
    """
    from symdecomp.verify.opensubdiv.loop import osd_loop_one_ring_matrix, osd_loop_position_mask, osd_loop_tangent_masks

    n = check_valence(n)
    levels = check_levels(levels, minimum=2, maximum=MAX_LEVELS, reason="double precision: beyond this the ring is below rounding")
    seed = check_int(seed, "seed", minimum=0, maximum=2**32 - 1)
    scheme = loop()
    exact = ring_subdivision_matrix(scheme, n, 1).exact_matrix()
    S = np.array([[float(exact[r, c]) for c in range(n + 1)] for r in range(n + 1)])
    osd = np.array(osd_loop_one_ring_matrix(n))
    rows = [exact_row("one-step matrix", float(np.max(np.abs(osd - S))))]

    spectrum = ring_spectrum(scheme, n, 1, digits=20, exact=False, jordan=False)
    ours = sorted((complex(float(e.value.real.mid()), float(e.value.imag.mid())) for e in spectrum.eigenvalues
                   for _ in range(e.multiplicity)), key=lambda z: (z.real, z.imag))
    theirs = sorted(np.linalg.eigvals(osd), key=lambda z: (z.real, z.imag))
    rows.append(exact_row("spectrum", max(abs(a - b) for a, b in zip(ours, theirs)) if len(ours) == len(theirs) else math.inf))

    masks = ring_masks(scheme, n, 1, digits=20)
    position = np.array([float(masks["position"]["O"])] + [float(x) for x in masks["position"]["a"]])
    rows.append(exact_row("limit mask", float(np.max(np.abs(np.array(osd_loop_position_mask(n)) - position)))))
    tangents = np.array([[float(m["O"])] + [float(x) for x in m["a"]] for m in masks["tangents"]])
    osd_tangents = np.array(osd_loop_tangent_masks(n))
    C, *_ = np.linalg.lstsq(tangents.T, osd_tangents.T, rcond=None)
    spans = abs(np.linalg.det(C)) > 1e-8
    residual = float(np.abs(tangents.T @ C - osd_tangents.T).max() / max(1.0, np.abs(osd_tangents).max()))
    rows.append(exact_row("tangent plane", residual if spans else math.inf))

    rng = random.Random(f"symdecomp-oracle-loop:{seed}:{n}")
    ring0 = np.array([[rng.uniform(-1.0, 1.0) for _ in range(3)] for _ in range(n + 1)])
    values = _frequency_values(spectrum, n)
    floor = 1e-13
    _, centres = loop_chain(ring0, n, levels, None)
    limit = position @ ring0
    # the centre sees frequency 0 only (the vertex rule weighs all a_i alike): it converges with its value after 1
    rate = abs(values[0][0])
    rows.append(limit_row("limit position", None, None, [float(np.max(np.abs(c - limit))) for c in centres], rate, floor, levels))
    rows.extend(_loop_shrink_rates(ring0, n, levels, values, floor))
    return ValenceComparison(n, levels, seed, tuple(rows))


def _loop_shrink_rates(ring0: np.ndarray, n: int, levels: int, values: dict, floor: float) -> list[Prediction]:
    """``shrink rate j=..``: a generic linear functional of frequency ``j``'s part, step over step."""
    ell = np.array([complex(*x) for x in np.random.default_rng(12345).uniform(-1, 1, (3, 2))])
    rows = []
    for j in range(n // 2 + 1):
        steps, _ = loop_chain(triangle_frequency_part(ring0, n, j), n, levels, j)
        seq = []
        for before, after in steps:
            if j == 0:
                z0, z1 = before[1:].mean(axis=0) - before[0], after[1:].mean(axis=0) - after[0]
            else:
                z0, z1 = np.fft.fft(before[1:], axis=0)[j], np.fft.fft(after[1:], axis=0)[j]
            seq.append(complex(np.dot(ell, z1) / np.dot(ell, z0)))
        dom = values[j][0]
        errors = [abs(x - dom) for x in seq]
        name = f"shrink rate j={j}"
        if len(values[j]) == 1:  # one value in this frequency: every step shrinks by it exactly
            rows.append(exact_row(name, max(errors), predicted=abs(dom), observed=abs(seq[-1])))
        else:
            rows.append(limit_row(name, abs(dom), abs(seq[-1]), errors, abs(values[j][1] / dom), floor, levels))
    return rows


#: The comparison at an interior vertex, by the lattice's regular patch: OpenSubdiv's Catmull-Clark or Loop.
_COMPARISONS = {BICUBIC: compare_with_opensubdiv, BOX_SPLINE: compare_loop_with_opensubdiv}


def comparison(lattice: Lattice):
    """The comparison with OpenSubdiv at an interior vertex of ``lattice``: a function of ``(n, levels, seed)``."""
    return lattice.select(_COMPARISONS, "the comparison with OpenSubdiv")


#: The kinds of vertex: ``boundary`` (k faces), ``corner`` (k faces, O tagged), ``crease`` (k faces on each
#: side of a crease through O), ``dart`` (k faces around O, a crease ending at O).
KINDS = ("boundary", "corner", "crease", "dart")


#: The sharpness values of issue 20 (for creases and darts; boundary edges are infinitely sharp).
SHARPNESS = (Fraction(0), Fraction(1, 2), Fraction(1), Fraction(5, 2), math.inf)


@dataclass(frozen=True)
class SharpCase:
    """One vertex and one set of OpenSubdiv options."""

    scheme: str
    kind: str
    k: int
    sharpness: object = math.inf
    boundary: str = "edge-and-corner"
    creasing: str = "uniform"

    def __post_init__(self):
        OsdOptions(self.scheme, self.boundary, self.creasing)  # checks the three names
        if self.kind not in KINDS:
            raise InvalidInputError(f"kind must be one of {', '.join(KINDS)}, got {self.kind!r}")
        if isinstance(self.k, bool) or not isinstance(self.k, int) or not 1 <= self.k <= 16 or (self.kind == "dart" and self.k < 2):
            raise InvalidInputError(f"k must be an integer from {2 if self.kind == 'dart' else 1} to 16, got {self.k!r}")

    @property
    def quad(self) -> bool:
        return self.scheme == "catmull-clark"

    def vertex(self):
        """The toolkit's neighbourhood object (a :class:`~symdecomp.schemes.sector.SharpVertex`)."""
        from symdecomp.schemes.sector import SharpVertex

        lattice = lattice_of_reference(self.scheme)
        if self.kind == "boundary":
            return SharpVertex.boundary(self.k, lattice)
        if self.kind == "corner":
            return SharpVertex.corner(self.k, lattice)
        if self.kind == "crease":
            return SharpVertex.crease(self.k, self.k, lattice, self.sharpness)
        return SharpVertex.dart(self.k, lattice, self.sharpness)

    def fan(self) -> OsdFan:
        """The same neighbourhood as an OpenSubdiv mesh with its tags."""
        sectors = (self.k, self.k) if self.kind == "crease" else (self.k,)
        return tagged_fan(sectors, closed=self.kind in ("crease", "dart"), quad=self.quad,
                          corner=self.kind == "corner", sharpness=self.sharpness)

    def levels(self) -> int:
        """The last level compared: where a semi-sharp crease has decayed (0 for sharpness 0 or infinite)."""
        s = self.sharpness
        return 0 if s == math.inf or s == 0 else math.ceil(s)

    def label(self) -> str:
        s = "inf" if self.sharpness == math.inf else str(self.sharpness)
        return f"{self.scheme} {self.kind} k={self.k} s={s} {self.boundary} {self.creasing}"


def sharp_cases(scheme: str, kinds=KINDS, ks=range(1, 13), sharpness=SHARPNESS) -> list[SharpCase]:
    """The cases of the sweep: boundaries and corners once (sharpness does not apply), with both boundary
    interpolations where they differ (a boundary vertex of one face); creases and darts (at least three
    faces around the vertex) at every sharpness, with both creasing methods where a semi-sharp crease decays."""
    out = []
    for kind in kinds:
        for k in ks:
            if kind in ("boundary", "corner"):
                bounds = ("edge-only", "edge-and-corner") if kind == "boundary" and k == 1 else ("edge-and-corner",)
                out += [SharpCase(scheme, kind, k, math.inf, b) for b in bounds]
            elif (2 * k if kind == "crease" else k) >= 3:  # a closed fan of at least 3 faces
                for s in sharpness:
                    methods = ("uniform", "chaikin") if 0 < s < math.inf else ("uniform",)
                    out += [SharpCase(scheme, kind, k, s, creasing=m) for m in methods]
    return out


def _ours(case: SharpCase, level: int) -> mpmath.matrix:
    """Our exact matrix of the level (rational, or algebraic for Loop), its entries to :data:`~symdecomp.verify.matrix_measures.DIGITS` digits."""
    from symdecomp.schemes.sector import sharp_subdivision_matrix
    from symdecomp.schemes.sharp import SharpOptions

    scheme = catmull_clark() if case.quad else loop()
    exact = sharp_subdivision_matrix(scheme, case.vertex(), level=level, options=SharpOptions(case.boundary, case.creasing))
    with mpmath.workdps(DIGITS):
        return mpmath.matrix([[_mp(x) for x in exact.row(r)] for r in range(exact.rows)])


def _mp(x: sp.Expr) -> mpmath.mpf:
    """An exact value to the working precision (a rational exactly rounded, an algebraic number by sympy's evalf)."""
    if x.is_Rational:
        return mpmath.mpf(int(x.p)) / int(x.q)
    return mpmath.mpf(str(sp.N(x, mpmath.mp.dps + 10)))


def _level_checks(case: SharpCase, fan: OsdFan, level: int, ours: mpmath.matrix, mask) -> list:
    osd = fan.ring(OsdOptions(case.scheme, case.boundary, case.creasing), level)
    mine = floats(ours)
    decayed = level >= case.levels()
    why = "" if decayed else "OpenSubdiv's Limit takes the crease rule of this level, not the decayed limit"
    checks = [SharpCheck("matrix", difference(ours, osd.matrix)),
              SharpCheck("ring closed", float(np.max(np.abs(osd.leak)))),
              SharpCheck("spectrum", spectrum_distance(mine, osd.matrix))]
    if mask is None:
        return checks + [SharpCheck("limit mask", math.inf, note="our eigenvalue 1 is not simple")]
    checks.append(SharpCheck("limit mask", difference(mpmath.matrix([mask]), osd.masks[:1]), decayed, why))
    (plane, half), stationary = left_spans(mine, 2 if case.kind == "crease" else 1), decayed and case.levels() == level
    note = "" if stationary else why or "our matrix of this level is not the stationary one"
    checks.append(SharpCheck("tangents independent", 0.0 if np.linalg.matrix_rank(osd.masks[1:], tol=1e-9) == 2 else 1.0))
    if case.kind != "dart" and (case.sharpness == math.inf or case.kind != "crease"):
        checks.append(SharpCheck("curve tangent", tangent_residual(half, osd.masks[1]), stationary, note))
    for name, mask in (("surface tangent 1", osd.masks[1]), ("surface tangent 2", osd.masks[2])):
        checks.append(SharpCheck(name, tangent_residual(plane, mask), stationary, note))
    return checks


def _limit_point_check(case: SharpCase, fan: OsdFan, mask, seed: int) -> SharpCheck:
    rng = np.random.default_rng(seed)
    positions = rng.uniform(-1, 1, size=(len(mask), 3))
    queries = [(j, 0.0, 0.0) for j in range(len(fan.faces))]
    limits, _, _ = fan.limits(positions, queries, OsdOptions(case.scheme, case.boundary, case.creasing))
    ours = np.array([sum(float(w) * positions[i, c] for i, w in enumerate(mask)) for c in range(3)])
    return SharpCheck("limit point", float(np.max(np.abs(limits - ours))), note="patch table at (face, 0, 0)")


def compare_sharp_case(case: SharpCase, *, seed: int = 0) -> list[SharpResult]:
    """The checks of ``case`` at every level from 0 to :meth:`SharpCase.levels` (see the module docstring)."""
    if not isinstance(case, SharpCase):
        raise InvalidInputError(f"case must be a SharpCase, got {type(case).__name__}")
    fan = case.fan()
    mats = [_ours(case, level) for level in range(case.levels() + 1)]
    masks = limit_masks(mats)
    results = []
    for level, (ours, mask) in enumerate(zip(mats, masks)):
        checks = _level_checks(case, fan, level, ours, mask)
        if level == 0 and mask is not None:
            checks.append(_limit_point_check(case, fan, mask, seed))
        results.append(SharpResult(case, level, tuple(checks)))
    return results
