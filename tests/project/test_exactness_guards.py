"""Exact means exact, precision is scoped: two greps over the package that keep it so.

* ``nsimplify`` guesses a closed form from digits; a guess is never a proof, so it has no place
  where a result is called exact (equality is shown exactly, or a displayed number says it is
  only displayed).
* FLINT/Arb precision is set in a scope (``with flint.ctx.workprec(...)``), as mpmath's
  ``workdps``, never assigned and restored by hand.
* ``sympify`` is always called with ``strict=True``: internal values (numbers, fractions, sympy
  objects) pass, text never does. User text goes through :mod:`symdecomp.expressions` only, so
  a string that reached a sympify call by mistake is an error, not an evaluation.

``NOT_YET`` lists the sites left in modules owned elsewhere; remove an entry once it is gone
(the last test fails on a stale entry).
"""

import ast
import pathlib
import re
from fractions import Fraction

import pytest
import sympy as sp

PACKAGE = pathlib.Path(__file__).resolve().parents[2] / "symdecomp"
MODULES = sorted(p for p in PACKAGE.rglob("*.py") if "_build" not in p.parts)

PATTERNS = {
    "nsimplify": re.compile(r"\bnsimplify\b"),
    "precision assigned by hand": re.compile(r"\bctx\.(prec|dps)\s*=|\bmp\.(prec|dps)\s*="),
}

#: ``(module, pattern name): count`` still present, in the claims modules (issue 10, item 5).
NOT_YET: dict[tuple[str, str], int] = {}


def _count(path: pathlib.Path, pattern: re.Pattern) -> int:
    return len(pattern.findall(path.read_text()))


@pytest.mark.parametrize("name", sorted(PATTERNS))
def test_no_guessing_and_no_unscoped_precision(name):
    found = {}
    for path in MODULES:
        rel = path.relative_to(PACKAGE).as_posix()
        count = _count(path, PATTERNS[name])
        if count > NOT_YET.get((rel, name), 0):
            found[rel] = count
    assert not found, f"{name} in {found}"


def test_the_exceptions_are_not_stale():
    stale = [key for key, count in NOT_YET.items() if _count(PACKAGE / key[0], PATTERNS[key[1]]) < count]
    assert not stale, f"remove from NOT_YET: {stale}"


def test_the_patterns_see_what_they_forbid():
    assert PATTERNS["nsimplify"].search("x = sp.nsimplify(y)")
    assert PATTERNS["precision assigned by hand"].search("    flint.ctx.prec = 128")
    assert PATTERNS["precision assigned by hand"].search("mpmath.mp.dps = 50")
    assert not PATTERNS["precision assigned by hand"].search("with flint.ctx.workprec(128):")


def _lenient_sympify_calls(source: str) -> list[int]:
    """Lines of the calls ``sympify(...)`` / ``x.sympify(...)`` without ``strict=True``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call):
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", None)
            strict = any(k.arg == "strict" and isinstance(k.value, ast.Constant) and k.value.value is True for k in node.keywords)
            if name == "sympify" and not strict:
                found.append(node.lineno)
    return found


def test_sympify_is_always_strict():
    found = {}
    for path in MODULES:
        lines = _lenient_sympify_calls(path.read_text())
        if lines:
            found[path.relative_to(PACKAGE).as_posix()] = lines
    assert not found, f"sympify without strict=True (text would be evaluated) at {found}"


def test_the_sympify_guard_sees_what_it_forbids():
    assert _lenient_sympify_calls("x = sp.sympify(y)") == [1]
    assert _lenient_sympify_calls("x = sympify(y, strict=False)") == [1]
    assert _lenient_sympify_calls("x = sp.sympify(y, strict=True)") == []


def test_a_string_reaching_an_internal_entry_point_is_refused_not_evaluated():
    from symdecomp.algebra.cyclotomic import cyclotomic_value

    assert cyclotomic_value(sp.cos(sp.pi / 3), {}).to_mpc().real == 0.5
    assert cyclotomic_value(Fraction(1, 3)).to_mpc().real * 3 == 1
    with pytest.raises(sp.SympifyError):
        cyclotomic_value("__import__('os').getcwd()")
    with pytest.raises(sp.SympifyError):
        cyclotomic_value(sp.Symbol("x"), {"x": "1/3"})
