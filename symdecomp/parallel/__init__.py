"""The toolkit's one pool of worker processes: ``check``, ``c1`` and ``evaldata`` map their valences through it.

:func:`ordered_map` yields ``func(item, **shared)`` for every item, in the items' order, computed

* here (``jobs`` 1, a single item, or no ``fork`` on this platform);
* in a :class:`concurrent.futures.ProcessPoolExecutor` of forked workers (``executor="local"``):
  ``shared`` (a scheme, its closed forms) is set before the workers fork, so only the items and
  the results travel through pipes, and ``warm_up`` computes the first item here first, so that
  what it caches (the symbolic step) is inherited by every worker;
* on a Dask cluster (``executor="dask"``: a ``LocalCluster`` started for the run and closed
  after; ``"dask=ADDRESS"``: the scheduler at ``ADDRESS``, e.g. ``tcp://127.0.0.1:8786``, whose
  workers must have symdecomp installed). ``shared`` is sent to each worker once.

The guarantees of the local pool:

* it has ``pool_size(jobs, work)`` workers: never more than ``jobs``, the items or the CPUs;
* SIGTERM or SIGINT in this process (the command line turns them into exceptions) stops every
  worker at once with SIGKILL, whatever it is computing: no tracebacks, no processes left;
* if this process is killed outright (SIGKILL), its workers are killed within a fraction of a
  second. A watchdog thread inside a worker could not do it: python-flint keeps the GIL for the
  whole of a long computation (a characteristic polynomial takes seconds to minutes), so no
  other thread of the worker runs meanwhile. Instead a small reaper process (a fresh
  interpreter, nothing imported) leads a process group that the workers join; it polls its
  parent and kills the whole group when the parent is gone. The group also keeps a terminal's
  Ctrl-C away from the workers: only this process receives it.

:func:`run_killable` gives the whole command the same guarantee: the command line runs in a
forked child, in a reaper's group, and the first process only waits for it. SIGTERM or Ctrl-C
there asks the child to stop (SIGTERM: its cleanup runs, workers and temporary files); a child
still inside a native computation after :data:`GRACE_SECONDS` is killed (SIGKILL), and if the
first process is killed outright, its reaper does the same: SIGTERM (the child removes its
temporary files and stops its workers), then SIGKILL :data:`GRACE_SECONDS` later.

The Dask side (addresses checked, the peer asked whether it is a Dask scheduler, a bound on every
wait) is a module of its own; both are named in the module map of :mod:`symdecomp`.
"""

from __future__ import annotations

import itertools
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import suppress
from dataclasses import dataclass

from symdecomp.errors import InvalidInputError, InvalidTypeError
from symdecomp.validate import check_int

__all__ = ["Executor", "parse_executor", "pool_size", "ordered_map", "LOCAL", "run_killable", "GRACE_SECONDS"]

#: Seconds a command gets to stop by itself after SIGTERM or Ctrl-C (its workers, its temporary
#: files) before it is killed: a native computation (FLINT, Arb) returns to Python only when done.
GRACE_SECONDS = 3.0

#: Seconds between the reaper's looks at its parent.
REAPER_POLL = 0.2

#: The reaper: once its parent is gone it kills its group; with a grace period (argv[2] seconds) it first
#: asks with SIGTERM, so that a command whose program was killed still removes its temporary files.
_REAPER = (
    "import os, signal, sys, time\n"
    "signal.signal(signal.SIGINT, signal.SIG_IGN)\n"
    "signal.signal(signal.SIGTERM, signal.SIG_IGN)\n"
    "parent, grace = int(sys.argv[1]), float(sys.argv[2])\n"
    "while os.getppid() == parent:\n"
    f"    time.sleep({REAPER_POLL})\n"
    "def others():\n"  # a live process of this group other than this one (Linux: /proc; elsewhere: assume so)
    "    try:\n"
    "        names = [e for e in os.listdir('/proc') if e.isdigit() and int(e) != os.getpid()]\n"
    "    except OSError:\n"
    "        return True\n"
    "    for e in names:\n"
    "        try:\n"
    "            fields = open(f'/proc/{e}/stat').read().rsplit(')', 1)[1].split()\n"
    "        except (OSError, IndexError):\n"
    "            continue\n"
    "        if fields[0] not in 'ZX' and int(fields[2]) == os.getpid():\n"
    "            return True\n"
    "    return False\n"
    "if grace > 0:\n"
    "    os.killpg(0, signal.SIGTERM)\n"
    "    end = time.monotonic() + grace\n"
    "    while time.monotonic() < end and others():\n"
    "        time.sleep(0.05)\n"
    "os.killpg(0, signal.SIGKILL)\n"
)

