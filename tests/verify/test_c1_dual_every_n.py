"""C1 for every valence of a dual scheme with the biquadratic regular part (issue 30: Doo-Sabin C1 at every n).

Each of Reif's spectral conditions is decided from the n-gon's weights for every n; every condition flips when the
weights change (variant files below), with the first valence where it fails computed; the n-gon's eigenvalues are
compared with the spectrum of the explicit matrix (the zoo's engine, :mod:`symdecomp.analysis.zoo_matrix`) in FLINT.
"""

from __future__ import annotations

import flint
import pytest
import sympy as sp

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.errors import InvalidInputError, InvalidTypeError, NotAffineError, NotApplicableError
from symdecomp.schemes.stencil_files import load_zoo, stencil_scheme_from_text
from symdecomp.schemes.stencils import N
from symdecomp.schemes.zoo_literature import FAMILIES
from symdecomp.verify.c1_dual_every_n import c1_dual_every_n, dual_spectral_every_n, ngon_spectrum
from symdecomp.verify.c1_dual_uniform import dual_uniform_map

DOO_SABIN = "KroneckerDelta(j, 0)/4 + (3 + 2*cos(2*pi*j/m))/(4*m)"


def variant(extra: str, name: str = "variant") -> str:
    """A Doo-Sabin file whose n-gon weights get ``extra`` (a multiple of ``m - 4``: the quads keep the B-spline's)."""
    return (f'name = "{name}"\nmesh = "quad"\ntopology = "dual"\n\n[[corner]]\n'
            f'terms = [{{walk = "", weight = "{DOO_SABIN} + {extra}", over = "face"}}]\n')


def scheme(extra: str):
    return stencil_scheme_from_text(variant(extra))


def spectrum(scheme, n: int) -> dict:
    """``{eigenvalue: multiplicity}`` of the engine's explicit matrix at ``n`` (3 or 6: rational entries), exactly in FLINT."""
    rows = zoo_matrix(scheme, n).matrix.tolist()
    exact = flint.fmpq_mat([[flint.fmpq(int(sp.Rational(e).p), int(sp.Rational(e).q)) for e in row] for row in rows])
    factors = exact.charpoly().factor()[1]
    assert all(f.degree() == 1 for f, _ in factors)  # every eigenvalue rational here
    return {sp.Rational(-f[0] / f[1]): k for f, k in factors}


def steps(s) -> dict:
    return {step.name: step for step in dual_spectral_every_n(s)}


def test_doo_sabin_spectral_conditions_are_proved_for_every_n():
    """lambda_1 = 1/2 (double), 1/4 at the other frequencies, sigma(0) = 1, the outer blocks 1/4, 1/8, 1/16."""
    sp_ = ngon_spectrum(load_zoo("doo-sabin"))
    assert (sp_.first, sp_.first_conjugate, sp_.zero) == (sp.Rational(1, 2), sp.Rational(1, 2), 1)
    assert sp_.others == (("every other k", sp.Rational(1, 4)),) and sp_.start == 3
    x = sp.Symbol("x")
    assert sp.Poly(sp_.outer, x).all_roots() == [sp.Rational(1, 16), sp.Rational(1, 8), sp.Rational(1, 4)]
    found = steps(load_zoo("doo-sabin"))
    assert [(k, s.status, s.valences) for k, s in found.items()] == [
        ("real-distinct", "proved", (3, None)), ("frequency-zero", "proved", (3, None)), ("dominant", "proved", (3, None)),
        ("bounds", "proved", (16, None))]
    # the literature's values (zoo_literature: the Fourier transform of Doo and Sabin's weights) are the derived ones
    facts = FAMILIES["doo-sabin"]
    assert facts.subdominant == sp_.first and facts.multiplicity == 2 and facts.rest_at_most == sp_.others[0][1]


@pytest.mark.parametrize("n", [3, 6])
def test_the_symbol_is_the_spectrum_of_the_explicit_matrix(n):
    """The engine's explicit matrix at n, in FLINT: its eigenvalues are 1, lambda_1 = sigma(1) twice, and the n-gon's
    other values and the outer roots, nothing else."""
    ds = load_zoo("doo-sabin")
    sp_, x = ngon_spectrum(ds), sp.Symbol("x")
    values = spectrum(ds, n)
    assert values[sp_.zero] == 1 and values[sp_.first] == 2
    assert set(values) == {sp_.zero, sp_.first, *(v for _, v in sp_.others), *sp.Poly(sp_.outer, x).all_roots()}


