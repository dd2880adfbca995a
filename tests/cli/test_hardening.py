"""The examples of the hardening issue, each ending as one clear error or the right answer."""

import os
import re
import subprocess
import sys
from pathlib import Path

import flint
import numpy as np
import pytest
import sympy as sp

from symdecomp import (
    SymdecompError,
    catmull_clark,
    closed_form_spectrum,
    constant_blocks,
    invariant_ratio_at,
    root_of_unity,
    subdivision_matrix,
    tangent_eigenvalues,
)
from symdecomp.algebra.polygons import decompose
from symdecomp.cli import main
from symdecomp.cli.files import replace_owned_files
from symdecomp.errors import (
    FrequencyOutOfRangeError,
    InvalidInputError,
    InvalidSchemeError,
    InvalidTypeError,
    InvalidValenceError,
    ResourceLimitError,
)
from symdecomp.schemes.full_matrix import characteristic_polynomial
from symdecomp.symbols import alpha as ALPHA
from symdecomp.symbols import beta as BETA
from symdecomp.symbols import n as N

ROOT = Path(__file__).resolve().parents[2]


def test_error_hierarchy():
    assert issubclass(InvalidValenceError, ValueError) and issubclass(InvalidValenceError, SymdecompError)
    assert issubclass(InvalidTypeError, TypeError) and not issubclass(InvalidTypeError, ValueError)
    assert not issubclass(SymdecompError, ValueError)


@pytest.mark.parametrize("n", [5.9, 0, -1, 2, "5", True, sp.Symbol("n"), np.float64(5)])
def test_non_integer_or_small_valences_are_refused(n):
    with pytest.raises(InvalidValenceError):
        invariant_ratio_at(catmull_clark(), n, 1)


def test_numpy_integers_are_valences():
    cc = catmull_clark()
    assert tangent_eigenvalues(cc).at(np.int64(5), np.int32(1)) == tangent_eigenvalues(cc).at(5, 1)


def test_non_integer_frequencies_and_powers_are_refused():
    with pytest.raises(FrequencyOutOfRangeError):
        invariant_ratio_at(catmull_clark(), 5, 1.7)
    with pytest.raises(InvalidValenceError):
        tangent_eigenvalues(catmull_clark()).at(0, 1)
    with pytest.raises(InvalidInputError, match="power"):
        root_of_unity(5, 2.5)


def test_booleans_are_not_weights():
    with pytest.raises(InvalidSchemeError, match="boolean"):
        catmull_clark(True, False)


def test_a_weight_undefined_at_the_valence_is_named():
    n = sp.Symbol("n")
    scheme = catmull_clark(1 / (n - 5), None)
    with pytest.raises(InvalidSchemeError, match="undefined at valence n = 5"):
        subdivision_matrix(scheme, 5)
    assert subdivision_matrix(scheme, 6)[0, 1] == 1  # 1/(6 - 5)


def test_a_users_symbol_n_is_the_valence():
    users_n = sp.Symbol("n")  # no assumptions: a different sympy object from symdecomp's n
    scheme = catmull_clark(sp.Rational(3, 2) / users_n**2, sp.Rational(1, 4) / users_n**2)
    assert scheme.parameters == ()
    assert subdivision_matrix(scheme, 5) == subdivision_matrix(catmull_clark(), 5)
    assert constant_blocks([[1 / users_n]], 3).rows[0][0][0] == 1 / N


def test_parameters_given_as_text_are_read_alike_everywhere():
    free = catmull_clark(ALPHA, BETA)
    by_text = closed_form_spectrum(free, 5, parameters={"alpha": "3/50", "beta": "1/100"})
    by_value = closed_form_spectrum(free, 5, parameters={ALPHA: sp.Rational(3, 50), BETA: sp.Rational(1, 100)})
    assert by_text == by_value
    assert characteristic_polynomial(free, 5, {"alpha": "3/50", "beta": "1/100"}) == characteristic_polynomial(
        free, 5, {ALPHA: sp.Rational(3, 50), BETA: sp.Rational(1, 100)})
    with pytest.raises(InvalidSchemeError, match="float"):
        closed_form_spectrum(free, 5, parameters={"alpha": 0.06, "beta": 0})


