"""Expression bombs: weights that would exhaust the machine are refused by the budget before anything is computed.

The table holds inputs whose cost explodes (nested powers, radical and function towers, huge numbers, deep nesting,
long sums, other number syntaxes, functions outside the fields the toolkit computes in). In-process every one is
refused by the parser with the bound it exceeds; the slow test runs each through the command line, inside a scheme
file, under a memory limit (``ulimit -v``) and a timeout, and sees exit code 2 and one line.
"""

import os
import resource
import subprocess
import sys
import time
from pathlib import Path

import flint
import pytest
import sympy as sp
from sympy import Rational as R

from symdecomp import Scheme, Stencil, VertexRule, catmull_clark, closed_form_spectrum, limit_masks_at, tune
from symdecomp.claims.guards import BudgetExceeded, time_budget
from symdecomp.cli import main
from symdecomp.errors import InvalidExpressionError, InvalidSchemeError
from symdecomp.expressions import BUDGET, MAX_NODES, exact_value, parse_expression
from symdecomp.schemes import full_matrix
from symdecomp.schemes.files import scheme_from_text
from symdecomp.symbols import n as N

ROOT = Path(__file__).resolve().parents[2]


def _tower(function: str, inner: str, depth: int) -> str:
    for _ in range(depth):
        inner = f"{function}({inner})"
    return inner


def _continued_fraction(depth: int) -> str:
    text = "n"
    for _ in range(depth):
        text = f"1/(1+{text})"
    return text


#: (name, weight text, a word of the refusal).
BOMBS = [
    ("power tower", "1/((((n**64)**64)**64)**64)", "degree"),
    ("power of a power", "(n**64)**2", "degree"),
    ("product of powers", "n**40*n**40", "degree"),
    ("powers of binomials", "1/((n+1)**64*(n+2)**64)", "degree"),
    ("sum of reciprocals", "+".join(f"1/(n+{k})" for k in range(1, 80)), "degree"),
    ("number tower", "((2**64)**64)", "bits"),
    ("huge denominator", "1/(10**60)**64", "bits"),
    ("huge numerator power", "(9**60)**60/n", "bits"),
    ("exponent beyond the bound", "n**65", "exponent"),
    ("exponent digits", "2**(10**99)", "exponent"),
    ("symbolic exponent", "2**n", "exponents must be"),
    ("cube root", "n**(1/3)", "exponents must be"),
    ("integer of 101 digits", "1/" + "9" * 101, "digits"),
    ("radical tower", _tower("sqrt", "2", 40) + "/n**2", "nested"),
    ("short radical tower", "sqrt(sqrt(sqrt(n)))", "nested"),
    ("mixed tower", "sqrt(1 + sqrt(2 + cos(2*pi/n)))", "nested"),
    ("cosine tower", _tower("cos", "1", 45), "rational multiples of pi"),
    ("cosine of 1", "cos(1)/n**2", "rational multiples of pi"),
    ("cosine of a parameter-free transcendental", "sin(pi*pi/n)", "rational multiples of pi"),
    ("large field", "cos(pi/(97*n))", "denominator over pi"),
    ("field growing with n squared", "cos(pi/n**2)", "denominator d or d.n"),
    ("deep parentheses", _continued_fraction(60), "nested deeper"),
    ("long sum", "+".join(["n"] * 600), "longer than"),
    ("long sum within the length", "+".join(["1"] * 420), "operations"),
    ("octal", "0o7/8", "decimal"),
    ("hexadecimal", "0x3/8", "decimal"),
    ("binary", "0b11/8", "decimal"),
]


def test_the_table_has_twenty_bombs_and_the_budget_a_reason_for_each_bound():
    assert len(BOMBS) >= 20
    assert all(bound > 0 and len(reason) > 20 for bound, reason in BUDGET.values())


@pytest.mark.parametrize(("name", "text", "word"), BOMBS, ids=[b[0] for b in BOMBS])
def test_each_bomb_is_refused_by_the_parser_quickly(name, text, word):
    start = time.process_time()
    with pytest.raises(InvalidExpressionError, match=word):
        parse_expression(text, {"n": N}, argument="weight")
    assert time.process_time() - start < 2


@pytest.mark.parametrize("text", ["3/(2*n**2)", "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n", "1/n**64", "1/(n+1)**64",
                                  "sqrt(2 + cos(2*pi/n))/n", "cos(pi*(n - 2)/(3*n))", "+".join(["1/16"] * 100)])
def test_weights_within_the_budget_are_read(text):
    value = parse_expression(text, {"n": N})
    assert value.free_symbols <= {N}
    assert value.subs(N, 7).is_real


