"""The second-order height fields are eigenvectors of the exact 2-ring subdivision matrix (built by refinement, not by frequency)."""

from __future__ import annotations

import cmath

import flint
import pytest
import sympy as sp

import symdecomp as sd
from symdecomp.analysis.second_order import height_eigenvector
from symdecomp.errors import InvalidSchemeError
from symdecomp.verify.shape import height_fields

CC, LOOP = sd.catmull_clark(), sd.loop()


def _full_vector(vec, labels):
    """The level-1 values on the full 2-ring (sector ``s``: ``omega^(j s)`` times sector 0's class), the centre 0."""
    out = []
    for s, u, v in labels:
        if (u, v) == (0, 0):
            out.append(0)
            continue
        z = vec.values[(u, v)]
        out.append(complex(float(z.real.mid()), float(z.imag.mid())) * cmath.exp(2j * cmath.pi * vec.j * s / vec.n))
    return out


@pytest.mark.parametrize("scheme, n, j", [(CC, 5, 0), (CC, 5, 2), (CC, 3, 2), (LOOP, 7, 0), (LOOP, 7, 2), (CC, 8, 0)])
def test_height_field_is_an_eigenvector_of_the_exact_ring_matrix_up_to_a_constant(scheme, n, j):
    fields = height_fields(scheme, n)
    mu = (fields.elliptic if j == 0 else fields.hyperbolic).value
    vec = height_eigenvector(scheme, n, j, flint.acb(mu))
    ring = sd.ring_subdivision_matrix(scheme, n, 2)
    S = ring.exact_matrix()
    S = [[complex(sp.N(S[r, c], 30)) for c in range(ring.size)] for r in range(ring.size)]
    x = _full_vector(vec, ring.labels)
    m = float(mu.mid())
    residual = [sum(S[r][c] * x[c] for c in range(ring.size)) - m * x[r] for r in range(ring.size)]
    # level 1 less its centre: S x = mu x + (mu - 1) v_O' 1 (a constant, 0 for j != 0)
    constant = residual[0]
    assert max(abs(z - constant) for z in residual) < 1e-12
    if j != 0:
        assert abs(constant) < 1e-12
    else:
        assert abs(constant) > 1e-3  # the centre moves: the shift is real
    assert abs(x[ring.labels.index((0, 1, 0))] - 1) < 1e-12  # normalised at a_0


def test_frequency_zero_refuses_an_eigenvalue_of_the_outer_block():
    """Loop at n = 3: mu_0 = 1/16 is also the regular part's outer eigenvalue 1/16 at frequency 0."""
    with pytest.raises(InvalidSchemeError, match="not determined by the 1-ring"):
        height_eigenvector(LOOP, 3, 0, flint.acb(flint.fmpq(1, 16)))
