"""OpenSubdiv against the toolkit at boundary, corner, crease and dart vertices (issue 20, item 6).

For a :class:`SharpCase` (scheme, kind of vertex, ``k`` faces per sector, sharpness, boundary
interpolation, creasing method) the toolkit's exact one-step matrix
(:func:`symdecomp.schemes.sector.exact_sharp_matrix`) is compared at every refinement level until
a semi-sharp crease has decayed with OpenSubdiv's (:func:`symdecomp.verify.opensubdiv.sharp.osd_sharp_ring`
on the same tagged fan, doubles):

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
:data:`TOLERANCE` (1e-12). While a semi-sharp crease has not decayed, OpenSubdiv's limit and tangent
masks are those of the crease rule of that level (its ``Limit`` takes the level's rule), not the
limit of the surface: those rows are reported with their numbers and marked not comparable, and
the limit point (the patch table refines the crease away) is the check of the true limit there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from symdecomp.errors import InvalidInputError
from symdecomp.schemes.lattice import lattice_of_reference
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.opensubdiv.sharp import OsdFan, OsdOptions, tagged_fan

__all__ = ["KINDS", "SHARPNESS", "TOLERANCE", "SharpCase", "SharpCheck", "SharpResult", "sharp_cases", "compare_sharp_case"]

#: The kinds of vertex: ``boundary`` (k faces), ``corner`` (k faces, O tagged), ``crease`` (k faces on each
#: side of a crease through O), ``dart`` (k faces around O, a crease ending at O).
KINDS = ("boundary", "corner", "crease", "dart")
#: The sharpness values of issue 20 (for creases and darts; boundary edges are infinitely sharp).
SHARPNESS = (Fraction(0), Fraction(1, 2), Fraction(1), Fraction(5, 2), math.inf)
#: Largest disagreement accepted (weights are at most 1 in size: absolute = relative).
TOLERANCE = 1e-12


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


@dataclass(frozen=True)
class SharpCheck:
    """One comparison: its name, the largest disagreement, whether it counts towards the verdict."""

    name: str
    disagreement: float
    comparable: bool = True
    note: str = ""

    @property
    def agrees(self) -> bool:
        return not self.comparable or self.disagreement <= TOLERANCE


@dataclass(frozen=True)
class SharpResult:
    """The checks of one case at one refinement level."""

    case: SharpCase
    level: int
    checks: tuple

    @property
    def agrees(self) -> bool:
        return all(c.agrees for c in self.checks)

    def as_json(self) -> dict:
        s = self.case.sharpness
        return {"scheme": self.case.scheme, "kind": self.case.kind, "k": self.case.k,
                "sharpness": "inf" if s == math.inf else str(s), "boundary": self.case.boundary,
                "creasing": self.case.creasing, "level": self.level, "agrees": self.agrees,
                "checks": [{"name": c.name, "disagreement": c.disagreement, "comparable": c.comparable,
                            "agrees": c.agrees, "note": c.note} for c in self.checks]}


#: Digits of our exact matrices' values in the comparisons (the difference with a double is then exact to 1e-50).
DIGITS = 50


def _ours(case: SharpCase, level: int) -> mpmath.matrix:
    """Our exact matrix of the level (rational, or algebraic for Loop), its entries to :data:`DIGITS` digits."""
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


def _floats(m: mpmath.matrix) -> np.ndarray:
    return np.array(m.tolist(), dtype=float)


def _difference(m: mpmath.matrix, doubles: np.ndarray) -> float:
    """``max |m - doubles|`` at :data:`DIGITS` digits (each double taken exactly)."""
    with mpmath.workdps(DIGITS):
        return float(max(abs(m[r, c] - mpmath.mpf(float(doubles[r, c]))) for r in range(m.rows) for c in range(m.cols)))


def _fixed_row(m: mpmath.matrix) -> list | None:
    """The left eigenvector of eigenvalue 1 of ``m`` with sum 1 (to :data:`DIGITS` digits); None unless unique."""
    n = m.rows
    with mpmath.workdps(DIGITS):
        system = m.T - mpmath.eye(n)
        system[n - 1, :] = mpmath.ones(1, n)  # the equations are dependent (rows of m sum to 1): one gives way to the sum
        if abs(mpmath.det(system)) < mpmath.mpf(10) ** (-DIGITS // 2):
            return None
        row = mpmath.lu_solve(system, mpmath.matrix([0] * (n - 1) + [1]))
        return [row[i] for i in range(n)]


def _limit_masks(mats: list) -> list:
    """Our limit mask of the vertex at every level: stationary at the last, pulled back through the levels before."""
    last = _fixed_row(mats[-1])
    if last is None:
        return [None] * len(mats)
    masks = [last]
    with mpmath.workdps(DIGITS):
        for m in reversed(mats[:-1]):
            row = mpmath.matrix([masks[0]]) * m
            masks.insert(0, [row[0, c] for c in range(row.cols)])
    return masks


def _spectrum_distance(ours: np.ndarray, theirs: np.ndarray) -> float:
    """For every eigenvalue of either matrix, the smallest singular value of the other minus it; the largest."""
    eye = np.eye(len(ours))
    worst = 0.0
    for a, b in ((ours, theirs), (theirs, ours)):
        for lam in np.linalg.eigvals(a):
            worst = max(worst, float(np.linalg.svd(b - lam * eye, compute_uv=False)[-1]))
    return worst


def _left_spans(ours: np.ndarray, planes: int) -> tuple[np.ndarray, np.ndarray]:
    """Columns spanning our left eigenvectors (a) of the largest eigenvalues below 1 (``planes + 1`` of them
    with their multiplicities: the tangent plane of the surface, or of each side of a crease, which share
    the crease's direction) and (b) of eigenvalue 1/2 (a crease curve's tangent)."""
    values, vectors = np.linalg.eig(ours.T)
    order = np.argsort(-np.abs(values))
    rest = [i for i in order if abs(values[i] - 1) > 1e-9]
    chosen, count = [], 0
    while rest and count < planes + 1:
        top = abs(values[rest[0]])
        group = [i for i in rest if abs(abs(values[i]) - top) < 1e-9]
        chosen += group
        count += len(group)
        rest = [i for i in rest if i not in group]
    half = [i for i in order if abs(values[i] - 0.5) < 1e-9]
    return tuple(np.hstack([vectors[:, c].real, vectors[:, c].imag]) for c in (chosen, half))


def _tangent_residual(span: np.ndarray, mask: np.ndarray) -> float:
    """Relative distance of one of OpenSubdiv's derivative masks from ``span``."""
    u, sv, _ = np.linalg.svd(span, full_matrices=False)
    q = u[:, sv > 1e-9 * max(sv.max(initial=0.0), 1e-300)]
    return float(np.linalg.norm(mask - q @ (q.T @ mask)) / np.linalg.norm(mask))


