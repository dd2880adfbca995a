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

The same question for any scheme and ``K``-ring (where the closed form does not reach): the
irreducible factors of ``det(lambda I - E_0)`` and ``det(lambda I - E(omega))``, factored once
symbolically (:func:`frequency_factors`), and the product form
``det(x I - S) = det(x I - E_0) prod_{k=1}^{n-1} det(x I - E(omega_n^k))``: at a valence the polynomial
is the full matrix's (FLINT), written through the centre weights (it is affine in them: only row 0
holds them), and compared with the product exactly, at ``size`` rational points for each corner of
the centre weights (:func:`product_identity`, the identity behind
:func:`~symdecomp.verify.certify.certify_ring`).

>>> from symdecomp.schemes.loop import loop_warren
>>> d = ring_charpoly(loop_warren(), 3)
>>> d["polynomial"], d["matches_matrix"]
('lambda**4 - 25*lambda**3/16 + 21*lambda**2/32 - 25*lambda/256 + 1/256', True)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache, partial

import flint
import sympy as sp

from symdecomp.algebra.numbers import rational_poly, to_fmpq
from symdecomp.analysis.frequency import RingBlocks, per_frequency_matrix, ring_blocks
from symdecomp.analysis.reduction import reduce_first_column, subdivision_block_form
from symdecomp.errors import InternalError, InvalidInputError, NotApplicableError
from symdecomp.schemes.full_matrix import characteristic_polynomial, entries_characteristic_polynomial
from symdecomp.schemes.rings import CENTRE_WEIGHTS, RingMatrix, ring_subdivision_matrix
from symdecomp.schemes.scheme import WEIGHT_SYMBOLS, Scheme, check_scheme
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_type, check_valence, parameter_values

__all__ = [
    "ClosedFormCharpoly",
    "closed_form_characteristic_polynomial",
    "to_fmpq_poly",
    "verify_closed_form",
    "COSK",
    "Factor",
    "FrequencyFactors",
    "frequency_factors",
    "irreducible_factors",
    "ring_charpoly",
    "product_form",
    "frequency_product_values",
    "ProductIdentity",
    "product_identity",
]

W_O, W_A, W_B = CENTRE_WEIGHTS


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
    poly = rational_poly(expr, variable)
    if poly is None:
        raise InvalidInputError(f"{expr} is not a polynomial in {variable} with rational coefficients")
    return poly


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


#: ``cos(2 pi k/n)``: the variable of the closed forms of frequency ``k`` when they are real.
COSK = sp.Symbol("c_k", real=True)


def _cosine_form(expr: sp.Expr) -> sp.Expr | None:
    """A Laurent polynomial in ``omega`` with ``p(omega) = p(1/omega)`` as a polynomial in ``c_k``; else ``None``."""
    numer, denom = sp.fraction(sp.together(sp.expand(expr)))
    if not denom.free_symbols <= {OMEGA} or numer.free_symbols - {OMEGA}:
        return None
    dp, np_ = sp.Poly(denom, OMEGA), sp.Poly(numer, OMEGA)
    if not dp.is_monomial:
        return None
    terms = {m[0] - dp.degree(): c / dp.LC() for m, c in np_.terms()}
    if any(terms.get(-p, 0) != c for p, c in terms.items()):
        return None
    return sp.expand(sp.Add(*[c * (2 * sp.chebyshevt_poly(p, COSK) if p else 1) for p, c in terms.items() if p >= 0]))


@dataclass(frozen=True)
class Factor:
    """An irreducible factor of a frequency's characteristic polynomial, with its exponent."""

    #: The factor as a polynomial in ``lambda`` (coefficients in ``omega`` or in ``n, w_a, w_b``).
    poly: sp.Expr
    #: Its exponent in the characteristic polynomial.
    exponent: int
    #: Closed-form roots (degree <= 2), else ``None``. Frequencies ``k != 0``: in ``c_k =
    #: cos(2 pi k/n)`` when the coefficients are symmetric in ``omega``, else in ``omega``.
    roots: tuple[sp.Expr, ...] | None

    @property
    def degree(self) -> int:
        return sp.degree(self.poly, LAM)


@dataclass(frozen=True)
class FrequencyFactors:
    """The factored characteristic polynomials: ``E_0`` and ``E(omega)``."""

    zero: tuple[Factor, ...]
    other: tuple[Factor, ...]


