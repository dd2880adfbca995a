"""Elliptic properties (Section 5.2): Eq. 42-45, Proposition 5.2, Remark 5.2.

The heights of ``O``, of the plane of ``A^0`` (centroid of the ``a``'s) and of the plane of
``B^0`` (centroid of the ``b``'s) along the normal move by the ``3 x 3`` matrix ``T`` of Eq. 43
(:func:`symdecomp.analysis.frequency.recursion_matrix`, derived from the rules). A scheme has
*nice elliptic properties* when

1. the subdominant eigenvalue ``mu`` of ``T`` equals ``lambda_1^2``, with ``lambda_1`` the
   dominant eigenvalue of ``M_1`` (Eq. 34 at ``j = 1``), and
2. the ratio ``(u_b - u_O)/(u_a - u_O)`` of Eq. 44 on the subdominant eigenvector ``u``
   equals ``|B^1/A^1|^2``, the square of the scale ratio of Eq. 39.

Everything below is derived from a :class:`~symdecomp.schemes.scheme.Scheme`. A fact that drives
the tuning results (:mod:`symdecomp.analysis.tuning`): rows 2 and 3 of ``T`` come from the edge and
face rules only, so the eigenvector of ``T`` for a given eigenvalue ``mu != 1``, and hence the
ratio of Eq. 44, depends on ``mu`` and the edge and face rules only, never on the vertex rule.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> cc = catmull_clark()
>>> recursion_eigenvector(cc, sp.Rational(1, 4), 4).T
Matrix([[-1/16, 1/32, 1/8]])
>>> eq44_ratio(cc, MU)
8*MU/(8*MU - 1)
>>> nice_elliptic_conditions(cc).subdominant
(3*n + sqrt(5*n**2 - 30*n + 49) - 7)/(8*n)
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import mpmath
import sympy as sp

from symdecomp.algebra.number_field import FieldElement, quadratic_element, quadratic_expression
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.valence_signs import integer_zeros
from symdecomp.analysis.design_input import cross
from symdecomp.analysis.frequency import laurent_to_cos, per_frequency_matrix, recursion_matrix
from symdecomp.analysis.spectrum import format_value, recursion_eigenvalues
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, cos_theta, sin_jtheta
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import cached, check_digits, check_valence

__all__ = [
    "MU",
    "recursion_eigenvector",
    "recursion_left_eigenvector",
    "eq44_ratio",
    "tangent_lambda",
    "scale_ratio_squared",
    "NiceEllipticConditions",
    "nice_elliptic_conditions",
    "EllipticDefectRow",
    "elliptic_defect_table",
    "rotation_free_form",
    "elliptic_component",
    "ComponentResultants",
    "component_resultants",
    "components_nonzero_every_n",
]

#: A symbol for an eigenvalue of the Eq. 43 matrix.
MU = sp.Symbol("MU")


def recursion_eigenvector(scheme: Scheme, eigenvalue=MU, n=N) -> sp.Matrix:
    """An eigenvector ``(u_O, u_a, u_b)`` of the Eq. 43 matrix for ``eigenvalue``.

    Taken as the cross product of rows 2 and 3 of ``T - eigenvalue*I`` (so the first row, the
    vertex rule, is not used: it holds automatically when ``eigenvalue`` is an eigenvalue).
    Zero when those two rows are dependent.
    """
    T = recursion_matrix(scheme, n)
    A = sp.Matrix(T) - eigenvalue * sp.eye(3)
    return sp.Matrix(cross(A.row(1), A.row(2))).applyfunc(sp.expand)


def recursion_left_eigenvector(scheme: Scheme, eigenvalue=MU, n=N) -> sp.Matrix:
    """A left eigenvector ``l`` (``l^T T = eigenvalue l^T``) of the Eq. 43 matrix, as a column.

    The cross product of columns 2 and 3 of ``T - eigenvalue*I``; it gives the component of an
    input on the eigenvector: ``(l . x)/(l . u)``.
    """
    T = recursion_matrix(scheme, n)
    A = sp.Matrix(T) - eigenvalue * sp.eye(3)
    return sp.Matrix(cross(A.col(1), A.col(2))).applyfunc(sp.expand)


def eq44_ratio(scheme: Scheme, eigenvalue=MU, n=N) -> sp.Expr:
    """``(u_b - u_O)/(u_a - u_O)`` of Eq. 44 on the eigenvector for ``eigenvalue`` (``d_b/d_a``)."""
    u = recursion_eigenvector(scheme, eigenvalue, n)
    return sp.factor(sp.cancel((u[2] - u[0]) / (u[1] - u[0])))


def _symmetric_in_cos(expr, what):
    value = laurent_to_cos(expr)
    if value.has(sin_jtheta):
        raise NotApplicableError(
            f"{what} is not symmetric in omega <-> 1/omega; the scheme is not mirror symmetric",
            parts=(what, " is not symmetric under ", OMEGA, " -> ", 1 / OMEGA, "; the scheme is not mirror symmetric"),
        )
    return value


def tangent_lambda(scheme: Scheme, frequency: int = 1) -> sp.Expr:
    """The dominant eigenvalue of ``M_j`` (Eq. 34) as a closed form in ``n``.

    ``frequency = 1`` gives ``lambda_1`` of Section 5.2 (with ``c = cos(pi/n) > 0``);
    ``frequency = 2`` gives the hyperbolic eigenvalue of Section 5.3 (``c = cos(2 pi/n)``).
    """
    dominant = tangent_eigenvalues(scheme).dominant
    c = sp.cos(frequency * sp.pi / N)
    if frequency == 1:
        dominant = dominant.subs(sp.Abs(cos_jtheta), cos_jtheta)
    return dominant.subs(cos_jtheta, c)


@cached(scheme=check_scheme)
def scale_ratio_squared(scheme: Scheme) -> sp.Expr:
    """``|B^1/A^1|^2`` on the dominant eigenvector of ``M_1``, in ``c = cos(pi/n)``.

    The square of the scale ratio of Eq. 39 between ``E_b`` and ``E_a``:
    ``|m_21|^2/(lambda_1 - m_22)^2``, with ``|m_21|^2 = m_21(omega) m_21(1/omega)`` rewritten
    in ``c`` (real-coefficient, mirror-symmetric schemes).
    """
    M = per_frequency_matrix(scheme)
    numerator = _symmetric_in_cos(sp.expand(M[1, 0] * M[1, 0].subs(OMEGA, 1 / OMEGA)), sp.Abs(sp.Symbol("m_21")) ** 2)
    m22 = _symmetric_in_cos(M[1, 1], sp.Symbol("m_22"))
    lam1 = tangent_eigenvalues(scheme).dominant.subs(sp.Abs(cos_jtheta), cos_jtheta)
    # j = 1: c = cos(pi/n) >= 1/2
    return sp.simplify((numerator / (lam1 - m22) ** 2).subs(cos_jtheta, cos_theta)).subs(cos_theta, cos_jtheta)


@dataclass(frozen=True)
class NiceEllipticConditions:
    """The two conditions for nice elliptic properties, as closed forms in ``n`` (Section 5.2)."""

    #: The Eq. 43 matrix, symbolic in ``n`` and the scheme's parameters.
    recursion_matrix: sp.ImmutableMatrix
    #: The subdominant eigenvalue ``mu`` of the Eq. 43 matrix (the ``+sqrt`` root of its quadratic).
    subdominant: sp.Expr
    #: The other non-unit eigenvalue of the Eq. 43 matrix.
    third: sp.Expr
    #: An eigenvector ``(u_O, u_a, u_b)`` for the eigenvalue :data:`MU` (a polynomial in ``MU``).
    eigenvector: sp.Matrix
    #: The ratio of Eq. 44 as a function of the eigenvalue :data:`MU` (no vertex-rule weights).
    eq44_ratio_of_mu: sp.Expr
    #: ``lambda_1(n)``, the dominant eigenvalue of ``M_1`` (Eq. 34, ``c = cos(pi/n)``).
    lambda1: sp.Expr
    #: ``|B^1/A^1|^2(n)``, the squared scale ratio of Eq. 39.
    scale_ratio_squared: sp.Expr
    #: Condition 1's defect: ``mu - lambda_1^2`` (zero when the condition holds).
    eigenvalue_defect: sp.Expr
    #: Condition 2's defect: ``(Eq. 44 ratio at mu) - |B^1/A^1|^2``.
    ratio_defect: sp.Expr


@cached(scheme=check_scheme)
def nice_elliptic_conditions(scheme: Scheme) -> NiceEllipticConditions:
    """Derive both conditions and their defects for ``scheme``, closed forms in ``n``."""
    _, mu, third = recursion_eigenvalues(scheme)
    c = sp.cos(sp.pi / N)
    lam1 = tangent_lambda(scheme, 1)
    ratio_of_mu = eq44_ratio(scheme, MU)
    R = scale_ratio_squared(scheme).subs(cos_jtheta, c)
    return NiceEllipticConditions(
        recursion_matrix=recursion_matrix(scheme),
        subdominant=mu,
        third=third,
        eigenvector=recursion_eigenvector(scheme, MU),
        eq44_ratio_of_mu=ratio_of_mu,
        lambda1=lam1,
        scale_ratio_squared=R,
        eigenvalue_defect=mu - lam1**2,
        ratio_defect=ratio_of_mu.subs(MU, mu) - R,
    )


@dataclass(frozen=True)
class EllipticDefectRow:
    """One valence of the table of distances from nice elliptic behaviour."""

    #: The valence.
    n: int
    #: Subdominant eigenvalue ``mu`` of the Eq. 43 matrix.
    subdominant: object
    #: ``lambda_1^2``.
    lambda1_squared: object
    #: ``mu - lambda_1^2`` (condition 1's defect).
    eigenvalue_defect: object
    #: The Eq. 44 ratio ``d_b/d_a`` at ``mu``.
    eq44_ratio: object
    #: ``|B^1/A^1|^2``.
    scale_ratio_squared: object
    #: ``d_b/d_a - |B^1/A^1|^2`` (condition 2's defect).
    ratio_defect: object
    #: Decimal strings of the six values above, in that order.
    texts: tuple[str, ...]

    def as_json(self) -> dict:
        keys = ("subdominant", "lambda1_squared", "eigenvalue_defect", "eq44_ratio", "scale_ratio_squared", "ratio_defect")
        return {"n": self.n, **dict(zip(keys, self.texts))}


def _value(expr, n: int, dps: int):
    value = sp.N(expr.subs(N, n), dps + 10)
    if value.has(sp.I) or not value.is_real:
        raise ArithmeticError(f"{expr} is not real at n = {n}")
    return mpmath.mpf(sp.Float(value, dps + 10)._mpf_)


def elliptic_defect_table(scheme: Scheme, valences, *, digits: int = 20) -> tuple[EllipticDefectRow, ...]:
    """Evaluate both defects of :func:`nice_elliptic_conditions` for each valence (``digits`` significant).

    The values are mpmath numbers computed at ``digits + 10`` digits; compare them inside a
    ``mpmath.workdps`` block of that precision (arithmetic outside runs at the ambient one).
    ``symdecomp tune N --table`` prints this table for ``n = 3..N``.

    >>> from symdecomp.schemes.scheme import catmull_clark
    >>> [r.texts[2] for r in elliptic_defect_table(catmull_clark(), [3, 4, 5], digits=6)]
    ['-0.00151292', '0.0', '0.0199873']
    """
    if check_scheme(scheme).parameters:
        raise NotApplicableError(f"scheme {scheme.name!r} has free parameters {scheme.parameters}; substitute them first")
    digits = check_digits(digits)
    valences = [check_valence(n) for n in valences]
    cond = nice_elliptic_conditions(scheme)
    exprs = (
        cond.subdominant,
        cond.lambda1**2,
        cond.eigenvalue_defect,
        cond.eq44_ratio_of_mu.subs(MU, cond.subdominant),
        cond.scale_ratio_squared,
        cond.ratio_defect,
    )
    rows = []
    with mpmath.workdps(digits + 10):
        for n in valences:
            n = check_valence(n)
            values = [_value(e, n, digits) for e in exprs]
            rows.append(EllipticDefectRow(n, *values, texts=tuple(format_value(v, digits) for v in values)))
    return tuple(rows)


def rotation_free_form(scheme: Scheme) -> tuple[sp.Matrix, sp.Matrix]:
    """Proposition 5.2 / Eq. 42: ``D^{-1} M_j D`` with ``D = diag(1, omega_2n^j)``, and its imaginary part.

    With ``z = omega_2n^j`` (so ``omega = z^2``), an entry ``e(z)`` with rational coefficients is
    real on the unit circle iff ``e(z) = e(1/z)``. Returns ``(D^{-1} M_j D, e(z) - e(1/z))``;
    Proposition 5.2 holds for the scheme iff the second matrix is zero.
    """
    z = sp.Symbol("z")
    M = per_frequency_matrix(scheme).subs(OMEGA, z**2)
    D = sp.diag(1, z)
    conj = (D.inv() * M * D).applyfunc(sp.expand)
    return conj, conj.applyfunc(lambda e: sp.expand(e - e.subs(z, 1 / z)))


def elliptic_component(scheme: Scheme, n, initial, eigenvalue=None) -> sp.Expr | None:
    """The coefficient of ``initial = (h_O, h_a, h_b)`` on the subdominant eigenvector (Remark 5.2), or ``None``.

    ``(l . x)/(l . u)`` with ``l``, ``u`` the left and right eigenvectors of the Eq. 43 matrix for
    the subdominant eigenvalue (or ``eigenvalue`` if given). The closed-form eigenvectors (cross
    products of two columns and two rows of ``T - mu I``) vanish where those columns or rows are
    dependent (a fixed centre, ``alpha = beta = 0``, makes the left one zero); then the eigenvectors
    are the exact null spaces. ``None`` when no single component exists: the eigenvalue is not simple
    (a null space of dimension 2, or ``l . u = 0``, a Jordan block). A zero vector is never used as an
    eigenvector, so the quotient is never ``0/0``. Symbolic ``n`` (or free parameters) uses the closed
    forms as they are and is ``None`` when they vanish identically.
    """
    if n is not N:
        n = check_valence(n)
    mu = recursion_eigenvalues(scheme)[1].subs(N, n) if eigenvalue is None else eigenvalue
    if n is not N and not scheme.parameters and (value := _component_in_field(scheme, n, initial, mu)) is not None:
        return value
    x = sp.Matrix(initial)
    left = recursion_left_eigenvector(scheme, mu, n)
    right = recursion_eigenvector(scheme, mu, n)
    if sp.simplify(left.dot(right)) != 0:
        return sp.simplify(left.dot(x) / left.dot(right))
    if n is N or scheme.parameters:
        return None
    T = sp.Matrix(recursion_matrix(scheme, n))
    rights, lefts = (T - mu * sp.eye(3)).nullspace(simplify=True), (T.T - mu * sp.eye(3)).nullspace(simplify=True)
    if len(rights) != 1 or len(lefts) != 1:
        return None
    left, right = lefts[0], rights[0]
    denominator = sp.simplify(left.dot(right))
    if denominator == 0:  # a Jordan block: the eigenvector has no complement to project along
        return None
    return sp.simplify(left.dot(x) / denominator)


def _component_in_field(scheme: Scheme, n: int, initial, mu) -> sp.Expr | None:
    """:func:`elliptic_component`'s quotient ``(l . x)/(l . u)`` (the same closed-form eigenvectors) computed exactly in
    ``Q(mu)`` when the Eq. 43 matrix is rational and ``mu = a + b sqrt(d)``; ``None`` outside that field, when the input
    is not rational, or when ``l . u = 0`` (then the caller's exact null spaces decide)."""
    field = quadratic_element(mu)
    T = recursion_matrix(scheme, n)
    if field is None or not all(e.is_Rational for e in T) or not all(sp.sympify(v, strict=True).is_Rational for v in initial):
        return None
    m, root = field

    def const(q) -> FieldElement:
        return FieldElement(flint.fmpq_poly([to_fmpq(q)]), m.modulus)

    A = [[const(T[r, c]) - (m if r == c else const(0)) for c in range(3)] for r in range(3)]
    left = cross([A[r][1] for r in range(3)], [A[r][2] for r in range(3)])
    right = cross(A[1], A[2])
    norm = sum((a * b for a, b in zip(left, right)), const(0))
    if not norm:
        return None
    weight = sum((a * const(v) for a, v in zip(left, initial)), const(0))
    return quadratic_expression(weight * norm.inverse(), root)


@dataclass(frozen=True)
class ComponentResultants:
    """Where the component of an input on an eigenvector of the Eq. 43 matrix can vanish, for every ``n`` at once.

    ``chi(mu) = det(mu I - T)/(mu - 1)`` has the two eigenvalues other than 1 as roots; ``l``, ``u``
    are the left and right eigenvectors as polynomials in ``mu`` (cross products). At a valence where
    ``Res_mu(l . x, chi)`` and ``Res_mu(l . u, chi)`` are nonzero (and no leading coefficient or
    denominator vanishes), both roots ``mu`` are simple, their eigenvectors are nonzero and the
    component ``(l . x)/(l . u)`` of ``x`` is nonzero.
    """

    #: The input ``x = (h_O, h_a, h_b)``.
    initial: tuple
    #: ``chi(mu)``, the non-unit factor of the characteristic polynomial.
    chi: sp.Expr
    #: ``l . x`` as a polynomial in ``mu``.
    weight: sp.Expr
    #: ``Res_mu(l . x, chi)``, a rational function of ``n``.
    resultant_weight: sp.Expr
    #: ``Res_mu(l . u, chi)``.
    resultant_norm: sp.Expr
    #: The integers ``n >= start`` where the argument fails (to be checked one by one), or ``None`` when a
    #: resultant vanishes identically (no argument for every ``n``).
    exceptions: tuple[int, ...] | None


def component_resultants(scheme: Scheme, initial, start: int) -> ComponentResultants:
    """The resultant argument that the component of ``initial`` is nonzero for every valence ``n >= start``.

    Needs rules rational in ``n`` without free parameters (else :class:`~symdecomp.errors.InvalidInputError`
    from :func:`~symdecomp.algebra.valence_signs.integer_zeros`).
    """
    mu = sp.Symbol("mu")
    T = sp.Matrix(recursion_matrix(scheme))
    chi = sp.cancel(sp.expand((mu * sp.eye(3) - T).det()) / (mu - 1))
    left, right = recursion_left_eigenvector(scheme, mu), recursion_eigenvector(scheme, mu)
    weight, norm = sp.expand(left.dot(sp.Matrix(initial))), sp.expand(left.dot(right))
    chi_numerator = sp.numer(sp.together(chi))
    res_w = sp.factor(sp.resultant(weight, chi_numerator, mu))
    res_u = sp.factor(sp.resultant(norm, chi_numerator, mu))
    # the resultant specialises to each valence where the leading coefficients and the denominators do not vanish
    parts = [sp.fraction(sp.together(e)) for e in (chi, weight, norm)]
    coefficients = [sp.Poly(p, mu).LC() for p, _ in parts if p.has(mu)] + [q for _, q in parts]
    bad: set[int] | None = set()
    for e in [res_w, res_u, *coefficients]:
        zeros = integer_zeros(e, N, start)
        if zeros is None:
            bad = None
            break
        bad.update(zeros)
    return ComponentResultants(tuple(initial), chi, weight, res_w, res_u, None if bad is None else tuple(sorted(bad)))


def components_nonzero_every_n(scheme: Scheme, lo: int) -> tuple[tuple[int, ...] | None, str]:
    """Remark 5.2 for every ``n >= lo``: the valences the argument leaves to a direct check, or ``None`` and the reason.

    (1,1,1) is the right eigenvector of 1 when the rows of the Eq. 43 matrix sum to 1 identically (checked), so every
    left eigenvector of an eigenvalue mu != 1 is orthogonal to it; mu = 1 only where chi(1) = 0. (0,1,1) and
    (0,1,-1) have nonzero components on both non-unit eigenvectors off the integer zeros of two resultants
    (:func:`component_resultants`)."""
    if scheme.parameters:
        return None, "the scheme has free parameters"
    T = sp.Matrix(recursion_matrix(scheme))
    if sp.simplify(T * sp.ones(3, 1) - sp.ones(3, 1)) != sp.zeros(3, 1):
        return None, "the rows of the Eq. 43 matrix do not sum to 1"
    bad: set[int] = set()
    try:
        for x in ((0, 1, 1), (0, 1, -1)):
            r = component_resultants(scheme, x, lo)
            if r.exceptions is None:
                return None, "a resultant vanishes identically"
            bad.update(r.exceptions)
            ones = integer_zeros(r.chi.subs(sp.Symbol("mu"), 1), N, lo)
            if ones is None:
                return None, "1 is a double eigenvalue of the Eq. 43 matrix for every n"
            bad.update(ones)
    except InvalidInputError as exc:  # a weight such as cos(2 pi/n): the resultants are not rational in n
        return None, str(exc)
    return tuple(sorted(bad)), ""