def test_api_expressions_meet_the_same_budget():
    for value, word in [(1 / N**4096, "exponent"), (sp.Integer(2) ** 10000, "bits"), (2**10000, "bits"),
                        (sp.cos(1) / N, "rational multiples of pi"), (sp.Add(*sp.symbols(f"x:{MAX_NODES}")), "operations"),
                        (sp.sqrt(1 + sp.sqrt(1 + sp.sqrt(N))), "nested"), (N ** sp.Rational(1, 8), "exponents must be")]:
        with pytest.raises(InvalidExpressionError, match=word):
            exact_value(value, {"n": N}, argument="weight")


def test_a_scheme_built_without_the_parser_meets_the_budget():
    cc = catmull_clark()
    with pytest.raises(InvalidSchemeError, match="degree"):
        weight = 1 / ((N + 1) ** 40 * (N + 2) ** 40)
        Scheme("bomb", cc.edge_rule, cc.face_rule, VertexRule(1 - N * weight, weight, 0))
    wide = Stencil(R(3, 8), ((-1, R(1, 16)), (0, R(3, 8)), (9999, R(1, 16))), ((-1, R(1, 16)), (0, R(1, 16))))
    with pytest.raises(InvalidSchemeError, match="offset 9999 is beyond"):
        Scheme("wide", wide, cc.face_rule, cc.vertex_rule)


# -- Item 3: valid files that never finished or answered wrongly ------------------------------------------------

EDGE_FACE = """[edge]
O = "3/8"
a = {{ "-1" = "1/16", "0" = "3/8", "{offset}" = "1/16" }}
b = {{ "-1" = "1/16", "0" = "1/16" }}
[face]
O = "1/4"
a = {{ "0" = "1/4", "1" = "1/4" }}
b = {{ "0" = "1/4" }}
[vertex]
a = "{a}"
b = "1/(4*n**2)"
"""


def _file(tmp_path, a: str = "3/(2*n**2)", offset: int = 1, name: str = "s") -> str:
    path = tmp_path / f"{name}.toml"
    path.write_text(EDGE_FACE.format(a=a, offset=offset))
    return str(path)


def _one_line(capsys, argv) -> str:
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2, err
    assert err.count("\n") == 1 and "Traceback" not in err
    return err


def test_a_cosine_of_one_is_refused_when_the_file_is_read(tmp_path, capsys):
    err = _one_line(capsys, ["claims", "--scheme", _file(tmp_path, "cos(1)/n**2")])
    assert "rational multiples of pi" in err and "[vertex] a" in err


def test_an_offset_beyond_the_budget_is_refused_with_the_reason(tmp_path, capsys):
    err = _one_line(capsys, ["masks", "5", "--scheme", _file(tmp_path, offset=9999)])
    assert "offset 9999 is beyond" in err and "Laurent polynomials" in err


def test_a_stencil_wider_than_the_valence_is_refused_by_every_command(tmp_path, capsys):
    path = _file(tmp_path, offset=4)  # offsets -1..4: six wide
    for argv in (["masks", "5"], ["spectrum", "5"], ["check", "--n", "3:8"], ["charpoly", "5"]):
        err = _one_line(capsys, [*argv, "--scheme", path])
        assert "stencils 6 wide, wider than the valence n =" in err


@pytest.mark.parametrize("argv", [["masks", "5"], ["tune", "5"], ["spectrum", "5"], ["check", "--n", "3:9"],
                                  ["charpoly", "5"], ["c1", "--n", "4:6"], ["evaldata", "--n", "3:6", "--out", "x.json"]])
def test_a_weight_undefined_at_a_valence_the_command_uses_is_refused(tmp_path, capsys, argv):
    err = _one_line(capsys, [*argv, "--scheme", _file(tmp_path, "1/(n-5)")])
    assert "undefined at valence n = 5" in err


def test_a_weight_not_real_at_a_valence_the_command_uses_is_refused(tmp_path, capsys):
    assert "not real at valence n = 4" in _one_line(capsys, ["spectrum", "5", "--scheme", _file(tmp_path, "sqrt(1-n)/n")])
    path = _file(tmp_path, "sqrt(5-n)/n", name="t")  # real up to n = 5
    assert main(["spectrum", "5", "--scheme", path]) == 0
    capsys.readouterr()
    assert "not real at valence n = 6 (it is" in _one_line(capsys, ["spectrum", "6", "--scheme", path])


def test_the_api_refuses_a_weight_undefined_at_the_valence():
    scheme = scheme_from_text(EDGE_FACE.format(a="1/(n-5)", offset=1))
    for call in (closed_form_spectrum, limit_masks_at, tune):
        with pytest.raises(InvalidSchemeError, match="undefined at valence n = 5"):
            call(scheme, 5)
    assert limit_masks_at(scheme, 6).n == 6


