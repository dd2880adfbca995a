"""Sphinx extension: the documentation pages that are generated from the code, not written by hand.

Each generator is a plain function that returns reStructuredText (so the tests read the same text
without running Sphinx); a directive parses that text into the page:

- ``symdecomp-commands``: the command reference, every subcommand of
  :func:`symdecomp.cli.build_parser` with its ``--help`` text (:func:`command_reference`);
- ``symdecomp-module-map``: the one module map, the table in the docstring of :mod:`symdecomp`
  (:func:`map_rows`), each module linked to its API entry;
- ``symdecomp-api ROW``: the API reference of one row of the map (:func:`api_reference`): a top-level module
  in full, a folder as its package's entry and a table of its modules (each with its docstring's first line)
  linking to one page per module (:func:`module_page`, written into ``docs/api/modules/`` when the build
  starts, generated and ignored by git), which opens with a table of the module's public names and the first
  sentence of each one's docstring (:func:`summary`), then documents them;
- ``symdecomp-public-api``: the names :mod:`symdecomp` re-exports, each linked to its home;
- ``symdecomp-table NAME``: the tables kept in the code (exit codes, command-line limits, the
  expression budget).

The notebooks in ``notebooks/`` are copied into ``docs/notebooks/`` (generated, ignored by git)
when the build starts, so that myst-nb renders the committed files.
"""

from __future__ import annotations

import contextlib
import importlib
import inspect
import os
import re
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
#: Where the one-page-per-module API pages are written, relative to the documentation's source folder.
MODULE_PAGES = "api/modules"
#: Width of the ``--help`` texts in the command reference (fixed, so that the pages do not depend on a terminal).
HELP_COLUMNS = 100


def map_rows(doc: str) -> list[tuple[str, str, list[str]]]:
    """The rows of the module map in ``doc``: ``(head, text, modules)``.

    ``head`` is the first column (``"errors"``, ``"algebra/"``), ``text`` the second joined into one
    line, ``modules`` the dotted names (relative to the package) of the head and of every
    ``double-quoted literal`` in a folder's row."""
    lines = doc.splitlines()
    borders = [i for i, line in enumerate(lines) if re.fullmatch(r"=+ +=+", line)]
    if len(borders) != 2:
        raise ValueError("the module map is one table without a header")
    width = lines[borders[0]].index(" ")
    rows: list[tuple[str, list[str]]] = []
    for line in lines[borders[0] + 1 : borders[1]]:
        head, text = line[:width].strip(), line[width:].strip()
        if head:
            rows.append((head, [text]))
        elif rows:
            rows[-1][1].append(text)
    result = []
    for head, texts in rows:
        (name,) = re.findall(r"``([^`]+)``", head)
        text = " ".join(texts)
        inside = re.findall(r"``([^`]+)``", text)
        if inside and not name.endswith("/"):
            raise ValueError(f"a top-level module's row names modules: {inside}")
        folder = name.rstrip("/").replace("/", ".")
        result.append((name, text, [folder] + [f"{folder}.{m}" for m in inside]))
    return result


def map_modules(doc: str) -> list[str]:
    """Every module the map names, relative to the package (``"algebra.circulant"``), in the map's order."""
    return [module for _, _, modules in map_rows(doc) for module in modules]


def _package_doc() -> str:
    import symdecomp

    return symdecomp.__doc__


def module_map() -> str:
    """The module map as a table, every module linked to its API entry."""
    out = [".. list-table::", "   :widths: 20 80", ""]
    for head, text, modules in map_rows(_package_doc()):
        folder = modules[0]
        linked = re.sub(r"``([^`]+)``", lambda m, folder=folder: f":mod:`{m.group(1)} <symdecomp.{folder}.{m.group(1)}>`", text)
        out += [f"   * - :mod:`{head} <symdecomp.{folder}>`", f"     - {linked}"]
    return "\n".join(out) + "\n"


def _row_modules(head: str) -> list[str]:
    rows = {name.rstrip("/"): modules for name, _, modules in map_rows(_package_doc())}
    if head not in rows:
        raise ValueError(f"{head!r} is not a row of the module map ({', '.join(rows)})")
    return rows[head]


def public_names(name: str) -> list[str]:
    """The public names module ``name`` defines, in the order of its source: the classes and functions defined
    there, and the other names of its ``__all__`` that it defines (constants); not what it re-exports."""
    module = importlib.import_module(name)
    listed = set(getattr(module, "__all__", ()))
    found = []
    for attr, obj in vars(module).items():
        if attr.startswith("_"):
            continue
        if inspect.isclass(obj) or inspect.isfunction(obj):
            if getattr(obj, "__module__", None) == name:
                found.append(attr)
        elif attr in listed and not inspect.ismodule(obj):
            found.append(attr)
    return found


