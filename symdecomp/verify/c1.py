"""Certified C1 at an extraordinary vertex: Reif's sufficient test on the characteristic map.

**The test** (Reif 1995, *A unified approach to subdivision algorithms near extraordinary
vertices*, CAGD 12, 153-174; Peters and Reif 2008, *Subdivision Surfaces*, Springer). A
subdivision scheme whose regular patches are C1 generates C1 surfaces at a vertex of valence
``n`` for almost every initial mesh if

1. the subdivision matrix has the spectral structure of :mod:`symdecomp.verify.c1_spectrum`
   (1 simple; ``lambda`` real, double, non-defective, strictly dominant), and
2. the characteristic map ``chi`` (the spline ring of the two real eigenvectors of ``lambda``:
   real and imaginary parts of the complex eigenvector, see
   :mod:`symdecomp.analysis.characteristic`) is *regular* (Jacobian of one strict sign on the
   ring) and *injective*.

**Regularity.** Catmull-Clark type: on each of the three bicubic sub-patches of sector 0 the
Jacobian determinant is a polynomial of bidegree (5, 5); its Bernstein-Bezier coefficients are
computed in Arb and must all be of one strict sign, with de Casteljau subdivision where a ball
straddles 0 (:func:`~symdecomp.verify.bezier.certify_sign`, depth ``max_depth``). Loop type: on
each of the three quartic box-spline sub-patches (the regular patch's Bezier basis,
:func:`~symdecomp.schemes.box_spline.regular_patch`, on the level-1 triangles
:data:`~symdecomp.analysis.characteristic.TRIANGLES`) the Jacobian is a triangular
Bernstein polynomial of degree 6, certified the same way with bisection
(:func:`~symdecomp.verify.bezier.certify_sign_triangles`, at most ``2 max_depth`` bisections,
as many halvings of the edges as ``max_depth`` tensor splits; the reported depth counts
bisections). One sector suffices: the eigenvector of frequency ``j`` has sector values
``omega^s c``, so the ring of sector ``s`` is the ring of sector 0 rotated by ``2 pi j s / n``
in the same local parameters, and a rotation has determinant 1. The Jacobian is taken in the
local parameters of the level-1 faces (quads) or triangles (lattice-unit triangles).

**Injectivity.** Criterion: for a regular characteristic map, injectivity is decided by the
index (winding number) of a closed curve, the image of the ring's boundary, around the origin
(Zorin 2000, *A method for analysis of C1-continuity of subdivision surfaces*, SIAM J. Numer.
Anal. 37(5), 1677-1708: "injectivity can be verified by computing the index of a curve"; Peters
and Reif 2008 give the criterion in their chapter on C1 analysis). *What was checked*: Zorin's
title, journal, pages and that sentence of his abstract, and Reif 1995's journal and pages as
Zorin's abstract cites them; the section numbers of Peters and Reif's book were not checked
(an earlier version of this docstring cited "Section 5.3" from memory and is corrected here).
Applied here: the map is injective when the image of the inner boundary winds around the
origin exactly once (``+1`` for a positive Jacobian, ``-1`` for a negative one); a regular ring
winding ``w`` times with ``|w| > 1`` covers points ``|w|`` times, so it is not injective and the
scheme is not C1 in general. The winding number is ``n`` times the argument swept by sector 0's
part of the inner boundary, divided by ``2 pi``: from the level-1 point ``(1, 0)`` through
``(1, 1)`` to ``(0, 1)`` (two cubic Bezier curves) on quads, the edge from ``(1, 0)`` to
``(0, 1)`` of the middle triangle (a quartic) on triangles. The argument is summed over curve
pieces whose control points lie in an open half-plane through 0
(:func:`~symdecomp.verify.bezier.curve_angle`), so the sum is rigorous.

**Scope.** Schemes whose regular rules are Catmull-Clark's (bicubic B-splines) or Loop's
(quartic box-splines), with any rules on the extraordinary vertex's 1-ring
(:func:`~symdecomp.analysis.characteristic.check_applicable` says in one line why the test
does not apply to other schemes).

The verdict is ``c1`` when everything is certified, ``not-c1`` when a condition is shown to fail
(named, with its numbers), ``undecided`` otherwise (saying what would decide it).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> r = c1_test(catmull_clark(), 5)
>>> str(r.verdict), r.winding_number, r.jacobian_sign
('c1', 1, 1)
>>> from symdecomp.schemes.loop import loop
>>> c1_test(loop(), 5).verdict is C1Verdict.C1
True
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache

import flint

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.triangle_bezier import bezier_indices
from symdecomp.analysis.characteristic import TRIANGLES, frequency_eigenvector, inner_boundary_nets, subpatch_nets
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.schemes.box_spline import BOX_POINTS, DEGREE, regular_patch
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE, QUAD, Lattice, lattice
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import check_bits, check_depth, check_limit, check_valence
from symdecomp.verify.bezier import (
    bspline_to_bezier,
    certify_sign,
    certify_sign_triangles,
    curve_angle,
    jacobian_net,
    triangle_jacobian_net,
)
from symdecomp.verify.c1_spectrum import SpectralResult, ball_text, round_down, spectral_conditions
from symdecomp.verify.result import C1Verdict

__all__ = ["C1Result", "c1_test", "characteristic_nets", "bezier_nets", "box_nets", "place_text", "METHOD", "method"]

#: The method, as reported with each verdict (quad meshes; :func:`method` for any lattice).
METHOD = QUAD.c1_method


def method(mesh: Lattice | str) -> str:
    """The method text for a scheme on ``mesh`` (:attr:`~symdecomp.schemes.lattice.Lattice.c1_method`)."""
    return lattice(mesh).c1_method


@dataclass(frozen=True)
class C1Result(NotebookDisplay):
    """Reif's test at one valence."""

    n: int
    scheme: str
    #: ``c1``, ``not-c1`` or ``undecided`` (:class:`~symdecomp.verify.result.C1Verdict`).
    verdict: C1Verdict
    reason: str
    spectral: SpectralResult
    #: Frequency of the subdominant eigenvalue (1 for a standard scheme).
    frequency: int | None = None
    #: ``+1`` / ``-1``: the Jacobian's certified sign; ``None`` if not certified.
    jacobian_sign: int | None = None
    #: A rigorous lower bound of ``sign * J`` over the ring (level-1 local parameters).
    jacobian_lower_bound: float | None = None
    #: Deepest de Casteljau subdivision used, and the limit.
    subdivision_depth: int | None = None
    max_depth: int = 6
    winding_number: int | None = None
    #: Working precision (bits) of the balls.
    precision: int = 64
    lattice: Lattice = QUAD

    @property
    def mesh(self) -> str:
        """The lattice's name."""
        return self.lattice.name

    def as_json(self) -> dict:
        lam = self.spectral.subdominant
        return {
            "n": self.n,
            "scheme": self.scheme,
            "verdict": self.verdict,
            "reason": self.reason,
            "lambda": None if lam is None else float(lam.value.real.mid()),
            "frequency": self.frequency,
            "gap": self.spectral.gap,
            "jacobian_sign": self.jacobian_sign,
            "jacobian_lower_bound": self.jacobian_lower_bound,
            "subdivision_depth": self.subdivision_depth,
            "max_depth": self.max_depth,
            "winding_number": self.winding_number,
            "precision_bits": self.precision,
            "method": self.lattice.c1_method,
        }


