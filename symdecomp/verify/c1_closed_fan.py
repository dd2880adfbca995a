"""Certified C1 at an infinitely sharp dart: Reif's test on the dart's closed fan, one ray of it sharp.

A dart is an interior vertex ``O`` of valence ``n`` where one infinitely sharp edge ends; OpenSubdiv keeps the smooth
vertex rule at ``O`` and applies the crease rules on the sharp edge. The test works on the dart's 2-ring subdivision
matrix (the one sector of :func:`~symdecomp.verify.mirror_parts.sector_matrices` for
``SharpVertex.dart(n, lattice)``, the matrix ``check --dart`` certifies), in which the points of ray ``0`` are copies of
those of ray ``n`` (checked exactly: their columns are zero, their rows and their refinement rows are ray ``n``'s). Reif's conditions
(U. Reif, *A unified approach to subdivision algorithms near extraordinary vertices*, CAGD 12, 1995):

1. *spectral*: 1 is a simple eigenvalue, the next two ``lambda_1 >= lambda_2`` are real, positive, with two
   eigenvectors, and strictly larger in modulus than every other eigenvalue. The exact 1-ring spectrum decides
   (:func:`~symdecomp.analysis.triangular_eigen.sharp_values`: rational factors, exact multiplicities, Arb balls), and the
   2-ring's other eigenvalues (:func:`~symdecomp.verify.mirror_parts.sector_eigenvalues`) are certified below
   ``|lambda_2|``;
2. *regular*: the characteristic map ``chi`` of the two subdominant eigenvectors (exact rational null space when the
   pair is one rational eigenvalue twice, else a certified null vector of the ball matrix) on the ring of ``3 n``
   bicubic sub-patches has a Jacobian of one strict sign. The sub-patches next to the sharp edge, on either side, are
   B-spline patches with the crease sectors' phantom points (:func:`~symdecomp.schemes.sector_patch.sector_net`): the
   sharp edge's points follow the cubic B-spline rules and no sub-patch of the level-1 ring reads ``O``'s new point, so
   these patches are splines of their control points. Jacobian bounds: Bernstein-Bezier coefficients in Arb with de
   Casteljau subdivision (:mod:`.bezier`, the sector test's routines);
3. *injective*: the ring is closed (ray ``0`` is ray ``n``), so a regular ``chi`` is injective iff the image of the
   ring's inner boundary winds once around the origin (and the outer one as often: no zero in the ring), the
   arguments swept certified by :func:`~symdecomp.verify.bezier.curve_angle`.

Catmull-Clark's darts of valence 3 to 8 are C1 (``tests/verify/test_c1_closed_fan.py``); at valence 4 the pair is
``1/2`` twice (the regular vertex's), elsewhere ``lambda_1`` is the smooth vertex's subdominant eigenvalue and
``lambda_2`` a new one below it. Loop's darts are tested where the dart's weights are rational (valences 3, 4, 6:
C1); at other valences the exact spectrum is out of reach and the verdict is ``undecided`` with that reason.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> str(c1_dart_test(catmull_clark(), 5).verdict)
'c1'
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.null_vector import null_vector
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.scheme import check_scheme
from symdecomp.schemes.sector import SharpVertex
from symdecomp.schemes.sector_patch import check_spline_sharp_rules
from symdecomp.validate import check_bits, check_depth, check_valence
from symdecomp.verify.c1 import place_text
from symdecomp.verify.c1_sector_matrix import SharpC1Result
from symdecomp.verify.c1_spectrum import SpectralResult, round_down
from symdecomp.verify.mirror_parts import ball_matrix, sector_eigenvalues, sector_matrices
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.sector_injectivity import SectorFinding, closed_fan_condition
from symdecomp.verify.sector_ring import arc_sweeps, jacobian_sign, level_one_map, ring_nets

__all__ = ["DART_METHOD", "DartSpectrum", "c1_dart_test", "dart_spectrum", "dart_vectors", "dart_map"]

#: The method, as reported with each verdict.
DART_METHOD = ("Reif's test on the dart's closed fan: exact spectrum of the 1-ring matrix and certified 2-ring remainder; "
               "Jacobian of the ring's bicubic sub-patches (phantom points at the sharp edge) in Bernstein-Bezier form "
               "(Arb, de Casteljau); winding number of the ring's boundary")


@dataclass(frozen=True)
class DartSpectrum:
    """The spectral conditions (condition 1) at a dart, from its exact 1-ring spectrum and its certified 2-ring."""

    #: ``c1`` when they hold, else ``not-c1`` (1 not simple and dominant) or ``undecided``.
    verdict: C1Verdict
    #: The facts, in words.
    reason: str
    #: ``lambda_1, lambda_2`` (:class:`~symdecomp.analysis.eigenvalue.Eigenvalue`; one value twice when double).
    pair: tuple = ()


def _exact_conditions(scheme, n: int) -> DartSpectrum:
    """Condition 1 on the exact 1-ring spectrum."""
    from symdecomp.analysis.spectrum import acb_text
    from symdecomp.analysis.triangular_eigen import by_modulus, merge, separated, sharp_values

    try:
        _, _, found = sharp_values(scheme, SharpVertex.dart(n, scheme.lattice))
    except NotApplicableError as exc:
        return DartSpectrum(C1Verdict.UNDECIDED, f"the dart's exact spectrum is out of reach: {exc}")
    values = by_modulus(merge(found))
    text = {v.key: acb_text(v.ball, 20) for v in values}
    top = values[0]
    if not (top.exact == 1 and top.multiplicity == 1 and separated(top, values[1])):
        return DartSpectrum(C1Verdict.NOT_C1, (
            f"the eigenvalue 1 is not simple and strictly dominant (largest modulus: {text[top.key]} of multiplicity "
            f"{top.multiplicity}, next {text[values[1].key]}): the rings do not shrink to a point"))
    first = values[1]
    pair = (first, first) if first.multiplicity >= 2 else tuple(values[1:3])
    rest = [v for v in values[1:] if v.key not in {p.key for p in pair}]
    if first.multiplicity > 2 or len(pair) < 2 or not all(p.is_real and p.exact > 0 for p in pair):
        return DartSpectrum(C1Verdict.UNDECIDED, (
            f"the subdominant eigenvalues are not a real positive pair ({text[first.key]} of multiplicity "
            f"{first.multiplicity}{'' if first.multiplicity > 1 else ', then ' + text[pair[-1].key]})"))
    if rest and not separated(pair[1], rest[0]):
        return DartSpectrum(C1Verdict.UNDECIDED, (
            f"the second eigenvalue {text[pair[1].key]} is not certified larger in modulus than the next, {text[rest[0].key]}"))
    following = f" (the next eigenvalue: {text[rest[0].key]})" if rest else ""
    return DartSpectrum(C1Verdict.C1, (f"spectral conditions of the 1-ring matrix hold: 1 simple, lambda_1 = {text[pair[0].key]}, "
                                       f"lambda_2 = {text[pair[1].key]} real, positive, strictly dominant{following}"), pair)


def dart_spectrum(scheme, n: int, sm) -> DartSpectrum:
    """Condition 1 (module docstring): the exact 1-ring spectrum, and the 2-ring's other eigenvalues below ``|lambda_2|``."""
    found = _exact_conditions(scheme, n)
    if found.verdict is not C1Verdict.C1:
        return found
    tops = [flint.acb(1), found.pair[0].ball, found.pair[1].ball]
    with flint.ctx.workprec(128):
        values = [x for x, _, _ in sector_eigenvalues(sm)]
        floor = abs(found.pair[1].ball)
        near = [x for x in values if any(x.overlaps(t) for t in tops)]
        below = [x for x in values if abs(x) < floor]
    if len(near) != 3 or len(near) + len(below) != len(values):
        return DartSpectrum(C1Verdict.UNDECIDED, f"{found.reason}; the 2-ring matrix's other eigenvalues are not certified "
                            "below lambda_2 in modulus", found.pair)
    return DartSpectrum(C1Verdict.C1, f"{found.reason}; the 2-ring's other eigenvalues certified below it", found.pair)


