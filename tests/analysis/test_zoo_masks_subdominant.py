"""Masks at large valences read the subdominant eigenvalue from the frequency-1 block alone.

``zoo_masks`` needs one eigenvalue, the largest in modulus at frequency 1; beyond n = 19 it takes it from the
certified eigenvalues of that K x K block instead of the whole spectrum (every block factored). These tests hold the
shortcut to the whole spectrum's answer, and the masks it gives to the full matrix's left eigenvectors.
"""

from __future__ import annotations

import flint
import numpy as np
import pytest

from symdecomp.analysis.masks import acb_matrix
from symdecomp.analysis.spectrum import acb_text
from symdecomp.analysis.zoo_blocks import zoo_blocks
from symdecomp.analysis.zoo_masks import _isolated_largest, zoo_masks
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import spectrum_of_blocks
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencils import N
from symdecomp.schemes.zoo_literature import FAMILIES
from symdecomp.symbols import omega as OMEGA


@pytest.mark.parametrize("name", ["doo-sabin", "sqrt3"])
def test_the_frequency_1_block_s_largest_is_the_whole_spectrum_s(name):
    n = 20
    scheme = load_zoo(name)
    zm = zoo_matrix(scheme, n)
    blocks = zoo_blocks(zm)
    spectrum = spectrum_of_blocks(blocks, digits=20, exact=False, depth=zm.depth, mesh=scheme.lattice)
    whole = max((e for e in spectrum.eigenvalues if 1 in e.frequencies), key=lambda e: float(e.value.abs_upper())).value
    with flint.ctx.workprec(144):
        w = flint.acb(flint.arb(flint.fmpq(2, n))).exp_pi_i()
        ours = _isolated_largest(acb_matrix(blocks.frequency_matrix(), (OMEGA,), (w,)))
    assert ours is not None and ours.overlaps(whole)
    assert acb_text(ours, 20) == acb_text(whole, 20)


def test_a_modulus_shared_at_frequency_1_is_left_to_the_whole_spectrum():
    # a rotation by a quarter turn: eigenvalues i and -i, one modulus; the shortcut does not choose between them
    with flint.ctx.workprec(144):
        assert _isolated_largest(flint.acb_mat([[0, -1], [1, 0]])) is None
        assert _isolated_largest(flint.acb_mat([[2, 0], [0, 1]])).overlaps(flint.acb(2))


def test_masks_at_a_large_valence_are_left_eigenvectors_of_the_full_matrix():
    n = 24
    scheme = load_zoo("doo-sabin")
    zm = zoo_matrix(scheme, n)
    masks = zoo_masks(scheme, n, digits=25)
    nb = zm.neighbourhood
    S = np.array([[float(x) for x in zm.matrix.row(i)] for i in range(zm.matrix.shape[0])])

    def vector(mask):
        return np.array([float(mask["classes"][str(nb.labels[v][1])][nb.labels[v][0]]) for v in nb.order])

    position = vector(masks["position"])
    assert abs(position.sum() - 1) < 1e-12 and np.abs(position @ S - position).max() < 1e-12
    lam1 = float(masks["subdominant"])
    assert lam1 == pytest.approx(float(FAMILIES["doo-sabin"].subdominant.subs(N, n)), abs=1e-15)
    for t in masks["tangents"]:
        tangent = vector(t)
        assert np.abs(tangent).max() > 0.5 and np.abs(tangent @ S - lam1 * tangent).max() < 1e-12
