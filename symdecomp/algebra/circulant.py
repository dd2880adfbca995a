"""Circulant matrices and the Fourier matrix (Section 2: Eq. 2, 7, 8, 9; Proposition 2.1).

Convention (Eq. 7): ``circ(c_0, ..., c_{n-1})`` has entry ``c_{(s-r) mod n}`` in row ``r``,
column ``s``. A circulant with a fixed set of nonzero diagonals is described, for symbolic
``n``, by its *offsets*: ``{k: c_k}`` with ``k`` possibly negative (``c_{n-1}`` is offset
``-1``). Its eigenvalue on the regular polygon ``v_j`` is the generating polynomial (Eq. 9)
evaluated at ``omega = omega_n^j``, a Laurent polynomial in ``omega``.

>>> circ([sp.Rational(1, 2), 0, 0, sp.Rational(1, 2)]).tolist()
[[1/2, 0, 0, 1/2], [1/2, 1/2, 0, 0], [0, 1/2, 1/2, 0], [0, 0, 1/2, 1/2]]
>>> generating_polynomial({0: sp.Rational(1, 2), -1: sp.Rational(1, 2)})
1/2 + 1/(2*omega)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy as sp

from symdecomp.errors import InvalidInputError, InvalidSchemeError
from symdecomp.expressions import exact_value
from symdecomp.symbols import n as N
from symdecomp.symbols import omega as OMEGA
from symdecomp.validate import check_int, check_valence

__all__ = [
    "coefficient",
    "root_of_unity",
    "fourier_matrix",
    "fourier_row",
    "circ",
    "circ_from_offsets",
    "generating_polynomial",
    "circulant_eigenvalue",
    "mode_eigenvalue_derivation",
]


#: Names a coefficient given as text may use: the valence ``n``.
COEFFICIENT_SYMBOLS = {"n": N}


def coefficient(value, argument: str) -> sp.Expr:
    """An exact coefficient: numbers, sympy expressions, or text parsed by :func:`symdecomp.expressions.parse_expression`.

    Text is never evaluated; a symbol named ``n`` is the valence. Other symbols are free.

    >>> coefficient("3/8", "c_0")
    3/8
    """
    return exact_value(value, COEFFICIENT_SYMBOLS, argument=argument, other_symbols=True)


def _sequence(values, argument: str) -> list:
    if isinstance(values, (str, bytes, Mapping, sp.Expr)) or not hasattr(values, "__iter__"):
        raise InvalidInputError(f"{argument} must be a sequence, got {type(values).__name__}")
    return list(values)


def _offsets(offsets) -> dict:
    """Offsets ``{k: c_k}`` with integer keys and exact coefficients."""
    if not isinstance(offsets, Mapping):
        raise InvalidInputError(f"offsets must be a mapping {{offset: coefficient}}, got {type(offsets).__name__}")
    return {check_int(k, "offset"): coefficient(w, f"offset {k!r}") for k, w in offsets.items()}


def root_of_unity(n: int, power: int = 1) -> sp.Expr:
    """``omega_n^power = exp(2*pi*i*power/n)`` (Eq. 3), exact."""
    n = check_valence(n, minimum=1)
    power = check_int(power, "power")
    return sp.exp(2 * sp.pi * sp.I * sp.Rational(power % n, n))


def fourier_row(n: int, k: int) -> list[sp.Expr]:
    """Row ``k`` of the Fourier matrix ``F_n`` (Eq. 2): the regular n-gon ``v_k``, exact.

    >>> fourier_row(4, 1)
    [1, I, -1, -I]
    """
    n = check_valence(n, minimum=1)
    return [root_of_unity(n, k * m) for m in range(n)]


def fourier_matrix(n: int) -> sp.ImmutableMatrix:
    """The Fourier matrix ``F_n`` of Eq. 2: row ``k`` is the regular n-gon ``v_k``."""
    n = check_valence(n, minimum=1)
    return sp.ImmutableMatrix([fourier_row(n, k) for k in range(n)])


def circ(c: Sequence) -> sp.ImmutableMatrix:
    """``circ(c_0, ..., c_{n-1})`` with the convention of Eq. 7."""
    c = [coefficient(x, f"circ: c_{i}") for i, x in enumerate(_sequence(c, "circ: the coefficients"))]
    size = len(c)
    if size == 0:
        raise InvalidSchemeError("circ needs at least one coefficient")
    return sp.ImmutableMatrix(size, size, lambda r, s: c[(s - r) % size])


def circ_from_offsets(offsets: Mapping[int, object], n: int) -> sp.ImmutableMatrix:
    """The ``n x n`` circulant with ``c_{k mod n} = offsets[k]``; offsets must be distinct mod ``n``."""
    n = check_valence(n, minimum=1)
    c = [sp.Integer(0)] * n
    seen: dict[int, int] = {}
    for k, w in _offsets(offsets).items():
        if k % n in seen:
            raise InvalidSchemeError(f"offsets {seen[k % n]} and {k} coincide mod n = {n}")
        seen[k % n] = k
        c[k % n] = coefficient(w, f"offset {k}")
    return circ(c)


def generating_polynomial(offsets: Mapping[int, object], variable: sp.Symbol = OMEGA) -> sp.Expr:
    """The generating polynomial of Eq. 9, ``p(z) = sum_k c_k z^k``, as a Laurent polynomial."""
    return sp.Add(*[w * variable**k for k, w in _offsets(offsets).items()])


def mode_eigenvalue_derivation(offsets: Mapping[int, object]) -> tuple[sp.Expr, sp.Expr]:
    """Apply a circulant with the given offsets to the mode ``v_j`` at a symbolic row ``i``.

    Returns ``(row_i, eigenvalue)`` where ``row_i = sum_k c_k omega^(i+k)`` is row ``i`` of
    ``C v_j`` (``omega = omega_n^j``; ``omega^n = 1`` makes the wrap-around of indices mod ``n``
    invisible) and ``eigenvalue = row_i / omega^i``. The eigenvalue is free of ``i``: that is
    Proposition 2.1 for every ``n``.
    """
    i = sp.Symbol("i", integer=True)
    row = sp.Add(*[w * OMEGA ** (i + k) for k, w in _offsets(offsets).items()])
    return row, sp.expand(sp.powsimp(sp.expand(row / OMEGA**i)))


def circulant_eigenvalue(offsets: Mapping[int, object], n: int, k: int) -> sp.Expr:
    """The eigenvalue of ``circ_from_offsets(offsets, n)`` on ``v_k`` (Eq. 8), exact."""
    n = check_valence(n, minimum=1)
    k = check_int(k, "frequency k")
    return sp.expand(generating_polynomial(offsets).subs(OMEGA, root_of_unity(n, k)))