@pytest.mark.parametrize("polygon", [[[1, 0, 0]] * 3, [[1, 0, 0], [-1, 0, 0]] * 2, [[1, 2, 3], [0, 1, -1], [2, 2, 0], [5, 1, 1]]])
def test_planar_pairs_sum_to_the_pair_polygon_at_every_j_exactly(polygon):
    d = decompose(polygon)
    n = len(polygon)
    for j in range(n):
        first, second = d.planar_pair(j)
        total = sp.Matrix(first.vertices()) + sp.Matrix(second.vertices())
        assert (total - d.pair_polygon(j)).applyfunc(sp.simplify) == sp.zeros(n, 3), j


def test_memory_hungry_steps_are_refused_with_an_estimate():
    with pytest.raises(ResourceLimitError, match="would need about .* of memory"):
        characteristic_polynomial(catmull_clark(), 20000)


def test_the_k_ring_characteristic_polynomial_checks_memory_too(monkeypatch):
    from symdecomp import validate
    from symdecomp.schemes.full_matrix import entries_characteristic_polynomial

    entries = {(i, i): flint.fmpq(1, i + 2) for i in range(40)}
    chi = entries_characteristic_polynomial(entries, 40)  # diagonal: the product of (x - 1/(i + 2))
    assert all(chi(flint.fmpq(1, i + 2)) == 0 for i in range(40)) and chi.degree() == 40
    monkeypatch.setattr(validate, "MEMORY_LIMIT", 1000)
    with pytest.raises(ResourceLimitError, match="of a 40 x 40 matrix would need about"):
        entries_characteristic_polynomial(entries, 40)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS as Linux counts it")
def test_evaldata_beyond_the_memory_limit_of_the_process_is_refused_before_it_starts(tmp_path):
    """Issue 25, item 5: under ``ulimit -v`` evaldata's estimate took only the machine's memory, so a run that could
    not fit started (3..400: 20 minutes) and ended out of memory; the limit of the process counts now."""
    import resource

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))

    run = subprocess.run([sys.executable, "-m", "symdecomp", "evaldata", "--n", "3:400", "--out", "x.bin"],
                         cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(ROOT)}, preexec_fn=limit,
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and run.stderr.count("\n") == 1, run.stderr
    assert "would need about 3 GiB of memory, more than the limit of 2 GiB" in run.stderr
    assert list(tmp_path.iterdir()) == []


def test_derive_replaces_its_files_as_a_whole(tmp_path):
    owned = re.compile(r"^(main|section-[0-9-]+)\.tex$")
    out = tmp_path / "out"
    out.mkdir()
    (out / "section-9.tex").write_text("stale")
    (out / "notes.txt").write_text("mine")
    written = replace_owned_files(out, {"main.tex": "new main", "section-2.tex": "two"}, owned)
    assert sorted(p.name for p in out.iterdir()) == ["main.tex", "notes.txt", "section-2.tex"]
    assert (out / "notes.txt").read_text() == "mine" and written == [out / "main.tex", out / "section-2.tex"]
    assert [p.name for p in tmp_path.iterdir()] == ["out"]  # no staging directory left behind


def test_an_interrupted_derive_leaves_the_old_files(tmp_path, monkeypatch):
    import symdecomp.cli.files as files

    owned = re.compile(r"^(main|section-[0-9-]+)\.tex$")
    out = tmp_path / "out"
    replace_owned_files(out, {"main.tex": "old", "section-2.tex": "old"}, owned)

    def interrupted(staging, target):
        raise KeyboardInterrupt

    monkeypatch.setattr(files, "_swap_in", interrupted)
    with pytest.raises(KeyboardInterrupt):
        replace_owned_files(out, {"main.tex": "new", "section-2.tex": "new"}, owned)
    assert {p.read_text() for p in out.iterdir()} == {"old"}
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def test_derive_onto_a_read_only_directory_is_one_line(tmp_path, capsys):
    if os.geteuid() == 0:
        pytest.skip("root writes anywhere")
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    assert main(["derive", "--out", str(ro / "x")]) == 2
    assert "not writable" in capsys.readouterr().err


