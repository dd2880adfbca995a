"""Property-based tests of the public API (hypothesis): looking for trouble at the edges.

Every test feeds generated inputs, good and bad, and asserts that nothing but the package's
own errors is raised and that the identities hold on what is accepted. The examples are
derandomized (the same inputs on every run) and add up to more than 1,000 per run.
"""

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symdecomp import (
    SymdecompError,
    block_eigenvalue_matrix,
    catmull_clark,
    cb_matrix,
    circ,
    invariant_ratio_at,
    lifted_vector,
    root_of_unity,
    tangent_eigenvalues,
)
from symdecomp.algebra.polygons import decompose
from symdecomp.errors import InvalidExpressionError, InvalidInputError
from symdecomp.expressions import exact_value, parse_expression
from symdecomp.schemes.scheme import Stencil
from symdecomp.validate import check_frequency, check_valence

FAST = settings(max_examples=150, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
MANY = settings(max_examples=300, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))

#: Anything a user might pass where a number is expected.
junk = st.one_of(
    st.none(),
    st.booleans(),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12),
    st.binary(max_size=4),
    st.complex_numbers(max_magnitude=10),
    st.lists(st.integers(-3, 3), max_size=3),
    st.dictionaries(st.integers(-2, 2), st.integers(-2, 2), max_size=2),
    st.integers(min_value=-(10**40), max_value=2),
    st.just(sp.Symbol("n")),
    st.just(sp.oo),
    st.just(sp.nan),
    st.just(float("nan")),
)


@MANY
@given(junk)
def test_valence_is_an_integer_or_a_package_error(value):
    try:
        n = check_valence(value)
    except InvalidInputError:
        return
    assert isinstance(n, int) and not isinstance(value, bool) and n == value and n >= 3


@FAST
@given(st.integers(3, 40), st.one_of(junk, st.integers(-100, 100)))
def test_frequency_is_in_range_or_a_package_error(n, j):
    try:
        got = check_frequency(j, n)
    except InvalidInputError:
        return
    assert got == j and 0 <= got < 2 * n and type(got) is int


@MANY
@given(st.text(alphabet="0123456789+-*/()n pisqrtco_.e'\"[]{}:;,=<>!@#$%^&|~`\\x", max_size=40))
def test_the_parser_returns_an_expression_or_a_package_error(text):
    n = sp.Symbol("n", integer=True, positive=True)
    try:
        value = parse_expression(text, {"n": n})
    except InvalidExpressionError:
        return
    assert isinstance(value, sp.Expr)
    assert value.free_symbols <= {n}
    assert not value.has(sp.Float, sp.nan, sp.zoo)


@st.composite
def rational_expressions(draw, depth=0):
    """A random arithmetic expression as text, with its exact value (None where it divides by 0)."""
    if depth > 2 or draw(st.booleans()):
        k = draw(st.integers(-50, 50))
        return (str(k) if k >= 0 else f"({k})"), Fraction(k)
    left_text, left = draw(rational_expressions(depth + 1))
    right_text, right = draw(rational_expressions(depth + 1))
    op = draw(st.sampled_from("+-*/"))
    if left is None or right is None or (op == "/" and right == 0):
        value = None
    else:
        value = {"+": left + right, "-": left - right, "*": left * right, "/": left / right if right else None}[op]
    return f"({left_text} {op} {right_text})", value


@FAST
@given(rational_expressions())
def test_parsed_arithmetic_is_exact(case):
    text, value = case
    if value is None:
        with pytest.raises(InvalidExpressionError, match="division by zero"):
            parse_expression(text)
        return
    assert parse_expression(text) == sp.Rational(value.numerator, value.denominator)


@FAST
@given(st.lists(st.tuples(st.integers(-99, 99), st.integers(1, 20)), min_size=1, max_size=5))
def test_circ_rows_are_shifts_and_sum_alike(pairs):
    c = [sp.Rational(p, q) for p, q in pairs]
    rows = circ([f"{p}/{q}" for p, q in pairs]).tolist()  # text is parsed exactly, never evaluated
    m = len(c)
    for r in range(m):
        assert [rows[r][(r + k) % m] for k in range(m)] == c
    assert {sum(row) for row in rows} == {sum(c)}


