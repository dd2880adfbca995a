"""C1 for a scheme of the zoo: Reif's test where the regular part is a spline patch this package evaluates, Zorin's test
where it is not (primal schemes on triangles), else ``undecided`` with the reason.

The route is decided by the scheme's model (:class:`~symdecomp.schemes.stencils.StencilScheme`), never by its name:

* a dual scheme whose rule in a regular face (the corner rule in a face of the lattice's size, at its regular
  valence) is the biquadratic B-spline's: each corner point is the tensor product of Chaikin's weights ``(3/4, 1/4)`` (the quadratic
  B-spline's mask ``(1, 3, 3, 1)/4``), so the regular part is the biquadratic B-spline and
  :func:`c1_dual_test` (:mod:`symdecomp.verify.c1_dual`) applies;
* a primal scheme (one step; the modified butterfly, which is interpolatory, so its regular part is no spline): Zorin's
  test, which needs no spline patch (D. Zorin, *A method for analysis of C1-continuity of subdivision surfaces*, SIAM
  J. Numer. Anal. 37(5), 2000: bounds on the characteristic map's control net and its differences under refinement;
  :mod:`symdecomp.verify.c1_zorin`), per valence; its bounds are written for triangles, and a scheme on another
  lattice is ``undecided`` with the fact that stopped it;
* a dual scheme whose regular corner rule has a refinable piecewise quadratic on the four-direction mesh (Midedge:
  the Zwart-Powell box spline, derived by :func:`~symdecomp.schemes.four_direction.four_direction_patch`): the same
  test over that patch's triangles (:mod:`symdecomp.verify.c1_four_direction`). Its translates are linearly
  dependent, so an eigenvector of the matrix may be the zero function: where the matrix fails Reif's conditions they
  are redone on the functions the patch makes (:mod:`symdecomp.verify.c1_four_direction_quotient`, exact), and the
  verdict is theirs (Midedge at n = 3: every eigenvector counts, and 1/4 has a Jordan block at frequencies 1, 2,
  which Reif's test does not cover; the map of the chains' eigenvectors decides it,
  :mod:`symdecomp.verify.c1_four_direction_jordan`: C1 for almost every net);
* any other scheme (sqrt(3)'s rotating steps): ``undecided``, naming what has no test here.

:func:`c1_dual_test` takes what the zoo's engine computes at valence ``n`` (:class:`ZooNeighbourhood`: the explicit
local mesh with orbit labels, the characteristic map's control points from the subdominant eigenvectors, and the
certified spectral conditions) and gives the verdict the way :func:`symdecomp.verify.c1.c1_test` does.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from math import comb
from typing import Any

import flint
import sympy as sp

from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.eigenvalue import Eigenvalue
from symdecomp.errors import InvalidSchemeError, UnavailableError
from symdecomp.schemes.four_direction import FourDirectionPatch, four_direction_patch
from symdecomp.schemes.lattice import lattice
from symdecomp.schemes.stencils import J, M, N, StencilScheme
from symdecomp.schemes.topology import topology_of
from symdecomp.validate import check_bits, check_depth
from symdecomp.verify.c1_dual import DualNeighbourhood, RingCertificate, certify_ring
from symdecomp.verify.c1_four_direction import FOUR_DIRECTION_METHOD, certify_four_direction_ring
from symdecomp.verify.c1_four_direction_jordan import JORDAN_CHAIN_METHOD, jordan_chain_verdict
from symdecomp.verify.c1_four_direction_quotient import quotient_test
from symdecomp.verify.c1_spectrum import SpectralResult, ball_text, block_root, round_down
from symdecomp.verify.result import C1Verdict

__all__ = ["DUAL_METHOD", "NO_METHOD", "ZORIN_CENTRE", "ZooNeighbourhood", "ZooC1Result", "biquadratic_corner_weights", "regular_corner_weights",
           "corner_weights", "spline_route", "four_direction_route", "four_direction_every_n_gap", "zorin_route", "c1_dual_test", "c1_zoo"]

#: The method, as reported with each verdict of the dual route.
DUAL_METHOD = ("Reif's test on the characteristic map's ring of biquadratic B-spline patches (the vertices one face from "
               "the centre n-gon): Jacobian in Bernstein-Bezier form (raised to bicubic), one strict sign in interval "
               "arithmetic with de Casteljau subdivision; injective by winding number 1 of the ring's inner boundary")

#: The method line of a scheme that neither test applies to (its verdicts are ``undecided``, each with the reason).
NO_METHOD = ("none applies: Reif's test needs a spline patch this package evaluates (a dual quad scheme whose regular part is "
             "the biquadratic B-spline or a C1 piecewise quadratic on the four-direction mesh), and Zorin's test, which "
             "needs none, is written for a net around a vertex of the triangle lattice")

#: The centre Zorin's test (:mod:`symdecomp.verify.c1_zorin`) is written for: a vertex (its net is sector 0 of a
#: triangle lattice around it, refined by the steps that return the lattice to itself: one primal step, sqrt(3)'s two).
ZORIN_CENTRE = "vertex"


@dataclass(frozen=True)
class ZooNeighbourhood:
    """What the zoo's engine hands to the C1 test at one valence."""

    #: The explicit local mesh around the centre element, with orbit labels.
    mesh: DualNeighbourhood
    #: ``vertex -> (x, y)`` (or a complex ball): the characteristic map's control points.
    points: Mapping[Any, Any]
    #: Reif's spectral conditions, certified (the subdominant eigenvalue and its frequency).
    spectral: SpectralResult
    #: The control points in the order of :attr:`matrix`'s rows and columns (empty when the engine gives no matrix).
    order: tuple[Any, ...] = ()
    #: The exact subdivision matrix on the neighbourhood (``None``: not given): the four-direction route reads the
    #: spectrum on the functions its patch can make from it (:mod:`symdecomp.verify.c1_four_direction_quotient`).
    matrix: Any = None


