"""Issue 35, items 7, 11, 12 and 15: ``[sharp]`` sections, sharp options, tuning regions and API bounds.

Each row of :data:`SIGNATURES` is one finding of the issue (an internal error, a run past two minutes), with what is
due instead: one line naming the input, exit status 2 (the package's error in the API), at once. Every row of items 7,
11 and 12 failed on the main branch the issue was filed against; the rows of item 21 keep the sharp options' checks
where they moved (``symdecomp.cli.element.check_sharp_options``).
"""

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest
import sympy as sp

from symdecomp import (
    artifact_indicators,
    catmull_clark,
    jordan_block_size,
    jordan_vertex_weights,
    loop,
    second_order_eigenstructure,
)
from symdecomp.analysis.tuning_region import tuning_region
from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError, InvalidValenceError, NotApplicableError
from symdecomp.schemes.files import load_scheme, scheme_from_text
from symdecomp.schemes.sector import SharpVertex

ROOT = Path(__file__).resolve().parents[2]

#: Catmull-Clark's rules as a file; a ``[sharp]`` section or a vertex rule is added per case.
CC_RULES = """name = "{name}"
{parameters}
[edge]
O = "3/8"
a = {{ "-1" = "1/16", "0" = "3/8", "1" = "1/16" }}
b = {{ "-1" = "1/16", "0" = "1/16" }}
[face]
O = "1/4"
a = {{ "0" = "1/4", "1" = "1/4" }}
b = {{ "0" = "1/4" }}
[vertex]
{vertex}
"""


def scheme_text(name: str, near: str | None = None, *, parameters: str = "", vertex: str = 'a = "3/(2*n**2)"\nb = "1/(4*n**2)"'):
    text = CC_RULES.format(name=name, parameters=parameters, vertex=vertex)
    if near is not None:  # BLZ's form: the two weights sum to the edge rule's 3/4
        text += f'[sharp]\nnear_edge_centre = "3/8 + {near}"\nnear_edge_end = "3/8 - {near}"\n'
    return text


FILES = {
    "undefined-at-2": scheme_text("undefined-at-2", "1/(k - 2)"),
    "bare-angle": scheme_text("bare-angle", "theta_k/8"),
    "irrational-multiple": scheme_text("irrational-multiple", "cos(sqrt(2)*theta_k)/4"),
    "bare-pi": scheme_text("bare-pi", "pi/100"),
    "free-sharp": scheme_text("free-sharp", "gamma", parameters='parameters = ["gamma"]'),
    "inverse-alpha": scheme_text("inverse-alpha", parameters='parameters = ["alpha", "beta"]', vertex='a = "1/alpha"\nb = "beta"'),
    "two-weights": scheme_text("two-weights", parameters='parameters = ["alpha", "beta"]', vertex='a = "alpha"\nb = "beta"'),
    "one-weight": scheme_text("one-weight", parameters='parameters = ["alpha"]', vertex='a = "alpha"\nb = "1/16"'),
}

