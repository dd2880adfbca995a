"""The regular patch derived from a dual quad scheme's corner rule on the four-direction mesh (Midedge's box spline).

Checked against what the derivation does not impose: hand-computed values of the Zwart-Powell box spline, its C1
joins (only continuity is built into the space), its symmetry, linear precision, an explicit dual step of a control
grid refined independently here, and the rules whose regular part is no piecewise quadratic there.
"""

from fractions import Fraction as F

import pytest
import sympy as sp

from symdecomp.algebra.triangle_bezier import bernstein
from symdecomp.errors import InvalidSchemeError, InvalidTypeError
from symdecomp.schemes.four_direction import CORNERS, OFFSETS, four_direction_patch, refinement_mask

MIDEDGE = (F(1, 2), F(1, 4), F(0), F(1, 4))
#: A grid of points in the cell centred at 0 (sides included), exact.
POINTS = [(F(i, 6) - F(1, 2), F(k, 6) - F(1, 2)) for i in range(7) for k in range(7)]


@pytest.fixture(scope="module")
def zp():
    return four_direction_patch(MIDEDGE)


def test_zwart_powell_hand_values(zp):
    """Worked by hand for the ZP box spline: 1/2 at its centre, 1/8 one lattice step away, 0 on the diagonal there;
    1/4 at a cell's corner from each of the four nearest points."""
    centre = (F(0), F(0))
    assert zp.value((0, 0), centre) == F(1, 2)
    assert all(zp.value(b, centre) == F(1, 8) for b in ((1, 0), (0, 1), (-1, 0), (0, -1)))
    assert all(zp.value(b, centre) == 0 for b in ((1, 1), (-1, 1), (1, -1), (-1, -1)))
    corner = (F(1, 2), F(1, 2))
    assert [zp.value(b, corner) for b in ((0, 0), (1, 0), (0, 1), (1, 1))] == [F(1, 4)] * 4
    assert all(zp.value(b, corner) == 0 for b in OFFSETS if b not in ((0, 0), (1, 0), (0, 1), (1, 1)))


def test_partition_of_unity_and_linear_precision(zp):
    for p in POINTS:
        assert sum(zp.value(b, p) for b in OFFSETS) == 1
        assert sum(b[0] * zp.value(b, p) for b in OFFSETS) == p[0]
        assert sum(b[1] * zp.value(b, p) for b in OFFSETS) == p[1]


def test_symmetric_under_the_square_group(zp):
    """phi(x - b) at p equals phi(x - R b) at R p for the quarter turn and the mirror (not built into the derivation)."""
    turns = (lambda x, y: (-y, x), lambda x, y: (x, -y))
    for r in turns:
        for b in OFFSETS:
            for p in POINTS:
                assert zp.value(b, p) == zp.value(r(*b), r(*p))


def _pieces(patch, b):
    """phi(x - b) on the four triangles of cell 0 as polynomials in x, y."""
    x, y = sp.symbols("x y")
    out = []
    for k in range(4):
        (ax, ay), (bx, by) = CORNERS[k], CORNERS[(k + 1) % 4]
        det = ax * by - ay * bx
        u, v = (x * by - y * bx) / det, (ax * y - ay * x) / det
        coeffs = patch.coefficients[k][OFFSETS.index(b)]
        out.append(sp.expand(sum(sp.Rational(c.numerator, c.denominator) * w for c, w in zip(coeffs, bernstein(2, u, v)))))
    return out, x, y


def test_c1_across_the_diagonals_and_the_cell_sides(zp):
    """The space is only continuous; the derived function's gradient is continuous too (the box spline is C1)."""
    for b in OFFSETS:
        pieces, x, y = _pieces(zp, b)
        for k in range(4):  # the diagonal between triangles k and k+1 is the ray through r_(k+1)
            (cx, cy) = CORNERS[(k + 1) % 4]
            t = sp.Symbol("t")
            on = {x: t * cx, y: t * cy}
            for d in (x, y):
                assert sp.expand((sp.diff(pieces[k], d) - sp.diff(pieces[(k + 1) % 4], d)).subs(on)) == 0
    for b in OFFSETS:  # across the side u = 1/2: cell 0's right triangle and cell (1, 0)'s left one
        right, x, y = _pieces(zp, b)
        shifted = (b[0] - 1, b[1])
        left = _pieces(zp, shifted)[0][2] if shifted in OFFSETS else sp.Integer(0)
        left = left.subs(x, x - 1)
        for d in (x, y):
            assert sp.expand((sp.diff(right[0], d) - sp.diff(left, d)).subs(x, sp.Rational(1, 2))) == 0


