"""Issue 35 (hardening, third round), the executor, design, report, files-and-signals findings: each one
ends as one clear line with the right exit status (or the right file state), where it used to hang, crash,
print an internal error or leave a file behind.

The network peers are local socket servers on 127.0.0.1 in a thread of this process, each stopped with
its test: one that accepts and stays silent, one that sends a bogus frame, one that speaks HTTP.
"""

import os
import socket
import stat
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from symdecomp.cli import Interrupted, main
from symdecomp.errors import InvalidInputError, InvalidSchemeError

ROOT = Path(__file__).resolve().parents[2]
DESIGN = ["design", "--n", "5", "--normal", "0,0,1"]


def _one_line(err: str) -> str:
    assert err.count("\n") == 1 and err.startswith("symdecomp"), err
    assert "internal error" not in err and "Traceback" not in err, err
    return err


# --- the table: one row per signature, each an internal error, a hang or a wrong exit 0 on the old code ------------


@pytest.fixture
def peer():
    """``peer(mode)``: the port of a local server that, to every connection, says nothing (``silent``), sends a
    bogus frame (``junk``: a length, then bytes that are no Dask message) or an HTTP answer (``http``)."""
    servers = []

    def start(mode: str) -> int:
        server = socket.create_server(("127.0.0.1", 0))
        server.settimeout(0.1)
        stop, held = threading.Event(), []

        def serve():
            while not stop.is_set():
                try:
                    conn, _ = server.accept()
                except OSError:
                    continue
                held.append(conn)
                if mode == "junk":
                    conn.sendall(struct.pack("Q", 24) + b"\xff" * 24)
                elif mode == "http":
                    conn.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")

        thread = threading.Thread(target=serve, daemon=True)
        thread.start()
        servers.append((server, stop, thread, held))
        return server.getsockname()[1]

    yield start
    for server, stop, thread, held in servers:
        stop.set()
        thread.join(5)
        for conn in held:
            conn.close()
        server.close()


@pytest.fixture
def quick_exchanges(monkeypatch):
    """A scheduler's answers awaited 1 s instead of 10 (the bound itself is what is tested)."""
    pytest.importorskip("distributed")
    from symdecomp.parallel import cluster

    monkeypatch.setattr(cluster, "EXCHANGE_SECONDS", 1.0)


@pytest.mark.parametrize(("mode", "problem"), [
    ("silent", "not a Dask scheduler (it accepted the connection and sent nothing more for 1 s)"),  # finding 8: hung
    ("junk", "not a Dask scheduler (its greeting is not Dask's)"),  # finding 14: struct.error
    ("http", "not a Dask scheduler (it sent b'HTTP/1.1' where a scheduler announces its greeting's length)"),  # "out of memory"
])
def test_a_peer_that_is_not_a_dask_scheduler_is_one_line_exit_2(peer, quick_exchanges, mode, problem, capsys):
    port = peer(mode)
    start = time.monotonic()
    assert main(["check", "--n", "5", "--jobs", "2", "--executor", f"dask=tcp://127.0.0.1:{port}"]) == 2
    assert time.monotonic() - start < 30  # bounded: the old code waited forever on the silent peer
    err = _one_line(capsys.readouterr().err)
    assert err == f"symdecomp: error: executor dask=tcp://127.0.0.1:{port}: {problem}\n"


@pytest.mark.parametrize(("address", "problem"), [
    ("tls://127.0.0.1:8786", "tls:// needs the client certificates of Dask's configuration"),  # TypeError: TLS expects ssl_context
    ("a..b:8786", "the scheduler's host has an empty label ('a..b')"),  # UnicodeError: idna
    (".example.org:8786", "the scheduler's host has an empty label"),
    ("x" * 64 + ".org:8786", "is not 1 to 63 letters, digits and inner hyphens"),  # UnicodeError: idna, label too long
    ("a." * 127 + "org:8786", "the scheduler's host is longer than 253 characters"),
    ("300.1.1.1:8786", "'300.1.1.1' is not an IPv4 address"),
    ("[::g]:8786", "in brackets must be an IPv6 address"),
    ("udp://127.0.0.1:8786", "must be [tcp://|tls://]HOST:PORT, not udp://"),
])
def test_a_bad_scheduler_address_is_one_line_before_any_connection(address, problem, capsys):
    pytest.importorskip("distributed")
    with pytest.raises(InvalidInputError, match="executor") as caught:
        from symdecomp.parallel import parse_executor

        parse_executor(f"dask={address}")
    assert problem in str(caught.value)
    assert main(["check", "--n", "3", f"--executor=dask={address}"]) == 2
    err = _one_line(capsys.readouterr().err)
    assert "argument --executor" in err and problem in err


