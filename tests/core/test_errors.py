"""Bad input gets an error that names the problem."""

import math

import numpy as np
import pytest
import sympy as sp

from symdecomp import (
    FrequencyOutOfRangeError,
    InvalidPolygonError,
    InvalidValenceError,
    NotAffineError,
    Stencil,
    VertexRule,
    catmull_clark,
    per_frequency_matrix_at,
    subdivision_matrix,
)
from symdecomp.algebra.polygons import decompose
from symdecomp.cli import main


@pytest.mark.parametrize("bad", [2, 0, -3, 3.0, "5", True, sp.Rational(7, 2)])
def test_valence_must_be_an_integer_at_least_three(bad):
    with pytest.raises(InvalidValenceError, match="valence n must be an integer >= 3"):
        subdivision_matrix(catmull_clark(), bad)


@pytest.mark.parametrize("j", [-1, 10, 2.0])
def test_frequency_out_of_range(j):
    with pytest.raises(FrequencyOutOfRangeError, match=r"0 <= j < 10"):
        per_frequency_matrix_at(catmull_clark(), 5, j)


def test_rules_must_be_affine():
    with pytest.raises(NotAffineError, match="weights sum to 9/8, not 1"):
        Stencil.from_weights(sp.Rational(1, 2), {0: sp.Rational(1, 2)}, {0: sp.Rational(1, 8)}, name="edge rule")
    with pytest.raises(NotAffineError, match="vertex rule is not affine"):
        VertexRule.from_weights(1 - sp.Symbol("a") - sp.Symbol("b"), sp.Symbol("a"), sp.Symbol("b"))
    with pytest.raises(Exception, match="float"):
        Stencil.from_weights(0.5, {0: 0.5}, {})


@pytest.mark.parametrize(
    "polygon, message",
    [
        (np.array([[0.0, 0, 0], [1, 0, 0], [0, math.nan, 0]]), "not finite"),
        (np.array([[0.0, 0], [1, 0], [0, 1]]), "got 2 coordinates"),
        (np.zeros((2, 3)), "at least 3 vertices"),
        ([[0, 0, 0], [1, 0, 0], [0, 1]], "different numbers of coordinates"),
        ([[0, 0, 0], [1, 0, 0], [0, sp.sqrt(2), 0]], "not a \\(Gaussian\\) rational"),
        (np.array([[0, 0, 0], [1, 0, 0], [0, 1j, 0]]), "not real"),
        ("abc", "expected an n x 3 array"),
    ],
)
def test_bad_polygons(polygon, message):
    with pytest.raises(InvalidPolygonError, match=message):
        decompose(polygon)


def test_cli_rejects_bad_valence(capsys):
    assert main(["spectrum", "2"]) == 2
    assert "argument N: expected a valence: an integer >= 3 and <= 2000, got 2" in capsys.readouterr().err
