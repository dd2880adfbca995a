"""Zorin's test over sqrt(3)'s two steps: the steps refine the triangle lattice by 1/3 (triadic), the regular rules'
difference scheme contracts, the characteristic map is certified regular and injective valence by valence (Kobbelt,
*sqrt(3)-subdivision*, SIGGRAPH 2000, Section 5: C1 at every valence), and a bad valence-dependent vertex weight is
found not C1 by the spectral conditions, with the eigenvalue the 2 x 2 block of the 1-ring predicts."""

from __future__ import annotations

from fractions import Fraction
from itertools import product

import flint
import pytest
import sympy as sp

from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text, stencil_scheme_to_text
from symdecomp.schemes.stencils import StencilScheme
from symdecomp.verify.c1_zoo import c1_zoo, zorin_route
from symdecomp.verify.c1_zorin import ZORIN_METHOD, c1_zorin_test
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zorin_bounds import difference_bounds, regular_mask, turn

SQRT3 = load_zoo("sqrt3")
KOBBELT_CENTRE = "2*cos(2*pi/n)/9 + 5/9"  # 1 - alpha_n, alpha_n = (4 - 2 cos(2 pi/n))/9, as the file is written
KOBBELT_RING = "(4 - 2*cos(2*pi/n))/(9*n)"


def _variant(name: str, centre: str, ring: str) -> StencilScheme:
    text = stencil_scheme_to_text(SQRT3)
    assert KOBBELT_CENTRE in text and KOBBELT_RING in text
    text = text.replace(KOBBELT_CENTRE, centre).replace(KOBBELT_RING, ring).replace('name = "sqrt3"', f'name = "{name}"')
    return stencil_scheme_from_text(text, source=f"{name}.toml")


def _lambda(n: int) -> float:
    """Kobbelt's subdominant eigenvalue of two steps, ``(2 + 2 cos(2 pi/n))/9``, from the 1-ring's frequency-1 block."""
    return float((2 + 2 * sp.cos(2 * sp.pi / n)) / 9)


