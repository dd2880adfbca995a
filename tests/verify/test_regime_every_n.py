"""The curvature regime for every valence (issue 32): Catmull-Clark unbounded for every n >= 5, Loop bounded at 4..6 and
unbounded for every n >= 7, as proofs in s = cos(2 pi/n) beyond the certified valences."""

from __future__ import annotations

import json

import flint
import sympy as sp

from symdecomp.cli import main
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.regime_every_n import _positive_on, hyperbolic_cause_from, regime_every_n, unbounded_from


def test_catmull_clark_is_unbounded_for_every_n_from_5():
    r = regime_every_n(catmull_clark())
    assert r.per_valence == ((3, "zero"), (4, "bounded")) and r.first_proved == 5
    assert [s.status for s in r.steps] == ["verified", "proved", "proved"] and r.steps[1].valences == (5, None)
    assert r.steps[2].valences == (5, None) and "the largest after 1 and lambda_1" in r.steps[2].text  # the cause
    assert unbounded_from(catmull_clark(), 4) is None  # n = 4 is bounded: lambda_2 = lambda_1^2 = 1/4 there


def test_loop_is_bounded_at_4_to_6_and_unbounded_for_every_n_from_7():
    r = regime_every_n(loop())
    assert r.per_valence == ((3, "unbounded"), (4, "bounded"), (5, "bounded"), (6, "bounded")) and r.first_proved == 7
    # lambda_2 - lambda_1^2 = (7 s^2 - 3 s)/16 - 1/64 = (7/16)(s - 1/2)(s + 1/14): zero at n = 6 (s = 1/2), positive beyond
    s = sp.Symbol("s")
    assert sp.factor(7 * s**2 / 16 - 3 * s / 16 - sp.Rational(1, 64)) == (2 * s - 1) * (14 * s + 1) / 64
    assert "7*s**2/16 - 3*s/16 - 1/64" in r.steps[1].text
    assert hyperbolic_cause_from(loop(), 7) is not None and hyperbolic_cause_from(catmull_clark(), 4) is None


def test_the_interval_proof_can_fail():
    """The bisection refuses a function negative somewhere, and one that only touches 0."""
    with flint.ctx.workprec(64):
        assert _positive_on(lambda x: x * x - flint.arb(1) / 4, flint.arb(0), flint.arb(1)) is False
        assert _positive_on(lambda x: (x - flint.arb(1) / 2) ** 2, flint.arb(0), flint.arb(1)) is False
        assert _positive_on(lambda x: x + 1, flint.arb(0), flint.arb(1)) is True


def test_the_command(capsys):
    assert main(["artifacts", "--every-n", "--scheme", "loop", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["unbounded_from"] == 7 and [s["status"] for s in data["steps"]] == ["verified", "proved", "proved"]
    assert "the hyperbolic eigenvalue is the largest" in data["steps"][2]["text"]  # the cause, for every n >= 7
    assert main(["artifacts", "--every-n"]) == 0
    assert "[proved] n >= 5:" in capsys.readouterr().out
    assert main(["artifacts"]) == 2
    assert "give --n A:B (the valences) or --every-n" in capsys.readouterr().err
    assert main(["artifacts", "--every-n", "--n", "5"]) == 2
    assert "--every-n and --n cannot be used together" in capsys.readouterr().err
