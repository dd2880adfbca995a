"""Certified C1 without a spline patch: Zorin's test on the characteristic map's control net (schemes on triangles).

D. Zorin, *A method for analysis of C1-continuity of subdivision surfaces*, SIAM J. Numer. Anal. 37(5) (2000),
1677-1708, reduces C1 (Reif's sufficient condition, extended in D. Zorin, *Smoothness of subdivision on irregular
meshes*, Constr. Approx. 16 (2000)) to a regular and injective characteristic map and shows, in the paper's
abstract's words, that "regularity can be inferred from the properties of a sufficiently close linear approximation,
and injectivity can be verified by computing the index of a curve", by interval arithmetic, for schemes whose
regular part is no spline (the butterfly and the modified butterfly of Zorin, Schroeder, Sweldens, *Interpolating
subdivision for meshes with arbitrary topology*, SIGGRAPH 1996). What was read: the SIAM paper's abstract, the
butterfly paper's project page (its introduction) and the group's page that lists the Constr. Approx. paper (title and
venue only); the test below is written from that statement, with bounds derived here
(:mod:`symdecomp.verify.zorin_bounds`), not the paper's constants.

**What is checked**, at one valence ``n``:

1. Reif's spectral conditions on the engine's matrix (:func:`~symdecomp.verify.zoo_characteristic.spectral_conditions`);
2. the characteristic map's control net: the subdominant eigenvector of the frequency block on the neighbourhood of
   depth 4 (deeper when the regular stencils reach further, :func:`net_depth`), grown outwards and refined ``m`` times
   by the scheme's own regular rules (:mod:`.zorin_net`): the steps that return the lattice to itself, refining it by
   ``1/a`` (``a = 2``: one primal step; ``a = 3``: sqrt(3)'s two steps, and ``lambda`` is then the two steps' eigenvalue);
3. the linear approximation is close: on each level-``m`` triangle ``T`` of one sector of the ring
   ``d <= |x| <= a d`` (level-``m`` graph distance; a fundamental domain of the scaling by ``lambda``),
   ``d_e chi(x)`` lies within ``E = K_1 a^m M_m F`` of ``a^m D_e p^m(T)`` for the two edge directions ``e``, with
   ``M_m`` the largest rhombus difference near the ring and ``K_1``, ``F`` computed from the regular rules'
   difference scheme (:class:`~symdecomp.verify.zorin_bounds.DifferenceBounds`: ``F`` exists only when the
   contraction closes, ``a^L nu_L < 1``);
4. regularity: the Jacobian ``Im(conj(d_1 chi) d_w chi)``, in Arb balls widened by ``E``, has one strict sign on every
   triangle (the other sectors are the same map rotated by ``rho``: the same Jacobian);
5. injectivity: the ring's inner boundary (``|x| = d`` in sector 0) maps into a chain of balls that avoid 0; the angle
   it sweeps, times ``n``, is ``2 pi`` times the winding number of the whole curve; a regular ring whose inner boundary
   winds once, with the Jacobian's sign, covers the annulus once.

The verdict is ``C1`` only when all five are certified; a bound that does not close at the deepest ``m`` tried is
``undecided``, saying which. The scope is **per valence**: each ``n`` is its own certificate; "every n" is not proved
here (Zorin's paper argues large valences separately).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import replace
from fractions import Fraction

import flint

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import check_bits, check_int
from symdecomp.verify.c1_spectrum import SpectralResult, ball_text, float_down, round_down
from symdecomp.verify.c1_zoo import ZooC1Result
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import characteristic_points, real_matrix, spectral_conditions
from symdecomp.verify.zorin_bounds import EDGES, RHOMBI, TRIANGLES, DifferenceBounds, Point, difference_bounds, hex_norm
from symdecomp.verify.zorin_net import WedgeNet, grow, refine, wedge_points

__all__ = ["ZORIN_METHOD", "NET_DEPTH", "MAX_REFINEMENT", "FIRST_POINTS", "depths", "net_depth", "c1_zorin_test"]

#: The method, as reported with each verdict of this route.
ZORIN_METHOD = ("Zorin's test: the characteristic map's control net refined m times by the regular rules; the limit's "
                "derivatives within a bound of the net's differences (from the contraction of the regular rules' "
                "difference scheme); the Jacobian's sign certified on every triangle of one sector's ring in interval "
                "arithmetic; injective by the winding number of the ring's inner boundary; per valence")
#: The least depth of the engine's neighbourhood the eigenvector is solved on (:func:`net_depth`).
NET_DEPTH = 4
#: The deepest refinement tried (each level has four times the points of the one before).
MAX_REFINEMENT = 7
#: The refinement tried first is the deepest whose points per coarse point (``a^(2m)``) are at most this: ``m = 4``
#: for one primal step (``a = 2``), ``m = 2`` for sqrt(3)'s two (``a = 3``).
FIRST_POINTS = 4 ** 4


def depths(bounds: DifferenceBounds, min_depth: int | None, max_depth: int) -> range:
    """The refinements tried: ``min_depth`` (default: the deepest within :data:`FIRST_POINTS`) to ``max_depth``, both
    capped where a level would have more points per coarse point than :data:`MAX_REFINEMENT` dyadic ones."""
    a = bounds.dilation
    deepest = max(m for m in range(1, MAX_REFINEMENT + 1) if m == 1 or a ** (2 * m) <= 4 ** MAX_REFINEMENT)
    first = max(m for m in range(1, MAX_REFINEMENT + 1) if m == 1 or a ** (2 * m) <= FIRST_POINTS)
    last = min(max_depth, deepest)
    return range(min(first if min_depth is None else min_depth, last), last + 1)


def _q(x: Fraction) -> flint.arb:
    return flint.arb(flint.fmpq(x.numerator, x.denominator))


def _widen(z: flint.acb, e: flint.arb) -> flint.acb:
    """``z`` plus every complex number of modulus at most ``e`` (a box around it)."""
    r = flint.arb(0, e.upper())
    return flint.acb(z.real + r, z.imag + r)


def net_depth(bounds: DifferenceBounds) -> int:
    """The depth the eigenvector is solved on: :data:`NET_DEPTH`, or deeper until the regular rules grow it."""
    return max(NET_DEPTH, bounds.clear_radius - 1)


def _characteristic(scheme: StencilScheme, n: int, depth: int = NET_DEPTH
                    ) -> SpectralResult | str | tuple[SpectralResult, WedgeNet]:
    """``(spectral, level-0 net of radius depth)``, or the spectral result / a reason string when there is no map."""
    zm = zoo_matrix(scheme, n, depth)
    spectral = spectral_conditions(zoo_spectrum(scheme, n, None, jordan=False), n,  # the smallest invariant depth
                                   real_matrix=real_matrix(zm))
    if spectral.status is not C1Verdict.C1 or spectral.subdominant is None:
        return spectral
    points = characteristic_points(zm, spectral.subdominant)
    if points is None:
        return "the subdominant eigenvector could not be solved in its frequency block at this precision"
    nb = zm.neighbourhood
    where, spoke = wedge_points(nb.mesh, nb.start, depth)
    s0, s1 = nb.labels[where[(1, 0)]][0], nb.labels[spoke][0]
    rho = flint.acb(flint.fmpq(2 * spectral.subdominant.frequencies[0] * (s1 - s0), n)).exp_pi_i()
    return spectral, WedgeNet({q: points[v] for q, v in where.items()}, rho)


def _level_net(net: WedgeNet, lam: flint.acb, bounds: DifferenceBounds, m: int) -> tuple[WedgeNet, int]:
    """``(net, d)``: sector 0 of level ``m`` on the ring ``[d, a d]`` widened by the margin."""
    a, low = bounds.dilation, 0
    for _ in range(m):
        low = max(a * low + bounds.reach, bounds.clear_radius)
    d = low + bounds.margin
    need = a * d + bounds.margin + 1
    for _ in range(m):  # the level-0 radius whose m refinements reach ``need``
        need = -(-(need + bounds.reach) // a)
    radius = net_depth(bounds)
    net, high = grow(net, radius, lam, bounds, max(need, radius))
    low = 0
    for _ in range(m):
        net, low, high = refine(net, low, high, bounds)
    return net, d


def _rhombus_bound(net: WedgeNet, inner: int, outer: int) -> flint.arb:
    """``M``: the largest rhombus difference with every corner at graph distance in ``[inner, outer]``."""
    top = flint.arb(0)
    for x in range(-2, outer + 1):  # every rhombus, turned to the sector of one of its corners, has its base here
        for y in range(-2, outer + 1):
            for rh in RHOMBI:
                corners = [((x + k[0], y + k[1]), s) for k, s in rh.items()]
                if all(inner <= hex_norm(c) <= outer for c, _ in corners):
                    top = top.max(abs(sum((s * net.value(c) for c, s in corners), flint.acb(0))).upper())
    return top


def _triangles(d: int, a: int) -> Iterator[list[Point]]:
    """Sector 0's level-``m`` triangles of the ring ``d <= |x| <= a d``: their corners."""
    for x in range(0, a * d + 1):
        for y in range(0, a * d + 1 - x):
            for corners in TRIANGLES.values():
                pts = [(x + c[0], y + c[1]) for c in corners]
                if all(d <= hex_norm(p) <= a * d for p in pts):
                    yield pts


