"""Certified shape at an extraordinary vertex: elliptic, hyperbolic or hybrid central surfaces.

**The question** (Karciauskas, Peters and Reif, *Shape characterization of subdivision surfaces:
case studies*, CAGD 21 (2004) 601-614; the theory in Peters and Reif, *Shape characterization of
subdivision surfaces: basic principles*, CAGD 21 (2004) 585-599): near an extraordinary vertex a
limit surface is, after an affine map, ``x = (lambda^m chi, h_m) + o(...)`` on the ``m``-th ring,
with ``chi`` the characteristic map (eigenvalue ``lambda``) and ``h_m`` the combination of the
*second-order* eigenfunctions the input excites (:mod:`symdecomp.analysis.second_order`): the
elliptic one (frequency 0, eigenvalue ``mu_0``, like ``x^2 + y^2``) and the hyperbolic pair
(frequency 2, ``mu_2``, like ``x^2 - y^2`` and ``2 x y``). The *central surface* is
``(chi_1, chi_2, h)`` over one ring; it is self-similar, so one ring decides. Its shape is
*elliptic* when its Gaussian curvature is positive on the whole ring, *hyperbolic* when it is
negative on the whole ring, and *hybrid* when it takes both signs (the curvature changes sign,
between sectors or within one): a hybrid central surface means the limit surface is neither
convex nor saddle-shaped near the vertex, whatever the input.

*What was checked of the sources*: the case studies' title, authors, journal and the sentences
of their abstract (both schemes, "for generic input data", "fail to converge to the hyperbolic
or elliptic limit shape suggested by the geometry of the input mesh: the limit shape is a
function of the valence", and "a type of chart" for designers). The definitions above (central
surface, elliptic/hyperbolic/hybrid by the sign of the Gaussian curvature on the ring) are those
of the issue and of the papers as cited there; the papers' full text, figures and theorem
numbers were not available to check, so no page or figure is cited and the numbers here are
computed, not compared with the papers' plots.

**The certificate.** ``K`` has the sign of ``L N - M^2`` (:mod:`symdecomp.verify.curvature`), a
polynomial on each of sector 0's three sub-patches (bidegree ``(14, 14)`` on quads, degree 16 on
Loop's triangles). Its Bernstein coefficients are balls; all positive on every patch of every
sector -> elliptic, all negative -> hyperbolic, a certified positive and a certified negative
value (corner coefficients are point values) -> hybrid, with the places; otherwise subdivide (de
Casteljau / bisection, :mod:`symdecomp.verify.bezier`) to ``max_depth``, and if still mixed the
answer is *undecided* with the depth and place that were not enough (also the honest answer
where ``K`` vanishes on a curve without changing sign, which no depth decides). The
characteristic map must pass the spectral part of Reif's test and have a certified regular
Jacobian, or there is no central surface to classify.

**Sectors.** The frequency-0 height is the same in every sector and the characteristic map's
sectors are rotations of sector 0, so sector 0 decides the elliptic input. The hyperbolic
eigenvector has sector values ``omega^(2 s) v_0``, so with amplitude ``b`` and angle ``t`` the
height on sector ``s`` is ``b Re(e^(-i theta_s) v_0)`` with ``theta_s = t - 4 pi s / n`` (in
sector 0's parameters): every distinct ``theta_s`` is classified (modulo ``pi`` when the elliptic
amplitude is 0, since ``K`` does not change when ``h`` changes sign).

**Mixtures and the chart.** ``h = a h_0 + b (cos t h_2c + sin t h_2s)`` (``h_2c``, ``h_2s`` the real
and imaginary parts of the frequency-2 eigenvector) is the central surface of an input with
amplitudes ``a``, ``b`` on the two eigenvalues *at one ring*: on ring ``m`` the amplitudes are
``a mu_0^m`` and ``b mu_2^m``, so the ratio ``b / a`` moves by ``mu_2 / mu_0`` per ring, towards the
frequency whose eigenvalue is larger. :func:`shape_chart` classifies a grid of mixtures (``a = 1 -
r``, ``b = r``) and angles: the chart a designer reads is the row of the input's ratio, and the
shape it tends to is the end of the chart on the side of the larger eigenvalue (reported as
``dominant``). Only where ``mu_0 = mu_2`` is one mixture the shape of every ring. Both height fields are
normalised to 1 at the level-1 point ``a_0`` (:mod:`symdecomp.analysis.second_order`), so at the regular
valence the mixture is ``(1 - r)(x^2 + y^2) + r Re(e^(-it) (x + iy)^2)`` and the chart changes from
elliptic to hyperbolic exactly at ``r = 1/2`` (a parabolic cylinder: undecided, which no depth decides).

**Findings** (certified here, default depth and precision, ``n = 3..64``). Catmull-Clark: the elliptic
input is elliptic and the hyperbolic input hyperbolic at every valence (``n = 4``: no hyperbolic pair);
``mu_0 > mu_2`` at ``n = 3`` and ``mu_2 > mu_0`` for ``n >= 5``. Loop: the elliptic input is elliptic for
``4 <= n <= 24`` and *hybrid* for ``25 <= n <= 64`` (``n = 3``: ``mu_0 = 1/16`` is also an outer eigenvalue,
so the 1-ring does not determine the eigenfunction: undecided, with that reason); the hyperbolic input is
hyperbolic for ``n >= 5``; ``mu_0 > mu_2`` at ``n = 4, 5``, equal at 6, ``mu_2 > mu_0`` for ``n >= 7``.
Against the case studies' abstract: where ``mu_2 > mu_0`` an input with any frequency-2 part ends at the
hyperbolic end of the chart (through a hybrid band), where ``mu_0 > mu_2`` at the elliptic end, whatever
the mesh suggests: the limit shape is a function of the valence, as the abstract says. Their figures and
tables could not be compared number by number (not available here).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> r = classify_shape(catmull_clark(), 4)          # regular: the height is x^2 + y^2
>>> r.kind, r.frequencies
('elliptic', (0,))
>>> classify_shape(catmull_clark(), 5, elliptic=0, hyperbolic=1).kind
'hyperbolic'
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import flint

from symdecomp.analysis.characteristic import check_applicable, frequency_blocks, outer_radius, ring_layout
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.analysis.second_order import height_eigenvector
from symdecomp.errors import InvalidInputError, InvalidSchemeError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_bits, check_depth, check_limit, check_rational, check_valence
from symdecomp.verify.bezier import SignCertificate
from symdecomp.verify.c1 import bezier_nets, characteristic_nets, place_text
from symdecomp.verify.c1_spectrum import ball_text, frequency_zero_eigenvalues, quadratic_roots, real_at, spectral_conditions
from symdecomp.verify.curvature import certify_nets, combine, curvature_gram, jacobian_nets, patch_algebra
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.second_order_spectrum import dominant_frequency

__all__ = ["KINDS", "HeightFields", "height_fields", "ShapeResult", "classify_shape", "ShapeChart", "shape_chart"]

#: The possible verdicts of :func:`classify_shape`.
KINDS = ("elliptic", "hyperbolic", "hybrid", "undecided")


class _Undecided(Exception):
    """Raised inside this module when the data a verdict needs are not certified (the message says why)."""


@dataclass(frozen=True)
class HeightFields:
    """The characteristic map and the second-order height fields of one valence, as Bezier nets of sector 0's sub-patches."""

    scheme: str
    n: int
    #: The subdominant eigenvalue ``lambda`` (a real ball).
    subdominant: flint.arb
    #: The elliptic eigenvalue (frequency 0) and the hyperbolic one (frequencies 2 and ``n - 2``; at ``n = 3`` frequency 2
    #: is frequency -1), when asked for: real Arb balls, the block read first in ``frequencies`` (:func:`_second_order`).
    elliptic: Eigenvalue | None
    hyperbolic: Eigenvalue | None
    #: ``[(X, Y), ...]``: the characteristic map's nets per sub-patch.
    chi: tuple
    #: Per sub-patch the height nets in order: ``h_0`` (if elliptic), then ``h_2c``, ``h_2s`` (if hyperbolic).
    heights: tuple
    #: The certified sign of the characteristic map's Jacobian (regularity).
    jacobian: SignCertificate
    lattice: object = None
    #: The frequencies (0, 2) whose eigenvalue is certified below the regular part's outer ones (not its frequency's largest).
    below_outer: tuple[int, ...] = ()