def irreducible_factors(charpoly: sp.Expr, gens) -> tuple[Factor, ...]:
    """The factors of ``charpoly`` (a polynomial in ``lambda`` over ``gens``) that hold ``lambda``, each monic, with its
    exponent and closed-form roots up to degree 2 (in ``c_k`` where the coefficients are symmetric in ``omega``)."""
    numer, _ = sp.fraction(sp.together(sp.expand(charpoly)))
    _, items = sp.factor_list(sp.expand(numer), *gens)
    out = []
    for f, e in items:
        if not f.has(LAM):
            continue  # a constant or a power of omega (the Laurent denominator)
        p = sp.Poly(f, LAM)
        lead = p.LC()
        c = [sp.cancel(x / lead) for x in p.all_coeffs()]
        if OMEGA in gens:
            cos_c = [_cosine_form(x) for x in c]
            if None not in cos_c:
                c = cos_c
        monic = sp.Add(*[x * LAM ** (p.degree() - i) for i, x in enumerate(c)])
        roots = None
        if p.degree() == 1:
            roots = (sp.cancel(-c[1]),)
        elif p.degree() == 2:
            disc = sp.factor(sp.cancel(c[1] ** 2 - 4 * c[2]))
            roots = tuple(sp.cancel(-c[1] / 2) + s * sp.sqrt(disc) / 2 for s in (1, -1))
        out.append(Factor(monic, int(e), roots))
    return tuple(out)


@cached(32, blocks=partial(check_type, kind=RingBlocks, argument="blocks", hint="ring_blocks(scheme, rings)"))
def frequency_factors(blocks: RingBlocks) -> FrequencyFactors:
    """Factor ``det(lambda I - E_0)`` and ``det(lambda I - E(omega))`` once, symbolically (exact)."""
    K = blocks.class_count
    E = blocks.frequency_matrix()
    other = irreducible_factors((LAM * sp.eye(K) - E).det(method="berkowitz"), (LAM, OMEGA))
    affine = 1 - sum(N * {"a": W_A, "b": W_B}[name] for name, _ in blocks.lattice.one_ring_classes)  # the vertex rule sums to 1
    E0 = blocks.frequency_zero_matrix(symbolic_weights=True).xreplace({W_O: affine})
    zero = irreducible_factors((LAM * sp.eye(K + 1) - E0).det(method="berkowitz"), (LAM, N, W_A, W_B))
    return FrequencyFactors(zero, other)


def _power(f, e):
    return f"({f})" if e == 1 else f"({f})^{e}"


def product_form(scheme: Scheme, rings: int = 1) -> tuple[list[str], list[str], str]:
    """``(E_0 factors, E(omega) factors, the product formula)`` as text."""
    ff = frequency_factors(ring_blocks(scheme, rings))
    zero = [_power(f.poly, f.exponent) for f in ff.zero]
    other = [_power(f.poly, f.exponent) for f in ff.other]
    formula = "det(x I - E_0) * prod_{k=1}^{n-1} det(x I - E(omega_n^k)), c_k = cos(2 pi k/n)"
    return zero, other, formula


@lru_cache(maxsize=32)
def _laurent_charpoly(blocks: RingBlocks, n: int | None = None) -> tuple[int, tuple[flint.fmpq_poly, ...]]:
    """``(m, (Q_0, Q_1, ...))`` with ``omega^m det(lambda I - E(omega)) = sum_i lambda^i Q_i(omega)``; ``n``: the valence,
    for blocks that depend on it (an edge rule in ``n``), else ``None``."""
    K = blocks.class_count
    E = blocks.frequency_matrix() if n is None else blocks.frequency_matrix().subs(N, n)
    det = sp.expand((LAM * sp.eye(K) - E).det(method="berkowitz"))
    terms = sp.Poly(sp.expand(det * OMEGA ** (4 * K * 8)), LAM, OMEGA).terms()
    low = min(b for (_, b), _ in terms)
    m = 4 * K * 8 - low
    degree = max(a for (a, _), _ in terms)
    polys: list[dict[int, flint.fmpq]] = [dict() for _ in range(degree + 1)]
    for (a, b), c in terms:
        polys[a][b - low] = to_fmpq(c)
    return m, tuple(flint.fmpq_poly([p.get(j, 0) for j in range(max(p, default=0) + 1)]) for p in polys)


def frequency_product_values(blocks: RingBlocks, n: int, weights: dict, points) -> list:
    """``det(l I - E_0) prod_{k=1}^{n-1} det(l I - E(omega^k))`` exactly at each rational ``l``.

    ``weights``: rational values for every symbol of :data:`CENTRE_WEIGHTS`.
    """
    m, Q = _laurent_charpoly(blocks, n if blocks.frequency_matrix().has(N) else None)
    E0 = blocks.frequency_zero_matrix(n, symbolic_weights=True).xreplace(weights)
    f0 = sp.Poly((LAM * sp.eye(E0.shape[0]) - E0).det(method="berkowitz"), LAM)
    zero = flint.fmpq_poly([to_fmpq(c) for c in reversed(f0.all_coeffs())])
    cyclotomic = flint.fmpq_poly([1] * n)
    sign = -1 if (m * (n - 1)) % 2 else 1
    out = []
    for lam in points:
        lam = flint.fmpq(lam)
        G, power = flint.fmpq_poly(0), flint.fmpq(1)
        for q in Q:
            G += q * power
            power *= lam
        out.append(zero(lam) * cyclotomic.resultant(G) * sign)
    return out


