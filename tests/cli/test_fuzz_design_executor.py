"""Fuzzed design amounts and executor addresses (issue 35): whatever the text, one line and exit status 0 or 2,
never an internal error, no file left behind by a refusal, within a bounded time.

Fast by default (a few dozen derandomized examples each); wide under ``-m slow``. No address is ever
connected to: the addresses are only parsed, and the command line runs only with those the parser refuses.
"""

import string
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symdecomp.cli import main
from symdecomp.errors import InvalidInputError

FAST = settings(max_examples=25, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
WIDE = settings(max_examples=400, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))

#: Seconds one fuzzed run may take (a refusal takes milliseconds; a design of valence 5 about a second).
BOUND = 60

_DIGITS = st.text("0123456789", min_size=1, max_size=6)
_NUMBER = st.one_of(
    st.builds(lambda m, e: f"{m}e{e}", st.sampled_from(["1", "-1", "9.99", "0.5", "-3"]), st.integers(-9999, 9999)),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(-(10**400), 10**400).map(str),
    st.builds(lambda p, q: f"{p}/{q}", st.integers(-(10**20), 10**20), st.integers(-5, 10**20)),
    st.sampled_from(["pi", "pi/6", "-pi", "2**1000", "10**(10**3)", "nan", "inf", "-inf", "1/0", "sqrt(2)", "I", "oo",
                     "", " ", "1e", "--1", "0x10", "1_000", "(", "pi**40", "exp(1000)", "1" * 5000]),
    st.text(string.printable, max_size=30),
)


def _design(tmp_path, capsys, option: str, value: str) -> None:
    out = tmp_path / "net.obj"
    start = time.monotonic()
    code = main(["design", "--n", "5", "--normal", "0,0,1", f"{option}={value}", "--out", str(out)])
    assert time.monotonic() - start < BOUND
    err = capsys.readouterr().err
    assert code in (0, 2), (value, err)
    if code == 2:
        assert err.count("\n") == 1 and err.startswith("symdecomp"), (value, err)
        assert not out.exists() and list(tmp_path.iterdir()) == []  # a refusal leaves nothing
    assert "internal error" not in err and "Traceback" not in err and "Warning" not in err, (value, err)
    for path in tmp_path.iterdir():
        path.unlink()


@pytest.mark.slow
@pytest.mark.parametrize("option", ["--elliptic", "--hyperbolic", "--angle"])
@FAST
@given(value=_NUMBER)
def test_fuzzed_design_amounts(tmp_path, capsys, option, value):
    _design(tmp_path, capsys, option, value)


@pytest.mark.slow
@pytest.mark.parametrize("option", ["--elliptic", "--hyperbolic", "--angle"])
@WIDE
@given(value=_NUMBER)
def test_fuzzed_design_amounts_wide(tmp_path, capsys, option, value):
    _design(tmp_path, capsys, option, value)


@FAST
@given(value=st.lists(_NUMBER, min_size=1, max_size=4).map(",".join))
def test_fuzzed_design_positions(tmp_path, capsys, value):
    _design(tmp_path, capsys, "--position", value)


_LABEL = st.one_of(st.text(string.ascii_letters + string.digits + "-", max_size=70),
                   st.text(max_size=8), st.just(""), _DIGITS)
_HOST = st.one_of(st.lists(_LABEL, min_size=1, max_size=6).map(".".join),
                  st.builds(lambda h: f"[{h}]", st.text("0123456789abcdefABCDEFg:.", max_size=45)),
                  st.sampled_from(["localhost", "127.0.0.1", "::1", "[::1]", "a" * 300, "ex ample.org", "ünï.org"]))
_ADDRESS = st.builds(lambda scheme, host, port: f"{scheme}{host}:{port}",
                     st.sampled_from(["", "tcp://", "tls://", "udp://", "inproc://", "tcp:/", "://"]),
                     _HOST, st.one_of(st.integers(-5, 70000).map(str), _DIGITS, st.text(max_size=6)))


def _executor(capsys, address: str) -> None:
    from symdecomp.parallel import parse_executor

    try:
        executor = parse_executor(f"dask={address}")
    except InvalidInputError as exc:
        assert "\n" not in str(exc) and str(exc).startswith("executor: ")
        start = time.monotonic()
        assert main(["check", "--n", "3", f"--executor=dask={address}"]) == 2
        assert time.monotonic() - start < BOUND
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "argument --executor" in err and "internal error" not in err, err
        return
    scheme, _, rest = executor.address.partition("://")  # accepted: written in full, never connected to here
    assert scheme in ("tcp", "tls") and 0 < int(rest.rpartition(":")[2]) < 65536


@pytest.mark.slow
@FAST
@given(address=_ADDRESS)
def test_fuzzed_executor_addresses(capsys, address):
    pytest.importorskip("distributed")
    _executor(capsys, address)


@pytest.mark.slow
@WIDE
@given(address=st.one_of(_ADDRESS, st.text(max_size=80)))
def test_fuzzed_executor_addresses_wide(capsys, address):
    pytest.importorskip("distributed")
    _executor(capsys, address)