def _kobbelt_two_steps() -> dict[tuple[int, int], Fraction]:
    """The regular two-step mask built here from Kobbelt's rules on the lattice, without the engine: the response to a
    unit at the origin, in coordinates of the lattice refined by 1/3 (the triangle lattice ``x e_1 + y w``)."""
    exact = sp.Rational((4 - 2 * sp.cos(2 * sp.pi / 6)) / 9)  # Kobbelt's alpha_n at n = 6
    alpha = Fraction(int(exact.p), int(exact.q))
    ring0 = [(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)]  # the six neighbours, counter-clockwise
    ring1 = [(a[0] + b[0], a[1] + b[1]) for a, b in zip(ring0, ring0[1:] + ring0[:1])]  # 3 x the centroids around 0

    def delta(v):
        return Fraction(1) if v == (0, 0) else Fraction(0)

    def level1(q):  # q in thirds: an old vertex (q = 0 mod 3), relaxed, or a centroid (the mean of its three corners)
        if q[0] % 3 == 0 and q[1] % 3 == 0:
            v = (q[0] // 3, q[1] // 3)
            return (1 - alpha) * delta(v) + alpha / 6 * sum(delta((v[0] + d[0], v[1] + d[1])) for d in ring0)
        corners = [(q[0] + d[0], q[1] + d[1]) for d in ring1 if (q[0] + d[0]) % 3 == 0 and (q[1] + d[1]) % 3 == 0]
        assert len(corners) == 3
        return sum(delta((c[0] // 3, c[1] // 3)) for c in corners) / 3

    def on_level1(q):
        return (q[0] - q[1]) % 3 == 0  # old vertices (0, 0) and centroids (1, 1), (2, 2) mod 3

    mask = {}
    for y in product(range(-10, 11), repeat=2):
        if on_level1(y):  # the second step relaxes a level-1 vertex over its six level-1 neighbours
            value = (1 - alpha) * level1(y) + alpha / 6 * sum(level1((y[0] + d[0], y[1] + d[1])) for d in ring1)
        else:  # or puts a point at the centroid of a level-1 triangle: its three corners are unit steps away
            corners = [(y[0] + d[0], y[1] + d[1]) for d in ring0 if on_level1((y[0] + d[0], y[1] + d[1]))]
            assert len(corners) == 3
            value = sum(level1(c) for c in corners) / 3
        if value:
            mask[y] = value
    return mask


def test_the_two_steps_are_kobbelts_rules_on_the_lattice_built_here():
    a, mask = regular_mask(SQRT3)
    assert (a, mask) == (3, _kobbelt_two_steps())


def test_two_steps_refine_the_lattice_by_a_third_and_reproduce_linear_functions():
    a, mask = regular_mask(SQRT3)
    assert a == 3
    for y0 in range(3):
        for y1 in range(3):  # each of the nine kinds of new point: weights summing to 1, centred where it sits, y / 3
            terms = [(w, ((y0 - u[0]) // 3, (y1 - u[1]) // 3)) for u, w in mask.items()
                     if (u[0] - y0) % 3 == 0 and (u[1] - y1) % 3 == 0]
            assert sum(w for w, _ in terms) == 1
            assert (sum(w * x[0] for w, x in terms), sum(w * x[1] for w, x in terms)) == (Fraction(y0, 3), Fraction(y1, 3))
    assert all(mask.get(turn(u)) == w for u, w in mask.items())  # a sixth of a turn maps the two steps to themselves


def test_the_route_is_zorins_and_the_regular_vertex_is_c1_by_the_contraction():
    assert zorin_route(SQRT3)
    b = difference_bounds(SQRT3)
    assert b.dilation == 3 and b.closes and b.position > 0  # sqrt(3) approximates: positions move
    r = c1_zoo(SQRT3, 6)
    assert r.verdict is C1Verdict.C1 and r.reason.startswith("the vertex is regular and the regular rules' derivative "
                                                             "scheme converges: 3^L nu_L = ")


@pytest.mark.parametrize("n", [3, pytest.param(4, marks=pytest.mark.slow)])
def test_sqrt3_is_c1(n):
    r = c1_zoo(SQRT3, n)
    assert r.verdict is C1Verdict.C1 and r.method == ZORIN_METHOD
    assert r.frequency == 1 and r.winding_number == 1 == r.jacobian_sign and r.jacobian_lower_bound > 0
    assert abs(r.spectral.subdominant.value.real.mid() - _lambda(n)) < 1e-15
    assert r.reason.endswith("winds once: injective (this valence)")


@pytest.mark.slow
@pytest.mark.parametrize("n", [5, 7, 8, 12])
def test_sqrt3_is_c1_at_more_valences(n):
    r = c1_zoo(SQRT3, n)
    assert r.verdict is C1Verdict.C1 and r.winding_number == 1 == r.jacobian_sign
    assert abs(r.spectral.subdominant.value.real.mid() - _lambda(n)) < 1e-15


@pytest.mark.parametrize("n", [pytest.param(3, marks=pytest.mark.slow), 4])
def test_a_bad_valence_dependent_vertex_weight_is_not_c1(n):
    # alpha_n = (n - 3)/9 agrees with Kobbelt's 1/3 at n = 6 (the regular rules are unchanged) but at n = 3, 4 the
    # frequency-0 block of the 1-ring, [[1 - alpha, alpha], [1/3, 2/3]] per step, has 2/3 - alpha, squared over the two
    # steps, above Kobbelt's frequency-1 eigenvalue
    bad = _variant("sqrt3-bad-alpha", "(12 - n)/9", "(n - 3)/(9*n)")
    r = c1_zoo(bad, n)
    assert r.verdict is C1Verdict.NOT_C1
    assert r.reason.startswith("the subdominant eigenvalue ") and r.reason.endswith("(its frequencies: 0)")
    expected = (Fraction(2, 3) - Fraction(n - 3, 9)) ** 2
    assert expected > _lambda(n)
    assert abs(float(r.reason.split()[3]) - float(expected)) < 1e-15


def test_a_vertex_that_stays_where_it_is_gives_no_derivative_bound():
    kept = _variant("sqrt3-kept", "1", "0")  # alpha = 0 at every valence, the regular one too
    b = difference_bounds(kept)
    assert not b.closes and b.dilation ** b.steps * b.contraction[-1] >= 1
    with flint.ctx.workprec(64):
        r = c1_zorin_test(kept, 5)
    assert r.verdict is C1Verdict.UNDECIDED
    assert r.reason == (f"the regular rules' difference scheme does not contract within {b.steps} steps (3^L nu_L = "
                        f"{float(3 ** b.steps * b.contraction[-1]):.4g} >= 1): no bound of the derivatives")


def test_the_clear_radius_counts_paths_whose_weights_cancel(monkeypatch):
    """A new point whose composed weight on an old point cancels to 0 still reads that point's rule through the steps:
    the radius past which rules are regular counts it (the nonzero mask alone would stop short of it)."""
    import symdecomp.verify.zorin_bounds as zb

    a, pos0, pos, rows = zb._regular_rows(SQRT3)
    assert zb.regular_reach(SQRT3) == max(zb.hex_norm(u) for u in regular_mask(SQRT3)[1]) == 5
    centre = next(i for i, p in pos.items() if p == (0, 0))
    far = max(pos0, key=lambda v: zb.hex_norm((int(pos0[v][0]), int(pos0[v][1]))))
    reach = zb.hex_norm((a * int(pos0[far][0]), a * int(pos0[far][1])))
    assert reach > 5
    cancelled = {**rows, centre: {**rows[centre], far: sp.Integer(0)}}  # a path to ``far`` whose weights sum to 0
    monkeypatch.setattr(zb, "_regular_rows", lambda scheme: (a, pos0, pos, cancelled))
    assert zb.regular_reach(SQRT3) == reach
    assert max(zb.hex_norm(u) for u in regular_mask(SQRT3)[1]) == 5
