"""The modified butterfly's spectral conditions for every valence (issue 30): derived from its structural blocks.

The characteristic polynomials ``p_k(x)`` read once from the scheme are compared with the explicit matrix of the zoo's
engine at ``n = 5..12`` (the product of the ``p_k`` at ``t = cos(2 pi k/n)`` over every ``k`` is its characteristic
polynomial, in Arb); the Schur-Cohn polynomials are counted by Sturm sequences; changing the tension or the centre
weights in a variant file flips a step, with the valence where it fails computed and checked on the explicit matrix.
"""

from __future__ import annotations

from pathlib import Path

import flint
import mpmath
import pytest
import sympy as sp

import symdecomp.schemes as schemes
from symdecomp.algebra.interval_signs import count_roots
from symdecomp.algebra.numbers import to_fmpq
from symdecomp.algebra.schur_cohn import schur_cohn_conditions
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.errors import InvalidInputError
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text
from symdecomp.verify.c1_every_n import EveryNStep, T
from symdecomp.verify.c1_zoo import ZooC1Result
from symdecomp.verify.c1_zorin_every_n import X, c1_zorin_every_n, frequency_polynomials, zorin_lambda_one, zorin_spectral_every_n
from symdecomp.verify.result import C1Verdict

BUTTERFLY = (Path(schemes.__file__).parent / "zoo" / "modified-butterfly.toml").read_text()
DIGITS = 40


def stub(verdict: C1Verdict, reason: str):
    """A per-valence test standing in for Zorin's: the same verdict at every valence, as the result type it returns."""
    return lambda n: ZooC1Result(n, "stub", verdict, reason)


def variant(old: str, new: str, name: str) -> object:
    """The shipped file with ``old`` replaced by ``new`` (each must occur)."""
    assert old in BUTTERFLY
    return stencil_scheme_from_text(BUTTERFLY.replace(old, new).replace('"modified-butterfly"', f'"{name}"'))


def _arb(e: sp.Expr) -> flint.arb:
    return flint.arb(str(sp.N(e, DIGITS + 20)), flint.arb(10) ** -(DIGITS + 15))


def _product_at(polys, n: int) -> flint.acb_poly:
    """``prod_k p_k(x)`` at ``t = cos(2 pi k/n)`` (the exceptional ``k`` at ``cos(2 pi/n)``), in Arb."""
    total = flint.acb_poly([1])
    for k in range(n):
        signed = k if k <= n // 2 else k - n
        p, angle = (polys.at[signed], 1) if signed in polys.at else (polys.other, k)
        t = sp.cos(2 * sp.pi * angle / n)
        coefficients = [_arb(c.subs(T, t)) for c in reversed(sp.Poly(p, X).all_coeffs())]
        total *= flint.acb_poly(coefficients)
    return total


@pytest.mark.parametrize("n", [5, 7, *(pytest.param(n, marks=pytest.mark.slow) for n in range(8, 13))])
def test_the_derived_polynomials_multiply_to_the_explicit_matrix_characteristic_polynomial(n):
    if n == 6:
        pytest.skip("n = 6 is the regular vertex: the centre rule is the regular one")
    polys = frequency_polynomials(load_zoo("modified-butterfly"))
    with flint.ctx.workprec(4 * DIGITS):
        A = flint.acb_mat([[_arb(e) for e in row] for row in zoo_matrix(load_zoo("modified-butterfly"), n).matrix.tolist()])
        explicit = A.charpoly()
        derived = _product_at(polys, n)
        assert explicit.degree() == derived.degree()
        for a, b in zip(explicit.coeffs(), derived.coeffs()):
            assert abs(a - b) < flint.arb(10) ** -DIGITS