@dataclass(frozen=True)
class ZooC1Result(NotebookDisplay):
    """The C1 verdict for a zoo scheme at one valence (the fields of :class:`~symdecomp.verify.c1.C1Result`'s JSON)."""

    n: int
    scheme: str
    verdict: C1Verdict
    reason: str
    #: ``None`` when the test did not run (no spline patch).
    spectral: SpectralResult | None = None
    frequency: int | None = None
    jacobian_sign: int | None = None
    jacobian_lower_bound: float | None = None
    subdivision_depth: int | None = None
    max_depth: int = 6
    winding_number: int | None = None
    precision: int = 64
    method: str = DUAL_METHOD

    def as_json(self) -> dict[str, Any]:
        lam = None if self.spectral is None else self.spectral.subdominant
        return {
            "n": self.n,
            "scheme": self.scheme,
            "verdict": self.verdict,
            "reason": self.reason,
            "lambda": None if lam is None else float(lam.value.real.mid()),
            "frequency": self.frequency,
            "gap": None if self.spectral is None else self.spectral.gap,
            "jacobian_sign": self.jacobian_sign,
            "jacobian_lower_bound": self.jacobian_lower_bound,
            "subdivision_depth": self.subdivision_depth,
            "max_depth": self.max_depth,
            "winding_number": self.winding_number,
            "precision_bits": self.precision,
            "method": self.method,
        }


def biquadratic_corner_weights() -> tuple[sp.Rational, ...]:
    """The biquadratic B-spline's corner rule in a quad: weights on corners ``0..3`` (counter-clockwise from the corner).

    Chaikin's weights ``(3/4, 1/4)`` are the two phases of the quadratic B-spline's mask ``C(3, k)/4``; the corner
    point takes ``3/4`` of its own corner in each direction: ``c(a) c(b)`` for ``a``, ``b`` steps along the two edges.
    """
    chaikin = (sp.Rational(comb(3, 1), 4), sp.Rational(comb(3, 0), 4))
    steps = ((0, 0), (1, 0), (1, 1), (0, 1))  # corner k of the quad: its steps along the anchor's edge and the other
    return tuple(chaikin[a] * chaikin[b] for a, b in steps)


def _corner_offset(walk: tuple[str, ...]) -> int | None:
    """The corner a walk inside the face reaches (``next`` +1, ``prev`` -1), or ``None`` if it leaves the face."""
    if any(move == "twin" for move in walk):
        return None
    return sum(1 if move == "next" else -1 for move in walk)


def regular_corner_weights(scheme: StencilScheme) -> tuple[sp.Expr, ...] | str:
    """The scheme's corner rule in a regular face of its lattice (weights on the corners), or why it cannot be read as one.

    The regular face and valence are the lattice's (:attr:`~symdecomp.schemes.lattice.Lattice.face_sides`,
    :attr:`~symdecomp.schemes.lattice.Lattice.regular_valence`).
    """
    lat = lattice(scheme.lattice)
    return corner_weights(scheme, lat.face_sides, lat.regular_valence)


