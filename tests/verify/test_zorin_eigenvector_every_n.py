"""The modified butterfly's frequency-1 eigenvector on Zorin's neighbourhood for every valence (issue 30, the map part).

The closed form is read once from the structural blocks on the depth-4 neighbourhood; it is checked against the
explicit matrix of the zoo's engine at several valences exactly (every row of ``S X = X / 2`` in ``Q(zeta_2n)``) and
against the per-valence route's eigenvector in Arb (proportional, to 30 digits); a tension variant changes it, and the
shipped closed form is then no eigenvector of the variant's matrix.
"""

from __future__ import annotations

from pathlib import Path

import flint
import pytest
import sympy as sp

import symdecomp.schemes as schemes
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.errors import NotApplicableError
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify.zoo_characteristic import characteristic_points, real_matrix, spectral_conditions
from symdecomp.verify.zorin_eigenvector_every_n import every_n_eigenvector, holds_at, remaining

BUTTERFLY_TEXT = (Path(schemes.__file__).parent / "zoo" / "modified-butterfly.toml").read_text()
BUTTERFLY = load_zoo("modified-butterfly")


def tension(w: sp.Rational) -> object:
    """The shipped butterfly with the regular rule's tension ``w`` (``1/16`` shipped): ``1/8 -> 2 w``, ``-1/16 -> -w``."""
    text = BUTTERFLY_TEXT.replace('weight = "1/8"', f'weight = "{2 * w}"').replace('weight = "-1/16"', f'weight = "{-w}"')
    return stencil_scheme_from_text(text.replace('"modified-butterfly"', '"tension"'))


@pytest.fixture(scope="module")
def ev():
    return every_n_eigenvector(BUTTERFLY)


def test_the_eigenvector_is_a_laurent_polynomial_vector_on_the_depth_four_neighbourhood(ev):
    assert (ev.depth, ev.first, ev.value) == (4, 16, sp.Rational(1, 2))
    assert len(ev.eigenvector) == 10 and ev.eigenvector[0] == 1
    # the block is triangular (an interpolatory scheme): det(lambda_1 I - B') is the product of lambda_1 - B_cc
    assert ev.scale == sp.prod([ev.value - ev.block[c, c] for c in range(1, 10)]) != 0
    # B_1(omega) x = x / 2 as an identity of Laurent polynomials in omega
    x = sp.Matrix(ev.eigenvector)
    assert all(sp.expand(e) == 0 for e in ev.block * x - ev.value * x)
    # the old vertices keep their places (a row with a single 1): there x_c = x_d / lambda_1, the net scaled by 2
    copies = [(c, d) for c in range(10) for d in range(10) if ev.block[c, d] == 1 and sum(ev.block.row(c)) == 1]
    assert len(copies) == 3
    assert all(sp.expand(ev.eigenvector[c] - 2 * ev.eigenvector[d]) == 0 for c, d in copies)


@pytest.mark.parametrize("n", [7, 9, pytest.param(17, marks=pytest.mark.slow)])
def test_the_closed_form_is_an_eigenvector_of_the_explicit_matrix_exactly(ev, n):
    assert holds_at(ev, BUTTERFLY, n)


def test_a_valence_whose_cosines_sympy_writes_as_radicals_is_refused_in_one_line(ev):
    with pytest.raises(NotApplicableError, match="n = 5: the matrix entry .* radicals"):
        holds_at(ev, BUTTERFLY, 5)


def test_the_closed_form_is_proportional_to_the_per_valence_eigenvector_to_30_digits(ev):
    n = 7
    zm = zoo_matrix(BUTTERFLY, n, ev.depth)
    spectral = spectral_conditions(zoo_spectrum(BUTTERFLY, n, None, jordan=False), n, real_matrix=real_matrix(zm))
    points = characteristic_points(zm, spectral.subdominant)
    assert spectral.subdominant.frequencies[0] == 1
    with flint.ctx.workprec(200):
        w = flint.acb(flint.fmpq(2, n)).exp_pi_i()
        nb = zm.neighbourhood
        closed = {}
        for v in nb.order:
            if v == nb.centre:
                continue
            s, c = nb.labels[v]
            poly = sp.Poly(sp.expand(ev.eigenvector[c] * OMEGA**(s + 8)), OMEGA)
            closed[v] = sum((flint.acb(flint.fmpq(int(a.p), int(a.q))) * w ** int(k[0]) for k, a in poly.terms()),
                            flint.acb(0)) * w**-8
        start = next(iter(closed))
        ratio = points[start] / closed[start]
        assert all(abs(points[v] - ratio * closed[v]) < flint.arb(10) ** -30 for v in closed)


def test_the_stretched_net_and_its_limit_are_the_chebyshev_sums(ev):
    # x_1 = -omega^2/6 + omega + 1 - 1/(6 omega): X = sum a_k T_|k|(t), Y = sum a_k sign(k) U_(|k|-1)(t)
    t = sp.Symbol("t")
    X, Y = ev.stretched(1)
    a = {2: sp.Rational(-1, 6), 1: 1, 0: 1, -1: sp.Rational(-1, 6)}
    def in_t(p: flint.fmpq_poly) -> sp.Expr:
        return sum((sp.Rational(int(c.p), int(c.q)) * t**j for j, c in enumerate(p.coeffs())), sp.Integer(0))

    assert sp.expand(in_t(X) - sum(c * sp.chebyshevt(abs(k), t) for k, c in a.items())) == 0
    assert sp.expand(in_t(Y) - sum(c * sp.sign(k) * (sp.chebyshevu(abs(k) - 1, t) if k else 0) for k, c in a.items())) == 0
    assert ev.limit(1) == (sum(a.values()), sum(k * c for k, c in a.items()))
    # the next sector's point is omega times this one: at t = 1 the stretched net turns by (X, Y) -> (X, X + Y)
    lx, ly = ev.limit(1)
    assert ev.limit(1, sector=1) == (lx, lx + ly)


def test_a_tension_variant_changes_the_eigenvector_and_the_shipped_one_fails_its_matrix(ev):
    other = tension(sp.Rational(1, 20))
    changed = every_n_eigenvector(other)
    assert changed.value == ev.value and changed.eigenvector != ev.eigenvector
    assert holds_at(changed, other, 7)
    assert not holds_at(ev, other, 7)


def test_what_remains_is_said(ev):
    text = remaining(ev)
    assert "derived for every n >= 16" in text and "not proved regular and injective for every n" in text