def test_the_butterfly_blocks_are_triangular_so_no_coefficient_depends_on_t():
    polys = frequency_polynomials(load_zoo("modified-butterfly"))
    assert sp.expand(polys.other - X**2 * (X - sp.Rational(1, 8))) == 0
    assert sp.expand(polys.at[1] - X * (X - sp.Rational(1, 2)) * (X - sp.Rational(1, 8))) == 0
    assert sp.expand(polys.at[0] - (X - 1) * X * (X - sp.Rational(1, 4)) * (X - sp.Rational(1, 8))) == 0
    assert polys.start == 16 and zorin_lambda_one(load_zoo("modified-butterfly")) == sp.Rational(1, 2)


def test_every_spectral_step_is_proved_and_the_schur_cohn_polynomials_have_no_root_in_range():
    steps = zorin_spectral_every_n(load_zoo("modified-butterfly"), per_valence=False)
    assert {s.name for s in steps} == {"lambda-one", "frequency-zero", "frequency-one", "frequency-exceptional",
                                       "other-frequencies"}
    assert all(s.status == "proved" and s.valences == (16, None) for s in steps)
    for step in steps:
        for _, delta in (f for f in step.formulas if f[0].startswith(r"\delta")):
            poly = flint.fmpq_poly([to_fmpq(c) for c in reversed(sp.Poly(delta, T).all_coeffs())])
            assert count_roots(poly, -1, 1) == 0 and delta.subs(T, 0) > 0


def test_schur_cohn_against_the_roots():
    # (x - t/2)(x + 1/4): inside the unit disc exactly for |t| < 2; delta_2 = 1 - (t/8)^2 changes sign at t = +-8 ...
    deltas = schur_cohn_conditions(sp.Poly((X - T / 2) * (X + sp.Rational(1, 4)), X))
    assert [sp.factor(d) for d in deltas][0] == sp.factor(1 - T**2 / 64)
    # ... and the last condition vanishes where a root reaches the circle: t = 2 (the root 1) and t = -2
    assert sp.expand(deltas[-1].subs(T, 2)) == 0 and sp.expand(deltas[-1].subs(T, -2)) == 0
    assert all(sp.expand(d.subs(T, 1)) > 0 for d in deltas)
    with pytest.raises(InvalidInputError, match="radius"):
        schur_cohn_conditions(sp.Poly(X, X), -1)


@pytest.mark.slow
def test_a_tension_above_one_quarter_refutes_the_other_frequencies_with_a_computed_valence():
    w = sp.Rational(3, 10)
    text = BUTTERFLY.replace('weight = "1/8"', f'weight = "{2 * w}"').replace('weight = "-1/16"', f'weight = "{-w}"')
    scheme = stencil_scheme_from_text(text.replace('"modified-butterfly"', '"tense"'))
    steps = {s.name: s for s in zorin_spectral_every_n(scheme, per_valence=False)}
    other = steps["other-frequencies"]
    assert other.status == "failed" and other.valences == (16, 16)
    assert "n = 16, k = 3" in other.text and "0 for every t" in other.text
    # it stays failed because the per-valence route refutes at that valence: 3/5 is not one pair's double eigenvalue
    assert "at n = 16 the per-valence route refutes C1" in other.text and "not a real double eigenvalue" in other.text
    # the explicit matrix at n = 16 has the eigenvalue 2w = 3/5 (the lambda_1 derived) more than twice
    lam = next(v for k, v in steps["lambda-one"].formulas if k == r"\lambda_1")
    assert lam == 2 * w
    assert _eigenvalues_near(zoo_matrix(scheme, 16).matrix, lam) >= 3


