"""The toolkit's predictions at an interior vertex checked against OpenSubdiv (an outside oracle).

OpenSubdiv implements Catmull-Clark and Loop with their standard weights; which comparison runs is the
lattice's (:func:`comparison`, read with :meth:`~symdecomp.schemes.lattice.Lattice.select` by the regular
patch). The measurements (single OpenSubdiv steps chained, renormalised, split by frequency) are
:mod:`symdecomp.verify.step_chains`; boundary, crease, corner and dart vertices are compared by
:mod:`symdecomp.verify.oracle_sharp`.

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
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from symdecomp.algebra.numbers import to_fraction
from symdecomp.analysis.elliptic import recursion_eigenvector
from symdecomp.analysis.masks import limit_masks_at
from symdecomp.analysis.ring_masks import ring_masks
from symdecomp.analysis.ring_spectrum import ring_spectrum
from symdecomp.analysis.spectrum import recursion_eigenvalues
from symdecomp.analysis.tangent import invariant_ratio_at, tangent_eigenvalues
from symdecomp.errors import InternalError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, Lattice
from symdecomp.schemes.loop import loop
from symdecomp.schemes.rings import ring_subdivision_matrix
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import n as N
from symdecomp.validate import INPUT_LIMITS, cached, check_int, check_levels, check_valence
from symdecomp.verify.step_chains import (
    loop_chain,
    lsq_ratio,
    quad_chain,
    random_ring,
    ring_as_mesh,
    ring_frequency_part,
    triangle_frequency_part,
)

__all__ = [
    "Prediction",
    "ValenceComparison",
    "ToolkitPredictions",
    "toolkit_predictions",
    "elliptic_eigenvector",
    "compare_with_opensubdiv",
    "compare_loop_with_opensubdiv",
    "comparison",
]


#: Agreement required of the quantities that are exact in exact arithmetic (data of size ~1).
EXACT_TOLERANCE = 1e-13


@dataclass(frozen=True)
class Prediction:
    """One predicted quantity compared with OpenSubdiv at one valence."""

    #: Short name, e.g. ``"one-step matrix"`` or ``"shrink rate j=1"``.
    name: str
    #: ``"exact"`` (agrees to double precision) or ``"limit"`` (converges with the levels).
    kind: str
    #: The toolkit's value (a float, or a complex for the Eq. 39 ratio; None for matrix checks).
    predicted: complex | float | None
    #: OpenSubdiv's value at the last level (same type as ``predicted``).
    observed: complex | float | None
    #: The largest disagreement (absolute).
    disagreement: float
    #: For ``"limit"`` rows: the factor by which the disagreement should shrink per level.
    rate: float | None
    #: For ``"limit"`` rows: the disagreement's observed shrink factor over the last levels
    #: still above rounding (None if it could not be measured).
    observed_rate: float | None
    #: Whether the disagreement is within what the kind allows (see :func:`compare_with_opensubdiv`).
    agrees: bool

    def as_json(self) -> dict:
        def enc(x):
            if x is None:
                return None
            if isinstance(x, complex):
                return [x.real, x.imag]
            return float(x)

        return {
            "name": self.name,
            "kind": self.kind,
            "predicted": enc(self.predicted),
            "observed": enc(self.observed),
            "disagreement": self.disagreement,
            "rate": self.rate,
            "observed_rate": self.observed_rate,
            "agrees": self.agrees,
        }


@dataclass(frozen=True)
class ValenceComparison:
    """All predictions at one valence."""

    #: The valence.
    n: int
    #: Number of refinement levels run in OpenSubdiv.
    levels: int
    #: Seed of the random 1-ring.
    seed: int
    #: The compared predictions.
    predictions: tuple[Prediction, ...]

    @property
    def agrees(self) -> bool:
        return all(p.agrees for p in self.predictions)

    def as_json(self) -> dict:
        return {
            "n": self.n,
            "levels": self.levels,
            "seed": self.seed,
            "agrees": self.agrees,
            "predictions": [p.as_json() for p in self.predictions],
        }


def elliptic_eigenvector(scheme, n: int) -> tuple[sp.Expr, tuple[sp.Expr, sp.Expr, sp.Expr]]:
    """``(mu_2, (u_O, u_a, u_b))``: the subdominant eigenvalue of the Eq. 43 matrix at ``n`` and its eigenvector.

    ``mu_2`` is the larger of the two eigenvalues other than 1 (closed form from
    :func:`symdecomp.analysis.spectrum.recursion_eigenvalues`); the eigenvector is
    :func:`symdecomp.analysis.elliptic.recursion_eigenvector`, scaled so that ``u_a - u_O = 1``.

    >>> mu, (uo, ua, ub) = elliptic_eigenvector(catmull_clark(), 4)
    >>> mu, (ub - uo) / (ua - uo)
    (1/4, 2)
    """
    n = check_valence(n)
    _, m2, m3 = (sp.radsimp(sp.simplify(e.subs(N, n))) for e in recursion_eigenvalues(scheme))
    mu = m2 if sp.N(abs(m2)) >= sp.N(abs(m3)) else m3
    u = recursion_eigenvector(scheme, mu, n)
    scale = sp.simplify(u[1] - u[0])
    if scale == 0:
        raise InternalError(f"the Eq. 43 eigenvector for {mu} at n = {n} has u_a = u_O; Eq. 44's ratio is undefined")
    return mu, tuple(sp.radsimp(sp.simplify(x / scale)) for x in u)


@dataclass(frozen=True)
class ToolkitPredictions:
    """The toolkit's numbers for Catmull-Clark at one valence (derived, then evaluated)."""

    #: The valence.
    n: int
    #: The exact subdivision matrix with Fraction entries (rows ``O, a_0.., b_0..``).
    matrix: tuple[tuple[Fraction, ...], ...]
    #: The limit mask: left eigenvector of eigenvalue 1, weights summing to 1 (Fractions).
    limit_mask: tuple[Fraction, ...]
    #: ``j -> (lambda_dom, lambda_sub)`` of ``M_j`` for ``j = 1..n-1`` (floats, by magnitude).
    tangent: dict
    #: Eigenvalues of the Eq. 43 matrix other than 1, larger first.
    mu: tuple[float, float]
    #: ``(u_b - u_O)/(u_a - u_O)`` on the ``mu_2`` eigenvector (Eq. 44).
    elliptic_ratio: float
    #: ``B^1/A^1`` on the dominant eigenvector of ``M_1`` (Eq. 39).
    eq39_ratio: complex