def dart_vectors(sm, spectrum: DartSpectrum) -> list | None:
    """The two real eigenvectors of ``lambda_1, lambda_2`` (2-ring, matrix order, Arb balls), or ``None`` if not certified.

    A rational eigenvalue twice: its exact null space, which must have dimension 2 (else the pair is defective and
    Reif's test does not apply). Otherwise each value is simple: a certified null vector of ``S - lambda I`` in Arb.
    """
    a, b = spectrum.pair
    if a.key == b.key:
        q = a.exact
        if not q.is_Rational:
            return None
        basis = (sm.matrix - q * sp.eye(sm.matrix.rows)).nullspace()
        if len(basis) != 2:
            raise NotApplicableError(f"the double eigenvalue {q} has {len(basis)} eigenvector(s): Reif's test needs two")
        return [[flint.arb(flint.fmpq(int(x.p), int(x.q))) for x in v] for v in basis]
    A = ball_matrix(sm.matrix.tolist(), sm.weight)
    out = []
    for value in (a.ball, b.ball):
        vec = null_vector(_shift(A, value))
        if vec is None:
            return None
        out.append([x.real for x in vec])
    return out


def _shift(A, value) -> flint.acb_mat:
    return flint.acb_mat([[A[r, c] - (value if r == c else 0) for c in range(A.ncols())] for r in range(A.nrows())])


