"""The characteristic map of a sharp sector with many faces from the closed-form modes: a few faces per ``k``, not ``k``.

Where the blocks (:mod:`.c1_mirror_blocks`) prove ``lambda_1 = lambda_2 = 1/2``, one eigenvector in each mirror part
(Biermann-Levin-Zorin's rules), the two eigenvectors are ``Re v`` and ``Im v`` of the closed form of
:mod:`.fourier_modes`: level-1 values of their own in the faces next to ray 0, mirror images ``-conj`` next to ray
``k``, and ``G(u, w) omega^s`` (``omega = e^(i pi/k)``) in every face between. So the characteristic map
``chi = Re v + i Im v = v`` is, on the faces between, the map of one face turned by ``omega^s``, and next to ray ``k``
the mirror image ``chi(P p) = -conj(chi(p))`` of the map next to ray 0. Conditions 3-5 of :mod:`.c1_sector_matrix` are then
decided on ``g + 1`` faces only (``g`` next to ray 0 and one face ``g`` between), in Arb, with the wide ring of
:mod:`.sector_ring` (BLZ's modified edges make the level-1 patches at ``O`` non-splines):

* **regular**: a rotation keeps the Jacobian; the mirror reverses the domain's and the image's orientation, so it keeps
  the Jacobian's sign and modulus. The Jacobian's Bezier coefficients of the ``g + 1`` faces' nets decide every face
  (:func:`~symdecomp.verify.sector_ring.jacobian_sign`). That face ``g``'s nets read Fourier values only is *checked*
  while they are built (each value read is recorded), not assumed;
* **the sweeps**: the argument swept by a curve does not change under a rotation, and a mirrored curve run backwards
  sweeps the same angle, so ``Delta = 2 sum_(s < g) Delta_s + (k - 2 g) Delta_g`` for the inner and the outer arc;
  then injectivity and the corner type as in :func:`~symdecomp.verify.sector_injectivity.injective_condition`.

With ``k <= 2 g + 1`` every face is checked one by one (the same nets, no symmetry used). The values come from the
closed forms evaluated at ``tau = tan(pi/(2 k))`` in Arb: O(1) work per ``k``, where the dense route's eigenvectors
cost a solve cubic in ``k``.

>>> from symdecomp.schemes.files import load_scheme
>>> from symdecomp.schemes.sector import SharpVertex
>>> from symdecomp.verify.c1_mirror_blocks import c1_mirror_blocks
>>> r = c1_mirror_blocks(load_scheme("catmull-clark-blz"), SharpVertex.boundary(1000, "quad"))
>>> str(r.verdict), round(r.opening, 6)   # the half-disk's opening: pi
('c1', 1.0)
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction

import flint

from symdecomp.errors import NotApplicableError
from symdecomp.schemes.lattice import Lattice
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import ORIGIN
from symdecomp.verify.bezier import curve_angle
from symdecomp.verify.c1 import place_text
from symdecomp.verify.c1_spectrum import SpectralResult, round_down
from symdecomp.verify.fourier_modes import WINDOW, SectorModes, sector_modes
from symdecomp.verify.mirror_parts import block_parts, mirror_label
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_injectivity import SectorFinding, injective_condition
from symdecomp.verify.sector_ring import jacobian_sign, ring_faces, wide_arcs, wide_nets

__all__ = ["fourier_map", "FOURIER_METHOD", "applies", "REACH"]

#: How many faces to each side a face's wide-ring nets read (the ring's level-1 values and the level-0 3-ring behind the
#: regular rule): the first face between is the one ``REACH`` faces past the values of their own.
REACH = 1

#: The method, as reported with each verdict whose map this route certified.
FOURIER_METHOD = ("Zorin's conditions 1-2 from the sector's blocks (certified leading values, exact multiplicities); the "
                  "subdominant eigenvectors in closed form in tan(pi/2k) (Fourier modes between the sharp rays, derived once "
                  "from exact rows); Jacobian of the wide spline ring on the faces next to a ray and one face between "
                  "(rotations and the mirror give the rest; Arb, de Casteljau); argument swept between the two sharp rays")


@dataclass(frozen=True)
class _Sector:
    """What the nets, the Jacobian and the arcs read of a sector: its faces and lattice."""

    k: int
    lattice: Lattice


def _gaussian(z) -> tuple:
    """A Gaussian rational of sympy's ``QQ_I`` as ``(real, imaginary)`` fmpq."""
    return flint.fmpq(int(z.x.numerator), int(z.x.denominator)), flint.fmpq(int(z.y.numerator), int(z.y.denominator))


