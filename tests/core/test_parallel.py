"""The toolkit's one worker pool (symdecomp.parallel): its size, its order, and what becomes of its workers
when the command is interrupted or killed; the Dask executor gives the local rows."""

import json
import multiprocessing.process
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from symdecomp import catmull_clark
from symdecomp.analysis.eigendata import rounded_eigendata
from symdecomp.cli import files as output_files
from symdecomp.cli import main
from symdecomp.cli.check_cmd import check_valences
from symdecomp.cli.progress import PLAIN_LINE
from symdecomp.errors import InvalidInputError, InvalidValenceError, SymdecompError
from symdecomp.parallel import GRACE_SECONDS, Executor, ordered_map, parse_executor, pool_size, run_killable

ROOT = Path(__file__).resolve().parents[2]
CPUS = os.cpu_count() or 1
needs_two_cpus = pytest.mark.skipif(CPUS < 2, reason="a pool needs two CPUs")
linux = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")


def _slow_first(item, delay):
    """The first item finishes last, so the order of the results is the pool's doing."""
    time.sleep(delay if item == 0 else 0)
    return item * item, os.getpid()


def _refuse(item):
    raise InvalidValenceError(f"valence {item}: refused in the worker")


def _die(item):
    os._exit(3)


def _shift(item, offset):
    return item + offset


def test_pool_is_never_larger_than_the_work_the_jobs_or_the_cpus():
    assert pool_size(256, 1) == 1
    assert pool_size(256, 100) == min(100, CPUS)
    assert pool_size(1, 100) == 1
    assert pool_size(3, 0) == 1
    for jobs in (0, "2", 2.0, True):
        with pytest.raises(SymdecompError, match="jobs"):
            list(ordered_map(_shift, [1], shared={"offset": 0}, jobs=jobs))


@needs_two_cpus
def test_results_come_in_order_from_no_more_processes_than_the_pool():
    rows = list(ordered_map(_slow_first, range(6), shared={"delay": 1.0}, jobs=64))
    assert [square for square, _ in rows] == [k * k for k in range(6)]
    workers = {pid for _, pid in rows}
    assert os.getpid() not in workers and 1 <= len(workers) <= min(64, 6, CPUS)


@needs_two_cpus
@pytest.mark.timeout(120)
def test_a_worker_error_is_raised_here_and_a_dead_worker_is_one_clear_error():
    with pytest.raises(InvalidValenceError, match="valence 4: refused in the worker"):
        list(ordered_map(_refuse, [4, 5], jobs=2))
    with pytest.raises(ChildProcessError, match="a worker process died"):
        list(ordered_map(_die, [4, 5], jobs=2))


@pytest.mark.timeout(60)
def test_a_dead_worker_is_noticed_from_its_exit_code_while_a_result_is_awaited():
    """A death the pool's own thread does not report (the run hung once in a fresh clone) still ends the wait."""
    from concurrent.futures import Future
    from concurrent.futures.process import BrokenProcessPool
    from types import SimpleNamespace

    from symdecomp import parallel

    never = Future()  # its result never comes
    alive = SimpleNamespace(_processes={1: SimpleNamespace(exitcode=None)})
    dead = SimpleNamespace(_processes={1: SimpleNamespace(exitcode=None), 2: SimpleNamespace(exitcode=3)})
    with pytest.raises(BrokenProcessPool):
        parallel._result(never, dead)
    done = Future()
    done.set_result(7)
    assert parallel._result(done, alive) == 7


@needs_two_cpus
def test_evaldata_starts_no_more_workers_than_the_cpus(monkeypatch):
    """`evaldata --jobs 256` forked 257 processes; the pool is capped by the CPUs and the valences."""
    started = []
    start = multiprocessing.process.BaseProcess.start

    def counting(self):
        started.append(self)
        return start(self)

    monkeypatch.setattr(multiprocessing.process.BaseProcess, "start", counting)
    rows = list(rounded_eigendata(catmull_clark(), [3, 4, 5], jobs=64))
    assert [r.n for _, r in rows] == [3, 4, 5]
    assert 1 <= len(started) <= min(3, CPUS)


