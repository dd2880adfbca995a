"""The pool on a Dask cluster: scheduler addresses parsed and checked, the peer asked first, a bound on every wait.

``--executor dask=ADDRESS`` names a peer this program does not control, so nothing is taken on trust:

* :func:`parse_address` reads ``[tcp://|tls://]HOST:PORT`` before anything connects: a host is an IPv4
  address, an IPv6 address in brackets or a DNS name (labels of 1 to 63 letters, digits and inner hyphens,
  253 characters at most); ``tls://`` needs the certificates of Dask's configuration
  (``distributed.comm.tls``).
* :func:`probe_scheduler` connects with its own socket and reads the greeting a Dask scheduler sends first
  (an 8-byte length, then a msgpack dict with ``compression``, ``python`` and ``pickle-protocol``): a peer
  that accepts and stays silent, sends junk or speaks HTTP is "not a Dask scheduler" within
  :data:`EXCHANGE_SECONDS`, before Dask's client would wait forever or read a length of exbibytes.
* the client connects with that timeout, waits at most as long for a worker, and while it waits for a
  result it checks every :data:`EXCHANGE_SECONDS` that the scheduler is still there and has workers.

A bad address, an unreachable peer or one that is not a Dask scheduler is
:class:`~symdecomp.errors.InvalidInputError` (bad input: exit code 2 on the command line); a scheduler
lost during the work is :class:`ConnectionError` (exit code 1).
"""

from __future__ import annotations

import ipaddress
import re
import signal
import socket
import struct
import threading
import time
from contextlib import contextmanager, suppress

from symdecomp.errors import InvalidInputError

__all__ = ["EXCHANGE_SECONDS", "GREETING_LIMIT", "parse_address", "probe_scheduler", "dask_map"]

#: Seconds for each exchange with a scheduler: to connect, to greet, to find a worker, between signs of life.
EXCHANGE_SECONDS = 10.0

#: Bytes a scheduler's greeting may take (it takes about 60).
GREETING_LIMIT = 1 << 16

_FORM = "[tcp://|tls://]HOST:PORT"
_LABEL = re.compile(r"[A-Za-z0-9](?:[A-Za-z0-9-]{0,61}[A-Za-z0-9])?", re.ASCII)
_SILENT = 60  # above logging.CRITICAL (50): nothing passes


def parse_address(address: str, prefix: str = "") -> str:
    """``address`` (``[tcp://|tls://]HOST:PORT``) checked and written in full (``tcp://`` by default).

    ``prefix`` starts each error message (the option's name). Raises
    :class:`~symdecomp.errors.InvalidInputError` with the part at fault.
    """
    shown = address if len(address) <= 60 else address[:57] + "..."
    scheme, sep, rest = address.partition("://")
    if not sep:
        scheme, rest = "tcp", address
    if scheme not in ("tcp", "tls"):
        raise InvalidInputError(f"{prefix}{shown!r}: the scheduler's address must be {_FORM}, not {scheme[:20]}://")
    host, colon, port = rest.rpartition(":")
    if not colon or not re.fullmatch(r"[0-9]{1,5}", port, re.ASCII) or not 0 < int(port) < 65536:
        raise InvalidInputError(f"{prefix}{shown!r}: the scheduler's address must be {_FORM} with a port 1..65535")
    problem = _host_problem(host)
    if problem:
        raise InvalidInputError(f"{prefix}{shown!r}: the scheduler's host {problem}")
    if scheme == "tls":
        _tls_context(f"{prefix}{shown!r}")
    return f"{scheme}://{host}:{int(port)}"


def _host_problem(host: str) -> str | None:
    """What is wrong with ``host`` (None: nothing)."""
    if host.startswith("["):
        try:
            ipaddress.IPv6Address(host[1:-1] if host.endswith("]") else "?")
        except ValueError:
            return "in brackets must be an IPv6 address"
        return None
    if not host:
        return "is empty"
    if len(host) > 253:
        return "is longer than 253 characters"
    labels = host.split(".")
    for label in labels:
        if not _LABEL.fullmatch(label):
            return (f"has an empty label ({host[:40]!r})" if not label else
                    f"label {label[:20]!r} is not 1 to 63 letters, digits and inner hyphens")
    if all(label.isdigit() for label in labels):
        try:
            ipaddress.IPv4Address(host)
        except ValueError:
            return f"{host!r} is not an IPv4 address"
    return None


