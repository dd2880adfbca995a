"""Derivation steps built only when read (:class:`~symdecomp.claims.registry.LazySteps`): the verdict does not wait for
them, the pool drops them unbuilt, and ``derive`` reads the same steps as before."""

from __future__ import annotations

import pickle

import sympy as sp

from symdecomp.claims.batch import _as_words
from symdecomp.claims.registry import LazySteps, Status, Step, get_claim
from symdecomp.schemes.scheme import catmull_clark


def _fresh(label: str):
    """The claim's check run anew (``check_claim`` caches: another test may have read its steps), given the scheme the
    registry would hand it for Catmull-Clark (Loop's claims read Loop: :meth:`Claim.reads_instead`)."""
    c = get_claim(label)
    return c.check(c.reads_instead(catmull_clark()) or catmull_clark())


def test_the_verdict_is_given_before_the_steps_are_built():
    result = _fresh("Eq. 47")
    assert result.status is Status.CORRECTED
    assert isinstance(result.steps, LazySteps) and not result.steps.built


def test_the_pool_drops_the_steps_unbuilt():
    result = _fresh("Eq. 47")
    assert _as_words(result).steps == ()
    assert isinstance(result.steps, LazySteps) and not result.steps.built


def test_read_steps_show_the_derivation():
    """Eq. 47's step is BV minus the block-product form: the zero row of nine entries (3 blocks of order 3)."""
    (step,) = _fresh("Eq. 47").steps
    assert step.expr == sp.zeros(1, 9)
    elliptic, lam1, defect = _fresh("Loop's vertex weight").steps
    (n,) = lam1.expr.free_symbols
    assert sp.simplify(lam1.expr.subs(n, 6) - sp.Rational(1, 2)) == 0  # lambda_1 = 3/8 + cos(2 pi/n)/4 = 1/2 at n = 6
    assert sp.simplify(elliptic.expr - lam1.expr**2) == 0 and defect.expr == 0


def test_built_once_compared_added_and_pickled_as_their_tuple():
    calls = []
    x = sp.Symbol("x")

    def build():
        calls.append(1)
        return [Step("a square", x**2)]

    steps = LazySteps(build)
    assert calls == [] and repr(steps) == "LazySteps(<not built>)"
    assert steps == (Step("a square", x**2),) and len(steps) == 1 and steps[0].expr == x**2
    assert () + steps + (Step("b"),) == (Step("a square", x**2), Step("b"))
    assert pickle.loads(pickle.dumps(steps)) == (Step("a square", x**2),)
    assert calls == [1]
