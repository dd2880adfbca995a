"""The data file's valences rounded straight from the frequency columns are the whole valence's, bit for bit.

Correct rounding is unique, so :func:`rounded_valence` (no ``K x K`` ball matrices, entries that do not
round sharpened row by row) must give the same float64s as :func:`certified_eigendata` (the whole ``V``,
``V^-1`` and tables in Arb, then rounded); the command's file must be the same bytes as the file written
from ``certified_eigendata``.
"""

from __future__ import annotations

import numpy as np
import pytest

from symdecomp.analysis.eigendata import certified_eigendata
from symdecomp.analysis.eigendata_direct import rounded_valence
from symdecomp.cli import main
from symdecomp.output.evaldata import binary_bytes, json_chunks, json_valence
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark

SCHEMES = {"catmull-clark": catmull_clark(), "loop": loop()}


def _same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and bool((a.view("u8") == b.view("u8")).all())


@pytest.mark.parametrize("name", sorted(SCHEMES))
@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 8, 11, 16, 21])
def test_rounded_valence_is_the_whole_valence_bit_for_bit(name, n):
    scheme = SCHEMES[name]
    prec, fast = rounded_valence(scheme, n)
    whole, slow = certified_eigendata(scheme, n)
    assert prec <= whole.prec
    for a, b in ((fast.values, slow.values), (fast.inverse, slow.inverse), (fast.phi, slow.phi)):
        assert _same_bits(a, b)
    assert [(i, c, float(g)) for i, c, g in fast.jordan] == [(i, c, float(g)) for i, c, g in slow.jordan]
    assert not np.signbit(fast.inverse[fast.inverse == 0]).any()  # exact zeros are +0.0, as the file had them


def test_entries_that_do_not_round_are_sharpened_alone():
    """Catmull-Clark at N = 4 and 16: the lower block's symmetric zeros do not round at 256 bits; they are taken
    from the columns at 1200 bits entry by entry, so the valence stays at 256 bits (the whole valence of
    certified_eigendata goes to 1200 bits at N = 4) and the sub-patch zeros at N = 16 are proved column by column."""
    from symdecomp.algebra.rounding import round_ball
    from symdecomp.analysis.eigendata import patch_eigendata

    cc = SCHEMES["catmull-clark"]
    for n in (4, 16):
        balls = patch_eigendata(cc, n, 256)
        assert any(round_ball(x) is None for x in balls.inverse.entries())  # there is something to sharpen
        assert rounded_valence(cc, n)[0] == 256
    assert certified_eigendata(cc, 4)[0].prec == 1200


@pytest.mark.parametrize(("name", "n"), [("catmull-clark", 5), ("catmull-clark", 9), ("loop", 9)])
def test_a_low_precision_leaves_entries_unrounded_and_they_come_out_the_same(name, n):
    """At 64 bits some entries of ``V^-1`` do not round (they are NaN in the rounded array, never a value); the
    valence then comes out of the sharpening steps or the whole route with the same float64s as at 256 bits."""
    import flint

    from symdecomp.analysis.eigendata_direct import _direct
    from symdecomp.schemes.patch import patch_matrices

    scheme = SCHEMES[name]
    with flint.ctx.workprec(64):
        _, inverse, phi = _direct(patch_matrices(scheme, n), 64)
    assert np.isnan(inverse).any() and np.isfinite(inverse[~np.isnan(inverse)]).all()
    assert np.isfinite(phi[~np.isnan(phi)]).all()
    _, low = rounded_valence(scheme, n, 64)
    _, slow = certified_eigendata(scheme, n)
    for a, b in ((low.values, slow.values), (low.inverse, slow.inverse), (low.phi, slow.phi)):
        assert _same_bits(a, b)


@pytest.mark.parametrize(("n", "count"), [(101, 5), (21, 2), (16, 3)])
def test_two_transforms_in_one_give_the_real_parts_of_each(n, count):
    """The real parts of Arb's DFT of each vector, and of two at once through Hermitian parts (lengths with a
    prime factor from 7), are overlapping balls narrower than 2^-200 (an odd vector out is transformed alone)."""
    import flint

    from symdecomp.analysis.eigendata_direct import _real_parts_of_dfts

    with flint.ctx.workprec(256):
        vectors = [[flint.acb(flint.fmpq(j * j - 3 * v, 7 + v), flint.fmpq(5 - j, 3 + j + v)) for j in range(n)]
                   for v in range(count)]
        packed = _real_parts_of_dfts(vectors)
        alone = [[x.real for x in flint.acb.dft(vector)] for vector in vectors]
    assert len(packed) == count
    for got, want in zip(packed, alone):
        assert all(a.overlaps(b) and a.rad() < 2.0**-200 for a, b in zip(got, want))


