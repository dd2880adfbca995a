"""Stam's eigen-data file: numbers rounded once, streamed output, the estimate checked before work."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from decimal import ROUND_HALF_EVEN, Decimal, localcontext
from fractions import Fraction

import flint
import numpy as np
import pytest

from symdecomp import validate
from symdecomp.algebra.rounding import round_ball_decimal
from symdecomp.analysis.eigendata import (
    certified_eigendata,
    eigendata_cost,
    patch_eigendata,
    rounded_eigendata,
)
from symdecomp.analysis.eigendata_sharpen import _round_all
from symdecomp.cli import main
from symdecomp.cli.files import write_output_file as write_atomic
from symdecomp.errors import ResourceLimitError
from symdecomp.output.evaldata import binary_bytes, binary_chunks
from symdecomp.schemes.loop import loop
from symdecomp.schemes.scheme import catmull_clark

CC, LOOP = catmull_clark(), loop()
REFERENCE_BITS = 3000  # far sharper than any working precision of the file


def _exact_mid(x: flint.arb) -> Fraction:
    m, e = (int(t) for t in x.mid().man_exp())
    return Fraction(m) * Fraction(2) ** e


def _reference_balls(scheme, n: int) -> dict:
    """The file's numbers as 3000-bit balls, in the file's element order (column-major tables)."""
    d = patch_eigendata(scheme, n, REFERENCE_BITS)
    order = lambda m: [m[i, j] for j in range(m.ncols()) for i in range(m.nrows())]  # noqa: E731
    out = {"values": list(d.values), "inverse": order(d.inverse), "phi": [order(t) for t in d.phi]}
    out["jordan"] = [g for *_, g in d.jordan]
    return out


def _pairs(entry: dict, ref: dict):
    yield from zip(entry["values"], ref["values"])
    yield from zip(entry["inverse"], ref["inverse"])
    for texts, balls in zip(entry["phi"], ref["phi"]):
        yield from zip(texts, balls)
    yield from zip([j["value"] for j in entry.get("jordan", [])], ref["jordan"])


@pytest.mark.parametrize("scheme, nmax", [(CC, 6), (LOOP, 7)], ids=["catmull-clark", "loop"])
def test_json_17_digits_read_back_as_the_correctly_rounded_double(tmp_path, scheme, nmax):
    """Every number of a 17-digit file is the correctly rounded float64 of the exact value, in its shortest
    form: compared with CPython's correctly rounded Fraction -> float of a 3000-bit midpoint (issue 24:
    17 digits of the ball's midpoint, read back, were one ulp off for about 5 % of the numbers)."""
    out = tmp_path / "data.json"
    assert main(["evaldata", "--scheme", scheme.name, "--n", f"3:{nmax}", "--format", "json", "--digits", "17", "--out", str(out)]) == 0
    doc = json.loads(out.read_text())
    assert doc["digits"] == 17 and [v["n"] for v in doc["valences"]] == list(range(3, nmax + 1))
    count = 0
    for entry in doc["valences"]:
        for text, ball in _pairs(entry, _reference_balls(scheme, entry["n"])):
            assert float(text) == float(_exact_mid(ball)), (entry["n"], text)
            assert repr(float(text)) == text  # the shortest text that reads back as that double
            count += 1
    assert count > 2000


def test_json_more_digits_are_the_exact_value_rounded_once(tmp_path):
    """``--digits 30``: each number is the exact value correctly rounded (ties to even) to 30 digits."""
    out = tmp_path / "loop30.json"
    assert main(["evaldata", "--scheme", "loop", "--n", "3:5", "--format", "json", "--digits", "30", "--out", str(out)]) == 0
    doc = json.loads(out.read_text())
    assert doc["digits"] == 30
    zeros = 0
    with localcontext() as ctx:
        ctx.prec = 1000
        for entry in doc["valences"]:
            for text, ball in _pairs(entry, _reference_balls(LOOP, entry["n"])):
                if ball.contains(0):
                    assert text == "0" and abs(ball) < flint.arb(2) ** -1075
                    zeros += 1
                    continue
                q = _exact_mid(ball)
                exact = Decimal(q.numerator) / Decimal(q.denominator)
                want = exact.quantize(Decimal(1).scaleb(exact.adjusted() - 29), rounding=ROUND_HALF_EVEN)
                assert Decimal(text) == want and len(text.split("e")[0].replace("-", "").replace(".", "")) == 30, text
    assert zeros > 0


