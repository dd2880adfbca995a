"""The zoo's engine against the independent reference: each shipped family's matrix on its neighbourhood.

The reference (``tests/schemes/zoo_reference.py``) refines explicit face lists by each family's rules as the papers
state them, imports nothing of the toolkit and identifies the new neighbourhood with the old by its own means; the
engine (``symdecomp.analysis.zoo_matrix``) walks the shipped files' stencils on a halfedge mesh and finds its
neighbourhood by closure. Labellings differ, so the two are compared by what does not depend on them: the size
of the neighbourhood and the spectrum.
"""

from __future__ import annotations

import numpy as np
import pytest

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.schemes.stencil_files import load_zoo
from tests.schemes import zoo_reference as ref
from tests.schemes.test_zoo_reference import MATRICES, TOLERANCE, VALENCES

CASES = [(name, n) for name in MATRICES for n in VALENCES.get(name, range(3, 9))]


@pytest.mark.parametrize(("name", "n"), CASES)
def test_the_engine_and_the_reference_have_one_matrix_up_to_labels(name, n):
    zm = zoo_matrix(load_zoo(name), n)
    ours = np.array(zm.matrix.evalf(30).tolist(), dtype=complex)
    theirs = np.asarray(MATRICES[name](n), dtype=complex)
    assert ours.shape == theirs.shape
    a, b = ref.spectrum(ours), ref.spectrum(theirs)
    assert np.allclose(sorted(np.abs(a)), sorted(np.abs(b)), atol=TOLERANCE)
    # the characteristic polynomials agree too: the same eigenvalues with their multiplicities, not only moduli
    assert np.allclose(np.poly(ours), np.poly(theirs), atol=1e-9)
