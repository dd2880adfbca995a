"""Certified shape of central surfaces (symdecomp.verify.shape): verdicts that must hold, and change where they must."""

from __future__ import annotations

from fractions import Fraction

import pytest

import symdecomp as sd
from symdecomp.errors import InvalidInputError, NotApplicableError
from symdecomp.verify.shape import classify_shape, shape_chart

CC, LOOP = sd.catmull_clark(), sd.loop()


@pytest.mark.parametrize("scheme, n", [(CC, 4), (LOOP, 6)])
def test_the_regular_elliptic_height_is_a_paraboloid(scheme, n):
    r = classify_shape(scheme, n)
    assert (r.kind, r.frequencies, r.depth) == ("elliptic", (0,), 0)
    assert r.mu[0] == pytest.approx(0.25, abs=1e-15) and r.subdominant == pytest.approx(0.5, abs=1e-15)


def test_the_regular_chart_changes_from_elliptic_to_hyperbolic_at_equal_amplitudes():
    """Loop at n = 6 is the quartic box spline: h = (1 - r)(x^2 + y^2) + r Re(e^(-it) z^2) has K > 0 iff r < 1/2, for every t.

    At r = 1/2 the height is a parabolic cylinder (K = 0 everywhere), which no subdivision decides.
    """
    chart = shape_chart(LOOP, 6, ratios=[Fraction(7, 16), Fraction(1, 2), Fraction(9, 16)], angles=[0, Fraction(1, 5)])
    assert chart.kinds == (("elliptic",) * 2, ("undecided",) * 2, ("hyperbolic",) * 2)
    assert "no subdivision depth decides" in chart.results[1][0].reason
    assert chart.dominant is None  # mu_0 = mu_2 = 1/4: not separated, as they are equal


def test_loop_elliptic_input_turns_hybrid_between_valence_24_and_25():
    before, after = classify_shape(LOOP, 24), classify_shape(LOOP, 25)
    assert before.kind == "elliptic" and before.lower_bound > 0
    assert after.kind == "hybrid"
    assert after.positive_at.startswith("sector 0") and after.negative_at.startswith("sector 0")


def test_catmull_clark_pure_inputs_keep_their_shape_but_the_mixture_does_not():
    """At n = 5 mu_2 > mu_0: both pure inputs keep their shape, and between them lies a hybrid band."""
    assert classify_shape(CC, 5).kind == "elliptic"
    assert classify_shape(CC, 5, elliptic=0, hyperbolic=1, angle="1/7").kind == "hyperbolic"
    mixed = classify_shape(CC, 5, elliptic=Fraction(1, 2), hyperbolic=Fraction(1, 2))
    assert mixed.kind == "hybrid" and mixed.dominant == 2 and mixed.mu[0] < mixed.mu[1]


def test_what_is_not_determined_says_why():
    with pytest.raises(NotApplicableError, match="n = 4 frequency 2 is n/2"):
        classify_shape(CC, 4, hyperbolic=1)
    with pytest.raises(NotApplicableError, match="holds only lambda"):
        classify_shape(LOOP, 3, elliptic=0, hyperbolic=1)
    r = classify_shape(LOOP, 3)  # mu_0 = 1/16 is also an outer eigenvalue of the regular part at frequency 0
    assert r.kind == "undecided" and "not determined by the 1-ring" in r.reason


@pytest.mark.parametrize("keywords, message", [
    (dict(elliptic=0.5), "elliptic must be an exact rational"),
    (dict(hyperbolic="x"), "hyperbolic must be an exact rational"),
    (dict(angle=True), "angle must be an exact rational"),
    (dict(elliptic=0, hyperbolic=0), "both 0"),
])
def test_bad_amplitudes_are_refused_in_one_line(keywords, message):
    with pytest.raises(InvalidInputError, match=message):
        classify_shape(CC, 5, **keywords)
