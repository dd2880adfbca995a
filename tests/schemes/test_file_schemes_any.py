"""Scheme files beyond the paper's shape: triangle meshes (Loop-type) and quad stencils with offsets -2..2.

Every command that takes ``--scheme`` runs on such a file, or refuses in one line saying why
its analysis does not apply; a file equal to Loop gives Loop's results.
"""

import json

import pytest
import sympy as sp

from symdecomp.algebra.circulant import root_of_unity
from symdecomp.analysis.frequency import per_frequency_matrix_at
from symdecomp.cli import main
from symdecomp.errors import SymdecompError
from symdecomp.schemes.files import scheme_from_text, scheme_to_text
from symdecomp.schemes.scheme import subdivision_matrix
from symdecomp.symbols import n as N
from tests.schemes.test_scheme_files import CC_TOML

N_DEPENDENT = CC_TOML.replace('a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }',
                              'a = { "-1" = "1/16 + 1/(8*n)", "0" = "3/8 - 1/(4*n)", "1" = "1/16 + 1/(8*n)" }')


@pytest.mark.parametrize("n, j", [(5, 1), (6, 2), (7, 3)])
def test_per_frequency_matrix_at_substitutes_the_valence_into_the_rules(n, j):
    scheme = scheme_from_text(N_DEPENDENT)
    M = per_frequency_matrix_at(scheme, n, j)
    assert N not in M.free_symbols
    # The circulant blocks' eigenvalues on v_j, read off the full matrix at this valence (Prop. 2.1).
    S, w = subdivision_matrix(scheme, n), root_of_unity(n, j)
    expected = sp.Matrix(2, 2, lambda p, q: sum(S[1 + p * n, 1 + q * n + c] * w**c for c in range(n)))
    assert (M - expected).applyfunc(lambda e: sp.simplify(sp.expand_complex(e))) == sp.zeros(2, 2)


# --------------------------------------------------------------------------------------------
# triangle scheme files

LOOP_TOML = """\
name = "my-loop"
mesh = "triangle"
[edge]            # new a_i = O*w + sum_k a[k]*a_{i+k}
O = "3/8"
a = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }
[vertex]          # new O = (1 - n*beta)*O + beta*sum_i a_i
beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"
"""


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def _json(capsys, *argv):
    code, out, err = _run(capsys, *argv, "--json")
    assert code == 0, err
    data = json.loads(out)
    return _without_names(data)


def _without_names(data):
    if isinstance(data, dict):
        return {k: _without_names(v) for k, v in data.items() if k not in ("scheme", "seconds", "elapsed")}
    if isinstance(data, list):
        return [_without_names(v) for v in data]
    return data


def test_a_loop_file_is_loop_and_reads_back():
    from symdecomp.schemes.loop import loop

    scheme = scheme_from_text(LOOP_TOML)
    assert scheme_from_text(LOOP_TOML.replace("beta = ", "a = ")) == scheme  # the quad files' key, accepted too
    assert scheme.mesh == "triangle" and scheme.face_rule is None
    assert scheme.vertex_rule.each_a == loop().vertex_rule.each_a
    assert scheme.edge_rule == loop().edge_rule
    assert scheme_from_text(scheme_to_text(scheme)) == scheme
    assert subdivision_matrix(scheme, 7) == subdivision_matrix(loop(), 7)


@pytest.mark.parametrize(
    "argv",
    [
        ("spectrum", "7"),
        ("spectrum", "5", "--rings", "2"),
        ("masks", "5"),
        ("masks", "5", "--rings", "2"),
        ("charpoly", "6"),
        ("check", "--n", "3:8", "--certify"),
        ("check", "--n", "3:5", "--certify", "--rings", "2"),
    ],
)
def test_a_loop_file_gives_loops_results(tmp_path, capsys, argv):
    path = tmp_path / "my-loop.toml"
    path.write_text(LOOP_TOML)
    assert _json(capsys, *argv, "--scheme", str(path)) == _json(capsys, *argv, "--scheme", "loop")


