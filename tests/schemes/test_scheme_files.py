"""Scheme files: the issue's Catmull-Clark file is the built-in scheme; bad files get one line naming the key."""

import pytest
import sympy as sp

from symdecomp.cli import main
from symdecomp.errors import InvalidSchemeError, NotAffineError, SymdecompError
from symdecomp.schemes.files import load_scheme, scheme_from_text, scheme_to_text
from symdecomp.schemes.scheme import catmull_clark, subdivision_matrix
from symdecomp.symbols import Parameter, alpha, n

CC_TOML = """\
name = "catmull-clark"
[edge]            # new a_i = O*w + sum_k a[k]*a_{i+k} + sum_k b[k]*b_{i+k}
O = "3/8"
a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }
b = { "-1" = "1/16", "0" = "1/16" }
[face]            # new b_i (b_i lies between a_i and a_{i+1})
O = "1/4"
a = { "0" = "1/4", "1" = "1/4" }
b = { "0" = "1/4" }
[vertex]          # new O; the weight of O is 1 - n*a - n*b
a = "3/(2*n**2)"
b = "1/(4*n**2)"
"""


def test_the_issue_file_is_catmull_clark(tmp_path):
    path = tmp_path / "cc.toml"
    path.write_text(CC_TOML)
    scheme = load_scheme(path)
    assert scheme == catmull_clark()
    assert subdivision_matrix(scheme, 5) == subdivision_matrix(catmull_clark(), 5)


def test_round_trip_and_names():
    assert scheme_from_text(scheme_to_text(catmull_clark())) == catmull_clark()
    assert load_scheme("catmull-clark") == catmull_clark()


def test_parameters_and_wide_offsets():
    text = CC_TOML.replace('name = "catmull-clark"', 'name = "wide"\nparameters = ["alpha", "t"]')
    text = text.replace('a = "3/(2*n**2)"', 'a = "alpha"').replace('a = { "-1" = "1/16", "0" = "3/8", "1" = "1/16" }',
                                                                     'a = { "-2" = "t", "-1" = "1/16", "0" = "3/8 - 2*t", "1" = "1/16", "2" = "t" }')
    scheme = scheme_from_text(text)
    t = Parameter("t", real=True)  # the users' namespace: not the toolkit's own t of its derivations
    assert t != sp.Symbol("t", real=True)
    assert dict(scheme.edge_rule.a)[-2] == t and alpha in scheme.parameters and t in scheme.parameters
    assert scheme.minimum_valence() == 5
    with pytest.raises(InvalidSchemeError, match="wider than the valence"):
        subdivision_matrix(scheme, 4)
    assert sp.expand(subdivision_matrix(scheme, 5).subs(t, 0) - subdivision_matrix(catmull_clark(alpha), 5).subs(n, 5)) == sp.zeros(11, 11)


@pytest.mark.parametrize(
    "change, error, message",
    [
        (('O = "1/4"', "O = 0.25"), InvalidSchemeError, r"\[face\] O: 0.25 is a float"),
        (('"0" = "3/8", "1"', '"0" = "23/64", "1"'), NotAffineError, r"\[edge\] is not affine: .* = 63/64"),
        (('a = "3/(2*n**2)"', 'a = "3/(2*m**2)"'), InvalidSchemeError, r"\[vertex\] a: .*unknown name 'm'"),
        (('"-1" = "1/16", "0" = "1/16"', '"x1" = "1/16", "0" = "1/16"'), InvalidSchemeError, r"\[edge\] b.'x1': an offset must be an integer"),
        (('a = "3/(2*n**2)"', 'a = "__import__(\'os\')"'), InvalidSchemeError, r"\[vertex\] a: .*calls only"),
        (('[face]', '[fase]'), InvalidSchemeError, "unknown key 'fase'"),
        (('O = "1/4"', 'O = "1/4"\nc = 1'), InvalidSchemeError, r"\[face\] unknown key 'c'"),
        (('name = "catmull-clark"', 'name = "x"\nmesh = "hex"'), InvalidSchemeError, "mesh 'hex' is not supported"),
        (('b = "1/(4*n**2)"', 'b = "1/(4*n**2)"\nO = "1/2"'), NotAffineError, r"\[vertex\] is not affine"),
        (('[edge]', '[edge'), InvalidSchemeError, "not valid TOML"),
    ],
)
def test_bad_files_name_the_key(tmp_path, change, error, message):
    path = tmp_path / "bad.toml"
    path.write_text(CC_TOML.replace(*change))
    with pytest.raises(error, match=message) as info:
        load_scheme(path)
    text = str(info.value)
    assert text.startswith(str(path)) and "\n" not in text


def test_command_line_one_line_exit_2(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text(CC_TOML.replace('O = "1/4"', "O = 0.25"))
    assert main(["spectrum", "--scheme", str(path), "5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "float" in err and "Traceback" not in err
    assert main(["spectrum", "--scheme", "no-such-scheme", "5"]) == 2
    assert "unknown scheme" in capsys.readouterr().err


def test_command_line_takes_a_file(tmp_path, capsys):
    path = tmp_path / "cc.toml"
    path.write_text(CC_TOML)
    assert main(["spectrum", "--scheme", str(path), "5", "--json"]) == 0
    from_file = capsys.readouterr().out
    assert main(["spectrum", "5", "--json"]) == 0
    assert capsys.readouterr().out == from_file


def test_errors_are_package_errors():
    with pytest.raises(SymdecompError):
        scheme_from_text("[edge]\nO = 1\n[face]\nO = 1\n[vertex]\na = 0")