def summary(obj) -> str:
    """The one-line summary of ``obj``: the first sentence of its docstring's first paragraph, unless cutting there
    would split inline markup (a literal, a role, emphasis, parentheses); then the whole paragraph."""
    paragraph = " ".join((inspect.getdoc(obj) or "").split("\n\n", 1)[0].split())
    for end in re.finditer(r"\.(?=\s|$)", paragraph):
        head = paragraph[: end.end()]
        if head.endswith(("e.g.", "i.e.", "Eq.", "Prop.", "Sec.", "Fig.", "cf.", "vs.")):
            continue
        literals, roles = head.count("``"), head.replace("``", "").count("`")
        if literals % 2 == 0 and roles % 2 == 0 and head.count("**") % 2 == 0 and head.count("(") == head.count(")"):
            return head
    return paragraph


class _DocComment:
    """A module constant's ``#:`` comment, as the docstring :func:`summary` reads."""

    def __init__(self, doc: str):
        self.__doc__ = doc


def _attribute_docs(module: str) -> dict[str, str]:
    """The ``#:`` comments of ``module``'s names (what autodoc documents a constant with)."""
    from sphinx.pycode import ModuleAnalyzer

    docs = ModuleAnalyzer.for_module(module).find_attr_docs()
    return {attr: "\n".join(lines) for (scope, attr), lines in docs.items() if scope == ""}


def _summary(names: list[str], modules: bool = False) -> list[str]:
    """A table of the dotted ``names`` (of modules, or of names in a module), each linked to its entry, beside the
    first sentence of its docstring."""
    rows = []
    for name in names:
        if modules:
            obj, link = importlib.import_module(name), f":py:mod:`{name}`"
        else:
            module, _, attr = name.rpartition(".")
            obj, link = getattr(importlib.import_module(module), attr), f":py:obj:`~{name}`"
            if not (inspect.isclass(obj) or inspect.isroutine(obj)):  # data: its ``#:`` comment, not its type's docstring
                obj = _DocComment(_attribute_docs(module).get(attr, ""))
        text = summary(obj)
        if text:  # autodoc leaves out what has no docstring: no row that links nowhere
            rows += [f"   * - {link}", f"     - {text}"]
    return [".. list-table::", "   :widths: 30 70", ""] + rows + [""] if rows else []


def _automodule(name: str) -> list[str]:
    if name.endswith(".__main__"):  # importing it runs the command line
        return [f".. py:module:: {name}", "", "``python -m symdecomp``: the command line, see :doc:`/commands`.", ""]
    return [f".. automodule:: {name}", "   :members:", ""]


def _names_table(name: str) -> list[str]:
    if name.endswith(".__main__"):
        return []
    table = _summary([f"{name}.{attr}" for attr in public_names(name)])
    return [f".. currentmodule:: {name}", ""] + table if table else []  # the summaries' short references resolve there


def api_reference(head: str) -> str:
    """The API reference of the map's row ``head`` (``"errors"``, ``"analysis"``).

    A top-level module: a table of its public names, then its entry. A folder: its package's entry and a table
    of its modules, each linked to its own page (:func:`module_page`), so that no page holds a whole layer."""
    modules = _row_modules(head)
    package = f"symdecomp.{modules[0]}"
    out = [f"``{package}``", "-" * (len(package) + 4), ""]
    if len(modules) == 1:
        return "\n".join(out + _names_table(package) + _automodule(package))
    out += _automodule(package) + [".. rubric:: Modules", ""] + _summary([f"symdecomp.{m}" for m in modules[1:]], modules=True)
    out += [".. toctree::", "   :hidden:", ""] + [f"   modules/symdecomp.{m}" for m in modules[1:]] + [""]
    return "\n".join(out)


def module_page(name: str) -> str:
    """The API page of module ``name`` (a module of a folder row): a table of its public names, then its entry."""
    title = f"``{name}``"
    return "\n".join([title, "=" * len(title), ""] + _names_table(name) + _automodule(name))


def write_module_pages(srcdir: Path) -> list[Path]:
    """Write :func:`module_page` of every module of the map's folders into ``srcdir/api/modules`` (a file only
    when its text changed, so that a rebuild is quick; pages of modules no longer in the map are removed)."""
    target = srcdir / MODULE_PAGES
    target.mkdir(parents=True, exist_ok=True)
    written = []
    for _, _, modules in map_rows(_package_doc()):
        for module in modules[1:]:
            path = target / f"symdecomp.{module}.rst"
            text = module_page(f"symdecomp.{module}") + "\n"
            if not path.exists() or path.read_text(encoding="utf-8") != text:
                path.write_text(text, encoding="utf-8")
            written.append(path)
    for stale in set(target.glob("*.rst")) - set(written):
        stale.unlink()
    return written


