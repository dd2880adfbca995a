"""Exact evaluation of boundary and corner patches: against exact refinement at dyadic parameters and the limit mask.

The default cases include defective matrices (Catmull-Clark boundary k = 3, Loop corner k = 3): the evaluator's
matrix powers need no eigenvector basis."""

from fractions import Fraction

import flint
import pytest
import sympy as sp

from symdecomp.analysis.evaluation import evaluate
from symdecomp.analysis.subpatch_data import sharp_patch_data
from symdecomp.errors import EvaluationError, InvalidInputError, NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sector import SharpVertex, exact_sharp_matrix
from symdecomp.verify.patch_eval import dyadic_check

SCHEMES = {"catmull-clark": catmull_clark, "loop": loop}


def _vertex(kind, k, scheme):
    return getattr(SharpVertex, kind)(k, scheme.lattice)


@pytest.mark.parametrize("name", SCHEMES)
@pytest.mark.parametrize("kind", ["boundary", "corner"])
@pytest.mark.parametrize("k", [1, 3])
def test_dyadic_points_equal_exact_refinement(name, kind, k):
    scheme = SCHEMES[name]()
    result = dyadic_check(scheme, _vertex(kind, k, scheme), levels=(1, 2), seed=k)
    assert result["points"] > 10 * k
    assert result["exact_mismatches"] == 0
    assert result["float_error"] < 1e-13


@pytest.mark.slow
@pytest.mark.parametrize("name", SCHEMES)
@pytest.mark.parametrize("kind", ["boundary", "corner"])
@pytest.mark.parametrize("k", range(1, 9))
def test_dyadic_points_deep_levels_k_1_to_8(name, kind, k):
    scheme = SCHEMES[name]()
    result = dyadic_check(scheme, _vertex(kind, k, scheme), levels=(1, 2, 3, 7), seed=100 + k)
    assert result["exact_mismatches"] == 0
    assert result["float_error"] < 1e-13


@pytest.mark.parametrize("name", SCHEMES)
def test_limit_mask_is_a_left_eigenvector_and_the_limit_of_the_patch(name):
    scheme = SCHEMES[name]()
    data = sharp_patch_data(scheme, SharpVertex.boundary(4, scheme.lattice))
    assert sum(data.limit) == 1
    image = [sum((data.limit[r] * w for r, row in enumerate(data.matrix) for c2, w in row.items() if c2 == c), Fraction(0))
             for c in range(data.size)]
    assert image == list(data.limit)
    net = [[Fraction((7 * i) % 11 - 5), Fraction(i % 3)] for i in range(data.size)]
    limit = evaluate(data, 2, 0, 0, net)["point"]
    floats = [[float(x) for x in p] for p in net]
    gaps = [max(abs(a - float(b)) for a, b in zip(evaluate(data, 2, 2.0**-m, 2.0**-m / 3, floats)["point"], limit))
            for m in (10, 20, 40)]
    assert gaps[0] > gaps[1] > gaps[2] and gaps[2] < 1e-6  # the subdominant eigenvalue of k = 4 is about 0.6


@pytest.mark.parametrize("name, kind, k, defective", [
    ("catmull-clark", "boundary", 4, (1, 2)), ("catmull-clark", "corner", 2, (1, 2)), ("loop", "boundary", 6, (1, 2)),
    ("catmull-clark", "boundary", 2, None), ("loop", "corner", 4, None),
])
def test_exact_spectrum_is_the_characteristic_polynomial_and_finds_the_jordan_blocks(name, kind, k, defective):
    scheme = SCHEMES[name]()
    vertex = _vertex(kind, k, scheme)
    data = sharp_patch_data(scheme, vertex)
    a = exact_sharp_matrix(scheme, vertex, rings=2)
    size = a.nrows()
    x = sp.Symbol("x")
    product = sp.Poly(sp.Mul(*(sp.Poly(list(reversed(q)), x).as_expr() ** e for q, e, _ in data.spectrum)), x).monic()
    coeffs = [flint.fmpq(int(c.p), int(c.q)) for c in product.all_coeffs()]
    assert len(coeffs) == size + 1 and coeffs[1] == -sum((a[i, i] for i in range(size)), flint.fmpq(0))
    assert coeffs[-1] == (-1) ** size * a.det()
    value = flint.fmpq_mat(size, size)
    for c in coeffs:  # Horner: the product annihilates A (Cayley-Hamilton), degree K, trace and determinant agree
        value = value * a
        for i in range(size):
            value[i, i] += c
    assert all(value[i, j] == 0 for i in range(size) for j in range(size))
    assert data.diagonalizable is (defective is None)
    if defective is not None:  # a Jordan chain at the eigenvalue p/q: the rank drops again at the square
        shifted = a - flint.fmpq(*defective) * flint.fmpq_mat(size, size, [int(i == j) for i in range(size) for j in range(size)])
        assert (shifted * shifted).rref()[1] < shifted.rref()[1]


def test_corner_interpolates_the_vertex():
    scheme = catmull_clark()
    data = sharp_patch_data(scheme, SharpVertex.corner(3, scheme.lattice))
    assert data.limit[0] == 1 and not any(data.limit[1:])


def test_affine_invariance_exact():
    scheme = loop()
    data = sharp_patch_data(scheme, SharpVertex.boundary(5, scheme.lattice))
    got = evaluate(data, 4, Fraction(3, 16), Fraction(5, 8), [[Fraction(2, 3)]] * data.size)
    assert got["point"] == [Fraction(2, 3)] and got["du"] == [0] and got["dv"] == [0]


def test_modified_edge_rules_are_refused():
    scheme = load_scheme("catmull-clark-blz")
    with pytest.raises(NotApplicableError, match="modified rules"):
        sharp_patch_data(scheme, SharpVertex.boundary(3, scheme.lattice))


def test_bad_input_one_line():
    scheme = catmull_clark()
    data = sharp_patch_data(scheme, SharpVertex.boundary(2, scheme.lattice))
    net = [[0.0]] * data.size
    with pytest.raises(InvalidInputError, match="face must be"):
        evaluate(data, 2, 0.5, 0.5, net)
    with pytest.raises(EvaluationError, match="u must be"):
        evaluate(data, 0, 1.5, 0.5, net)
    with pytest.raises(InvalidInputError, match="control points"):
        evaluate(data, 0, 0.5, 0.5, net[1:])
    with pytest.raises(NotApplicableError, match="boundary and corner"):
        sharp_patch_data(scheme, SharpVertex.crease(2, 2, scheme.lattice))
