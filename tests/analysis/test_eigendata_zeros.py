"""The sub-patch tables' zeros proved by a mirror symmetry are zeros of the certified balls, and Loop's are all of them.

Every entry :func:`mirror_zeros` claims must be a ball around 0 that rounds to 0.0 at 1200 bits (an independent
computation: the eigenvectors and their products in Arb); for Loop the claim covers every ball around 0 that is
not exactly 0, so no entry of its tables needs a 1200-bit eigenvector any more.
"""

from __future__ import annotations

from fractions import Fraction

import flint
import pytest

from symdecomp.algebra.rounding import round_ball
from symdecomp.analysis import eigendata_direct
from symdecomp.analysis.eigendata import _g_rows, _regular_part, _ring_columns
from symdecomp.analysis.eigendata_columns import _rational_columns, circulant_weights
from symdecomp.analysis.eigendata_zeros import lower_mirror_zeros, mirror_zeros
from symdecomp.schemes.loop import loop, loop_warren
from symdecomp.schemes.patch import patch_matrices
from symdecomp.schemes.scheme import catmull_clark

SCHEMES = {"catmull-clark": catmull_clark(), "loop": loop(), "loop-warren": loop_warren()}


def _claims_and_balls(scheme, n: int, prec: int = 1200):
    p = patch_matrices(scheme, n)
    with flint.ctx.workprec(prec):
        data, *_ = eigendata_direct._direct(p, prec)  # the claimed entries come out exact 0; the balls below do not use them
        cols = _ring_columns(p, prec)
        nus, wmat, winv = _regular_part(p)
        claims = mirror_zeros(p, cols, nus, wmat, _g_rows(p, winv))
    return p, claims


@pytest.mark.parametrize("name", sorted(SCHEMES))
@pytest.mark.parametrize("n", [4, 5, 6, 7, 12, 33])
def test_claimed_zeros_are_balls_that_round_to_zero(name, n, monkeypatch):
    monkeypatch.setattr(eigendata_direct, "mirror_zeros", lambda *args: [])  # the balls as computed, no claim used
    p, claims = _claims_and_balls(SCHEMES[name], n)
    with flint.ctx.workprec(1200):
        data, *_ = eigendata_direct._direct(p, 1200)
    assert claims
    for k, i, l in claims:
        ball = data.phi[k][i, l]
        assert ball.contains(0) and round_ball(ball) == 0.0, (k, i, l, ball)
    if name.startswith("loop"):  # every ball around 0 is claimed: none is left for the 1200-bit columns
        claimed = set(claims)
        open_zeros = [(k, i, l) for k in range(3) for i in range(data.size) for l in range(data.phi[0].ncols())
                      if data.phi[k][i, l].contains(0) and not data.phi[k][i, l].is_zero()]
        assert set(open_zeros) <= claimed


def test_loop_sine_columns_vanish_on_the_edge_o_a0():
    """Loop's sub-patch points on the edge ``O a_0`` (sub-patch 0's points 5, 6; 1's 7; 2's 2 at N = 10) are 0 for
    every sine column (the odd-numbered 1-ring columns from 3 on)."""
    _, claims = _claims_and_balls(loop(), 10, 256)
    sines = range(3, 11, 2)
    for k, l in ((0, 5), (0, 6), (1, 7), (2, 2)):
        assert all((k, i, l) in claims for i in sines)


def test_frequency_zero_columns_are_balls_at_the_current_precision():
    """An irrational eigenvalue of the frequency-0 block is a ball at the precision asked for, even when the block
    was asked for before at a lower one (Catmull-Clark at N = 5: its eigen-pairs are kept between the two)."""
    p = patch_matrices(catmull_clark(), 5)
    with flint.ctx.workprec(256):
        low = [col.value for col in _rational_columns(circulant_weights(p), 5, 0)]
    with flint.ctx.workprec(1200):
        high = [col.value for col in _rational_columns(circulant_weights(p), 5, 0)]
    assert any(x.rad() > 0 for x in low)  # an irrational eigenvalue: a ball, not an exact number
    assert all(x.rad() < flint.arb(2) ** -1100 for x in high)


@pytest.mark.parametrize("name", sorted(SCHEMES))
@pytest.mark.parametrize("n", [4, 5, 6, 9, 16])
def test_lower_block_zeros_are_zeros_of_the_exact_block(name, n):
    """Each entry of ``V^-1``'s lower-left block claimed 0 by a mirror is 0 in the exact block ``-g_r (S - nu_r)^-1``
    (one exact rational solve, where ``nu_r`` is not an eigenvalue of ``S``); Catmull-Clark's six are all found."""
    scheme = SCHEMES[name]
    p = patch_matrices(scheme, n)
    with flint.ctx.workprec(256):
        cols = _ring_columns(p, 256)
        nus, _, winv = _regular_part(p)
        g_rows = _g_rows(p, winv)
        claims = lower_mirror_zeros(p, cols, g_rows)
    if not claims:  # Loop's lower block has no zero of a mirror (its g rows are not antisymmetric)
        assert name != "catmull-clark"
        return
    k0 = p.ring_size
    s = flint.fmpq_mat(k0, k0)
    for i in range(k0):
        for c, x in p.sparse[i].items():
            s[i, c] = flint.fmpq(x.numerator, x.denominator)
    checked = 0
    for i, j in claims:
        r = i - k0
        m = s.transpose()
        for q in range(k0):
            m[q, q] -= flint.fmpq(nus[r].numerator, nus[r].denominator)
        if m.det() == 0:
            continue  # nu_r is an eigenvalue of S: the resolvent is the complement's, left to the balls
        g = flint.fmpq_mat(k0, 1, [flint.fmpq(g_rows[r].get(c, Fraction(0)).numerator, g_rows[r].get(c, Fraction(0)).denominator)
                                   for c in range(k0)])
        assert m.solve(g)[j, 0] == 0
        checked += 1
    if name == "catmull-clark":
        assert len(claims) == 6
        assert checked == (0 if n == 4 else 6)  # at N = 4 the rows' 1/16 is an eigenvalue of S as well
