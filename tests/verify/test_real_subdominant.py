"""The engine's matrices are real, so the C1 routes that read its spectrum (Zorin's test, the zoo's characteristic-map
plots) judge a subdominant eigenvalue real from its certified ball, even where sympy cannot reduce the imaginary part
of its exact form to 0."""

from __future__ import annotations

import dataclasses

import pytest
import sympy as sp

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.output.plotting import zoo_maps
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.verify import c1_zorin
from symdecomp.verify.result import C1Verdict
from symdecomp.verify.zoo_characteristic import real_matrix, spectral_conditions

BUTTERFLY = load_zoo("modified-butterfly")
N = 5
#: ``i (log 4 - 2 log 2)``: zero, but sympy keeps the difference of logarithms, so ``im`` does not reduce to 0.
HIDDEN_ZERO = sp.I * (sp.log(4) - 2 * sp.log(2))


def _opaque_spectrum(*args, **kwargs):
    """The engine's spectrum with the subdominant eigenvalue's exact form written so that sympy cannot show it real."""
    spectrum = zoo_spectrum(*args, **kwargs)
    values = list(spectrum.eigenvalues)
    i = next(k for k, e in enumerate(values) if e.exact is not None and e.exact != 1)
    values[i] = dataclasses.replace(values[i], exact=values[i].exact + HIDDEN_ZERO)
    return dataclasses.replace(spectrum, eigenvalues=tuple(values))


def test_the_opaque_form_is_zero_but_not_reduced_by_sympy() -> None:
    assert sp.expand_log(HIDDEN_ZERO, force=True) == 0
    assert sp.im(HIDDEN_ZERO) != 0
    opaque = _opaque_spectrum(BUTTERFLY, N, None, jordan=False)
    assert spectral_conditions(opaque, N).status is C1Verdict.UNDECIDED
    assert spectral_conditions(opaque, N, real_matrix=True).status is C1Verdict.C1


def test_the_engine_matrix_is_real() -> None:
    assert real_matrix(zoo_matrix(BUTTERFLY, N))


def test_zorin_reads_realness_from_the_real_matrix(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(c1_zorin, "zoo_spectrum", _opaque_spectrum)
    found = c1_zorin._characteristic(BUTTERFLY, N)
    assert isinstance(found, tuple), found
    assert found[0].status is C1Verdict.C1


def test_zoo_map_reads_realness_from_the_real_matrix(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(zoo_maps, "zoo_spectrum", _opaque_spectrum)
    curves = zoo_maps._net_curves(BUTTERFLY, N, 1)
    assert curves["lines"] and curves["drawn"].startswith("the control net refined")
