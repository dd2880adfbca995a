"""``symdecomp c1 --every-n --scheme doo-sabin`` (or a user's dual file): the verdict in text and --json, a variant
file that breaks a condition, a malformed one, a scheme the route does not cover."""

from __future__ import annotations

import json

import jsonschema
import pytest

from symdecomp.cli import c1_cmd, main
from symdecomp.cli.json_envelope import json_schema

DOO_SABIN = "KroneckerDelta(j, 0)/4 + (3 + 2*cos(2*pi*j/m))/(4*m)"


def write(tmp_path, weight: str) -> str:
    path = tmp_path / "variant.toml"
    path.write_text(f'name = "variant"\nmesh = "quad"\ntopology = "dual"\n\n[[corner]]\n'
                    f'terms = [{{walk = "", weight = "{weight}", over = "face"}}]\n', encoding="utf-8")
    return str(path)


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_doo_sabin_every_n_in_text(monkeypatch, capsys):
    """The spectral conditions proved for every n (the bounds from n = 16), the dual test at n = 3..15, the map for every
    n >= 16: C1 proved for every n."""
    monkeypatch.setattr(c1_cmd, "ZOO_EVERY_N_CERTIFIED", 15)
    assert main(["c1", "--every-n", "--scheme", "doo-sabin", "--quiet", "--jobs", "1"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "doo-sabin: C1 for every valence? proved"
    assert out[1].startswith("  [proved] n >= 3: the n-gon's eigenvalue at frequency 1 is its weights' symbol sigma(1) = 1/2")
    assert out[4].startswith("  [proved] n >= 16: lambda_1 < 1 and lambda_1 > 1/4")
    assert out[5].startswith("  [verified] n = 3..15: Reif's test at each valence: ")  # the range said once
    assert all(line.startswith("  [proved] n >= 16: ") for line in out[6:9])
    assert "the characteristic map is regular for every n >= 16" in out[7]
    assert out[8].endswith("the boundary winds once, the map is injective")
    assert out[-1] == ("proved: C1 for every n >= 3: the spectral conditions proved for every n, the characteristic map "
                       "regular and injective for every n >= 16 (exact signs in t = cos(2 pi/n)), Reif's test certified at "
                       "n = 3..15")


@pytest.mark.slow
def test_a_variant_that_breaks_dominance_is_refuted_at_the_computed_valence(tmp_path, monkeypatch, capsys):
    """sigma(+-2) = 1/4 + (n - 4)/8 reaches lambda_1 = 1/2 at n = 6: the step says so, the dual test fails there."""
    monkeypatch.setattr(c1_cmd, "ZOO_EVERY_N_CERTIFIED", 7)
    path = write(tmp_path, f"{DOO_SABIN} + (m - 4)*cos(4*pi*j/m)/(4*m)")
    plot = tmp_path / "every-n.svg"
    assert main(["c1", "--every-n", "--scheme", path, "--json", "--quiet", "--jobs", "1", "--plot", str(plot)]) == 1
    assert plot.read_bytes().startswith(b"<?xml")  # a refutation is drawn too: lambda_1(n) and the valences tested
    data = json.loads(capsys.readouterr().out)
    jsonschema.validate(data, json_schema())  # the one envelope, its step names among the schema's
    assert data["status"] == "refuted" and data["failure"] == 6 and data["certified"] == [3, 5]
    steps = {s["name"]: s for s in data["steps"]}
    assert steps["dominant"]["status"] == "failed" and steps["dominant"]["valences"] == [6, None]
    assert steps["dominant"]["text"].endswith("it fails at n = 6 and at every n after it")
    assert steps["reif-at-n"]["valences"] == [6, 6] and steps["reif-at-n"]["status"] in ("failed", "open")
    assert [r["n"] for r in data["rows"]] == [3, 4, 5, 6]


@pytest.mark.parametrize("weight, line", [
    ("cos(", "weight"),
    ("KroneckerDelta(j, 0)/4 + 3/(4*m)", "--every-n: the spectral conditions for every n are not derived for 'variant'"),
])
def test_malformed_or_uncovered_files_are_one_line(tmp_path, capsys, weight, line):
    path = write(tmp_path, weight)
    assert main(["c1", "--every-n", "--scheme", path]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and line in err[0] and "Traceback" not in err[0]


def test_a_zoo_scheme_outside_the_route_is_refused_with_the_reason(capsys):
    assert main(["c1", "--every-n", "--scheme", "midedge"]) == 2
    (err,) = capsys.readouterr().err.strip().splitlines()
    assert err.startswith("symdecomp: error: --every-n: the spectral conditions for every n are not derived for 'midedge' "
                          "(a scheme of the zoo: its regular part is the four-direction patch")
    # the n-gon's symbol at frequency 1, computed: 1/2 + cos(2 pi/n)/2 (c1 --n certifies it valence by valence)
    assert "lambda_1 = sigma(1) is t/2 + 1/2 with t = cos(2 pi/n), varying with n" in err and err.endswith("give --n A:B")


@pytest.mark.parametrize("scheme", ["doo-sabin", "catmull-clark"])
def test_every_n_with_a_bad_plot_target_is_one_line_before_the_work(scheme, tmp_path, capsys):
    """--every-n draws (the proof's lambda_1(n) beside the certified valences); a target it cannot write is refused
    before any valence is tested, in one line, and nothing is written."""
    target = tmp_path / "map.txt"
    assert main(["c1", "--every-n", "--scheme", scheme, "--plot", str(target)]) == 2
    (err,) = capsys.readouterr().err.strip().splitlines()
    assert err.startswith("symdecomp: error: ") and "--plot" in err and ".txt" in err
    assert not target.exists()
