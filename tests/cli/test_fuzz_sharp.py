"""Fuzzing ``[sharp]`` sections and the sharp options (issue 35): every input ends in bounded time with the right status.

Generated scheme files (``[sharp]`` weights built from pieces that are exact, undefined at some ``k``, transcendental,
free, malformed or hostile) and generated option text (``N``, ``--crease``, ``--sharpness``) go through the command
line in the process. Whatever the input, the run ends with exit status 0 (answered), 1 (partly or numerically
undecided, e.g. tangent masks that are not the tangent plane's) or 2 (bad input, one line on stderr), never an
internal error, within a time bound. The default examples are few and small; ``-m slow`` runs many more, wider.
"""

import itertools
import tempfile
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symdecomp.cli import main

FAST = settings(max_examples=25, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
WIDE = settings(max_examples=250, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))

#: Pieces of a weight: exact in Q(cos(pi/k)), undefined at some k, transcendental, free, malformed, hostile.
PIECES = ["1/8", "3/8", "0", "-1", "1/16", "k", "1/k", "cos(theta_k)", "sin(theta_k)", "cos(2*theta_k)", "cos(theta_k/3)",
          "cos(theta_k)**2", "1/(k-2)", "1/(k-3)", "1/(k-1)", "1/cos(theta_k)", "theta_k", "theta_k**2", "gamma", "pi",
          "cos(1)", "sqrt(2)", "cos(pi/k)", "cos(sqrt(2)*theta_k)", "k**k", "2**100", "1e3", "0.5", "", "x", "n",
          "__import__('os')", "log(k)", "nan", "oo", "zoo", "1/0", "1/(k-k)", "(", "k!", "I", "exp(theta_k)"]

#: Weights a file may well hold (exact at most k, some undefined at one k or free): drawn more often, so that runs get past
#: reading the file into the sharp routes.
LIKELY = ["1/16", "cos(theta_k)/4", "sin(theta_k)/8", "cos(2*theta_k)/8", "cos(theta_k)**2/4", "k/64", "1/(k+1)",
          "1/(k-2)", "1/(8*(k-3))", "gamma", "1/(4*k*(k-1))"]

piece = st.sampled_from(PIECES)
weight = st.one_of(st.sampled_from(LIKELY), st.sampled_from(LIKELY), piece,
                   st.builds(lambda a, op, b: f"({a}) {op} ({b})", piece, st.sampled_from("+-*/"), piece))
_COUNTER = itertools.count()
_FOLDER = Path(tempfile.mkdtemp(prefix="symdecomp-fuzz-sharp-"))

RULES = """name = "fuzz"
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
a = "3/(2*n**2)"
b = "1/(4*n**2)"
[sharp]
"""


@st.composite
def sharp_section(draw) -> str:
    """A scheme file: Catmull-Clark's rules with a generated ``[sharp]`` section."""
    lines = []
    if draw(st.integers(0, 3)):  # mostly BLZ's form, affine whatever the weight: the weight itself is what is tested
        near = draw(weight)
        lines += [f'near_edge_centre = "3/8 + ({near})"', f'near_edge_end = "3/8 - ({near})"']
    else:
        for key in draw(st.sets(st.sampled_from(["crease_centre", "crease_end", "crease_edge", "near_edge_centre",
                                                 "near_edge_end"]))):
            lines.append(f'{key} = "{draw(weight)}"')
    parameters = draw(st.sampled_from(["", "", 'parameters = ["gamma"]', 'parameters = ["x"]']))
    return RULES.format(parameters=parameters) + "\n".join(lines) + "\n"


def vertex_options(faces: int):
    kinds = st.one_of(st.just(["--boundary"]), st.just(["--corner"]), st.just(["--dart"]),
                      st.integers(1, max(1, faces - 1)).map(lambda k2: ["--crease", str(k2)]))
    return st.tuples(st.integers(1, faces), kinds)