def corner_weights(scheme: StencilScheme, sides: int, valence: int) -> tuple[sp.Expr, ...] | str:
    """The corner rule in a face of ``sides`` corners whose vertices have ``valence``: the weight on the corner ``k`` steps
    on (counter-clockwise) from the new point's own corner, ``k = 0..sides-1``; or why it is not a rule inside the face."""
    try:
        rules = scheme.rules_of("corner")
    except InvalidSchemeError as exc:
        return str(exc)
    rule = next((r for r in rules.rules if r.applies(valence, valence, regular=valence)), None)
    if rule is None:
        return f"no corner rule applies where the vertices have valence {valence}"
    weights = [sp.Integer(0)] * sides
    for term in rule.terms:
        offset = _corner_offset(term.walk)
        if term.source != "old" or term.over == "ring" or offset is None:
            return "its corner rule reaches outside the face (a walk across an edge, a ring or new points)"
        for j in range(sides if term.over == "face" else 1):
            weights[(j + offset) % sides] += term.weight.subs({M: sides, N: valence, J: j})
    return tuple(weights)


def spline_route(scheme: StencilScheme) -> str | None:
    """``None`` when the scheme's regular part is the biquadratic B-spline (the dual route applies), else the reason."""
    centre = topology_of(scheme).centre
    tail = (f"Zorin's test, which needs no spline patch, is written here for a net around a {ZORIN_CENTRE} of the triangle "
            f"lattice{'' if centre == ZORIN_CENTRE else f', and this scheme centres on a {centre}'}")
    if scheme.interpolatory:
        return f"the scheme is interpolatory, so its regular part is no spline and Reif's test has no patch; {tail}"
    if scheme.topology != "dual":
        return (f"its steps are {scheme.topology} on the {scheme.lattice} lattice: the spline patch of the dual quad route "
                f"does not apply (primal schemes: the edge/face/vertex form's c1); {tail}")
    weights = regular_corner_weights(scheme)
    if isinstance(weights, str):
        return f"its regular rule cannot be read as a corner rule ({weights}); {tail}"
    target = biquadratic_corner_weights()
    if len(weights) != len(target) or any(sp.simplify(w - t) != 0 for w, t in zip(weights, target)):
        return (f"its regular corner weights ({', '.join(map(str, weights))}) are not the biquadratic B-spline's "
                f"({', '.join(map(str, target))}): no spline patch is evaluated for it; {tail}")
    return None


def _verdict(ring: RingCertificate, lam: Eigenvalue, gap: float | None) -> tuple[C1Verdict, str]:
    """The verdict from the certified ring once the spectral conditions hold (as :func:`symdecomp.verify.c1.c1_test`)."""
    if ring.status == "changes":
        return C1Verdict.NOT_C1, f"the Jacobian of the characteristic map changes sign ({ring.where}): it is not regular"
    if ring.status == "undecided":
        return C1Verdict.UNDECIDED, (f"the Jacobian's sign is not certified at subdivision depth {ring.depth} "
                                     "(a deeper subdivision or more precision would decide)")
    if ring.winding_number is None:
        return C1Verdict.UNDECIDED, "the winding number of the inner boundary is not certified"
    text, j = ball_text(lam.value), lam.frequency
    if ring.winding_number == ring.jacobian_sign:
        gap_text = "" if gap is None else f", gap >= {round_down(gap)}"
        bound = "" if ring.jacobian_lower_bound is None else f" (|J| >= {round_down(ring.jacobian_lower_bound)})"
        return C1Verdict.C1, f"lambda = {text} (frequency {j}{gap_text}); the characteristic map is regular{bound} and winds once: injective"
    if abs(ring.winding_number) > 1:
        return C1Verdict.NOT_C1, (f"the characteristic map (lambda = {text} at frequency {j}) is regular but winds "
                                  f"{ring.winding_number} times around the origin: it is not injective")
    return C1Verdict.UNDECIDED, f"winding number {ring.winding_number} does not match the Jacobian's sign {ring.jacobian_sign}"