def _tls_context(label: str):
    """The client's TLS context from Dask's configuration; one line if it names no certificates."""
    from distributed.security import Security

    context = Security().get_connection_args("client").get("ssl_context")
    if context is None:
        raise InvalidInputError(f"{label}: tls:// needs the client certificates of Dask's configuration "
                                "(distributed.comm.tls.ca-file, .client.cert, .client.key); none are set")
    return context


def _not_a_scheduler(label: str, what: str) -> InvalidInputError:
    return InvalidInputError(f"{label}: not a Dask scheduler ({what})")


def _read(sock: socket.socket, size: int, deadline: float, label: str, timeout: float) -> bytes:
    data = b""
    while len(data) < size:
        sock.settimeout(max(0.0, deadline - time.monotonic()) or 1e-3)
        try:
            chunk = sock.recv(size - len(data))
        except TimeoutError:
            raise _not_a_scheduler(label, f"it accepted the connection and sent nothing more for {timeout:g} s") from None
        except OSError as exc:
            raise _not_a_scheduler(label, f"the connection failed: {exc.strerror or exc}") from None
        if not chunk:
            raise _not_a_scheduler(label, "it closed the connection without greeting")
        data += chunk
    return data


def probe_scheduler(address: str, label: str, timeout: float = EXCHANGE_SECONDS) -> dict:
    """The greeting of the Dask scheduler at ``address`` (as :func:`parse_address` returns it), within ``timeout`` s.

    Raises :class:`~symdecomp.errors.InvalidInputError` starting with ``label``: unreachable, or not a Dask scheduler.
    """
    scheme, _, rest = address.partition("://")
    host, _, port = rest.rpartition(":")
    deadline = time.monotonic() + timeout
    try:
        sock = socket.create_connection((host.strip("[]"), int(port)), timeout=timeout)
    except (OSError, UnicodeError) as exc:
        raise InvalidInputError(f"{label}: cannot reach the scheduler ({getattr(exc, 'strerror', None) or exc})") from None
    with sock:
        if scheme == "tls":
            try:
                sock = _tls_context(label).wrap_socket(sock, server_hostname=host.strip("[]"))
            except OSError as exc:
                raise InvalidInputError(f"{label}: the TLS handshake failed ({exc.strerror or exc})") from None
        head = _read(sock, 8, deadline, label, timeout)
        (size,) = struct.unpack("Q", head)
        if not 16 <= size <= GREETING_LIMIT:
            raise _not_a_scheduler(label, f"it sent {head!r} where a scheduler announces its greeting's length")
        body = _read(sock, size, deadline, label, timeout)
    return _greeting(body, label)


def _greeting(body: bytes, label: str) -> dict:
    from distributed.protocol.core import loads
    from distributed.protocol.utils import unpack_frames

    try:
        message = loads(unpack_frames(body), deserialize=False)
    except Exception:  # noqa: BLE001 - whatever the decoder makes of junk, the answer is the same
        message = None
    if not isinstance(message, dict) or not {"compression", "python"} <= set(message):
        raise _not_a_scheduler(label, "its greeting is not Dask's")
    return message


def _dask_call(func, shared, item):
    return func(item, **shared)


def dask_map(func, items, shared, spec, workers, order):
    """``func(item, **shared)`` for ``items`` on the Dask cluster of ``spec`` (an executor), in the items' order."""
    with _quiet_logs("distributed", "asyncio", "tornado"):  # a cluster closed early logs its lost tasks
        yield from _dask_run(func, items, shared, spec, workers, order)


@contextmanager
def _quiet_logs(*names):
    """Silence these loggers, CRITICAL included (a closing scheduler logs its lost comms as CRITICAL).

    They are restored when the work ends normally; an interrupted run leaves them silent, since the
    scheduler's threads may still log while the interpreter stops.
    """
    import logging

    loggers = [logging.getLogger(name) for name in names]
    levels = [logger.level for logger in loggers]
    for logger in loggers:
        logger.setLevel(_SILENT)
    yield
    for logger, level in zip(loggers, levels):
        logger.setLevel(level)


