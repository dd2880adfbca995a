"""The symbol of a face or ring family of weights, summed exactly for every size: closed forms in ``m``.

A term ``Term(w(m, j), over="face")`` (or ``over="ring"`` with ``n``) weighs the ``m`` corners of a face
with ``w(m, j)``; on the face's corners the rule is the circulant with first row ``w(m, 0..m-1)``, whose
eigenvalue at frequency ``k`` is the *symbol* ``sum_j w(m, j) omega^(jk)`` (``omega = e^(2 pi i/m)``).
For a trigonometric polynomial in ``2 pi j/m`` the sum is exact for every ``m`` by orthogonality:

* ``c(m)`` (no ``j``) gives ``m c(m)`` at ``k = 0``;
* ``c(m) cos(2 pi p j/m)`` gives ``m c(m)/2`` at ``k = p`` and at ``k = -p`` (``m c(m)`` when ``p = -p``);
* ``c(m) sin(2 pi p j/m)`` gives ``m c(m)/(2i)`` at ``k = -p`` and its negative at ``k = p``;
* ``c(m) KroneckerDelta(j, 0)`` gives ``c(m)`` at every ``k``.

The result is a value for every frequency and the exceptions at ``k = 0, +-p``, valid for every ``m``
larger than twice the largest ``p`` (so that ``0, p, -p`` are distinct modulo ``m``). Doo and Sabin's
corner rule has the symbol 1 at ``k = 0``, 1/2 at ``k = +-1`` and 1/4 otherwise, for every ``m >= 3``:

>>> import sympy as sp
>>> from symdecomp.schemes.stencils import J, M
>>> s = family_symbol(sp.KroneckerDelta(J, 0) / 4 + (3 + 2 * sp.cos(2 * sp.pi * J / M)) / (4 * M), M)
>>> s.otherwise, s.at, s.valid_from
(1/4, {-1: 1/2, 0: 1, 1: 1/2}, 3)
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from symdecomp.errors import NotApplicableError
from symdecomp.schemes.stencils import J

__all__ = ["FamilySymbol", "family_symbol"]


@dataclass(frozen=True)
class FamilySymbol:
    """``sum_j w(m, j) omega^(jk)`` for every size ``m`` (a symbol) and frequency ``k``."""

    #: The size symbol (``m`` of a face, ``n`` of a ring).
    size: sp.Symbol
    #: The value at a frequency ``k`` not in :attr:`at`.
    otherwise: sp.Expr
    #: ``{k: value}`` at the exceptional frequencies (``k`` modulo the size, as a signed integer).
    at: dict[int, sp.Expr]
    #: The smallest size for which the exceptional frequencies are distinct.
    valid_from: int

    def value(self, k: int) -> sp.Expr:
        """The symbol at frequency ``k`` (a signed integer, ``|k| <`` half the size)."""
        return self.at.get(k, self.otherwise)


def _frequency(arg: sp.Expr, size: sp.Symbol) -> int:
    """``p`` with ``arg = 2 pi p j/size``; :class:`NotApplicableError` otherwise."""
    p = sp.simplify(arg * size / (2 * sp.pi * J))
    if not p.is_Integer:
        raise NotApplicableError(f"{arg} is not 2 pi p j/{size} with an integer p")
    return int(p)


def _term(term: sp.Expr, size: sp.Symbol) -> dict[int | None, sp.Expr]:
    """The contributions of one term: ``{k: value}``, with ``None`` for every ``k``."""
    delta = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.KroneckerDelta)]
    trig = [f for f in sp.Mul.make_args(term) if isinstance(f, (sp.cos, sp.sin)) and f.has(J)]
    rest = sp.Mul(*[f for f in sp.Mul.make_args(term) if f not in delta and f not in trig])
    if rest.has(J) or len(trig) > 1 or len(delta) > 1 or (delta and (trig or set(delta[0].args) != {J, 0})):
        raise NotApplicableError(f"the term {term} is not c(m), c(m) KroneckerDelta(j, 0) or c(m) cos/sin(2 pi p j/m)")
    if delta:
        return {None: rest}
    if not trig:
        return {0: size * rest}
    p = _frequency(trig[0].args[0], size)
    if isinstance(trig[0], sp.cos):
        return {p: size * rest / 2, -p: size * rest / 2} if p else {0: size * rest}
    return {-p: size * rest / (2 * sp.I), p: -size * rest / (2 * sp.I)} if p else {}


def family_symbol(weight: sp.Expr, size: sp.Symbol) -> FamilySymbol:
    """The symbol of the family with weights ``weight`` (in ``j`` and ``size``), exactly for every size (module docstring)."""
    otherwise = sp.Integer(0)
    at: dict[int, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(weight)):
        for k, value in _term(term, size).items():
            if k is None:
                otherwise += value
            else:
                at[k] = at.get(k, 0) + value
    at = {k: sp.simplify(v + otherwise) for k, v in sorted(at.items())}
    p = max((abs(k) for k in at), default=0)
    return FamilySymbol(size, sp.simplify(otherwise), at, max(3, 2 * p + 1))
