"""Evaluation data at an extraordinary face of a dual quad scheme (Doo-Sabin): the decomposition is exact, Jordan
blocks where the ranks say so, the limit point is the face's centroid (derived from the rules), and at n = 4 the
patches are the biquadratic B-spline of the regular grid."""

import math
from fractions import Fraction
from pathlib import Path

import flint
import pytest
import sympy as sp

from symdecomp.analysis.dual_evaldata import CELLS, dual_evaldata, mesh_chart, spline_reason
from symdecomp.analysis.dual_evaluation import evaluate
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_jordan import with_jordan
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks
from symdecomp.errors import EvaluationError, InvalidInputError, NotApplicableError
from symdecomp.schemes.files import load_scheme
from symdecomp.schemes.lattice import QUAD
from symdecomp.schemes.neighbourhood import neighbourhood
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencils import J, M

DOO_SABIN = load_zoo("doo-sabin")
X = sp.Symbol("x")
VARIANT = Path(__file__).parents[1] / "corpus" / "zoo" / "doo-sabin-rational-gon.toml"
PARAMS = [(Fraction(1, 3), Fraction(1, 5)), (Fraction(7, 8), Fraction(1, 16)), (Fraction(1), Fraction(1)),
          (Fraction(3, 64), Fraction(5, 128)), (Fraction(0), Fraction(2, 3))]


def _identity(size):
    out = flint.fmpq_mat(size, size)
    for i in range(size):
        out[i, i] = 1
    return out


def _nullity(m):
    return m.ncols() - m.rref()[1]


@pytest.mark.parametrize("n", [3, 4, 6])
def test_decomposition_is_exact_and_its_factors_make_the_characteristic_polynomial(n):
    d = dual_evaldata(DOO_SABIN, n)
    assert d.exact and d.size == 9 * n
    product = flint.fmpq_poly([1])
    for b in d.decomposition:
        assert d.matrix * b.basis == b.basis * b.block
        assert b.left * b.basis == _identity(b.basis.ncols())
        product *= flint.fmpq_poly(list(b.factor)) ** b.multiplicity
    charpoly = d.matrix.charpoly()
    assert product / product.coeffs()[-1] == charpoly


@pytest.mark.parametrize("n, defective", [(3, False), (4, False), (6, True)])
def test_jordan_blocks_where_the_ranks_say_so(n, defective):
    """Doo-Sabin's 1/4 at frequencies 2..n-2 of the n-gon meets the regular part's 1/4: ker (A - 1/4)^2 is larger
    than ker (A - 1/4) exactly when the data say a block has fewer eigenvectors than its multiplicity."""
    d = dual_evaldata(DOO_SABIN, n)
    shifted = d.matrix - _identity(d.size) * flint.fmpq(1, 4)
    assert (_nullity(shifted * shifted) > _nullity(shifted)) is defective
    quarter = next(b for b in d.decomposition if b.factor == (-1, 4))
    assert (quarter.eigenvectors < quarter.multiplicity) is defective
    assert quarter.eigenvectors == _nullity(shifted)


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_the_limit_point_is_the_centroid_of_the_face(n):
    """The corner rule's weights sum to 1 over the corners (read from the rule), so a step keeps every face's centroid:
    the limit of F is the mean of its n points."""
    (term,) = DOO_SABIN.rules_of("corner").rules[0].terms
    for m in range(3, 9):
        total = sum(term.weight.subs({M: m, J: j}) for j in range(m))
        assert sp.minimal_polynomial(total - 1, X) == X  # an algebraic number whose minimal polynomial is x: zero
    d = dual_evaldata(DOO_SABIN, n)
    nb = neighbourhood(QUAD, n, 2, centred="face")
    gon = {nb.index()[v] for v in nb.mesh.faces[nb.mesh.face[nb.start]]}
    for i, w in enumerate(d.limit):
        want = 1 if i in gon else 0
        assert (n * w == want) if d.exact else ((n * w).contains(want) and w.rad() < 2.0**-200)
    assert d.exact is (n in (3, 4, 6))


def _quadratic(t):  # the uniform quadratic B-spline basis, written out (not the evaluator's)
    return [(1 - t) ** 2 / 2, Fraction(1, 2) + t - t * t, t * t / 2]


def test_at_n_4_the_patches_are_the_biquadratic_b_spline_of_the_regular_grid():
    """At n = 4 the whole neighbourhood is the grid of half-integer points: every sector's point at (u, v) is the
    level-0 biquadratic patch of the grid around F's corner, and the grid's own coordinates come back (linear precision)."""
    d = dual_evaldata(DOO_SABIN, 4)
    nb = neighbourhood(QUAD, 4, 2, centred="face")
    where, start = {}, nb.start
    for s in range(4):
        for (x, y), v in mesh_chart(nb.mesh, start, 5).items():
            x, y = Fraction(x, 2), Fraction(y, 2)
            for _ in range(s):
                x, y = -y, x
            where[nb.index()[v]] = (x, y)
        start = nb.mesh.next[start]
    at = {p: i for i, p in enumerate(where[i] for i in range(d.size))}
    net = [[Fraction(i % 7 - 3, 1 + i % 4), Fraction(i * i % 11)] for i in range(d.size)]
    for s in range(4):
        for u, v in PARAMS:
            x, y = u, v
            for _ in range(s):
                x, y = -y, x
            cx, cy = min(math.floor(x), 0), min(math.floor(y), 0)  # the level-0 cell of (x, y) in [-1, 1]^2
            want = [sum(_quadratic(x - cx)[i] * _quadratic(y - cy)[j] * net[at[(cx - Fraction(1, 2) + i, cy - Fraction(1, 2) + j)]][k]
                        for i in range(3) for j in range(3)) for k in range(2)]
            got = evaluate(d, s, u, v, net)
            assert [Fraction(int(g.p), int(g.q)) for g in got["point"]] == want
            assert [Fraction(int(g.p), int(g.q)) for g in evaluate(d, s, u, v, [list(where[i]) for i in range(d.size)])["point"]] == [x, y]


