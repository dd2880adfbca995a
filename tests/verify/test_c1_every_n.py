"""C1 for every valence (issue 32): what is proved in n, what is certified per valence, what is open, and thresholds."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from symdecomp.cli import main
from symdecomp.schemes.files import load_scheme, scheme_from_text
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark
from symdecomp.verify.c1_every_n import T, c1_every_n, laurent_in_t, spectral_every_n

CORPUS = Path(__file__).parents[1] / "corpus"


def test_the_frequency_blocks_in_t():
    """Catmull-Clark's M(omega) has trace 5/8 + t/8 and discriminant (t + 1)(t + 9)/64 in t = cos(2 pi j/n)."""
    from symdecomp.analysis.frequency import one_ring_matrices

    M = sp.Matrix(one_ring_matrices(catmull_clark())[0])
    tr, det = laurent_in_t(M.trace()), laurent_in_t(M.det())
    assert sp.expand(tr - (sp.Rational(5, 8) + T / 8)) == 0
    assert sp.factor(tr**2 - 4 * det) == (T + 1) * (T + 9) / 64
    # at n = 4 (t = 0) the eigenvalues are 1/2 and 1/8: Catmull-Clark's lambda_1 = 1/2
    assert sp.Poly(sp.Symbol("x") ** 2 - tr.subs(T, 0) * sp.Symbol("x") + det.subs(T, 0)).all_roots() == [sp.Rational(1, 8), sp.Rational(1, 2)]


@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=["catmull-clark", "loop"])
def test_the_spectral_conditions_are_proved_for_every_n(scheme):
    steps = spectral_every_n(scheme)
    assert all(s.status == "proved" for s in steps), [s.text for s in steps if s.status != "proved"]
    assert max(s.valences[0] for s in steps) <= 4 and all(s.valences[1] is None for s in steps)


@pytest.mark.parametrize("scheme", [catmull_clark(), loop()], ids=["catmull-clark", "loop"])
def test_every_n_is_proved(scheme):
    """The spectral conditions in t, Reif's test at 3..12, and the characteristic map for every n >= 3 by exact signs."""
    r = c1_every_n(scheme, 12)
    assert r.status == "proved" and r.certified == (3, 12) and r.failure is None
    assert [s.status for s in r.steps][-4:] == ["verified", "proved", "proved", "proved"]
    assert all(s.valences == (3, None) for s in r.steps[-3:]) and r.summary.startswith("C1 for every n >= 3")


def test_without_the_uniform_map_the_map_stays_open(monkeypatch):
    """When the exact signs do not close (here: refused), C1 is verified for 3..last and the map is open beyond."""
    from symdecomp.verify import c1_uniform

    monkeypatch.setattr(c1_uniform, "uniform_nets", lambda scheme: (_ for _ in ()).throw(
        c1_uniform.NotApplicableError("refused for the test")))
    r = c1_every_n(catmull_clark(), 12)
    assert r.status == "verified" and [s.status for s in r.steps][-2:] == ["verified", "open"]
    assert r.steps[-1].valences == (13, None) and "refused for the test" in r.steps[-1].text


def test_a_spectral_condition_that_fails_is_not_called_proved():
    """Vertex weights 1/100, 1/100 at every n, except the regular ones at 4 (the whole-mesh model): the E_0 eigenvalues
    cross lambda_1, Proposition 5.1's tail bound does not hold, and C1 fails at a concrete valence."""
    s = catmull_clark(sp.Rational(3, 32) + (sp.Symbol("n") - 4) ** 2 / 100, sp.Rational(1, 64))
    r = c1_every_n(s, 12)
    assert r.status == "refuted" and r.failure is not None and r.failure <= 12