#: The lattice map of each of :data:`TRIANGLES` from the patch's own triangle ``(0, 0), (1, 0), (0, 1)``:
#: ``(origin, image of (1, 0), image of (0, 1))`` as steps. The outer two are translations, the middle one is a
#: rotation by 60 degrees (``(1, 0) -> (0, 1)``, ``(0, 1) -> (-1, 1)``: it permutes the three lattice directions and
#: has determinant +1, a symmetry of the box spline that keeps the Jacobian's sign and size).
_TRIANGLE_MAPS = tuple((t[0], (t[1][0] - t[0][0], t[1][1] - t[0][1]), (t[2][0] - t[0][0], t[2][1] - t[0][1])) for t in TRIANGLES)


@lru_cache(maxsize=1)
def _box_terms() -> tuple[tuple[tuple[int, flint.fmpq], ...], ...]:
    """The regular patch's Bezier coefficients as FLINT rationals: per coefficient ``((control point, weight), ...)``.

    :meth:`~symdecomp.schemes.box_spline.RegularPatch.bezier_net` on balls, with the exact weights converted once.
    """
    rows = regular_patch().coefficients
    return tuple(tuple((i, to_fmpq(row[k])) for i, row in enumerate(rows) if row[k]) for k in range(len(rows[0])))


def _triangle_nets(vec):
    """The degree-4 Bezier nets ``(x, y)`` of sector 0's three box-spline sub-patches (each in its own parameters)."""
    return [([z.real for z in net], [z.imag for z in net]) for net in box_nets(subpatch_nets(vec))]


