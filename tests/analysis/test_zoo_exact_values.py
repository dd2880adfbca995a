"""Exact values and Jordan blocks at valences where sympy writes cosines as radicals (5, 10, 12, 16, 20, ...).

sympy evaluates ``cos(2 pi/5)`` to ``(sqrt(5) - 1)/4`` and ``cos(pi/8)`` to ``sqrt(sqrt(2)/4 + 1/2)``; the engine's
cyclotomic arithmetic reads neither, so at those valences the exact column was an unreduced sum of exponentials, the
Jordan structure ``?`` and the C1 test's subdominant eigenvalue "not real" (a false ``not C1`` from n = 20 on). The
radicals are read back as the cosines they came from (:func:`symdecomp.analysis.zoo_roots.cosine_form`); the values
and block sizes are checked against the independent reference's matrices (``tests/schemes/zoo_reference.py``), whose
Jordan blocks are counted from the kernels of the powers of ``S - lambda I`` in floats.
"""

import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.zoo_roots import cosine_form
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import C1_DEPTH, spectral_conditions
from tests.schemes import zoo_reference as ref


def _reference_partition(S: np.ndarray, value: float, multiplicity: int) -> list[int]:
    """Jordan block sizes of ``value`` from ``dim ker (S - value I)^i`` (singular values below 1e-8 counted)."""
    A, P, dims = S - value * np.eye(len(S)), np.eye(len(S)), [0]
    while dims[-1] < multiplicity:
        P = P @ A
        dims.append(int((np.linalg.svd(P, compute_uv=False) < 1e-8).sum()))
        assert len(dims) <= multiplicity + 1, "the kernels do not reach the multiplicity"
    more = [dims[i + 1] - dims[i] for i in range(len(dims) - 1)]  # blocks of size > i
    return sorted((i + 1 for i in range(len(more)) for _ in range(more[i] - (more[i + 1] if i + 1 < len(more) else 0))),
                  reverse=True)


def _reference(name: str, n: int) -> np.ndarray:
    if name == "doo-sabin":
        return ref.dual_matrix(n, ref.doo_sabin_weights)[0]
    return ref.butterfly_matrix(n)


@pytest.mark.parametrize(("name", "n"), [("doo-sabin", 5), ("doo-sabin", 10), ("doo-sabin", 16), ("modified-butterfly", 12)])
def test_rational_values_and_jordan_blocks_where_cosines_are_radicals(name, n):
    S = _reference(name, n)
    spectrum = zoo_spectrum(load_zoo(name), n)
    assert sum(e.multiplicity for e in spectrum.eigenvalues) == len(S)
    reference = np.linalg.eigvals(S)
    for e in spectrum.eigenvalues:
        if e.multiplicity == 1:
            continue
        assert isinstance(e.exact, sp.Rational), (n, e.text, e.exact)
        value = float(e.exact)
        assert int(np.sum(np.abs(reference - value) < 1e-4)) == e.multiplicity  # a Jordan block splits by ~sqrt(rounding)
        assert e.jordan is not None and list(e.jordan) == _reference_partition(S, value, e.multiplicity), (n, e.text)


def test_an_exact_zero_is_shown_as_zero():
    zero = next(e for e in zoo_spectrum(load_zoo("modified-butterfly"), 7).eigenvalues if e.exact == 0)
    assert zero.text == "0.0" and zero.multiplicity == 9


@pytest.mark.slow
@pytest.mark.parametrize("n", [20, 24])
def test_doo_sabin_s_subdominant_eigenvalue_is_real_where_its_form_has_radicals(n):
    # the neighbourhood the C1 test reads is explicit at every n; its exact 1/2 was an unreduced complex form
    spectrum = zoo_spectrum(load_zoo("doo-sabin"), n, C1_DEPTH, jordan=False)
    result = spectral_conditions(spectrum, n)
    assert result.status is C1Verdict.C1, result.reason
    assert spectrum.eigenvalues[1].exact == sp.Rational(1, 2) and spectrum.eigenvalues[1].frequencies == (1, n - 1)


@pytest.mark.parametrize(("radicals", "n"), [(sp.sqrt(5) / 4 - sp.Rational(1, 4), 5), (sp.sqrt(sp.sqrt(2) / 4 + sp.Rational(1, 2)), 16),
                                             (sp.sqrt(2) / 4 + sp.sqrt(6) / 4, 12)])
def test_cosine_form_is_the_same_number(radicals, n):
    form = cosine_form(radicals, n)
    assert not form.atoms(sp.Pow) - {p for p in form.atoms(sp.Pow) if p.exp.is_Integer}  # no radical is left
    x = sp.Dummy("x")
    assert sp.minimal_polynomial(form - radicals, x) == x