#: ``(finding, command line with {file}, what the one line says)``.
SIGNATURES = [
    ("11: 1/(k-2) at k = 2, masks --corner (NotAlgebraic: zoo)", ["masks", "2", "--corner"], "undefined-at-2",
     "undefined at k = 2"),
    ("11: 1/(k-2) at k = 2, check --certify --crease (NotAlgebraic: zoo)", ["check", "--certify", "--crease", "2", "--k", "2"],
     "undefined-at-2", "undefined at k = 2"),
    ("11: 1/(k-2) at the regular boundary next to O (NotAlgebraic: zoo)", ["spectrum", "3", "--boundary"], "undefined-at-2",
     "undefined at k = 2"),
    ("11: a bare theta_k, spectrum --boundary (NotAlgebraic: pi)", ["spectrum", "3", "--boundary"], "bare-angle",
     "theta_k outside cos and sin"),
    ("11: a bare theta_k, check --certify --boundary (NotAlgebraic: pi)", ["check", "--certify", "--boundary", "--k", "3"],
     "bare-angle", "theta_k outside cos and sin"),
    ("11 (found by the fuzz suite): pi outside cos and sin (NotAlgebraic: pi)", ["spectrum", "2", "--boundary"], "bare-pi",
     "pi outside cos and sin"),
    ("11: a free parameter in [sharp], masks --corner (TypeError: invalid input)", ["masks", "2", "--corner"], "free-sharp",
     "free parameters gamma"),
    ("11: a free parameter in [sharp], spectrum --boundary (TypeError)", ["spectrum", "3", "--boundary"], "free-sharp",
     "free parameters gamma"),
    ("11: a free parameter in [sharp], check --certify --crease (TypeError)", ["check", "--certify", "--crease", "2", "--k", "2"],
     "free-sharp", "free parameters gamma"),
    ("12: tune --region on a = 1/alpha (PolynomialError)", ["tune", "5", "--region"], "inverse-alpha", "not affine"),
    ("7: tune 64 --region, two weights (over 600 s)", ["tune", "64", "--region"], "two-weights", "phi(n) = 32 > 4"),
    ("7: tune 7 --region, one weight (over 300 s)", ["tune", "7", "--region"], "one-weight", "phi(n) = 6 > 4"),
    ("7: artifacts --n 3:4096 (over 120 s)", ["artifacts", "--n", "3:4096"], None, "more than the limit"),
    ("21: --sharpness without --crease or --dart", ["spectrum", "5", "--sharpness", "1/2"], None, "--crease K2 or --dart"),
    ("21: --sharpness with --boundary", ["masks", "5", "--boundary", "--sharpness", "1/2"], None, "boundary edges are infinitely sharp"),
]


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sharp-schemes")
    out = {}
    for name, text in FILES.items():
        out[name] = folder / f"{name}.toml"
        out[name].write_text(text)
    return out


@pytest.mark.parametrize("finding, argv, scheme, says", SIGNATURES, ids=[s[0] for s in SIGNATURES])
def test_refused_in_one_line(finding, argv, scheme, says, files, capsys):
    start = time.monotonic()
    code = main(argv + (["--scheme", str(files[scheme])] if scheme else []))
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert code == 2, (finding, err)
    assert "\n" not in err and "internal error" not in err and "Traceback" not in err, err
    assert says in err, err
    assert captured.out == ""  # refused before the work: no header printed
    assert time.monotonic() - start < 30


def test_sharp_rules_refused_when_read():
    """A weight that is not exact at the vertex is refused with the file, before any command runs."""
    for name, says in (("bare-angle", "theta_k outside cos and sin"), ("irrational-multiple", "rational multiples? of theta_k")):
        with pytest.raises(InvalidSchemeError, match=says):
            scheme_from_text(FILES[name], source=f"{name}.toml")
    blz = load_scheme("catmull-clark-blz")  # cos(theta_k): exact in Q(cos(pi/k)), read as before
    assert blz.sharp.near_edge(sp.pi / 4, 4) == (sp.Rational(3, 8) + sp.sqrt(2) / 8, sp.Rational(3, 8) - sp.sqrt(2) / 8)


def test_near_edge_weights_checked_at_each_sector():
    rules = scheme_from_text(FILES["undefined-at-2"], source="x.toml").sharp
    assert rules.near_edge(sp.pi / 3, 3) == (sp.Rational(3, 8) + 1, sp.Rational(3, 8) - 1)  # 1/(k - 2) = 1 at k = 3
    with pytest.raises(InvalidSchemeError, match="undefined at k = 2"):
        rules.near_edge(sp.pi / 2, 2)
    with pytest.raises(InvalidSchemeError, match="undefined at k = 2"):
        rules.check_at(SharpVertex.boundary(3, "quad").sectors + (2,))
    free = scheme_from_text(FILES["free-sharp"], source="x.toml").sharp
    with pytest.raises(InvalidSchemeError, match="free parameters gamma"):
        free.check_at((3,))


