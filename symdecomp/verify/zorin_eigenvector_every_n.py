"""The frequency-1 eigenvector on the neighbourhood Zorin's test reads, for every valence: the map part's first piece.

Zorin's test at one valence (:mod:`symdecomp.verify.c1_zorin`) solves the subdominant eigenvector of a primal scheme
of the zoo on the neighbourhood of depth :func:`~symdecomp.verify.c1_zorin.net_depth` (4 for the modified butterfly)
and grows and refines it by the regular rules. For the map part of C1 for every ``n`` that eigenvector is needed in
closed form, as the dual schemes have it (:mod:`symdecomp.verify.c1_dual_uniform`):

* **The block for every n.** The frequency blocks on that neighbourhood are read once
  (:func:`~symdecomp.analysis.zoo_structure.zoo_structure` at that depth: read at ``N0``, checked exactly against the
  explicit matrices at two more valences); each centre family's symbol is put in at frequency 1 (``sigma(1)``, a
  closed form in ``n``), which gives ``B_1(omega)``, its entries Laurent polynomials in ``omega = exp(2 pi i/n)``.
* **The eigenvector.** ``lambda_1`` is the spectral steps' (:func:`~symdecomp.verify.c1_zorin_every_n.zorin_lambda_one`,
  derived from ``det(x I - B_1)``), here a rational constant. With ``x_0 = 1`` (class 0: the first ring's point on the
  start spoke), the other classes are ``x' = (lambda_1 I - B')^(-1) b``, ``B'`` the block without class 0 and ``b`` its
  column 0, solved exactly; where ``det(lambda_1 I - B')`` is a nonzero constant (it is for the modified butterfly: the
  block is triangular, an interpolatory scheme's) they are Laurent polynomials in ``omega``, the same for every ``n``,
  and class 0's row holds as an identity in ``omega``. The eigenvalue is then simple in the block at every ``n``
  (``x'`` is forced), and the control point of label ``(s, c)`` is ``omega^s x_c``, as the per-valence route has it
  (:func:`~symdecomp.verify.zoo_characteristic.characteristic_points`).
* **Stretched, in t.** A Laurent polynomial ``sum a_k omega^k`` is ``X(t) + i s Y(t)`` with ``t = cos(2 pi/n)``,
  ``s = sin(2 pi/n)`` (Chebyshev polynomials, :func:`~symdecomp.verify.c1_dual_uniform.dual_ring`'s convention): the
  net stretched by ``1/s`` across the real axis. At ``t = 1`` (the limit ``n -> oo``) ``X = sum a_k``,
  ``Y = sum k a_k``: the stretched net of the limit.

:func:`holds_at` checks the closed form against the explicit matrix at a valence exactly, in ``Q(zeta_2n)``: every
row of ``S X = lambda_1 X`` on the whole neighbourhood. What this module does not give is the rest of the map part:
the net's growth beyond the neighbourhood and the refinement's difference bounds as signs in ``t``
(:func:`remaining`); the verdict for every ``n`` stays open on those.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import flint
import sympy as sp

from symdecomp.errors import NotApplicableError
from symdecomp.schemes.stencils import N, StencilScheme
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_int, check_type

if TYPE_CHECKING:
    from symdecomp.verify.c1_zorin_every_n import FrequencyPolynomials

__all__ = ["EveryNEigenvector", "every_n_eigenvector", "holds_at", "remaining"]


@dataclass(frozen=True)
class EveryNEigenvector:
    """The frequency-1 eigenvector on Zorin's neighbourhood for every ``n >= first`` (module docstring)."""

    #: The scheme's name.
    scheme: str
    #: The first valence the block's form holds at.
    first: int
    #: The neighbourhood's ring depth.
    depth: int
    #: ``lambda_1``, a rational constant.
    value: sp.Rational
    #: ``B_1(omega)``, the frequency-1 block on the neighbourhood.
    block: sp.ImmutableMatrix
    #: ``det(lambda_1 I - B')``: a nonzero rational.
    scale: sp.Rational
    #: ``x_c`` by class, Laurent polynomials in ``omega`` with rational coefficients (``x_0 = 1``).
    eigenvector: tuple[sp.Expr, ...]

    def stretched(self, c: int, sector: int = 0) -> tuple[flint.fmpq_poly, flint.fmpq_poly]:
        """``(X(t), Y(t))`` of the control point of label ``(sector, c)``: ``omega^sector x_c = X + i s Y``."""
        from symdecomp.verify.c1_dual_uniform import _in_t

        return _in_t(sp.expand(self.eigenvector[c] * OMEGA**sector))

    def limit(self, c: int, sector: int = 0) -> tuple[sp.Rational, sp.Rational]:
        """The stretched control point at ``t = 1``, the limit ``n -> oo``: ``(sum a_k, sum k a_k)``."""
        x, y = self.stretched(c, sector)
        return sp.Rational(str(x(1))), sp.Rational(str(y(1)))


def _laurent_terms(v: sp.Expr) -> list[tuple[sp.Rational, int]]:
    """``[(a_k, k)]`` of ``v = sum a_k omega^k``; :class:`NotApplicableError` where ``v`` is no Laurent polynomial in
    ``omega`` with rational coefficients."""
    out = []
    for term in sp.Add.make_args(sp.expand(v)):
        a, k = term.as_coeff_exponent(OMEGA)
        if not (a.is_Rational and k.is_Integer):
            raise NotApplicableError(f"the eigenvector entry {v} is not a Laurent polynomial in omega")
        out.append((a, int(k)))
    return out