def _above_outer(scheme: Scheme, value: flint.arb) -> bool | None:
    radius = outer_radius(scheme.lattice)
    if radius is None:  # pragma: no cover - the regular rules the C1 test knows have exact outer eigenvalues
        return None
    return True if abs(value) > radius else False if abs(value) < radius else None


def _second_order(n: int, frequency: int, value: flint.arb) -> Eigenvalue:
    """A second-order eigenvalue, the one type: its block's copies (frequency 0 once, 2 with ``n - 2``), that block first."""
    frequencies = (0,) if frequency == 0 else (2, n - 2)
    return Eigenvalue(value, ball_text(value), len(frequencies), frequencies=frequencies)


def _ball(e: Eigenvalue) -> flint.arb:
    """The real Arb ball of a second-order eigenvalue (:func:`_second_order` makes them)."""
    assert isinstance(e.value, flint.arb)
    return e.value


def _mu_text(e: Eigenvalue, below_outer: tuple[int, ...]) -> str:
    below = " (below the regular part's outer eigenvalues)" if e.frequencies[0] in below_outer else ""
    return f"mu_{e.frequencies[0]} = {e.text}{below}"


def _elliptic_eigenvalue(scheme: Scheme, n: int) -> Eigenvalue:
    """The largest non-unit eigenvalue of the frequency-0 1-ring block (Eq. 43 on quads), certified real and simple."""
    eigen, failure = frequency_zero_eigenvalues(scheme, n)
    if failure:
        raise _Undecided(failure)
    eigen = sorted(eigen, key=lambda e: -abs(e.value).mid())
    top = eigen[0]
    if top.conjugate or not top.value.imag.contains(0):
        raise _Undecided(f"the largest frequency-0 eigenvalue after 1 is not real ({ball_text(top.value)}): no elliptic eigenfunction")
    if top.multiplicity != 1 or top.defective:
        raise _Undecided(f"the largest frequency-0 eigenvalue after 1, {ball_text(top.value)}, is a double root: its eigenfunction is not one")
    if len(eigen) > 1 and not abs(eigen[1].value) < abs(top.value):
        raise _Undecided(f"the frequency-0 eigenvalues {ball_text(top.value)} and {ball_text(eigen[1].value)} are not separated at this precision")
    return _second_order(n, 0, top.value.real)


