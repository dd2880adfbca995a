"""The subdivision matrix in exact rational arithmetic (FLINT), built straight from the rules.

:func:`symdecomp.schemes.scheme.subdivision_matrix` builds a sympy matrix: right for derivations,
but a dense symbolic ``(2n+1) x (2n+1)`` matrix is slow and large at ``n = 256``. Here the
same matrix is built as a ``flint.fmpq_mat``: each weight of the scheme is evaluated once at
the valence (and at the given parameter values), exactly, and the entries come from the one
assembly of the matrix, :func:`~symdecomp.schemes.scheme.subdivision_entries`, without any
circulant or block structure.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> S = exact_subdivision_matrix(catmull_clark(), 4)
>>> S[0, 0], S[0, 1], S[0, 5]
(9/16, 3/32, 1/64)
>>> characteristic_polynomial(catmull_clark(), 3).degree()
7
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import flint
import sympy as sp

from symdecomp import validate
from symdecomp.algebra.compile import compile_expression
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.errors import InvalidSchemeError, UnsupportedExpressionError
from symdecomp.schemes.scheme import WEIGHT_SYMBOLS, Scheme, check_scheme, subdivision_entries
from symdecomp.symbols import n as N
from symdecomp.validate import check_memory, check_valence

__all__ = [
    "parameter_values",
    "exact_weight",
    "sparse_subdivision_matrix",
    "exact_subdivision_matrix",
    "characteristic_polynomial",
    "entries_characteristic_polynomial",
]


def parameter_values(scheme: Scheme, parameters: Mapping | None) -> dict:
    """Values for the scheme's free parameters as a sympy substitution (keys may be names).

    Raises :class:`~symdecomp.errors.InvalidSchemeError` naming the parameters left without
    a value or given a value that is not an exact number (see :func:`symdecomp.validate.parameter_values`).
    """
    return validate.parameter_values(scheme.parameters, parameters, owner=f"scheme {scheme.name!r}",
                                     symbols=WEIGHT_SYMBOLS)


def exact_weight(weight: sp.Expr, n: int, subs: Mapping) -> flint.fmpq:
    """One weight of a rule at valence ``n`` as an exact ``fmpq``."""
    value = weight.subs({N: n, **subs}) if weight.free_symbols else weight
    if not value.is_Rational and value.is_number:
        value = sp.simplify(value)  # e.g. a parameter value written as an unevaluated expression
    if not value.is_Rational:
        raise InvalidSchemeError(
            f"weight {weight} is not rational at n = {n} (it is {value}); the exact checks need rational weights"
        )
    return to_fmpq(value)


_RULE_CACHE: dict = {}


def _weight_evaluator(scheme: Scheme, subs: Mapping):
    """A function ``weight -> fmpq`` at a valence, compiled once per scheme (exact throughout).

    Weights are rational functions of ``n`` and the parameters; they are compiled to exact
    FLINT arithmetic. A weight that is not (e.g. with a square root of a parameter value) is
    evaluated by sympy instead.
    """
    cached = _RULE_CACHE.get(id(scheme))
    if cached is None or cached[0] is not scheme:
        cached = (scheme, {})
        _RULE_CACHE[id(scheme)] = cached
    compiled = cached[1]
    variables = (N, *scheme.parameters)
    values = []
    for p in scheme.parameters:
        value = sp.sympify(subs[p], strict=True)
        values.append(to_fmpq(value) if value.is_Rational else None)

    def at(n: int):
        args = (flint.fmpq(n), *values)

        def w(expr):
            if None not in values:
                if expr not in compiled:
                    try:
                        compiled[expr] = compile_expression(expr, variables, "fmpq")
                    except UnsupportedExpressionError:
                        compiled[expr] = None
                f = compiled[expr]
                if f is not None:
                    try:
                        return f(*args)
                    except (UnsupportedExpressionError, ZeroDivisionError):
                        pass
            return exact_weight(expr, n, subs)

        return w

    return at


def sparse_subdivision_matrix(scheme: Scheme, n: int, parameters: Mapping | None = None) -> dict:
    """The nonzero entries ``{(row, column): fmpq}`` of the subdivision matrix, from the rules.

    :func:`symdecomp.schemes.scheme.subdivision_entries` with each weight evaluated exactly
    as a FLINT rational: ``O(n)`` entries, no block structure.
    """
    n = check_scheme(scheme).fitting_valence(n)
    subs = parameter_values(scheme, parameters)
    return subdivision_entries(scheme, n, _weight_evaluator(scheme, subs)(n))


def exact_subdivision_matrix(scheme: Scheme, n: int, parameters: Mapping | None = None) -> flint.fmpq_mat:
    """The ``(2n+1) x (2n+1)`` subdivision matrix as a ``flint.fmpq_mat``, from the rules.

    Equal entry for entry to :func:`symdecomp.schemes.scheme.subdivision_matrix` (the tests check
    that). Memory is that of ``(2n+1)^2`` small rationals; no symbolic matrix is built.
    """
    size = 2 * check_valence(n) + 1
    check_memory(size * size * 64, f"the exact {size} x {size} subdivision matrix")
    S = flint.fmpq_mat(size, size)
    for (r, c), x in sparse_subdivision_matrix(scheme, n, parameters).items():
        S[r, c] = x
    return S


def _lcm(values) -> int:
    out = 1
    for v in values:
        v = int(v)
        out = out * v // math.gcd(out, v)
    return out


def _coprime_base(values) -> list[int]:
    """Pairwise coprime integers > 1 of which every one of ``values`` is a product of powers, by gcds alone.

    (A factor refinement: no factoring, so a denominator such as ``10**30`` or a large prime costs a few gcds.)
    """
    base = sorted({abs(int(v)) for v in values} - {0, 1})
    while True:
        pair = next(((a, b) for i, a in enumerate(base) for b in base[i + 1:] if math.gcd(a, b) > 1), None)
        if pair is None:
            return sorted({_root(b) for b in base})
        a, b = pair
        g = math.gcd(a, b)
        base = sorted((set(base) - {a, b}) | ({a // g, g, b // g} - {1}))


def _root(b: int) -> int:
    """The smallest ``r`` with ``b = r^k`` (so that the exponents of a prime power in the base are its own)."""
    power = sp.perfect_power(b)
    return int(power[0]) if power else b


def _multiplicity(b: int, m: int) -> int:
    """The exponent of ``b`` in ``m`` (``b`` > 1, ``m`` != 0)."""
    e, m = 0, abs(m)
    while m % b == 0:
        m //= b
        e += 1
    return e


def _scale(den_rest: int, row, col) -> flint.fmpq:
    """The ``t`` of :func:`_balanced_integer_matrix`: among the divisors of the row's common denominator, the
    smallest that makes the common denominator of ``den_rest``, ``x t`` (row) and ``y / t`` (column) smallest.

    The common denominator is a product over the elements ``b`` of a coprime base of all the numbers involved,
    and the exponent of ``b`` in it depends only on the exponent ``k`` of ``b`` in ``t``: each ``b`` is chosen
    alone (the smallest best ``k`` for each, which gives the smallest best ``t``).
    """
    row, col = list(row), list(col)
    numbers = [den_rest] + [int(v) for x in row + col for v in (x.p, x.q)]
    t = 1
    for b in _coprime_base(numbers):
        rest = _multiplicity(b, den_rest)
        rows = [_multiplicity(b, int(x.p)) - _multiplicity(b, int(x.q)) for x in row]
        cols = [_multiplicity(b, int(y.p)) - _multiplicity(b, int(y.q)) for y in col]
        top = max([0] + [-v for v in rows])  # the exponent of b in the row's common denominator
        exponents = [max([rest, 0] + [-(v + k) for v in rows] + [-(v - k) for v in cols]) for k in range(top + 1)]
        t *= b ** exponents.index(min(exponents))  # the first best k
    return flint.fmpq(t)


def _balanced_integer_matrix(entries: dict, size: int) -> tuple[flint.fmpz_mat, int]:
    """An integer matrix ``A`` and ``d`` with ``A = d * T S T^-1`` for a diagonal ``T``.

    ``T`` scales row and column 0 (the central vertex, whose weights carry the ``1/n^2``
    denominators) by the factor ``t`` that makes the common denominator ``d`` smallest
    (:func:`_scale`, without factoring any number).
    A similarity leaves the characteristic polynomial unchanged, and the cost of FLINT's
    exact characteristic polynomial grows with the bit size of ``d``.
    """
    row = {x for (r, c), x in entries.items() if r == 0 and c}
    col = {x for (r, c), x in entries.items() if c == 0 and r}
    den_rest = _lcm(x.q for (r, c), x in entries.items() if (r == 0) == (c == 0))

    def common_denominator(t):
        return _lcm([den_rest] + [(x * t).q for x in row] + [(x / t).q for x in col])

    t = _scale(den_rest, row, col)
    d = common_denominator(t)
    A = flint.fmpz_mat(size, size)
    for (r, c), x in entries.items():
        if r == 0 and c:
            x = x * t
        elif c == 0 and r:
            x = x / t
        A[r, c] = (x * d).p
    return A, d


def charpoly_memory(size: int, bits: int) -> int:
    """An estimate (bytes) of FLINT's exact characteristic polynomial of a ``size x size`` integer matrix.

    Entries of ``bits`` bits grow, during the elimination, to about ``size * (bits + log2 size)``
    bits (Hadamard's bound); a dense matrix of such numbers is the peak.
    """
    grown = size * (bits + max(1, size.bit_length()))
    return size * size * (grown // 8 + 16)


def characteristic_polynomial(scheme: Scheme, n: int, parameters: Mapping | None = None) -> flint.fmpq_poly:
    """``det(lambda I - S)`` of the full subdivision matrix, exactly (FLINT ``fmpz_mat.charpoly``).

    Computed on ``d * T S T^-1`` (integer, see above) and rescaled:
    ``chi_S(lambda) = d^-(2n+1) chi_A(d lambda)``. No block structure is used.
    """
    n = check_valence(n)
    size = 2 * n + 1
    # a first estimate before anything is built (entries of about 2 log2(n) + 8 bits), then the real one
    check_memory(charpoly_memory(size, 2 * n.bit_length() + 8), f"the exact characteristic polynomial at n = {n}")
    return _rational_charpoly(sparse_subdivision_matrix(scheme, n, parameters), size, f"at n = {n}")


def _rational_charpoly(entries: dict, size: int, what: str) -> flint.fmpq_poly:
    """The exact characteristic polynomial of a sparse rational matrix, after the memory check.

    ``chi_S(lambda) = d^-size chi_A(d lambda)`` for the balanced integer matrix ``A = d T S T^-1``.
    """
    A, d = _balanced_integer_matrix(entries, size)
    # A is as sparse as the entries: the others are zeros, of no bits
    bits = max(int(d).bit_length(), max((abs(int(A[r, c])).bit_length() for r, c in entries), default=1))
    check_memory(charpoly_memory(size, bits), f"the exact characteristic polynomial {what}")
    coeffs = A.charpoly().coeffs()
    size = len(coeffs) - 1
    d = flint.fmpz(d)
    # coefficient of lambda^k in chi_S is c_k(A) * d^k / d^size
    return flint.fmpq_poly([flint.fmpq(c * d**k, d**size) for k, c in enumerate(coeffs)])


def entries_characteristic_polynomial(entries: dict, size: int) -> flint.fmpq_poly:
    """``det(lambda I - S)`` of the ``size x size`` rational matrix ``{(row, column): value}``, exactly.

    Row and column 0 are balanced as in :func:`characteristic_polynomial` (the centre carries the
    ``1/n`` denominators); FLINT's ``fmpz_mat.charpoly`` does the rest. Used by the K-ring
    certificates (:mod:`symdecomp.verify.certify`).
    """
    entries = {k: to_fmpq(v) for k, v in entries.items()}
    return _rational_charpoly(entries, size, f"of a {size} x {size} matrix")