def test_api_sharp_spectrum_refuses_free_parameters():
    """The API's sharp routes read the near-edge weights through the same check (was ``TypeError: invalid input``)."""
    from symdecomp.analysis.spectrum import sharp_spectrum

    scheme = scheme_from_text(FILES["free-sharp"], source="x.toml")
    with pytest.raises(InvalidSchemeError, match="free parameters gamma"):
        sharp_spectrum(scheme, SharpVertex.boundary(3, "quad"))


def test_tuning_region_refuses_non_polynomial_weights():
    scheme = scheme_from_text(FILES["inverse-alpha"], source="x.toml")
    with pytest.raises(NotApplicableError, match="not affine in alpha, beta"):
        tuning_region(scheme, 5)


@pytest.mark.parametrize("call", [
    lambda: jordan_block_size(loop(), 5, "3/8"),
    lambda: jordan_vertex_weights(loop(), 5, "3/8"),
])
def test_jordan_functions_refuse_triangle_schemes(call):
    """Item 15: ``AttributeError: 'NoneType' object has no attribute 'center'`` on any triangle scheme."""
    with pytest.raises(NotApplicableError, match="triangle-mesh scheme; the Eq. 43 recursion matrix"):
        call()


def test_jordan_block_size_still_exact_on_quads():
    # Catmull-Clark at n = 5: 1/4 is no eigenvalue of Eq. 43; the doctest's tuned weights give a block of size 2
    assert jordan_block_size(catmull_clark(), 5, sp.Rational(1, 4)) == 0
    assert jordan_block_size(catmull_clark(), 4, sp.Rational(1, 4)) == 1


@pytest.mark.parametrize("function", [artifact_indicators, second_order_eigenstructure])
@pytest.mark.parametrize("n", [2**64, 2**64 + 1, 10**6, 4097])
def test_api_valence_bounds(function, n):
    """Item 15 (``OverflowError`` at n >= 2^64) and item 7 (10^6 never returned): refused at once, naming the bound."""
    start = time.monotonic()
    with pytest.raises(InvalidValenceError, match=r"3 <= n <= 4096"):
        function(catmull_clark(), n)
    assert time.monotonic() - start < 5


def test_dart_memory_estimated_before_flint(monkeypatch, capsys):
    """Item 7: ``masks 64 --dart`` died of SIGABRT (FLINT's failed allocation at 3.8 GB under a 4 GB cap): the estimate,
    the faces to the 4th power, is checked first, so a cap below it is one line, exit 2, before any allocation."""
    import symdecomp.validate

    monkeypatch.setattr(symdecomp.validate, "MEMORY_LIMIT", 4 << 30)
    start = time.monotonic()
    assert main(["masks", "64", "--dart"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == ("symdecomp: error: dart n=64: the exact analysis would need about 7 GiB of memory, more than the limit "
                   "of 4 GiB; choose a smaller valence")
    assert time.monotonic() - start < 10
    monkeypatch.setattr(symdecomp.validate, "MEMORY_LIMIT", 1 << 30)  # 40 faces: about 1.07 GiB; 36 faces 0.7 GiB
    assert main(["spectrum", "40", "--dart"]) == 2 and "1 GiB" in capsys.readouterr().err


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS as Linux counts it")
@pytest.mark.parametrize("argv", [["masks", "64", "--dart"], ["check", "--certify", "--dart", "--k", "60:64"]])
def test_dart_under_a_4_gib_cap_is_refused_not_aborted(argv, tmp_path):
    """Item 7 as the issue ran it: under a 4 GB address-space cap, no SIGABRT after minutes, but one line and exit 2."""
    import resource

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))

    start = time.monotonic()
    run = subprocess.run([sys.executable, "-m", "symdecomp", *argv], cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(ROOT)},
                         preexec_fn=limit, capture_output=True, text=True, timeout=120)
    assert run.returncode == 2, run.stderr[-500:]
    assert run.stderr.count("\n") == 1 and "of memory, more than the limit of 4 GiB" in run.stderr, run.stderr
    assert run.stdout == "" and time.monotonic() - start < 60
