"""Exact arithmetic in the cyclotomic field Q(zeta_N), for exact polygon decompositions.

An element is a rational polynomial in ``zeta = exp(2 pi i/N)`` reduced modulo the
cyclotomic polynomial ``Phi_N`` (python-flint). Equality is exact: an element is zero iff
its reduced polynomial is zero. With ``4 | N`` the field contains ``i = zeta^(N/4)``, so real
and imaginary parts stay in it.

>>> K = CyclotomicField(20)
>>> w = K.zeta(4)                  # omega_5 = zeta_20^4
>>> sum((w**k for k in range(5)), K(0)) == 0
True
>>> (K.zeta(5) * K.zeta(5)).to_sympy()    # i * i
-1
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache, lru_cache, reduce

import flint
import mpmath
import sympy as sp

from symdecomp.algebra.numbers import rational_poly, to_fmpq, to_fraction
from symdecomp.errors import InvalidInputError, InvalidTypeError
from symdecomp.symbols import n as VALENCE
from symdecomp.symbols import omega as OMEGA

__all__ = ["CyclotomicField", "Cyclotomic", "cyclotomic_value", "CyclotomicFunction", "exact_entry", "matrix_rank",
           "to_acb"]


@cache
def _phi(N: int) -> flint.fmpq_poly:
    return flint.fmpq_poly([int(c) for c in flint.fmpz_poly.cyclotomic(N).coeffs()])


class CyclotomicField:
    """The field Q(zeta_N)."""

    def __init__(self, N: int):
        if N < 1:
            raise InvalidInputError(f"N must be positive, got {N}")
        self.N = N
        self.phi = _phi(N)

    def __eq__(self, other):
        return isinstance(other, CyclotomicField) and other.N == self.N

    def __hash__(self):
        return hash(("Q(zeta)", self.N))

    def __call__(self, value) -> Cyclotomic:
        """Embed a rational (int, Fraction, sympy Rational) or a Gaussian rational ``a + b*I``."""
        if isinstance(value, Cyclotomic):
            return value
        if isinstance(value, (int, Fraction)):
            return Cyclotomic(self, flint.fmpq_poly([to_fmpq(value)]))
        v = sp.sympify(value, strict=True)
        re, im = v.as_real_imag()
        if not (re.is_Rational and im.is_Rational):
            raise InvalidTypeError(f"{value!r} is not a (Gaussian) rational number")
        out = self(to_fraction(re))
        if im != 0:
            out = out + self.i * self(to_fraction(im))
        return out

    def zeta(self, k: int = 1) -> Cyclotomic:
        """``zeta_N^k``."""
        k %= self.N
        coeffs = [0] * k + [1]
        return Cyclotomic(self, flint.fmpq_poly(coeffs) % self.phi)

    def root(self, n: int, k: int) -> Cyclotomic:
        """``omega_n^k = zeta_N^(k N/n)``; ``n`` must divide ``N``."""
        if self.N % n:
            raise InvalidInputError(f"omega_{n} is not in Q(zeta_{self.N})")
        return self.zeta(k * (self.N // n))

    @property
    def i(self) -> Cyclotomic:
        if self.N % 4:
            raise InvalidInputError(f"i is not in Q(zeta_{self.N}) (needs 4 | N)")
        return self.zeta(self.N // 4)


class Cyclotomic:
    """An element of Q(zeta_N)."""

    __slots__ = ("field", "poly")

    def __init__(self, field: CyclotomicField, poly: flint.fmpq_poly):
        self.field = field
        self.poly = poly

    def _lift(self, other) -> Cyclotomic:
        if isinstance(other, Cyclotomic):
            if other.field != self.field:
                raise InvalidInputError("elements of different cyclotomic fields")
            return other
        return self.field(other)

    def __add__(self, other):
        return Cyclotomic(self.field, self.poly + self._lift(other).poly)

    __radd__ = __add__

    def __sub__(self, other):
        return Cyclotomic(self.field, self.poly - self._lift(other).poly)

    def __rsub__(self, other):
        return self._lift(other) - self

    def __neg__(self):
        return Cyclotomic(self.field, -self.poly)

    def __mul__(self, other):
        return Cyclotomic(self.field, (self.poly * self._lift(other).poly) % self.field.phi)

    __rmul__ = __mul__

    def __truediv__(self, other):
        if isinstance(other, (int, Fraction)):
            f = Fraction(other)
            if f == 0:
                raise ZeroDivisionError("division by zero")
            return Cyclotomic(self.field, self.poly * flint.fmpq(f.denominator, f.numerator))
        other = self._lift(other)
        g, s, _ = other.poly.xgcd(self.field.phi)  # s*other = g (mod phi), g a nonzero constant
        if other.poly == 0:
            raise ZeroDivisionError("division by zero in a cyclotomic field")
        return Cyclotomic(self.field, (self.poly * s * (1 / g[0])) % self.field.phi)

    def __pow__(self, k: int):
        out = self.field(1)
        base = self if k >= 0 else self.field(1) / self
        for _ in range(abs(k)):
            out = out * base
        return out

    def __eq__(self, other):
        try:
            return (self - other).poly == 0
        except (TypeError, ValueError):
            return NotImplemented

    def __hash__(self):
        return hash((self.field.N, str(self.poly)))

    def conjugate(self) -> Cyclotomic:
        """Complex conjugate: ``zeta -> zeta^(-1)``."""
        N = self.field.N
        coeffs = [0] * N
        for k, c in enumerate(self.poly.coeffs()):
            coeffs[(-k) % N] = coeffs[(-k) % N] + c
        return Cyclotomic(self.field, flint.fmpq_poly(coeffs) % self.field.phi)

    def real(self) -> Cyclotomic:
        return (self + self.conjugate()) / 2

    def imag(self) -> Cyclotomic:
        return (self - self.conjugate()) / (2 * self.field.i)

    def to_sympy(self) -> sp.Expr:
        """As a sympy number: ``sum_k c_k (cos(2 pi k/N) + i sin(2 pi k/N))``, expanded.

        No call to ``sp.expand``: each root is expanded once (:func:`_root_of_unity`), a rational times an expanded sum
        is distributed by sympy as it is built, and a sum of expanded terms is expanded; ``expand`` would only walk the
        result again (most of the time of a decomposition in exact arithmetic)."""
        N = self.field.N
        return sp.Add(*(sp.Rational(int(c.p), int(c.q)) * _root_of_unity(N, k) for k, c in enumerate(self.poly.coeffs()) if c != 0))

    def to_mpc(self):
        """As an mpmath number at the current working precision."""
        N = self.field.N
        total = mpmath.mpc(0)
        for k, c in enumerate(self.poly.coeffs()):
            if c != 0:
                total += mpmath.mpf(int(c.p)) / int(c.q) * mpmath.expjpi(mpmath.mpf(2 * k) / N)
        return total

    def __repr__(self):
        return f"Cyclotomic({self.poly}, N={self.field.N})"


@lru_cache(maxsize=4096)
def _root_of_unity(N: int, k: int) -> sp.Expr:
    """``cos(2 pi k/N) + i sin(2 pi k/N)`` as sympy evaluates it, expanded (shared by every :meth:`Cyclotomic.to_sympy`)."""
    angle = 2 * sp.pi * sp.Rational(k, N)
    return sp.expand(sp.cos(angle) + sp.I * sp.sin(angle))


def _trig_fraction(term: sp.Expr, values: dict) -> sp.Rational:
    """``r`` with ``term = cos(r pi)``, ``sin(r pi)`` or ``exp(i r pi)`` (after ``values``), ``r`` rational."""
    arg = term.args[0] if not isinstance(term, sp.exp) else term.args[0] / sp.I
    r = sp.cancel(arg.xreplace(values) / sp.pi)
    if not r.is_Rational:
        raise ValueError(f"{term} is not a cosine, sine or exponential of a rational multiple of pi")
    return r


def cyclotomic_value(expr, values: dict | None = None, field: CyclotomicField | None = None) -> Cyclotomic:
    """An exact number built from rationals and ``cos``/``sin``/``exp(i .)`` of rational multiples of ``pi``.

    ``values`` substitutes symbols first (e.g. ``{n: 7}``); trigonometric terms are replaced
    *before* the substitution so that sympy cannot rewrite ``cos(2 pi/5)`` into radicals. The
    result lies in the smallest ``Q(zeta_N)`` holding every term, or in ``field`` when given (it
    must contain them). Raises ``ValueError`` when the
    expression is not of that kind (a square root, a free symbol left, a float).

    >>> from sympy import cos, pi, Symbol
    >>> m = Symbol("m")
    >>> x = cyclotomic_value((cos(2*pi/m) + 1) / 4, {m: 5})
    >>> x.field.N, float(x.to_mpc().real)
    (10, 0.32725424859373686)
    """
    expr = sp.sympify(expr, strict=True)
    values = {sp.sympify(k, strict=True): sp.sympify(v, strict=True) for k, v in (values or {}).items()}
    trig = sorted(expr.atoms(sp.cos, sp.sin, sp.exp), key=sp.default_sort_key)
    dummies, fractions, order = {}, {}, 4 if any(isinstance(t, sp.sin) for t in trig) else 1
    for t in trig:
        r = _trig_fraction(t, values)
        d = sp.Dummy("t")
        dummies[t], fractions[d] = d, (type(t), r)
        order = order * (2 * int(r.q)) // math.gcd(order, 2 * int(r.q))
    plain = expr.xreplace(dummies).xreplace(values) if values else expr.xreplace(dummies)
    if field is not None:
        if field.N % order:
            raise ValueError(f"{expr} is not in Q(zeta_{field.N})")
        order = field.N
    K = field or CyclotomicField(order)
    leaves = {}
    for d, (kind, r) in fractions.items():
        z = K.zeta(int(r.p) * (order // (2 * int(r.q))))  # exp(i r pi)
        leaves[d] = z if kind is sp.exp else (z + z.conjugate()) / 2 if kind is sp.cos else (z - z.conjugate()) / (2 * K.i)
    return _walk(sp.sympify(plain, strict=True), K, leaves)


def _walk(e: sp.Expr, K: CyclotomicField, leaves: dict) -> Cyclotomic:
    if e in leaves:
        return leaves[e]
    if e.is_Rational:
        return K(to_fraction(e))
    if e is sp.I:
        return K.i
    if isinstance(e, sp.Add):
        out = K(0)
        for a in e.args:
            out = out + _walk(a, K, leaves)
        return out
    if isinstance(e, sp.Mul):
        out = K(1)
        for a in e.args:
            out = out * _walk(a, K, leaves)
        return out
    if isinstance(e, sp.Pow) and e.exp.is_Integer:
        return _walk(e.base, K, leaves) ** int(e.exp)
    raise ValueError(f"{e} is not a rational function of roots of unity")


class CyclotomicFunction:
    """An expression of :func:`cyclotomic_value`'s kind in one symbol, read once and then evaluated exactly at many
    values of the symbol without sympy: the trigonometric terms' arguments (over ``pi``) become rational functions
    of the symbol (FLINT polynomials), the rest a tree of field operations. ``f(x, field)`` is
    ``cyclotomic_value(expr, {symbol: x}, field=field)`` (``x`` an int or Fraction); raises ``ValueError`` when the
    expression is not of that kind (when read), or a term is not in ``field`` or its argument not defined at ``x``.
    Symbols ``given`` stand for elements of the field passed after it, ``f(x, field, *values)`` (``omega`` as a root of
    unity, say).

    >>> from sympy import cos, pi, Symbol
    >>> m = Symbol("m")
    >>> f = CyclotomicFunction((cos(2*pi/m) + 1) / 4, m)
    >>> f(5, CyclotomicField(10)) == cyclotomic_value((cos(2*pi/m) + 1) / 4, {m: 5}, field=CyclotomicField(10))
    True
    """

    def __init__(self, expr, symbol: sp.Symbol, given: tuple[sp.Symbol, ...] = ()):
        expr = sp.sympify(expr, strict=True)
        trig = sorted(expr.atoms(sp.cos, sp.sin, sp.exp), key=sp.default_sort_key)
        leaves: dict = {symbol: 0, **{g: 1 + i for i, g in enumerate(given)}}
        self._terms = []  # (kind, numerator, denominator) of each term's argument over pi, a rational function of symbol
        for t in trig:
            arg = t.args[0] if not isinstance(t, sp.exp) else t.args[0] / sp.I
            num, den = sp.fraction(sp.cancel(arg / sp.pi))
            self._terms.append((type(t), _rational_poly(num, symbol, t), _rational_poly(den, symbol, t)))
            leaves[t] = len(leaves)
        self._tree = _tree(expr, leaves)

    def __call__(self, x, field: CyclotomicField, *given: Cyclotomic) -> Cyclotomic:
        at = flint.fmpq(x.numerator, x.denominator) if isinstance(x, Fraction) else flint.fmpq(int(x))
        env = [field(to_fraction(at)), *given]
        for kind, num, den in self._terms:
            d = den(at)
            if d == 0:
                raise ValueError(f"a trigonometric term's argument is not defined at {x}")
            r = num(at) / d
            p, q = int(r.p), int(r.q)
            if field.N % (2 * q):
                raise ValueError(f"exp(i pi {r}) is not in Q(zeta_{field.N})")
            z = field.zeta(p * (field.N // (2 * q)))  # exp(i r pi)
            env.append(z if kind is sp.exp else (z + z.conjugate()) / 2 if kind is sp.cos else (z - z.conjugate()) / (2 * field.i))
        return self._tree(env, field)


def _rational_poly(e: sp.Expr, symbol: sp.Symbol, term) -> flint.fmpq_poly:
    poly = rational_poly(e, symbol)
    if poly is None:
        raise ValueError(f"{term} is not a cosine, sine or exponential of a rational multiple of pi")
    return poly


def _tree(e: sp.Expr, leaves: dict):
    """``e`` as a function ``(env, field) -> Cyclotomic``, ``env[leaves[x]]`` the value of a leaf ``x`` (as :func:`_walk`)."""
    if e in leaves:
        i = leaves[e]
        return lambda env, K: env[i]
    if e.is_Rational:
        f = to_fraction(e)
        return lambda env, K: K(f)
    if e is sp.I:
        return lambda env, K: K.i
    parts = [_tree(a, leaves) for a in e.args]
    if isinstance(e, sp.Add):
        return lambda env, K: sum((part(env, K) for part in parts), K(0))
    if isinstance(e, sp.Mul):
        return lambda env, K: reduce(lambda x, part: x * part(env, K), parts, K(1))
    if isinstance(e, sp.Pow) and e.exp.is_Integer:
        base, k = parts[0], int(e.exp)
        return lambda env, K: base(env, K) ** k
    raise ValueError(f"{e} is not a rational function of roots of unity")


@lru_cache(maxsize=512)
def _entry_function(expr: sp.Expr) -> CyclotomicFunction | None:
    try:
        return CyclotomicFunction(expr, VALENCE, (OMEGA,))
    except ValueError:
        return None


@lru_cache(maxsize=64)
def _valence_field(n: int) -> CyclotomicField:
    """``Q(zeta_2n)`` (``= Q(zeta_n)`` for odd ``n``): holds ``omega_n^j`` and ``cos(2 pi k/n)``."""
    return CyclotomicField(2 * n)


def exact_entry(expr, n: int, j: int = 0) -> Cyclotomic | None:
    """An expression in ``n``, ``omega`` and ``cos``/``sin`` of rational multiples of pi at ``n``, ``omega = omega_n^j``.

    Read once per expression into a :class:`CyclotomicFunction` of ``n`` with ``omega``
    given as ``zeta_2n^(2j)`` (the same element of the field, without sympy at each valence and frequency); an
    expression it cannot read or evaluate goes through :func:`cyclotomic_value`.
    """
    expr = sp.sympify(expr, strict=True)
    function, field = _entry_function(expr), _valence_field(n)
    if function is not None:
        try:
            return function(n, field, field.zeta(2 * j))
        except (ValueError, ZeroDivisionError):
            pass
    if expr.has(OMEGA):
        expr = expr.xreplace({OMEGA: sp.exp(2 * sp.pi * sp.I * sp.Rational(j, n))})
    try:
        return cyclotomic_value(expr, {VALENCE: n}, _valence_field(n))
    except ValueError:
        return None


def matrix_rank(rows: list[list[Cyclotomic]]) -> int:
    """The rank of a matrix over ``Q(zeta_N)`` (exact Gaussian elimination)."""
    rows = [list(r) for r in rows]
    rank, cols = 0, len(rows[0]) if rows else 0
    for c in range(cols):
        pivot = next((r for r in range(rank, len(rows)) if rows[r][c].poly != 0), None)
        if pivot is None:
            continue
        rows[rank], rows[pivot] = rows[pivot], rows[rank]
        for r in range(rank + 1, len(rows)):
            if rows[r][c].poly != 0:
                f = rows[r][c] / rows[rank][c]
                rows[r] = [x - f * y for x, y in zip(rows[r], rows[rank])]
        rank += 1
    return rank


def to_acb(x: Cyclotomic, prec: int = 128):
    """A certified complex ball (FLINT ``acb``) containing ``x``, at ``prec`` bits."""
    with flint.ctx.workprec(prec):
        N = x.field.N
        total = flint.acb(0)
        for k, c in enumerate(x.poly.coeffs()):
            if c != 0:
                total += flint.acb(flint.arb(c)) * flint.acb(flint.arb(flint.fmpq(2 * k, N))).exp_pi_i()
        return total
