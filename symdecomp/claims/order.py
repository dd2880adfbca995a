"""The order of the claims: the paper's sections numerically, then the toolkit's own, and within a section the order of
its modules in a fresh interpreter (each after the claim modules it imports) and of their registrations.

The order is a fact of the sources, not of the run: a caller that imports ``s6_closing`` before ``s6_cb_subdivision``
gets the same list of claims, and the same derivations, as ``symdecomp claims`` (:func:`module_ranks` reads the
claim modules' imports from their source and never executes them).

>>> sorted(["B.1", "6", "5.10", "5.2"], key=section_key)
['5.2', '5.10', '6', 'B.1']
"""

from __future__ import annotations

import ast
import importlib.util
import pkgutil
from functools import cache

__all__ = ["BEYOND", "section_key", "section_modules", "module_ranks"]

#: The prefix of the sections of the toolkit's own claims (modules ``b<digit>_*.py``), after the paper's: ``"B.1"``.
BEYOND = "B"


def section_key(section: str) -> tuple:
    """Where a section sorts: the paper's numerically, then the toolkit's own (``"B.1"``, ``"B.2"``).

    >>> sorted(["B.1", "6", "5.10", "5.2"], key=section_key)
    ['5.2', '5.10', '6', 'B.1']
    """
    head, _, rest = section.partition(".")
    own = head == BEYOND
    return (int(own), *(int(p) for p in (rest if own else section).split(".")))



def section_modules() -> list[str]:
    """The claim modules' names, in name order: the paper's sections (``s<digit>_*``), then the toolkit's (``b<digit>_*``)."""
    from symdecomp import claims as package

    return [info.name for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda m: m.name)
            if info.name[:1] in ("s", BEYOND.lower()) and info.name[1:2].isdigit()]


def module_ranks() -> dict[str, int]:
    """Claim module -> its place in the canonical load order (see :func:`_ranks`); a copy the caller may keep."""
    return dict(_ranks())


@cache
def _ranks() -> dict[str, int]:
    """Where each claim module registers in a fresh interpreter that imports them in name order: each after the claim
    modules it imports (read from its source, never executed), so the order does not depend on what was imported first."""
    from symdecomp import claims as package

    names = section_modules()
    deps: dict[str, list[str]] = {}
    for name in names:
        spec = importlib.util.find_spec(f"{package.__name__}.{name}")
        tree = ast.parse(open(spec.origin, encoding="utf-8").read()) if spec and spec.origin else ast.Module([], [])
        found = [node.module.rsplit(".", 1)[-1] for node in tree.body
                 if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith(f"{package.__name__}.")]
        deps[name] = [d for d in found if d in names]
    order: list[str] = []

    def visit(name: str) -> None:
        if name not in order:
            for dep in deps[name]:
                visit(dep)
            order.append(name)

    for name in names:
        visit(name)
    return {f"{package.__name__}.{name}": i for i, name in enumerate(order)}


