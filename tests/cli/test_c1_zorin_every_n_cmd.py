"""``symdecomp c1 --every-n --scheme modified-butterfly``: the spectral steps for every n in --json, and the verdict
``undecided`` because the characteristic map is certified per valence only (issue 30).

Zorin's test at each valence is covered by ``tests/verify/test_c1_zorin.py`` (a minute at n = 3); here the rows it
would give are one certified row per valence, so that the test reads what the command builds around them.
"""

from __future__ import annotations

import json

import jsonschema
import numpy as np
import pytest

from symdecomp.analysis.zoo_matrix import zoo_matrix
from symdecomp.cli import c1_cmd, main
from symdecomp.cli.json_envelope import json_schema
from symdecomp.schemes.stencil_files import load_zoo
from symdecomp.symbols import n as N
from symdecomp.verify.result import C1Verdict


def _certified(n: int, scheme, max_depth: int) -> c1_cmd._Row:
    return c1_cmd._Row(n, C1Verdict.C1, "certified (a row of this test)", {"n": n, "verdict": "c1", "reason": "certified"})


@pytest.mark.slow  # the valences below the structural form: an exact spectrum each (about a minute)
def test_the_butterfly_every_n_json_carries_the_steps_and_is_undecided(monkeypatch, capsys):
    monkeypatch.setattr(c1_cmd, "ZORIN_EVERY_N_CERTIFIED", 4)
    monkeypatch.setattr(c1_cmd, "_zoo_one", _certified)
    assert main(["c1", "--every-n", "--scheme", "modified-butterfly", "--quiet", "--jobs", "1", "--json"]) == 1
    out = json.loads(capsys.readouterr().out)
    jsonschema.validate(out, json_schema())
    steps = {s["name"]: s for s in out["steps"]}
    assert out["status"] == "undecided" and "not proved for every n" in out["summary"]
    for name in ("lambda-one", "frequency-zero", "frequency-one", "frequency-exceptional", "other-frequencies"):
        assert steps[name]["status"] == "proved" and steps[name]["valences"] == [16, None]
    assert steps["below-structural"]["status"] == "verified" and steps["below-structural"]["valences"] == [3, 15]
    assert steps["map-open"]["status"] == "open" and steps["map-open"]["valences"] == [5, None]
    assert [r["n"] for r in out["rows"]] == [3, 4]


def _fast(monkeypatch) -> None:
    """The command's own work around the valences: Zorin's test per valence and the spectra below the structural form
    (minutes) replaced by certified rows and nothing."""
    from symdecomp.verify import c1_zorin_every_n as zorin

    monkeypatch.setattr(zorin, "_per_valence", lambda scheme, start: None)
    monkeypatch.setattr(c1_cmd, "ZORIN_EVERY_N_CERTIFIED", 4)
    monkeypatch.setattr(c1_cmd, "_zoo_one", _certified)