def _f(expr, dps=30) -> float:
    with mpmath.workdps(dps):
        return float(sp.N(expr, dps))


@cached(n=check_valence)
def toolkit_predictions(n: int) -> ToolkitPredictions:
    """Derive the predictions for standard Catmull-Clark at valence ``n``."""
    n = check_valence(n)
    cc = catmull_clark()
    S = subdivision_matrix(cc, n)
    size = 2 * n + 1
    mask = limit_masks_at(cc, n).position
    ev = tangent_eigenvalues(cc)
    tangent = {}
    for j in range(1, n):
        d, s = ev.at(n, j)
        d, s = _f(d), _f(s)
        tangent[j] = (d, s) if abs(d) >= abs(s) else (s, d)
    mu, (uo, ua, ub) = elliptic_eigenvector(cc, n)
    others = sorted((_f(e.subs(N, n)) for e in recursion_eigenvalues(cc)[1:]), key=abs, reverse=True)
    r39 = complex(sp.N(invariant_ratio_at(cc, n, 1), 30))
    return ToolkitPredictions(
        n,
        tuple(tuple(to_fraction(S[i, k]) for k in range(size)) for i in range(size)),
        tuple(to_fraction(x) for x in mask),
        tangent,
        (others[0], others[1]),
        _f((ub - uo) / (ua - uo)),
        r39,
    )


