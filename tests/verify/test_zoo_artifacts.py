"""The zoo's artifacts (density, the curvature regime) against the independent reference's matrices.

The reference (``tests/schemes/zoo_reference.py``) refines explicit meshes by each family's rules as the papers state
them, in floats, on the neighbourhood the engine analyses (the dual 4n cells, sqrt(3)'s 2-ring over two steps, the
butterfly's 2-ring). From its matrix the regime follows as the definitions say (:mod:`symdecomp.analysis.curvature_regime`):
the largest modulus after 1 and lambda_1 against lambda_1^2, and at a tie whether that eigenvalue has fewer
eigenvectors than its multiplicity (a Jordan block). The engine's exact values are checked against these numbers, and
its ties are checked exactly (the difference of the exact values reduces to zero).
"""

import numpy as np
import pytest
import sympy as sp

from symdecomp.analysis.charpoly import COSK
from symdecomp.analysis.curvature_regime import CurvatureRegime
from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.errors import InvalidTypeError
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.symbols import lam as LAM
from symdecomp.symbols import omega as OMEGA
from symdecomp.verify.zoo_artifacts import NOT_COMPUTED, zoo_artifacts
from tests.schemes import zoo_reference as ref

#: A Jordan block of size m splits its eigenvalue by about the m-th root of the rounding error in floats (m <= 3 here).
TIE = 1e-4


def _matrix(name: str, n: int) -> np.ndarray:
    if name in ("doo-sabin", "midedge"):
        return ref.dual_matrix(n, ref.doo_sabin_weights if name == "doo-sabin" else ref.midedge_weights)[0]
    return {"sqrt3": ref.sqrt3_two_ring_matrix, "modified-butterfly": ref.butterfly_matrix}[name](n)


def _reference(S: np.ndarray) -> tuple[float, float, CurvatureRegime]:
    """``(lambda_1, |mu|, regime)`` of the matrix ``S`` in floats (module docstring)."""
    ev = ref.spectrum(S)
    assert abs(ev[0] - 1) < 1e-12 and abs(ev[1] - ev[2]) < 1e-9 and abs(ev[2]) > abs(ev[3]) + 1e-6  # 1, then a double lambda_1
    lam = abs(ev[1])
    mu = max(abs(z) for z in ev[3:])
    if mu > lam**2 + TIE:
        return lam, mu, CurvatureRegime.UNBOUNDED
    if mu < lam**2 - TIE:
        return lam, mu, CurvatureRegime.ZERO
    tied = [z for z in ev[3:] if abs(abs(z) - lam**2) < TIE]
    assert all(abs(z - lam**2) < TIE for z in tied)  # the ties here are the positive lambda_1^2
    eigenvectors = S.shape[0] - np.linalg.matrix_rank(S - lam**2 * np.eye(S.shape[0]), tol=1e-9)
    return lam, mu, CurvatureRegime.UNBOUNDED if eigenvectors < len(tied) else CurvatureRegime.BOUNDED


def _agrees(name: str, n: int):
    a = zoo_artifacts(load_zoo(name), n)
    lam, mu, regime = _reference(_matrix(name, n))
    assert a.regime is regime, (name, n, a.reason)
    assert abs(complex(a.lambda1.value.mid()) - lam) < 1e-12
    assert abs(abs(complex(a.mu[0].eigenvalue.value.mid())) - mu) < TIE  # a Jordan block splits in floats
    if a.mu[0].comparison == 0:  # an exact tie: lambda_1^2 - |mu| reduces to zero, and the reference agrees to rounding
        x = sp.Dummy("x")
        if a.lambda1_squared is not None:
            assert sp.minimal_polynomial(a.lambda1_squared - a.mu[0].eigenvalue.exact, x) == x
        else:  # lambda_1 is a root of a cubic: sqrt(mu) is a root of that factor at frequency 1
            at = {LAM: sp.sqrt(a.mu[0].eigenvalue.exact), COSK: sp.cos(2 * sp.pi / n), OMEGA: sp.exp(2 * sp.pi * sp.I / n)}
            assert sp.expand(a.lambda1.factor.xreplace(at)) == 0
        assert abs(lam**2 - mu) < TIE
    regular_n = zoo_matrix(load_zoo(name), 3).neighbourhood.regular_valence
    regular = _reference(_matrix(name, regular_n))[0]
    assert a.density == (0 if abs(lam - regular) < 1e-12 else int(np.sign(lam - regular)))
    return a


@pytest.mark.slow
@pytest.mark.parametrize("n", range(3, 9))
def test_sqrt3_curvature_by_valence_over_two_steps(n):
    a = _agrees("sqrt3", n)
    assert a.steps == 2 and a.lambda1.exact is not None


@pytest.mark.parametrize("n", range(3, 9))
def test_doo_sabin_regime(n):
    a = _agrees("doo-sabin", n)
    assert a.lambda1.exact == sp.Rational(1, 2) and a.lambda1_squared == sp.Rational(1, 4)
    assert a.mu[0].eigenvalue.exact == sp.Rational(1, 4) and a.density == 0


@pytest.mark.parametrize("n", range(3, 9))
def test_modified_butterfly_regime(n):
    a = _agrees("modified-butterfly", n)
    assert a.density == 0 and a.mu[0].comparison == 0


@pytest.mark.parametrize("n", range(4, 9))
def test_midedge_regime(n):
    a = _agrees("midedge", n)
    assert a.mu[0].comparison == (0 if n == 4 else -1)  # the regular face size ties; a flat spot elsewhere


def test_not_applicable_names_the_condition():
    a = zoo_artifacts(load_zoo("midedge"), 3)
    assert a.regime is CurvatureRegime.NOT_APPLICABLE and a.lambda1 is None
    assert a.reason == ("curvature regime not applicable: lambda_1 = 0.25 is not real and double at frequencies 1 and n - 1")
    assert a.as_json()["density"] == "not applicable" and a.as_json()["not_computed"] == NOT_COMPUTED


def test_a_scheme_that_is_not_a_stencil_scheme_is_refused():
    with pytest.raises(InvalidTypeError, match="scheme"):
        zoo_artifacts("sqrt3", 3)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["doo-sabin", "sqrt3", "modified-butterfly"])
def test_a_larger_neighbourhood_adds_nothing_above_mu(name):
    """One ring more only adds eigenvalues of smaller modulus: the regime and mu are those of the smallest neighbourhood."""
    small = zoo_artifacts(load_zoo(name), 5)
    large = zoo_artifacts(load_zoo(name), 5, small.depth + 1)
    assert large.depth == small.depth + 1 and (large.regime, large.reason) == (small.regime, small.reason)
    assert [m.eigenvalue.exact for m in large.mu] == [m.eigenvalue.exact for m in small.mu]


@pytest.mark.slow
@pytest.mark.parametrize(("name", "n"), [("doo-sabin", 10), ("doo-sabin", 16), ("doo-sabin", 20), ("modified-butterfly", 12)])
def test_the_regime_where_sympy_writes_cosines_as_radicals(name, n):
    """At these valences the blocks' entries hold radicals (cos(pi/8) = sqrt(sqrt(2)/4 + 1/2)): the tie with lambda_1^2
    and its Jordan blocks are still decided exactly (n = 16 was undecided, n = 20 took minutes), as the reference says."""
    a = _agrees(name, n)
    assert a.regime is not CurvatureRegime.UNDECIDED and a.mu[0].comparison == 0
