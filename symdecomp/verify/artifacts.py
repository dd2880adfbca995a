"""Artifact indicators at an extraordinary vertex, certified, for any scheme the C1 test reads (issue 21, item 4).

Each indicator is computed from the 2-ring matrix of :mod:`symdecomp.verify.second_order_spectrum` at one valence;
its source:

* **Density** (``lambda_1`` against the regular ``1/2``): a subdivision step scales the rings around the
  vertex by ``lambda_1`` and those of the regular mesh by ``1/2``, so ``lambda_1 < 1/2`` packs the
  refined mesh densely around the vertex and ``lambda_1 > 1/2`` leaves it sparse (Sabin, *Eigenanalysis
  and artifacts of subdivision curves and surfaces*, in Iske, Quak, Floater (eds.), *Tutorials on
  Multiresolution in Geometric Modelling*, Springer 2002, the paper's reference [17]; Peters and Reif,
  *Subdivision Surfaces*, Springer 2008, Section 5.3). Compared exactly when the ball holds ``1/2``.
* **Negative weights in the limit and tangent masks** (Sabin, ibid.: a negative weight makes the limit
  point or the tangent move against the control point, ripples in the surface): the limit-position
  mask is the left eigenvector of the frequency-0 block for eigenvalue 1, solved exactly in the
  cyclotomic field (:mod:`symdecomp.algebra.cyclotomic`); its sign is that of each class
  (``O``, then the 1-ring classes). The tangent masks (:func:`symdecomp.analysis.masks.ring_masks`) weigh the
  1-ring by ``cos`` of the direction of each point, so their sign changes by design; a weight *against*
  the direction of its point is the artifact: on quads the face points ``b_s`` (at angle
  ``(2s + 1) pi / n``) get ``Re(y_b omega^-s)`` with ``y`` the left eigenvector of ``M_1`` for
  ``lambda_1`` (``y_a = 1``), which follows the direction iff ``y_b e^{i pi/n} > 0`` (certified in Arb).
  On triangles the 1-ring holds only edge points, whose tangent weights follow their directions.
* **Curvature regime** (:mod:`symdecomp.analysis.curvature_regime`; Peters and Reif, *Shape characterization
  of subdivision surfaces: basic principles*, CAGD 21 (2004)).
* **Shape class** (Karciauskas, Peters, Reif, *Shape characterization of subdivision surfaces: case
  studies*, CAGD 21 (2004): "for generic input data, both schemes fail to converge to the hyperbolic or
  elliptic limit shape suggested by the geometry of the input mesh"): the certified shape of the central
  surface (:func:`symdecomp.verify.shape.classify_shape`) for elliptic input (the frequency-0 height,
  like ``x^2 + y^2``) and for hyperbolic input (frequency 2), and which of the two second-order parts
  dominates on fine rings (the larger of the largest frequency-0 and frequency-2 eigenvalues after
  ``lambda_1``): where the hyperbolic part dominates, convex input does not stay convex.
* **Non-uniformity of the characteristic map**: the 2-ring matrix is block-circulant, so the
  characteristic map (the eigenvectors of ``lambda_1``) is the same in every sector up to the rotation
  by ``2 pi / n``: between sectors it differs from the regular map only by the sector angle, ``2 pi / n``
  against ``2 pi / n_regular`` (reported as the ratio ``n_regular / n``). Within a sector the indicator
  is the *ring spacing ratio*, ``|phi(2, 0) - phi(1, 0)| / |phi(1, 0) - phi(0, 0)|`` of its control net
  along the sector's edge (``phi(0, 0) = 0``), 1 on the regular mesh (the characteristic map is then
  linear): above 1 the first ring is crowded towards the vertex, below 1 stretched (Sabin, ibid.,
  on the characteristic map's non-uniform parametrization; Reif's characteristic map,
  :mod:`symdecomp.analysis.characteristic`).
"""

from __future__ import annotations

from dataclasses import dataclass

import flint

from symdecomp.algebra.cyclotomic import Cyclotomic, CyclotomicField, to_acb
from symdecomp.analysis.characteristic import frequency_block, frequency_eigenvector, ring_layout
from symdecomp.analysis.display import NotebookDisplay
from symdecomp.analysis.frequency import one_ring_matrices
from symdecomp.errors import NotApplicableError, SymdecompError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.validate import cached, check_limit, check_valence
from symdecomp.verify.c1_spectrum import ball_text, exact_charpoly, exact_entry, other_frequency_eigenvalues, sibling_values
from symdecomp.verify.second_order_spectrum import CurvatureResult, dominant_part, second_order_eigenstructure
from symdecomp.verify.shape import classify_shape

