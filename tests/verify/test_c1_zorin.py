"""Zorin's test for schemes with no spline patch: the modified butterfly is C1 valence by valence, a butterfly whose
regular rule is linear interpolation is not certified (its difference scheme does not contract), and Loop agrees with
Reif's test on its box-spline patches."""

from __future__ import annotations

import json
from fractions import Fraction

import flint
import pytest

from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.stencil_convert import as_stencils
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text, stencil_scheme_to_text
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.verify.c1 import c1_test
from symdecomp.verify.c1_zoo import c1_zoo
from symdecomp.verify.c1_zorin import ZORIN_METHOD, _characteristic, c1_zorin_test
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zorin_bounds import RHOMBI, _expand, decompose, difference_bounds, hex_norm, regular_mask, turn
from symdecomp.verify.zorin_net import grow, refine

BUTTERFLY = load_zoo("modified-butterfly")


def _linear_interpolation() -> StencilScheme:
    """The modified butterfly with its regular rule cut to the edge's midpoint (the tension w = 0 of the butterfly)."""
    text = stencil_scheme_to_text(BUTTERFLY)
    lines = [line for line in text.splitlines() if not ('"-1/16"' in line or '"1/8"' in line)]
    return stencil_scheme_from_text("\n".join(lines).replace('name = "modified-butterfly"', 'name = "w0"'), source="w0.toml")


def _twisted() -> StencilScheme:
    """The modified butterfly with its rule at valences >= 5 moved from frequency 1 to frequency 2: on the centre's
    neighbours ``(1/4 + cos(2 pi j/K)/2 + 6 cos(4 pi j/K)/5)/K``, so frequency 1 gives ``1/4`` and frequency 2 ``3/5``."""
    text = stencil_scheme_to_text(BUTTERFLY).replace("(cos(2*pi*j/n) + cos(4*pi*j/n)/2 + 1/4)/n",
                                                     "(cos(2*pi*j/n)/2 + 6*cos(4*pi*j/n)/5 + 1/4)/n")
    assert "6*cos(4*pi*j/n)/5" in text
    return stencil_scheme_from_text(text.replace('name = "modified-butterfly"', 'name = "twisted"'), source="twisted.toml")


