"""Exact means exact, precision is scoped: two greps over the package that keep it so.

* ``nsimplify`` guesses a closed form from digits; a guess is never a proof, so it has no place
  where a result is called exact (equality is shown exactly, or a displayed number says it is
  only displayed).
* FLINT/Arb precision is set in a scope (``with flint.ctx.workprec(...)``), as mpmath's
  ``workdps``, never assigned and restored by hand.

``NOT_YET`` lists the sites left in modules owned elsewhere; remove an entry once it is gone
(the last test fails on a stale entry).
"""

import pathlib
import re

import pytest

PACKAGE = pathlib.Path(__file__).resolve().parents[1] / "symdecomp"
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