_EXPECTED = "expected local, dask or dask=ADDRESS (a Dask scheduler such as tcp://127.0.0.1:8786)"


@dataclass(frozen=True)
class Executor:
    """Where :func:`ordered_map` runs: ``kind`` ``"local"`` or ``"dask"``; ``address`` a Dask scheduler (``None``:
    a ``LocalCluster`` for the run)."""

    kind: str = "local"
    address: str | None = None

    def __str__(self) -> str:
        return self.kind if self.address is None else f"{self.kind}={self.address}"


LOCAL = Executor()


def parse_executor(spec: str | Executor = "local", option: str | None = "executor") -> Executor:
    """``"local"``, ``"dask"`` or ``"dask=ADDRESS"`` as an :class:`Executor`; a Dask one only if Dask is installed.

    Raises :class:`~symdecomp.errors.InvalidInputError` naming ``option`` (the command line gives
    ``None`` and lets argparse name it).
    """
    if isinstance(spec, Executor):
        return spec
    prefix = f"{option}: " if option else ""
    if not isinstance(spec, str):
        raise InvalidTypeError(f"{prefix}{_EXPECTED}, got {type(spec).__name__}")
    shown = spec if len(spec) <= 60 else spec[:57] + "..."
    kind, eq, address = spec.partition("=")
    if kind == "local" and not eq:
        return LOCAL
    if kind != "dask" or (eq and not address):
        raise InvalidInputError(f"{prefix}{_EXPECTED}, got {shown!r}")
    try:
        import distributed  # noqa: F401 - only asking whether it is installed
    except ImportError:
        raise InvalidInputError(f"{prefix}{shown!r} needs the optional packages dask and distributed: "
                                "pip install 'symdecomp[dask]'") from None
    if eq:
        from symdecomp.parallel.cluster import parse_address

        address = parse_address(address, prefix)
    return Executor("dask", address or None)


def pool_size(jobs: int, work: int) -> int:
    """Worker processes for ``work`` items: never more than the work, the CPUs or ``jobs`` (at least 1)."""
    return max(1, min(jobs, work, os.cpu_count() or 1))


def ordered_map(func: Callable, items: Iterable, *, shared: dict | None = None, jobs: int = 1,
                executor: str | Executor = "local", warm_up: bool = False, cost: Callable | None = None) -> Iterator:
    """Yield ``func(item, **shared)`` for each of ``items``, in order, on at most ``jobs`` processes.

    ``func`` is a module-level function (workers find it by name); ``shared`` its keyword
    arguments common to all items; ``warm_up``: compute the first item in this process before
    the local workers fork (they inherit what it cached); ``cost(item)``: hand out the costliest items
    first (the results still come in order). An exception of ``func`` is raised here.
    """
    spec = parse_executor(executor)
    jobs = check_int(jobs, "jobs", minimum=1)
    items, shared = list(items), dict(shared or {})
    if warm_up and items and spec.kind == "local":
        yield func(items[0], **shared)
        items = items[1:]
    order = sorted(range(len(items)), key=lambda i: -cost(items[i])) if cost else list(range(len(items)))
    workers = pool_size(jobs, len(items))
    if spec.kind == "dask":
        from symdecomp.parallel.cluster import dask_map

        yield from dask_map(func, items, shared, spec, workers, order)
    elif workers > 1 and "fork" in _start_methods() and sys.executable:
        yield from _local_map(func, items, shared, workers, order)
    else:
        for item in items:
            yield func(item, **shared)


def _start_methods() -> list[str]:
    import multiprocessing

    return multiprocessing.get_all_start_methods()


#: What each running local pool computes, by token, set before its workers fork (so only items travel).
_JOBS: dict[int, tuple[Callable, dict]] = {}
_TOKENS = itertools.count()


def _call(token: int, item):
    func, shared = _JOBS[token]
    return func(item, **shared)


