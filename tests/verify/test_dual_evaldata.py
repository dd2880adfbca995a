"""The evaluation data of Doo-Sabin's n-gon against exact refinement at dyadic parameters (symdecomp.verify.dual_evaldata):
every sector, both routes, both levels on a ring's edge; a moved weight of A or of a picking matrix fails."""

from dataclasses import replace
from pathlib import Path

import flint
import pytest

from symdecomp.analysis.dual_evaldata import dual_evaldata
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.dual_evaldata import dyadic_check, regular_face_mask

DOO_SABIN = load_zoo("doo-sabin")
VARIANT = Path(__file__).parents[1] / "corpus" / "zoo" / "doo-sabin-rational-gon.toml"


def test_the_regular_face_mask_is_derived_and_is_the_centroid():
    """The left eigenvector of the regular face's own matrix: Doo-Sabin keeps face centroids, 1/4 on each corner."""
    mask = regular_face_mask(DOO_SABIN)
    assert {p: str(w) for p, w in mask.items()} == {(1, 1): "1/4", (-1, 1): "1/4", (1, -1): "1/4", (-1, -1): "1/4"}


@pytest.mark.slow
@pytest.mark.parametrize("n", [3, 4, 5, 6])
def test_the_data_equal_exact_refinement_at_dyadic_parameters(n):
    result = dyadic_check(DOO_SABIN, n, levels=(1, 2, 3))
    # every lattice point (p, q), 1 <= max(p, q) <= min(4, 2^M), of every sector: the mask's 2 x 2 support always fits
    assert result["points"] == n * sum((min(4, 2**m) + 1) ** 2 - 1 for m in (1, 2, 3)) and result["mismatches"] == 0
    assert result["routes"] == (("eigen", "powers") if n != 5 else ("powers",))


def test_a_user_variant_file_is_certified_the_same_way():
    result = dyadic_check(load_scheme(str(VARIANT)), 5, levels=(1, 2))
    assert result["mismatches"] == 0 and result["routes"] == ("eigen", "powers")


def _moved(m, row, exact):
    """``m`` with 1/64 moved from one nonzero entry of ``row`` to the next (the row still sums alike)."""
    out = type(m)(m)
    cols = [c for c in range(m.ncols()) if m[row, c] != 0]
    step = flint.fmpq(1, 64) if exact else flint.arb(1) / 64
    out[row, cols[0]] += step
    out[row, (cols[0] + 1) % m.ncols()] -= step
    return out


@pytest.mark.slow
@pytest.mark.parametrize("n", [4, 5])
def test_a_moved_weight_fails(n):
    data = dual_evaldata(DOO_SABIN, n)
    ring_row = 2 * n  # class 2 of the orbit order, a point outside the n-gon (class 0)
    bad = replace(data, matrix=_moved(data.matrix, ring_row, data.exact), decomposition=None, phi=None)
    assert dyadic_check(DOO_SABIN, n, levels=(1, 2), data=bad)["mismatches"] > 0
    patches = [list(sector) for sector in data.patches]
    patches[1][2] = _moved(patches[1][2], 4, data.exact)
    bad = replace(data, patches=tuple(map(tuple, patches)), decomposition=None, phi=None)
    assert dyadic_check(DOO_SABIN, n, levels=(1, 2), data=bad)["mismatches"] > 0
    assert dyadic_check(DOO_SABIN, n, levels=(1, 2), data=replace(data, decomposition=None, phi=None))["mismatches"] == 0


@pytest.mark.slow
@pytest.mark.parametrize("n", [7, 8, 12])
def test_larger_faces_equal_exact_refinement(n):
    result = dyadic_check(DOO_SABIN, n, levels=(1, 2))
    assert result["points"] == n * 32 and result["mismatches"] == 0