def c1_dual_test(neighbourhood: ZooNeighbourhood, *, scheme: str, n: int, max_depth: int = 6, prec: int = 64,
                 patch: FourDirectionPatch | None = None) -> ZooC1Result:
    """Reif's test on a dual quad neighbourhood whose regular part is the biquadratic B-spline, or the four-direction
    ``patch`` when one is given (module docstring)."""
    max_depth, prec = check_depth(max_depth), check_bits(prec)
    spectral, lam = neighbourhood.spectral, neighbourhood.spectral.subdominant
    result = ZooC1Result(n=n, scheme=scheme, verdict=spectral.status, reason=spectral.reason, spectral=spectral,
                         max_depth=max_depth, precision=prec, method=DUAL_METHOD if patch is None else FOUR_DIRECTION_METHOD)
    if spectral.status is C1Verdict.NOT_C1 and patch is not None and patch.dependent_translates:
        if neighbourhood.matrix is None:
            return replace(result, verdict=C1Verdict.UNDECIDED, reason=(
                f"{spectral.reason}; Reif's spectral conditions fail on the matrix, but the regular patch's translates are "
                "linearly dependent, so an eigenvector may give no function, and no matrix was given to tell: "
                "not shown to be not C1"))
        return _quotient_result(result, neighbourhood, patch)
    if spectral.status is not C1Verdict.C1:
        return result
    if lam is None:
        return replace(result, verdict=C1Verdict.UNDECIDED, reason="the spectral conditions name no subdominant eigenvalue")
    with flint.ctx.workprec(prec):
        ring = (certify_ring(neighbourhood.mesh, neighbourhood.points, max_depth=max_depth) if patch is None else
                certify_four_direction_ring(neighbourhood.mesh, neighbourhood.points, patch, max_depth=max_depth))
    verdict, reason = _verdict(ring, lam, spectral.gap)
    return replace(result, verdict=verdict, reason=reason, frequency=lam.frequency, jacobian_sign=ring.jacobian_sign,
                   jacobian_lower_bound=ring.jacobian_lower_bound, subdivision_depth=ring.depth,
                   winding_number=ring.winding_number)


def _quotient_result(result: ZooC1Result, neighbourhood: ZooNeighbourhood, patch: FourDirectionPatch) -> ZooC1Result:
    """The verdict from the spectrum on the functions the four-direction patch makes
    (:func:`~symdecomp.verify.c1_four_direction_quotient.quotient_test`) where the matrix fails Reif's conditions."""
    found = quotient_test(neighbourhood.mesh, neighbourhood.order, neighbourhood.matrix, patch, result.n,
                          max_depth=result.max_depth, prec=result.precision)
    head = f"{result.reason} on the matrix, whose patch's translates are linearly dependent; {found.reason}"
    if found.refuted:
        return replace(result, verdict=C1Verdict.NOT_C1, reason=head)
    ring = found.ring
    if ring is None:
        return replace(result, verdict=C1Verdict.UNDECIDED, reason=head)
    shown = replace(result, frequency=found.frequency, jacobian_sign=ring.jacobian_sign,
                    jacobian_lower_bound=ring.jacobian_lower_bound, subdivision_depth=ring.depth,
                    winding_number=ring.winding_number)
    value = found.spectrum.subdominant
    if found.conditions_hold and value is not None and found.frequency is not None:
        lam = block_root(flint.acb(flint.fmpq(value.numerator, value.denominator)), found.frequency, 2, result.n)
        verdict, reason = _verdict(ring, lam, None)
        return replace(shown, verdict=verdict, reason=f"{head}; {reason}")
    chained = jordan_chain_verdict(found)
    if chained is not None:
        return replace(shown, verdict=chained[0], reason=f"{head}; {chained[1]}", method=JORDAN_CHAIN_METHOD)
    return replace(shown, verdict=C1Verdict.UNDECIDED, reason=(
        f"{head}; the map is certified ({ring.status}, winding {ring.winding_number}) but the spectral structure is not one "
        "this package reads (Reif's test needs no Jordan block; the chain route one pair of longest chains): "
        "not shown C1 or not C1"))


def four_direction_route(scheme: StencilScheme) -> FourDirectionPatch | str:
    """The regular patch of a dual scheme on the four-direction mesh derived from its regular corner rule
    (:func:`~symdecomp.schemes.four_direction.four_direction_patch`), or why there is none."""
    if scheme.topology != "dual":
        return f"its steps are {scheme.topology}, not dual"
    weights = regular_corner_weights(scheme)
    if isinstance(weights, str):
        return f"its regular rule cannot be read as a corner rule ({weights})"
    if not all(isinstance(w, sp.Rational) for w in weights):
        return f"its regular corner weights ({', '.join(map(str, weights))}) are not all rational"
    try:
        patch = four_direction_patch(weights)
    except InvalidSchemeError as exc:
        return str(exc)
    if not patch.c1:
        return (f"corner rule ({', '.join(map(str, patch.corner_weights))}): its regular part, a piecewise quadratic on the "
                "four-direction mesh, is not C1 (its gradient jumps across an edge), so Reif's test does not apply")
    return patch