@FAST
@given(st.one_of(junk, st.lists(junk, max_size=4), st.lists(st.lists(junk, max_size=3), max_size=3)))
def test_circulant_constructors_refuse_junk_with_package_errors(value):
    for build in (circ, lambda v: cb_matrix(v), lambda v: lifted_vector(v, [1, 2])):
        try:
            build(value)
        except SymdecompError:
            pass


@FAST
@given(st.integers(1, 12), st.one_of(junk, st.integers(-30, 30)))
def test_root_of_unity_is_a_root_or_a_package_error(n, power):
    try:
        w = root_of_unity(n, power)
    except SymdecompError:
        assert not (isinstance(power, int) and not isinstance(power, bool))
        return
    assert sp.simplify(w**n - 1) == 0
    assert sp.simplify(w - sp.exp(2 * sp.pi * sp.I * (power % n) / n)) == 0


@FAST
@given(junk, st.one_of(junk, st.integers(-3, 12)))
def test_tangent_and_ratio_refuse_bad_valences(n, j):
    cc = _cc()
    for call in (lambda: tangent_eigenvalues(cc).at(n, j), lambda: invariant_ratio_at(cc, n, j)):
        with pytest.raises(SymdecompError):
            call()


@FAST
@given(st.one_of(junk, st.dictionaries(st.one_of(st.integers(-2, 2), st.booleans(), st.none(), st.text(max_size=3),
                                                 st.floats(allow_nan=False)), junk, max_size=3)))
def test_stencils_refuse_junk_with_package_errors(weights):
    try:
        Stencil.from_weights(weights if not isinstance(weights, dict) else 0, weights, {})
    except SymdecompError:
        pass


@FAST
@given(st.integers(3, 9), st.data())
def test_decompose_reconstructs_and_pairs_sum_to_the_pair_polygon(n, data):
    coords = data.draw(st.lists(st.lists(st.integers(-9, 9), min_size=3, max_size=3), min_size=n, max_size=n))
    P = np.array(coords, dtype=float)
    d = decompose(P)
    assert np.allclose(np.array(d.reconstruct(), dtype=float), P)
    for j in range(n):  # every j, including 0 and n/2
        first, second = d.planar_pair(j)
        pair = np.array(first.vertices(), dtype=float) + np.array(second.vertices(), dtype=float)
        assert np.allclose(pair, np.array(d.pair_polygon(j), dtype=float), atol=1e-9)
    # the pairs {j, n-j} for j = 0..floor(n/2) partition the frequencies: they sum to the polygon
    pairs = sum(np.array(d.pair_polygon(j), dtype=float) for j in range(n // 2 + 1))
    assert np.allclose(pairs, P, atol=1e-9)


@FAST
@given(st.one_of(junk, st.lists(st.lists(junk, max_size=4), max_size=5)))
def test_polygons_refuse_junk_with_package_errors(polygon):
    try:
        decompose(polygon)
    except SymdecompError:
        pass


@FAST
@given(junk)
def test_exact_values_are_exact_or_refused(value):
    try:
        got = exact_value(value)
    except InvalidExpressionError:
        return
    assert isinstance(got, sp.Expr) and not got.has(sp.Float)


@FAST
@given(st.integers(1, 4), st.one_of(junk, st.integers(-2, 6)))
def test_frequency_matrix_of_a_cb_matrix(m, k):
    B = cb_matrix([[[Fraction(i + 1, 3) for i in range(m)]]])
    try:
        E = block_eigenvalue_matrix(B, k)
    except SymdecompError:
        return
    assert 0 <= k < m
    assert sp.simplify(E[0, 0] - sum(Fraction(i + 1, 3) * root_of_unity(m, k * i) for i in range(m))) == 0


_CC = []


def _cc():
    if not _CC:
        _CC.append(catmull_clark())
    return _CC[0]


def test_these_properties_cover_more_than_a_thousand_inputs():
    tests = [v for k, v in globals().items() if k.startswith("test_") and hasattr(v, "hypothesis")]
    total = sum(t._hypothesis_internal_use_settings.max_examples for t in tests)
    assert total >= 1000


def test_hostile_text_is_never_executed(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    attack = "__import__('pathlib').Path('pwned').touch()"
    for call in (lambda: circ([attack, 0, 0]), lambda: lifted_vector([attack], [1]),
                 lambda: catmull_clark(attack, None), lambda: exact_value(attack)):
        with pytest.raises(SymdecompError):
            call()
    assert not (tmp_path / "pwned").exists()