def _hyperbolic_eigenvalue(scheme: Scheme, n: int, lam: flint.acb) -> Eigenvalue:
    """The largest eigenvalue of the frequency-2 1-ring block other than ``lambda``, certified real and simple."""
    if n == 4:
        raise NotApplicableError("at n = 4 frequency 2 is n/2: its eigenvectors are real (sector values (-1)^s), so there is no "
                                 "cos/sin pair of one complex eigenvector; the hyperbolic input needs n = 3 or n >= 5")
    k1 = ring_layout(scheme.lattice).one_ring
    B = frequency_blocks(scheme, n)(2 % n, k1)
    roots = [B[0, 0]] if k1 == 1 else list(quadratic_roots(B[0, 0] + B[1, 1], B[0, 0] * B[1, 1] - B[0, 1] * B[1, 0]))
    if n == 3:  # frequency 2 is frequency -1: its block is conj(M_1), which holds lambda itself
        roots = [r for r in roots if not r.overlaps(lam)]
        if not roots:
            raise NotApplicableError("at n = 3 frequency 2 is frequency -1, whose 1-ring block holds only lambda: the 1-ring has no "
                                     "hyperbolic eigenvalue (the largest frequency-2 eigenvalue is the regular part's)")
    roots.sort(key=lambda r: -abs(r).mid())
    top = roots[0]
    if len(roots) > 1 and not abs(roots[1]) < abs(top):
        raise _Undecided(f"the frequency-2 eigenvalues {ball_text(top)} and {ball_text(roots[1])} are not separated at this precision")
    real = top.imag.contains(0) and real_at(scheme, n)
    if real and k1 == 2:
        t, d = B[0, 0] + B[1, 1], B[0, 0] * B[1, 1] - B[0, 1] * B[1, 0]
        real = bool((t * t - 4 * d).real > 0)
    if not real:
        raise _Undecided(f"the frequency-2 eigenvalue {ball_text(top)} is not shown to be real: no real hyperbolic pair")
    return _second_order(n, 2, top.real)