@pytest.mark.slow
def test_dominance_flips_at_a_computed_valence_and_the_matrix_agrees():
    """A frequency-2 weight: sigma(+-2) = 1/4 + (n - 4)/8 reaches lambda_1 = 1/2 at n = 6, computed; the matrix agrees."""
    s = scheme("(m - 4)*cos(4*pi*j/m)/(4*m)")
    sp_ = ngon_spectrum(s)
    others = dict(sp_.others)
    assert sorted(others) == ["every other k", "k = -2", "k = 2"] and sp_.start == 5
    assert all(sp.simplify(others[k] - (sp.Rational(1, 4) + (N - 4) / 8)) == 0 for k in ("k = -2", "k = 2"))
    dominant = steps(s)["dominant"]
    assert dominant.status == "failed" and dominant.valences == (6, None)
    assert dominant.text.endswith("it fails at n = 6 and at every n after it")
    # at n = 6 the explicit matrix has 1/2 four times (frequencies +-1 and +-2): lambda_1 is not strictly dominant
    assert spectrum(s, 6)[sp.Rational(1, 2)] == 4
    # the per-valence test agrees: it does not certify n = 6
    assert c1_dual_every_n(s, last=6).failure == 6


@pytest.mark.slow
@pytest.mark.parametrize("extra, name, status, text", [
    ("(m - 4)*sin(2*pi*j/m)/(8*m)", "real-distinct", "failed", "are not one real value"),
    ("(m - 4)*cos(2*pi*j/m)/(32*m)", "bounds", "failed", "it fails at n = 36 and at every n after it"),
])
def test_each_condition_flips_when_the_weights_change(extra, name, status, text):
    found = steps(scheme(extra))
    assert found[name].status == status and text in found[name].text
    # the conditions the change leaves alone stay proved; with lambda_1 not real the comparisons are not asked
    later = ("dominant", "bounds") if name == "real-distinct" else ()
    assert all(s.status == "proved" for k, s in found.items() if k not in (name, *later))
    assert all(found[k].status == "open" and found[k].text.endswith("lambda_1 is not real") for k in later)


def test_weights_that_do_not_sum_to_one_are_refused_at_the_door():
    """sigma(0) = 1 (frequency-zero) is the file's affinity: a variant that breaks it is one line when it is read."""
    with pytest.raises(NotAffineError) as info:
        scheme("(m - 4)/(16*m)")
    assert str(info.value) == "<scheme>: [[corner]] 1: not affine: the weights sum to (m + 12)/16, not 1"


def test_a_weight_with_no_symbol_stops_at_per_valence():
    """A weight that is no trigonometric polynomial in j has no closed-form symbol: the verdict rests on n = 3..last."""
    s = scheme("(m - 4)*(j*(m - j) - (m**2 - 1)/6)/m**4")  # sums to 0 over j: still affine
    with pytest.raises(NotApplicableError, match="not c"):
        ngon_spectrum(s)
    r = c1_dual_every_n(s, last=4)
    assert r.status == "verified" and r.steps[0].name == "spectral" and r.steps[0].status == "open"
    assert "spectral conditions are not proved for every n" in r.summary


@pytest.mark.slow
def test_doo_sabin_is_c1_at_every_n():
    """Peters and Reif's verdict, computed: the spectral conditions for every n (the bounds from n = 16), the dual test
    at n = 3..15, the characteristic map regular and injective for every n >= 16 by exact signs in t: proved."""
    r = c1_dual_every_n(load_zoo("doo-sabin"), last=15)
    assert r.status == "proved" and r.certified == (3, 15)
    assert [(s.name, s.status, s.valences) for s in r.steps][-4:] == [
        ("reif-per-valence", "verified", (3, 15)), ("map-scale", "proved", (16, None)),
        ("map-regular", "proved", (16, None)), ("map-injective", "proved", (16, None))]
    assert r.summary == ("C1 for every n >= 3: the spectral conditions proved for every n, the characteristic map regular "
                         "and injective for every n >= 16 (exact signs in t = cos(2 pi/n)), Reif's test certified at n = 3..15")
    assert r.uniform is not None and r.uniform.coefficients == 108 + 8


