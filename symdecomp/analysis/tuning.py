"""Tuning the vertex rule for nice elliptic properties (Section 5.2, Eq. 16's ``alpha``, ``beta``).

The vertex rule enters only the first row of the Eq. 43 matrix ``T``, and the coefficients
of ``det(lambda I - T)/(lambda - 1) = lambda^2 + p lambda + q`` are linear in its weights.
Hence:

* **condition 1** (subdominant eigenvalue of ``T`` equal to ``lambda_1^2``): ``lambda_1^2`` is a
  root of the quadratic on a *line* in the ``(alpha, beta)`` plane, and it is the subdominant
  eigenvalue on the segment of that line where the other root ``nu`` has ``|nu| < lambda_1^2``;
* **condition 2** (Eq. 44 ratio equal to ``|B^1/A^1|^2``): the ratio on the eigenvector for an
  eigenvalue ``mu`` depends on ``mu`` and the edge and face rules only
  (:func:`symdecomp.analysis.elliptic.eq44_ratio`); solving ``ratio(mu) = |B^1/A^1|^2`` gives one target
  ``mu_2(n)``, and the condition holds on the line (and segment) where ``mu_2`` is subdominant;
* **both**: the subdominant eigenvalue would have to be ``lambda_1^2`` and ``mu_2`` at once, so
  both hold iff ``ratio(lambda_1^2) = |B^1/A^1|^2`` -- an equation in ``n`` alone, which no
  vertex-rule weights can change. For Catmull-Clark it holds only at ``n = 4``
  (:func:`joint_obstruction`); elsewhere the edge and face rules (rows 2-3 of ``T`` and
  ``M_1``) would have to change.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> sorted(joint_obstruction(catmull_clark()).valences)
[4]
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache, cached_property

import mpmath
import sympy as sp

from symdecomp.analysis.elliptic import MU, eq44_ratio, nice_elliptic_conditions
from symdecomp.analysis.frequency import laurent_to_cos, per_frequency_matrix, recursion_matrix, valences_at_roots
from symdecomp.analysis.spectrum import format_value
from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, VertexRule, check_scheme
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import cos_jtheta, cos_theta
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_digits

__all__ = [
    "with_free_vertex_rule",
    "eigenvalue_quadratic",
    "unit_quotient",
    "ConditionLine",
    "condition_line",
    "ratio_target",
    "JointObstruction",
    "joint_obstruction",
    "TuningAtValence",
    "tune",
]


def with_free_vertex_rule(scheme: Scheme) -> Scheme:
    """The scheme with the vertex rule replaced by the free affine rule with weights ``alpha``, ``beta``."""
    return Scheme(scheme.name + " (free vertex rule)", scheme.edge_rule, scheme.face_rule, VertexRule.affine(ALPHA, BETA))


def unit_quotient(T: sp.Matrix) -> sp.Poly:
    """``det(lambda I - T)/(lambda - 1)`` in ``lambda``: the non-unit eigenvalues of a frequency-0 block ``T`` of an affine
    scheme (Eq. 43 on quads), its entries in any symbols (``n``, free weights). The one computation of it, for
    :func:`eigenvalue_quadratic` and :mod:`symdecomp.analysis.tuning_region`."""
    charpoly = sp.Poly(sp.expand((LAM * sp.eye(T.rows) - T).det()), LAM)
    quotient, remainder = sp.div(charpoly, sp.Poly(LAM - 1, LAM))
    if sp.expand(remainder.as_expr()) != 0:  # pragma: no cover - affine rules guarantee it
        raise InvalidSchemeError("the frequency-0 block (Eq. 43) of an affine scheme must have the eigenvalue 1")
    return quotient


@cached(scheme=check_scheme)
def eigenvalue_quadratic(scheme: Scheme) -> sp.Poly:
    """``det(lambda I - T)/(lambda - 1)`` for the Eq. 43 matrix with a free vertex rule, in ``lambda``."""
    return sp.Poly(sp.expand(unit_quotient(recursion_matrix(with_free_vertex_rule(scheme))).as_expr()), LAM)


@dataclass(frozen=True)
class ConditionLine:
    """The vertex-rule weights for which ``target`` is the subdominant eigenvalue of Eq. 43."""

    #: The eigenvalue the condition asks for, a closed form in ``n``.
    target: sp.Expr
    #: ``Q(target) = 0`` (``Q`` the quadratic of :func:`eigenvalue_quadratic`): linear in ``alpha``, ``beta``.
    equation: sp.Equality
    #: ``alpha`` on the line, as a function of ``n`` and ``beta``.
    alpha_on_line: sp.Expr
    #: The other non-unit eigenvalue ``nu`` of Eq. 43 on the line, in ``n`` and ``beta``.
    other_eigenvalue: sp.Expr
    #: The two values of ``beta`` where ``nu = target`` and ``nu = -target``; between them ``|nu| < target``.
    beta_bounds: tuple[sp.Expr, sp.Expr]


@cache
def _generic_line(scheme: Scheme) -> ConditionLine:
    Q = eigenvalue_quadratic(scheme)
    equation = sp.expand(Q.as_expr().subs(LAM, MU))
    alpha_on_line = sp.solve(equation, ALPHA)
    if len(alpha_on_line) != 1:
        raise InvalidSchemeError(f"the condition does not determine alpha from beta: {alpha_on_line}")
    alpha_on_line = sp.factor(alpha_on_line[0])
    _, p, _q = Q.all_coeffs()  # monic: lambda^2 + p lambda + q
    nu = sp.factor(sp.expand(-p.subs(ALPHA, alpha_on_line) - MU))
    bounds = []
    for value in (MU, -MU):
        sol = sp.solve(sp.Eq(nu, value), BETA)
        if len(sol) != 1:
            raise InvalidSchemeError(f"the other eigenvalue does not depend on beta along the line: {nu}")
        bounds.append(sp.factor(sol[0]))
    return ConditionLine(MU, sp.Eq(equation, 0), alpha_on_line, nu, tuple(bounds))


def condition_line(scheme: Scheme, target: sp.Expr = MU) -> ConditionLine:
    """The line of weights making ``target`` an eigenvalue of Eq. 43, and where it is subdominant.

    Derived once with a symbolic eigenvalue :data:`~symdecomp.analysis.elliptic.MU`, then ``target`` is
    substituted (``target`` may be a closed form in ``n``, or a value at one valence).
    """
    g = _generic_line(scheme)
    s = {MU: target}
    return ConditionLine(
        target,
        sp.Eq(g.equation.lhs.subs(s), 0),
        g.alpha_on_line.subs(s),
        g.other_eigenvalue.subs(s),
        tuple(b.subs(s) for b in g.beta_bounds),
    )


@cached(scheme=check_scheme)
def ratio_target(scheme: Scheme) -> sp.Expr:
    """The eigenvalue ``mu_2(n)`` whose Eq. 44 ratio equals ``|B^1/A^1|^2`` (condition 2's target)."""
    R = sp.Symbol("R", positive=True)
    solutions = sp.solve(sp.Eq(eq44_ratio(scheme, MU), R), MU)
    if len(solutions) != 1:
        raise InvalidSchemeError(f"the Eq. 44 ratio does not determine the eigenvalue uniquely: {solutions}")
    return solutions[0].subs(R, nice_elliptic_conditions(scheme).scale_ratio_squared)


@dataclass(frozen=True)
class JointObstruction:
    """Why both conditions cannot be met by the vertex rule, except at finitely many valences."""

    #: ``ratio(lambda_1^2) - |B^1/A^1|^2`` in ``n`` as derived (see :attr:`defect`).
    derived_defect: sp.Expr
    #: A polynomial in ``c = cos(pi/n)`` vanishing wherever the defect does (a resultant).
    polynomial: sp.Expr
    #: Its real roots ``c`` in ``[1/2, 1)`` (``cos(pi/n)`` for ``n >= 3``), as exact algebraic numbers.
    roots: tuple[sp.Expr, ...]
    #: The valences at which the defect vanishes exactly (both conditions are achievable).
    valences: tuple[int, ...]

    @cached_property
    def defect(self) -> sp.Expr:
        """``ratio(lambda_1^2) - |B^1/A^1|^2`` in ``n``, simplified: vertex-rule free; both conditions need it zero.

        Simplified when first read (sympy's ``simplify`` takes about a second; the claims read only the valences)."""
        return sp.simplify(self.derived_defect)


@cached(scheme=check_scheme)
def joint_obstruction(scheme: Scheme) -> JointObstruction:
    """Decide for every ``n`` whether both conditions can hold together.

    The defect ``g = ratio(L^2) - |m_21|^2/(L - m_22)^2`` is written with a symbol ``L`` for
    ``lambda_1`` and ``c`` for ``cos(pi/n)``; the resultant in ``L`` of its numerator and the
    characteristic polynomial of ``M_1`` is a polynomial in ``c`` that vanishes wherever ``g``
    does. Its roots in ``[1/2, 1)`` are the only candidates; each is tested exactly.
    """
    c = cos_theta
    L = sp.Symbol("L", positive=True)
    M = per_frequency_matrix(scheme)
    m21sq = laurent_to_cos(sp.expand(M[1, 0] * M[1, 0].subs(OMEGA, 1 / OMEGA)))
    m22 = laurent_to_cos(M[1, 1])
    trace = laurent_to_cos(M.trace())
    det = laurent_to_cos(sp.expand(M.det()))
    g = sp.together(eq44_ratio(scheme, MU).subs(MU, L**2) - m21sq / (L - m22) ** 2).subs(cos_jtheta, c)
    numerator = sp.numer(g)
    charpoly = (L**2 - trace * L + det).subs(cos_jtheta, c)
    polynomial = sp.factor(sp.resultant(sp.expand(numerator), sp.expand(charpoly), L))
    cond = nice_elliptic_conditions(scheme)
    defect = cond.eq44_ratio_of_mu.subs(MU, cond.lambda1**2) - cond.scale_ratio_squared
    roots, valences = valences_at_roots(polynomial, c, lambda k: sp.simplify(defect.subs(N, k)) == 0)
    return JointObstruction(defect, polynomial, roots, valences)


@dataclass(frozen=True)
class TuningAtValence:
    """The tuning results at one valence (``symdecomp tune N``)."""

    #: The valence.
    n: int
    #: ``lambda_1``, dominant eigenvalue of ``M_1`` (exact).
    lambda1: sp.Expr
    #: ``|B^1/A^1|^2`` (exact).
    scale_ratio_squared: sp.Expr
    #: The scheme's own ``(alpha, beta)``.
    standard: tuple[sp.Expr, sp.Expr]
    #: Condition 1 alone: the line, with ``target = lambda_1^2``.
    eigenvalue_condition: ConditionLine
    #: Condition 2 alone: the line, with ``target = mu_2``.
    ratio_condition: ConditionLine
    #: ``(alpha, beta)`` on each line with the scheme's own ``beta`` kept, in the order of the two conditions.
    at_standard_beta: tuple[tuple[sp.Expr, sp.Expr], tuple[sp.Expr, sp.Expr]]
    #: Whether the scheme's own ``beta`` lies strictly inside each line's admissible segment.
    standard_beta_admissible: tuple[bool, bool]
    #: Whether each target is below ``lambda_1`` (else the tangent-plane eigenvalue is no longer subdominant).
    below_lambda1: tuple[bool, bool]
    #: Whether both conditions can hold together at this valence.
    jointly_possible: bool
    #: The joint defect ``ratio(lambda_1^2) - |B^1/A^1|^2`` at this valence (zero iff jointly possible).
    joint_defect: sp.Expr
    #: ``alpha`` on a condition's line as a function of its target eigenvalue ``MU`` and ``beta``, at this ``n``.
    alpha_on_line_in_mu: sp.Expr

    def as_json(self, digits: int = 20) -> dict:
        digits = check_digits(digits)

        def num(e):
            with mpmath.workdps(digits + 10):
                return format_value(mpmath.mpf(sp.Float(sp.N(e, digits + 10), digits + 10)._mpf_), digits)

        def line(cl: ConditionLine, point, admissible, below):
            return {
                "target": num(cl.target),
                "alpha": num(point[0]),
                "beta": num(point[1]),
                "beta_interval": sorted((num(b) for b in cl.beta_bounds), key=float),
                "standard_beta_admissible": admissible,
                "target_below_lambda1": below,
                "line": f"alpha = {sp.sstr(self.alpha_on_line_in_mu)} with MU = target",
            }

        return {
            "n": self.n,
            "lambda1": num(self.lambda1),
            "lambda1_squared": num(self.lambda1**2),
            "scale_ratio_squared": num(self.scale_ratio_squared),
            "standard": {"alpha": str(self.standard[0]), "beta": str(self.standard[1])},
            "eigenvalue_condition": line(
                self.eigenvalue_condition, self.at_standard_beta[0], self.standard_beta_admissible[0], self.below_lambda1[0]
            ),
            "ratio_condition": line(self.ratio_condition, self.at_standard_beta[1], self.standard_beta_admissible[1], self.below_lambda1[1]),
            "jointly_possible": self.jointly_possible,
            "joint_defect": num(self.joint_defect),
        }


def _less(a, b) -> bool:
    with mpmath.workdps(60):
        x = mpmath.mpf(sp.Float(sp.N(a, 70), 70)._mpf_)
        y = mpmath.mpf(sp.Float(sp.N(b, 70), 70)._mpf_)
        return bool(x < y)


def tune(scheme: Scheme, n: int) -> TuningAtValence:
    """Tune the vertex rule of ``scheme`` at valence ``n`` for each condition alone and for both."""
    n = check_scheme(scheme).fitting_valence(n)  # the stencils fit, and every weight is defined and real at n
    if scheme.parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters {scheme.parameters}; tune a concrete scheme")
    cond = nice_elliptic_conditions(scheme)
    lam1 = cond.lambda1.subs(N, n)
    R = cond.scale_ratio_squared.subs(N, n)
    std_beta = scheme.vertex_rule.each_b.subs(N, n)
    std_alpha = scheme.vertex_rule.each_a.subs(N, n)
    lines, points, admissible, below = [], [], [], []
    for target in (cond.lambda1**2, ratio_target(scheme)):
        at_n = condition_line(scheme, target.subs(N, n))
        at_n = ConditionLine(
            at_n.target,
            sp.Eq(at_n.equation.lhs.subs(N, n), 0),
            at_n.alpha_on_line.subs(N, n),
            at_n.other_eigenvalue.subs(N, n),
            tuple(b.subs(N, n) for b in at_n.beta_bounds),
        )
        lines.append(at_n)
        points.append((at_n.alpha_on_line.subs(BETA, std_beta), std_beta))
        lo, hi = sorted(at_n.beta_bounds, key=lambda b: float(sp.N(b, 30)))
        admissible.append(_less(lo, std_beta) and _less(std_beta, hi))
        below.append(_less(at_n.target, lam1))
    joint = joint_obstruction(scheme)
    return TuningAtValence(
        n=n,
        lambda1=lam1,
        scale_ratio_squared=R,
        standard=(std_alpha, std_beta),
        eigenvalue_condition=lines[0],
        ratio_condition=lines[1],
        at_standard_beta=(points[0], points[1]),
        standard_beta_admissible=(admissible[0], admissible[1]),
        below_lambda1=(below[0], below[1]),
        jointly_possible=n in joint.valences,
        joint_defect=joint.defect.subs(N, n),
        alpha_on_line_in_mu=_generic_line(scheme).alpha_on_line.subs(N, n),
    )