def command(faces: int):
    """``spectrum``, ``masks`` or ``check --certify`` at a generated vertex with few faces."""
    def build(pair, which):
        k, kind = pair
        return {"spectrum": ["spectrum", str(k)], "masks": ["masks", str(k)],
                "check": ["check", "--certify", "--k", str(k)]}[which] + kind

    return st.builds(build, vertex_options(faces), st.sampled_from(["spectrum", "masks", "check"]))


def run_bounded(argv, capsys, seconds: float):
    start = time.monotonic()
    code = main(argv)
    elapsed = time.monotonic() - start
    err = capsys.readouterr().err.strip()
    assert code in (0, 1, 2), (argv, code, err)
    assert "internal error" not in err and "Traceback" not in err, (argv, err)
    if code == 2:
        assert err and "\n" not in err, (argv, err)  # one line naming the problem
    assert elapsed < seconds, (argv, elapsed)
    return code, err


def _file(text: str) -> str:
    path = _FOLDER / f"fuzz-{next(_COUNTER)}.toml"  # a new path each time: nothing cached by name answers for it
    path.write_text(text)
    return str(path)


@pytest.mark.slow
@FAST
@given(text=sharp_section(), argv=command(3))
def test_sharp_sections_end_with_one_line_or_an_answer(text, argv, capsys):
    run_bounded(argv + ["--scheme", _file(text)], capsys, 60)


@pytest.mark.slow
@WIDE
@given(text=sharp_section(), argv=command(6))
def test_sharp_sections_wide(text, argv, capsys):
    run_bounded(argv + ["--scheme", _file(text)], capsys, 120)


#: Option text a user might type: numbers in and out of range, and what is not a number.
NUMBER_TEXT = st.one_of(st.integers(-3, 5).map(str), st.sampled_from(["65", "1000", "99999999999999", "", " 3", "3 ", "٣", "5.0",
                                                                    "0x5", "1e3", "+4", "-0", "3:4", "abc", "∞"]))
SHARPNESS_TEXT = st.one_of(st.fractions(0, 12, max_denominator=7).map(str), st.sampled_from(
    ["inf", "oo", "-oo", "nan", "-1", "1e400", "9999999/1000000", "1/0", "abc", "10", "0", "1/3", "0.5", "1" + "0" * 400,
     "sqrt(2)", "pi", "", "--", "2**1000"]))


@st.composite
def option_line(draw, faces: int):
    argv = [draw(st.sampled_from(["spectrum", "masks"])), draw(NUMBER_TEXT if draw(st.booleans()) else
                                                                st.integers(1, faces).map(str))]
    for option in draw(st.sets(st.sampled_from(["--boundary", "--corner", "--crease", "--dart", "--sharpness"]), max_size=3)):
        argv.append(option)
        if option == "--crease":
            argv.append(draw(st.one_of(st.integers(1, faces).map(str), NUMBER_TEXT)))
        elif option == "--sharpness":
            argv.append(draw(SHARPNESS_TEXT))
    return argv


@FAST
@given(argv=option_line(3))
def test_sharp_options_end_with_one_line_or_an_answer(argv, capsys):
    run_bounded(argv, capsys, 60)


@pytest.mark.slow
@WIDE
@given(argv=option_line(5))
def test_sharp_options_wide(argv, capsys):
    run_bounded(argv, capsys, 120)


@settings(max_examples=150, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
@given(near=weight, k=st.integers(1, 12))
def test_sharp_rules_api_raise_only_the_package_errors(near, k):
    """The API: rules built from any weight text are refused with the package's error or give exact finite weights at
    every sector, never sympy's or FLINT's errors, never ``zoo`` or a free symbol."""
    import sympy as sp

    from symdecomp.errors import SymdecompError
    from symdecomp.schemes.sharp import SharpRules

    try:
        rules = SharpRules("3/4", "1/8", "1/2", f"3/8 + ({near})", f"3/8 - ({near})")
        values = rules.near_edge(sp.pi / k, k)
    except SymdecompError:
        return
    for value in values:
        assert value.is_finite is not False and not value.free_symbols, (near, k, value)
        assert not value.has(sp.zoo, sp.nan), (near, k, value)