def _frequency_one_block(scheme: StencilScheme, depth: int) -> tuple[sp.Matrix, int]:
    """``(B_1(omega), first)``: the structural block on the neighbourhood of ``depth`` with ``sigma_t(1)`` put in."""
    from symdecomp.analysis.zoo_structure import zoo_structure

    st = zoo_structure(scheme, depth=depth)
    if not st.has_centre:
        raise NotApplicableError(f"scheme {scheme.name!r}: no centre vertex (a dual scheme: c1_dual_uniform)")
    sigma = {sig: sp.sympify(s.value(1), strict=True).subs(s.size, N) for sig, s in zip(st.sigma, st.symbols)}
    B = sp.Matrix(st.block).xreplace(sigma)
    if B.has(N):
        raise NotApplicableError("the frequency-1 block depends on n beyond omega: its eigenvector is not solved here")
    return B, st.valid_from


def every_n_eigenvector(scheme: StencilScheme, depth: int | None = None,
                        polys: FrequencyPolynomials | None = None) -> EveryNEigenvector:
    """The closed form for every ``n`` (module docstring) on the neighbourhood of ``depth`` (default: Zorin's test's,
    :func:`~symdecomp.verify.c1_zorin.net_depth`); :class:`~symdecomp.errors.NotApplicableError` (one line) where it does
    not apply: no ``lambda_1`` constant for every ``n``, a ``det`` that is not a nonzero constant, ``x_0 = 1`` no
    eigenvector. ``polys``: the scheme's :func:`~symdecomp.verify.c1_zorin_every_n.frequency_polynomials` where the
    caller has them already."""
    from symdecomp.verify.c1_zorin import net_depth
    from symdecomp.verify.c1_zorin_every_n import zorin_lambda_one
    from symdecomp.verify.zorin_bounds import difference_bounds

    check_type(scheme, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('modified-butterfly')")
    if depth is not None:
        depth = check_int(depth, "depth", minimum=1)
    lam = zorin_lambda_one(scheme, polys)
    if lam is None or not lam.is_Rational:
        raise NotApplicableError(f"lambda_1 = {lam} is not a rational constant for every n: the eigenvector is not solved here")
    depth = net_depth(difference_bounds(scheme)) if depth is None else depth
    B, first = _frequency_one_block(scheme, depth)
    K = B.rows
    shifted = lam * sp.eye(K - 1) - B[1:, 1:]
    scale = sp.factor(shifted.det())
    if scale.has(OMEGA) or scale == 0:
        raise NotApplicableError(f"det(lambda_1 I - B') = {scale} is not a nonzero constant")
    x = [sp.Integer(1)] + [sp.expand(sp.cancel(v)) for v in shifted.LUsolve(B[1:, 0])]
    row0 = sp.expand(lam * x[0] - sum((B[0, c] * x[c] for c in range(K)), sp.Integer(0)))
    if row0 != 0:
        raise NotApplicableError(f"x_0 = 1 does not give an eigenvector: class 0's row leaves {row0}")
    for v in x:
        _laurent_terms(v)
    return EveryNEigenvector(scheme.name, first, depth, lam, sp.ImmutableMatrix(B), scale, tuple(x))


def holds_at(ev: EveryNEigenvector, scheme: StencilScheme, n: int) -> bool:
    """Whether ``X(s, c) = omega^s x_c`` (``0`` at the centre) is an eigenvector of the explicit matrix at ``n`` for
    ``lambda_1``: every row of ``S X = lambda_1 X`` on the neighbourhood of :attr:`~EveryNEigenvector.depth`, exactly
    in ``Q(zeta_2n)`` (the matrix's cosines of ``2 pi j/n`` lie there); :class:`~symdecomp.errors.NotApplicableError`
    at a valence whose matrix has a cosine sympy wrote as radicals (``n = 5, 8, 10, 12``)."""
    from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
    from symdecomp.analysis.zoo_matrix import zoo_matrix

    n = check_int(n, "n", minimum=3)
    zm = zoo_matrix(scheme, n, ev.depth)
    field = CyclotomicField(2 * n)
    w = field.root(n, 1)
    x = []
    for v in ev.eigenvector:
        total = field(0)
        for a, k in _laurent_terms(v):
            total = total + w**k * field(a)
        x.append(total)
    nb = zm.neighbourhood
    values = [field(0) if v == nb.centre else w ** nb.labels[v][0] * x[nb.labels[v][1]] for v in nb.order]
    seen: dict[sp.Expr, object] = {}
    for i in range(len(values)):
        total = field(0)
        for j, value in enumerate(values):
            entry = zm.matrix[i, j]
            if entry != 0:
                if entry not in seen:
                    try:
                        seen[entry] = cyclotomic_value(entry, field=field)
                    except ValueError:
                        raise NotApplicableError(f"n = {n}: the matrix entry {entry} is not read in Q(zeta_{2 * n}) (sympy "
                                                 "wrote a cosine as radicals)") from None
                total = total + seen[entry] * value
        if total != values[i] * field(ev.value):
            return False
    return True


def remaining(ev: EveryNEigenvector) -> str:
    """What the map part for every ``n`` still needs after the eigenvector, in one sentence."""
    return (f"the frequency-1 eigenvector on the depth-{ev.depth} neighbourhood is derived for every n >= {ev.first} "
            f"(lambda_1 = {ev.value}, {len(ev.eigenvector)} classes, Laurent polynomials in omega, det(lambda_1 I - B') = "
            f"{ev.scale}); the net's growth beyond that neighbourhood and the refinement's difference bounds are not yet "
            "exact signs in t = cos(2 pi/n), so the characteristic map is not proved regular and injective for every n")