__all__ = ["ArtifactIndicators", "artifact_indicators", "compare_exactly"]


@dataclass(frozen=True)
class ArtifactIndicators(NotebookDisplay):
    """The artifact indicators at one valence (module docstring for each one's source)."""

    n: int
    #: The curvature regime and the second-order eigenstructure.
    curvature: CurvatureResult
    #: The sign of ``lambda_1 - 1/2`` (``None``: undecided): ``-1`` dense, ``0`` regular, ``1`` sparse.
    density: int | None
    #: The classes of the limit-position mask with negative weight (``"O"``, ``"1,0"``, ...; empty: none).
    negative_position: tuple[str, ...]
    #: Whether a tangent-mask weight lies against its point's direction (``None``: undecided; ``False`` on triangles).
    tangent_against: bool | None
    #: ``|phi(2, 0) - phi(1, 0)| / |phi(1, 0)|`` of the characteristic map's net (1 on the regular mesh).
    spacing: flint.arb | None
    #: ``n_regular / n``: the sector angle of the characteristic map against the regular one.
    sector_angle: float
    #: The shape class of the central surface for elliptic and for hyperbolic input (:data:`symdecomp.verify.shape.KINDS`,
    #: or ``'not applicable'``), and the frequency (0, 2) of the part that dominates on fine rings (``None``: a tie or undecided).
    shape: tuple[str, str, int | None] = ("not applicable", "not applicable", None)

    @property
    def shape_text(self) -> str:
        elliptic, _, dominant = self.shape
        return elliptic + {0: "", 2: ", hyperbolic part dominates", None: ""}[dominant]

    @property
    def density_text(self) -> str:
        return {-1: "dense", 0: "regular", 1: "sparse", None: "undecided"}[self.density]

    @property
    def masks_text(self) -> str:
        parts = [f"limit mask: {', '.join(self.negative_position)}" if self.negative_position else ""]
        if self.tangent_against is None:
            parts.append("tangent mask: undecided")
        elif self.tangent_against:
            parts.append("tangent mask: face points")
        return "; ".join(p for p in parts if p) or "none"

    def as_json(self) -> dict:
        return {
            "n": self.n, "density": self.density_text, "negative_weights": self.masks_text,
            "negative_position_classes": list(self.negative_position), "tangent_weights_against_direction": self.tangent_against,
            "ring_spacing_ratio": None if self.spacing is None else ball_text(self.spacing, 8),
            "sector_angle_ratio": self.sector_angle, "curvature": self.curvature.as_json(),
            "shape": {"text": self.shape_text, "elliptic_input": self.shape[0], "hyperbolic_input": self.shape[1],
                      "dominant_frequency": self.shape[2]},
        }


def compare_exactly(ball: flint.acb, poly: tuple | None, siblings: list, target: Cyclotomic) -> int | None:
    """The sign of ``ball - target`` for a real root (``ball``) of ``x^k + poly_1 x^(k-1) + ..``; exact on a tie.

    A tie is shown when ``target`` is a root of the polynomial (exactly) and no other root's ball
    (``siblings``) meets ``target``'s ball; ``None`` when neither the balls nor the exact test decide.
    """
    t = to_acb(target, max(flint.ctx.prec, 64)).real
    x = ball.real
    if x < t:
        return -1
    if x > t:
        return 1
    if poly is None:
        return None
    value = sum((c * target ** (len(poly) - 1 - i) for i, c in enumerate(poly)), target ** len(poly))
    if value == 0 and all(not s.overlaps(flint.acb(t)) for s in siblings):
        return 0
    return None


