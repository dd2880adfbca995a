"""The characteristic map of a dual scheme with the biquadratic regular part, regular and injective for every ``n >= N0``.

The uniform argument of :mod:`symdecomp.verify.c1_uniform`, written for the ring of biquadratic patches of the dual
test (:mod:`symdecomp.verify.c1_dual`):

* **The eigenvector for every n.** On the neighbourhood of the dual test (ring depth
  :data:`~symdecomp.verify.zoo_characteristic.C1_DEPTH`), the rows of the outer classes are the regular rules: their
  blocks ``A_d`` by sector offset ``d`` are read at ``N0`` (:data:`~symdecomp.analysis.zoo_structure.READ_AT`) and
  checked exactly at the next two valences, as the structural form is (:mod:`symdecomp.analysis.zoo_structure`). With
  ``lambda_1`` a rational constant (the ``n``-gon's symbol at frequency 1), the frequency-1 eigenvector is the ``n``-gon's
  Fourier mode (1 at corner 0) and, on the outer classes, ``x = (lambda_1 I - B(omega))^(-1) C(omega)``, solved exactly:
  where ``det(lambda_1 I - B(omega))`` is a nonzero constant its entries are Laurent polynomials in ``omega``.
* **Stretched nets in t.** A Laurent polynomial ``sum a_k omega^k`` is ``X(t) + i s Y(t)`` with ``t = cos(2 pi/n)``,
  ``s = sin(2 pi/n)``, ``X = sum a_k T_|k|(t)``, ``Y = sum a_k sign(k) U_(|k|-1)(t)`` (Chebyshev polynomials):
  ``(X, Y)`` is the map stretched by ``1/s`` across the real axis, its Jacobian the true one over ``s > 0``.
* **Regular**: every Bezier coefficient of the Jacobian of sector 0's patches (the ring's patches are its rotations)
  is a polynomial in ``t``, positive on ``[t_0, 1]`` (:func:`~symdecomp.verify.c1_uniform.t_lower_bound`; Sturm
  sequences in FLINT). **Injective**: sector 0's inner boundary (the patches' sides that face the hole, the hole on
  their left) is one chain from a point ``A`` on the ray of the ``n``-gon's corner 0 to ``omega A`` (exact identities
  of its end points), and its control points lie in the closed wedge between the rays of corners 0 and 1
  (``Y >= 0``, ``X - t Y >= 0``), none at 0 (``X^2 + (1 - t^2) Y^2 > 0``): with its rotations the boundary closes
  counter-clockwise, each sector's piece sweeping ``2 pi/n``: it winds once, the sign of the Jacobian.

The patches' grids and their orbit labels are read from the engine's mesh at ``N0``; the neighbourhood of a sector is
the same at every larger ``n``. Below ``N0`` the valences are certified one by one.
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.interval_signs import positive_on
from symdecomp.analysis.zoo_matrix import ZooMatrix
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify.c1_uniform import UniformMapResult, t_lower_bound

__all__ = ["DualRing", "dual_ring", "jacobian_coefficients", "dual_uniform_map"]

T = sp.Symbol("t")
#: A 3 x 3 net of polynomials in ``t``.
Net = tuple[tuple[flint.fmpq_poly, ...], ...]
#: A side of a bicubic net: its control points ``(X, Y)``.
Piece = list[tuple[flint.fmpq_poly, flint.fmpq_poly]]


@dataclass(frozen=True)
class DualRing:
    """Sector 0's patches of the characteristic ring for every ``n >= first``, as stretched nets in ``t``."""

    #: The valence the blocks are read at (and the first one covered).
    first: int
    #: ``det(lambda_1 I - B(omega))``: a nonzero rational.
    scale: sp.Rational
    #: Per patch of sector 0: the ``3 x 3`` control nets ``X`` and ``Y`` (``fmpq_poly`` in ``t``) and its hole sides.
    patches: tuple[tuple[Net, Net, tuple[str, ...]], ...]
    #: The eigenvector by class (the engine's classes), Laurent polynomials in ``omega``: ``x_c omega^s`` at ``(s, c)``.
    eigenvector: tuple[sp.Expr, ...] = ()


