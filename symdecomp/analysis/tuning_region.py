"""The exact region of free vertex weights by curvature regime at one valence (issue 21, item 5).

**Setting.** A scheme with free parameters in its vertex rule (``parameters = ["alpha", "beta"]``
in a scheme file, each weight affine in them); the parameters are the vertex weights at the
extraordinary vertex ``O`` of valence ``n``. Everything else keeps the scheme's edge and face
rules, and every other vertex (all of the regular valence) the rules of the lattice's reference
scheme (Catmull-Clark, Loop): a scheme tuned at extraordinary vertices only, as
:class:`~symdecomp.schemes.scheme.Scheme` describes.

**Which eigenvalues depend on the weights.** The 2-ring matrix of Reif's test
(:mod:`symdecomp.verify.c1_spectrum`) splits by frequency. The vertex rule at ``O`` enters only
frequency 0, and there only the 1-ring block ``T`` (Eq. 43, :func:`~symdecomp.analysis.frequency.one_ring_matrices`;
the outer block ``S_0`` holds the regular rules). ``det(x - T) = (x - 1) Q(x)`` with ``Q`` monic of
degree 2 on quads (``x^2 + p x + q``) and 1 on triangles (``x + p``), ``p, q`` affine in the weights
(:func:`symdecomp.analysis.tuning.eigenvalue_quadratic`). Weight-independent: the eigenvalues of
``M_j`` (``j >= 1``) and of the outer blocks (the regular rules' roots, the same at every
frequency). So at each ``n``: ``lambda_1`` (dominant eigenvalue of ``M_1``) and ``m`` (the largest
modulus among the weight-independent eigenvalues other than ``1`` and the pair ``lambda_1``) are
fixed algebraic numbers, and ``mu = max(m, |nu| for the roots nu of Q)``.

**Conditions.** "Both roots of ``Q`` have modulus ``< r``" (``r > 0``) is, by the Schur-Cohn-Jury
test, ``Q(r) > 0``, ``(-1)^d Q(-r) > 0`` and (degree 2) ``r^2 - q > 0``: linear inequalities in the
weights, with coefficients in ``Q(lambda_1)``; with ``>=`` they say ``<= r``. Then

* **C1** (the weight-dependent part of Reif's spectral conditions: ``1`` simple and ``lambda_1``
  strictly dominant) is the open set for ``r = lambda_1``. The rest of Reif's test does not depend
  on the weights: the other frequencies' eigenvalues, and the characteristic map, which lives in
  frequency 1 (its eigenvector has ``O = 0`` and is built from ``M_1`` and the regular rules,
  :mod:`symdecomp.analysis.characteristic`). It is certified once per ``n`` by
  :func:`~symdecomp.verify.c1.c1_test` at one *witness* point of the open set (both roots of ``Q`` of
  modulus ``< lambda_1 / 2``); if the test fails there, no weights make the scheme C1 at ``n``.
* with ``r = lambda_1^2``, and ``m`` compared with ``lambda_1^2`` exactly: if ``m < lambda_1^2``,
  **mu < lambda_1^2** is the open set (a flat spot), **mu = lambda_1^2** its boundary (the closed set
  with one form ``= 0``), **mu > lambda_1^2** the rest of C1; if ``m = lambda_1^2`` (Catmull-Clark at
  ``n = 4``: the frequency-2 eigenvalue ``1/4``) the closed set is ``mu = lambda_1^2`` and nothing is
  ``< lambda_1^2``; if ``m > lambda_1^2`` every C1 point has ``mu > lambda_1^2``.

The regimes compare moduli, as the issue defines them (the eigenvalue of modulus ``lambda_1^2``
may be ``-lambda_1^2`` or complex on parts of the boundary), and are those of
:mod:`symdecomp.analysis.curvature_regime` (:class:`~symdecomp.analysis.curvature_regime.CurvatureRegime`:
``zero``, ``bounded``, ``unbounded``; ``not applicable`` outside the C1 set, where there is no dominant
``lambda_1``), decided by its :func:`~symdecomp.analysis.curvature_regime.curvature_regime` from the sign of
``|mu| - lambda_1^2``. Its Jordan rule (``|mu| = lambda_1^2`` with a Jordan block is unbounded, the curvature
growing like ``k``) applies at the (at most two) corners where ``Q`` has a double root ``+-lambda_1^2`` and
``T`` is not diagonalizable there (exact rank, :meth:`TuningRegion.corners`): such a point is unbounded though
it satisfies the closed conditions; the printed conditions of the bounded set exclude them in words.
Membership of an exact point is decided by exact signs (:func:`~symdecomp.algebra.algebraic_sign.exact_sign`);
for one parameter the sets are unions of intervals with algebraic endpoints (the forms' roots,
sorted exactly). More than two parameters are refused (a region in 3+ dimensions is not printed
or drawn here); so are weights not affine in the parameters, and two parameters that enter ``Q``
through fewer than two independent combinations.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.algebra.algebraic_sign import exact_sign, rational_between, real_ball
from symdecomp.analysis.characteristic import outer_charpoly
from symdecomp.analysis.curvature_regime import CurvatureRegime, curvature_regime
from symdecomp.analysis.frequency import laurent_to_cos, one_ring_matrices
from symdecomp.analysis.tuning import unit_quotient
from symdecomp.errors import InvalidInputError, InvalidValenceError, NotApplicableError
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.scheme import Scheme, VertexRule, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.validate import API_LIMITS, cached, check_type, check_valence

__all__ = ["Form", "TuningRegion", "tuning_region", "interval_region", "check_region_valence"]


def check_region_valence(n) -> int:
    """``n`` if the exact signs of its region are within reach (:data:`~symdecomp.validate.API_LIMITS`: Euler's ``phi(n)``,
    the degree of ``Q(cos(2 pi/n))`` doubled, bounds their cost), refused before any work otherwise: the intervals
    (:func:`interval_region`), the placed points (:func:`placed_points`) and ``tune --region`` check it first; the forms
    themselves (:func:`tuning_region`) are cheap at every ``n``."""
    n = check_valence(n)
    bound, why = API_LIMITS["tune --region, interval_region, placed_points: phi(n)"]
    if sp.totient(n) > bound:
        raise InvalidValenceError(f"valence n = {n}: phi(n) = {sp.totient(n)} > {bound}, so the exact region is out of reach "
                                  f"({why})")
    return n


@dataclass(frozen=True)
class Form:
    """A linear form in the parameters whose sign is one of the conditions."""

    #: A short name: ``Q(r)``, ``Q(-r)`` (``-Q(-r)`` on triangles) or ``r^2 - q``, with ``r`` named.
    name: str
    #: The form, affine in the parameters, with exact algebraic coefficients.
    expr: sp.Expr

    def text(self, relation: str) -> str:
        return f"{sp.sstr(self.expr)} {relation} 0"


@dataclass(frozen=True)
class TuningRegion:
    """The regions of :func:`tuning_region` at one valence (module docstring)."""

    scheme: str
    n: int
    parameters: tuple[sp.Symbol, ...]
    #: ``Q(x) = det(x - T)/(x - 1)``, its coefficients affine in the parameters.
    quadratic: sp.Expr
    lambda1: sp.Expr
    #: ``sign(m - lambda_1^2)``, ``m`` the largest weight-independent modulus after ``1`` and ``lambda_1``.
    fixed_vs_square: int
    #: A rigorous enclosure of ``m``, as text.
    fixed_text: str
    #: The forms ``> 0`` on the C1 set (``r = lambda_1``), and the forms for ``r = lambda_1^2``.
    c1_forms: tuple[Form, ...]
    square_forms: tuple[Form, ...]
    #: The frequency-0 block ``T`` at ``n``, its first row in the parameters.
    block: sp.ImmutableMatrix
    #: Parameter values of a point of the open C1 set (``None``: the set is empty).
    witness: tuple[sp.Expr, ...] | None
    #: Reif's weight-independent conditions at the witness: ``c1``, ``not-c1``, ``undecided``, or ``unchecked`` (this
    #: module does not run the test; :func:`symdecomp.verify.tuning_c1.certified_tuning_region` does), and why.
    witness_verdict: str = "unchecked"
    witness_reason: str = "Reif's weight-independent conditions not checked"

    @property
    def independent_c1(self) -> bool:
        """False when the weight-independent conditions fail (then no weights give C1); the sets assume them otherwise."""
        return self.witness is not None and self.witness_verdict != "not-c1"

    def signs(self, point) -> tuple[tuple[int, ...], tuple[int, ...]]:
        """The exact signs of the C1 forms and of the ``lambda_1^2`` forms at an exact point."""
        values = dict(zip(self.parameters, _exact_point(point, self.parameters)))
        return (tuple(exact_sign(f.expr.subs(values)) for f in self.c1_forms),
                tuple(exact_sign(f.expr.subs(values)) for f in self.square_forms))

    def classify(self, point) -> CurvatureRegime:
        """The regime at an exact point (rationals or exact algebraic numbers, one per parameter); ``not applicable`` outside C1.

        A double root ``+-lambda_1^2`` of ``Q`` with a Jordan block in ``T`` (a corner of the closed set) makes the
        curvature grow like ``k``: unbounded, although ``|mu| = lambda_1^2`` (:func:`curvature_regime`'s ``defective``).
        """
        c1, square = self.signs(point)
        if not in_c1(c1, self.independent_c1):
            return CurvatureRegime.NOT_APPLICABLE
        comparison = square_comparison(square, self.fixed_vs_square)
        return curvature_regime(comparison, defective=comparison == 0 and self._jordan(point, square))

    def _jordan(self, point, square: tuple[int, ...]) -> bool:
        """Whether ``Q`` has a double root ``+-lambda_1^2`` at the point and ``T`` a Jordan block for it (exact rank)."""
        if len(square) != 3 or square[2] != 0 or 0 not in square[:2]:
            return False
        root = self.lambda1**2 if square[0] == 0 else -self.lambda1**2
        values = dict(zip(self.parameters, _exact_point(point, self.parameters)))
        A = (self.block.subs(values) - root * sp.eye(3)).applyfunc(sp.expand)
        return any(exact_sign(A.extract([r for r in range(3) if r != i], [c for c in range(3) if c != j]).det()) != 0
                   for i in range(3) for j in range(3))

    def corners(self) -> list[tuple[str, tuple[sp.Expr, ...], bool]]:
        """Two parameters, degree 2: the points where ``Q`` has the double root ``+-lambda_1^2``, and whether ``T`` has a
        Jordan block there (those corners of the closed set are unbounded)."""
        if len(self.parameters) != 2 or len(self.square_forms) != 3:
            return []
        out = []
        for k, name in ((0, "lambda_1^2"), (1, "-lambda_1^2")):
            sol = sp.solve([self.square_forms[k].expr, self.square_forms[2].expr], self.parameters, dict=True)
            if len(sol) == 1 and all(v in sol[0] for v in self.parameters):
                point = tuple(sp.radsimp(sol[0][v]) for v in self.parameters)
                out.append((name, point, self._jordan(point, self.signs(point)[1])))
        return out

    def conditions(self) -> dict[CurvatureRegime, list[list[str]]]:
        """Each regime's set as alternatives (a union) of conjunctions of exact (in)equalities."""
        c1 = [f.text(">") for f in self.c1_forms]
        sq = self.square_forms
        if not self.independent_c1:
            return {CurvatureRegime.ZERO: [], CurvatureRegime.BOUNDED: [], CurvatureRegime.UNBOUNDED: []}
        if self.fixed_vs_square > 0:
            return {CurvatureRegime.ZERO: [], CurvatureRegime.BOUNDED: [], CurvatureRegime.UNBOUNDED: [c1]}
        closed = [f.text(">=") for f in sq]
        if self.fixed_vs_square == 0:
            bounded = [closed]
            flat = []
        else:
            bounded = [[f.text("=")] + [g.text(">=") for g in sq if g is not f] for f in sq]
            flat = [[f.text(">") for f in sq]]
        return {CurvatureRegime.ZERO: flat, CurvatureRegime.BOUNDED: bounded, CurvatureRegime.UNBOUNDED: [c1 + [f.text("<")] for f in sq]}


def in_c1(c1: tuple[int, ...], independent_c1: bool) -> bool:
    """Whether a point with these signs of the C1 forms lies in the (open) C1 set."""
    return independent_c1 and all(s > 0 for s in c1)


def square_comparison(square: tuple[int, ...], fixed_vs_square: int) -> int:
    """The sign of ``|mu| - lambda_1^2`` at a C1 point, from the signs of the ``lambda_1^2`` forms (module docstring)."""
    if fixed_vs_square > 0 or any(s < 0 for s in square):
        return 1
    return 0 if fixed_vs_square == 0 or any(s == 0 for s in square) else -1


def _exact_point(point, parameters) -> tuple[sp.Expr, ...]:
    if not isinstance(point, (tuple, list)) or len(point) != len(parameters):
        raise InvalidInputError(f"point: give {len(parameters)} exact value(s), one per parameter "
                                f"({', '.join(map(str, parameters))}), got {point!r:.80}")
    out = []
    for value in point:
        if isinstance(value, float) or not isinstance(value, (int, sp.Expr)) or isinstance(value, bool):
            raise InvalidInputError(f"point: {value!r:.40} is not an exact number (give integers, sympy Rationals or exact algebraic numbers)")
        value = sp.sympify(value, strict=True)
        if value.free_symbols or not value.is_real:
            raise InvalidInputError(f"point: {value} is not a real number")
        out.append(value)
    return tuple(out)


def _parameters(scheme: Scheme) -> tuple[sp.Symbol, ...]:
    params = tuple(scheme.parameters)
    if not params:
        raise NotApplicableError(f"scheme {scheme.name!r} has no free parameters; the region needs free vertex weights "
                                 "(parameters = [...] in the scheme file)")
    if len(params) > 2:
        raise NotApplicableError(f"scheme {scheme.name!r} has {len(params)} parameters; the region is computed for 1 or 2")
    rules = [scheme.edge_rule] + ([scheme.face_rule] if scheme.face_rule is not None else [])
    if any(w.has(*params) for r in rules for w in [r.center, *(x for _, x in r.a + r.b)]):
        raise NotApplicableError(f"scheme {scheme.name!r}: its edge or face rule has free parameters; the region is for free "
                                 "vertex weights only")
    return params


def _affine_check(expr: sp.Expr, params, scheme: Scheme) -> sp.Expr:
    expr = sp.expand(expr)
    try:
        degree = sp.Poly(expr, *params).total_degree()
    except sp.PolynomialError:  # 1/alpha, alpha**(1/2): not a polynomial in the parameters at all
        degree = None
    if degree is None or degree > 1:
        raise NotApplicableError(f"scheme {scheme.name!r}: the vertex weights are not affine in {', '.join(map(str, params))} "
                                 f"(frequency 0 has {sp.sstr(expr)}); the region is computed for affine weights")
    return expr


def _quadratic(scheme: Scheme, n: int, params) -> sp.Poly:
    quotient = unit_quotient(one_ring_matrices(scheme)[1].subs(N, n))
    coeffs = [_affine_check(c, params, scheme) for c in quotient.all_coeffs()]
    return sp.Poly(sum(c * LAM**k for k, c in enumerate(reversed(coeffs))), LAM)


def _forms(Q: sp.Poly, r: sp.Expr, name: str) -> tuple[Form, ...]:
    """The Schur-Cohn-Jury forms: all ``> 0`` iff every root of ``Q`` has modulus ``< r``."""
    q_plus = sp.expand(Q.as_expr().subs(LAM, r))
    q_minus = sp.expand(Q.as_expr().subs(LAM, -r))
    if Q.degree() == 1:
        return Form(f"Q({name})", q_plus), Form(f"-Q(-{name})", -q_minus)
    q = Q.all_coeffs()[2]
    return Form(f"Q({name})", q_plus), Form(f"Q(-{name})", q_minus), Form(f"{name}^2 - q", sp.expand(r**2 - q))


def _frequency_eigenvalues(scheme: Scheme, n: int, j: int) -> list[tuple[str, sp.Expr]]:
    """The eigenvalues of ``M_j`` at valence ``n`` as exact expressions: ``("real", x)`` or ``("modulus^2", |x|^2)`` pairs."""
    M = one_ring_matrices(scheme)[0]
    c = sp.cos(j * sp.pi / n)

    def at(e):
        e = laurent_to_cos(sp.expand(e))
        if e.has(sin_jtheta):
            raise NotApplicableError(f"scheme {scheme.name!r}: its rules are not mirror-symmetric (M_j depends on sin(j pi/n)); "
                                     "the region needs real eigenvalues in closed form")
        return sp.expand(e.subs(cos_jtheta, c).subs(N, n))

    if M.rows == 1:
        return [("real", at(M[0, 0]))]
    tr, det = at(M.trace()), at(M.det())
    disc = sp.expand(tr**2 - 4 * det)
    if exact_sign(disc) < 0:
        return [("modulus^2", det), ("modulus^2", det)]
    root = sp.sqrt(disc)
    big, small = (tr + root) / 2, (tr - root) / 2
    return [("real", big), ("real", small)] if exact_sign(tr) >= 0 else [("real", small), ("real", big)]


def _fixed_comparison(scheme: Scheme, n: int) -> tuple[sp.Expr, int, str]:
    """``lambda_1``, ``sign(m - lambda_1^2)`` and an enclosure of ``m`` (module docstring)."""
    first = _frequency_eigenvalues(scheme, n, 1)
    kind, lam1 = first[0]
    if kind != "real" or exact_sign(lam1) <= 0:
        raise NotApplicableError(f"scheme {scheme.name!r}: M_1 has no positive real dominant eigenvalue at n = {n}")
    others = first[1:] + [e for j in range(2, n // 2 + 1) for e in _frequency_eigenvalues(scheme, n, j)]
    coeffs = outer_charpoly(scheme.lattice)
    x = sp.Symbol("x")
    outer = sp.Poly([sp.Rational(int(c.p), int(c.q)) for c in coeffs], x).all_roots() if coeffs else []
    others += [("real", r) for r in outer]
    square = lam1**2
    sign, moduli = -1, []
    for kind, value in others:
        if kind == "real":
            sign = max(sign, exact_sign(value - square), exact_sign(-value - square))
            moduli.append(abs(real_ball(value, 64)))
        else:
            sign = max(sign, exact_sign(value - square**2))
            moduli.append(real_ball(value, 64).sqrt())
    largest = max(moduli, key=lambda b: float(b.mid())) if moduli else None
    text = "none" if largest is None else largest.str(8, radius=False)
    return lam1, sign, text


def _c1_set_interval(forms, t) -> tuple[sp.Expr | None, sp.Expr | None, bool]:
    """The open interval where every form ``> 0`` (one parameter ``t``): ``(lo, hi, nonempty)``, ``None`` unbounded."""
    lo = hi = None
    for f in forms:
        c1, c0 = sp.expand(f.expr).coeff(t, 1), sp.expand(f.expr).coeff(t, 0)
        s = exact_sign(c1)
        if s == 0:
            if exact_sign(c0) <= 0:
                return None, None, False
            continue
        root = sp.expand(-c0 / c1)
        if s > 0 and (lo is None or exact_sign(root - lo) > 0):
            lo = root
        if s < 0 and (hi is None or exact_sign(root - hi) < 0):
            hi = root
    nonempty = lo is None or hi is None or exact_sign(hi - lo) > 0
    return lo, hi, nonempty


def _witness(scheme: Scheme, n: int, params, Q: sp.Poly, lam1: sp.Expr):
    """Weights at ``O`` (a point of the open C1 set, the roots of ``Q`` of modulus ``< lambda_1/2`` if one parameter allows)."""
    s = sp.Rational(int(float(real_ball(lam1, 64).mid()) * 50), 100)  # about lambda_1 / 2, rational, < lambda_1
    if len(params) == 2:
        coeffs = Q.all_coeffs()
        if len(coeffs) != 3:
            raise NotApplicableError(f"scheme {scheme.name!r}: two parameters, but the frequency-0 block has one weight-dependent "
                                     "eigenvalue; give one parameter")
        p, q = coeffs[1], coeffs[2]
        jac = sp.Matrix([[sp.diff(e, v) for v in params] for e in (p, q)])
        if exact_sign(jac.det()) == 0:
            raise NotApplicableError(f"scheme {scheme.name!r}: the two parameters enter the frequency-0 block through one "
                                     "combination; give one parameter")
        sol = sp.solve([sp.Eq(p, 0), sp.Eq(q, -s**2)], params, dict=True)[0]
        return tuple(sp.radsimp(sol[v]) for v in params)
    t = params[0]
    for r in (s, lam1):
        lo, hi, nonempty = _c1_set_interval(_forms(Q, r, "r"), t)
        if nonempty:
            return (rational_between(lo, hi),)
    return None


def _vertex_weights(scheme: Scheme, n: int, values: dict) -> tuple[sp.Expr, sp.Expr]:
    v = scheme.vertex_rule
    return tuple(sp.expand(sp.sympify(w, strict=True).subs(values).subs(N, n)) for w in (v.each_a, v.each_b))


def witness_scheme(region: TuningRegion, scheme: Scheme) -> Scheme | None:
    """A concrete scheme with the region's witness weights at ``O`` and the reference's elsewhere (``None``: C1 set empty).

    Reif's weight-independent conditions at ``n`` hold for every weight iff they hold for this scheme; at the
    regular valence ``O``'s own weights are the reference's (a point of the C1 set when the edge and face rules are
    the reference's, which the C1 test requires anyway).
    """
    n, ref = region.n, scheme.lattice.reference()
    if region.witness is None:
        return None
    if n == scheme.lattice.regular_valence:
        rule = ref.vertex_rule
    else:
        wa, wb = _vertex_weights(scheme, n, dict(zip(region.parameters, region.witness)))
        pick = [sp.Piecewise((w, sp.Eq(N, n)), (r, True)) for w, r in ((wa, ref.vertex_rule.each_a), (wb, ref.vertex_rule.each_b))]
        rule = VertexRule.affine(*pick)
    return Scheme(scheme.name + " (witness)", scheme.edge_rule, scheme.face_rule, rule, (), scheme.lattice)


@cached(scheme=check_scheme, n=check_valence)
def tuning_region(scheme: Scheme, n: int) -> TuningRegion:
    """The exact regions of the free vertex weights of ``scheme`` at valence ``n`` by regime (module docstring).

    The weight-independent part of Reif's test is not run here (``witness_verdict`` is ``unchecked``);
    :func:`symdecomp.verify.tuning_c1.certified_tuning_region` runs it.
    """
    params = _parameters(scheme)
    n = scheme.fitting_valence(n, real=True)
    Q = _quadratic(scheme, n, params)
    lam1, fixed_sign, fixed_text = _fixed_comparison(scheme, n)
    c1_forms = _forms(Q, lam1, "lambda_1")
    square_forms = _forms(Q, lam1**2, "lambda_1^2")
    witness = _witness(scheme, n, params, Q, lam1)
    block = sp.ImmutableMatrix(one_ring_matrices(scheme)[1].subs(N, n).applyfunc(sp.expand))
    return TuningRegion(scheme.name, n, params, Q.as_expr(), lam1, fixed_sign, fixed_text, c1_forms, square_forms, block, witness)


@dataclass(frozen=True)
class Interval:
    """A piece of the line of one parameter: ``lo < t < hi`` (ends included where closed; ``None``: unbounded)."""

    regime: CurvatureRegime
    lo: sp.Expr | None
    hi: sp.Expr | None
    lo_closed: bool
    hi_closed: bool

    def text(self) -> str:
        if self.lo is not None and self.hi is not None and self.lo == self.hi:
            return f"{{{sp.sstr(self.lo)}}}"
        left = "(-oo" if self.lo is None else ("[" if self.lo_closed else "(") + sp.sstr(self.lo)
        right = "oo)" if self.hi is None else sp.sstr(self.hi) + ("]" if self.hi_closed else ")")
        return f"{left}, {right}"


def _sorted_roots(region: TuningRegion) -> list[sp.Expr]:
    import functools

    t = region.parameters[0]
    roots = []
    for f in region.c1_forms + region.square_forms:
        c1, c0 = sp.expand(f.expr).coeff(t, 1), sp.expand(f.expr).coeff(t, 0)
        if exact_sign(c1) != 0:
            root = sp.radsimp(sp.expand(-c0 / c1))
            if all(exact_sign(root - r) != 0 for r in roots):
                roots.append(root)
    return sorted(roots, key=functools.cmp_to_key(lambda a, b: exact_sign(a - b)))


def interval_region(region: TuningRegion) -> list[Interval]:
    """One parameter: the line cut into maximal intervals of one regime, with exact algebraic ends, in order."""
    check_type(region, TuningRegion, "region", hint="tuning_region(scheme, n)")
    if len(region.parameters) != 1:
        raise NotApplicableError(f"the region of {region.scheme!r} has {len(region.parameters)} parameters; intervals need one")
    check_region_valence(region.n)
    roots = _sorted_roots(region)
    pieces = []  # (regime, lo, hi): a point when lo is hi
    bounds = [None] + roots + [None]
    for k in range(len(bounds) - 1):
        lo, hi = bounds[k], bounds[k + 1]
        pieces.append((region.classify((rational_between(lo, hi),)), lo, hi))
        if hi is not None:
            pieces.append((region.classify((hi,)), hi, hi))
    out: list[Interval] = []
    for regime, lo, hi in pieces:
        point = lo is not None and lo is hi
        if out and out[-1].regime is regime:
            last = out[-1]
            out[-1] = Interval(regime, last.lo, hi, last.lo_closed, point)
        else:
            out.append(Interval(regime, lo, hi, point, point))
    return out


def _paper_points(concrete: Scheme, n: int) -> list[tuple[str, tuple[sp.Expr, sp.Expr]]]:
    """The paper's Section 5.2 tuning at ``n``: on each condition's line, with the scheme's own ``beta``
    (:func:`symdecomp.analysis.tuning.tune` without its valence-free joint obstruction)."""
    from symdecomp.analysis.elliptic import nice_elliptic_conditions
    from symdecomp.analysis.tuning import condition_line, ratio_target
    from symdecomp.symbols import beta as BETA

    beta = sp.sympify(concrete.vertex_rule.each_b, strict=True).subs(N, n)
    out = []
    for k, target in enumerate((nice_elliptic_conditions(concrete).lambda1**2, ratio_target(concrete)), start=1):
        line = condition_line(concrete, target.subs(N, n))
        alpha = sp.radsimp(line.alpha_on_line.subs(BETA, beta).subs(N, n))
        out.append((f"paper 5.2 condition {k}", (alpha, beta)))
    return out


def placed_points(scheme: Scheme, n: int) -> list[tuple[str, tuple[sp.Expr, ...]]]:
    """Published and paper weights at valence ``n`` as parameter values, where the parameters can express them.

    Quads: Catmull-Clark's weights, and the paper's Section 5.2 tuning (:func:`symdecomp.analysis.tuning.tune` on the
    scheme with Catmull-Clark's vertex rule: condition 1 (subdominant eigenvalue of Eq. 43 equal to
    ``lambda_1^2``) and condition 2 (the Eq. 44 ratio), each with Catmull-Clark's ``beta``). Triangles: Loop's
    ``beta`` and Warren's ``3/(8n)`` (``3/16`` at ``n = 3``), as :mod:`symdecomp.schemes.loop` defines them.
    """
    from symdecomp.errors import SymdecompError
    from symdecomp.schemes.loop import loop, loop_warren

    params = _parameters(check_scheme(scheme))
    n = scheme.fitting_valence(check_region_valence(n), real=True)
    ref = scheme.lattice.reference()
    weights = []
    if scheme.lattice.handled("the published vertex weights", BICUBIC, BOX_SPLINE) == BICUBIC:
        weights.append(("Catmull-Clark", _vertex_weights(ref, n, {})))
        concrete = Scheme(scheme.name, scheme.edge_rule, scheme.face_rule, ref.vertex_rule, (), scheme.lattice)
        try:
            weights += _paper_points(concrete, n)
        except SymdecompError:  # not the paper's shape (e.g. rules not mirror-symmetric): nothing to place
            pass
    else:
        weights += [("Loop", _vertex_weights(loop(), n, {})), ("Warren", _vertex_weights(loop_warren(), n, {}))]
    out = []
    for label, (wa, wb) in weights:
        mine = _vertex_weights(scheme, n, {})
        sol = sp.solve([sp.Eq(mine[0], wa), sp.Eq(mine[1], wb)], params, dict=True)
        if len(sol) == 1 and all(v in sol[0] for v in params):
            out.append((label, tuple(sp.radsimp(sol[0][v]) for v in params)))
    return out