def _position_signs(scheme: Scheme, n: int) -> tuple[str, ...]:
    """The classes whose limit-position weight is negative, exactly (``y (E_0 - I) = 0``, ``y_O = 1``)."""
    E0 = [[exact_entry(x, n) for x in row] for row in one_ring_matrices(scheme)[1].tolist()]
    k = len(E0)
    A = [[E0[r][c] - (1 if r == c else 0) for c in range(k)] for r in range(k)]
    # y = (1, z): sum_r y_r A[r][c] = 0 for every c; solve for z on columns where the (k-1) x (k-1) system is regular
    rows = range(1, k)
    for cols in ([[0], [1]] if k == 2 else [[0, 1], [0, 2], [1, 2]]):
        sub = [[A[r][c] for r in rows] for c in cols]
        rhs = [-A[0][c] for c in cols]
        det = sub[0][0] if k == 2 else sub[0][0] * sub[1][1] - sub[0][1] * sub[1][0]
        if det == 0:
            continue
        z = [rhs[0] / det] if k == 2 else [(rhs[0] * sub[1][1] - sub[0][1] * rhs[1]) / det,
                                           (sub[0][0] * rhs[1] - rhs[0] * sub[1][0]) / det]
        y = [E0[0][0].field(1), *z]
        total = sum(y[1:], y[0])
        names = ["O", *(f"{u},{v}" for u, v in ring_layout(scheme.lattice).labels[: k - 1])]
        return tuple(name for name, w in zip(names, y) if _negative(w / total))
    raise NotApplicableError(f"n = {n}: the eigenvalue 1 of the frequency-0 block is not simple; no limit-position mask")


def _negative(w: Cyclotomic) -> bool:
    ball = to_acb(w, 128).real
    if ball < 0:
        return True
    if ball >= 0 or w == 0:
        return False
    raise NotApplicableError(f"a limit-mask weight {ball_text(ball)} could not be given a sign")  # pragma: no cover


def _tangent_against(scheme: Scheme, n: int, lam: flint.acb) -> bool | None:
    """Whether the face points' tangent weights lie against their directions (quads; triangles: ``False``)."""
    if ring_layout(scheme.lattice).one_ring < 2:
        return False
    M = frequency_block(scheme, n, 1, rows=2)
    # y M = lambda y with y = (1, y_b): column 0 gives m00 + y_b m10 = lambda, column 1 m01 + y_b m11 = lambda y_b
    y_b = (lam - M[0, 0]) / M[1, 0] if M[1, 0] != 0 else M[0, 1] / (lam - M[1, 1])
    rho = y_b * flint.acb(flint.arb(flint.fmpq(1, n))).exp_pi_i()
    if rho.real < 0:
        return True
    return False if rho.real > 0 else None


@cached(maxsize=512, n=check_valence)
def _indicators(scheme: Scheme, n: int) -> ArtifactIndicators:
    curvature = second_order_eigenstructure(scheme, n)
    density = tangent = spacing = None
    if curvature.lambda1 is not None:
        with flint.ctx.workprec(128):
            lam = curvature.lambda1
            j = curvature.lambda1_frequency
            poly = exact_charpoly(scheme, n, j)
            field = CyclotomicField(2 * n)
            inner = other_frequency_eigenvalues(scheme, n, outer=False)[0]
            dom = max((e for e in inner if e.frequency == j), key=lambda e: abs(e.value).mid())
            density = compare_exactly(lam, poly, sibling_values(inner, dom), field(flint.fmpq(1, 2)))
            tangent = _tangent_against(scheme, n, lam)
            values = frequency_eigenvector(scheme, n, j, lam).values
            spacing = abs(values[(2, 0)] - values[(1, 0)]) / abs(values[(1, 0)])
    negative = _position_signs(scheme, n)
    return ArtifactIndicators(n, curvature, density, negative, tangent, spacing, scheme.lattice.regular_valence / n,
                              _shape(scheme, n, curvature))


def _kind(scheme: Scheme, n: int, elliptic: int, hyperbolic: int) -> str:
    try:
        return classify_shape(scheme, n, elliptic=elliptic, hyperbolic=hyperbolic).kind
    except SymdecompError:  # no characteristic map or no second-order part to classify: the reason is the regime's
        return "not applicable"


def _shape(scheme: Scheme, n: int, curvature: CurvatureResult) -> tuple[str, str, int | None]:
    if curvature.lambda1 is None:
        return ("not applicable", "not applicable", None)
    return (_kind(scheme, n, 1, 0), _kind(scheme, n, 0, 1), dominant_part(curvature))


def artifact_indicators(scheme: Scheme, n: int) -> ArtifactIndicators:
    """The artifact indicators at valence ``n`` (module docstring); :class:`~symdecomp.errors.NotApplicableError`
    for schemes outside the C1 test (:mod:`symdecomp.verify.second_order_spectrum`).

    >>> from symdecomp.schemes.scheme import catmull_clark
    >>> a = artifact_indicators(catmull_clark(), 3)
    >>> a.density_text, a.masks_text, a.curvature.regime.value
    ('dense', 'none', 'zero')
    """
    n = check_scheme(scheme).fitting_valence(check_limit(check_valence(n), "artifact_indicators(n)", "valence n"))
    return _indicators(scheme, n)