def _eigenvalues_near(matrix: sp.Matrix, value: sp.Expr, digits: int = 40) -> int:
    """How many eigenvalues of ``matrix`` (mpmath at ``digits`` digits) lie within ``10^(-digits/4)`` of ``value``: a
    root of multiplicity ``m`` moves by about ``eps^(1/m)`` under rounding, far inside that radius for ``m <= 3``; sympy's
    exact characteristic polynomial of the 49 x 49 matrix with cosines in it takes minutes."""
    with mpmath.workdps(digits):
        A = mpmath.matrix([[mpmath.mpf(str(sp.N(e, digits + 10))) for e in row] for row in matrix.tolist()])
        eigenvalues = mpmath.eig(A, left=False, right=False)
        target = mpmath.mpf(str(sp.N(value, digits + 10)))
        return sum(1 for z in eigenvalues if abs(z - target) < mpmath.mpf(10) ** (-digits // 4))


@pytest.mark.slow
def test_a_centre_weight_at_frequency_two_above_lambda_one_is_refuted_at_the_first_valence_of_the_form():
    scheme = variant("cos(4*pi*j/n)/2", "3*cos(4*pi*j/n)/2", "twisted")
    steps = {s.name: s for s in zorin_spectral_every_n(scheme, per_valence=False)}
    assert steps["other-frequencies"].status == "proved"
    assert steps["frequency-exceptional"].status == "failed" and steps["frequency-exceptional"].valences == (16, 16)
    # the per-valence route refutes there: the subdominant pair is of the frequencies 2, 14, so the map winds twice
    assert "of the frequencies 2, 14, not 1, n - 1" in steps["frequency-exceptional"].text
    certified = stub(C1Verdict.C1, "certified by the stub of this test")
    result = c1_zorin_every_n(scheme, 4, certify=certified, per_valence=False)
    assert result.status == "refuted" and result.failure == 16 and result.summary.startswith("C1 fails at n = 16")
    # a valence below where Zorin's test is undecided does not hide the counterexample at n = 16
    open_at_3 = stub(C1Verdict.UNDECIDED, "undecided by the stub of this test")
    assert c1_zorin_every_n(scheme, 4, certify=open_at_3, per_valence=False).failure == 16
    # sigma(2) = 3/4 is an eigenvalue of the explicit matrix at that valence: its characteristic polynomial vanishes there
    assert _eigenvalues_near(zoo_matrix(scheme, 16).matrix, sp.Rational(3, 4)) >= 1


def _reaching() -> object:
    """The butterfly with the extraordinary edge rule also reading the vertex two rings out along its spoke (weight 1/16,
    taken from the centre's 3/4): the frequency-1 block gains ``x^2 - sigma(1) x - 1/16`` besides the tension's
    linear factor."""
    rule = 'origin = "irregular"\nterms = [\n  {walk = "", weight = "3/4"},'
    return variant(rule, rule.replace('"3/4"', '"11/16"') + '\n  {walk = "next twin next twin next next", weight = "1/16"},',
                   "reaching")


def _tense_reaching(w: sp.Rational) -> object:
    """:func:`_reaching` with the tension ``w`` (edge weights ``2 w`` and ``-w``): ``p_1`` gains ``x - 2 w`` at every
    frequency, which holds the largest root of ``p_1`` once ``2 w > (1 + sqrt 2)/4``."""
    rule = 'origin = "irregular"\nterms = [\n  {walk = "", weight = "3/4"},'
    text = BUTTERFLY.replace(rule, rule.replace('"3/4"', '"11/16"')
                             + '\n  {walk = "next twin next twin next next", weight = "1/16"},')
    text = text.replace('weight = "1/8"', f'weight = "{2 * w}"').replace('weight = "-1/16"', f'weight = "{-w}"')
    return stencil_scheme_from_text(text.replace('"modified-butterfly"', '"tense-reaching"'))


@pytest.mark.slow
def test_lambda_one_is_the_largest_root_of_p1_where_a_quadratic_factor_holds_it_and_the_spectral_part_is_proved():
    scheme = _reaching()
    polys = frequency_polynomials(scheme)
    steps = zorin_spectral_every_n(scheme, per_valence=False, polys=polys)
    lam = dict(steps[0].formulas)[r"\lambda_1"]
    roots = sp.Poly(polys.at[1], X).real_roots()
    # lambda_1 is the largest root of p_1, not the linear factor's 1/8: an irrational root of a quadratic factor
    assert steps[0].name == "lambda-one" and sp.expand(lam - max(roots)) == 0 and not lam.is_Rational
    assert sp.minimal_polynomial(lam, X) == 16 * X**2 - 8 * X - 1
    assert all(s.status == "proved" for s in steps), [s.text for s in steps if s.status != "proved"]
    # each step's roots against lambda_1 at one valence, in Arb: the largest modulus besides lambda_1 is below it
    with flint.ctx.workprec(4 * DIGITS):
        p1 = flint.acb_poly([_arb(c) for c in reversed(sp.Poly(polys.at[1], X).all_coeffs())])
        moduli = sorted((abs(r) for r in p1.roots()), key=lambda b: b.mid())
        assert moduli[-1].overlaps(_arb(lam)) and moduli[-2] < _arb(lam)
    certified = stub(C1Verdict.C1, "certified by the stub of this test")
    result = c1_zorin_every_n(scheme, 4, certify=certified, per_valence=False, polys=polys)
    assert result.status == "undecided" and result.failure is None
    assert result.summary.startswith("the spectral conditions hold for every n")


@pytest.mark.slow
@pytest.mark.parametrize("n", [16, 20])
def test_the_per_valence_route_finds_the_algebraic_lambda_one_as_the_double_subdominant_eigenvalue(n):
    """The explicit matrix at ``n`` (exact factors of each block, certified gap): its subdominant eigenvalue is the
    every-n proof's ``lambda_1 = (1 + sqrt 2)/4``, double, of the frequencies ``1, n - 1``."""
    from symdecomp.verify.c1_zorin_every_n import _spectral_at
    from symdecomp.verify.result import C1Verdict

    scheme = _reaching()
    lam = zorin_lambda_one(scheme)
    r = _spectral_at(scheme, n)
    assert r.status is C1Verdict.C1 and r.subdominant.multiplicity == 2 and set(r.subdominant.frequencies) == {1, n - 1}
    with flint.ctx.workprec(4 * DIGITS):
        assert flint.acb(r.subdominant.value).overlaps(flint.acb(_arb(lam)))
        assert abs(flint.acb(r.subdominant.value).mid() - flint.acb(_arb(lam)).mid()) < flint.arb(10) ** -12


@pytest.mark.slow
def test_a_tension_that_moves_the_largest_root_of_p1_to_the_linear_factor_changes_lambda_one_and_refutes():
    """Tension ``3/10``: ``3/5 < (1 + sqrt 2)/4``, the quadratic factor holds ``lambda_1`` and every step is proved;
    tension ``8/25``: ``16/25`` is larger, the linear factor holds it, and it is a root at every frequency: refuted."""
    below, above = _tense_reaching(sp.Rational(3, 10)), _tense_reaching(sp.Rational(8, 25))
    lam_below, lam_above = zorin_lambda_one(below), zorin_lambda_one(above)
    assert sp.minimal_polynomial(lam_below, X) == 16 * X**2 - 8 * X - 1 and lam_above == sp.Rational(16, 25)
    assert all(s.status == "proved" for s in zorin_spectral_every_n(below, per_valence=False))
    steps = {s.name: s for s in zorin_spectral_every_n(above, per_valence=False)}
    other = steps["other-frequencies"]
    assert other.status == "failed" and other.valences == (16, 16) and "at n = 16 the per-valence route refutes C1" in other.text
    certified = stub(C1Verdict.C1, "certified by the stub of this test")
    assert c1_zorin_every_n(below, 4, certify=certified, per_valence=False).status == "undecided"
    assert c1_zorin_every_n(above, 4, certify=certified, per_valence=False).failure == 16
    # 16/25 is an eigenvalue of the explicit matrix at n = 16 more than twice
    assert _eigenvalues_near(zoo_matrix(above, 16).matrix, lam_above) >= 3


@pytest.mark.slow
def test_a_root_of_p1_above_a_linear_factors_root_is_no_refutation_where_the_per_valence_route_holds():
    """The step run with the linear factor's root ``1/8`` as the radius (the old choice) fails at ``n = 16``; the
    per-valence route there finds the spectral conditions holding, so the step is ``open``, never a refutation."""
    from symdecomp.verify.c1_uniform import t_lower_bound
    from symdecomp.verify.c1_zorin_every_n import _against_per_valence, _disc_step
    from symdecomp.verify.zorin_lambda_in_t import linear_roots

    scheme = _reaching()
    polys = frequency_polynomials(scheme)
    (linear,) = linear_roots(polys.at[1])
    step = _disc_step("frequency-one", "k = 1", polys.at[1], linear, t_lower_bound(16), 1, 16, 2, divide=True)
    assert linear == sp.Rational(1, 8) and step.status == "failed" and step.valences == (16, 16)
    one = _against_per_valence(scheme, step, {})
    assert one.status == "open" and one.valences == (16, 16) and "not that C1 fails" in one.text
    # the explicit matrix at n = 16: the largest root of p_1 is a double eigenvalue, and no eigenvalue besides 1 is larger
    top = max(sp.Poly(polys.at[1], X).real_roots())
    assert _eigenvalues_near(zoo_matrix(scheme, 16).matrix, top) == 2
    with mpmath.workdps(DIGITS):
        A = mpmath.matrix([[mpmath.mpf(str(sp.N(e, DIGITS + 10))) for e in row] for row in zoo_matrix(scheme, 16).matrix.tolist()])
        moduli = sorted((abs(z) for z in mpmath.eig(A, left=False, right=False)), reverse=True)
        assert abs(moduli[0] - 1) < mpmath.mpf(10) ** -30
        assert abs(moduli[1] - mpmath.mpf(str(sp.N(top, DIGITS + 10)))) < mpmath.mpf(10) ** -30
    # the proof run with the old choice (the linear factor's 1/8) leaves the step open at n = 16, never refuted; a
    # per-valence test that refutes at that witness valence (beyond the certified ones) is what refutes, cited with n
    import symdecomp.verify.c1_zorin_every_n as every_n

    def linear_choice(polys_):
        return linear, EveryNStep(f"lambda_1 = {linear}", "proved", (16, None), "lambda-one", ())

    certified = stub(C1Verdict.C1, "certified by the stub of this test")
    refuting = stub(C1Verdict.NOT_C1, "refuted by the stub of this test")
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(every_n, "_lambda_one", linear_choice)
        result = c1_zorin_every_n(scheme, 4, certify=certified, per_valence=False, polys=polys)
        assert result.status == "undecided" and result.failure is None
        cited = c1_zorin_every_n(scheme, 4, certify=lambda n: refuting(n) if n == 16 else certified(n), per_valence=False,
                                 polys=polys)
    assert cited.status == "refuted" and cited.failure == 16 and "refuted by the stub of this test" in cited.summary


@pytest.mark.slow
def test_below_the_structural_form_each_valence_but_the_regular_one_is_certified():
    below = zorin_spectral_every_n(load_zoo("modified-butterfly"))[-1]
    assert below.name == "below-structural" and below.status == "verified" and below.valences == (3, 15)


def test_the_every_n_verdict_is_undecided_because_the_map_is_certified_per_valence_only():
    certified = stub(C1Verdict.C1, "certified by the stub of this test")
    result = c1_zorin_every_n(load_zoo("modified-butterfly"), 4, certify=certified, per_valence=False)
    assert result.status == "undecided"
    assert "not proved for every n" in result.summary
    names = [s.name for s in result.steps]
    assert "map-open" in names and names.index("other-frequencies") < names.index("map-open")
    # the open map step says what of the map part is derived for every n (the eigenvector) and what remains
    map_open = next(s for s in result.steps if s.name == "map-open")
    assert "the frequency-1 eigenvector on the depth-4 neighbourhood is derived for every n >= 16" in map_open.text
    assert "difference bounds are not yet exact signs in t" in map_open.text
    per_valence = next(s for s in result.steps if s.name == "reif-per-valence")
    assert per_valence.valences == (3, 4) and per_valence.text.startswith("Zorin's test at each valence: ")