def box_nets(values, triangles=TRIANGLES) -> list:
    """The degree-4 Bezier nets (complex balls) of the box-spline sub-patches ``triangles`` (corners, counter-clockwise).

    ``values``: for each triangle (default :data:`TRIANGLES`, the three of one face), ``{lattice point: value}`` on its 12
    :func:`~symdecomp.analysis.characteristic.triangle_patch_points`; each net is in its triangle's own
    parameters (``bezier_indices(4)`` order), as :func:`characteristic_nets` gives them.
    """
    out = []
    maps = _TRIANGLE_MAPS if triangles == TRIANGLES else tuple(
        (t[0], (t[1][0] - t[0][0], t[1][1] - t[0][1]), (t[2][0] - t[0][0], t[2][1] - t[0][1])) for t in triangles)
    for triangle, (o, e1, e2) in zip(values, maps):
        control = [triangle[(o[0] + a * e1[0] + b * e2[0], o[1] + a * e1[1] + b * e2[1])] for a, b in BOX_POINTS]
        net = []
        for terms in _box_terms():
            total = control[terms[0][0]] * terms[0][1]
            for i, w in terms[1:]:
                total = total + control[i] * w
            net.append(total)
        out.append(net)
    return out


def characteristic_nets(scheme: Scheme, n: int, spectral: SpectralResult | None = None):
    """The Bezier nets ``(x, y)`` of sector 0's three sub-patches, and the eigenvector they come from.

    Quads: ``4 x 4`` tensor nets; triangles: 15 coefficients in ``bezier_indices(4)`` order.
    """
    spectral = spectral or spectral_conditions(scheme, n)
    lam = spectral.subdominant
    vec = frequency_eigenvector(scheme, n, lam.frequency, lam.value)
    return _patches(scheme.lattice).nets(vec), vec


def _quad_nets(vec):
    """The bicubic Bezier nets ``(x, y)`` of sector 0's three B-spline sub-patches."""
    nets = []
    for net in subpatch_nets(vec):
        x = bspline_to_bezier([[z.real for z in row] for row in net])
        y = bspline_to_bezier([[z.imag for z in row] for row in net])
        nets.append((x, y))
    return nets


def _quad_boundary_angle(vec, nets):
    first, last = (bspline_to_bezier(net) for net in inner_boundary_nets(vec))
    a = curve_angle([first[0][k] for k in range(4)])  # face (1, 0), edge u = 1: (1,0) -> (1,1)
    b = curve_angle([last[i][0] for i in range(3, -1, -1)])  # face (0, 1), edge v = 1: (1,1) -> (0,1)
    return None if a is None or b is None else a + b


def _triangle_boundary_angle(vec, nets):
    # the middle triangle, in its own parameters: corner (0, 0) is the lattice point (1, 0), corner (0, 1) is (0, 1)
    x, y = nets[1]
    pos = {i: k for k, i in enumerate(bezier_indices(DEGREE))}
    edge = [pos[(DEGREE - t, 0, t)] for t in range(DEGREE + 1)]
    return curve_angle([flint.acb(x[k], y[k]) for k in edge])


@dataclass(frozen=True)
class _Patches:
    """How the C1 test reads the characteristic ring's sub-patches on one lattice."""

    #: ``vec -> [(x, y), ...]``: the Bezier nets of sector 0's three sub-patches.
    nets: Callable
    #: ``(nets, max_depth) -> sign``: the Jacobian's sign over them, certified.
    sign: Callable
    #: ``(vec, nets) -> angle``: the argument swept by sector 0's inner boundary (or ``None``).
    boundary_angle: Callable


_PATCHES = {
    BICUBIC: _Patches(_quad_nets, lambda nets, depth: certify_sign([jacobian_net(x, y) for x, y in nets], depth), _quad_boundary_angle),
    # a bisection halves a piece, a tensor split quarters it: twice the depth
    BOX_SPLINE: _Patches(
        _triangle_nets,
        lambda nets, depth: certify_sign_triangles([triangle_jacobian_net(x, y) for x, y in nets], DEGREE, 2 * depth),
        _triangle_boundary_angle,
    ),
}


def _patches(lat: Lattice) -> _Patches:
    return lat.select(_PATCHES, "the C1 test's sub-patches")


def bezier_nets(vec) -> list:
    """The Bezier nets ``(real part, imaginary part)`` of sector 0's three sub-patches of any ring eigenvector ``vec``.

    As :func:`characteristic_nets` for the characteristic map: ``4 x 4`` tensor nets on quads, 15
    coefficients in ``bezier_indices(4)`` order on triangles (each sub-patch in its own parameters).
    """
    return _patches(vec.lattice).nets(vec)