def test_a_triangle_file_with_its_own_beta_has_its_spectrum(tmp_path, capsys):
    """beta = (1/2 + cos(4 pi/n)/8)/n: frequency k != 0 gives 3/8 + cos(2 pi k/n)/4, frequency 0 gives 5/8 - n beta."""
    path = tmp_path / "cos4.toml"
    path.write_text(LOOP_TOML.replace('beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"', 'beta = "(1/2 + cos(4*pi/n)/8)/n"'))
    n = 9
    data = _json(capsys, "spectrum", str(n), "--scheme", str(path))
    values = sorted((sp.nsimplify(0) + sp.Float(e["value"], 30), e["multiplicity"]) for e in data["eigenvalues"])
    expected = [sp.Integer(1), sp.Rational(5, 8) - (sp.Rational(1, 2) + sp.cos(4 * sp.pi / n) / 8)]
    expected += [sp.Rational(3, 8) + sp.cos(2 * sp.pi * k / n) / 4 for k in range(1, n)]
    flat = sorted(sp.Float(v, 30) for v, m in values for _ in range(m))
    assert len(flat) == n + 1
    assert all(abs(a - sp.N(b, 30)) < 1e-18 for a, b in zip(flat, sorted(expected, key=lambda e: sp.N(e, 30))))
    code, out, _ = _run(capsys, "check", "--n", "3:10", "--certify", "--scheme", str(path))
    assert code == 0 and "8 agree" in out


def test_a_triangle_file_whose_edge_rule_is_not_a_mesh_rule_works_on_its_1_ring(tmp_path, capsys):
    path = tmp_path / "asym.toml"
    path.write_text(LOOP_TOML.replace('a = { "-1" = "1/8", "0" = "3/8", "1" = "1/8" }', 'a = { "-1" = "1/16", "0" = "3/8", "1" = "3/16" }'))
    code, out, _ = _run(capsys, "check", "--n", "4:7", "--certify", "--scheme", str(path))
    assert code == 0 and "4 agree" in out
    data = _json(capsys, "charpoly", "7", "--scheme", str(path))
    assert data["matches_matrix"] is True
    code, _, err = _run(capsys, "spectrum", "7", "--rings", "2", "--scheme", str(path))
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "weighs the two ends" in err and "2-ring matrix needs the scheme's rules on the whole mesh" in err


