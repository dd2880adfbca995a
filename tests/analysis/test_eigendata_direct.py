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


def test_the_command_writes_the_whole_valences_bytes(tmp_path):
    out = tmp_path / "cc.dat"
    assert main(["evaldata", "--n", "3:9", "--out", str(out), "--quiet", "--jobs", "1"]) == 0
    assert out.read_bytes() == binary_bytes(certified_eigendata(SCHEMES["catmull-clark"], n)[1] for n in range(3, 10))
    out = tmp_path / "loop.json"
    assert main(["evaldata", "--scheme", "loop", "--format", "json", "--n", "3:7", "--out", str(out), "--quiet", "--jobs", "1"]) == 0
    entries = (json_valence(certified_eigendata(SCHEMES["loop"], n)[1]) for n in range(3, 8))
    assert out.read_text() == "".join(json_chunks(entries, 7, 17, "loop"))
