"""The characteristic polynomial of the full subdivision matrix in closed form (Section 6, Eq. 51).

Derivation (every ingredient is computed from the scheme):

1. ``S' = Q^{-1} S Q`` (:mod:`symdecomp.analysis.reduction`) is block upper-triangular with first
   column ``(1, 0, ..., 0)``, so ``det(xI - S) = (x - 1) det(xI - L)`` with ``L`` the CB-block
   of ``S'``: the circulants ``C_pq`` minus constant blocks (``alpha J``, ``beta J``).
2. ``L`` is similar to ``diag(E_0, ..., E_{n-1})`` (Remark 6.1): ``E_k = M(omega_n^k)`` for
   ``k != 0`` (``M`` the per-frequency matrix of Eq. 33, free of the vertex weights), and
   ``E_0 = M(1) + n T`` with ``T = -[[alpha, beta], [alpha, beta]]`` (Prop. 6.3).
3. With ``q(x, w) = det(xI - M(w)) = c_-(x)/w + c_0(x) + c_+(x) w`` (Laurent degree 1 for
   stencils of offsets ``-1..1``) and ``rho_+ rho_- = c_+ c_-``, ``rho_+ + rho_- = c_0``:
   ``q(w) = (rho_+ + c_+ w)(rho_- + c_+ w)/(c_+ w)``, and ``prod_k (rho + c w_k) = rho^n - (-c)^n``
   over the n-th roots of unity ``w_k`` (from ``prod_k (y - w_k) = y^n - 1``) gives

       ``prod_{k=0}^{n-1} q(x, omega_n^k) = rho_+^n + rho_-^n - (-c_+)^n - (-c_-)^n``.

   Dividing out the ``k = 0`` factor ``q(x, 1)``:

       ``det(xI - S) = (x - 1) det(xI - E_0) (rho_+^n + rho_-^n - (-c_+)^n - (-c_-)^n) / q(x, 1)``,

   one expression in ``n``, ``x`` and the weights; ``rho_+^n + rho_-^n`` is a polynomial in ``x``
   (the square roots cancel).

>>> from symdecomp.schemes.scheme import catmull_clark
>>> cf = closed_form_characteristic_polynomial(catmull_clark())
>>> cf.laurent_coefficients
(-lambda/16, lambda**2 - 5*lambda/8 + 1/16, -lambda/16)
>>> cf.at(3) == characteristic_polynomial(catmull_clark(), 3)
True
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import flint
import sympy as sp

from symdecomp.algebra.numbers import to_fmpq
from symdecomp.analysis.frequency import per_frequency_matrix
from symdecomp.analysis.reduction import reduce_first_column, subdivision_block_form
from symdecomp.errors import InternalError, InvalidInputError, NotApplicableError
from symdecomp.schemes.full_matrix import characteristic_polynomial
from symdecomp.schemes.scheme import WEIGHT_SYMBOLS, Scheme, check_scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_valence, parameter_values

__all__ = [
    "ClosedFormCharpoly",
    "closed_form_characteristic_polynomial",
    "to_fmpq_poly",
    "verify_closed_form",
]


@dataclass(frozen=True)
class ClosedFormCharpoly:
    """``det(x I - S)`` for symbolic ``n`` and weights, in the variable :data:`symdecomp.symbols.lam`."""

    #: ``x - 1``: the eigenvalue 1 separated by the reduction ``S -> S'``.
    unit_factor: sp.Expr
    #: ``E_0 = M(1) + n T``, the block-eigenvalue matrix at frequency 0 of ``L`` (Prop. 6.3); the only place the vertex weights enter.
    zero_frequency_matrix: sp.ImmutableMatrix
    #: ``det(x I - E_0)``: its two roots are the eigenvalues the vertex weights move.
    zero_frequency_factor: sp.Expr
    #: ``q(x, omega) = det(x I - M(omega))``, a Laurent polynomial in ``omega``.
    frequency_factor: sp.Expr
    #: ``(c_-, c_0, c_+)``: ``q = c_-/omega + c_0 + c_+ omega``.
    laurent_coefficients: tuple[sp.Expr, sp.Expr, sp.Expr]
    #: ``rho_+, rho_-``: the roots of ``rho^2 - c_0 rho + c_+ c_-``.
    rho: tuple[sp.Expr, sp.Expr]
    #: ``prod_{k=0}^{n-1} q(x, omega_n^k) = rho_+^n + rho_-^n - (-c_+)^n - (-c_-)^n``.
    frequency_product: sp.Expr
    #: ``q(x, 1)``, the ``k = 0`` factor of that product (divided out).
    frequency_one: sp.Expr
    #: The whole characteristic polynomial, one expression in ``n``, ``x`` and the weights.
    expression: sp.Expr
    #: For a symmetric ``q`` (``c_+ = c_-``): ``Psi = (sigma_+^n - sigma_-^n)/(sigma_+ - sigma_-)`` with
    #: ``sigma_+- = (sqrt(c_0 - 2c_+) +- sqrt(c_0 + 2c_+))/2`` (so ``sigma_+-^2 = rho_+-``); then
    #: ``prod_{k=1}^{n-1} q(x, omega_n^k) = Psi^2``: every frequency ``k`` pairs with ``n - k``.
    #: ``None`` when ``c_+ != c_-``.
    paired_factor: sp.Expr | None = None

    def at(self, n: int, values: Mapping[sp.Symbol, object] | None = None) -> flint.fmpq_poly:
        """Evaluate the closed form exactly at valence ``n`` (and parameter values), as an ``fmpq_poly``.

        The powers ``rho_+^n + rho_-^n`` are computed in ``Q[x][sqrt(D)]``, ``D = c_0^2 - 4 c_+ c_-``,
        by repeated squaring; the division by ``q(x, 1)`` must leave no remainder.
        """
        n = check_valence(n)
        subs = {N: n}
        declared = sorted(self.expression.free_symbols - {N, LAM}, key=str)
        subs.update(parameter_values(declared, values, owner="the closed form", symbols=WEIGHT_SYMBOLS))
        c_minus, c_zero, c_plus = (to_fmpq_poly(c.subs(subs)) for c in self.laurent_coefficients)
        D = c_zero * c_zero - 4 * c_plus * c_minus
        half = flint.fmpq(1, 2)
        a, b = _quadratic_power((c_zero * half, flint.fmpq_poly([half])), D, n)
        product = 2 * a - (-c_plus) ** n - (-c_minus) ** n
        numerator = to_fmpq_poly(self.unit_factor.subs(subs)) * to_fmpq_poly(self.zero_frequency_factor.subs(subs)) * product
        quotient, remainder = divmod(numerator, to_fmpq_poly(self.frequency_one.subs(subs)))
        if not remainder.is_zero():
            raise InternalError(f"closed form at n = {n}: q(x, 1) does not divide the frequency product")
        return quotient


def _quadratic_power(base, D, e: int):
    """``(a + b sqrt(D))^e`` as ``(a', b')``, by repeated squaring."""
    one = (flint.fmpq_poly([1]), flint.fmpq_poly([]))

    def mul(u, v):
        return (u[0] * v[0] + u[1] * v[1] * D, u[0] * v[1] + u[1] * v[0])

    result = one
    while e:
        if e & 1:
            result = mul(result, base)
        base = mul(base, base)
        e >>= 1
    return result


def to_fmpq_poly(expr, variable: sp.Symbol = LAM) -> flint.fmpq_poly:
    """An exact polynomial in ``variable`` with rational coefficients as an ``fmpq_poly``."""
    expr = sp.expand(sp.sympify(expr, strict=True))
    free = expr.free_symbols - {variable}
    if free:
        raise InvalidInputError(f"cannot evaluate exactly: free symbols {sorted(map(str, free))} left; give their values")
    poly = sp.Poly(expr, variable)
    coeffs = []
    for c in reversed(poly.all_coeffs()):
        if not c.is_Rational:
            raise InvalidInputError(f"coefficient {c} of {expr} is not rational")
        coeffs.append(to_fmpq(c))
    return flint.fmpq_poly(coeffs)


@cached(scheme=check_scheme)
def closed_form_characteristic_polynomial(scheme: Scheme) -> ClosedFormCharpoly:
    """Derive ``det(x I - S)`` of ``scheme`` in closed form, symbolic in ``n`` and the weights.

    Raises :class:`~symdecomp.errors.InvalidSchemeError` when ``det(x I - M(omega))`` is not of
    Laurent degree 1 in ``omega`` (stencils wider than offsets ``-1..1`` would need the roots
    of a higher-degree polynomial, not a closed form).
    """
    reduction = reduce_first_column(subdivision_block_form(scheme))
    L = reduction.lower_right
    x = LAM
    M = sp.Matrix(L.block_eigenvalue_matrix(zero_frequency=False))
    if sp.expand(M - sp.Matrix(per_frequency_matrix(scheme))) != sp.zeros(*M.shape):
        raise InternalError("the CB-block of S' disagrees with the per-frequency matrix (internal inconsistency)")
    E0 = sp.ImmutableMatrix(L.block_eigenvalue_matrix(zero_frequency=True).applyfunc(sp.expand))
    size = M.rows
    q = sp.expand((x * sp.eye(size) - M).det())
    try:
        shifted = sp.Poly(sp.expand(q * OMEGA), OMEGA)
    except sp.PolynomialError:
        shifted = None
    if shifted is None or shifted.degree() > 2:
        det_M = sp.Function("det")(x * sp.Symbol("I", commutative=False) - sp.Function("M")(OMEGA))
        raise NotApplicableError(
            f"det(xI - M(omega)) = {q} is not of Laurent degree 1 in omega; the closed form of Eq. 51 needs the narrow shape (offsets -1..1)",
            parts=(sp.Eq(det_M, q, evaluate=False), " is not of Laurent degree 1 in ", OMEGA,
                   "; the closed form of Eq. 51 needs the narrow shape (offsets -1..1)"),
        )
    c_minus, c_zero, c_plus = (sp.expand(shifted.coeff_monomial(OMEGA**k)) for k in range(3))
    disc = sp.expand(c_zero**2 - 4 * c_plus * c_minus)
    rho_p = (c_zero + sp.sqrt(disc)) / 2
    rho_m = (c_zero - sp.sqrt(disc)) / 2
    product = rho_p**N + rho_m**N - (-c_plus) ** N - (-c_minus) ** N
    q_one = sp.factor(sp.expand(q.subs(OMEGA, 1)))
    unit = x - reduction.reduced.corner
    zero_factor = sp.expand((x * sp.eye(size) - E0).det())
    paired = None
    if sp.expand(c_plus - c_minus) == 0:
        sigma_p = (sp.sqrt(c_zero - 2 * c_plus) + sp.sqrt(c_zero + 2 * c_plus)) / 2
        sigma_m = (sp.sqrt(c_zero - 2 * c_plus) - sp.sqrt(c_zero + 2 * c_plus)) / 2
        paired = (sigma_p**N - sigma_m**N) / (sigma_p - sigma_m)
    return ClosedFormCharpoly(
        unit_factor=unit,
        zero_frequency_matrix=E0,
        zero_frequency_factor=zero_factor,
        frequency_factor=q,
        laurent_coefficients=(c_minus, c_zero, c_plus),
        rho=(rho_p, rho_m),
        frequency_product=product,
        frequency_one=q_one,
        expression=unit * zero_factor * product / q_one,
        paired_factor=paired,
    )


def _affine_in(expr: sp.Expr, params) -> bool:
    poly = sp.Poly(sp.expand(expr), *params) if params else None
    return poly is None or poly.total_degree() <= 1


def verify_closed_form(scheme: Scheme, n: int) -> bool:
    """Does the closed form equal the matrix's characteristic polynomial at ``n``, for all parameter values?

    With free parameters, they must enter only the vertex rule and affinely (as ``alpha``,
    ``beta`` do); then both sides are affine in them (only the first row of ``S`` depends on
    them; ``det(xI - E_0)`` is checked to be affine), so equality at the ``p + 1`` points ``0``
    and ``e_i`` proves equality identically.
    """
    params = tuple(scheme.parameters)
    if not params:
        return closed_form_characteristic_polynomial(scheme).at(n) == characteristic_polynomial(scheme, n)
    for rule in (scheme.edge_rule, scheme.face_rule):
        weights = [rule.center] + [w for _, w in rule.a + rule.b]
        if any(w.free_symbols & set(params) for w in weights):
            raise NotApplicableError("parameters outside the vertex rule: the exact check covers only vertex-rule weights")
    v = scheme.vertex_rule
    cf = closed_form_characteristic_polynomial(scheme)
    if not all(_affine_in(w, params) for w in (v.center, v.each_a, v.each_b, cf.zero_frequency_factor)):
        raise NotApplicableError("the vertex-rule weights do not enter affinely; a finite exact check is not a proof")
    points = [{p: 0 for p in params}] + [{p: (1 if p == q else 0) for p in params} for q in params]
    return all(cf.at(n, pt) == characteristic_polynomial(scheme, n, pt) for pt in points)