def _poly(p) -> list:
    degree = max((m[0] for m in p.monoms()), default=0)
    coeffs = [(flint.fmpq(0), flint.fmpq(0))] * (degree + 1)
    for (e,), c in p.terms():
        coeffs[e] = _gaussian(c)
    return coeffs


@functools.lru_cache(maxsize=8)
def _compiled(scheme) -> tuple[SectorModes, dict, dict]:
    """The scheme's modes and every value as ``(numerator, denominator)`` coefficient lists in ``tau`` (exact)."""
    modes = sector_modes(scheme)

    def pair(z):
        return _poly(z.numer), _poly(z.denom)

    return modes, {lab: pair(z) for lab, z in modes.near.items()}, {uv: pair(z) for uv, z in modes.fourier.items()}


def _evaluate(pair, tau: flint.acb) -> flint.acb:
    def horner(coeffs):
        out = flint.acb(0)
        for re, im in reversed(coeffs):
            out = out * tau + flint.acb(re, im)
        return out

    return horner(pair[0]) / horner(pair[1])


class _ModeValues:
    """The level-1 values ``chi`` of a ``k``-sector (3-ring, and the sharp rays 0 and ``k`` to distance 5), as a mapping;
    :attr:`special` records whether a value of its own or a mirror image was read (module docstring)."""

    def __init__(self, scheme, k: int):
        modes, near, fourier = _compiled(scheme)
        lattice = scheme.lattice
        tau = flint.acb(flint.arb.pi() / (2 * k)).tan()
        self.k, self.lattice, self.last = k, lattice, modes.depth + 1
        self.near = {lab: _evaluate(p, tau) for lab, p in near.items()}
        self.fourier = {uv: _evaluate(p, tau) for uv, p in fourier.items()}
        self.direction = 2 * self.near[(0, 1, 0)]
        self.special = False

    def __contains__(self, label) -> bool:
        if label == ORIGIN:
            return True
        s, u, w = label
        return (w == 0 and s in (0, self.k) and 1 <= u <= 5) or self.lattice.ring_of(u, w) <= 3

    def __getitem__(self, label) -> flint.acb:
        if label not in self:
            raise KeyError(label)
        if label == ORIGIN:
            return flint.acb(0)
        s, u, w = label
        if w == 0 and s in (0, self.k):  # the sharp rays: exactly linear (:mod:`.fourier_modes` checks it)
            self.special = True
            d = self.direction if s == 0 else -self.direction.conjugate()
            return d * u / 2
        if s <= self.last:
            self.special = True
            return self.near[label]
        mirror = mirror_label(label, self.k)
        if mirror[0] <= self.last:
            self.special = True
            return -self.near[mirror].conjugate()
        return self.fourier[(u, w)] * flint.acb(flint.fmpq(s, self.k)).exp_pi_i()


def applies(vertex: SharpVertex, k: int, picks: list, crease) -> bool:
    """Whether this route reads the sector: not a corner, at least :data:`WINDOW` faces, and the subdominant pair is the
    blocks' exact double ``1/2`` with one eigenvector odd (the crease block's) and one even (a sine block's)."""
    if vertex.corner or k < WINDOW or len(picks) != 2 or picks[0][1] is not picks[1][1]:
        return False
    value = picks[0][1]
    if value.key != ("q", Fraction(1, 2)):
        return False
    parts = block_parts(crease, picks)
    return parts is not None and sorted(parts) == ["even", "odd"]