def test_an_interrupted_evaldata_write_leaves_no_temporary_file(tmp_path, monkeypatch):
    def interrupted(fd):
        raise KeyboardInterrupt  # what SIGTERM or Ctrl-C raise in the command

    monkeypatch.setattr(output_files.os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        output_files.write_output_file(tmp_path / "cc.dat", b"x" * 100_000)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("spec, problem", [
    ("threads", "expected local, dask or dask=ADDRESS"),
    ("dask=", "expected local, dask or dask=ADDRESS"),
    ("local=x", "expected local, dask or dask=ADDRESS"),
    ("dask=tcp://127.0.0.1", "HOST:PORT"),
    ("dask=tcp://127.0.0.1:99999", "HOST:PORT"),
    ("dask=http://127.0.0.1:8786", "HOST:PORT"),
    ("dask=host:8786;rm -rf", "HOST:PORT"),
])
def test_a_bad_executor_is_one_line_naming_the_option(spec, problem, capsys):
    with pytest.raises(InvalidInputError, match="executor"):
        parse_executor(spec)
    assert main(["check", "--n", "3", "--certify", "--executor", spec]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--executor" in err and problem in err


def test_without_dask_the_dask_executor_is_one_line_exit_2(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed now fails
    for command in (["check", "--n", "3:4", "--certify"], ["c1", "--n", "3"], ["evaldata", "--n", "3:4", "--out", "x.dat"]):
        assert main([*command, "--executor", "dask"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--executor" in err and "symdecomp[dask]" in err
    assert parse_executor("local") == Executor("local")


def test_c1_over_a_range_gives_the_same_rows_on_two_workers(capsys):
    assert main(["c1", "--n", "3:6", "--json", "--jobs", "1"]) == 0
    one = json.loads(capsys.readouterr().out)["rows"]
    assert main(["c1", "--n", "3:6", "--json", "--jobs", "2"]) == 0
    two = json.loads(capsys.readouterr().out)["rows"]
    assert [r["n"] for r in two] == [3, 4, 5, 6] and two == one


@pytest.fixture(scope="module")
def dask_scheduler():
    """A Dask scheduler with one worker of threads inside this process (quick to start); its address."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, protocol="tcp", dashboard_address=":0",
                                  silence_logs=False) as cluster:
        yield cluster.scheduler_address


def test_a_dask_scheduler_at_an_address_gives_the_local_results(dask_scheduler):
    executor = parse_executor(f"dask={dask_scheduler}")
    assert executor.kind == "dask" and executor.address == dask_scheduler
    assert list(ordered_map(_shift, range(7), shared={"offset": 10}, executor=executor)) == list(range(10, 17))
    scheme = catmull_clark()
    here = [r.as_json() for r in check_valences(scheme, range(3, 7), certified=True, show_progress=False)]
    there = [r.as_json() for r in check_valences(scheme, range(3, 7), certified=True, show_progress=False, executor=executor)]
    assert [r["n"] for r in there] == [3, 4, 5, 6] and there == here



def _charpoly_at(weights, n):
    from symdecomp.schemes.full_matrix import characteristic_polynomial

    alpha, beta = weights
    return str(characteristic_polynomial(catmull_clark(alpha, beta), n))


def test_a_grid_of_tuning_weights_on_a_dask_scheduler_gives_the_local_results(dask_scheduler):
    """A sweep over vertex weights (alpha, beta), not valences, goes through the same map (issue 24, item 5)."""
    from fractions import Fraction

    n = 5
    grid = [(Fraction(a, 100), Fraction(b, 100)) for a in (4, 5, 7) for b in (1, 2)] + [(Fraction(3, 2 * n * n), Fraction(1, 4 * n * n))]
    here = list(ordered_map(_charpoly_at, grid, shared={"n": n}, jobs=2))
    there = list(ordered_map(_charpoly_at, grid, shared={"n": n}, executor=parse_executor(f"dask={dask_scheduler}")))
    assert there == here and len(set(here)) == len(grid)  # every weight pair gives its own polynomial
    # the last pair is Catmull-Clark's own vertex rule at n = 5: its polynomial is the standard scheme's
    assert here[-1] == _charpoly_at((None, None), n)


@pytest.mark.slow
def test_check_certify_on_a_dask_local_cluster_gives_the_local_rows():
    pytest.importorskip("distributed")
    rows = {}
    for executor in ("local", "dask"):
        out = subprocess.run([sys.executable, "-m", "symdecomp", "check", "--n", "3:12", "--certify", "--json", "--jobs", "2",
                              "--executor", executor], capture_output=True, text=True, cwd=ROOT, timeout=300)
        assert out.returncode == 0 and all(PLAIN_LINE.fullmatch(line) for line in out.stderr.splitlines()), out.stderr
        rows[executor] = json.loads(out.stdout)["rows"]
    assert [r["n"] for r in rows["dask"]] == list(range(3, 13)) and rows["dask"] == rows["local"]


@pytest.mark.slow
def test_an_unreachable_scheduler_is_one_line_exit_2(capsys):
    pytest.importorskip("distributed")
    assert main(["check", "--n", "3:4", "--certify", "--executor", "dask=tcp://127.0.0.1:1"]) == 2
    captured = capsys.readouterr()
    assert captured.err.count("\n") == 1 and "cannot reach the scheduler" in captured.err
    assert "agree" not in captured.out  # nothing was computed before the connection failed


# --- signals: run the command in its own process group (as a shell does), watch its processes in /proc ---


def _descendants(pid: int) -> list[int]:
    children = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = Path(f"/proc/{entry}/stat").read_text()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                children.append(int(entry))
    return children + [d for c in children for d in _descendants(c)]


def _alive(pid: int) -> bool:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] not in "ZX"
    except OSError:
        return False


def _start_with_pool(argv, tmp_path, processes: int = 3):
    """The command, once its pool is up: two workers and the reaper (local), or a cluster's processes (Dask);
    above them, the program's own reaper and the child that runs the command (``run_killable``)."""
    processes += 2
    proc = subprocess.Popen([sys.executable, "-m", "symdecomp", *argv], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(ROOT)}, process_group=0)
    deadline = time.monotonic() + 120
    while len(_descendants(proc.pid)) < processes:
        assert proc.poll() is None, proc.stderr.read()
        if time.monotonic() > deadline:
            proc.kill()
            pytest.skip("the pool did not start in time")
        time.sleep(0.2)
    time.sleep(1.5)  # the workers are inside a valence now
    return proc, _descendants(proc.pid)


def _gone_within(pids, seconds: float) -> list[int]:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and any(_alive(p) for p in pids):
        time.sleep(0.05)
    return [p for p in pids if _alive(p)]


COMMANDS = {
    "check": ["check", "--n", "3:400", "--certify", "--jobs", "2"],
    "evaldata": ["evaldata", "--n", "3:400", "--out", "cc.dat", "--jobs", "256"],
    "c1": ["c1", "--n", "3:2000", "--jobs", "2"],
    "check on dask": ["check", "--n", "3:400", "--certify", "--jobs", "2", "--executor", "dask"],
}


def _interrupt(command, signum, tmp_path):
    if "dask" in command:
        pytest.importorskip("distributed")
    proc, processes = _start_with_pool(COMMANDS[command], tmp_path)
    try:
        sent = time.monotonic()
        if signum == signal.SIGINT:
            os.killpg(proc.pid, signum)  # Ctrl-C: the terminal signals the whole foreground group
        else:
            proc.send_signal(signum)
        assert proc.wait(timeout=30) == 130
        took = time.monotonic() - sent
        assert proc.stderr.read() == "symdecomp: interrupted\n"
        assert took < 10, f"stopped after {took:.1f} s"
        assert _gone_within(processes, 5) == []
        assert [p.name for p in tmp_path.iterdir()] == []  # no output file, no temporary file
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


@pytest.mark.slow
@linux
@needs_two_cpus
@pytest.mark.parametrize("command, signum", [("evaldata", signal.SIGTERM), ("check", signal.SIGINT)])
def test_an_interrupted_command_stops_at_once_with_its_workers(command, signum, tmp_path):
    _interrupt(command, signum, tmp_path)


@linux
@needs_two_cpus
@pytest.mark.slow
@pytest.mark.parametrize("command, signum", [("evaldata", signal.SIGINT), ("check", signal.SIGTERM),
                                             ("c1", signal.SIGTERM), ("c1", signal.SIGINT),
                                             ("check on dask", signal.SIGTERM), ("check on dask", signal.SIGINT)])
def test_every_pooled_command_stops_at_once_with_its_workers(command, signum, tmp_path):
    _interrupt(command, signum, tmp_path)


@linux
@needs_two_cpus
@pytest.mark.parametrize("command", ["evaldata", pytest.param("check", marks=pytest.mark.slow)])
def test_the_workers_of_a_killed_command_die_within_a_second_or_two(command, tmp_path):
    """SIGKILL leaves the parent no cleanup: the reaper sees it gone and kills the workers, even inside a flint call."""
    proc, processes = _start_with_pool(COMMANDS[command], tmp_path)
    proc.kill()
    proc.wait()
    assert _gone_within(processes, 3) == []


@pytest.mark.slow
@linux
@needs_two_cpus
def test_a_killed_program_leaves_no_temporary_file(tmp_path):
    """SIGKILL of the program while evaldata streams its file: the reaper asks the command to stop (SIGTERM), so it
    removes its temporary file and its workers; it used to kill it at once and leave the ``.cc.dat.*.tmp`` file."""
    proc, processes = _start_with_pool(COMMANDS["evaldata"], tmp_path)
    deadline = time.monotonic() + 60
    while not [p for p in tmp_path.iterdir() if p.suffix == ".tmp"] and time.monotonic() < deadline:
        time.sleep(0.1)
    assert [p.suffix for p in tmp_path.iterdir()] == [".tmp"]  # the file is being written
    proc.kill()
    proc.wait()
    assert _gone_within(processes, GRACE_SECONDS + 2) == []
    assert list(tmp_path.iterdir()) == []


def _killable_command(tmp_path):
    """``charpoly 300``: one FLINT call of many seconds, which no Python signal handler interrupts."""
    proc = subprocess.Popen([sys.executable, "-m", "symdecomp", "charpoly", "300"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(ROOT)})
    deadline = time.monotonic() + 120  # a loaded machine starts Python slowly: wait for the command's process and its reaper
    while len(_descendants(proc.pid)) < 2:
        assert proc.poll() is None, proc.stderr.read()
        if time.monotonic() > deadline:
            proc.kill()
            pytest.skip("the command did not start in time")
        time.sleep(0.2)
    time.sleep(3)  # inside the native characteristic polynomial now
    assert proc.poll() is None, proc.stderr.read()
    return proc, _descendants(proc.pid)


@linux
@pytest.mark.slow
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_native_computation_is_stopped_within_the_grace_period(signum, tmp_path):
    """Issue 25: SIGTERM waited for FLINT to return (minutes); the program now kills the command's process."""
    proc, processes = _killable_command(tmp_path)
    sent = time.monotonic()
    proc.send_signal(signum)
    assert proc.wait(timeout=30) == 130
    assert time.monotonic() - sent < GRACE_SECONDS + 2
    assert proc.stderr.read() == "symdecomp: interrupted\n"
    assert _gone_within(processes, 2) == []


@linux
@pytest.mark.slow
def test_killing_the_program_kills_the_command(tmp_path):
    proc, processes = _killable_command(tmp_path)
    proc.kill()
    proc.wait()
    # its reaper and the command's process: asked with SIGTERM, killed GRACE_SECONDS later (inside FLINT)
    assert len(processes) == 2 and _gone_within(processes, GRACE_SECONDS + 2) == []


def test_run_killable_returns_the_exit_code_and_names_a_killing_signal(capsys):
    assert run_killable(lambda: 3) == 3
    assert run_killable(lambda: os.kill(os.getpid(), signal.SIGKILL)) == 1
    assert "killed by SIGKILL" in capsys.readouterr().err