def _outer_rows(scheme: StencilScheme, n: int) -> tuple[dict[int, sp.Matrix], ZooMatrix, int]:
    """``({d: A_d[1:, :]}, mesh data)`` of the engine's matrix at ``n`` on the dual test's neighbourhood."""
    from symdecomp.analysis.zoo_blocks import zoo_blocks
    from symdecomp.analysis.zoo_matrix import zoo_matrix
    from symdecomp.verify.zoo_characteristic import C1_DEPTH

    zm = zoo_matrix(scheme, n, C1_DEPTH)
    blocks = zoo_blocks(zm)
    rows = {d: A[1:, :] for d, A in blocks.offsets.items() if any(x != 0 for x in A[1:, :])}
    return rows, zm, blocks.class_count


def _in_t(expr: sp.Expr) -> tuple[flint.fmpq_poly, flint.fmpq_poly]:
    """``sum a_k omega^k`` as ``(X, Y)``, value ``X + i s Y`` (module docstring)."""
    X, Y = sp.Integer(0), sp.Integer(0)
    for term in sp.Add.make_args(sp.expand(expr)):
        a, k = term.as_coeff_exponent(OMEGA)
        if a.has(OMEGA) or not a.is_Rational or not k.is_Integer:
            raise NotApplicableError(f"an eigenvector entry {expr} is not a Laurent polynomial in omega with rational coefficients")
        k = int(k)
        X += a * sp.chebyshevt(abs(k), T)
        Y += a * sp.sign(k) * (sp.chebyshevu(abs(k) - 1, T) if k else 0)
    return tuple(flint.fmpq_poly([flint.fmpq(int(c.p), int(c.q)) for c in reversed(sp.Poly(P, T).all_coeffs())])  # type: ignore[return-value]
                 for P in (X, Y))


def dual_ring(scheme: StencilScheme, lam: sp.Expr, first: int) -> DualRing:
    """Sector 0's stretched nets for every ``n >= first`` (module docstring); :class:`NotApplicableError` where the
    argument does not apply (``lambda_1`` not a rational constant, a singular or varying ``det``, blocks that change)."""
    from symdecomp.analysis.zoo_blocks import signed_offset
    from symdecomp.verify.c1_dual import DualNeighbourhood, ring_patches

    if not sp.sympify(lam, strict=True).is_Rational:
        raise NotApplicableError(f"lambda_1 = {lam} is not a rational constant: the eigenvector is not solved for every n here")
    rows, zm, K = _outer_rows(scheme, first)
    for n in (first + 1, first + 2):
        later = _outer_rows(scheme, n)[0]
        if set(later) != set(rows) or any(sp.Matrix(later[d] - rows[d]).is_zero_matrix is not True for d in rows):
            raise NotApplicableError(f"the outer classes' blocks at n = {n} are not those at n = {first}")
    B = sp.zeros(K - 1, K)
    for d, A in rows.items():
        B += A * OMEGA**d
    shifted = lam * sp.eye(K - 1) - B[:, 1:]
    scale = sp.factor(shifted.det())
    if scale.has(OMEGA) or scale == 0:
        raise NotApplicableError(f"det(lambda_1 I - B(omega)) = {scale} is not a nonzero constant")
    x = [sp.Integer(1)] + [sp.expand(sp.cancel(v)) for v in shifted.LUsolve(B[:, 0])]
    nb = zm.neighbourhood
    faces = tuple(tuple(f) for f in nb.mesh.faces if set(f) <= set(nb.order))
    centre = next(tuple(f) for f in nb.mesh.faces if len(f) == first)
    patches = []
    for p in ring_patches(DualNeighbourhood(faces, centre, dict(nb.labels))):
        if nb.labels[p.vertex][0] != 0:
            continue
        nets = [[_in_t(x[nb.labels[v][1]] * OMEGA ** signed_offset(nb.labels[v][0], first)) for v in row] for row in p.grid]
        patches.append((tuple(tuple(a for a, _ in row) for row in nets), tuple(tuple(b for _, b in row) for row in nets),
                        p.hole_sides))
    return DualRing(first, scale, tuple(patches), tuple(x))