def _edge_difference(net: WedgeNet, pts: list[Point], e: Point, scale: int) -> flint.acb:
    for a in pts:
        b = (a[0] + e[0], a[1] + e[1])
        if b in pts:
            return scale * (net.value(b) - net.value(a))
    raise AssertionError("a lattice triangle has an edge in each direction")  # pragma: no cover


def _jacobian(net: WedgeNet, d: int, a: int, m: int, error: flint.arb
              ) -> tuple[set[int], flint.arb | None, Point | None]:
    """``(signs seen, lower bound of |J|, a triangle where the sign is open)`` over sector 0's ring."""
    signs: set[int] = set()
    low: flint.arb | None = None
    open_at: Point | None = None
    for pts in _triangles(d, a):
        d1 = _widen(_edge_difference(net, pts, EDGES[0], a ** m), error)
        dw = _widen(_edge_difference(net, pts, EDGES[1], a ** m), error)
        jac = d1.real * dw.imag - d1.imag * dw.real
        if jac > 0 or jac < 0:
            signs.add(1 if jac > 0 else -1)
            bound = abs(jac).lower()
            low = bound if low is None else low.min(bound)
        elif open_at is None:
            open_at = pts[0]
    return signs, low, open_at


def _winding(net: WedgeNet, d: int, n: int, edge: int, error: flint.arb, node_error: flint.arb) -> int | None:
    """The winding number of the ring's inner boundary around 0, or ``None`` when a piece may pass through 0."""
    angle = flint.arb(0)
    for t in range(d):
        a, b = (d - t, t), (d - t - 1, t + 1)
        pa, pb = _widen(net.value(a), node_error), _widen(net.value(b), node_error)
        piece = pa + flint.arb(0.5, 0.5) * _widen(net.value(b) - net.value(a), error / edge)
        if piece.real.contains(0) and piece.imag.contains(0):
            return None
        angle += (pb / pa).arg()
    w = n * angle / (2 * flint.arb.pi())
    lo, hi = math.ceil(float(w.lower())), math.floor(float(w.upper()))
    return lo if lo == hi else None