def test_stdout_on_a_full_device_is_one_line_and_nonzero():
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full")
    with open("/dev/full", "w") as full:
        out = subprocess.run([sys.executable, "-m", "symdecomp", "spectrum", "5"], stdout=full, stderr=subprocess.PIPE,
                             text=True, timeout=300, cwd=ROOT)
    assert out.returncode == 1
    assert out.stderr.strip().splitlines() == ["symdecomp: error: cannot write the output: No space left on device"]


def test_version(capsys):
    assert main(["--version"]) == 0
    assert re.fullmatch(r"symdecomp \d+\.\d+\.\d+\n", capsys.readouterr().out)


def test_help_documents_exit_codes_and_limits(capsys):
    assert main(["--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    for phrase in ("0 success", "2 bad input", "3 an optional component is missing", "130 interrupted", "digits <= 1000"):
        assert phrase in text


@pytest.fixture
def private_bridge(tmp_path, monkeypatch):
    """The bridge built into a private directory, and the loader's cache cleared."""
    import symdecomp.verify.opensubdiv as osd
    from symdecomp.verify.opensubdiv import build as osd_build

    if not osd_build.headers_present():
        pytest.skip("OpenSubdiv headers (libosd-dev) or g++ not installed")
    monkeypatch.setattr(osd_build, "BUILD_DIR", tmp_path)
    monkeypatch.setattr(osd_build, "LIBRARY", tmp_path / "libsymdecomp_osd.so")
    monkeypatch.setattr(osd_build, "STAMP", tmp_path / "libsymdecomp_osd.stamp")
    monkeypatch.setattr(osd, "_lib", None)
    return osd, osd_build


@pytest.mark.slow  # over 10 s: the default run stays under 10 minutes on 2 cores; CI runs it with the slow tests
def test_a_truncated_bridge_is_rebuilt(private_bridge):
    osd, osd_build = private_bridge
    library = osd_build.build()
    library.write_bytes(library.read_bytes()[:1000])  # loading this could crash the process (SIGBUS)
    assert not osd_build.is_current()
    osd.load_bridge()
    assert osd_build.is_current()
    assert library.stat().st_size > 1000


def test_a_bridge_that_returns_nothing_is_reported_with_the_fix(private_bridge, monkeypatch, tmp_path, capsys):
    osd, osd_build = private_bridge
    stub = tmp_path / "stub.cpp"
    stub.write_text(f'extern "C" {{ int symdecomp_osd_bridge_version() {{ return {osd_build.BRIDGE_VERSION}; }}\n'
                    "int symdecomp_osd_refine_ring(int, int, const int*, const double*, int, int, const int*, const int*,"
                    " int, double*, double*, char*, int) { return 0; } }\n")
    library = tmp_path / "stub.so"
    subprocess.run([osd_build.compiler(), "-shared", "-fPIC", str(stub), "-o", str(library)], check=True)
    monkeypatch.setattr(osd_build, "build", lambda force=False: library)  # a rebuild would not help
    with pytest.raises(osd.BridgeUnavailableError, match="self-test .*" + re.escape(osd_build.REBUILD_COMMAND)):
        osd.load_bridge()
    assert main(["oracle", "--n", "4", "--levels", "2"]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "self-test" in err[0]


def test_no_progress_bar_when_stderr_is_not_a_terminal(capsys):
    from symdecomp.cli.common import progress

    assert list(progress(range(5), 5, "work")) == [0, 1, 2, 3, 4]
    assert capsys.readouterr().err == ""

    class Terminal:
        text = ""

        def isatty(self):
            return True

        def write(self, s):
            Terminal.text += s

        def flush(self):
            pass

    import sys as _sys

    real, _sys.stderr = _sys.stderr, Terminal()
    try:
        assert list(progress(range(5), 5, "work")) == [0, 1, 2, 3, 4]
    finally:
        _sys.stderr = real
    assert Terminal.text.startswith("\rwork:   0%") and "5/5 [" in Terminal.text and "it/s]" in Terminal.text