def _worker_init(parent: int, group: int) -> None:
    """In each forked worker: join the reaper's group, leave Ctrl-C and SIGTERM to the parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent stops the pool (no traceback per worker)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        os.setpgid(0, group)
    except OSError:  # the reaper is gone already: so is the parent, or it is stopping the pool
        os._exit(1)
    if os.getppid() != parent:  # the parent died before this worker joined the group
        os._exit(1)


def _local_map(func, items, shared, workers, order):
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    reaper = _start_reaper()
    token = next(_TOKENS)
    _JOBS[token] = (func, shared)
    pool = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork"),
                               initializer=_worker_init, initargs=(os.getpid(), reaper.pid))
    finished = False
    try:
        try:  # a worker that dies early breaks the pool while the work is still being submitted
            futures = [None] * len(items)
            for i in order:  # the workers fork at the first submit, with _JOBS[token] in place
                futures[i] = pool.submit(_call, token, items[i])
            for future in futures:
                yield _result(future, pool)
        except BrokenProcessPool:
            raise ChildProcessError("a worker process died (killed by the system: out of memory?); "
                                    "try a smaller --jobs or range") from None
        finished = True
    finally:
        if not finished:  # interrupted, an error, or the caller stopped early: kill the workers now
            _kill_group(reaper.pid)
        pool.shutdown(wait=True, cancel_futures=True)
        _kill_group(reaper.pid)
        reaper.wait()
        _JOBS.pop(token, None)


#: Seconds between looks at the workers while a result is awaited.
WORKER_POLL = 0.5


def _result(future, pool):
    """The future's result; a worker that has died is noticed here too, not only by the pool's own thread.

    The pool's management thread marks the pool broken when a worker dies; looking at the workers' exit codes
    while waiting makes that certain (a death it misses would otherwise leave this process waiting forever).
    """
    from concurrent.futures.process import BrokenProcessPool

    while True:
        try:
            return future.result(timeout=WORKER_POLL)
        except TimeoutError:
            workers = list((getattr(pool, "_processes", None) or {}).values())
            if any(p.exitcode not in (None, 0) for p in workers):
                raise BrokenProcessPool("a worker process died") from None


def _start_reaper(grace: float = 0.0) -> subprocess.Popen:
    """A reaper for this process: a fresh interpreter leading a new process group, which kills the
    group once this process is gone (processes join it with ``os.setpgid(0, reaper.pid)``); with a
    ``grace`` (seconds) it sends SIGTERM first and SIGKILL that much later."""
    return subprocess.Popen([sys.executable, "-I", "-S", "-c", _REAPER, str(os.getpid()), repr(float(grace))],
                            process_group=0,
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def run_killable(func: Callable[[], int]) -> int:
    """``func()`` (an exit code) computed in a forked child that this process can always stop.

    SIGTERM or SIGINT here sends SIGTERM to the child; if it has not ended :data:`GRACE_SECONDS`
    later (it is inside a native call, which Python signal handlers cannot interrupt), it is
    killed, and the exit code is 130. A child killed by anything else (the out-of-memory killer)
    gives exit code 1 with one line. Without ``fork``, ``func()`` runs here.
    """
    if "fork" not in _start_methods():
        return func()
    sys.stdout.flush()
    sys.stderr.flush()
    reaper = _start_reaper(GRACE_SECONDS)
    pid = os.fork()
    if pid == 0:  # the child: run the command in the reaper's group, then leave without the parent's cleanup
        code = 1
        try:
            try:
                os.setpgid(0, reaper.pid)
            except OSError as exc:  # the reaper is gone: the program is stopping
                print(f"symdecomp: error: cannot start the command ({exc.strerror or exc})", file=sys.stderr)
                raise
            code = func()
            sys.stdout.flush()
            sys.stderr.flush()
        finally:
            os._exit(code)
    return _supervise(pid, reaper)


def _supervise(pid: int, reaper: subprocess.Popen) -> int:
    asked: list[float] = []

    def stop(signum, frame):
        if not asked:
            asked.append(time.monotonic())
            with suppress(ProcessLookupError):
                os.kill(pid, signal.SIGTERM)

    previous = {s: signal.signal(s, stop) for s in (signal.SIGTERM, signal.SIGINT)}
    try:
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                break
            if asked and time.monotonic() - asked[0] > GRACE_SECONDS:
                _kill_group(reaper.pid)  # the child, stuck in a native computation, and the reaper
            time.sleep(0.02)
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        _kill_group(reaper.pid)
        reaper.wait()
    code = os.waitstatus_to_exitcode(status)
    if code >= 0:
        return code
    if asked:
        print("symdecomp: interrupted", file=sys.stderr)
        return 130
    print(f"symdecomp: error: the command was killed by {signal.Signals(-code).name} (out of memory?)", file=sys.stderr)
    return 1


def _kill_group(group: int) -> None:
    try:
        os.killpg(group, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
