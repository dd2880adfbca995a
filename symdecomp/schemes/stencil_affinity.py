"""Affinity of a zoo scheme's rules: each rule's weights sum to 1 wherever it can apply.

A rule of a :class:`~symdecomp.schemes.stencils.StencilScheme` is affine when its weights sum to 1 at
every valence ``n`` of the anchor's origin and every size ``m`` of the anchor's face it can meet: a
term over ``"one"`` gives its weight, a term over ``"ring"`` the sum of its weight over ``j = 0..n-1``,
a term over ``"face"`` the sum over ``j = 0..m-1``.

The sum is taken in closed form when each weight is a sum of products of a factor free of ``j`` and one
of ``1``, a polynomial in ``j``, ``cos``/``sin`` of ``2 pi a j/L`` (``a`` an integer, ``L`` the family's
size: the sum is ``0`` once ``L`` exceeds ``|a|``) or ``KroneckerDelta(j, e)`` (``1`` when ``0 <= e < L``),
and the total minus 1 is then an identity in ``n`` and ``m``
(:func:`symdecomp.expressions.identically_zero`); the few sizes below the closed form's validity are
checked one by one. Any other weight is checked exactly, one valence at a time, in a cyclotomic field
(:func:`symdecomp.algebra.cyclotomic.cyclotomic_value`), at :data:`CHECKED_SIZES`.

>>> import sympy as sp
>>> from symdecomp.schemes.stencils import J, M, Term, Rule
>>> corner = Term(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), over="face")
>>> rule_sum(Rule((corner,)))
1
>>> check_affine(Rule((corner,)), where="[[corner]] 1", valences=[4], face_sizes=range(3, 9))
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import sympy as sp

from symdecomp.algebra.cyclotomic import CyclotomicField, cyclotomic_value
from symdecomp.errors import NotAffineError
from symdecomp.expressions import identically_zero
from symdecomp.schemes.stencils import J, M, N, Rule, Term

__all__ = ["CHECKED_SIZES", "rule_sum", "check_affine"]

#: The valences and face sizes at which a sum without a closed form is checked, one by one.
CHECKED_SIZES = range(3, 65)


def _family_size(term: Term) -> sp.Expr | None:
    return {"ring": N, "face": M}.get(term.over)


def _closed_sum(weight: sp.Expr, size: sp.Symbol) -> tuple[sp.Expr, int] | None:
    """``sum_{j=0}^{size-1} weight`` in closed form, and the least size from which it holds; None if there is none."""
    total, least = sp.Integer(0), 1
    for part in sp.Add.make_args(sp.expand(weight)):
        coefficient, factor = part.as_independent(J, as_Add=False)
        if factor == 1 or (factor.is_polynomial(J) and not factor.has(sp.cos, sp.sin, sp.KroneckerDelta)):
            total += coefficient * sp.summation(factor, (J, 0, size - 1))
        elif isinstance(factor, (sp.cos, sp.sin)):
            a = sp.cancel(factor.args[0] * size / (2 * sp.pi * J))
            if not a.is_Integer:
                return None
            if a == 0:  # pragma: no cover - sympy folds cos(0) and sin(0) before this
                total += coefficient * size * (factor.func == sp.cos)
            least = max(least, abs(int(a)) + 1)
        elif isinstance(factor, sp.KroneckerDelta) and J in factor.args:
            e = factor.args[1] if factor.args[0] == J else factor.args[0]
            if e.is_Integer and e >= 0:
                least = max(least, int(e) + 1)
            elif (size - e).is_Integer and size - e >= 1:
                least = max(least, int(size - e))
            else:
                return None
            total += coefficient
        else:
            return None
    return total, least


def rule_sum(rule: Rule) -> sp.Expr | None:
    """The sum of the rule's weights in closed form in ``n`` and ``m`` (valid for the sizes that are not too small),
    or None when a weight has no closed sum here (it is then checked valence by valence)."""
    total = sp.Integer(0)
    for term in rule.terms:
        size = _family_size(term)
        if size is None:
            total += term.weight
            continue
        closed = _closed_sum(term.weight, size)
        if closed is None:
            return None
        total += closed[0]
    return total


def _least_sizes(rule: Rule) -> float:
    """The least family size from which :func:`rule_sum` holds (infinite when it has no closed form)."""
    least: float = 1
    for term in rule.terms:
        size = _family_size(term)
        if size is not None:
            closed = _closed_sum(term.weight, size)
            least = max(least, closed[1] if closed else math.inf)
    return least


def _sum_at(rule: Rule, n: int, m: int) -> sp.Expr:
    """The exact sum of the rule's weights at valence ``n`` and face size ``m`` (a cyclotomic number, as sympy)."""
    points = [(term.weight, {N: n, M: m, J: j}) for term in rule.terms for j in range({"ring": n, "face": m}.get(term.over, 1))]
    field = CyclotomicField(math.lcm(*(cyclotomic_value(w, at).field.N for w, at in points)))
    total = field(0)
    for w, at in points:
        total = total + cyclotomic_value(w, at, field=field)
    return total.to_sympy()


def check_affine(rule: Rule, *, where: str, valences: Iterable[int] = CHECKED_SIZES, face_sizes: Iterable[int] = CHECKED_SIZES) -> None:
    """Raise :class:`~symdecomp.errors.NotAffineError` naming ``where`` unless the rule's weights sum to 1.

    ``valences`` and ``face_sizes`` are the ``n`` and ``m`` the rule can meet, the first of each its usual one; the
    closed form is an identity for all of them at once, the sizes below its validity are checked one by one (and, when
    it has none, the valences with the first face size, the face sizes with the first valence, and ``m = n``).
    """
    valences, face_sizes = list(valences), list(face_sizes)
    total = rule_sum(rule)
    fixed = valences if len(valences) == 1 else [None]  # a rule for one valence sums to 1 there, not for every n
    for n in fixed:
        at = total if total is None or n is None else total.subs(N, n)
        if at is not None and not identically_zero(at - 1):
            shown = sp.factor(at)
            raise NotAffineError(f"{where}: not affine: the weights sum to {shown}{'' if n is None else f' at n = {n}'}, not 1")
    least = _least_sizes(rule) if total is not None else math.inf
    ring = any(t.over == "ring" for t in rule.terms)
    face = any(t.over == "face" for t in rule.terms)
    uses_n = ring or any(t.weight.has(N) for t in rule.terms)
    uses_m = face or any(t.weight.has(M) for t in rule.terms)
    n_range = valences if uses_n else valences[:1]
    m_range = face_sizes if uses_m else face_sizes[:1]
    pairs = {(n, m) for n in n_range for m in m_range if m == n or n == n_range[0] or m == m_range[0]}
    for n, m in sorted(pairs):
        if (not ring or n >= least) and (not face or m >= least):
            continue  # the closed form holds there
        value = _sum_at(rule, n, m)
        if value != 1:
            raise NotAffineError(f"{where}: not affine: the weights sum to {value} at n = {n}, m = {m}, not 1")
