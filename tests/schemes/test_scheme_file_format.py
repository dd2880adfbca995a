"""The scheme-file format has one description, the docstring of ``symdecomp.schemes.files`` (the
documentation's page is that text): its examples are read here with the parser, and the facts it
states are compared with what the parser does."""

import re
import textwrap

import pytest

import symdecomp as sd
from symdecomp.errors import InvalidSchemeError
from symdecomp.schemes import files
from symdecomp.symbols import RESERVED_NAMES

DOC = files.__doc__


def _examples() -> list[str]:
    """The literal blocks (``::``) of the docstring: the example files."""
    return [textwrap.dedent(block) for block in re.findall(r"::\n\n((?:    .*\n|\n)+)", DOC)]


@pytest.mark.parametrize("n", [3, 5, 7])
def test_each_example_file_is_the_built_in_scheme_it_names(n):
    examples = _examples()
    assert len(examples) == 3
    for text in examples:
        scheme = files.scheme_from_text(text)
        built_in = files.load_scheme(scheme.name)  # a built-in scheme or a file shipped with the package
        assert scheme == built_in
        assert sd.subdivision_matrix(scheme, n) == sd.subdivision_matrix(built_in, n)


def test_the_reserved_names_are_those_the_parser_refuses():
    listed = re.search(r"reserved and refused in one\s+line: (.*?)\. ", DOC, re.S).group(1)
    names = tuple(re.findall(r"``(\w+)``", listed))
    assert names == RESERVED_NAMES
    for name in names:
        with pytest.raises(InvalidSchemeError, match=name):
            files.scheme_from_text(f'parameters = ["{name}"]\n[edge]\nO = "1"\n')


def test_the_stated_bounds_are_the_parser_s():
    assert "at most 100 characters" in DOC
    files.scheme_from_text('name = "' + "x" * 100 + '"\n' + _examples()[0].split("\n", 1)[1])
    with pytest.raises(InvalidSchemeError, match="100"):
        files.scheme_from_text('name = "' + "x" * 101 + '"\n' + _examples()[0].split("\n", 1)[1])
    assert "at most 16" in DOC
    with pytest.raises(InvalidSchemeError):
        files.scheme_from_text('parameters = ["a' + "b" * 16 + '"]\n' + _examples()[0].split("\n", 1)[1])


def test_the_error_example_is_what_the_command_line_prints(tmp_path, capsys):
    from symdecomp.cli import main

    path = tmp_path / "my.toml"
    text = _examples()[0].replace('[face]            # new b_i (b_i lies between a_i and a_{i+1})\nO = "1/4"', "[face]\nO = 0.25")
    path.write_text(text)
    assert main(["claims", "--scheme", str(path)]) == 2
    line = re.search(r"``(symdecomp: error: argument --scheme: my\.toml: .*?)``", " ".join(DOC.split())).group(1)
    assert capsys.readouterr().err.strip() == line.replace("my.toml", str(path))