def _cosets(mask):
    """Per new point kind (``y mod 2``): the weights' sum and first moments, ``sum A[y - 2x] x`` at ``y`` in ``{0, 1}^2``."""
    out = {}
    for u, a in mask.items():
        y = (u[0] % 2, u[1] % 2)
        x = ((y[0] - u[0]) // 2, (y[1] - u[1]) // 2)
        s, m0, m1 = out.get(y, (0, 0, 0))
        out[y] = (s + a, m0 + a * x[0], m1 + a * x[1])
    return out


@pytest.mark.parametrize("scheme", [BUTTERFLY, as_stencils(loop())], ids=["butterfly", "loop"])
def test_the_regular_mask_is_read_from_the_rules_and_reproduces_linear_functions(scheme):
    a, mask = regular_mask(scheme)
    assert a == 2
    for y, (total, m0, m1) in _cosets(mask).items():  # each new point is where it refines: y / 2
        assert (total, m0, m1) == (1, Fraction(y[0], 2), Fraction(y[1], 2))
    for u, a in mask.items():  # the rules do not depend on the direction: a sixth of a turn maps the mask to itself
        assert mask.get(turn(u)) == a


@pytest.mark.slow
def test_the_butterfly_interpolates_and_its_difference_scheme_contracts():
    _, mask = regular_mask(BUTTERFLY)
    assert {u: a for u, a in mask.items() if u[0] % 2 == 0 and u[1] % 2 == 0} == {(0, 0): 1}
    b = difference_bounds(BUTTERFLY)
    assert b.closes and b.position == 0 and b.steps >= 2
    assert all(later <= earlier for earlier, later in zip(b.contraction, b.contraction[1:]))


def test_linear_interpolation_halves_second_differences_exactly_so_the_bound_never_closes():
    w0 = _linear_interpolation()
    b = difference_bounds(w0)
    assert [2 ** r * nu for r, nu in enumerate(b.contraction)] == [1] * len(b.contraction) and not b.closes
    r = c1_zorin_test(w0, 5)
    assert r.verdict is C1Verdict.UNDECIDED
    assert r.reason == ("the regular rules' difference scheme does not contract within 3 steps (2^L nu_L = 1 >= 1): no "
                        "bound of the derivatives")


def test_a_functional_is_written_exactly_in_rhombus_differences():
    _, mask = regular_mask(BUTTERFLY)
    c = {(-u[0] // 2, -u[1] // 2): a for u, a in mask.items() if u[0] % 2 == 0 and u[1] % 2 == 0}  # (S p)(0)
    c[(0, 0)] = c.get((0, 0), 0) - 1  # minus p(0): zero here (the butterfly interpolates)
    assert decompose({k: v for k, v in c.items() if v}) == [{}, {}, {}]
    edge = {(0, 0): Fraction(1, 2), (1, 0): Fraction(1, 2), (0, 1): Fraction(-1, 2), (1, -1): Fraction(-1, 2)}
    g = decompose(edge)  # half of a rhombus: the exact combination is found and checked
    assert _expand(g) == edge and sum(abs(v) for gr in g for v in gr.values()) == Fraction(1, 2)
    with pytest.raises(InvalidSchemeError, match=r"^a functional that should vanish on linear functions does not"):
        decompose({(0, 0): Fraction(1), (1, 0): Fraction(-2)})
    assert all(hex_norm(k) <= 2 for r in RHOMBI for k in r)


def test_the_grown_net_is_the_eigenvector_extended_one_level_finer_is_lambda_times_it():
    bounds = difference_bounds(BUTTERFLY)
    with flint.ctx.workprec(128):
        spectral, net = _characteristic(BUTTERFLY, 5)
        lam = spectral.subdominant.value
        net, radius = grow(net, 4, lam, bounds, 20)
        fine, low, high = refine(net, 0, radius, bounds)
        shared = [q for q in fine.values if q in net.values]
        assert len(shared) > 50
        assert max(abs(fine.values[q] - lam * net.values[q]).upper() for q in shared) < 1e-25


@pytest.mark.slow
@pytest.mark.parametrize("n", [4, 5, 7, 8])
def test_the_modified_butterfly_is_c1(n):
    r = c1_zoo(BUTTERFLY, n)
    assert r.verdict is C1Verdict.C1 and r.method == ZORIN_METHOD
    assert r.frequency == 1 and r.winding_number == 1 == r.jacobian_sign and r.jacobian_lower_bound > 0
    assert abs(r.spectral.subdominant.value - flint.fmpq(1, 2)).upper() < 1e-15
    assert r.reason.endswith("winds once: injective (this valence)")


def test_the_regular_valence_is_c1_by_the_regular_rules():
    r = c1_zoo(BUTTERFLY, 6)
    assert r.verdict is C1Verdict.C1 and r.reason.startswith("the vertex is regular and the regular rules' derivative scheme "
                                                             "converges: 2^L nu_L = ")


@pytest.mark.slow
def test_the_modified_butterfly_is_c1_at_valence_3():
    r = c1_zoo(BUTTERFLY, 3)
    assert r.verdict is C1Verdict.C1 and r.winding_number == 1 and r.subdivision_depth == 6


def test_a_shallow_refinement_says_the_bound_did_not_close():
    r = c1_zorin_test(BUTTERFLY, 4, min_depth=1, max_depth=1)
    assert r.verdict is C1Verdict.UNDECIDED and r.reason.startswith("the bound did not close at m = 1: the Jacobian's sign is open")


@pytest.mark.slow
@pytest.mark.parametrize("n", [3, 5, 7])
def test_loop_agrees_with_reifs_test(n):
    zorin, reif = c1_zorin_test(as_stencils(loop()), n), c1_test(loop(), n)
    assert zorin.verdict is reif.verdict is C1Verdict.C1
    assert abs(zorin.spectral.subdominant.value - reif.spectral.subdominant.value).upper() < 1e-12


def test_a_quad_scheme_is_undecided_naming_the_triangles():
    r = c1_zoo(as_stencils(catmull_clark()), 5)
    assert r.verdict is C1Verdict.UNDECIDED
    assert r.reason == "the regular rules give no difference bound: the difference bounds are for triangles; a face has 4 sides"


def test_c1_command_json(capsys):
    assert main(["c1", "--scheme", "modified-butterfly", "--n", "5", "--json", "--quiet"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    assert row["verdict"] == "c1" and row["method"] == ZORIN_METHOD and row["subdivision_depth"] == 4


@pytest.mark.slow
def test_a_butterfly_twisted_to_frequency_two_is_not_certified_at_a_shallow_depth():
    r = c1_zorin_test(_twisted(), 7, min_depth=4, max_depth=4)
    assert r.verdict is C1Verdict.UNDECIDED and r.reason.startswith("the bound did not close at m = 4")


@pytest.mark.slow
def test_a_butterfly_twisted_to_frequency_two_winds_twice_so_it_is_not_c1():
    r = c1_zorin_test(_twisted(), 7)
    assert r.verdict is C1Verdict.NOT_C1 and r.frequency == 2 and r.winding_number == 2
    assert abs(r.spectral.subdominant.value - flint.fmpq(3, 5)).upper() < 1e-15
    assert r.reason == "the characteristic map (lambda = 0.600000) is regular but winds 2 times around the origin: not injective"