@pytest.mark.parametrize(("option", "value", "problem"), [
    ("--elliptic", "1e308", "elliptic must be at most 1e+06 in magnitude, got 1e308"),  # OverflowError
    ("--hyperbolic", "1e308", "hyperbolic must be at most 1e+06 in magnitude, got 1e308"),  # OverflowError
    ("--angle", "1e9999", "angle must be at most 1e+06 in magnitude, got 1e9999"),  # NaN, or exit 0
    ("--position", "1e308,0,0", "position must have coordinates of at most 1e+06 in magnitude, got 1e308,0,0"),  # normal 0 0 0
    ("--tangent", "1e300,1,0", "tangent: its direction needs integers beyond 1e+15 (give it with at most 15 significant digits)"),
])
def test_design_amounts_beyond_their_bounds_are_one_line_and_no_file(tmp_path, option, value, problem, capsys):
    out = tmp_path / "net.obj"
    assert main([*DESIGN, f"{option}={value}", "--out", str(out)]) == 2
    assert _one_line(capsys.readouterr().err) == f"symdecomp: error: {problem}\n"
    assert list(tmp_path.iterdir()) == []


def test_design_mesh_near_the_largest_double_is_one_line(tmp_path, capsys):
    net = tmp_path / "net.obj"
    assert main([*DESIGN, "--elliptic", "1/2", "--out", str(net)]) == 0
    capsys.readouterr()
    lines = [" ".join(["v", *(repr(float(x) * 1e307) for x in line.split()[1:])]) if line.startswith("v ") else line
             for line in net.read_text().splitlines()]
    huge = tmp_path / "huge.obj"
    huge.write_text("\n".join(lines) + "\n")
    out = tmp_path / "out.obj"
    assert main(["design", "--mesh", str(huge), "--vertex", "0", "--normal", "0,0,1", "--out", str(out)]) == 2  # TypeError
    err = _one_line(capsys.readouterr().err)
    assert "magnitude" in err or "1e+12" in err
    assert not out.exists()


def test_design_position_at_the_bound_keeps_its_exact_normal(tmp_path, capsys):
    """At the bound the net's limit is still measured: a normal parallel to --normal, not ``0 0 0`` (``--exact``: the
    exact net, not its doubles)."""
    import json

    assert main([*DESIGN, "--position", "1e6,0,-1e6", "--elliptic=-1e6", "--exact", "--json", "--out", str(tmp_path / "net.obj")]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["position_exact"] == ["1000000", "0", "-1000000"] and data["normal_exact"] is True
    assert abs(data["normal"][2] - 1) < 1e-9 and abs(data["elliptic"] + 1e6) < 1e-3


def test_a_report_on_free_parameters_is_refused_before_any_section():
    from symdecomp.output.report import build_report, check_values, claims_section, scheme_section, shape_section, spectrum_section
    from symdecomp.schemes.files import load_scheme

    scheme = load_scheme(ROOT / "tests" / "corpus" / "free-vertex.toml")
    with pytest.raises(InvalidSchemeError, match=r"free parameters \['alpha', 'beta'\]; a report needs their values "
                       r"for the spectrum: write them into the scheme file"):
        build_report(scheme, [3], sections=(claims_section, spectrum_section))  # old: after the claims' minutes
    assert check_values(scheme, (scheme_section, shape_section)) is None  # these say "not applicable" themselves


@pytest.mark.slow
def test_a_report_onto_a_fifo_without_a_reader_is_refused_before_the_work(tmp_path):
    fifo = tmp_path / "report.html"
    os.mkfifo(fifo)
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "symdecomp", "report", "catmull-clark", "--n", "3", "--out", str(fifo)],
                          capture_output=True, text=True, timeout=60, cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.returncode == 2 and time.monotonic() - start < 30  # the old code computed, then blocked in open()
    assert _one_line(done.stderr) == (f"symdecomp: error: --out {fifo}: a FIFO that no process reads (waited 2 s); "
                                      "start its reader first\n")
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode) and sorted(p.name for p in tmp_path.iterdir()) == ["report.html"]