def _height_fields(scheme: Scheme, n: int, elliptic: bool, hyperbolic: bool, max_depth: int) -> HeightFields:
    spectral = spectral_conditions(scheme, n)
    if spectral.status is not C1Verdict.C1:
        raise _Undecided(f"there is no characteristic map to build the central surface on: {spectral.reason}")
    if spectral.subdominant.frequency != 1:
        raise _Undecided(f"the characteristic map comes from frequency {spectral.subdominant.frequency}, not 1: the second-order "
                         "frequencies 0 and 2 are those of a frequency-1 map")
    chi, _ = characteristic_nets(scheme, n, spectral)
    alg = patch_algebra(scheme.lattice)
    jac = certify_nets(alg, jacobian_nets(alg, chi), alg.add(alg.lower(alg.degree, "u"), alg.lower(alg.degree, "v")), max_depth)
    if jac.status not in ("positive", "negative"):
        raise _Undecided(f"the characteristic map's Jacobian is not certified of one sign ({jac.status}): no regular central surface")
    lam = spectral.subdominant.value
    heights: list[list] = [[] for _ in chi]
    eigen = {}
    for wanted, kind, pick in ((elliptic, "elliptic", lambda: _elliptic_eigenvalue(scheme, n)),
                               (hyperbolic, "hyperbolic", lambda: _hyperbolic_eigenvalue(scheme, n, lam))):
        if not wanted:
            continue
        mu = eigen[kind] = pick()
        try:
            vec = height_eigenvector(scheme, n, mu.frequencies[0] % n, flint.acb(_ball(mu)))
        except InvalidSchemeError as exc:
            raise _Undecided(str(exc)) from exc
        for patch, (re, im) in zip(heights, bezier_nets(vec)):
            patch += [re] if mu.frequencies[0] == 0 else [re, im]
    below = tuple(e.frequencies[0] for e in eigen.values() if _above_outer(scheme, e.value) is False)
    return HeightFields(scheme.name, n, lam.real, eigen.get("elliptic"), eigen.get("hyperbolic"), tuple(chi),
                        tuple(tuple(h) for h in heights), jac, scheme.lattice, below)


def height_fields(scheme: Scheme, n: int, *, elliptic: bool = True, hyperbolic: bool = True, prec: int = 64) -> HeightFields:
    """The characteristic map and the second-order height fields at valence ``n`` (see the module docstring).

    Raises :class:`~symdecomp.errors.NotApplicableError` (one line) when they are not determined: the scheme's
    ring is not a known spline, the spectral conditions fail, an eigenvalue is not separated or not real, or
    (hyperbolic) ``n = 4``.
    """
    check_scheme(scheme)
    n = check_valence(n)
    prec = check_bits(prec)
    check_applicable(scheme)
    with flint.ctx.workprec(prec):
        try:
            return _height_fields(scheme, n, bool(elliptic), bool(hyperbolic), 6)
        except _Undecided as exc:
            raise NotApplicableError(f"scheme {scheme.name!r} at n = {n}: {exc}") from None


