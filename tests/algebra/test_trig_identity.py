"""Identities in sines and cosines decided as exponential polynomials: an identity is 0, and what is not one keeps
simplify's form (never 0)."""

import sympy as sp

from symdecomp.algebra.trig_identity import reduced, vanishes_as_exponentials

x, i = sp.symbols("theta i")


def test_addition_theorems_and_the_mirror_residual_vanish():
    assert vanishes_as_exponentials(sp.sin(i * x + x) - sp.sin(i * x) * sp.cos(x) - sp.cos(i * x) * sp.sin(x))
    assert vanishes_as_exponentials(sp.cos(2 * x) - 2 * sp.cos(x) ** 2 + 1)
    # Catmull-Clark's b-row of the sine block (analysis.mirror): (sin(t(i+1)) + sin(t i)) / 4 - cos(t/2) sin(t(i+1/2)) / 2
    half = sp.Rational(1, 2)
    assert reduced((sp.sin(x * (i + 1)) + sp.sin(x * i)) / 4 - sp.cos(x / 2) * sp.sin(x * (i + half)) / 2) == 0


def test_what_is_not_an_identity_keeps_simplifys_form():
    off = (sp.sin(i * x + x) - sp.sin(i * x)) / 16
    assert not vanishes_as_exponentials(off)
    assert reduced(off) == sp.simplify(off) != 0
    # vanishes only at theta = pi j/k (sin(k theta) at theta = pi j/k): not an identity in theta, kept
    k, j = sp.symbols("k j", integer=True, positive=True)
    assert reduced(sp.sin(x * k)) == sp.sin(x * k)
    assert reduced(sp.sin(k * x).subs(x, sp.pi * j / k)) == 0  # simplify decides it, as before