def dart_map(sm, vectors, *, max_depth: int = 6) -> SectorFinding:
    """Conditions 2 and 3 (module docstring) for the dart sector ``sm`` and two real eigenvectors (``vectors``)."""
    nets = ring_nets(sm, level_one_map(sm, vectors))
    cert = jacobian_sign(sm, nets, max_depth)
    if cert.status == "changes":
        return SectorFinding(C1Verdict.NOT_C1, f"the Jacobian of the characteristic map changes sign ({place_text(cert.where)}, "
                             f"face {cert.where[0] // (len(nets) // sm.k)}): it is not regular", depth=cert.depth)
    if cert.status == "undecided":
        return SectorFinding(C1Verdict.UNDECIDED, f"the Jacobian's sign is not certified at subdivision depth {cert.depth}",
                             depth=cert.depth)
    sign = 1 if cert.status == "positive" else -1
    verdict, why, winding = closed_fan_condition(sign, arc_sweeps(sm, nets))
    reason = why if winding is None else f"the characteristic map is regular (|J| >= {round_down(cert.lower_bound)}) {why}"
    return SectorFinding(verdict, reason, sign=sign, bound=cert.lower_bound, depth=cert.depth, winding=winding)


def _check_aliases(sm) -> None:
    """Ray 0's points are ray ``n``'s (module docstring), exactly; else the ring is not the dart's closed fan."""
    index = {lab: i for i, lab in enumerate(sm.labels)}
    S = sm.matrix
    for (s, u, v), i in index.items():
        if s == 0 and v == 0 and u > 0:
            j = index[(sm.k, u, 0)]
            if any(S[r, i] != 0 for r in range(S.rows)) or S.row(i) != S.row(j):
                raise NotApplicableError(f"the dart's matrix does not identify ray 0 with ray {sm.k} at distance {u}")
    fine = {lab: i for i, lab in enumerate(sm.fine_labels)}
    for (s, u, v), i in fine.items():
        if s == 0 and v == 0 and u > 0 and sm.refine.row(i) != sm.refine.row(fine[(sm.k, u, 0)]):
            raise NotApplicableError(f"the dart's refinement does not identify ray 0 with ray {sm.k} at distance {u}")


def _result(scheme, n: int, spectrum: DartSpectrum, found: SectorFinding | None, max_depth: int, prec: int) -> SharpC1Result:
    verdict = spectrum.verdict if found is None else found.verdict
    reason = spectrum.reason if found is None else f"{spectrum.reason}; {found.reason}"
    lambdas = tuple(float(v.ball.real.mid()) for v in spectrum.pair) or None
    spectral = SpectralResult(n, spectrum.verdict, spectrum.reason)
    return SharpC1Result(
        n=n, scheme=scheme.name, verdict=verdict, reason=reason, spectral=spectral,
        jacobian_sign=None if found is None else found.sign, jacobian_lower_bound=None if found is None else found.bound,
        subdivision_depth=None if found is None else found.depth, max_depth=max_depth, precision=prec,
        lattice=scheme.lattice, vertex=f"dart n = {n}", lambdas=lambdas, method=DART_METHOD,
        winding_number=None if found is None else found.winding)


def c1_dart_test(scheme, n: int, *, max_depth: int = 6, prec: int = 64) -> SharpC1Result:
    """Reif's test at an infinitely sharp dart of valence ``n`` (module docstring); the map retried once at twice the
    precision if undecided. ``max_depth``: the deepest subdivision of the Jacobian's nets; ``prec``: bits of the balls."""
    scheme = check_scheme(scheme)
    n, max_depth, prec = check_valence(n), check_depth(max_depth), check_bits(prec)
    check_spline_sharp_rules(scheme.sharp, f"scheme {scheme.name!r}")
    sm = sector_matrices(scheme, SharpVertex.dart(n, scheme.lattice), 0)
    _check_aliases(sm)
    spectrum = dart_spectrum(scheme, n, sm)
    if spectrum.verdict is not C1Verdict.C1:
        return _result(scheme, n, spectrum, None, max_depth, prec)
    for bits in (prec, 2 * prec):
        with flint.ctx.workprec(bits):
            vectors = dart_vectors(sm, spectrum)
            found = (SectorFinding(C1Verdict.UNDECIDED, "an eigenvector is not certified") if vectors is None
                     else dart_map(sm, vectors, max_depth=max_depth))
        if found.verdict is not C1Verdict.UNDECIDED:
            return _result(scheme, n, spectrum, found, max_depth, bits)
    return _result(scheme, n, spectrum, found, max_depth, 2 * prec)

