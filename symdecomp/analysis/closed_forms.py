"""The closed-form eigenvalues under test, and fast evaluation of them (mpmath or Arb balls).

The cross-checks (:mod:`symdecomp.verify.numeric`, :mod:`symdecomp.verify.certify`) compare the full
subdivision matrix with *closed forms*: the three eigenvalues of the Eq. 43 matrix, as
expressions in ``n``, and the two eigenvalues of ``M_k`` (Eq. 34), as expressions in
``c = cos(k pi/n)`` and ``s = sin(k pi/n)``. :func:`derived_closed_forms` takes them from
:func:`symdecomp.analysis.spectrum.recursion_eigenvalues` and
:func:`symdecomp.analysis.tangent.tangent_eigenvalues`, the same ones that ``symdecomp spectrum``
prints. A :class:`ClosedForms` can also be built by hand, which is how the tests inject a
deliberately wrong closed form and see both checks fail.

>>> from symdecomp.schemes.scheme import catmull_clark
>>> cf = derived_closed_forms(catmull_clark())
>>> cf.frequency_k[0]
c**2/8 + sqrt(c**2 + 4)*Abs(c)/8 + 1/4
>>> [(str(v.label), v.frequency) for v in cf.eigenvalue_labels(3)][:4]
[('Eq. 43 root 1', 0), ('Eq. 43 root 2', 0), ('Eq. 43 root 3', 0), ('Eq. 34 dominant', 1)]
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import flint
import mpmath
import sympy as sp

from symdecomp.algebra.compile import compile_expression
from symdecomp.analysis.eigenvalue import ClosedFormLabel
from symdecomp.analysis.spectrum import recursion_eigenvalues
from symdecomp.analysis.tangent import tangent_eigenvalues
from symdecomp.schemes.scheme import Scheme, check_scheme
from symdecomp.symbols import cos_jtheta, sin_jtheta
from symdecomp.symbols import n as N
from symdecomp.validate import cached, check_valence

__all__ = ["ClosedForms", "derived_closed_forms"]


@dataclass(frozen=True)
class ClosedForms:
    """The closed-form eigenvalues of a scheme's subdivision matrix, for symbolic ``n``."""

    #: The scheme they belong to.
    scheme: Scheme
    #: The three eigenvalues of the Eq. 43 matrix, in ``n`` (and the scheme's parameters).
    frequency_zero: tuple[sp.Expr, ...]
    #: ``(dominant, subdominant)`` eigenvalue of ``M_k`` (Eq. 34), in ``c``, ``s`` (and ``n``).
    frequency_k: tuple[sp.Expr, sp.Expr]
    #: Names of the two ``M_k`` eigenvalues, for messages.
    names: tuple[str, str] = ("dominant", "subdominant")
    #: Compiled evaluators, by (parameters, engine); not part of the value.
    _compiled: dict = field(default_factory=dict, init=False, repr=False, compare=False, hash=False)

    def __getstate__(self):
        state = dict(self.__dict__)
        state["_compiled"] = {}  # compiled functions do not pickle; they are rebuilt on use
        return state

    def __setstate__(self, state):
        for key, value in state.items():
            object.__setattr__(self, key, value)

    def eigenvalue_labels(self, n: int) -> tuple[ClosedFormLabel, ...]:
        """The ``2n+1`` labels, in the order of :meth:`values`."""
        n = check_valence(n)
        out = [ClosedFormLabel(0, f"Eq. 43 root {i + 1}") for i in range(len(self.frequency_zero))]
        for k in range(1, n):
            out.extend(ClosedFormLabel(k, f"Eq. 34 {name}") for name in self.names)
        return tuple(out)

    def values(self, n: int, parameters: Mapping, *, engine: str = "mpmath", prec: int = 200) -> list:
        """The ``2n+1`` closed-form eigenvalues at valence ``n``.

        ``engine="mpmath"`` gives ``mpf``/``mpc`` at the current mpmath precision;
        ``engine="arb"`` gives ``flint.acb`` balls computed at ``prec`` bits (rigorous
        enclosures: the exact value is inside each ball).
        """
        n = check_valence(n)
        key = (tuple(sorted(parameters.items(), key=lambda kv: str(kv[0]))), engine)
        if key not in self._compiled:
            self._compiled[key] = _compile_closed_forms(self, key[0], engine)
        zero, pair = self._compiled[key]
        if engine == "arb":
            with flint.ctx.workprec(prec):
                nn = flint.acb(n)
                out = [f(nn, nn, nn) for f in zero]
                for k in range(1, n):
                    c = flint.acb(flint.arb.cos_pi_fmpq(flint.fmpq(k, n)))
                    s = flint.acb(flint.arb.sin_pi_fmpq(flint.fmpq(k, n)))
                    out.extend(f(c, s, nn) for f in pair)
            return out
        nn = mpmath.mpf(n)
        out = [f(nn, nn, nn) for f in zero]
        for k in range(1, n):
            c, s = mpmath.cospi(mpmath.mpf(k) / n), mpmath.sinpi(mpmath.mpf(k) / n)
            out.extend(f(c, s, nn) for f in pair)
        return [mpmath.mpmathify(v) for v in out]


@cached(32, scheme=check_scheme)
def derived_closed_forms(scheme: Scheme) -> ClosedForms:
    """The closed forms that symdecomp derives for ``scheme`` (Eq. 34 and Eq. 43)."""
    ev = tangent_eigenvalues(scheme)
    return ClosedForms(scheme, tuple(recursion_eigenvalues(scheme)), (ev.dominant, ev.subdominant))


def _compile_closed_forms(cf: ClosedForms, parameters: tuple, engine: str):
    subs = dict(parameters)
    variables = (cos_jtheta, sin_jtheta, N)
    zero = tuple(compile_expression(sp.sympify(e, strict=True).subs(subs), variables, engine) for e in cf.frequency_zero)
    pair = tuple(compile_expression(sp.sympify(e, strict=True).subs(subs), variables, engine) for e in cf.frequency_k)
    return zero, pair