def test_round_ball_decimal_rounds_once_and_refuses_what_it_cannot_decide():
    with flint.ctx.workprec(300):
        third = flint.arb(1) / 3
        assert round_ball_decimal(-third * 2, 25) == "-6.666666666666666666666667e-01"
        assert round_ball_decimal(flint.arb(1) - flint.arb(2) ** -100, 20) == "1.0000000000000000000e+00"  # carry into a new decade
        assert round_ball_decimal(flint.arb("0 +/- 1e-400"), 20) == "0"  # a ball within 2^-1075 of 0
    assert round_ball_decimal(flint.arb("1 +/- 1e-5"), 20) is None
    assert round_ball_decimal(flint.arb("0 +/- 1e-300"), 20) is None  # cannot be told from 1e-301
    # exact balls round exactly, ties to even: 0.0625 -> 6.2e-02, 0.375 -> 3.8e-01, 0.625 -> 6.2e-01
    assert round_ball_decimal(flint.arb(1) / 16, 2) == "6.2e-02" and round_ball_decimal(flint.arb(3) / 8, 2) == "3.8e-01"
    assert round_ball_decimal(flint.arb(5) / 8, 2) == "6.2e-01" and round_ball_decimal(flint.arb(7) / 8, 2) == "8.8e-01"
    # a ball whose 2-digit rounding lies on a tie cannot be decided: 0.0625 +- tiny straddles it
    with flint.ctx.workprec(200):
        third = flint.arb(1) / 3
        assert round_ball_decimal(flint.arb(1) / 16 + third - third, 2) is None


def test_loop_zeros_are_taken_from_1200_bits_column_by_column():
    """Loop's exact zeros (symmetries) no longer make a whole 1200-bit recomputation: the eigenvectors whose
    entries do not round are taken from one, and the data stay an eigen-decomposition (V^-1 V = I)."""
    for n in (5, 8):
        data, rounded = certified_eigendata(LOOP, n)
        assert data.prec == 256
        whole = _round_all(patch_eigendata(LOOP, n, 1200))  # every entry at 1200 bits, rounded
        assert np.array_equal(rounded.inverse, whole.inverse) and np.array_equal(rounded.phi, whole.phi)
        assert np.array_equal(rounded.values, whole.values)
        with flint.ctx.workprec(256):
            product = data.inverse * data.vectors
        k = data.size
        assert all(product[i, j].contains(int(i == j)) for i in range(k) for j in range(k))
        assert max(float(product[i, j].rad()) for i in range(k) for j in range(k)) < 1e-60


def test_streamed_file_equals_whole_and_a_failure_leaves_the_old_file(tmp_path):
    rounded = [r for _, r in rounded_eigendata(CC, range(3, 6))]
    path = tmp_path / "cc.dat"
    assert write_atomic(path, binary_chunks(iter(rounded), 5)) == len(binary_bytes(rounded))
    assert path.read_bytes() == binary_bytes(rounded)

    def broken():
        yield from rounded[:2]
        raise RuntimeError("stopped half way")

    with pytest.raises(RuntimeError):
        write_atomic(path, binary_chunks(broken(), 5))
    assert path.read_bytes() == binary_bytes(rounded) and os.listdir(tmp_path) == ["cc.dat"]
    with pytest.raises(Exception, match="3..Nmax"):  # a valence missing at the end
        write_atomic(tmp_path / "short.dat", binary_chunks(iter(rounded), 6))
    assert os.listdir(tmp_path) == ["cc.dat"]