def _dask_run(func, items, shared, spec, workers, order):
    opened = []  # the cluster and the client, closed in reverse order whatever happens
    futures = []
    try:
        with _signals_held():
            client = _dask_client(spec, workers, opened)
        if not items:
            return
        [ref] = client.scatter([shared], broadcast=True, hash=False, timeout=EXCHANGE_SECONDS)
        futures = [None] * len(items)
        for i in order:
            futures[i] = client.submit(_dask_call, func, ref, items[i], pure=False)
        for future in futures:
            yield _result(client, future, spec)
    finally:
        if opened and futures:
            with suppress(Exception):
                opened[-1].cancel([f for f in futures if f is not None])
        for thing in reversed(opened):
            with suppress(Exception):
                thing.close(timeout=EXCHANGE_SECONDS)


def _result(client, future, spec):
    """The future's result, checking every :data:`EXCHANGE_SECONDS` that the scheduler is there and has workers."""
    from concurrent.futures import CancelledError

    idle_since = None
    while True:
        try:
            return future.result(timeout=EXCHANGE_SECONDS)
        except TimeoutError:
            pass
        except CancelledError:
            raise ConnectionError(f"executor {spec}: lost the Dask scheduler during the work") from None
        if client.status != "running":
            raise ConnectionError(f"executor {spec}: lost the Dask scheduler during the work ({client.status})")
        if client.scheduler_info().get("workers"):
            idle_since = None
        elif idle_since is None:
            idle_since = time.monotonic()
        elif time.monotonic() - idle_since > EXCHANGE_SECONDS:
            raise ConnectionError(f"executor {spec}: the Dask scheduler has had no workers for {EXCHANGE_SECONDS:g} s")


def _dask_client(spec, workers: int, opened: list):
    """A connected ``distributed.Client`` (appended to ``opened``, after the ``LocalCluster`` started for it, if any)."""
    from distributed import Client, LocalCluster

    if spec.address is None:
        # ":0": any free port for its HTTP server (8787, the default, may be another cluster's)
        opened.append(LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0",
                                   silence_logs=_SILENT))
        opened.append(Client(opened[-1]))
        return opened[-1]
    label = f"executor {spec}"
    probe_scheduler(spec.address, label, timeout=EXCHANGE_SECONDS)
    try:
        opened.append(Client(spec.address, timeout=EXCHANGE_SECONDS))
    except (OSError, TimeoutError) as exc:
        raise InvalidInputError(f"{label}: cannot reach the scheduler ({' '.join(str(exc).split())})") from None
    try:
        opened[-1].wait_for_workers(1, timeout=EXCHANGE_SECONDS)
    except TimeoutError:
        raise InvalidInputError(f"{label}: the Dask scheduler has no workers (waited {EXCHANGE_SECONDS:g} s)") from None
    return opened[-1]


@contextmanager
def _signals_held():
    """Hold SIGINT and SIGTERM while Dask starts its processes, then deliver them (so that what started is closed).

    SIGINT is blocked: the processes spawned meanwhile inherit the mask, so a terminal's Ctrl-C
    reaches only this process, which closes the cluster. SIGTERM is only noted (those processes
    must stay stoppable by their nanny's SIGTERM) and sent again afterwards.
    """
    import os
    from multiprocessing import resource_tracker

    resource_tracker.ensure_running()  # now: started later, from Dask's thread, it would unblock SIGINT there
    held, swapped = [], threading.current_thread() is threading.main_thread()
    if swapped:
        previous = signal.signal(signal.SIGTERM, lambda signum, frame: held.append(signum))
    mask = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT}) if hasattr(signal, "pthread_sigmask") else None
    try:
        yield
    finally:
        if swapped:
            signal.signal(signal.SIGTERM, previous)
        if mask is not None:
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)  # a Ctrl-C meanwhile is raised here
        if held:
            os.kill(os.getpid(), signal.SIGTERM)
