"""Biermann-Levin-Zorin's near-edge rules as schemes, for the sector C1 tests."""

import dataclasses

import sympy as sp

from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.schemes.sharp import SharpRules
from symdecomp.symbols import theta_k


def blz(lattice: str):
    """BLZ's rules: on a smooth edge at a sharp vertex, ``1/2 - cos(theta_k)/4`` (Loop) or ``3/8 - cos(theta_k)/4``
    (Catmull-Clark) on the edge's other end, the rest of the ends' weight on the sharp vertex."""
    base, end = (catmull_clark(), sp.Rational(3, 8)) if lattice == "quad" else (loop(), sp.Rational(1, 2))
    near_end = end - sp.cos(theta_k) / 4
    rules = SharpRules(sp.Rational(3, 4), sp.Rational(1, 8), sp.Rational(1, 2), sp.Rational(3, 4) - near_end, near_end)
    return dataclasses.replace(base, sharp=rules, name=f"{base.name}-blz")
