"""``certify_sharp`` for Biermann-Levin-Zorin's rules: the mirror blocks against the refined matrix in ``Q(cos(pi/k))[l]``."""

from __future__ import annotations

import pytest
import sympy as sp

import symdecomp as sd
import symdecomp.analysis.mirror_threshold as mt
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.verify.certify import certify_sharp
from symdecomp.verify.result import CrossCheckStatus

CC, LOOP = load_scheme("catmull-clark-blz"), load_scheme("loop-blz")


@pytest.mark.parametrize("scheme", [CC, LOOP], ids=["cc", "loop"])
@pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 6])
def test_boundary_blocks_are_the_spectrum(scheme, k):
    r = certify_sharp(scheme, sd.SharpVertex.boundary(k, scheme.lattice))
    assert r.status is CrossCheckStatus.AGREE and r.multiplicities_certified
    assert ("Q(cos(pi/" in r.method) == (k > 3)
    assert sum(r.multiplicities) == (2 * k + 2 if scheme is CC else k + 2)


def test_crease_and_corner_with_one_field():
    for vertex in (sd.SharpVertex.crease(5, 5, CC.lattice), sd.SharpVertex.corner(5, CC.lattice),
                   sd.SharpVertex.crease(3, 5, CC.lattice)):
        assert certify_sharp(CC, vertex).status is CrossCheckStatus.AGREE


def test_a_wrong_block_product_is_refuted(monkeypatch):
    """The identity can fail: the blocks of a sector with one face more do not give this matrix's polynomial."""
    real = mt.sine_part_in_cos
    monkeypatch.setattr(mt, "sine_part_in_cos", lambda scheme, k, rules=None, dart=False: real(scheme, k + 1, rules, dart=dart))
    r = certify_sharp(CC, sd.SharpVertex.boundary(5, CC.lattice))
    assert r.status is CrossCheckStatus.DISAGREE and "Q(cos(pi/5))[l]" in r.message


def test_sine_product_at_a_rational_angle_is_the_rational_one():
    """At k = 3 (cos(pi/3) = 1/2) the product in ``Q[x, c_k]`` at ``c_k = 1/2`` is :func:`sine_part` of the rules there."""
    from symdecomp.analysis.mirror import with_near_edge

    centre, end = CC.sharp.near_edge(sp.pi / 3, 3)
    rules = with_near_edge(CC, centre, end)
    rational = mt.sine_part(CC, 3, rules)
    general = mt.sine_part_in_cos(CC, 3).as_expr().subs(mt.CK, sp.Rational(1, 2))
    assert sp.expand(general - rational.as_expr()) == 0


def test_two_fields_are_refused():
    with pytest.raises(NotApplicableError, match=r"Q\(cos\(pi/4\), cos\(pi/5\)\)"):
        certify_sharp(CC, sd.SharpVertex.crease(5, 4, CC.lattice))