def c1_zorin_test(scheme: StencilScheme, n: int, *, min_depth: int | None = None, max_depth: int = 6,
                  prec: int = 128) -> ZooC1Result:
    """Zorin's test at valence ``n`` (module docstring), refining ``m = min_depth..max_depth`` times until it decides
    (:func:`depths`: by default from the deepest level of at most :data:`FIRST_POINTS` points per coarse point)."""
    prec = check_bits(prec)
    max_depth = check_int(max_depth, "max_depth", minimum=1, maximum=MAX_REFINEMENT)
    if min_depth is not None:
        min_depth = check_int(min_depth, "min_depth", minimum=1, maximum=max_depth)
    result = ZooC1Result(n=n, scheme=scheme.name, verdict=C1Verdict.UNDECIDED, reason="", max_depth=max_depth,
                         precision=prec, method=ZORIN_METHOD)
    try:
        bounds = difference_bounds(scheme)
    except InvalidSchemeError as exc:
        return replace(result, reason=f"the regular rules give no difference bound: {exc}")
    if not bounds.closes:
        a = bounds.dilation
        return replace(result, reason=(f"the regular rules' difference scheme does not contract within {bounds.steps} steps "
                                       f"({a}^L nu_L = {float(a ** bounds.steps * bounds.contraction[-1]):.4g} >= 1): "
                                       "no bound of the derivatives"))
    if n == lattice(scheme.lattice).regular_valence:  # the vertex is regular: the regular rules' C1 is the verdict
        return replace(result, verdict=C1Verdict.C1, reason=(
            f"the vertex is regular and the regular rules' derivative scheme converges: {bounds.dilation}^L nu_L = "
            f"{bounds.dilation ** bounds.steps * bounds.contraction[-1]} < 1 at L = {bounds.steps}"))
    with flint.ctx.workprec(prec):
        start = _characteristic(scheme, n, net_depth(bounds))
        if isinstance(start, str):
            return replace(result, reason=start)
        if not isinstance(start, tuple):
            return replace(result, verdict=start.status, reason=start.reason, spectral=start)
        reason = "no depth tried"
        for m in depths(bounds, min_depth, max_depth):
            decided = _at_depth(start, n, bounds, m, result)
            if isinstance(decided, ZooC1Result):
                return decided
            reason = decided
    return replace(result, reason=reason)