def test_a_late_crossing_file_gets_its_exact_threshold():
    """tests/corpus/tuned-at-ev.toml: vertex weights 3/32 + (n - 4)/200, 1/64 - (n - 4)/400 (Catmull-Clark's at 4). C1 is
    certified at n = 3..9; at n = 10 an eigenvalue of E_0 (-0.6382) exceeds lambda_1 (0.6263), and from n = 12 on
    q(-L') < 0 with L' > lim lambda_1 = (3 + sqrt(5))/8: C1 fails for every n >= 10."""
    r = c1_every_n(load_scheme(str(CORPUS / "tuned-at-ev.toml")), 64)
    assert r.status == "refuted" and r.failure == 10 and r.certified == (3, 9)
    assert "exact threshold" in r.summary and r.steps[-1].status == "proved" and r.steps[-1].valences == (10, None)
    assert "sqrt(5)/8 + 3/8" in r.steps[-1].text


def test_a_failure_at_one_valence_is_a_concrete_refutation():
    """Edge weights (2n - 5)/8, (9 - 2n)/16 (Catmull-Clark's at 4): at n = 5 the frequency 2 dominates."""
    text = ('name = "frequency two"\n[edge]\nO = "(2*n - 5)/8"\na = { "-1" = "(9 - 2*n)/16", "0" = "(2*n - 5)/8", '
            '"1" = "(9 - 2*n)/16" }\nb = { "-1" = "(9 - 2*n)/16", "0" = "(9 - 2*n)/16" }\n[face]\nO = "1/4"\n'
            'a = { "0" = "1/4", "1" = "1/4" }\nb = { "0" = "1/4" }\n[vertex]\na = "3/(2*n**2)"\nb = "1/(4*n**2)"\n')
    r = c1_every_n(scheme_from_text(text), 12)
    assert r.status == "refuted" and r.failure == 5 and r.steps[0].status == "open"  # M depends on n: no argument in t


@pytest.mark.parametrize(("scheme", "regular"), [(catmull_clark(), 4), (loop(), 6)], ids=["catmull-clark", "loop"])
def test_lambda_one_in_n_is_the_certified_lambda_at_each_valence(scheme, regular):
    """The closed form the --every-n figure draws is the eigenvalue Reif's test certifies, valence by valence."""
    from symdecomp.symbols import n as N
    from symdecomp.verify.c1 import c1_test
    from symdecomp.verify.c1_every_n import lambda_one

    lam = lambda_one(scheme)
    assert lam.free_symbols == {N}
    for k in range(3, 9):
        assert abs(float(lam.subs(N, k)) - c1_test(scheme, k).as_json()["lambda"]) < 1e-12
    assert sp.simplify(lam.subs(N, regular) - sp.Rational(1, 2)) == 0  # the regular valence: the spline's 1/2
    from tests.schemes.test_scheme_files import CC_TOML

    free = scheme_from_text(CC_TOML.replace('name = "catmull-clark"', 'name = "free"\nparameters = ["alpha"]')
                            .replace('a = "3/(2*n**2)"', 'a = "alpha"'))
    assert free.parameters and lambda_one(free) is None  # free parameters: no closed form


@pytest.mark.slow
def test_the_command(capsys, tmp_path):
    plot = tmp_path / "every-n.png"
    assert main(["c1", "--every-n", "--scheme", "loop", "--json", "--plot", str(plot)]) == 0
    assert plot.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")  # the proof's lambda_1(n) beside the certified valences
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "proved" and data["certified"] == [3, 64]
    assert [s["status"] for s in data["steps"]] == ["proved", "proved", "proved", "verified", "proved", "proved", "proved"]
    assert main(["c1", "--n", "3:"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "catmull-clark: C1 for every valence? proved" and out.splitlines()[-1].startswith("proved: C1 for every n >= 3")
    assert main(["c1", "--n", "5:"]) == 2
    assert "an open range starts at 3" in capsys.readouterr().err
    assert main(["c1", "--every-n", "--n", "5"]) == 2
    assert "--every-n and --n cannot be used together" in capsys.readouterr().err