@dataclass(frozen=True)
class ShapeResult:
    """The certified shape of the central surface ``(chi, a h_0 + b (cos t h_2c + sin t h_2s))`` at one valence."""

    scheme: str
    n: int
    #: ``'elliptic'``, ``'hyperbolic'``, ``'hybrid'`` or ``'undecided'`` (:data:`KINDS`).
    kind: str
    #: One line: why (the eigenvalues, the places, the bound), or what would decide.
    reason: str
    #: The amplitudes ``a`` (elliptic), ``b`` (hyperbolic) and the angle ``t`` in units of ``pi``.
    elliptic: Fraction
    hyperbolic: Fraction
    angle: Fraction
    #: The frequencies whose eigenfunctions make the height (0 and/or 2).
    frequencies: tuple[int, ...] = ()
    #: The eigenvalues used, by frequency (midpoints; the reason prints the balls).
    mu: tuple[float, ...] = ()
    #: The subdominant eigenvalue ``lambda`` (midpoint), when the characteristic map exists.
    subdominant: float | None = None
    #: The frequency (0 or 2) whose eigenvalue is the larger, the one the rings tend to; ``None`` if only one is used or not separated.
    dominant: int | None = None
    #: A rigorous lower bound of ``|L N - M^2|`` on the ring (level-1 local parameters) when elliptic or hyperbolic.
    lower_bound: float | None = None
    #: Where a positive and a negative Gaussian curvature were certified (hybrid), as text.
    positive_at: str | None = None
    negative_at: str | None = None
    #: Deepest subdivision used, and the limit; the working precision in bits.
    depth: int | None = None
    max_depth: int = 6
    precision: int = 64
    #: Sector cases classified (distinct angles ``theta_s``).
    cases: int = 0

    def as_json(self) -> dict:
        out = {k: getattr(self, k) for k in ("scheme", "n", "kind", "reason", "frequencies", "mu", "subdominant", "dominant",
                                             "lower_bound", "positive_at", "negative_at", "depth", "max_depth", "precision", "cases")}
        out.update(elliptic=str(self.elliptic), hyperbolic=str(self.hyperbolic), angle=str(self.angle), frequencies=list(self.frequencies),
                   mu=list(self.mu))
        return out


def _cases(n: int, a: Fraction, b: Fraction, t: Fraction) -> list[tuple[int, Fraction | None]]:
    """``(sector, theta_s / pi)`` for each distinct height on sector 0's parameters (``theta_s = t - 4 pi s / n``)."""
    if b == 0:
        return [(0, None)]
    period = 1 if a == 0 else 2  # h and -h have the same curvature sign
    seen: dict[Fraction, int] = {}
    for s in range(n):
        seen.setdefault((t - Fraction(4 * s, n)) % period, s)
    return [(s, theta) for theta, s in seen.items()]


def _weights(fields: HeightFields, a: Fraction, b: Fraction, theta: Fraction | None) -> list:
    out = [flint.arb(flint.fmpq(a.numerator, a.denominator))] if fields.elliptic else []
    if fields.hyperbolic and theta is None:  # b = 0: the hyperbolic pair is there but not excited
        out += [flint.arb(0), flint.arb(0)]
    elif fields.hyperbolic:
        bb, th = flint.arb(flint.fmpq(b.numerator, b.denominator)), flint.arb(flint.fmpq(theta.numerator, theta.denominator))
        out += [bb * th.cos_pi(), bb * th.sin_pi()]
    return out