def _at_depth(start: tuple[SpectralResult, WedgeNet], n: int, bounds: DifferenceBounds, m: int,
              result: ZooC1Result) -> ZooC1Result | str:
    """The verdict at refinement depth ``m``, or why the bound did not close there."""
    spectral, net0 = start
    lam = spectral.subdominant
    assert lam is not None  # the spectral conditions hold: _characteristic returned a net
    net, d = _level_net(net0, lam.value, bounds, m)
    a = bounds.dilation
    M = _rhombus_bound(net, d - bounds.margin, a * d + bounds.margin)
    error = _q(bounds.derivative) * a ** m * M * _q(bounds.derivative_factor())
    node_error = _q(bounds.position) * M * _q(bounds.position_factor())
    signs, low_j, open_at = _jacobian(net, d, a, m, error)
    base = replace(result, spectral=spectral, frequency=lam.frequency, subdivision_depth=m)
    if len(signs) > 1:
        return replace(base, verdict=C1Verdict.NOT_C1, reason=(f"the Jacobian of the characteristic map has both signs on "
                                                               f"the ring at depth {m}: it is not regular"))
    if open_at is not None or not signs or low_j is None:
        return (f"the bound did not close at m = {m}: the Jacobian's sign is open on the triangle at {open_at} "
                f"(derivative error <= {float(error.upper()):.3g})")
    sign = signs.pop()
    winding = _winding(net, d, n, a ** m, error, node_error)
    found = replace(base, jacobian_sign=sign, jacobian_lower_bound=float_down(low_j), winding_number=winding)
    if winding is None:
        return f"the winding number of the inner boundary is not certified at m = {m}"
    text = ball_text(lam.value)
    if winding == sign:
        gap = "" if spectral.gap is None else f", gap >= {round_down(spectral.gap)}"
        return replace(found, verdict=C1Verdict.C1, reason=(
            f"lambda = {text} (frequency {lam.frequency}{gap}); the characteristic map is regular (|J| >= "
            f"{round_down(float_down(low_j))} at depth {m}, derivative error <= {float(error.upper()):.3g}) and winds once: "
            "injective (this valence)"))
    if abs(winding) > 1:
        return replace(found, verdict=C1Verdict.NOT_C1, reason=(f"the characteristic map (lambda = {text}) is regular but "
                                                                f"winds {winding} times around the origin: not injective"))
    return replace(found, reason=f"winding number {winding} does not match the Jacobian's sign {sign}")