def _faces_angles(sector: _Sector, nets: list, per: int, count: int) -> list:
    """``[(Delta_in, Delta_out)]`` of each of ``count`` faces (``None`` where a piece is not decided)."""
    out = []
    for f in range(count):
        inner, outer = wide_arcs(_Sector(1, sector.lattice), nets[per * f: per * (f + 1)])
        sums = []
        for curves in (inner, outer):
            angles = [curve_angle(c) for c in curves]
            sums.append(None if any(a is None for a in angles) else sum(angles, flint.arb(0)))
        out.append(tuple(sums))
    return out


def _sweeps(angles: list, k: int, explicit: bool):
    """The total sweeps from each face's (module docstring: the mirror doubles the faces next to ray 0)."""
    totals = []
    for side in (0, 1):
        parts = [a[side] for a in angles]
        if any(p is None for p in parts):
            totals.append(None)
        elif explicit:
            totals.append(sum(parts, flint.arb(0)))
        else:
            g = len(parts) - 1
            totals.append(2 * sum(parts[:g], flint.arb(0)) + (k - 2 * g) * parts[g])
    return tuple(totals)


def fourier_map(scheme, vertex: SharpVertex, k: int, spectral: SpectralResult, picks: list, max_depth: int) -> SectorFinding:
    """Conditions 3-5 in a sector of ``k`` faces from the closed-form modes (module docstring); ``NotApplicableError``
    where :func:`~.fourier_modes.sector_modes` finds no closed form."""
    lambdas = tuple(float(p[0].real.mid()) for p in picks)
    chi = _ModeValues(scheme, k)
    sector = _Sector(k, scheme.lattice)
    dirs = (chi.direction, -chi.direction.conjugate())
    if chi.direction.contains(0):
        return SectorFinding(C1Verdict.UNDECIDED, "a sharp ray's image is not shown to be non-degenerate", spectral, lambdas)
    g = chi.last + REACH + 1  # face g reads faces g - REACH .. g + REACH: Fourier values only (checked below)
    explicit = k <= 2 * g + 1
    faces = list(range(k)) if explicit else list(range(g))
    half = (flint.arb(1) / 2, flint.arb(1) / 2)
    nets = wide_nets(sector, chi, half, faces)
    if not explicit:
        chi.special = False
        nets += wide_nets(sector, chi, half, [g])
        if chi.special:
            raise NotApplicableError(f"face {g} of the sector reads values next to a sharp ray: no rotation symmetry there")
        faces.append(g)
    per = len(ring_faces(scheme.lattice))
    cert = jacobian_sign(sector, nets, max_depth)
    if cert.status == "changes":
        face = faces[cert.where[0] // per]
        return SectorFinding(C1Verdict.NOT_C1, f"the Jacobian of the characteristic map changes sign ({place_text(cert.where)}, "
                             f"face {face}, wide ring): it is not regular", spectral, lambdas, depth=cert.depth,
                             method=FOURIER_METHOD)
    if cert.status == "undecided":
        return SectorFinding(C1Verdict.UNDECIDED, f"the Jacobian's sign is not certified at subdivision depth {cert.depth}",
                             spectral, lambdas, depth=cert.depth, method=FOURIER_METHOD)
    sign = 1 if cert.status == "positive" else -1
    sweeps = _sweeps(_faces_angles(sector, nets, per, len(faces)), k, explicit)
    verdict, text, opening = injective_condition(None, vertex, sign, dirs, sweeps)
    if verdict is C1Verdict.C1:
        how = "every face" if explicit else f"faces 0..{g - 1} and {g}, the rest by rotations and the mirror"
        text = (f"{spectral.reason}; the characteristic map (closed-form modes) is regular on the ring past the modified edges "
                f"({how}; |J| >= {round_down(cert.lower_bound)}) and {text}")
    return SectorFinding(verdict, text, spectral, lambdas, sign, cert.lower_bound, cert.depth, opening, method=FOURIER_METHOD)
