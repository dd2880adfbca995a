"""The characteristic map's nets for every n (issue 32): exact polynomials in t = cos(2 pi/n) and lambda_1."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from symdecomp.analysis.characteristic_uniform import reduce_element, uniform_nets
from symdecomp.schemes.lattice import BICUBIC, BOX_SPLINE
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.bezier import bspline_to_bezier
from symdecomp.verify.c1 import box_nets, characteristic_nets
from symdecomp.verify.c1_uniform import jacobian_coefficients


def _jacobians(scheme):
    nets = uniform_nets(scheme)
    return nets, [reduce_element(c, nets.quadratic) for c in jacobian_coefficients(nets, scheme.lattice)]


@pytest.mark.parametrize(("scheme", "n", "t"), [(catmull_clark(), 4, sp.Integer(0)), (loop(), 6, sp.Rational(1, 2))], ids=["cc", "loop"])
def test_at_the_regular_valence_the_map_is_affine(scheme, n, t):
    """At the regular valence lambda_1 = 1/2 and the characteristic map is the regular parametrisation (linear): every
    Bezier coefficient of its Jacobian, on every sub-patch, is one and the same positive rational."""
    nets, coeffs = _jacobians(scheme)
    values = {c(sp.QQ(1, 2), 0, sp.QQ(t.p, t.q)) for c in coeffs}  # s is gone: the stretched map is free of it
    assert len(values) == 1 and values.pop() > 0
    assert nets.quadratic(sp.QQ(1, 2), 0, sp.QQ(t.p, t.q)) == 0  # 1/2 is a root of lambda_1's polynomial there


@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=["cc", "loop"])
@pytest.mark.parametrize("n", [3, 5, 7, 11])
def test_the_nets_are_the_per_valence_nets_up_to_a_positive_factor(scheme, n):
    """At a valence, the exact nets (with t = cos(2 pi/n), L = lambda_1, the y coordinate times s = sin(2 pi/n)) are the
    certified nets of Reif's test (normalised to 1 at a_0) times one positive number, to 10 digits."""
    nets = uniform_nets(scheme)
    t, s = math.cos(2 * math.pi / n), math.sin(2 * math.pi / n)
    tr = float(nets.trace.subs(sp.Symbol("t", real=True), t))
    lam = (tr + math.sqrt(float(nets.discriminant.subs(sp.Symbol("t", real=True), t)))) / 2
    ours = [(float(v.x(lam, s, t)), float(v.y(lam, s, t)) * s) for v in _values(scheme, nets.nets)]
    theirs, _ = characteristic_nets(scheme, n)
    flat = [(float(x.mid()), float(y.mid())) for x, y in _flat_arb(scheme, theirs)]
    ratios = [a / b for pair, other in zip(ours, flat) for a, b in zip(pair, other) if abs(b) > 1e-6]
    assert len(ratios) > 20 and min(ratios) > 0 and max(ratios) - min(ratios) < 1e-10 * max(ratios)


def _values(scheme, nets):
    return scheme.lattice.select({
        BICUBIC: lambda: [v for net in nets for row in bspline_to_bezier([list(row) for row in net]) for v in row],
        BOX_SPLINE: lambda: [v for net in box_nets(nets) for v in net],
    }, "the nets' control points")()


def _flat_arb(scheme, nets):
    return scheme.lattice.select({
        BICUBIC: lambda: [(x[i][k], y[i][k]) for x, y in nets for i in range(4) for k in range(4)],
        BOX_SPLINE: lambda: [(a, b) for x, y in nets for a, b in zip(x, y)],
    }, "the certified nets' control points")()


def test_rules_that_depend_on_n_are_refused_in_one_line():
    from symdecomp.errors import NotApplicableError
    from symdecomp.schemes.scheme import Scheme, Stencil

    cc = catmull_clark()
    e = sp.Rational(3, 8) + (sp.Symbol("n") - 4) / 100
    edge = Stencil.from_weights(e, {-1: (1 - 2 * e) / 4, 0: e, 1: (1 - 2 * e) / 4}, {-1: (1 - 2 * e) / 4, 0: (1 - 2 * e) / 4})
    with pytest.raises(NotApplicableError, match="is not a rational constant"):
        uniform_nets(Scheme("edge in n", edge, cc.face_rule, cc.vertex_rule))