def _rate_from(errors: list[float], floor: float) -> float | None:
    """Shrink factor of a disagreement sequence over its last two levels above ``floor``."""
    usable = [k for k in range(1, len(errors)) if errors[k] > floor and errors[k - 1] > floor]
    if not usable:
        return None
    k = usable[-1]
    return errors[k] / errors[k - 1]


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
    rows.append(_exact("1-ring locality", float(np.max(np.abs(alone.rings - larger.rings)))))

    # limit mask vs OpenSubdiv's limit positions
    limit = np.array([float(sum(w * Fraction(p[c]) for w, p in zip(pred.limit_mask, ring0))) for c in range(3)])
    rows.append(_exact("limit mask", float(max(np.max(np.abs(alone.limit - limit)), np.max(np.abs(larger.limit - limit))))))

    # The whole random ring, chained: the one-step matrix and the limit position.
    chain = quad_chain(ring0, n, levels, pred.matrix, limit=limit)
    rows.insert(0, _exact("one-step matrix", chain.one_step))
    mu2, mu3 = pred.mu
    floor = 1e-13
    rows.append(_limit("limit position", None, None, chain.centre_errors, abs(mu2), floor, levels))

    # Per frequency: the ring's frequency-j part alone (j and n - j together, so it stays real),
    # projected back onto frequency j after every OpenSubdiv step so that rounding noise in the
    # other frequencies cannot outgrow it.
    leak = 0.0
    chains = {}
    for j in range(0, n // 2 + 1):
        part = ring_frequency_part(np.array(ring0), n, j)
        chains[j] = quad_chain(part, n, levels, pred.matrix, frequency=j)
        leak = max(leak, chains[j].leak)
    rows.append(_exact("frequencies decouple", leak))

    rows.extend(_shrink_rates(n, chains, pred, floor, levels))

    # Eq. 39: B^1/A^1 on the frequency-1 chain
    q1 = abs(pred.tangent[1][1] / pred.tangent[1][0])
    ratios = [lsq_ratio(b[1], a[1]) for _, (o, a, b) in chains[1].steps]
    rows.append(_limit("Eq. 39 ratio B1/A1", pred.eq39_ratio, ratios[-1], [abs(r - pred.eq39_ratio) for r in ratios], q1, floor, levels))

    # Eq. 44: (bbar - O)/(abar - O) on the frequency-0 chain
    ell = [lsq_ratio(b[0].real - o, a[0].real - o).real for _, (o, a, b) in chains[0].steps]
    q0 = abs(mu3 / mu2)
    rows.append(_limit("Eq. 44 elliptic ratio", pred.elliptic_ratio, ell[-1], [abs(r - pred.elliptic_ratio) for r in ell], q0, floor, levels))
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
            rows.append(_exact(name, max(errs), predicted=dom, observed=seen))
        else:
            rows.append(_limit(name, dom, seen, errs, q, floor, levels))
    return rows


def _exact(name, disagreement, predicted=None, observed=None) -> Prediction:
    return Prediction(name, "exact", predicted, observed, disagreement, None, None, disagreement <= EXACT_TOLERANCE)


def _limit(name, predicted, observed, errors, rate, floor, levels) -> Prediction:
    last = errors[-1]
    bound = 100.0 * rate**levels + 1e-12
    return Prediction(name, "limit", predicted, observed, last, rate, _rate_from(errors, floor), last <= bound)


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
    rows = [_exact("one-step matrix", float(np.max(np.abs(osd - S))))]

    spectrum = ring_spectrum(scheme, n, 1, digits=20, exact=False, jordan=False)
    ours = sorted((complex(float(e.value.real.mid()), float(e.value.imag.mid())) for e in spectrum.eigenvalues
                   for _ in range(e.multiplicity)), key=lambda z: (z.real, z.imag))
    theirs = sorted(np.linalg.eigvals(osd), key=lambda z: (z.real, z.imag))
    rows.append(_exact("spectrum", max(abs(a - b) for a, b in zip(ours, theirs)) if len(ours) == len(theirs) else math.inf))

    masks = ring_masks(scheme, n, 1, digits=20)
    position = np.array([float(masks["position"]["O"])] + [float(x) for x in masks["position"]["a"]])
    rows.append(_exact("limit mask", float(np.max(np.abs(np.array(osd_loop_position_mask(n)) - position)))))
    tangents = np.array([[float(m["O"])] + [float(x) for x in m["a"]] for m in masks["tangents"]])
    osd_tangents = np.array(osd_loop_tangent_masks(n))
    C, *_ = np.linalg.lstsq(tangents.T, osd_tangents.T, rcond=None)
    spans = abs(np.linalg.det(C)) > 1e-8
    residual = float(np.abs(tangents.T @ C - osd_tangents.T).max() / max(1.0, np.abs(osd_tangents).max()))
    rows.append(_exact("tangent plane", residual if spans else math.inf))

    rng = random.Random(f"symdecomp-oracle-loop:{seed}:{n}")
    ring0 = np.array([[rng.uniform(-1.0, 1.0) for _ in range(3)] for _ in range(n + 1)])
    values = _frequency_values(spectrum, n)
    floor = 1e-13
    _, centres = loop_chain(ring0, n, levels, None)
    limit = position @ ring0
    # the centre sees frequency 0 only (the vertex rule weighs all a_i alike): it converges with its value after 1
    rate = abs(values[0][0])
    rows.append(_limit("limit position", None, None, [float(np.max(np.abs(c - limit))) for c in centres], rate, floor, levels))
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
            rows.append(_exact(name, max(errors), predicted=abs(dom), observed=abs(seq[-1])))
        else:
            rows.append(_limit(name, abs(dom), abs(seq[-1]), errors, abs(values[j][1] / dom), floor, levels))
    return rows


#: The comparison at an interior vertex, by the lattice's regular patch: OpenSubdiv's Catmull-Clark or Loop.
_COMPARISONS = {BICUBIC: compare_with_opensubdiv, BOX_SPLINE: compare_loop_with_opensubdiv}


def comparison(lattice: Lattice):
    """The comparison with OpenSubdiv at an interior vertex of ``lattice``: a function of ``(n, levels, seed)``."""
    return lattice.select(_COMPARISONS, "the comparison with OpenSubdiv")
