"""Fast evaluation of sympy expressions: mpmath, Arb balls, or exact FLINT rationals.

Used wherever a closed form is evaluated at many points (the cross-checks, the exact
matrices with weights in ``n``): the expression tree is compiled once into nested closures,
so each evaluation does no symbolic work.
"""

from __future__ import annotations

import functools
import operator
from collections.abc import Callable
from typing import Any

import flint
import mpmath
import sympy as sp

from symdecomp.errors import UnsupportedExpressionError

__all__ = ["compile_expression", "UnsupportedExpressionError"]


_MP_OPS = {
    "const": lambda p, q: mpmath.mpf(p) / q,
    "add": lambda xs: mpmath.fsum(xs),
    "mul": lambda xs: mpmath.fprod(xs),
    "sqrt": mpmath.sqrt,
    "abs": abs,
    "pow": lambda x, e: x**e,
    "cos": mpmath.cos,
    "sin": mpmath.sin,
    "pi": lambda: +mpmath.pi,
    "I": lambda: mpmath.mpc(0, 1),
}


def _product(one):
    """The product of a list, starting from ``one`` (the unit of the number type: FLINT has no ``math.prod``)."""
    return lambda xs: functools.reduce(operator.mul, xs, one)


def _exact_only(name):
    def fail(*args):
        raise UnsupportedExpressionError(f"{name} of a rational is not evaluated exactly")

    return fail


_FMPQ_OPS = {
    "const": lambda p, q: flint.fmpq(p, q),
    "add": lambda xs: sum(xs, flint.fmpq(0)),
    "mul": _product(flint.fmpq(1)),
    "sqrt": _exact_only("sqrt"),
    "abs": lambda x: abs(x),
    "pow": lambda x, e: x**e,
    "cos": _exact_only("cos"),
    "sin": _exact_only("sin"),
    "pi": _exact_only("pi"),
    "I": _exact_only("I"),
}


_ARB_OPS = {
    "const": lambda p, q: flint.acb(flint.fmpq(p, q)),
    "add": lambda xs: sum(xs, flint.acb(0)),
    "mul": _product(flint.acb(1)),
    "sqrt": lambda x: flint.acb(x).sqrt(),
    "abs": lambda x: flint.acb(abs(flint.acb(x))),
    "pow": lambda x, e: flint.acb(x) ** e,
    "cos": lambda x: flint.acb(x).cos(),
    "sin": lambda x: flint.acb(x).sin(),
    "pi": lambda: flint.acb(flint.arb.pi()),
    "I": lambda: flint.acb(0, 1),
}


def _is_power_of_two(q: int) -> bool:
    return q > 1 and q & (q - 1) == 0


def _repeated_sqrt(sqrt: Callable, x: Any, times: int) -> Any:
    for _ in range(times):
        x = sqrt(x)
    return x


_SHOWN = 160  # characters of an unsupported subexpression an error line shows


def _abbreviated(e: sp.Expr) -> str:
    """The text of ``e`` for a one-line error: its head and the number of characters left out when it is long."""
    text = str(e)
    if len(text) <= _SHOWN:
        return text
    return f"{text[:_SHOWN]}... ({len(text) - _SHOWN} more characters; a {type(e).__name__})"


def _power(exponent: sp.Expr, base: Callable, ops: dict) -> Callable | None:
    """``base ** exponent`` for an integer exponent or one ``p/2**j``; None for any other exponent."""
    if exponent == -sp.Rational(1, 2):
        return lambda args: ops["const"](1, 1) / ops["sqrt"](base(args))
    if exponent.is_Integer:
        k = int(exponent)
        return lambda args: ops["pow"](base(args), k)
    if exponent.is_Rational and _is_power_of_two(int(exponent.q)):
        # principal z**(p/2**j) = (sqrt applied j times to z)**p: the principal square root's argument lies
        # in (-pi/2, pi/2], so log(sqrt(z)) = log(z)/2 and each step halves the principal logarithm
        k, halvings = int(exponent.p), int(exponent.q).bit_length() - 1
        if k == 1:
            return lambda args: _repeated_sqrt(ops["sqrt"], base(args), halvings)
        return lambda args: ops["pow"](_repeated_sqrt(ops["sqrt"], base(args), halvings), k)
    return None


def compile_expression(expr: sp.Expr, variables: tuple[sp.Symbol, ...], engine: str = "mpmath") -> Callable:
    """Turn a sympy expression into a fast function of ``variables`` (mpmath or Arb).

    Rationals stay exact (``p/q`` at the working precision, or an exact Arb ball), so the Arb
    version is a rigorous enclosure; ``engine="fmpq"`` evaluates a rational function exactly
    (``flint.fmpq``) and refuses square roots and the like. Supported: ``+ *``, ``**`` with an integer exponent
    or one ``p/2**j`` (principal roots by repeated square roots), ``sqrt``, ``Abs``, ``cos``, ``sin``, ``pi``, ``I``;
    anything else raises :class:`UnsupportedExpressionError`, whose one line shows at most the head of a long
    subexpression.

    >>> x = sp.Symbol("x")
    >>> f = compile_expression(sp.sqrt(x**2 + 1) / 3, (x,))
    >>> with mpmath.workdps(20):
    ...     print(f(mpmath.mpf(2)))
    0.7453559924999298988
    """
    ops = {"mpmath": _MP_OPS, "arb": _ARB_OPS, "fmpq": _FMPQ_OPS}[engine]
    index = {v: i for i, v in enumerate(variables)}

    def build(e):
        if e in index:
            i = index[e]
            return lambda args: args[i]
        if e.is_Rational:
            p, q = int(e.p), int(e.q)
            return lambda args: ops["const"](p, q)  # at the precision in force when called
        if e is sp.pi:
            return lambda args: ops["pi"]()
        if e is sp.I:
            return lambda args: ops["I"]()
        if isinstance(e, sp.Add):
            parts = [build(a) for a in e.args]
            return lambda args: ops["add"]([f(args) for f in parts])
        if isinstance(e, sp.Mul):
            parts = [build(a) for a in e.args]
            return lambda args: ops["mul"]([f(args) for f in parts])
        if isinstance(e, sp.Pow) and (power := _power(e.exp, build(e.base), ops)) is not None:
            return power
        if isinstance(e, sp.Abs):
            inner = build(e.args[0])
            return lambda args: ops["abs"](inner(args))
        if isinstance(e, (sp.cos, sp.sin)):
            inner = build(e.args[0])
            name = "cos" if isinstance(e, sp.cos) else "sin"
            return lambda args: ops[name](inner(args))
        raise UnsupportedExpressionError(f"cannot evaluate {_abbreviated(e)} (in a closed form) with {engine}")

    f = build(sp.sympify(expr, strict=True))
    return lambda *args: f(args)