def place_text(where) -> str:
    """A place on the ring as a :class:`~symdecomp.verify.bezier.SignCertificate` reports it, in words."""
    return _where(where)


def _boundary_angle(vec, nets):
    """The argument swept by sector 0's inner boundary, from the image of ``a_0`` to that of ``a_1`` (or ``None``)."""
    return _patches(vec.lattice).boundary_angle(vec, nets)


def _winding(vec, n: int, nets):
    """The winding number (an ``int``) of the inner boundary, or ``None`` if not decided (``nets``: the sub-patches')."""
    angle = _boundary_angle(vec, nets)
    if angle is None:
        return None
    w = angle * n / (2 * flint.arb.pi())
    lo, hi = math.ceil(float(w.lower())), math.floor(float(w.upper()))
    return lo if lo == hi else None


def _where(where) -> str:
    """Where a sign change was found: a sub-patch and its parameter box (quads) or triangle (triangles)."""
    p, *rest = where
    if len(rest) == 2:
        ur, vr = rest
        return f"sub-patch {p}, u in [{ur[0]:g}, {ur[1]:g}], v in [{vr[0]:g}, {vr[1]:g}]"
    return f"sub-patch {p}, triangle " + ", ".join(f"({u:g}, {v:g})" for u, v in rest[0])


def _test(scheme: Scheme, n: int, max_depth: int, prec: int) -> C1Result:
    spectral = spectral_conditions(scheme, n)
    base = dict(n=n, scheme=scheme.name, spectral=spectral, max_depth=max_depth, precision=prec, lattice=scheme.lattice)
    if spectral.status is not C1Verdict.C1:
        return C1Result(verdict=spectral.status, reason=spectral.reason, **base)
    j = spectral.subdominant.frequency
    nets, vec = characteristic_nets(scheme, n, spectral)
    sign = _patches(scheme.lattice).sign(nets, max_depth)
    winding = _winding(vec, n, nets)
    base.update(frequency=j, subdivision_depth=sign.depth, winding_number=winding)
    lam = ball_text(spectral.subdominant.value)
    if sign.status == "changes":
        return C1Result(verdict=C1Verdict.NOT_C1, reason=f"the Jacobian of the characteristic map changes sign ({_where(sign.where)}): "
                        "it is not regular", **base)
    if sign.status == "undecided":
        return C1Result(verdict=C1Verdict.UNDECIDED, reason=f"the Jacobian's sign is not certified at subdivision depth "
                        f"{sign.depth} and {prec} bits (a deeper subdivision or more precision would decide)", **base)
    s = 1 if sign.status == "positive" else -1
    base.update(jacobian_sign=s, jacobian_lower_bound=sign.lower_bound)
    if winding is None:
        return C1Result(verdict=C1Verdict.UNDECIDED, reason="the winding number of the inner boundary is not certified", **base)
    if winding == s:
        return C1Result(verdict=C1Verdict.C1, reason=f"lambda = {lam} (frequency {j}, gap >= {round_down(spectral.gap)}); the "
                        f"characteristic map is regular (|J| >= {round_down(sign.lower_bound)}) and winds once: injective", **base)
    if abs(winding) > 1:
        return C1Result(verdict=C1Verdict.NOT_C1, reason=f"the characteristic map (lambda = {lam} at frequency {j}) is regular but "
                        f"winds {winding} times around the origin: it is not injective", **base)
    return C1Result(verdict=C1Verdict.UNDECIDED, reason=f"winding number {winding} does not match the Jacobian's sign {s}", **base)


def c1_test(scheme: Scheme, n: int, *, max_depth: int = 6, prec: int = 64) -> C1Result:
    """Reif's test at valence ``n`` (see the module docstring); retried once at twice the precision if undecided.

    ``max_depth``: the deepest subdivision of the Jacobian's nets, ``0..MAX_DEPTH`` (12); ``prec``: bits of the
    balls, ``16..MAX_BITS`` (65536; :mod:`symdecomp.validate`).
    """
    check_scheme(scheme)
    n = check_limit(check_valence(n), "c1_test(n)", "valence n")
    max_depth, prec = check_depth(max_depth), check_bits(prec)
    with flint.ctx.workprec(prec):
        result = _test(scheme, n, max_depth, prec)
    if result.verdict is C1Verdict.UNDECIDED:
        with flint.ctx.workprec(2 * prec):
            result = _test(scheme, n, max_depth, 2 * prec)
    return result