@dataclass(frozen=True)
class ProductIdentity:
    """``chi_S = det(l I - E_0) prod_k det(l I - E(omega^k))`` tested exactly at one valence.

    The one home of the comparison behind ``charpoly`` and ``check --certify``: ``chi_S`` of
    the refined matrix (FLINT, no block structure) against the product of the frequency
    factors (resultants, :func:`frequency_product_values`) at ``size`` rational points, for
    each corner of the centre weights that are not rational (both sides are affine in them).
    """

    #: The refined matrix.
    matrix: RingMatrix
    #: The centre-weight symbols kept free (algebraic weights), sorted by name.
    free: tuple
    #: The other centre weights: symbol -> exact rational value at ``n``.
    fixed: dict
    #: The corners: ``{symbol: 0 or 1}`` for the free symbols (one corner, ``{}``, if none).
    corners: tuple
    #: ``chi_S`` at each corner (``flint.fmpq_poly``).
    chis: tuple
    #: ``None`` if the identity holds, else ``(corner, l, chi_S(l), product at l)`` of the first failure.
    failure: tuple | None


def product_identity(scheme: Scheme, n: int, rings: int = 1, *, blocks: RingBlocks | None = None) -> ProductIdentity:
    """Test the product identity at valence ``n`` exactly (``blocks``: the block form under test)."""
    n = check_valence(n)
    blocks = blocks or ring_blocks(scheme, rings)
    S = ring_subdivision_matrix(scheme, n, rings)
    free = tuple(sorted(S.weights, key=str))
    v = scheme.vertex_rule
    rule = dict(zip(CENTRE_WEIGHTS, (v.center, v.each_a, v.each_b)))
    fixed = {s: sp.sympify(w, strict=True).subs(N, n) for s, w in rule.items() if s not in free}
    corners = tuple([{s: 0 for s in free}] + [{s: int(s == t) for s in free} for t in free])
    chis, failure = [], None
    for point in corners:
        chi = entries_characteristic_polynomial(S.entries(point), S.size)
        chis.append(chi)
        if failure is None:
            values = frequency_product_values(blocks, n, {**fixed, **{s: sp.Integer(x) for s, x in point.items()}}, range(S.size))
            bad = next((x for x in range(S.size) if chi(flint.fmpq(x)) != values[x]), None)
            if bad is not None:
                failure = (point, bad, chi(flint.fmpq(bad)), values[bad])
    return ProductIdentity(S, free, fixed, corners, tuple(chis), failure)


def ring_charpoly(scheme: Scheme, n: int, rings: int = 1) -> dict:
    """JSON-ready: the product form, the polynomial at ``n`` (exact coefficients) and whether they agree."""
    return ring_charpoly_exact(scheme, n, rings)[0]


def ring_charpoly_exact(scheme: Scheme, n: int, rings: int = 1) -> tuple[dict, tuple[sp.Expr, ...]]:
    """:func:`ring_charpoly` and the exact coefficients it prints (sympy numbers, highest degree first): what
    ``charpoly --plot`` finds the roots of."""
    identity = product_identity(scheme, n, rings)
    S, free, corners, matches = identity.matrix, identity.free, identity.corners, identity.failure is None
    polys = [[sp.Rational(int(c.p), int(c.q)) for c in chi.coeffs()] for chi in identity.chis]
    actual = S.weight_values()
    coeffs = [sp.expand(p0 + sum((actual[s] * (p[i] - p0) for s, p in zip(free, polys[1:])), sp.Integer(0))) for i, p0 in enumerate(polys[0])]
    polynomial = sp.Add(*[c * LAM**i for i, c in enumerate(coeffs)])
    zero, other, formula = product_form(scheme, rings)
    return {
        "n": n, "scheme": scheme.name, "rings": rings, "size": S.size,
        "product_form": formula, "frequency_zero_factors": zero, "frequency_factors": other,
        "centre_weights": {str(s): str(w) for s, w in actual.items()},
        "polynomial": str(polynomial), "coefficients": [str(c) for c in reversed(coeffs)],
        "matches_matrix": bool(matches),
        "method": f"chi_S = product at {S.size} points" + (f" for {len(corners)} values of the centre weights" if free else ""),
    }, tuple(reversed(coeffs))