def test_the_valences_where_a_weight_is_undefined_are_the_integer_roots_of_its_denominator():
    scheme = scheme_from_text(EDGE_FACE.format(a="1/((n-7)*(2*n-9)*(n**2+1)*(n+3))", offset=1))
    refused = []
    for n in range(3, 40):
        try:
            scheme.fitting_valence(n)
        except InvalidSchemeError as exc:
            refused.append(n)
            assert f"undefined at valence n = {n}" in str(exc)
    assert refused == [7]


# -- Item 8: number syntax ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("text", ["0o7/8", "0b11/8", "0x3/8", "0O7", "0X3/8", "1_0/80"])
def test_only_decimal_integers_are_numbers(text, tmp_path, capsys):
    with pytest.raises(InvalidExpressionError, match="decimal|separators"):
        parse_expression(text)
    assert "[vertex] a" in _one_line(capsys, ["spectrum", "5", "--scheme", _file(tmp_path, f"({text})/n**2")])


# -- The balancing of the exact characteristic polynomial needs no factoring -------------------------------------

def _scale_by_divisors(den_rest, row, col):
    """The former search: every divisor of the row's common denominator, the smallest best one."""
    den_row = full_matrix._lcm(x.q for x in row)
    divisors = [d for d in range(1, den_row + 1) if den_row % d == 0]

    def common(t):
        return full_matrix._lcm([den_rest] + [(x * t).q for x in row] + [(x / t).q for x in col])

    return min((flint.fmpq(d) for d in divisors), key=lambda t: (common(t), t))


def test_the_scale_is_the_best_divisor_found_without_factoring():
    import random

    rng = random.Random(25)
    pool = [1, 2, 3, 4, 5, 6, 8, 9, 12, 16, 18, 24, 25, 27, 32, 36, 48, 64, 72, 96, 100, 128, 144]
    for _ in range(400):
        row = {flint.fmpq(rng.randint(1, 9), rng.choice(pool)) for _ in range(rng.randint(1, 3))}
        col = {flint.fmpq(rng.randint(1, 9), rng.choice(pool)) for _ in range(rng.randint(1, 3))}
        den_rest = rng.choice(pool)
        assert full_matrix._scale(den_rest, row, col) == _scale_by_divisors(den_rest, row, col)


def test_a_huge_denominator_costs_no_trial_division():
    # 1/10**30 took the trial division up to 10**15 (over 40 s); 2**127 - 1 is prime (no divisor search ends)
    cc = catmull_clark()
    for weight in (R(1, 10**30), R(1, (2**127 - 1) * 4)):
        scheme = Scheme("tiny", cc.edge_rule, cc.face_rule, VertexRule.affine(weight, R(1, 4) / N**2))
        try:
            with time_budget(20):
                chi = full_matrix.characteristic_polynomial(scheme, 3)
        except BudgetExceeded:
            pytest.fail(f"the characteristic polynomial with the weight {weight} took more than 20 s")
        assert chi(1) == 0  # the subdivision matrix of an affine scheme has the eigenvalue 1


# -- Every bomb through the command line, under a memory limit and a timeout ------------------------------------

MEMORY_LIMIT_KB = 1_500_000
COMMANDS = [["spectrum", "5"], ["claims"], ["check", "--certify", "--n", "3:6"], ["charpoly", "5"], ["masks", "5"],
            ["tune", "5"], ["evaldata", "--n", "3:5", "--out", "e.json"], ["c1", "--n", "5"]]


def _limited(argv, cwd, timeout=120):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT_KB * 1024, MEMORY_LIMIT_KB * 1024))

    return subprocess.run([sys.executable, "-m", "symdecomp", *argv], cwd=cwd, capture_output=True, text=True,
                          preexec_fn=limit, timeout=timeout,
                          env={**os.environ, "PYTHONPATH": str(ROOT), "OPENBLAS_NUM_THREADS": "1"})


def _run_bomb(tmp_path, k: int, text: str) -> None:
    path = tmp_path / f"bomb{k}.toml"
    path.write_text(EDGE_FACE.format(a=text.replace('"', ""), offset=1))
    out = _limited([*COMMANDS[k % len(COMMANDS)], "--scheme", str(path)], tmp_path)
    assert out.returncode == 2, out.stderr
    assert out.stderr.count("\n") == 1 and "Traceback" not in out.stderr and out.stdout == ""


@pytest.mark.slow
def test_a_bomb_through_the_command_line_under_a_memory_limit(tmp_path):
    control = _limited(["spectrum", "5"], tmp_path)  # the limit leaves room for the command itself
    assert control.returncode == 0, control.stderr
    _run_bomb(tmp_path, 0, BOMBS[0][1])


@pytest.mark.slow
@pytest.mark.parametrize(("k", "bomb"), list(enumerate(BOMBS)), ids=[b[0] for b in BOMBS])
def test_every_bomb_through_the_command_line_under_a_memory_limit(tmp_path, k, bomb):
    _run_bomb(tmp_path, k, bomb[1])