def _corner_places(alg, nets, s: int) -> dict[int, str]:
    """``{sign: place}`` of certified signs among the corner values of the whole sub-patches (point values of the polynomial)."""
    found: dict[int, str] = {}
    for p, net in enumerate(nets):
        if isinstance(net[0], list):
            corners = {(0, 0): net[0][0], (0, 1): net[0][-1], (1, 0): net[-1][0], (1, 1): net[-1][-1]}
        else:
            d = next(k for k in range(len(net)) if (k + 1) * (k + 2) // 2 == len(net))
            corners = {(0, 0): net[0], (1, 0): net[d], (0, 1): net[-1]}
        for (u, v), c in corners.items():
            for sign in (1, -1):
                if sign * c > 0:
                    found.setdefault(sign, f"sector {s}, sub-patch {p}, at (u, v) = ({u}, {v})")
    return found


def _flat(net) -> list:
    return [c for row in net for c in row] if net and isinstance(net[0], list) else list(net)


def _classify_cases(fields: HeightFields, gram: list, degree, a, b, t, max_depth: int) -> dict:
    """Certify each sector case: signs found with their places, undecided cases, certificates."""
    alg = patch_algebra(fields.lattice)
    found: dict[int, str] = {}
    undecided, certs = [], []
    for s, theta in _cases(fields.n, a, b, t):
        nets = [combine(g, _weights(fields, a, b, theta)) for g in gram]
        flat = [_flat(net) for net in nets]
        vanishing = [p for p, coeffs in enumerate(flat) if all(c.contains(0) for c in coeffs)]
        if vanishing:  # no subdivision separates a polynomial from 0 if it may be 0 everywhere: do not try
            cert = SignCertificate("undecided", None, 0, len(nets), (vanishing[0], (0.0, 1.0), (0.0, 1.0)))
            certs.append(cert)
            undecided.append(f"L N - M^2 is 0 to within the balls on all of sub-patch {vanishing[0]} of sector {s}: the curvature may "
                             "vanish identically there (as on a parabolic cylinder), which no subdivision depth decides")
            continue
        cert = certify_nets(alg, nets, degree, max_depth)
        certs.append(cert)
        if cert.status in ("positive", "negative"):
            found.setdefault(1 if cert.status == "positive" else -1, f"sector {s} (all of it)")
            continue
        corners = _corner_places(alg, nets, s)
        if cert.status == "changes":
            found.setdefault(-1, f"sector {s}, {place_text(cert.where)}")
            found.setdefault(1, corners.get(1, f"sector {s} (a subdivided piece)"))
        else:
            for sign, place in corners.items():
                found.setdefault(sign, place)
            undecided.append(f"the sign of L N - M^2 is not certified in sector {s} ({place_text(cert.where)}) at subdivision depth "
                             f"{max_depth}; a deeper subdivision or more precision would decide, unless the curvature vanishes there "
                             "without changing sign")
    return dict(found=found, undecided=undecided, certs=certs)


def _gram(fields: HeightFields) -> tuple[list[dict], object]:
    """Per sub-patch the nets ``G_pq`` of :func:`~symdecomp.verify.curvature.curvature_gram`, and their degree."""
    alg = patch_algebra(fields.lattice)
    gram, degree = [], None
    for (X, Y), heights in zip(fields.chi, fields.heights):
        g, degree = curvature_gram(alg, X, Y, list(heights))
        gram.append(g)
    return gram, degree


def _verdict(fields: HeightFields, gram: list, degree, a, b, t, max_depth: int, prec: int) -> ShapeResult:
    out = _classify_cases(fields, gram, degree, a, b, t, max_depth)
    found, undecided, certs = out["found"], out["undecided"], out["certs"]
    eigen = [e for e in (fields.elliptic, fields.hyperbolic) if e is not None]
    mus = "; ".join(_mu_text(e, fields.below_outer) for e in eigen) + f", lambda = {ball_text(fields.subdominant)}"
    base = dict(scheme=fields.scheme, n=fields.n, elliptic=a, hyperbolic=b, angle=t, frequencies=tuple(e.frequencies[0] for e in eigen),
                mu=tuple(float(_ball(e).mid()) for e in eigen), subdominant=float(fields.subdominant.mid()), dominant=_dominant(fields),
                depth=max(c.depth for c in certs), max_depth=max_depth, precision=prec, cases=len(certs))
    if 1 in found and -1 in found:
        return ShapeResult(kind="hybrid", reason=f"{mus}: the Gaussian curvature of the central surface changes sign, positive in "
                           f"{found[1]}, negative in {found[-1]}", positive_at=found[1], negative_at=found[-1], **base)
    if undecided:
        return ShapeResult(kind="undecided", reason=f"{mus} ({prec} bits): {undecided[0]}",
                           positive_at=found.get(1), negative_at=found.get(-1), **base)
    sign = 1 if 1 in found else -1
    bound = min(c.lower_bound for c in certs)
    kind = "elliptic" if sign > 0 else "hyperbolic"
    return ShapeResult(kind=kind, reason=f"{mus}: L N - M^2 is {'positive' if sign > 0 else 'negative'} on every sub-patch of "
                       f"every sector ({len(certs)} case{'s' if len(certs) > 1 else ''}, |L N - M^2| >= {bound:.3g}): the central surface "
                       f"is {kind}", lower_bound=bound, **base)


def _dominant(fields: HeightFields) -> int | None:
    """The frequency (0 or 2) of the larger second-order eigenvalue, when both are used and separated
    (:func:`~symdecomp.verify.second_order_spectrum.dominant_frequency`, the one comparison)."""
    e, h = fields.elliptic, fields.hyperbolic
    return dominant_frequency(None if e is None else e.value, None if h is None else h.value)


def _classify(scheme: Scheme, n: int, a: Fraction, b: Fraction, t: Fraction, max_depth: int, prec: int) -> ShapeResult:
    try:
        fields = _height_fields(scheme, n, a != 0, b != 0, max_depth)
    except _Undecided as exc:
        return ShapeResult(scheme=scheme.name, n=n, kind="undecided", reason=str(exc), elliptic=a, hyperbolic=b, angle=t,
                           max_depth=max_depth, precision=prec)
    return _verdict(fields, *_gram(fields), a, b, t, max_depth, prec)


def _arguments(scheme, n, elliptic, hyperbolic, angle, max_depth, prec):
    check_scheme(scheme)
    n = check_limit(check_valence(n), "classify_shape(n)", "valence n")
    a, b, t = check_rational(elliptic, "elliptic"), check_rational(hyperbolic, "hyperbolic"), check_rational(angle, "angle")
    max_depth, prec = check_depth(max_depth), check_bits(prec)
    if a == 0 and b == 0:
        raise InvalidInputError("elliptic and hyperbolic are both 0: there is no height to classify")
    check_applicable(scheme)
    return n, a, b, t, max_depth, prec


def classify_shape(scheme: Scheme, n: int, *, elliptic=1, hyperbolic=0, angle=0, max_depth: int = 6,
                   prec: int = 64) -> ShapeResult:
    """The certified shape of the central surface for the height ``elliptic h_0 + hyperbolic (cos t h_2c + sin t h_2s)``.

    ``elliptic``, ``hyperbolic``: exact rational amplitudes (an int, a Fraction or text like ``'1/3'``);
    ``angle``: ``t`` in units of ``pi`` (exact rational); ``max_depth``: the deepest subdivision, ``0..12``;
    ``prec``: bits of the balls (retried once at twice the precision if undecided). See the module docstring
    for what is classified and how. A hyperbolic amplitude at ``n = 4`` (frequency 2 is ``n/2``) or for a
    scheme whose frequency-2 1-ring block holds only ``lambda`` (Loop at ``n = 3``) raises
    :class:`~symdecomp.errors.NotApplicableError`.
    """
    n, a, b, t, max_depth, prec = _arguments(scheme, n, elliptic, hyperbolic, angle, max_depth, prec)
    with flint.ctx.workprec(prec):
        result = _classify(scheme, n, a, b, t, max_depth, prec)
    if result.kind == "undecided":
        with flint.ctx.workprec(2 * prec):
            result = _classify(scheme, n, a, b, t, max_depth, 2 * prec)
    return result


@dataclass(frozen=True)
class ShapeChart:
    """The shape of the central surface over a grid of mixtures ``a = 1 - r``, ``b = r`` and angles ``t`` (one valence)."""

    scheme: str
    n: int
    #: The mixtures ``r`` (rows) and the angles ``t`` in units of ``pi`` (columns).
    ratios: tuple[Fraction, ...]
    angles: tuple[Fraction, ...]
    #: ``results[i][k]``: :class:`ShapeResult` at ``ratios[i]``, ``angles[k]`` (the column is irrelevant where ``r = 0``).
    results: tuple[tuple[ShapeResult, ...], ...]
    #: ``mu_0``, ``mu_2`` (midpoints) and the frequency of the larger one (where the rings go), ``None`` if not separated.
    mu: tuple[float, float]
    dominant: int | None

    @property
    def kinds(self) -> tuple[tuple[str, ...], ...]:
        """The verdicts, ``kinds[i][k]``."""
        return tuple(tuple(r.kind for r in row) for row in self.results)

    def as_json(self) -> dict:
        return {"scheme": self.scheme, "n": self.n, "ratios": [str(r) for r in self.ratios], "angles": [str(t) for t in self.angles],
                "mu": list(self.mu), "dominant": self.dominant, "kinds": [list(row) for row in self.kinds]}


def _grid(values, default, argument: str) -> tuple[Fraction, ...]:
    if values is None:
        return default
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise InvalidInputError(f"{argument} must be a sequence of exact rationals, got {values!r}")
    out = tuple(check_rational(x, argument) for x in values)
    if not out or len(out) > 64:
        raise InvalidInputError(f"{argument} must hold 1 to 64 values, got {len(out)}")
    return out


def shape_chart(scheme: Scheme, n: int, *, ratios=None, angles=None, max_depth: int = 6, prec: int = 64) -> ShapeChart:
    """The shape chart at valence ``n``: :func:`classify_shape` for ``elliptic = 1 - r``, ``hyperbolic = r``, ``angle = t``.

    ``ratios``: the mixtures ``r`` in ``[0, 1]`` (default ``0, 1/8, .., 1``); ``angles``: ``t`` in units of ``pi``
    (default ``0, 1/n, 2/n, 3/n``: the classification has period ``4 pi / n`` in ``t``, a shift of the sectors). The
    eigen-data and the nets ``G_pq`` are computed once; each cell is certified at ``prec`` bits (an undecided cell
    says so; :func:`classify_shape` retries at twice the precision). Raises
    :class:`~symdecomp.errors.NotApplicableError` where the hyperbolic pair or the elliptic eigenfunction is not
    determined (``n = 4``; Loop at ``n = 3``).
    """
    check_scheme(scheme)
    n = check_valence(n)
    ratios = _grid(ratios, tuple(Fraction(k, 8) for k in range(9)), "ratios")
    angles = _grid(angles, tuple(Fraction(k, n) for k in range(4)), "angles")
    if any(not 0 <= r <= 1 for r in ratios):
        raise InvalidInputError(f"ratios must lie in [0, 1] (elliptic = 1 - r, hyperbolic = r), got {[str(r) for r in ratios]}")
    max_depth, prec = check_depth(max_depth), check_bits(prec)
    check_applicable(scheme)
    with flint.ctx.workprec(prec):
        try:
            fields = _height_fields(scheme, n, True, True, max_depth)
        except _Undecided as exc:
            raise NotApplicableError(f"scheme {scheme.name!r} at n = {n}: no shape chart: {exc}") from None
        gram, degree = _gram(fields)
        rows = tuple(tuple(_verdict(fields, gram, degree, 1 - r, r, t, max_depth, prec) for t in angles) for r in ratios)
    mu = (float(fields.elliptic.value.mid()), float(fields.hyperbolic.value.mid()))
    return ShapeChart(scheme.name, n, ratios, angles, rows, mu, _dominant(fields))
