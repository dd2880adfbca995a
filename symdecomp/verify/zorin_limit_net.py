"""The stretched characteristic map in the limit ``n -> oo``: its net, refined by the regular rules, and its Jacobian.

The frequency-1 eigenvector on Zorin's neighbourhood is, for every ``n >= N0``, a vector of Laurent polynomials in
``omega`` (:mod:`symdecomp.verify.zorin_eigenvector_every_n`); stretched by ``1/sin(2 pi/n)`` across the real axis,
each control point is ``(X(t), Y(t))`` with polynomials in ``t = cos(2 pi/n)``, and at ``t = 1``
``(sum a_k, sum k a_k)``: the stretched net of the limit. The rotation by ``d`` sectors, ``omega^d``, becomes the shear
``(X, Y) -> (X, Y + d X)`` there (determinant 1: the Jacobian's sign and size are kept), which is how
:class:`LimitNet` answers the neighbouring sectors (:class:`~symdecomp.verify.zorin_net.WedgeNet` multiplies by
``rho``). The regular rules are real and linear, so they refine ``X`` and ``Y`` each on its own, and the bounds of
:mod:`symdecomp.verify.zorin_bounds` hold for each component with the rhombus differences of the pair (their modulus
bounds each part's).

:func:`limit_regularity` runs the regularity half of Zorin's test (:mod:`symdecomp.verify.c1_zorin`: grow, refine
``m`` times, the Jacobian on every triangle of sector 0's ring widened by the derivative bound) on that limit net in
Arb: where the Jacobian has one strict sign with a lower bound, the stretched limit map is regular on the ring, with
that margin. This is a fact about the limit only: the distance of the nets at ``t < 1`` from it (an error bound in
``1 - t``) and injectivity are not derived here, so nothing for a finite ``n`` follows from it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import flint

from symdecomp.errors import InvalidSchemeError, NotApplicableError
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.validate import check_int, check_type
from symdecomp.verify.zorin_bounds import Point, turn
from symdecomp.verify.zorin_net import WedgeNet, wedge_points

if TYPE_CHECKING:
    from symdecomp.verify.zorin_eigenvector_every_n import EveryNEigenvector

__all__ = ["LimitNet", "LimitRegularity", "limit_net", "limit_regularity"]


def _shear(z: flint.acb, d: int) -> flint.acb:
    """``(X, Y) -> (X, Y + d X)``, the point ``X + i Y``: ``omega^d`` on a stretched point at ``t = 1``."""
    return flint.acb(z.real, z.imag + d * z.real)


@dataclass
class LimitNet(WedgeNet):
    """Sector 0 of the stretched limit net, ``(x, y) -> X + i Y``; ``shift``: the next sector's offset ``d``."""

    shift: int = 1

    def value(self, q: Point) -> flint.acb:
        """The stretched point at any point of the sectors -1, 0, 1 (sheared by ``+-d``; 0 at the centre)."""
        if q == (0, 0):
            return flint.acb(0)
        if q[0] >= 1 and q[1] >= 0:
            return self.values[q]
        back = (q[0] + q[1], -q[0])
        if back[0] >= 1 and back[1] >= 0:
            return _shear(self.values[back], self.shift)
        on = turn(q)
        if on[0] >= 1 and on[1] >= 0:
            return _shear(self.values[on], -self.shift)
        raise InvalidSchemeError(f"the point {q} is not in the three sectors around sector 0")


@dataclass(frozen=True)
class LimitRegularity:
    """The stretched limit map's Jacobian on sector 0's ring at one refinement depth."""

    #: ``regular`` (one strict sign on every triangle) or ``open`` (a triangle where it is not decided).
    status: str
    #: The refinement depth ``m``.
    depth: int
    #: The Jacobian's sign (``0`` where open).
    sign: int
    #: A lower bound of ``|J|`` over the ring (``0`` where open).
    margin: float
    #: The derivative error bound ``E`` the Jacobian was widened by.
    error: float
    #: What was found, in one sentence.
    text: str


def limit_net(scheme: StencilScheme) -> tuple[LimitNet, EveryNEigenvector]:
    """``(net, eigenvector)``: sector 0 of the stretched limit net on Zorin's neighbourhood, from the closed form."""
    from symdecomp.analysis.zoo_blocks import signed_offset
    from symdecomp.analysis.zoo_matrix import zoo_matrix
    from symdecomp.verify.zorin_eigenvector_every_n import every_n_eigenvector

    ev = every_n_eigenvector(scheme)
    n = ev.first
    nb = zoo_matrix(scheme, n, ev.depth).neighbourhood
    where, spoke = wedge_points(nb.mesh, nb.start, ev.depth)
    s0 = nb.labels[where[(1, 0)]][0]
    values = {}
    for q, v in where.items():
        s, c = nb.labels[v]
        x, y = ev.limit(c, signed_offset(s - s0, n))
        values[q] = flint.acb(flint.fmpq(int(x.p), int(x.q)), flint.fmpq(int(y.p), int(y.q)))
    return LimitNet(values, flint.acb(1), signed_offset(nb.labels[spoke][0] - s0, n)), ev


def limit_regularity(scheme: StencilScheme, depth: int = 4, prec: int = 128) -> LimitRegularity:
    """The regularity half of Zorin's test on the stretched limit net at refinement ``depth`` (module docstring);
    :class:`~symdecomp.errors.NotApplicableError` where there is no closed form or no difference bound."""
    from symdecomp.verify.c1_zorin import _jacobian, _level_net, _q, _rhombus_bound
    from symdecomp.verify.zorin_bounds import difference_bounds

    check_type(scheme, StencilScheme, "scheme", hint="a scheme of the zoo, e.g. load_zoo('modified-butterfly')")
    m = check_int(depth, "depth", minimum=1, maximum=6)
    bounds = difference_bounds(scheme)
    if not bounds.closes:
        raise NotApplicableError("the regular rules' difference scheme does not contract: no bound of the derivatives")
    with flint.ctx.workprec(prec):
        net0, ev = limit_net(scheme)
        lam = flint.acb(flint.fmpq(int(ev.value.p), int(ev.value.q)))
        net, d = _level_net(net0, lam, bounds, m)
        a = bounds.dilation
        M = _rhombus_bound(net, d - bounds.margin, a * d + bounds.margin)
        error = _q(bounds.derivative) * a**m * M * _q(bounds.derivative_factor())
        signs, low, open_at = _jacobian(net, d, a, m, error)
    if len(signs) == 1 and open_at is None and low is not None:
        sign, margin = signs.pop(), float(low.lower())
        return LimitRegularity("regular", m, sign, margin, float(error.upper()), (
            f"the stretched limit map (n -> oo) is regular on sector 0's ring: its Jacobian has sign {sign:+d} on every "
            f"triangle at depth {m}, |J| >= {margin:.4g} (derivative error <= {float(error.upper()):.3g})"))
    where = "both signs" if len(signs) > 1 else f"an undecided triangle at {open_at}"
    return LimitRegularity("open", m, 0, 0.0, float(error.upper()),
                           f"the stretched limit map's Jacobian is not decided at depth {m}: {where}")