def test_an_explicit_dual_step_gives_the_same_surface(zp):
    """A control grid refined by the corner rule, face by face (written here, not the mask), has the same limit."""
    coarse = {(i, k): F((3 * i * i - 2 * k + i * k * k) % 7) for i in range(-4, 5) for k in range(-4, 5)}
    fine = {}
    for i in range(-4, 4):
        for k in range(-4, 4):
            corners = [(i, k), (i + 1, k), (i + 1, k + 1), (i, k + 1)]
            for own, (a, c) in enumerate(((0, 0), (1, 0), (1, 1), (0, 1))):
                fine[(2 * i + a, 2 * k + c)] = sum(MIDEDGE[(m - own) % 4] * coarse[corners[m]] for m in range(4))

    def surface(net, p, scale, shift):
        q = (scale * p[0] - shift, scale * p[1] - shift)
        cell = (int((q[0] + F(1, 2)) // 1), int((q[1] + F(1, 2)) // 1))
        local = (q[0] - cell[0], q[1] - cell[1])
        return sum(net[(cell[0] + b[0], cell[1] + b[1])] * zp.value(b, local) for b in OFFSETS)

    for p in [(F(i, 5) - F(1, 1), F(k, 7) - F(1, 2)) for i in range(11) for k in range(8)]:
        assert surface(coarse, p, 1, 0) == surface(fine, p, 2, F(1, 2))


def test_the_mask_of_the_midedge_rule():
    """Each fine point around the old point 0 puts 1/2, 1/4 or 0 on it; the four parities each sum to 1 (affine)."""
    mask = refinement_mask(MIDEDGE)
    assert len(mask) == 16
    for parity in ((0, 0), (0, 1), (1, 0), (1, 1)):
        assert sum(w for (a, c), w in mask.items() if (a % 2, c % 2) == parity) == 1
    assert sorted(mask.values()).count(F(1, 2)) == 4


def test_the_centroid_rule_is_a_c0_quadratic_and_is_found_not_c1(zp):
    """All four corners at the face's centroid: a refinable piecewise quadratic here, but with a kink; ZP's has none."""
    assert zp.c1
    centroid = four_direction_patch((F(1, 4),) * 4)
    assert not centroid.c1
    assert all(sum(centroid.value(b, p) for b in OFFSETS) == 1 for p in POINTS)


def test_dependent_translates(zp):
    """The ZP box spline's translates are linearly dependent (its directions are not unimodular)."""
    assert zp.dependent_translates
    for p in POINTS:
        assert sum((1 - 2 * ((b[0] + b[1]) % 2)) * zp.value(b, p) for b in OFFSETS) == 0


@pytest.mark.parametrize("weights", [(F(9, 16), F(3, 16), F(1, 16), F(3, 16)), (F(5, 8), F(1, 8), F(1, 8), F(1, 8)),
                                     (F(1, 2), F(3, 16), F(1, 16), F(1, 4))])
def test_rules_without_a_quadratic_regular_part(weights):
    """Doo-Sabin's (biquadratic: total degree 4), a symmetric perturbation and a skewed one: no solution."""
    with pytest.raises(InvalidSchemeError, match=r"^corner rule \(.*\): its regular part is no continuous piecewise quadratic"):
        four_direction_patch(weights)


def test_a_rule_needs_four_weights():
    with pytest.raises(InvalidSchemeError, match="a quad face has 4 corners, got 3 weights"):
        four_direction_patch((F(1, 2), F(1, 4), F(1, 4)))


@pytest.mark.parametrize("weights, match", [((0.5, 0.25, 0, 0.25), "exact rationals: expected an exact rational number, got 0.5"),
                                            ("1/2", "a sequence of 4 rationals, got str"), (None, "got NoneType")])
def test_weights_that_are_not_exact_rationals_are_refused(weights, match):
    with pytest.raises(InvalidTypeError, match=f"^corner_weights must be .*{match}"):
        four_direction_patch(weights)


def test_sympy_rationals_are_the_same_rule():
    assert four_direction_patch([sp.Rational(1, 2), sp.Rational(1, 4), 0, sp.Rational(1, 4)]) == four_direction_patch(MIDEDGE)