def _level_checks(case: SharpCase, fan: OsdFan, level: int, ours: mpmath.matrix, mask) -> list:
    osd = fan.ring(OsdOptions(case.scheme, case.boundary, case.creasing), level)
    mine = _floats(ours)
    decayed = level >= case.levels()
    why = "" if decayed else "OpenSubdiv's Limit takes the crease rule of this level, not the decayed limit"
    checks = [SharpCheck("matrix", _difference(ours, osd.matrix)),
              SharpCheck("ring closed", float(np.max(np.abs(osd.leak)))),
              SharpCheck("spectrum", _spectrum_distance(mine, osd.matrix))]
    if mask is None:
        return checks + [SharpCheck("limit mask", math.inf, note="our eigenvalue 1 is not simple")]
    checks.append(SharpCheck("limit mask", _difference(mpmath.matrix([mask]), osd.masks[:1]), decayed, why))
    (plane, half), stationary = _left_spans(mine, 2 if case.kind == "crease" else 1), decayed and case.levels() == level
    note = "" if stationary else why or "our matrix of this level is not the stationary one"
    checks.append(SharpCheck("tangents independent", 0.0 if np.linalg.matrix_rank(osd.masks[1:], tol=1e-9) == 2 else 1.0))
    if case.kind != "dart" and (case.sharpness == math.inf or case.kind != "crease"):
        checks.append(SharpCheck("curve tangent", _tangent_residual(half, osd.masks[1]), stationary, note))
    for name, mask in (("surface tangent 1", osd.masks[1]), ("surface tangent 2", osd.masks[2])):
        checks.append(SharpCheck(name, _tangent_residual(plane, mask), stationary, note))
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
    masks = _limit_masks(mats)
    results = []
    for level, (ours, mask) in enumerate(zip(mats, masks)):
        checks = _level_checks(case, fan, level, ours, mask)
        if level == 0 and mask is not None:
            checks.append(_limit_point_check(case, fan, mask, seed))
        results.append(SharpResult(case, level, tuple(checks)))
    return results