def public_api() -> str:
    """The names :mod:`symdecomp` re-exports, each linked to the module that defines it."""
    import symdecomp

    out = [".. list-table::", "   :widths: 35 65", ""]
    for name in symdecomp.__all__:
        obj = getattr(symdecomp, name)
        if isinstance(obj, type(symdecomp)):
            target, home = obj.__name__, obj.__name__
            out += [f"   * - :mod:`{name} <{target}>`", f"     - module ``{home}``"]
            continue
        home = getattr(obj, "__module__", None) or ""
        if not home.startswith("symdecomp") or not hasattr(importlib.import_module(home), name):
            out += [f"   * - ``{name}``", "     - a constant of :mod:`symdecomp`"]
            continue
        role = "class" if isinstance(obj, type) else "func" if callable(obj) else "data"
        out += [f"   * - :py:{role}:`{name} <{home}.{name}>`", f"     - from :mod:`{home}`"]
    return "\n".join(out) + "\n"


@contextlib.contextmanager
def _columns(width: int):
    previous = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = str(width)
    try:
        yield
    finally:
        if previous is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = previous


def subcommands(parser) -> dict:
    """The subcommands of ``parser`` by name, in the order ``--help`` lists them."""
    import argparse

    (action,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return dict(action.choices)


def _literal(text: str) -> list[str]:
    return [".. code-block:: text", ""] + [f"    {line}".rstrip() for line in text.rstrip().splitlines()] + [""]


def command_reference() -> str:
    """Every subcommand of :func:`symdecomp.cli.build_parser`, a section each with its ``--help`` text."""
    from symdecomp.cli import build_parser

    with _columns(HELP_COLUMNS):
        parser = build_parser()
        out = ["``symdecomp``", "-" * 13, ""] + _literal(parser.format_help())
        for name, sub in subcommands(parser).items():
            title = f"``symdecomp {name}``"
            out += [f".. _command-{name}:", "", title, "-" * len(title), ""] + _literal(sub.format_help())
    return "\n".join(out)


def tables() -> dict:
    """The tables kept in the code, as reStructuredText by name."""
    from symdecomp.cli import EXIT_CODES
    from symdecomp.cli.common import LIMITS
    from symdecomp.expressions import BUDGET

    def table(header, rows):
        out = [".. list-table::", "   :header-rows: 1", ""]
        for row in [header, *rows]:
            out += [f"   * - {row[0]}"] + [f"     - {cell}" for cell in row[1:]]
        return "\n".join(out) + "\n"

    return {
        "exit-codes": table(("exit code", "meaning"), [(code, text) for code, text in EXIT_CODES.items()]),
        "limits": table(("option or argument", "at most", "why"), [(f"``{k}``", b, w) for k, (b, w) in LIMITS.items()]),
        "budget": table(("bound", "limit", "why"), [(k, b, w) for k, (b, w) in BUDGET.items()]),
    }


def copy_notebooks(srcdir: Path) -> list[Path]:
    """Copy ``notebooks/*.ipynb`` into ``srcdir/notebooks`` (only those that changed, so that a rebuild is quick).

    The data files the notebooks read (``notebooks/data/``) go along, so that they run from the copy.
    """
    target = srcdir / "notebooks"
    target.mkdir(exist_ok=True)
    copied = []
    for path in sorted(NOTEBOOKS.glob("*.ipynb")):
        dest = target / path.name
        if not dest.exists() or dest.read_bytes() != path.read_bytes():
            shutil.copyfile(path, dest)
        copied.append(dest)
    for stale in target.glob("*.ipynb"):
        if not (NOTEBOOKS / stale.name).exists():
            stale.unlink()
    if (NOTEBOOKS / "data").is_dir():
        shutil.copytree(NOTEBOOKS / "data", target / "data", dirs_exist_ok=True)
    return copied


def setup(app):
    from docutils import nodes
    from docutils.parsers.rst import Directive, directives
    from docutils.parsers.rst import Parser as RSTParser
    from docutils.parsers.rst.states import RSTState
    from docutils.statemachine import StringList
    from docutils.utils import new_document
    from sphinx.util.nodes import nested_parse_with_titles

    def directive(generate, arguments=0):
        class Generated(Directive):
            required_arguments = arguments
            has_content = False

            def run(self):
                text = generate(*self.arguments)
                if not isinstance(self.state, RSTState):  # a Markdown page (myst): parse the text as rST all the same
                    document = new_document(self.state.document.current_source, self.state.document.settings)
                    RSTParser().parse(text, document)
                    return document.children
                node = nodes.section()  # a holder: its children (sections, tables) join the page
                node.document = self.state.document
                source = self.state.document.current_source
                nested_parse_with_titles(self.state, StringList(text.splitlines(), source=source), node)
                return node.children

        return Generated

    directives.register_directive("symdecomp-commands", directive(command_reference))
    directives.register_directive("symdecomp-module-map", directive(module_map))
    directives.register_directive("symdecomp-api", directive(api_reference, 1))
    directives.register_directive("symdecomp-public-api", directive(public_api))
    directives.register_directive("symdecomp-table", directive(lambda name: tables()[name], 1))
    app.connect("builder-inited", lambda app: copy_notebooks(Path(app.srcdir)))
    app.connect("builder-inited", lambda app: write_module_pages(Path(app.srcdir)))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
