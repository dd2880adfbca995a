"""One type means "a distinct eigenvalue with its multiplicity": :class:`symdecomp.analysis.eigenvalue.Eigenvalue`.

A class anywhere in ``symdecomp/`` that holds both a value (a field named as one) and a multiplicity re-defines it;
what a new computation knows beyond the value (its factor and root, its part, its blocks, a key) is an optional field
of ``Eigenvalue``, or a label type beside it (``ClosedFormLabel``, ``MirrorBlock``), never a second eigenvalue type.
"""

from __future__ import annotations

import ast
from pathlib import Path

import symdecomp

PACKAGE = Path(symdecomp.__file__).parent

#: Field names that hold the eigenvalue itself (or its exact form, or its certified ball).
VALUE_FIELDS = {"value", "ball", "exact", "eigenvalue", "root"}

#: The one type.
THE_TYPE = ("analysis/eigenvalue.py", "Eigenvalue")

#: Still there: none (the C1 test's roots of one frequency block and the second-order eigenvalues are ``Eigenvalue``).
ALLOWED: set[tuple[str, str]] = set()


def _fields(node: ast.ClassDef) -> set[str]:
    """The names a class body declares: annotated fields, assignments and properties."""
    names: set[str] = set()
    for item in node.body:
        if isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
            names.add(item.target.id)
        elif isinstance(item, ast.Assign):
            names |= {t.id for t in item.targets if isinstance(t, ast.Name)}
        elif isinstance(item, ast.FunctionDef) and any(isinstance(d, ast.Name) and d.id == "property" for d in item.decorator_list):
            names.add(item.name)
    return names


def eigenvalue_types(root: Path = PACKAGE) -> set[tuple[str, str]]:
    """Every class under ``root`` with a multiplicity and a value field, as ``(path relative to root, class name)``."""
    found = set()
    for path in sorted(root.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef):
                names = _fields(node)
                if "multiplicity" in names and names & VALUE_FIELDS:
                    found.add((path.relative_to(root).as_posix(), node.name))
    return found


def test_one_type_holds_a_distinct_eigenvalue_with_its_multiplicity():
    extra = eigenvalue_types() - {THE_TYPE} - ALLOWED
    assert not extra, f"a second type of 'a distinct eigenvalue with its multiplicity': {sorted(extra)}; use Eigenvalue"


def test_the_allowed_set_holds_only_what_is_still_there():
    assert THE_TYPE in eigenvalue_types()
    assert ALLOWED <= eigenvalue_types(), "a type of the allowed set is gone: take it out of ALLOWED"


def test_the_check_finds_a_second_type(tmp_path):
    (tmp_path / "mine.py").write_text(
        "from dataclasses import dataclass\n\n\n@dataclass(frozen=True)\nclass Root:\n    ball: object\n    multiplicity: int\n\n\n"
        "class Counted:\n    value = None\n\n    @property\n    def multiplicity(self):\n        return 1\n\n\n"
        "class Label:\n    multiplicity: int\n    block: str\n",
        encoding="utf-8",
    )
    assert eigenvalue_types(tmp_path) == {("mine.py", "Root"), ("mine.py", "Counted")}
