"""The guide's sixth family (``docs/guide/adding-a-scheme.md``) through the engine, against the independent reference.

The file is read from the guide itself, so that the page's example is what is tested; the reference is
``tests/schemes/zoo_reference.py``'s dual refinement with the family's weights written from its description.
"""

from __future__ import annotations

import numpy as np
import pytest

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from tests.schemes import zoo_reference as ref
from tests.schemes.test_zoo_reference import _guide_family


@pytest.mark.parametrize("n", range(3, 9))
def test_the_engine_and_the_reference_have_one_characteristic_polynomial(n):
    ours = np.array(zoo_matrix(_guide_family(), n).matrix.evalf(30).tolist(), dtype=float)
    theirs, _ = ref.dual_matrix(n, ref.corner_mean_weights)
    assert ours.shape == theirs.shape
    assert np.allclose(np.poly(ours), np.poly(theirs), atol=1e-9)


@pytest.mark.parametrize("n", [3, 5, 8])
def test_the_engine_s_subdominant_eigenvalue_is_the_reference_s(n):
    theirs = ref.spectrum(ref.dual_matrix(n, ref.corner_mean_weights)[0])
    values = zoo_spectrum(_guide_family(), n).eigenvalues
    assert values[0].multiplicity == 1 and abs(complex(values[0].value) - 1) < 1e-12
    assert values[1].multiplicity == 2 and np.isclose(complex(values[1].value), theirs[1], atol=1e-12)
