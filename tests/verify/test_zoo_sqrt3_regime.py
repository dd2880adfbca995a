"""sqrt(3)'s curvature regime by valence, derived from its rules and compared with ``artifacts``.

Over the two steps that return the lattice to itself, the 1-ring ``(c, p_0..p_(n-1))`` is closed, and its blocks follow
from the shipped file's weights by the Fourier transform round the centre: a step puts the face point of the triangle
``(c, p_i, p_(i+1))`` at direction ``i + 1/2`` with weight ``w`` (the file's face rule at m = 3) on each corner, so at
frequency ``k != 0`` one step multiplies by ``w (omega^(k/2) + omega^(-k/2)) = 2 w cos(pi k/n)`` and two steps by
``(2 w cos(pi k/n))^2``; at frequency 0 the centre's rule ``(1 - alpha_n) c + alpha_n/n sum p_i`` (``alpha_n`` read from
the file's vertex rule) and the face points ``w c + 2 w p`` give the 2 x 2 block ``[[1 - alpha_n, alpha_n], [w, 2 w]]``,
whose eigenvalues are 1 and ``2 w - alpha_n`` (``2/3 - alpha_n``; the trace less 1), squared over two steps. So

* ``lambda_1 = (2 w cos(pi/n))^2 = (2 + 2 cos(2 pi/n))/9``, the subdominant pair (frequencies 1, n - 1);
* frequency 0 gives ``(2/3 - alpha_n)^2``, which Kobbelt's ``alpha_n`` makes exactly ``lambda_1^2`` (a tie, elliptic);
* frequency 2 gives ``(2 + 2 cos(4 pi/n))/9``: below ``lambda_1^2`` for n < 6, equal at n = 6, above from n = 7 on.

Hence the regime, with the 1-ring's values: bounded at n = 4, 5, 6 (the tie at frequency 0, no Jordan block), unbounded
from n = 7 on (hyperbolic, frequency 2). At n = 3 the 1-ring is not the whole story: the second ring adds
``2/81 + sqrt(7)/162 > lambda_1^2 = 1/81`` at frequency 0 (``tests/schemes/zoo_reference.py``'s two-ring matrix
agrees), so the curvature is unbounded there too. What the source says is only its abstract (L. Kobbelt, 2000,
sqrt(3)-subdivision, SIGGRAPH 2000): C2 at regular points, C1 at extraordinary ones; it is not a statement of the
curvature by valence, so these are checked against the derivation, not against a quoted result.
"""

import pytest
import sympy as sp

from symdecomp.analysis.curvature_regime import CurvatureRegime
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.schemes.stencils import M, N
from symdecomp.verify.zoo_artifacts import zoo_artifacts

X = sp.Dummy("x")


def _weights(n: int) -> tuple[sp.Expr, sp.Expr]:
    """``(w, alpha_n)`` read from the shipped file: the face rule's weight at m = 3, and n times the vertex rule's ring weight."""
    scheme = load_zoo("sqrt3")
    kinds = {k.kind: k for k in scheme.kinds}
    (face,) = kinds["face"].rules[0].terms
    ring = next(t for t in kinds["vertex"].rules[0].terms if t.over == "ring")
    return face.weight.subs(M, 3), sp.simplify(n * ring.weight.subs(N, n))


def _derived(n: int) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """``(lambda_1, frequency 0's second value, frequency 2's value)`` over two steps (module docstring)."""
    w, alpha = _weights(n)
    step = lambda k: 2 * w * sp.cos(sp.pi * k / n)  # noqa: E731 - one line of the derivation
    return sp.expand(step(1) ** 2), sp.expand((2 * w - alpha) ** 2), sp.expand(step(2) ** 2)


def _zero(e: sp.Expr) -> bool:
    return sp.minimal_polynomial(e, X) == X


def _sign(a: sp.Expr, b: sp.Expr) -> int:
    return 0 if _zero(a - b) else (1 if float(a - b) > 0 else -1)


@pytest.mark.parametrize("n", range(3, 13))
def test_the_derivation_is_kobbelt_s_closed_form(n):
    lam, zero, _ = _derived(n)
    assert _zero(lam - (2 + 2 * sp.cos(2 * sp.pi / n)) / 9)
    assert _zero(zero - lam**2), "Kobbelt's alpha_n makes frequency 0's second eigenvalue lambda_1^2"


@pytest.mark.slow
@pytest.mark.parametrize("n", range(4, 11))
def test_the_regime_by_valence_is_the_derived_one(n):
    lam, zero, two = _derived(n)
    expected = CurvatureRegime.UNBOUNDED if _sign(two, lam**2) > 0 else CurvatureRegime.BOUNDED
    assert expected is (CurvatureRegime.UNBOUNDED if n >= 7 else CurvatureRegime.BOUNDED)
    a = zoo_artifacts(load_zoo("sqrt3"), n)
    assert a.regime is expected, (n, a.reason)
    assert _zero(a.lambda1.exact - lam) if a.lambda1.exact is not None else abs(complex(a.lambda1.value.mid()) - float(lam)) < 1e-15
    top = a.mu[0].eigenvalue
    assert abs(complex(top.value.mid()) - float(two if n >= 7 else zero)) < 1e-15
    assert ("hyperbolic" in a.mu[0].kinds) == (n >= 6) and ("elliptic" in a.mu[0].kinds) == (n <= 6)


def test_valence_3_is_unbounded_by_the_second_ring():
    lam, zero, two = _derived(3)
    a = zoo_artifacts(load_zoo("sqrt3"), 3)
    assert a.regime is CurvatureRegime.UNBOUNDED and a.depth >= 2
    outer = a.mu[0].eigenvalue.exact
    assert _zero(outer - (sp.Rational(2, 81) + sp.sqrt(7) / 162)) and _sign(outer, lam**2) == 1
    assert _sign(zero, lam**2) == 0 and _zero(two - lam)  # 1-ring alone: a tie at frequency 0 (2 is n - 1 here): bounded