@pytest.mark.parametrize("n", [3, 6])
def test_the_eigen_expansion_equals_the_powers(n):
    d = dual_evaldata(DOO_SABIN, n)
    net = [[Fraction(i, 3), Fraction(1, i + 2)] for i in range(d.size)]
    for s in (0, n - 1):
        for u, v in PARAMS:
            assert evaluate(d, s, u, v, net) == evaluate(d, s, u, v, net, route="powers")


def test_a_user_variant_with_rational_rules_is_exact_at_every_n():
    variant = load_scheme(str(VARIANT))
    d = dual_evaldata(variant, 5)
    assert d.exact and d.decomposition is not None and len(d.patches) == 5 and all(len(c) == len(CELLS) for c in d.patches)
    assert spline_reason(variant) is None


@pytest.mark.parametrize("name, words", [
    ("midedge", "is not the biquadratic B-spline's corner rule"),
    ("sqrt3", "takes sqrt3 steps on the triangle lattice"),
    ("modified-butterfly", "is interpolatory: its regular part is not a spline"),
])
def test_families_without_a_biquadratic_part_say_why(name, words):
    reason = spline_reason(load_zoo(name))
    assert words in reason and "\n" not in reason
    with pytest.raises(NotApplicableError):
        dual_evaldata(load_zoo(name), 4)
    assert spline_reason(DOO_SABIN) is None


def test_bad_input_is_one_line():
    d = dual_evaldata(DOO_SABIN, 3)
    net = [[Fraction(1)]] * d.size
    with pytest.raises(InvalidInputError, match="sector must be an integer from 0 to 2, got 3"):
        evaluate(d, 3, Fraction(1, 2), 0, net)
    with pytest.raises(EvaluationError, match="u must be an exact rational in"):
        evaluate(d, 0, 1.5, 0, net)
    with pytest.raises(InvalidInputError, match="control points: need 27 points"):
        evaluate(d, 0, Fraction(1, 2), 0, net[:-1])
    with pytest.raises(EvaluationError, match="level must be an integer m >= 1"):
        evaluate(d, 0, Fraction(1, 2), 0, net, level=3)
    with pytest.raises(InvalidInputError, match="valence"):
        dual_evaldata(DOO_SABIN, 2)


def test_the_jordan_blocks_are_the_frequency_blocks_ones():
    """Another route: the engine's frequency blocks over the cyclotomic field (zoo_jordan) give 1/4 at n = 6 the
    Jordan partition (2, 2, 1, 1, 1, 1, 1): as many eigenvectors as parts, the multiplicity their sum."""
    blocks = zoo_blocks(zoo_matrix(DOO_SABIN, 6, 2))
    (quarter_sizes,) = [e.jordan for e in with_jordan(blocks, spectrum_of_blocks(blocks)).eigenvalues if e.exact == sp.Rational(1, 4)]
    quarter = next(b for b in dual_evaldata(DOO_SABIN, 6).decomposition if b.factor == (-1, 4))
    assert (quarter.eigenvectors, quarter.multiplicity) == (len(quarter_sizes), sum(quarter_sizes)) == (7, 9)


@pytest.mark.parametrize("n", [3, 5, 6])
def test_the_derivatives_are_the_central_differences(n):
    """In one cell the patch is quadratic in u for fixed v: the central difference is its exact derivative."""
    d = dual_evaldata(DOO_SABIN, n)
    net = [[Fraction(i % 5 - 2, 1 + i % 3), Fraction(i * i % 13)] for i in range(d.size)]
    h = Fraction(1, 512)
    for u, v in ((Fraction(3, 8), Fraction(5, 16)), (Fraction(11, 16), Fraction(13, 16)), (Fraction(3, 64), Fraction(5, 128))):
        got = evaluate(d, 1, u, v, net)
        for key, (du, dv) in (("du", (h, 0)), ("dv", (0, h))):
            ahead, back = evaluate(d, 1, u + du, v + dv, net), evaluate(d, 1, u - du, v - dv, net)
            assert ahead["level"] == back["level"] == got["level"]
            for g, a, b in zip(got[key], ahead["point"], back["point"]):
                diff = (a - b) * 256  # / (2 h)
                assert (g == diff) if d.exact else (g.overlaps(diff) and g.rad() < 2.0**-150)
