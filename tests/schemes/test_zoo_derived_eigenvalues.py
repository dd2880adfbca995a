"""The zoo's leading eigenvalues derived from the shipped files' rules, then compared with the engine and, separately,
with the literature's closed forms.

Round an extraordinary element the rules are circulant, so the eigenvalue at frequency ``k`` of the points that map
among themselves is the discrete Fourier transform of the rule's weights, ``sum_j w_j zeta^(j k)`` (``zeta =
e^(2 pi i/n)``): for a dual family the new point at corner 0 of the n-gon from the corners ``j = 0..n-1``, for the
modified butterfly the new point on the edge towards ring point 0 from the ring points ``j`` (the old vertex is kept).
The weights are read from the files (``symdecomp/schemes/zoo/*.toml``), not typed in; the derived value must be the
engine's exact eigenvalue at that frequency (the difference's minimal polynomial is ``x``). The literature's closed
forms (:data:`symdecomp.schemes.zoo_literature.FAMILIES`: Doo and Sabin 1978's 1/2, the butterfly's 1/2 of Zorin,
Schroeder and Sweldens 1996, Peters and Reif 1997's mid-edge values) are a second, separate check of the same values.
sqrt(3)'s two-step values are derived the same way in ``tests/verify/test_zoo_sqrt3_regime.py``.
"""

import pytest
import sympy as sp

from symdecomp.analysis.zoo_spectrum import zoo_spectrum
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencils import J, M, N
from symdecomp.schemes.zoo_literature import FAMILIES

X = sp.Dummy("x")
OFFSET = {(): 0, ("next",): 1, ("prev",): -1}  # a face corner's walks: itself, the next corner, the previous one


def _corner_weights(name: str, n: int) -> list[sp.Expr]:
    """The weights of a dual family's corner rule on the n-gon's corners ``j = 0..n-1`` (corner 0 the new point's)."""
    (rule,) = next(k for k in load_zoo(name).kinds if k.kind == "corner").rules
    w = [sp.Integer(0)] * n
    for term in rule.terms:
        if term.over == "face":
            for j in range(n):
                w[(OFFSET[term.walk] + j) % n] += term.weight.subs({M: n, J: j})
        else:
            w[OFFSET[term.walk] % n] += term.weight.subs(M, n)
    return w


def _butterfly_weights(n: int) -> list[sp.Expr]:
    """The modified butterfly's weights on the ring of a centre of valence ``n`` (not 6) for the edge point towards ring
    point 0: the file's first ``[[edge]]`` rule whose origin is ``n`` or ``irregular``."""
    edge = next(k for k in load_zoo("modified-butterfly").kinds if k.kind == "edge")
    rule = next(r for r in edge.rules if r.origin in (n, "irregular"))
    (ring,) = [t for t in rule.terms if t.over == "ring"]
    return [ring.weight.subs({N: n, J: j}) for j in range(n)]


def _fourier(weights: list[sp.Expr], k: int) -> sp.Expr:
    n = len(weights)
    return sp.expand(sum(w * sp.exp(2 * sp.pi * sp.I * j * k / n) for j, w in enumerate(weights)))


def _equal(a: sp.Expr, b: sp.Expr) -> bool:
    return sp.minimal_polynomial(sp.expand(a - b), X) == X


def _weights(name: str, n: int) -> list[sp.Expr]:
    return _butterfly_weights(n) if name == "modified-butterfly" else _corner_weights(name, n)


CASES = [pytest.param(name, n, marks=pytest.mark.slow) if (name, n) == ("modified-butterfly", 7) else (name, n)  # 14 s
         for name in ("doo-sabin", "midedge", "modified-butterfly") for n in (3, 4, 5, 7, 8) if (name, n) != ("midedge", 3)]


@pytest.mark.slow
@pytest.mark.parametrize(("name", "n"), CASES)
def test_the_engine_s_subdominant_eigenvalue_is_the_fourier_transform_of_the_file_s_weights(name, n):
    weights = _weights(name, n)
    assert _equal(sum(weights), 1 if name != "modified-butterfly" else sp.Rational(1, 4))  # the butterfly's 3/4 is on the centre
    derived = _fourier(weights, 1)
    spectrum = zoo_spectrum(load_zoo(name), n)
    sub = spectrum.eigenvalues[1]
    assert sub.frequencies == (1, n - 1) and sub.multiplicity == 2
    assert sub.exact is not None and _equal(sub.exact, derived), (name, n, sub.exact, derived)
    if n > 4:  # frequency 2's value from the same weights is an eigenvalue at frequency 2
        second = _fourier(weights, 2)
        assert any(2 in e.frequencies and e.exact is not None and _equal(e.exact, second) for e in spectrum.eigenvalues)


@pytest.mark.slow
@pytest.mark.parametrize(("name", "n"), CASES)
def test_the_derived_value_is_the_literature_s_closed_form(name, n):
    """A separate, cited check: the closed form the source gives (``FAMILIES[name].source``) at this valence."""
    facts = FAMILIES[name]
    assert facts.source and facts.multiplicity == 2
    assert _equal(_fourier(_weights(name, n), 1), facts.subdominant.subs(N, n))