@pytest.mark.slow
def test_the_map_stays_open_where_the_valences_stop_short_or_lambda_depends_on_n():
    r = c1_dual_every_n(load_zoo("doo-sabin"), last=5)
    assert r.status == "verified" and r.steps[-1].name == "map-open"  # the bounds hold from n = 16: not asked
    s = scheme("(m - 4)*cos(2*pi*j/m)/(4*m**2)")  # lambda_1 = 1/2 + (n - 4)/(8 n): every spectral condition holds
    assert all(step.status == "proved" for step in dual_spectral_every_n(s))
    result = dual_uniform_map(s, ngon_spectrum(s).first, 16)
    assert result.status == "open" and result.facts[0].startswith("lambda_1 = ") and "is not a rational constant" in result.facts[0]


def test_bad_arguments_are_one_line_errors():
    with pytest.raises(InvalidTypeError, match="scheme"):
        c1_dual_every_n("doo-sabin")
    with pytest.raises(InvalidInputError, match="last"):
        c1_dual_every_n(load_zoo("doo-sabin"), last=2)


def test_a_scheme_whose_regular_part_is_not_biquadratic_is_refused():
    with pytest.raises(NotApplicableError, match="not the biquadratic B-spline's"):
        ngon_spectrum(load_zoo("midedge"))


@pytest.mark.slow
def test_the_dual_test_certifies_doo_sabin_where_the_exact_form_of_one_half_is_long():
    """At n = 15 the engine's exact form of lambda_1 = 1/2 is a long sum of roots of unity whose imaginary part sympy
    does not reduce to 0; the matrix is real and lambda_1 strictly dominant, so its conjugate is itself: real (it was
    refuted as 'not a real double eigenvalue' before, against the symbol's proof for every n)."""
    from symdecomp.verify.c1_zoo import c1_zoo
    from symdecomp.verify.zoo_characteristic import engine_neighbourhood

    r = c1_zoo(load_zoo("doo-sabin"), 15, neighbourhood=engine_neighbourhood)
    assert r.verdict == "c1" and r.frequency == 1 and r.winding_number == 1
    assert r.spectral is not None and r.spectral.subdominant is not None
    assert r.spectral.subdominant.value.contains(flint.acb(flint.fmpq(1, 2)))


@pytest.mark.slow
def test_the_map_argument_fails_where_lambda_is_below_the_outer_eigenvalues():
    """The same nets solved with lambda = 1/5 < 1/4 (an outer eigenvalue): the Jacobian's first Bezier coefficient is
    not positive (its value at the limit t = 1 is negative), so the map is open; with 1/2 every sign holds."""
    from symdecomp.verify.bezier import jacobian_net
    from symdecomp.verify.c1_dual import biquadratic_to_bicubic
    from symdecomp.verify.c1_dual_uniform import dual_ring

    ds = load_zoo("doo-sabin")
    low = dual_uniform_map(ds, sp.Rational(1, 5), 16)
    assert low.status == "open" and low.facts[0].startswith("Bezier coefficient 0 of the Jacobian is not shown positive")
    X, Y, _ = dual_ring(ds, sp.Rational(1, 5), 16).patches[0]
    assert jacobian_net(biquadratic_to_bicubic(X), biquadratic_to_bicubic(Y))[0][0](1) < 0
    assert dual_uniform_map(ds, sp.Rational(1, 2), 16).status == "proved"


@pytest.mark.slow
def test_the_eigenvector_for_every_n_is_the_engines_at_a_valence():
    """At n = 20 the engine's characteristic points (its eigenvector, solved numerically per valence) are one complex
    multiple of x_c(omega) omega^s, the eigenvector solved once in omega, at every labelled vertex."""
    import cmath
    import math

    from symdecomp.symbols import omega
    from symdecomp.verify.c1_dual_uniform import dual_ring
    from symdecomp.verify.zoo_characteristic import engine_neighbourhood

    ds, n = load_zoo("doo-sabin"), 20
    x = dual_ring(ds, sp.Rational(1, 2), 16).eigenvector
    nb = engine_neighbourhood(ds, n)
    w = cmath.exp(2j * math.pi / n)
    ours = {v: complex(sp.N(x[c].subs(omega, w) * w**s)) for v, (s, c) in nb.mesh.labels.items() if v in nb.points}
    theirs = {v: complex(float(z.real.mid()), float(z.imag.mid())) for v, z in nb.points.items()}
    corner = next(v for v, (s, c) in nb.mesh.labels.items() if (s, c) == (0, 0))
    scale = theirs[corner] / ours[corner]
    assert len(ours) > 8 * n and max(abs(theirs[v] - scale * ours[v]) for v in ours) < 1e-12