def _from_ray_to_rotated_ray(pieces: list[Piece]) -> bool:
    """Whether sector 0's boundary pieces (control points ``(X, Y)``, the hole on their left) join into one chain from a
    point ``A = X_A`` on the real axis (``Y_A = 0``) to ``omega A`` (``X = t X_A``, ``Y = X_A``), exactly: the rotated
    copies then close the boundary counter-clockwise, sector after sector."""
    t = flint.fmpq_poly([0, 1])
    piece = next((p for p in pieces if not any(q[-1] == p[0] for q in pieces)), None)
    chain: list[Piece] = []
    while piece is not None and len(chain) < len(pieces):
        chain.append(piece)
        piece = next((p for p in pieces if p[0] == chain[-1][-1]), None)
    if len(chain) != len(pieces) or piece is not None:
        return False
    (xa, ya), (xb, yb) = chain[0][0], chain[-1][-1]
    return bool(ya.is_zero() and xb == t * xa and yb == xa)


def jacobian_coefficients(ring: DualRing) -> list[flint.fmpq_poly]:
    """The Bezier coefficients of the Jacobian of sector 0's patches (raised to bicubic), polynomials in ``t``."""
    from symdecomp.verify.bezier import jacobian_net
    from symdecomp.verify.c1_dual import biquadratic_to_bicubic

    out: list[flint.fmpq_poly] = []
    for X, Y, _ in ring.patches:
        net = jacobian_net(biquadratic_to_bicubic(X), biquadratic_to_bicubic(Y))  # type: ignore[no-untyped-call]  # bezier's nets are untyped
        out += [c for row in net for c in row]
    return out


def dual_uniform_map(scheme: StencilScheme, lam: sp.Expr, first: int) -> UniformMapResult:
    """Regularity and injectivity of the characteristic map for every ``n >= first`` (module docstring); ``open`` with the
    part that is not shown."""
    from symdecomp.verify.c1_dual import _SIDES, biquadratic_to_bicubic

    low = t_lower_bound(first)
    try:
        ring = dual_ring(scheme, lam, first)
    except NotApplicableError as exc:
        return UniformMapResult("open", first, low, (str(exc),), 0)
    t = flint.fmpq_poly([0, 1])
    coefficients = jacobian_coefficients(ring)
    pieces: list[Piece] = []
    for X, Y, sides in ring.patches:
        x, y = biquadratic_to_bicubic(X), biquadratic_to_bicubic(Y)
        pieces += [list(zip(_SIDES[side](x), _SIDES[side](y))) for side in sides]
    points = [p for piece in pieces for p in piece]
    interval = f"t = cos(2 pi/n) in [{low}, 1] (every n >= {first}, and the limit n -> oo at t = 1)"
    bad = next((k for k, c in enumerate(coefficients) if not positive_on(c, low, 1)), None)
    if bad is not None:
        return UniformMapResult("open", first, low, (f"Bezier coefficient {bad} of the Jacobian is not shown positive for "
                                                     f"{interval} (no subdivision is tried)",), bad)
    in_wedge = _from_ray_to_rotated_ray(pieces) and all(
        positive_on(b, low, 1, strict=False) and positive_on(a - t * b, low, 1, strict=False)
        and positive_on(a * a + (1 - t * t) * b * b, low, 1) for a, b in points)
    facts = (
        f"the frequency-1 eigenvector for every n >= {first}: the n-gon's Fourier mode and (lambda_1 I - B(omega))^(-1) "
        f"C(omega) on the outer classes, det(lambda_1 I - B(omega)) = {ring.scale} (blocks read at n = {first}, checked "
        f"at n = {first + 1}, {first + 2}): Laurent polynomials in omega",
        f"all {len(coefficients)} Bezier coefficients of the Jacobian of sector 0's biquadratic patches (raised to bicubic, "
        f"stretched by 1/sin(2 pi/n)) are positive polynomials in t on [{low}, 1] (Sturm sequences): the characteristic map "
        f"is regular for every n >= {first}",
        f"sector 0's inner boundary runs from a point A on the ray of the n-gon's corner 0 to omega A, and its "
        f"{len(points)} control points lie in the closed wedge between the rays of corners 0 and 1, none at 0, for every t "
        f"in [{low}, 1]: each sector's piece sweeps 2 pi/n, the boundary winds once, the map is injective"
        if in_wedge else "the inner boundary's control points are not shown to lie in sector 0's wedge: injectivity open",
    )
    return UniformMapResult("proved" if in_wedge else "open", first, low, facts, len(coefficients) + len(points))