def test_the_estimate_refuses_before_any_work(tmp_path, capsys):
    """Issue 25: ``--n 3:1000`` ran into 10 GB and ended in 'BrokenProcessPool'; now one line, exit 2, at once."""
    out = tmp_path / "big.dat"
    assert main(["evaldata", "--n", "3:1000", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "3..1000" in err and "GiB of memory" in err and "limit" in err
    assert not out.exists()
    memory, seconds = eigendata_cost(CC, 1000, 2)
    assert memory > 16 << 30 and seconds > 3600  # beyond the limit on every machine (at most 16 GiB)


def test_the_time_estimate_counts_the_valences_as_the_file_path_costs_them():
    """The direct path's cost per valence is about linear in K up to N = 128 and cubic beyond (Catmull-Clark): the
    estimate is a sum over the valences of ``a K + b K^2 + c K^3``, split over the processes, and the dense path at
    ``D > 17`` digits costs more than the float64 file at every size."""
    for scheme in (CC, LOOP):
        one = [eigendata_cost(scheme, n, 1)[1] for n in range(3, 131)]
        steps = [b - a for a, b in zip(one, one[1:])]
        assert all(x < y for x, y in zip(steps, steps[1:]))  # each valence costs more than the one before
        assert eigendata_cost(scheme, 128, 2)[1] == pytest.approx(one[125] / 2)
        assert eigendata_cost(scheme, 128, 1, digits=20)[1] > one[125]


def test_the_estimate_counts_the_json_text_waiting_in_the_main_process():
    """With workers, the finished valences wait in the main process as the file's pieces: JSON text takes more than the
    8 bytes of a float64 a number, and the estimate with ``text`` counts at least what the text takes."""
    from symdecomp.output.evaldata import json_valence_text

    arrays = [d for _, d in rounded_eigendata(LOOP, range(3, 21))]
    numbers = sum(d.values.size + d.inverse.size + d.phi.size for d in arrays)
    text = sum(len(json_valence_text(d).text) for d in arrays)
    extra = eigendata_cost(LOOP, 20, 2, text=True)[0] - eigendata_cost(LOOP, 20, 2)[0]
    assert 8 * numbers < text <= 8 * numbers + extra
    assert eigendata_cost(LOOP, 20, 1, text=True) == eigendata_cost(LOOP, 20, 1)  # one process: nothing waits


def test_the_estimate_follows_the_limit_in_the_api_and_the_command(tmp_path, monkeypatch, capsys):
    memory, _ = eigendata_cost(LOOP, 10, 1)
    monkeypatch.setattr(validate, "MEMORY_LIMIT", memory - 1)
    with pytest.raises(ResourceLimitError, match="valences 3..10"):
        next(rounded_eigendata(LOOP, range(3, 11), 1))
    assert main(["evaldata", "--scheme", "loop", "--n", "3:10", "--format", "json", "--jobs", "1", "--out", str(tmp_path / "x.json")]) == 2
    assert "memory" in capsys.readouterr().err
    monkeypatch.setattr(validate, "MEMORY_LIMIT", memory)
    assert main(["evaldata", "--scheme", "loop", "--n", "3:10", "--format", "json", "--jobs", "1", "--out", str(tmp_path / "x.json")]) == 0


def test_digits_below_a_double_are_refused(tmp_path, capsys):
    assert main(["evaldata", "--n", "3:4", "--format", "json", "--digits", "16", "--out", str(tmp_path / "x.json")]) == 2
    err = capsys.readouterr().err
    assert "--digits" in err and ">= 17" in err and len(err.strip().splitlines()) == 1


@pytest.mark.slow
def test_the_memory_estimate_is_not_below_the_measured_peak(tmp_path):
    """The estimate bounds what a run takes (peak resident memory of the command, measured) without being wild.

    The command is started by a small launcher that reads its children's rusage: a child's
    ``ru_maxrss`` includes the resident memory of the process that spawned it (``fork``/``vfork``
    and ``exec`` keep the high-water mark), and the test process is large."""
    out = tmp_path / "loop.json"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.getcwd(), os.environ.get("PYTHONPATH", "")]))
    launcher = ("import resource, subprocess, sys; p = subprocess.run(sys.argv[1:], capture_output=True, text=True); "
                "print(p.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss); print(p.stdout)")
    argv = [sys.executable, "-m", "symdecomp", "evaldata", "--scheme", "loop", "--n", "3:60", "--format", "json", "--jobs", "1",
            "--out", str(out), "--json"]
    first, rest = subprocess.run([sys.executable, "-c", launcher, *argv], env=env, capture_output=True, text=True).stdout.split("\n", 1)
    code, peak = (int(x) for x in first.split())
    assert code == 0
    estimate = json.loads(rest)["estimate"]["megabytes"] << 20
    assert estimate == pytest.approx(eigendata_cost(LOOP, 60, 1)[0], abs=1 << 20)
    assert peak * 1024 <= estimate <= 4 * peak * 1024