def test_the_command_writes_the_whole_valences_bytes(tmp_path):
    out = tmp_path / "cc.dat"
    assert main(["evaldata", "--n", "3:9", "--out", str(out), "--quiet", "--jobs", "1"]) == 0
    assert out.read_bytes() == binary_bytes(certified_eigendata(SCHEMES["catmull-clark"], n)[1] for n in range(3, 10))
    out = tmp_path / "loop.json"
    assert main(["evaldata", "--scheme", "loop", "--format", "json", "--n", "3:7", "--out", str(out), "--quiet", "--jobs", "1"]) == 0
    entries = (json_valence(certified_eigendata(SCHEMES["loop"], n)[1]) for n in range(3, 8))
    assert out.read_text() == "".join(json_chunks(entries, 7, 17, "loop"))


def _lower_block_pieces(scheme, n: int):
    """The patch, its 1-ring columns and ``D`` at 256 bits, as :func:`rounded_valence` computes them."""
    import flint

    from symdecomp.analysis.eigendata import _outer_coefficients, _regular_part, _ring_columns
    from symdecomp.schemes.patch import patch_matrices

    p = patch_matrices(scheme, n)
    with flint.ctx.workprec(256):
        cols = _ring_columns(p, 256)
        nus, _, winv = _regular_part(p)
        right = {i: [col.right_at(i) for col in cols] for i in range(p.ring_size)}
        dmat, _ = _outer_coefficients(p, cols, nus, winv, right)
    return p, cols, dmat, nus, winv


@pytest.mark.parametrize("n", [3, 5, 8, 13])
def test_lower_block_by_waves_holds_the_exact_rational_entries(n):
    """Catmull-Clark: row r of V^-1's lower-left block is -g_r (S - nu_r)^-1 (g = W^-1 S11), an exact rational
    row (one exact solve, where nu_r is not an eigenvalue of S); every ball of the block summed by DFTs contains it
    and is narrow."""
    import flint

    from symdecomp.analysis.eigendata_direct import _lower_by_waves, _wave_layout

    p, cols, dmat, nus, winv = _lower_block_pieces(SCHEMES["catmull-clark"], n)
    assert _wave_layout(cols) is not None  # the DFT route is the one taken
    with flint.ctx.workprec(256):
        lower = _lower_by_waves(cols, dmat)
    k0, size = p.ring_size, p.size
    s = flint.fmpq_mat([[p.matrix[i, c] for c in range(k0)] for i in range(k0)])
    s11 = flint.fmpq_mat([[p.matrix[i, c] for c in range(k0)] for i in range(k0, size)])
    g, checked = winv * s11, 0
    for r, nu in enumerate(nus):
        m = s.transpose() - flint.fmpq(nu.numerator, nu.denominator) * flint.fmpq_mat(k0, k0, [int(i == j) for i in range(k0) for j in range(k0)])
        try:
            exact = m.solve(flint.fmpq_mat([[-g[r, c]] for c in range(k0)]))
        except ZeroDivisionError:  # nu_r is an eigenvalue of S: no resolvent to compare with (N = 8: nu = 1/8)
            continue
        checked += 1
        with flint.ctx.workprec(1024):  # the rational as a ball far narrower than the 256-bit ones
            assert all(lower[r][j].contains(flint.arb(exact[j, 0])) and lower[r][j].rad() < flint.arb(2) ** -200 for j in range(k0))
    assert checked >= 5


@pytest.mark.parametrize("n", [4, 7, 12])
def test_lower_block_by_waves_agrees_with_the_matrix_product_for_loop(n):
    """Loop (1-ring weights in Q(zeta_2N)): the DFT sums overlap the K x K ball product -D V0^-1 and are as narrow."""
    import flint

    from symdecomp.analysis.eigendata_direct import _lower_by_waves

    _, cols, dmat, _, _ = _lower_block_pieces(SCHEMES["loop"], n)
    with flint.ctx.workprec(256):
        waves = _lower_by_waves(cols, dmat)
        product = (-(flint.arb_mat(dmat) * flint.arb_mat([col.left for col in cols]))).tolist()
    assert waves is not None
    for row_w, row_p in zip(waves, product):
        assert all(a.overlaps(b) and a.rad() < flint.arb(2) ** -200 for a, b in zip(row_w, row_p))
