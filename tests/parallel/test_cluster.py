"""The Dask side of the pool (``symdecomp.parallel.cluster``): addresses parsed exactly, the peer's greeting read
within a bound. The peers are on 127.0.0.1 only: a Dask scheduler in this process, and raw sockets."""

import socket
import struct
import threading
import time

import pytest

from symdecomp.errors import InvalidInputError

distributed = pytest.importorskip("distributed")

from symdecomp.parallel.cluster import GREETING_LIMIT, parse_address, probe_scheduler  # noqa: E402 - after the skip


@pytest.mark.parametrize(("address", "full"), [
    ("127.0.0.1:8786", "tcp://127.0.0.1:8786"),
    ("tcp://scheduler.example.org:08786", "tcp://scheduler.example.org:8786"),
    ("[::1]:1", "tcp://[::1]:1"),
    ("a-b.c-d:65535", "tcp://a-b.c-d:65535"),
    ("x" * 63 + ".org:1", "tcp://" + "x" * 63 + ".org:1"),
])
def test_good_addresses_are_written_in_full(address, full):
    assert parse_address(address) == full


@pytest.mark.parametrize(("address", "problem"), [
    ("127.0.0.1:0", "a port 1..65535"),
    ("127.0.0.1:65536", "a port 1..65535"),
    ("127.0.0.1", "a port 1..65535"),
    (":8786", "host is empty"),
    ("-a.org:1", "label '-a' is not 1 to 63"),
    ("a-.org:1", "label 'a-' is not 1 to 63"),
    ("ex ample.org:1", "label 'ex ample' is not 1 to 63"),
    ("ünï.org:1", "label 'ünï' is not 1 to 63"),  # idna is never asked
    ("1.2.3:1", "'1.2.3' is not an IPv4 address"),
    ("[127.0.0.1:1", "in brackets must be an IPv6 address"),
])
def test_bad_addresses_name_the_part_at_fault(address, problem):
    with pytest.raises(InvalidInputError, match="the scheduler's") as caught:
        parse_address(address, "executor: ")
    assert problem in str(caught.value) and str(caught.value).startswith("executor: ")


def test_a_dask_schedulers_greeting_is_read():
    with distributed.LocalCluster(n_workers=0, processes=False, protocol="tcp", dashboard_address=":0") as cluster:
        greeting = probe_scheduler(parse_address(cluster.scheduler_address), "here", timeout=10)
    assert {"compression", "python"} <= set(greeting) and tuple(greeting["python"])[:2] >= (3, 8)


def _one_shot(payload: bytes | None):
    """A server on a free loopback port sending ``payload`` to its first connection (``None``: nothing) and then
    holding it open for 3 s; its address."""
    server = socket.create_server(("127.0.0.1", 0))
    server.settimeout(5)

    def serve():
        with server:
            try:
                conn, _ = server.accept()
            except OSError:
                return
            with conn:
                if payload is not None:
                    conn.sendall(payload)
                time.sleep(3)

    threading.Thread(target=serve, daemon=True).start()
    return f"tcp://127.0.0.1:{server.getsockname()[1]}"


@pytest.mark.parametrize(("payload", "problem"), [
    (None, "sent nothing more for 0.5 s"),
    (b"\x00" * 8, "where a scheduler announces its greeting's length"),
    (struct.pack("Q", GREETING_LIMIT + 1), "where a scheduler announces its greeting's length"),
    (struct.pack("Q", 40) + b"\x00" * 10, "sent nothing more for 0.5 s"),  # a length, then too little
    (struct.pack("Q", 16) + struct.pack("Q", 1) + struct.pack("Q", 0), "its greeting is not Dask's"),
    (struct.pack("Q", 24) + b"\xff" * 24, "its greeting is not Dask's"),
])
def test_a_peer_that_does_not_greet_as_dask_does_is_refused_in_time(payload, problem):
    start = time.monotonic()
    with pytest.raises(InvalidInputError, match="not a Dask scheduler") as caught:
        probe_scheduler(_one_shot(payload), "executor x", timeout=0.5)
    assert problem in str(caught.value) and time.monotonic() - start < 2.5


def test_a_closed_port_is_unreachable():
    with socket.create_server(("127.0.0.1", 0)) as server:
        port = server.getsockname()[1]
    with pytest.raises(InvalidInputError, match="cannot reach the scheduler"):
        probe_scheduler(f"tcp://127.0.0.1:{port}", "executor x", timeout=2)