def test_a_report_tex_on_a_full_disk_leaves_no_figure(tmp_path, monkeypatch, capsys):
    from symdecomp.cli import files
    from symdecomp.output import report, report_tex

    monkeypatch.setattr(report, "build_report", lambda *a, **k: None)  # the sections are not what is tested
    monkeypatch.setattr(report_tex, "report_latex", lambda r: ("\\includegraphics{height-field.pdf}",
                                                               {f"{name}.pdf": b"%PDF-1.4\n" for name in report.FIGURES}))
    real, calls = files.tempfile.mkstemp, []

    def full_disk(*args, **kwargs):  # the figures fit, the document does not
        calls.append(kwargs.get("prefix"))
        if len(calls) > len(report.FIGURES):
            raise OSError(28, "No space left on device")
        return real(*args, **kwargs)

    monkeypatch.setattr(files.tempfile, "mkstemp", full_disk)
    assert main(["report", "catmull-clark", "--n", "3", "--out", str(tmp_path / "r.tex")]) == 1
    assert _one_line(capsys.readouterr().err).endswith("cannot write (No space left on device)\n")
    assert list(tmp_path.iterdir()) == []  # the old code left r-characteristic-map.pdf and the others


def test_an_interruption_swallowed_by_a_finalizer_still_ends_the_command(tmp_path, monkeypatch, capsys):
    """SIGTERM's exception raised inside a ``__del__`` is lost there ("Exception ignored ... Interrupted") and the
    command ran on until the grace kill: it is raised again, and the command ends at once with exit 130."""
    from symdecomp.cli import design_cmd

    class Finalized:
        def __del__(self):
            raise Interrupted  # where SIGTERM's handler raises when the signal arrives during a finalizer

    def run(args):
        Finalized()  # garbage at once
        end = time.monotonic() + 10
        while time.monotonic() < end:
            time.sleep(0.01)
        return 0

    monkeypatch.setattr(design_cmd, "run", run)
    start = time.monotonic()
    assert main([*DESIGN, "--out", str(tmp_path / "x.obj")]) == 130
    assert time.monotonic() - start < 5
    assert capsys.readouterr().err == "symdecomp: interrupted\n"


def test_the_bridge_is_built_in_a_user_cache_not_in_the_package(tmp_path, monkeypatch):
    from symdecomp.verify.opensubdiv import build

    monkeypatch.delenv(build.BUILD_DIR_VARIABLE, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert build.build_dir() == tmp_path / "symdecomp" / f"opensubdiv-bridge-{build.BRIDGE_VERSION}"  # was HERE/_build
    monkeypatch.setenv(build.BUILD_DIR_VARIABLE, str(tmp_path / "elsewhere"))
    assert build.build_dir() == tmp_path / "elsewhere"


def test_a_dask_scheduler_without_workers_is_one_line_not_a_hang(quick_exchanges, capsys):
    """A scheduler that answers but has no worker would hold the submitted valences forever."""
    import distributed

    with distributed.LocalCluster(n_workers=0, processes=False, protocol="tcp", dashboard_address=":0") as cluster:
        address = cluster.scheduler_address
        assert main(["check", "--n", "5", "--executor", f"dask={address}"]) == 2
    err = _one_line(capsys.readouterr().err)
    assert err == f"symdecomp: error: executor dask={address}: the Dask scheduler has no workers (waited 1 s)\n"
