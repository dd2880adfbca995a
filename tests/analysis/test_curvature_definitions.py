"""The curvature regimes' definitions (analysis/curvature_regime.py): one function decides, from the sign of |mu| - lambda_1^2."""

import pytest

from symdecomp.analysis.curvature_regime import CurvatureRegime, curvature_regime, frequency_kind
from symdecomp.errors import InvalidInputError, InvalidValenceError


def test_each_sign_gives_its_regime_and_a_jordan_block_makes_a_tie_unbounded():
    assert [curvature_regime(s) for s in (-1, 0, 1, None)] == [
        CurvatureRegime.ZERO, CurvatureRegime.BOUNDED, CurvatureRegime.UNBOUNDED, CurvatureRegime.UNDECIDED]
    assert curvature_regime(0, defective=True) is CurvatureRegime.UNBOUNDED
    assert curvature_regime(-1, defective=True) is CurvatureRegime.ZERO  # a Jordan block below lambda_1^2 still decays


@pytest.mark.parametrize("bad", [2, -2, 0.0, True, "0"])
def test_a_comparison_that_is_not_a_sign_is_refused(bad):
    with pytest.raises(InvalidInputError, match="comparison"):
        curvature_regime(bad)


def test_frequencies_are_named_as_in_the_paper_modulo_conjugation():
    # j and n - j are one frequency pair: at n = 3 the frequency 2 is the tangent plane's conjugate, at n = 4 it is n/2
    assert [frequency_kind(j, 3) for j in range(3)] == ["elliptic", "tangent", "tangent"]
    assert [frequency_kind(j, 8) for j in range(5)] == ["elliptic", "tangent", "hyperbolic", "frequency 3", "frequency 4"]
    assert frequency_kind(6, 8) == "hyperbolic"
    with pytest.raises(InvalidValenceError):
        frequency_kind(0, 2)
    with pytest.raises(InvalidInputError):
        frequency_kind(-1, 5)