def four_direction_every_n_gap(scheme: StencilScheme) -> str | None:
    """Why ``c1 --every-n`` does not cover a scheme on the four-direction route (``None`` when it is not on it).

    The every-n argument (:mod:`symdecomp.verify.c1_dual_every_n`, :mod:`symdecomp.verify.c1_dual_uniform`) is written
    for the biquadratic B-spline's patches, and solves the frequency-1 eigenvector for every ``n`` only where
    ``lambda_1 = sigma(1)``, the ``n``-gon's symbol at frequency 1, is a rational constant. The symbol is read from the
    structural form of the matrix (:func:`~symdecomp.analysis.zoo_structure.zoo_structure`) and written in
    ``t = cos(2 pi/n)`` (``omega^k + omega^-k = 2 T_k(t)``), so the reason names the computed ``lambda_1(t)``.
    """
    if scheme.topology != "dual" or isinstance(four_direction_route(scheme), str):
        return None
    from symdecomp.analysis.zoo_structure import zoo_structure
    from symdecomp.symbols import omega

    entry = sp.sympify(zoo_structure(scheme).block[0, 0], strict=True)
    t = sp.Symbol("t")
    real = sp.Integer(0)
    for term in sp.Add.make_args(sp.expand(entry)):
        a, k = term.as_coeff_exponent(omega)
        if a.has(omega) or not k.is_Integer or a.free_symbols:
            return (f"its regular part is the four-direction patch (certified valence by valence with --n A:B), but the "
                    f"every-n argument is written for the biquadratic B-spline's patches, and the n-gon's block {entry} "
                    "is not a Laurent polynomial in omega with constant coefficients")
        real += a * sp.chebyshevt(abs(int(k)), t)
    lam = sp.expand(real)
    constant = "a constant" if lam.is_Rational else f"{lam} with t = cos(2 pi/n), varying with n"
    return (f"its regular part is the four-direction patch (certified valence by valence with --n A:B), but the every-n "
            f"argument is written for the biquadratic B-spline's patches and solves the eigenvector for every n only for a "
            f"rational constant lambda_1, and here lambda_1 = sigma(1) is {constant} (the n-gon's block {entry})")


def zorin_route(scheme: StencilScheme) -> bool:
    """Whether C1 of ``scheme`` is Zorin's test (no spline patch, :func:`spline_route`; a vertex at the centre, the steps
    that return the lattice to itself read by :func:`~symdecomp.verify.zorin_bounds.regular_mask`, which names what stops it):
    the one test of :func:`c1_zoo` and of ``c1 --every-n``, which then reads the spectral conditions for every n from
    the structural blocks (:mod:`symdecomp.verify.c1_zorin_every_n`)."""
    return spline_route(scheme) is not None and topology_of(scheme).centre == ZORIN_CENTRE


def c1_zoo(scheme: StencilScheme, n: int, *, neighbourhood: Callable[[StencilScheme, int], ZooNeighbourhood] | None = None,
           max_depth: int = 6, prec: int = 64) -> ZooC1Result:
    """C1 at valence ``n`` for a zoo scheme: the dual route (:func:`c1_dual_test`), Zorin's test for a primal scheme
    (:func:`~symdecomp.verify.c1_zorin.c1_zorin_test`, refining up to ``max_depth`` times), or ``undecided`` with the reason.

    ``neighbourhood(scheme, n)``: the zoo engine's local mesh, characteristic map and spectral conditions; without it
    a scheme the dual route applies to cannot be tested (:class:`~symdecomp.errors.UnavailableError`).
    """
    if zorin_route(scheme):
        from symdecomp.verify.c1_zorin import MAX_REFINEMENT, c1_zorin_test  # imported when this route runs

        return c1_zorin_test(scheme, n, max_depth=min(max(max_depth, 1), MAX_REFINEMENT))
    patch = None
    if (reason := spline_route(scheme)) is not None:
        found = four_direction_route(scheme) if scheme.topology == "dual" else reason
        if isinstance(found, str):
            reason = reason if found == reason else f"{reason}; nor on the four-direction mesh: {found}"
            return ZooC1Result(n=n, scheme=scheme.name, verdict=C1Verdict.UNDECIDED, reason=reason, max_depth=max_depth,
                               precision=prec, method=NO_METHOD)
        patch = found
    if neighbourhood is None:
        raise UnavailableError(f"c1 for {scheme.name!r} needs the zoo engine's neighbourhood at valence {n}, which is not "
                               "available in this installation")
    return c1_dual_test(neighbourhood(scheme, n), scheme=scheme.name, n=n, max_depth=max_depth, prec=prec, patch=patch)
