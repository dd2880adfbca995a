"""Zorin's C1 test at boundary vertices, k = 1..16: the standard rules fail where published, BLZ's rules pass.

The expected verdicts are the mathematics of the spectrum, cross-checked here rather than typed in: for the standard
rules a boundary sector's interior (sine) modes are the interior vertex's modes of valence 2k that are odd under the
mirror (the edge rule near the boundary is the interior one), so lambda_1 is the interior subdominant eigenvalue at
n = 2k, and the tangent of the boundary curve has the eigenvalue 1/2. The standard rules are C1 while 1/2 is one of the
two largest, i.e. while the second sine mode stays below 1/2; BLZ's near-edge rule puts the first sine mode at 1/2.
"""

import math

import pytest
import sympy as sp

from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex
from symdecomp.verify.c1_sector_matrix import c1_sharp_test
from symdecomp.verify.c1_spectrum import spectral_conditions
from symdecomp.verify.result import C1Verdict

FAST = range(1, 9)
SLOW = range(9, 17)


def _interior_modes(scheme, k):
    """The sine modes' eigenvalues: ``lambda(j)`` of the interior vertex of valence 2k at frequencies 1 and 2 (decreasing)."""
    if scheme.lattice.name == "triangle":  # Loop's frequency-j eigenvalue 3/8 + cos(2 pi j / n) / 4
        return [sp.Rational(3, 8) + sp.cos(sp.pi * j / k) / 4 for j in (1, 2)]
    return None


def _expected_standard(scheme, k):
    """The verdict the spectrum implies, for the standard rules (see the module docstring)."""
    if k == 1:
        return C1Verdict.C1  # one face: a corner (edge-and-corner interpolation), both tangents 1/2
    second = {"catmull-clark": {2: "<", 3: "<", 4: "="}, "loop": {2: "<", 3: "<", 4: "<", 5: "<", 6: "="}}[scheme.name].get(k, ">")
    return {"<": C1Verdict.C1, "=": C1Verdict.UNDECIDED, ">": C1Verdict.NOT_C1}[second]


def _check_standard(scheme, k):
    lat = scheme.lattice
    r = c1_sharp_test(scheme, SharpVertex.boundary(k, lat))
    assert r.verdict is _expected_standard(scheme, k), (k, r.reason)
    if k >= 3 and r.lambdas:
        # lambda_1 is the interior subdominant eigenvalue at valence 2k (the mirror-odd interior mode)
        interior = spectral_conditions(scheme, 2 * k).subdominant.value.real
        assert abs(r.lambdas[0] - float(interior.mid())) < 1e-12
    modes = _interior_modes(scheme, k)
    if modes is not None and k >= 3:  # Loop: the closed form decides where 1/2 falls, independently of the test
        assert (_expected_standard(scheme, k) is C1Verdict.NOT_C1) == bool(modes[1] > sp.Rational(1, 2))
    if r.verdict is C1Verdict.NOT_C1:
        assert "tangent of the boundary curve" in r.reason and "not in the tangent plane" in r.reason
    if r.verdict is C1Verdict.C1:
        assert r.opening is not None and (k == 1 or abs(r.opening - 1) < 1e-9)  # a boundary opens by pi exactly
        assert r.jacobian_lower_bound > 0


@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=lambda s: s.name)
@pytest.mark.parametrize("k", FAST)
def test_standard_boundary_rules(scheme, k):
    _check_standard(scheme, k)


@pytest.mark.slow
@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=lambda s: s.name)
@pytest.mark.parametrize("k", SLOW)
def test_standard_boundary_rules_many_faces(scheme, k):
    _check_standard(scheme, k)


def blz(lattice):
    """The shipped scheme files with Biermann-Levin-Zorin's near-edge rule."""
    return load_scheme("catmull-clark-blz" if lattice == "quad" else "loop-blz")


def _check_blz(scheme, k):
    r = c1_sharp_test(scheme, SharpVertex.boundary(k, scheme.lattice))
    assert all(abs(x - 0.5) < 1e-12 for x in r.lambdas)  # BLZ: the sine mode at 1/2, with the curve's tangent
    assert r.spectral.gap > 0
    regular = k == 1 or (k, scheme.lattice.name) in ((2, "quad"), (3, "triangle"))  # no smooth edge at O, or BLZ's = the smooth rule
    if regular:
        assert r.verdict is C1Verdict.C1 and r.jacobian_lower_bound > 0, (k, r.reason)
    else:  # the ring's patches next to the modified edges are not splines: certified on the ring past them, which are
        assert r.verdict is C1Verdict.C1 and r.jacobian_lower_bound > 0 and "past the modified edges" in r.reason, (k, r.reason)
        assert r.opening == pytest.approx(1.0, abs=1e-6)  # a boundary's image opens by pi


@pytest.mark.parametrize("lattice", ["quad", "triangle"])
@pytest.mark.parametrize("k", [1, 2, 3, 5, 8])
def test_blz_boundary_rules(lattice, k):
    _check_blz(blz(lattice), k)


@pytest.mark.slow
@pytest.mark.parametrize("lattice", ["quad", "triangle"])
@pytest.mark.parametrize("k", [4, 6, 7, *SLOW])
def test_blz_boundary_rules_many_faces(lattice, k):
    _check_blz(blz(lattice), k)


def test_the_boundary_opening_is_a_straight_angle():
    r = c1_sharp_test(catmull_clark(), SharpVertex.boundary(3, "quad"))
    assert r.verdict is C1Verdict.C1 and math.isclose(r.opening, 1.0, abs_tol=1e-12)
    assert r.as_json()["vertex"] == "boundary k = 3" and r.as_json()["lambdas"][1] == pytest.approx(0.5)
