"""The package root's public names (``__all__``), imported on first use (PEP 562), are the objects of
the modules they come from, and ``from symdecomp import *`` still gives all of them."""

from __future__ import annotations

import importlib
import json
import subprocess
import sys
from pathlib import Path

import pytest

import symdecomp

ROOT = Path(__file__).resolve().parents[2]


def test_every_public_name_is_its_modules_object():
    for module, names in symdecomp._EXPORTS.items():
        source = importlib.import_module(module)
        for name in names:
            assert name in symdecomp.__all__, name
            assert getattr(symdecomp, name) is getattr(source, name), f"symdecomp.{name} is not {module}.{name}"


def test_the_section_6_api_and_every_error_are_public():
    from symdecomp import errors
    from symdecomp.algebra import cbmatrix

    assert set(cbmatrix.__all__) <= set(symdecomp.__all__)
    assert set(errors.__all__) <= set(symdecomp.__all__)
    assert symdecomp.cbmatrix is cbmatrix
    assert symdecomp.symbols is importlib.import_module("symdecomp.symbols")
    assert sorted(set(symdecomp.__all__)) == sorted(symdecomp.__all__), "a name listed twice"


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        symdecomp.no_such_name  # noqa: B018
    with pytest.raises(ImportError):
        exec("from symdecomp import no_such_name", {})


def test_star_import_and_dir_give_every_public_name():
    code = ("import json\nfrom symdecomp import *\nimport symdecomp\n"
            "print(json.dumps([[n for n in symdecomp.__all__ if n not in globals()], "
            "[n for n in symdecomp.__all__ if n not in dir(symdecomp)], len(symdecomp.__all__)]))")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    missing, hidden, count = json.loads(done.stdout)
    assert (missing, hidden) == ([], [])
    assert count == len(symdecomp.__all__) > 90
