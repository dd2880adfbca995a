"""The characteristic map regular and injective for every n >= N0 by exact signs in t = cos(2 pi/n) (issue 32)."""

from __future__ import annotations

import dataclasses

import pytest
import sympy as sp

from symdecomp.analysis.characteristic_uniform import UniformValue, uniform_nets
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify import c1_uniform
from symdecomp.verify.c1_uniform import T, sign_with_root, t_lower_bound, uniform_map


def _p(expr):
    return sp.Poly(expr, T, domain=sp.QQ)


def test_signs_with_a_square_root_are_decided_exactly():
    """sqrt(2) - 1 > 0; sqrt(t + 3) - 2 is 0 at t = 1 (nonnegative on [1, 2], not positive); sqrt(t + 3) - 2 < 0 on
    [0, 1/2]; 3/2 - sqrt(2) > 0 (U^2 - V^2 disc = 1/4); t - 1/2 changes sign on [0, 1]."""
    assert sign_with_root(_p(-1), _p(1), sp.Integer(2), 0, 1)
    assert sign_with_root(_p(-2), _p(1), T + 3, 1, 2, strict=False) and not sign_with_root(_p(-2), _p(1), T + 3, 1, 2)
    assert not sign_with_root(_p(-2), _p(1), T + 3, 0, sp.Rational(1, 2), strict=False)
    assert sign_with_root(_p(sp.Rational(3, 2)), _p(-1), sp.Integer(2), 0, 1)
    assert not sign_with_root(_p(T - sp.Rational(1, 2)), _p(0), sp.Integer(1), 0, 1, strict=False)


@pytest.mark.parametrize("first", [3, 4, 5, 7, 64])
def test_the_interval_holds_every_valence_from_first(first):
    low = t_lower_bound(first)
    assert low.is_Rational and all(low <= sp.cos(2 * sp.pi / n) for n in (first, first + 1, 10 * first))
    assert (low == sp.cos(2 * sp.pi / first)) is (first in (3, 4, 6))


@pytest.mark.parametrize(("scheme", "coefficients", "points"), [(catmull_clark(), 108, 8), (loop(), 84, 5)], ids=["cc", "loop"])
def test_the_map_is_proved_for_every_n(scheme, coefficients, points):
    r = uniform_map(scheme, 3)
    assert r.status == "proved" and r.t_low == sp.Rational(-1, 2) and r.coefficients == coefficients + points
    assert f"all {coefficients} Bezier coefficients" in r.facts[1] and f"the {points} control points" in r.facts[2]


def _altered(monkeypatch, scheme, change):
    nets = uniform_nets(scheme)
    altered = tuple([[change(v) for v in row] for row in net] for net in nets.nets)
    monkeypatch.setattr(c1_uniform, "uniform_nets", lambda s: dataclasses.replace(nets, nets=altered))


def test_a_mirrored_map_is_not_called_regular(monkeypatch):
    """The mirror image (y -> -y) has a negative Jacobian: its coefficients are not shown positive."""
    _altered(monkeypatch, catmull_clark(), lambda v: UniformValue(v.x, -v.y))
    r = uniform_map(catmull_clark(), 3)
    assert r.status == "open" and r.facts[0].startswith("Bezier coefficient 0 of the Jacobian is not shown positive")


def test_a_map_that_leaves_the_wedge_is_not_called_injective(monkeypatch):
    """Doubling y keeps the Jacobian positive, but the inner boundary's last point leaves sector 0's wedge."""
    _altered(monkeypatch, catmull_clark(), lambda v: UniformValue(v.x, 2 * v.y))
    r = uniform_map(catmull_clark(), 3)
    assert r.status == "open" and "not shown to lie in sector 0's wedge" in r.facts[-1]