def test_the_butterfly_every_n_text_asks_and_names_each_range_once(monkeypatch, capsys):
    """The title asks, with the verdict beside it (undecided), and no step repeats the valences it is printed under."""
    _fast(monkeypatch)
    assert main(["c1", "--every-n", "--scheme", "modified-butterfly", "--quiet", "--jobs", "1"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "modified-butterfly: C1 for every valence? undecided"
    assert out[-1].startswith("undecided: ") and "not proved for every n" in out[-1]
    steps = [line for line in out if line.startswith("  [")]
    assert "  [open] n >= 5: regularity and injectivity of the characteristic map beyond the certified valences are open" \
        in [line.split(": the frequency-1 eigenvector")[0] for line in steps]
    assert any("is derived for every n >= 16" in line and "not proved regular and injective for every n" in line
               for line in steps if line.startswith("  [open]"))
    for line in steps:  # "[open] n >= 5: n > 4: ..." said the valences twice
        where, text = line.split("] ", 1)[1].split(": ", 1)
        assert where.startswith("n ") and not text.startswith(("n > ", "n >= ", "n = ", "for n ")), line


def test_the_butterfly_every_n_computes_its_frequency_polynomials_once(monkeypatch, capsys, tmp_path):
    """The blocks' characteristic polynomials are computed once in a run: the check before any valence, the proof and
    the plot's lambda_1 read the same (they are not cached)."""
    from matplotlib.figure import Figure

    from symdecomp.verify import c1_zorin_every_n as zorin

    _fast(monkeypatch)
    calls: list[str] = []
    computed = zorin.frequency_polynomials

    def counted(scheme):
        calls.append(scheme.name)
        return computed(scheme)

    def figure(result, rows, lam):
        calls.append(f"lambda_1 = {lam}")
        return Figure()

    monkeypatch.setattr(zorin, "frequency_polynomials", counted)
    monkeypatch.setattr(c1_cmd, "_every_n_figure", figure)
    plot = tmp_path / "every-n.png"
    assert main(["c1", "--every-n", "--scheme", "modified-butterfly", "--quiet", "--jobs", "1", "--plot", str(plot)]) == 1
    assert calls == ["modified-butterfly", "lambda_1 = 1/2"]  # once; the plot's lambda_1 read from the same polynomials
    assert plot.read_bytes().startswith(b"\x89PNG")
    assert capsys.readouterr().out.splitlines()[0] == "modified-butterfly: C1 for every valence? undecided"


def test_the_sqrt3_every_n_json_proves_the_spectral_steps_with_lambda_one_in_t(monkeypatch, capsys, tmp_path):
    """sqrt(3)'s lambda_1 depends on n: the steps are proved for every n >= 16 all the same, the map stays open, and the
    plot draws the proof's lambda_1(n)."""
    from matplotlib.figure import Figure

    _fast(monkeypatch)
    drawn: list[object] = []

    def figure(result, rows, lam):
        drawn.append(lam)
        return Figure()

    monkeypatch.setattr(c1_cmd, "_every_n_figure", figure)
    plot = tmp_path / "every-n.png"
    assert main(["c1", "--every-n", "--scheme", "sqrt3", "--quiet", "--jobs", "1", "--json", "--plot", str(plot)]) == 1
    out = json.loads(capsys.readouterr().out)
    jsonschema.validate(out, json_schema())
    steps = {s["name"]: s for s in out["steps"]}
    assert out["status"] == "undecided" and out["summary"].startswith("the spectral conditions hold for every n")
    for name in ("lambda-one", "frequency-zero", "frequency-one", "other-frequencies"):
        assert steps[name]["status"] == "proved" and steps[name]["valences"] == [16, None]
    assert steps["map-open"]["status"] == "open"
    (lam,) = drawn
    assert abs(float(lam.subs(N, 16)) - zoo_subdominant(16)) < 1e-12


def zoo_subdominant(valence: int) -> float:
    """The explicit 1-ring matrix's second largest eigenvalue modulus at ``valence`` (numpy), the engine's own matrix."""
    A = np.array(zoo_matrix(load_zoo("sqrt3"), valence).matrix.evalf(30).tolist(), dtype=float)
    return float(sorted(abs(np.linalg.eigvals(A)), reverse=True)[1])


def test_a_variant_file_whose_largest_root_of_p1_is_irrational_gets_every_spectral_step_proved(monkeypatch, capsys, tmp_path):
    """The butterfly with the extraordinary edge rule reading the vertex two rings out along its spoke, given as a file:
    ``p_1 = (8 x - 1)(16 x^2 - 8 x - 1)/128``, ``lambda_1`` the quadratic's root ``(1 + sqrt 2)/4``, not ``1/8``."""
    from pathlib import Path

    import symdecomp.schemes as schemes

    text = (Path(schemes.__file__).parent / "zoo" / "modified-butterfly.toml").read_text()
    rule = 'origin = "irregular"\nterms = [\n  {walk = "", weight = "3/4"},'
    assert rule in text
    path = tmp_path / "reaching.toml"
    path.write_text(text.replace(rule, rule.replace('"3/4"', '"11/16"') + '\n  {walk = "next twin next twin next next", '
                                 'weight = "1/16"},').replace('"modified-butterfly"', '"reaching"'), encoding="utf-8")
    _fast(monkeypatch)
    assert main(["c1", "--every-n", "--scheme", str(path), "--quiet", "--jobs", "1", "--json"]) == 1
    out = json.loads(capsys.readouterr().out)
    jsonschema.validate(out, json_schema())
    steps = {s["name"]: s for s in out["steps"]}
    assert steps["lambda-one"]["text"].startswith("lambda_1 = 1/4 + sqrt(2)/4: the largest root of det(x I - B_1)")
    assert "(16*x**2 - 8*x - 1)/16" in steps["lambda-one"]["text"]
    for name in ("lambda-one", "frequency-zero", "frequency-one", "frequency-exceptional", "other-frequencies"):
        assert steps[name]["status"] == "proved" and steps[name]["valences"] == [16, None]
    assert out["status"] == "undecided" and out["summary"].startswith("the spectral conditions hold for every n")