@pytest.mark.parametrize(
    "change, message",
    [
        (("[vertex]", '[face]\nO = "1/2"\n[vertex]'), r"\[face\]: a triangle mesh has no face rule"),
        (('"1" = "1/8" }', '"1" = "1/8" }\nb = { "0" = "0" }'), r"\[edge\] b: a triangle mesh has no face neighbours"),
        (("beta = ", 'a = "1/8"\nbeta = '), r"\[vertex\] a and beta are the same weight"),
        (("beta = ", 'b = "0"\nbeta = '), r"\[vertex\] b: on a triangle mesh the vertex rule is one weight, beta"),
        (('beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"', 'O = "1/2"'), r"\[vertex\] beta is missing"),
        (('beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"', "beta = 0.1"), r"\[vertex\] beta: 0.1 is a float"),
        (('beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"', 'beta = "3/(8*n)"\nO = "1/2"'), r"\[vertex\] is not affine: O = 1/2"),
        (('beta = "(5/8 - (3/8 + cos(2*pi/n)/4)**2)/n"', 'beta = "cos(2*pi/m)"'), r"\[vertex\] beta: .*unknown name 'm'"),
        (('mesh = "triangle"', 'mesh = "hexagon"'), r"mesh 'hexagon' is not supported"),
    ],
)
def test_bad_triangle_files_get_one_line_naming_the_key(tmp_path, capsys, change, message):
    import re

    text = LOOP_TOML.replace(*change)
    assert text != LOOP_TOML
    with pytest.raises(SymdecompError, match=message):
        scheme_from_text(text)
    path = tmp_path / "bad.toml"
    path.write_text(text)
    assert main(["spectrum", "5", "--scheme", str(path)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and re.search(message, err)


# --------------------------------------------------------------------------------------------
# quad files with stencils of offsets -2..2

WIDE_TOML = CC_TOML.replace('a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }',
                            'a = { "-2" = "1/64", "-1" = "1/32", "0" = "3/8", "1" = "1/32", "2" = "1/64" }').replace(
    'b = { "-1" = "1/16", "0" = "1/16" }', 'b = { "-2" = "1/64", "-1" = "1/16", "0" = "1/16", "1" = "1/64" }')
WIDE_ASYMMETRIC = WIDE_TOML.replace('"-1" = "1/16", "0" = "1/16", "1"', '"-1" = "3/64", "0" = "5/64", "1"')


def _matrix_eigenvalues(scheme, n):
    import mpmath

    S = subdivision_matrix(scheme, n)
    with mpmath.workdps(40):
        values = mpmath.eig(mpmath.matrix([[mpmath.mpf(x.p) / x.q for x in S.row(r)] for r in range(S.rows)]), left=False, right=False)
        return sorted(values, key=lambda z: (round(float(z.real), 12), round(float(z.imag), 12)))


@pytest.mark.slow
@pytest.mark.parametrize("text", [WIDE_TOML, WIDE_ASYMMETRIC], ids=["symmetric", "asymmetric"])
def test_a_wide_quad_file_runs_through_every_command(tmp_path, capsys, text):
    import mpmath

    path = tmp_path / "wide.toml"
    path.write_text(text)
    scheme, n = scheme_from_text(text), 7
    assert scheme.minimum_valence() == 5
    # spectrum: the values with multiplicities are the eigenvalues of the full matrix
    data = _json(capsys, "spectrum", str(n), "--scheme", str(path))
    values = [complex(e["value"]) for e in data["eigenvalues"] for _ in range(e["multiplicity"])]
    matrix = _matrix_eigenvalues(scheme, n)
    assert len(values) == len(matrix) == 2 * n + 1
    for z in matrix:
        assert min(abs(complex(z) - complex(v)) for v in values) < 1e-12
    # check, numeric and certified (both certificates)
    for extra in ((), ("--certify",), ("--certify", "--structural")):
        code, out, err = _run(capsys, "check", "--n", "5:6", "--scheme", str(path), *extra)
        assert code == 0 and "2 agree" in out, (extra, out, err)
    # charpoly: no closed form (Eq. 51 needs offsets -1..1), the product form equals the matrix's
    assert _json(capsys, "charpoly", str(n), "--scheme", str(path))["matches_matrix"] is True
    # masks: the position mask is a left eigenvector of S for 1, summing to 1
    code, out, err = _run(capsys, "masks", str(n), "--scheme", str(path), "--json")
    masks = _without_names(json.loads(out))
    if text is WIDE_ASYMMETRIC:  # M_1's dominant eigenvalue is not real: masks says so and exits 1
        assert code == 1 and masks["lambda_1_subdominant"] is False and "is not real" in masks["subdominance"]
    else:
        assert code == 0 and masks["lambda_1_subdominant"] is True, err
    S = subdivision_matrix(scheme, n)
    position = masks["position"]
    row = [position["O"]] + (position["a"] + position["b"] if "a" in position else
                             [w for s in range(n) for w in (position["classes"]["1,0"][s], position["classes"]["1,1"][s])])
    if "a" not in position:  # the any-scheme route lists classes sector by sector; reorder to (O, a_i, b_i)
        row = [row[0]] + row[1::2] + row[2::2]
    with mpmath.workdps(30):
        l = mpmath.matrix([[mpmath.mpf(x) for x in row]])
        M = mpmath.matrix([[mpmath.mpf(x.p) / x.q for x in S.row(r)] for r in range(S.rows)])
        assert mpmath.norm(l * M - l) < 1e-15 and abs(sum(l) - 1) < 1e-15
    # --rings 2: one line saying why
    code, _, err = _run(capsys, "spectrum", str(n), "--rings", "2", "--scheme", str(path))
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "reaches beyond the two faces" in err and "2-ring matrix needs the scheme's rules on the whole mesh" in err
    # tune: the closed forms need mirror symmetry
    code, out, err = _run(capsys, "tune", "5", "--scheme", str(path))
    if text is WIDE_ASYMMETRIC:
        assert code == 2 and "not mirror-symmetric" in err and len(err.strip().splitlines()) == 1
    else:
        assert code == 0


@pytest.mark.parametrize("argv, why", [
    (("derive", "--out", "OUT"), "statements about quad meshes"),
    (("tune", "5"), "derived for quad meshes, not triangle meshes"),
    (("oracle", "--n", "5"), None),
])
def test_commands_about_quad_meshes_say_why_in_one_line(tmp_path, capsys, argv, why):
    path = tmp_path / "my-loop.toml"
    path.write_text(LOOP_TOML)
    argv = [str(tmp_path / "out") if a == "OUT" else a for a in argv]
    code, _, err = _run(capsys, *argv, "--scheme", str(path))
    if why is None:  # a file with Loop's rules is Loop for OpenSubdiv: it runs (or says the bridge is missing)
        assert code in (0, 3), err
        return
    assert code == 2 and len(err.strip().splitlines()) == 1 and why in err


def test_a_weight_defined_by_cases_is_not_written_to_a_file():
    from symdecomp.errors import InvalidSchemeError
    from symdecomp.schemes.loop import loop_warren

    with pytest.raises(InvalidSchemeError, match="defined by cases"):
        scheme_to_text(loop_warren())
