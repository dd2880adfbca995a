"""The modified butterfly's stretched characteristic map in the limit n -> oo (issue 30, the map part).

The limit net is the closed-form eigenvector at t = 1 (rationals); its neighbouring sectors are shears, and the
regularity half of Zorin's test on it is certified at refinement depth 6 and not at depth 5, where the derivative
bound is still too wide; a tension variant gives another net and another margin.
"""

from __future__ import annotations

from pathlib import Path

import flint
import pytest
import sympy as sp

import symdecomp.schemes as schemes
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text
from symdecomp.verify.zorin_limit_net import LimitNet, limit_net, limit_regularity

BUTTERFLY = load_zoo("modified-butterfly")


def test_the_limit_net_is_the_eigenvector_at_t_one_and_its_neighbours_are_shears():
    net, ev = limit_net(BUTTERFLY)
    assert net.shift in (1, -1)
    # on the start spoke the eigenvector is real (Y = 0) and the old points sit at twice their level's distance
    assert net.value((1, 0)) == flint.acb(1) and net.value((2, 0)) == flint.acb(2) and net.value((4, 0)) == flint.acb(4)
    # a point of sector 1 is the shear (X, Y) -> (X, Y + d X) of its preimage in sector 0 (omega^d at t = 1)
    q = (2, 1)
    turned = (-q[1], q[0] + q[1])
    z = net.values[q]
    sheared = net.value(turned)
    assert sheared.real.overlaps(z.real) and (sheared.imag - net.shift * sheared.real).overlaps(z.imag)
    assert not sheared.imag.overlaps(z.imag)  # X != 0 there: the shear moves it
    # the stretched limit of x_c is (sum a_k, sum k a_k) of its Laurent polynomial
    x1 = ev.eigenvector[1]
    a = sp.Poly(sp.expand(x1 * sp.Symbol("omega") ** 4), sp.Symbol("omega"))
    assert ev.limit(1) == (sum(c for _, c in a.terms()), sum((k[0] - 4) * c for k, c in a.terms()))
    with pytest.raises(InvalidSchemeError, match="not in the three sectors"):
        LimitNet({}, flint.acb(1), 1).value((-1, -1))


@pytest.mark.slow
def test_depth_five_leaves_the_limit_open():
    r = limit_regularity(BUTTERFLY, 5)
    assert r.status == "open" and r.sign == 0 and r.error > 0.25


@pytest.fixture(scope="module")
def certified():
    return limit_regularity(BUTTERFLY, 6)


def test_the_limit_map_is_regular_on_the_ring_at_depth_six(certified):
    assert certified.status == "regular" and certified.sign == 1 and certified.depth == 6
    # the margin is below the Jacobian of the net's own differences (about 0.7128) by the widening, and positive
    assert 0.2 < certified.margin < 0.7128 and 0 < certified.error < 0.2
    assert "n -> oo" in certified.text and "|J| >= 0.2384" in certified.text


@pytest.mark.slow
def test_a_tension_variant_changes_the_limit_margin(certified):
    text = (Path(schemes.__file__).parent / "zoo" / "modified-butterfly.toml").read_text()
    w = sp.Rational(1, 20)
    text = text.replace('weight = "1/8"', f'weight = "{2 * w}"').replace('weight = "-1/16"', f'weight = "{-w}"')
    other = limit_regularity(stencil_scheme_from_text(text.replace('"modified-butterfly"', '"tension"')), 6)
    assert (other.status, other.margin, other.error) != (certified.status, certified.margin, certified.error)
